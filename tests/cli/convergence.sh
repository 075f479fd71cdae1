#!/usr/bin/env bash
# tools/convergence on a tiny case (report: "Speed against error"): a reference made on the fly
# into a temporary folder, then every method at 1..8 spp of --scene ch10 at 32 px.
#   convergence.sh CH17_FAST_TRAVERSAL      (the program tools/convergence renders with)
# Checks: the reference and its record are written, and a normal run leaves them untouched; the
# CSV has its columns, one curve per method with spp doubling from 1; its RMSE, relative MSE,
# display RMSE and shares of error in the brightest 1 % of pixels and in those over white of mis +
# sobol at 8 spp equal
# those computed here, independently, from the same render; the plot and the error maps are
# PNGs; the table has one row per method and a speed-up by each measure; a missing reference and a bad method are refused (exit code 2,
# one line, nothing written). Without matplotlib or numpy it fails at once, saying so: the test
# command installs them (tools/install-deps), so a skip would only hide a broken install.
set -euo pipefail
exe=$1
here=$(cd "$(dirname "$0")" && pwd)
convergence=$here/../../tools/convergence
if ! /usr/bin/python3 -c 'import matplotlib, numpy' 2>/dev/null; then
    echo "FAIL: needs python3-matplotlib and python3-numpy (tools/install-deps installs them)"
    exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() {
    echo "FAIL: $*"
    exit 1
}
common=(--width 32 --reference-dir refs --exe "$exe")

# A missing reference is refused before anything is rendered or written.
if "$convergence" ch10 "${common[@]}" --max-spp 8 --out-dir out 2>err.txt; then
    fail "a run without a reference succeeded"
else
    code=$?
fi
[ "$code" -eq 2 ] || fail "a missing reference gave exit code $code, not 2"
[ "$(wc -l <err.txt)" -eq 1 ] && grep -q "must have a converged reference" err.txt ||
    fail "a missing reference must give one line naming it, got: $(cat err.txt)"
[ ! -e out ] || fail "a refused run wrote $(ls out)"

"$convergence" ch10 "${common[@]}" --make-reference --spp 16 2>log.txt ||
    fail "making the reference failed: $(tail -3 log.txt)"
[ -s refs/ch10.pfm ] && [ -s refs/ch10.json ] || fail "no reference written: $(ls refs)"
before=$(md5sum refs/ch10.pfm refs/ch10.json)

# A bad method is refused.
if "$convergence" ch10 "${common[@]}" --methods path:independent,mis:halton 2>err.txt; then
    fail "a bad method was accepted"
else
    code=$?
fi
[ "$code" -eq 2 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "mis:halton" err.txt ||
    fail "a bad method gave exit code $code and: $(cat err.txt)"

"$convergence" ch10 "${common[@]}" --max-spp 8 --stop spp --out-dir out 2>log.txt ||
    fail "a normal run failed: $(tail -3 log.txt)"
[ "$(md5sum refs/ch10.pfm refs/ch10.json)" = "$before" ] || fail "a normal run changed the reference"
"$exe" --scene ch10 --integrator mis --sampler sobol --width 32 --spp 8 --seed 1 --quiet \
    --out mis8.pfm

/usr/bin/python3 - "$here/../../tools" <<'EOF' || exit 1
import csv, math, sys

sys.dont_write_bytecode = True  # leave no __pycache__ in tools/
sys.path.insert(0, sys.argv[1])
from rtlib import pfm  # the tools' reader; the errors below are computed without numpy

def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)

columns = ["scene", "integrator", "sampler", "spp", "seconds", "rmse", "relmse", "rays",
           "samples_per_second", "render_seconds", "cpu_seconds", "display_rmse",
           "bright_share", "over_white_share"]
with open("out/ch10.csv") as f:
    reader = csv.DictReader(f)
    if reader.fieldnames[:len(columns)] != columns:
        fail(f"CSV columns must start with {columns}, got {reader.fieldnames}")
    rows = list(reader)
methods = {}
for r in rows:
    methods.setdefault((r["integrator"], r["sampler"]), []).append(r)
expected = {(i, s) for i in ("path", "light", "mis") for s in ("independent", "sobol")}
expected.add(("mis-expected", "sobol"))
if set(methods) != expected:
    fail(f"CSV must hold one curve per method, got {sorted(methods)}")
for m, curve in methods.items():
    spp = [int(r["spp"]) for r in curve]
    if spp != [1, 2, 4, 8]:
        fail(f"{m}: spp must double from 1 to 8, got {spp}")
    for r in curve:
        if r["scene"] != "ch10" or not (float(r["seconds"]) > 0 and float(r["rmse"]) > 0
                                        and float(r["relmse"]) > 0 and int(r["rays"]) > 0):
            fail(f"{m}: a row with a bad value: {r}")

ref, img = pfm.read("refs/ch10.pfm").pixels, pfm.read("mis8.pfm").pixels
rmse = math.sqrt(sum((a - b) ** 2 for a, b in zip(img, ref)) / len(ref))
relmse = sum((a - b) ** 2 / (b * b + 0.01) for a, b in zip(img, ref)) / len(ref)

def shown(v):  # clamped and sRGB-encoded, as a screen shows it
    v = min(max(v, 0.0), 1.0)
    return 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055

display = math.sqrt(sum((shown(a) - shown(b)) ** 2 for a, b in zip(img, ref)) / len(ref))
# The brightest 1 % of the reference's pixels (32 x 18 = 576: 6 pixels), by the channels' mean.
pixels = len(ref) // 3
brightness = [sum(ref[3 * p:3 * p + 3]) / 3 for p in range(pixels)]
order = sorted(range(pixels), key=lambda p: brightness[p])
bright = set(order[-math.ceil(0.01 * pixels):])
square = [sum((img[3 * p + c] - ref[3 * p + c]) ** 2 for c in range(3)) for p in range(pixels)]
share = sum(square[p] for p in bright) / sum(square)
over_white = sum(square[p] for p in range(pixels) if brightness[p] > 1) / sum(square)
row = methods[("mis", "sobol")][-1]
for what, mine, theirs in (("RMSE", rmse, float(row["rmse"])),
                           ("relative MSE", relmse, float(row["relmse"])),
                           ("display RMSE", display, float(row["display_rmse"])),
                           ("share of error in the brightest 1 %", share,
                            float(row["bright_share"])),
                           ("share of error over white", over_white,
                            float(row["over_white_share"]))):
    if abs(mine - theirs) > 1e-4 * mine:
        fail(f"{what} of mis + sobol at 8 spp: the CSV says {theirs}, computed here {mine}")

for png in ("out/ch10.png", "out/ch10-error-maps.png"):
    with open(png, "rb") as f:
        if f.read(8) != b"\x89PNG\r\n\x1a\n":
            fail(f"{png} is not a PNG")
with open("out/ch10.md") as f:
    table = [line for line in f if line.startswith("| ") and " + " in line.split("|")[1]]
names = sorted(line.split("|")[1].strip() for line in table)
if names != sorted(f"{i} + {s}" for i, s in expected):
    fail(f"the table must have one row per method, got {names}")
header = next(line for line in open("out/ch10.md") if line.startswith("| method"))
for measure in ("speed-up by relative MSE", "speed-up by display RMSE",
                "error in the brightest 1 %", "error in pixels over white"):
    if measure not in header:
        fail(f"the table must have a column '{measure}', got: {header.strip()}")
baseline = next(line for line in table if line.split("|")[1].strip() == "path + independent")
if baseline.split("|")[8].strip() != "1.0x" or baseline.split("|")[9].strip() != "1.0x":
    fail(f"the baseline's speed-ups by relative MSE and display RMSE must be 1.0x: {baseline}")
print("convergence: CSV, plot and table as expected")
EOF
