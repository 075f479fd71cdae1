#!/usr/bin/env bash
# The shared command line refuses bad values: exit code 2, exactly one line on stderr that
# names the bad value, and no output file created or truncated.
#   bad_input.sh CHAPTER_EXE
set -uo pipefail
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0

# expect_refusal VALUE_IN_MESSAGE ARGS...
expect_refusal() {
    local value=$1
    shift
    printf 'keep' >existing.png
    "$exe" --quiet --width 8 --spp 1 "$@" >stdout.txt 2>stderr.txt
    local rc=$?
    local lines
    lines=$(wc -l <stderr.txt)
    local problem=""
    [ "$rc" -eq 2 ] || problem+=" exit code $rc, not 2;"
    [ "$lines" -eq 1 ] || problem+=" $lines lines on stderr, not 1;"
    grep -qF -- "$value" stderr.txt || problem+=" message does not name '$value';"
    [ "$(cat existing.png)" = "keep" ] || problem+=" existing.png was changed;"
    local extra
    extra=$(ls -A | grep -vxE 'existing.png|stdout.txt|stderr.txt')
    [ -z "$extra" ] || problem+=" left files: $extra;"
    if [ -n "$problem" ]; then
        echo "FAIL [$*]:$problem stderr: $(cat stderr.txt)"
        failures=$((failures + 1))
    else
        echo "ok   [$*] -> $(cat stderr.txt)"
    fi
    rm -f stdout.txt stderr.txt
}

expect_refusal 0 --width 0 --out existing.png
expect_refusal 100000 --width 100000 --out existing.png
expect_refusal abc --width abc --out existing.png
expect_refusal -3 --spp -3 --out existing.png
expect_refusal 0 --spp 0 --out existing.png
expect_refusal 0 --max-depth 0 --out existing.png
expect_refusal -1 --threads -1 --out existing.png
expect_refusal --bogus --bogus --out existing.png
expect_refusal missing_folder --out missing_folder/image.png
expect_refusal image.jpg --out image.jpg
expect_refusal image.png --variance-out image.png
expect_refusal noext --out existing.png --out noext

# And the good path: --help exits 0; a real render writes exactly the requested files.
if ! "$exe" --help >/dev/null; then
    echo "FAIL: --help did not exit 0"
    failures=$((failures + 1))
fi
rm -f existing.png
if ! "$exe" --quiet --width 8 --spp 1 --out a.png --out b.pfm 2>stderr.txt || [ -s stderr.txt ] ||
    [ "$(ls -A | grep -v stderr.txt | tr '\n' ' ')" != "a.png b.pfm " ]; then
    echo "FAIL: a good render did not write exactly a.png and b.pfm quietly: $(ls -A)"
    head -n 3 stderr.txt  # what the render said instead
    failures=$((failures + 1))
fi
echo "$failures failures"
[ "$failures" -eq 0 ]
