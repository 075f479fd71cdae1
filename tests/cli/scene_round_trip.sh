#!/usr/bin/env bash
# A built-in scene and its scene file render the same image, byte for byte (chapter 19):
#   scene_round_trip.sh PROGRAM SCENE COMMITTED_FILE SCALAR
# PROGRAM --scene SCENE renders the scene built in code; --dump-scene writes it as a file, which
# must render the very same PFM; so must the committed file assets/scenes/book/SCENE.toml, whose
# text must be the dump's but for the paths of texture files (written relative to the file's
# folder). The committed files are the double build's: in float, only the dump is compared.
set -euo pipefail
program=$1 scene=$2 committed=$3 scalar=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() {
    echo "scene_round_trip $scene: $*" >&2
    exit 1
}
settings=(--width 48 --spp 2 --quiet)

"$program" --scene "$scene" --dump-scene "$tmp/$scene.toml"
"$program" --scene "$scene" "${settings[@]}" --out "$tmp/compiled.pfm"
"$program" --scene-file "$tmp/$scene.toml" "${settings[@]}" --out "$tmp/from_file.pfm"
cmp "$tmp/compiled.pfm" "$tmp/from_file.pfm" ||
    fail "the file --dump-scene wrote renders another image than the scene built in code"
[ "$scalar" = double ] || exit 0

[ -f "$committed" ] || fail "no committed file $committed (tools/make-scene-files writes it)"
"$program" --scene-file "$committed" "${settings[@]}" --out "$tmp/committed.pfm"
cmp "$tmp/compiled.pfm" "$tmp/committed.pfm" ||
    fail "$committed renders another image than the scene built in code (tools/make-scene-files)"
without_paths() { sed -E 's/file = "[^"]*"/file = "..."/' "$1"; }
diff <(without_paths "$committed") <(without_paths "$tmp/$scene.toml") ||
    fail "$committed differs from what --dump-scene writes now (tools/make-scene-files)"
echo "scene_round_trip $scene: the same image from code, the dump and the committed file"
