#!/usr/bin/env bash
# tools/benchmark on tiny images (--quick): the JSON record of every scene, the line per scene
# for tools/make-report, and performance.md's table, with ratios that follow from the rates.
#   benchmark_tool.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 build=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$src/tools/benchmark" --quick --build "$build" --out-dir "$tmp" 2>"$tmp/log" ||
    { cat "$tmp/log"; echo "FAIL: tools/benchmark --quick failed"; exit 1; }
python3 - "$tmp" "$src" <<'EOF_CHECK'
import json, sys, os
d, src = sys.argv[1], sys.argv[2]
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
# What the targets ask of one ray: each row restated from the rates and the committed Embree
# anchor (report/data/embree_anchor.json), book 1 weighting one camera ray per sample.
anchor_path = os.path.join(src, "report", "data", "embree_anchor.json")
anchor = {b["batch"]: b for b in json.load(open(anchor_path))["batches"]} if os.path.exists(anchor_path) else {}
batches = {"book1_bvh": ("book1-camera", "book1-bounce"), "bouncing_bvh": ("ch07-recorded",),
           "cornell_box": ("ch11-recorded",), "book2_final": ("ch13-recorded",)}
section = md.split("## What the per-core targets ask of one ray", 1)
rows_checked = 0
for s in data.get("scenes", []):
    names = batches.get(s["name"])
    if not (s["target"] and names and all(n in anchor for n in names)):
        continue
    if len(section) < 2:
        problems.append("performance.md has no table of what the targets ask of one ray")
        break
    row = [l for l in section[1].splitlines() if l.startswith(f"| {s['description']} |")]
    if len(row) != 1:
        problems.append(f"what the targets ask: {len(row)} rows for {s['name']}")
        continue
    cells = [float(c) for c in row[0].strip("|").split("|")[1:]]
    one = s["one_thread"]
    rps = one["rays_per_second"] / one["samples_per_second"]
    needed = s["target"] * s["book"] * 1e6
    ns = {who: [1e9 / anchor[n][f"{who}_rays_per_second"] for n in names] for who in ("embree", "ours")}
    for who, v in ns.items():
        ns[who] = v[0] if len(v) == 1 else v[0] / rps + v[1] * (1 - 1 / rps)
    allowed = 1e9 / (needed * rps)
    want = [needed * 1e-6, rps, needed * rps * 1e-6, allowed, ns["embree"], allowed - ns["embree"],
            1e9 / one["rays_per_second"], ns["ours"], 1e9 / one["rays_per_second"] - ns["ours"]]
    tolerance = [0.006, 0.006, 0.006, 0.6, 0.6, 1.1, 0.6, 0.6, 1.1]  # the table's rounding
    for k, (got, w, tol) in enumerate(zip(cells, want, tolerance)):
        if abs(got - w) > tol:
            problems.append(f"what the targets ask, {s['name']}, column {k + 2}: {got}, want {w:.3f}")
    rows_checked += 1
if anchor and rows_checked != 4:
    problems.append(f"what the targets ask: {rows_checked} scenes checked, want 4")
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
# --versus: the same build against itself, side by side: every scene, a ratio per round, their
# median, and the section of performance.md written from them.
"$src/tools/benchmark" --versus "$build" --quick --build "$build" --out-dir "$tmp" 2>"$tmp/log" ||
    { cat "$tmp/log"; echo "FAIL: tools/benchmark --versus failed"; exit 1; }
python3 - "$tmp" <<'EOF_VERSUS'
import json, sys, os
d = sys.argv[1]
v = json.load(open(os.path.join(d, "versus.json")))
problems = []
if [s["name"] for s in v["scenes"]] != ["book1_final", "book1_bvh", "bouncing_bvh",
                                         "bouncing_list", "cornell_box", "book2_final"]:
    problems.append("versus.json: not the six scenes")
for s in v["scenes"]:
    want = [n / o for n, o in zip(s["new_samples_per_second"], s["old_samples_per_second"])]
    if s["ratios"] != want or len(want) != v["runs"] or not all(r > 0 for r in want):
        problems.append(f"versus {s['name']}: ratios {s['ratios']}, want {want}")
    if s["median_ratio"] not in s["ratios"]:
        problems.append(f"versus {s['name']}: median {s['median_ratio']} is no round's ratio")
md = open(os.path.join(d, "performance.md")).read()
if "## Side by side with an earlier build" not in md or f"**{v['scenes'][0]['median_ratio']:.3f}**" not in md:
    problems.append("performance.md has no side-by-side section from versus.json")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
EOF_VERSUS
# Against a build older than chapter 17 (here: one without its program), --versus runs each
# scene through the program that build has: the chapter's own.
mkdir -p "$tmp/old-build/chapters"
for chapter in ch06_defocus ch07_motion_blur ch11_instances ch13_final; do
    ln -s "$build/chapters/$chapter" "$tmp/old-build/chapters/$chapter"
done
"$src/tools/benchmark" --versus "$tmp/old-build" --quick --build "$build" --out-dir "$tmp" 2>"$tmp/log" ||
    { cat "$tmp/log"; echo "FAIL: tools/benchmark --versus against a build before ch17 failed"; exit 1; }
python3 - "$tmp" <<'EOF_EARLIER'
import json, sys, os
v = json.load(open(os.path.join(sys.argv[1], "versus.json")))
want = {"book1_final": "ch06_defocus --scene final", "book1_bvh": "ch07_motion_blur --scene ch06-final",
        "bouncing_bvh": "ch07_motion_blur --width", "bouncing_list": "ch07_motion_blur --width",
        "cornell_box": "ch11_instances --width", "book2_final": "ch13_final --width"}
problems = [f"versus {s['name']}: earlier command {s['old_command']!r}, want {want[s['name']]!r}..."
            for s in v["scenes"] if not s["old_command"].startswith(want[s["name"]])]
problems += [f"versus {s['name']}: new command {s['chapter']}" for s in v["scenes"]
             if s["name"] not in ("book1_final", "bouncing_list") and s["chapter"] != "ch17_fast_traversal"]
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
EOF_EARLIER
if "$src/tools/benchmark" --versus "$tmp/no-build" --quick --build "$build" --out-dir "$tmp" 2>"$tmp/log"; then
    echo "FAIL: --versus without an old build succeeded"; exit 1
fi
[ "$(wc -l <"$tmp/log")" -eq 1 ] && grep -q "no-build" "$tmp/log" ||
    { cat "$tmp/log"; echo "FAIL: --versus without a build: not one line naming it"; exit 1; }
echo "tools/benchmark --quick: 6 scenes, JSON, make-report lines and performance.md consistent (what the targets ask of one ray restated); --rewrite reproduces it; --versus side by side, also against a build before ch17"
