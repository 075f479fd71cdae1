#!/usr/bin/env bash
# Two renders that must agree byte for byte: same_image.sh EXE "ARGS A" "ARGS B"
# (for instance --threads 1 against --threads 2, or the BVH against a flat list).
set -euo pipefail
exe=$1 args_a=$2 args_b=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck disable=SC2086  # each ARGS string holds several arguments on purpose
"$exe" --quiet $args_a --out "$tmp/a.pfm"
# shellcheck disable=SC2086
"$exe" --quiet $args_b --out "$tmp/b.pfm"
if cmp -s "$tmp/a.pfm" "$tmp/b.pfm"; then
    echo "identical: [$args_a] and [$args_b]"
else
    echo "FAIL: [$args_a] and [$args_b] give different images"
    exit 1
fi
