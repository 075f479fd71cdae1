#!/usr/bin/env bash
# Two programs' renders that must agree byte for byte:
#   same_image_across.sh EXE_A "ARGS A" EXE_B "ARGS B"
# (for instance chapter 07's BVH against chapter 06's flat list on book 1's final scene).
set -euo pipefail
exe_a=$1 args_a=$2 exe_b=$3 args_b=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck disable=SC2086  # each ARGS string holds several arguments on purpose
"$exe_a" --quiet $args_a --out "$tmp/a.pfm"
# shellcheck disable=SC2086
"$exe_b" --quiet $args_b --out "$tmp/b.pfm"
if cmp -s "$tmp/a.pfm" "$tmp/b.pfm"; then
    echo "identical: $(basename "$exe_a") [$args_a] and $(basename "$exe_b") [$args_b]"
else
    echo "FAIL: $(basename "$exe_a") [$args_a] and $(basename "$exe_b") [$args_b] differ"
    exit 1
fi
