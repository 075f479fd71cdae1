#!/usr/bin/env bash
# tools/merge refuses parts that do not make one render: exit code 2, exactly one line on stderr
# saying what is wrong, and no merged file written.
#   merge_refuses.sh EXE MERGE_PARTS   (EXE: chapter 07, which has a flag of its own, --accel)
set -uo pipefail
exe=$1
export RT_MERGE_PARTS=$2
merge=$(cd "$(dirname "$0")/../../tools" && pwd)/merge
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0

# part NAME ARGS...: renders a part of the 16-pixel-wide, 4-spp image into NAME.{pfm,json}.
part() {
    local name=$1
    shift
    "$exe" --quiet --width 16 --spp 4 --threads 1 --out "$name.pfm" --stats-out "$name.json" "$@" ||
        { echo "FAIL: rendering part $name"; exit 1; }
}
read -r height < <("$exe" --quiet --width 16 --spp 1 --out h.pfm && sed -n 2p h.pfm | cut -d' ' -f2)
part left --crop "0,0,8,$height"
part right --crop "8,0,16,$height"
part wide_left --crop "0,0,10,$height"
part seed2_right --crop "8,0,16,$height" --seed 2
part list_right --crop "8,0,16,$height" --accel list
part first --samples 0:3
part overlapping --samples 2:4
part last --samples 3:4
"$exe" --quiet --width 20 --spp 4 --crop "8,0,16,$height" --out wider.pfm --stats-out wider.json
"$exe" --quiet --width 16 --spp 4 --crop "8,0,16,$height" --out png_only.png \
    --stats-out png_only.json
"$exe" --quiet --width 16 --spp 4 --crop "8,0,16,$height" --out half_right.exr --exr-half \
    --stats-out half_right.json
printf 'not json' >broken.json

# expect_refusal PHRASE MERGE_ARGS...
expect_refusal() {
    local phrase=$1
    shift
    "$merge" --out merged.png --out merged.pfm "$@" >stdout.txt 2>stderr.txt
    local rc=$? problem=""
    [ "$rc" -eq 2 ] || problem+=" exit code $rc, not 2;"
    [ "$(wc -l <stderr.txt)" -eq 1 ] || problem+=" $(wc -l <stderr.txt) lines on stderr, not 1;"
    grep -qF -- "$phrase" stderr.txt || problem+=" message does not say '$phrase';"
    ! ls merged.* >/dev/null 2>&1 || problem+=" wrote $(ls merged.*);"
    if [ -n "$problem" ]; then
        echo "FAIL [$*]:$problem stderr: $(cat stderr.txt)"
        failures=$((failures + 1))
    else
        echo "ok   [$*] -> $(cat stderr.txt)"
    fi
    rm -f stdout.txt stderr.txt merged.*
}

expect_refusal "crops must not overlap" wide_left.json right.json
expect_refusal "crops must cover the whole 16 x $height image, got none for pixel (8, 0)" left.json
expect_refusal "got seed 1 in 'left.json' and 2 in 'seed2_right.json'" left.json seed2_right.json
expect_refusal "got scene flags" left.json list_right.json
expect_refusal "got width 16 in 'left.json' and 20 in 'wider.json'" left.json wider.json
expect_refusal "must have a .pfm or .exr output" left.json png_only.json
expect_refusal "half_right.exr' holds half floats" left.json half_right.json
expect_refusal "must not overlap, got 2:4" first.json overlapping.json
expect_refusal "must cover 0:4, missing 0:2" overlapping.json
expect_refusal "must cover 0:4, missing 3:4" first.json
expect_refusal "must have a variance image" --variance-out merged-variance.pfm first.json last.json
expect_refusal "broken.json" broken.json
expect_refusal "missing.json" missing.json
expect_refusal "unknown extension" --out merged.jpg first.json last.json

# And the good paths, so that the refusals above are not all a broken merge.
"$merge" --out merged.pfm left.json right.json || { echo "FAIL: left + right"; failures=$((failures + 1)); }
"$merge" --out merged2.pfm first.json last.json || { echo "FAIL: 0:3 + 3:4"; failures=$((failures + 1)); }

[ "$failures" -eq 0 ] || exit 1
echo "ok: tools/merge refuses every bad set of parts"
