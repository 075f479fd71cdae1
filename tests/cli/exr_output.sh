#!/usr/bin/env bash
# OpenEXR output as other tools read it: exr_output.sh EXE ARGS...
#  - `--out x.exr` beside `--out x.pfm`: oiiotool (OpenImageIO) reads the .exr as a 3-channel
#    float OpenEXR with finite statistics, and finds it equal to the PFM of the same run: no
#    pixel differs at all (a difference threshold of 0);
#  - `--exr-half`: a half-float OpenEXR, within half's rounding of the PFM;
#  - a --variance-out .exr equals its .pfm the same way.
set -euo pipefail
exe=$(realpath "$1")
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$exe" --quiet "$@" --out x.pfm --out x.exr --variance-out v.exr --stats-out x.json
"$exe" --quiet "$@" --out h.exr --exr-half --variance-out v.pfm

fail() { echo "FAIL: $*"; exit 1; }
info=$(oiiotool --info --stats x.exr)
grep -q "3 channel, float openexr" <<<"$info" || fail "x.exr is not a 3-channel float EXR: $info"
grep -qE "NanCount: 0 0 0" <<<"$info" || fail "x.exr has NaNs: $info"
grep -qE "InfCount: 0 0 0" <<<"$info" || fail "x.exr has infinities: $info"
oiiotool --info h.exr | grep -q "3 channel, half openexr" || fail "h.exr is not a half EXR"

# compare A B THRESHOLD: oiiotool's difference of two images, none above THRESHOLD.
compare() {
    local out
    out=$(oiiotool "$1" "$2" --warn "$3" --fail "$3" --diff 2>&1) || true
    grep -q "^PASS" <<<"$out" || fail "$1 and $2 differ beyond $3: $out"
    echo "ok: $1 = $2 within $3"
}
compare x.exr x.pfm 0
compare v.exr v.pfm 0
# Half's rounding is relative (at most 2^-12 of 1 below 1, 2^-11 below 2), and oiiotool's
# threshold absolute: the image must stay below 2 in every channel (checked first).
python3 - <<'PY' || fail "a pixel of x.pfm reaches 2: the half comparison needs values below 2"
import struct, sys
with open("x.pfm", "rb") as f:
    header = [f.readline() for _ in range(3)]
    data = f.read()
values = struct.unpack(f"<{len(data) // 4}f", data)
sys.exit(0 if max(values) < 2 else 1)
PY
compare h.exr x.pfm 0.00049
