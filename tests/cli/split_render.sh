#!/usr/bin/env bash
# A render split into four parts, rendered as parallel processes by GNU parallel and put back
# together by tools/merge, against the same render in one run (README: "Rendering past one
# machine").
#   split_render.sh MODE EXE MERGE_PARTS ARGS...
#   crops    four crops (the quadrants): merged .png and .pfm equal the single run's byte for byte
#   samples  four sample ranges: merged mean and variance (.pfm) within 1e-6 relative, the
#            variance also within what the parts' float means carry (compare_pfm.py)
#   mixed    two crops (the halves) of two sample ranges each: the same bounds
#   exr      four crops written as OpenEXR only (mean and variance, 32-bit floats): merged
#            .exr, .pfm and variance equal the single run's byte for byte
set -euo pipefail
mode=$1 exe=$2
export RT_MERGE_PARTS=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
merge=$here/../../tools/merge
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$exe" --quiet "$@" --out full.png --out full.pfm --variance-out full-variance.pfm \
    --stats-out full.json
read -r width height spp < <(python3 -c 'import json, sys; s = json.load(open(sys.argv[1]))["settings"]
print(s["width"], s["height"], s["spp"])' full.json)
[ "$spp" -ge 4 ] || { echo "FAIL: needs --spp 4 or more, got $spp"; exit 1; }
x=$((width / 2)) y=$((height / 2))
a=$((spp / 4)) b=$((spp / 2)) c=$((3 * spp / 4))

# One line per part: its --crop and --samples arguments.
case $mode in
crops | exr) printf '%s\n' "--crop 0,0,$x,$y" "--crop $x,0,$width,$y" "--crop 0,$y,$x,$height" \
    "--crop $x,$y,$width,$height" >parts.txt ;;
samples) printf '%s\n' "--samples 0:$a" "--samples $a:$b" "--samples $b:$c" \
    "--samples $c:$spp" >parts.txt ;;
mixed) printf '%s\n' "--crop 0,0,$x,$height --samples 0:$b" \
    "--crop 0,0,$x,$height --samples $b:$spp" "--crop $x,0,$width,$height --samples 0:$a" \
    "--crop $x,0,$width,$height --samples $a:$spp" >parts.txt ;;
*) echo "FAIL: unknown mode $mode"; exit 1 ;;
esac

# Four processes at once, one thread each; {=uq=} is the line unquoted (several arguments),
# {#} the part's number, 1..4.
mkdir parts
if [ "$mode" = exr ]; then
    images="--out parts/{#}.exr --variance-out parts/{#}-variance.exr"
else
    images="--out parts/{#}.pfm --out parts/{#}.png --variance-out parts/{#}-variance.pfm"
fi
parallel --will-cite --halt now,fail=1 \
    "\"$exe\" --quiet --threads 1 $* {=uq=} $images --stats-out parts/{#}.json" :::: parts.txt
[ "$(ls parts/*.json | wc -l)" -eq 4 ] || { echo "FAIL: not four parts: $(ls parts)"; exit 1; }

if [ "$mode" = exr ]; then
    "$exe" --quiet "$@" --out full.exr --variance-out full-variance.exr
    "$merge" --out merged.exr --out merged.pfm --variance-out merged-variance.exr parts/*.json
    for f in full.exr full.pfm full-variance.exr; do
        cmp "$f" "merged${f#full}" || { echo "FAIL: merged ${f#full} differs from $f"; exit 1; }
    done
    echo "ok: four crops of $width x $height written as .exr merged equal one run byte for byte"
    exit 0
fi

"$merge" --out merged.png --out merged.pfm --variance-out merged-variance.pfm parts/*.json

if [ "$mode" = crops ]; then
    for f in png pfm; do
        cmp full.$f merged.$f || { echo "FAIL: merged .$f differs from the single run's"; exit 1; }
    done
    cmp -s full-variance.pfm merged-variance.pfm ||
        { echo "FAIL: merged variance differs from the single run's"; exit 1; }
    echo "ok: four crops of $width x $height merged equal one run byte for byte (.png, .pfm)"
else
    python3 "$here/compare_pfm.py" full.pfm merged.pfm 1e-6
    python3 "$here/compare_pfm.py" full-variance.pfm merged-variance.pfm 1e-6 full.pfm "$spp"
    echo "ok: four parts ($mode) of $spp spp merged equal one run within 1e-6 relative"
fi
