#!/usr/bin/env bash
# tools/convergence --cycles --two-seeds without Blender: a stand-in `blender` on the PATH runs
# bench/cycles_anchor.py's command line through our own renderer (path + independent, written as
# OpenEXR, as Blender writes), so the tool's side of the anchor is tested where Blender is not
# installed (the tests never install it).
#   convergence_cycles.sh CH17_FAST_TRAVERSAL
# Checks: the stand-in is called with the script and the scene, size, spp, seed and threads, once
# per render and seed; the CSV's noise column is the RMS of the two seeds' difference over sqrt 2,
# computed here from renders of our own; "Cycles" (here our path tracer) is the same scene within
# noise; the table says how far ahead each method is, and the stand-in, which renders exactly as
# the baseline, is judged 1.00x behind it by noise; --cycles on a scene the script does not build
# and a failing Blender are refused (exit code 2, one line).
set -euo pipefail
exe=$1
here=$(cd "$(dirname "$0")" && pwd)
convergence=$here/../../tools/convergence
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() {
    echo "FAIL: $*"
    exit 1
}

mkdir bin
cat >bin/blender <<EOF
#!/usr/bin/env bash
# The stand-in: bench/cycles_anchor.py's arguments follow "--".
echo "\$*" >>"$work/calls.txt"
[ -n "\${BLENDER_FAILS:-}" ] && { echo "Error: out of memory"; exit 1; }
while [ "\$1" != "--" ]; do shift; done; shift
while [ \$# -gt 0 ]; do
    case "\$1" in
        --scene) scene=\$2 ;; --width) width=\$2 ;; --spp) spp=\$2 ;; --seed) seed=\$2 ;;
        --out) out=\$2 ;; --stats-out) stats=\$2 ;; --threads) ;;
    esac
    shift 2
done
"$exe" --scene "\$scene" --integrator path --sampler independent --width "\$width" \
    --spp "\$spp" --seed "\$seed" --quiet --out "\$out"
echo '{"render_seconds": 0.25, "settings": {}, "scene": "'"\$scene"'", "blender": "stand-in"}' \
    >"\$stats"
EOF
chmod +x bin/blender
export PATH=$work/bin:$PATH
common=(--width 32 --reference-dir refs --exe "$exe")

# A scene the script does not build is refused before anything runs.
if "$convergence" ch10 "${common[@]}" --cycles 2>err.txt; then
    fail "--cycles on ch10 was accepted"
else
    code=$?
fi
[ "$code" -eq 2 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "ch11, ch12" err.txt ||
    fail "--cycles on ch10 gave exit code $code and: $(cat err.txt)"
[ ! -e calls.txt ] || fail "a refused run called Blender"

"$convergence" ch11 "${common[@]}" --make-reference --spp 64 2>log.txt ||
    fail "making the reference failed: $(tail -3 log.txt)"

# A failing Blender: one error line (after the progress of the renders before it) with
# Blender's last line, exit code 2, nothing written.
if BLENDER_FAILS=1 "$convergence" ch11 "${common[@]}" --cycles --max-spp 2 \
    --methods path:independent --out-dir bad 2>err.txt; then
    fail "a failing Blender was not noticed"
else
    code=$?
fi
[ "$code" -eq 2 ] && [ "$(grep -c "error:" err.txt)" -eq 1 ] &&
    tail -1 err.txt | grep -q "Blender must render, got exit code 1: Error: out of memory" ||
    fail "a failing Blender gave exit code $code and: $(cat err.txt)"
[ ! -e bad ] || fail "a run with a failing Blender wrote $(ls bad)"
rm -f calls.txt

"$convergence" ch11 "${common[@]}" --cycles --two-seeds --max-spp 8 --stop spp \
    --methods path:independent,mis:sobol --out-dir out 2>log.txt ||
    fail "a run with --cycles failed: $(tail -3 log.txt)"
for spp in 1 2 4 8; do
    for seed in 1 2; do
        call="-P .*bench/cycles_anchor.py -- --scene ch11 --width 32 --spp $spp --seed $seed"
        grep -q -- "$call --threads " calls.txt ||
            fail "Blender was not called for $spp spp, seed $seed: $(cat calls.txt)"
    done
done
"$exe" --scene ch11 --integrator mis --sampler sobol --width 32 --spp 8 --seed 1 --quiet --out a.pfm
"$exe" --scene ch11 --integrator mis --sampler sobol --width 32 --spp 8 --seed 2 --quiet --out b.pfm

/usr/bin/python3 - "$here/../../tools" <<'EOF' || exit 1
import csv, math, sys

sys.dont_write_bytecode = True
sys.path.insert(0, sys.argv[1])
from rtlib import pfm

def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)

with open("out/ch11.csv") as f:
    rows = list(csv.DictReader(f))
curves = {}
for r in rows:
    curves.setdefault((r["integrator"], r["sampler"]), []).append(r)
if set(curves) != {("path", "independent"), ("mis", "sobol"), ("cycles", "pmj")}:
    fail(f"the CSV must hold our two methods and Cycles' curve, got {sorted(curves)}")
if [int(r["spp"]) for r in curves[("cycles", "pmj")]] != [1, 2, 4, 8]:
    fail(f"Cycles' curve must double from 1 to 8 spp: {curves[('cycles', 'pmj')]}")
for r in curves[("cycles", "pmj")]:
    if float(r["seconds"]) != 0.25 or not float(r["process_seconds"]) > 0:
        fail(f"Cycles' seconds must be its render time (0.25) beside its process time: {r}")
a, b = pfm.read("a.pfm").pixels, pfm.read("b.pfm").pixels
noise = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / len(a) / 2)
got = float(curves[("mis", "sobol")][-1]["noise"])
if abs(got - noise) > 1e-4 * noise:
    fail(f"noise of mis + sobol at 8 spp: the CSV says {got}, computed here {noise}")
# The stand-in renders as the baseline does, image for image: equal noise at every spp.
for ours, theirs in zip(curves[("path", "independent")], curves[("cycles", "pmj")]):
    if ours["noise"] != theirs["noise"]:
        fail(f"the stand-in's noise must equal the baseline's: {ours} against {theirs}")

table = open("out/ch11.md").read()
for text in ("speed-up by noise", "Beside Cycles", "| mis + sobol |", "Same scene? Cycles + PMJ",
             "| path + independent | "):
    if text not in table:
        fail(f"the table must say '{text}':\n{table}")
line = next(l for l in table.splitlines() if l.startswith("| path + independent | ") and
            l.count("|") == 6)
# path + independent's own time to its noise at 8 spp, against the stand-in's 0.25 s there.
if line.split("|")[3].strip() == "-":
    fail(f"the baseline's ratio to Cycles by noise must be given: {line}")
agreement = next(l for l in table.splitlines() if l.startswith("Same scene? Cycles + PMJ"))
if "0.0 % of the blocks beyond noise" not in agreement:
    fail(f"our own renders must be judged the same scene: {agreement}")
print("convergence --cycles: CSV, noise, comparison and agreement as expected")
EOF
