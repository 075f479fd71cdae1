#!/usr/bin/env bash
# A write that fails half way (file size limit, like a full disk) must exit with code 2, keep the
# existing output file as it was, and leave no temporary file: write_failure.sh EXE EXTENSION
set -uo pipefail
exe=$1 ext=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
printf 'keep' >"existing.$ext"
# Ignore SIGXFSZ so that write() fails with EFBIG instead of killing the process; 8 KiB is far
# less than a 400x225 image.
(trap '' XFSZ; ulimit -f 8; exec "$exe" --quiet --width 1600 --spp 1 --out "existing.$ext") 2>err.txt
rc=$?
problems=""
[ "$rc" -eq 2 ] || problems+=" exit code $rc, not 2;"
[ "$(cat "existing.$ext")" = "keep" ] || problems+=" existing.$ext was replaced;"
left=$(ls -A | grep -vxE "existing.$ext|err.txt")
[ -z "$left" ] || problems+=" left files: $left;"
if [ -n "$problems" ]; then
    echo "FAIL ($ext):$problems stderr: $(cat err.txt)"
    exit 1
fi
echo "ok ($ext): $(cat err.txt)"
