#!/usr/bin/env bash
# A run writes all its outputs or none (rt/files/output_set.h): write_failure.sh EXE EXTENSION
#  - a write that fails half way (file size limit, like a full disk) exits with code 2, names the
#    file and the reason, keeps the existing output as it was and leaves no temporary file;
#  - so does a second --out that cannot be created (/proc/new.EXT), and the first output, written
#    in full before it, is not renamed over its old file either;
#  - (EXTENSION pfm) a write cut short in the second of two outputs: the first is kept too;
#  - a good run writes every output (each --out, --variance-out, --stats-out).
set -uo pipefail
exe=$(realpath "$1") ext=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0

# Whether FILE still holds the "keep" it was made with.
kept() { [ "$(head -c 5 "$1" | tr -d '\0')" = keep ] && [ "$(stat -c %s "$1")" -eq 4 ]; }

# check NAME RC WANT_RC MESSAGE: the exit code, stderr holding MESSAGE (empty: stderr empty),
# every file named in $keep still "keep", and no file in the folder but $keep, $expect and err.txt.
check() {
    local name=$1 rc=$2 want=$3 message=$4 problems=""
    [ "$rc" -eq "$want" ] || problems+=" exit code $rc, not $want;"
    if [ -z "$message" ]; then
        [ ! -s err.txt ] || problems+=" stderr is not empty;"
    else
        grep -qF -- "$message" err.txt || problems+=" stderr does not hold '$message';"
    fi
    for f in $keep; do
        kept "$f" || problems+=" $f was replaced;"
    done
    local left
    left=$(ls -A | grep -vxE "$(echo $keep $expect err.txt | tr ' ' '|')")
    [ -z "$left" ] || problems+=" left files: $(echo $left);"
    if [ -n "$problems" ]; then
        echo "FAIL [$name]:$problems stderr: $(cat err.txt)"
        failures=$((failures + 1))
    else
        echo "ok   [$name]: $(cat err.txt)"
    fi
}

# Each case starts in an empty folder.
# Ignore SIGXFSZ so that write() fails with EFBIG instead of killing the process; 8 KiB is far
# less than a 1600 x 900 image.
printf 'keep' >"existing.$ext"
(trap '' XFSZ; ulimit -f 8; exec "$exe" --quiet --width 1600 --spp 1 --out "existing.$ext") 2>err.txt
keep="existing.$ext" expect="" check "write cut short" $? 2 "cannot write 'existing.$ext': File too large"

rm -f -- *
# /proc takes no new file: the second output cannot even be created.
printf 'keep' >"existing.$ext"
"$exe" --quiet --width 16 --spp 1 --out "existing.$ext" --out "/proc/new.$ext" 2>err.txt
keep="existing.$ext" expect="" check "second output cannot be created" $? 2 \
    "cannot write '/proc/new.$ext': No such file or directory"

rm -f -- *
# The same for the record, added last: the images written before it stay unrenamed.
printf 'keep' >"existing.$ext"
"$exe" --quiet --width 16 --spp 1 --out "existing.$ext" --stats-out /proc/new.json 2>err.txt
keep="existing.$ext" expect="" check "stats file cannot be created" $? 2 \
    "cannot write '/proc/new.json': No such file or directory"

if [ "$ext" = pfm ]; then
    rm -f -- *
    # 2 MiB: the 1600 x 900 PNG (about 130 KB) fits, its 17 MB PFM does not.
    printf 'keep' >existing.png
    printf 'keep' >existing.pfm
    (trap '' XFSZ; ulimit -f 2048
     exec "$exe" --quiet --width 1600 --spp 1 --out existing.png --out existing.pfm) 2>err.txt
    keep="existing.png existing.pfm" expect="" check "second output cut short" $? 2 \
        "cannot write 'existing.pfm': File too large"
fi

rm -f -- *
# A good run replaces and creates every output.
printf 'keep' >"existing.$ext"
"$exe" --quiet --width 16 --spp 1 --out "existing.$ext" --out new.png --variance-out var.pfm \
    --stats-out run.json 2>err.txt
keep="" expect="existing.$ext new.png var.pfm run.json" check "good run" $? 0 ""
for f in "existing.$ext" new.png var.pfm run.json; do
    if [ ! -s "$f" ] || kept "$f"; then
        echo "FAIL [good run]: $f was not written"
        failures=$((failures + 1))
    fi
done
grep -q '"outputs": \["existing.'"$ext"'", "new.png"\]' run.json ||
    { echo "FAIL [good run]: run.json does not list the outputs"; failures=$((failures + 1)); }

[ "$failures" -eq 0 ] || { echo "$failures cases left the wrong files"; exit 1; }
echo "every failed run kept the old files and left nothing else; the good run wrote them all"
