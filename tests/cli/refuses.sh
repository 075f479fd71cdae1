#!/usr/bin/env bash
# One refused command line: refuses.sh EXE VALUE ARGS...
# The program must exit with code 2, print exactly one line on stderr that names VALUE, and
# leave no file behind in its (empty) working folder.
set -uo pipefail
exe=$1 value=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
"$exe" --quiet --width 8 --spp 1 "$@" >/dev/null 2>"$work.err"
rc=$?
message=$(cat "$work.err")
rm -f "$work.err"
problems=""
[ "$rc" -eq 2 ] || problems+=" exit code $rc, not 2;"
[ "$(printf '%s\n' "$message" | wc -l)" -eq 1 ] || problems+=" not exactly one line;"
printf '%s' "$message" | grep -qF -- "$value" || problems+=" message does not name '$value';"
[ -z "$(ls -A)" ] || problems+=" left files: $(ls -A);"
if [ -n "$problems" ]; then
    echo "FAIL [$*]:$problems stderr: $message"
    exit 1
fi
echo "ok [$*] -> $message"
