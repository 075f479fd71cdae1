#!/usr/bin/env bash
# tools/benchmark on tiny images (--quick): the JSON record of every scene, the line per scene
# for tools/make_report.py, and performance.md's table, with ratios that follow from the rates.
#   benchmark_tool.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 build=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$src/tools/benchmark" --quick --build "$build" --out-dir "$tmp" 2>"$tmp/log" ||
    { cat "$tmp/log"; echo "FAIL: tools/benchmark --quick failed"; exit 1; }
python3 - "$tmp" <<'EOF_CHECK'
import json, sys, os
d = sys.argv[1]
data = json.load(open(os.path.join(d, "benchmarks.json")))
problems = []
for key in ("commit", "date", "machine", "compiler", "runs", "scenes"):
    if key not in data:
        problems.append(f"benchmarks.json has no '{key}'")
names = [s["name"] for s in data.get("scenes", [])]
want = ["book1_final", "book1_bvh", "bouncing_bvh", "bouncing_list", "cornell_box", "book2_final"]
if names != want:
    problems.append(f"scenes {names}, want {want}")
for s in data.get("scenes", []):
    for t in ("one_thread", "two_threads"):
        run = s[t]
        if run["threads"] != (1 if t == "one_thread" else 2):
            problems.append(f"{s['name']}: {t} ran {run['threads']} threads")
        if not (run["samples_per_second"] > 0 and run["rays_per_second"] >= run["samples_per_second"]):
            problems.append(f"{s['name']}: {t}: rates {run['samples_per_second']}, {run['rays_per_second']}")
        if not run["max_rss_kib"] > 0:
            problems.append(f"{s['name']}: no peak memory")
    if s["book"]:
        want_ratio = s["one_thread"]["samples_per_second"] * 1e-6 / s["book"]
        if abs(s["ratio_to_book"] - want_ratio) > 1e-9 * want_ratio:
            problems.append(f"{s['name']}: ratio {s['ratio_to_book']}, want {want_ratio}")
    want_scaling = s["two_threads"]["samples_per_second"] / s["one_thread"]["samples_per_second"]
    if abs(s["scaling"] - want_scaling) > 1e-9 * want_scaling:
        problems.append(f"{s['name']}: scaling {s['scaling']}, want {want_scaling}")
lines = open(os.path.join(d, "benchmarks.txt")).read().splitlines()
if [l.split("|")[0] for l in lines] != want:
    problems.append("benchmarks.txt does not list the scenes in order")
for l in lines:
    record = json.loads(l.split("|", 4)[4])
    if record["settings"]["threads"] != 1:
        problems.append(f"benchmarks.txt: {l[:40]}... is not the one-thread run")
md = open(os.path.join(d, "performance.md")).read()
for s in data.get("scenes", []):
    if f"`{s['chapter']} {s['args']}`" not in md:
        problems.append(f"performance.md has no row for {s['name']}")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
EOF_CHECK
# --rewrite measures nothing and writes the same performance.md from the data files; without
# them it refuses in one line.
cp "$tmp/performance.md" "$tmp/measured.md"
rm "$tmp/performance.md"
"$src/tools/benchmark" --rewrite --build "$tmp/no-build" --out-dir "$tmp" 2>"$tmp/log" ||
    { cat "$tmp/log"; echo "FAIL: tools/benchmark --rewrite failed"; exit 1; }
cmp -s "$tmp/performance.md" "$tmp/measured.md" ||
    { diff "$tmp/measured.md" "$tmp/performance.md" | head; echo "FAIL: --rewrite differs"; exit 1; }
mkdir "$tmp/empty"
if "$src/tools/benchmark" --rewrite --build "$build" --out-dir "$tmp/empty" 2>"$tmp/log"; then
    echo "FAIL: --rewrite without data succeeded"; exit 1
fi
[ "$(wc -l <"$tmp/log")" -eq 1 ] && grep -q "benchmarks.json" "$tmp/log" ||
    { cat "$tmp/log"; echo "FAIL: --rewrite without data: not one line naming benchmarks.json"; exit 1; }
[ ! -e "$tmp/empty/performance.md" ] || { echo "FAIL: --rewrite without data wrote a file"; exit 1; }
echo "tools/benchmark --quick: 6 scenes, JSON, make_report lines and performance.md consistent; --rewrite reproduces it"
