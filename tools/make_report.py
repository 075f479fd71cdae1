#!/usr/bin/python3
"""Writes report/README.md from report/intro.md, report/figures.txt (captions) and
report/figures/timings.txt (each figure's settings, time and speed, as tools/render-report
measured them on this machine: each line ends with the run's --stats-out record).

report/figures.txt has two kinds of lines. A rendered figure, "figure | chapter | arguments |
caption", is shown under its own heading with its command line and time; one with an empty
caption is shown only inside the composite figure that uses it. A composite figure,
"figure | crops | SOURCE... WxH+X+Y ZOOM | caption", is made by tools/render-report from
figures rendered before it: the sources side by side, and below each the region WxH+X+Y enlarged
ZOOM times."""
import json
import os
import re
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in tools/
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from rtlib import provenance  # noqa: E402  (tools/rtlib: what the tools share)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPORT = os.path.join(ROOT, "report")


def timing(record, where):
    """What the report shows of a run, as text, from its --stats-out record (a JSON string)."""
    try:
        r = json.loads(record)
        s = r["settings"]
        return {"size": f"{s['width']}x{s['height']}", "spp": str(s["spp"]),
                "depth": str(s["max_depth"]), "seed": str(s["seed"]),
                "threads": str(s["threads"]), "seconds": f"{r['seconds']:.3f}",
                "rate": f"{r['samples_per_second'] * 1e-6:.3f}"}
    except (ValueError, KeyError, TypeError) as e:
        raise SystemExit(f"make_report: no --stats-out record for {where} ({e}): {record}")


def read_figures():
    """The lines of report/figures.txt in order: (figure, chapter, arguments, caption)."""
    figures = []
    with open(os.path.join(REPORT, "figures.txt")) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                figure, chapter, extra, caption = [p.strip() for p in line.split("|", 3)]
                figures.append((figure, chapter, extra, caption))
    return figures


def read_timings():
    rows = []
    with open(os.path.join(REPORT, "figures", "timings.txt")) as f:
        for line in f:
            figure, extra, record = line.rstrip("\n").split("|", 2)
            rows.append((figure, extra, timing(record, figure)))
    return rows


def anchor(figure):
    """The link target of a figure's heading, as GitHub makes it (a dot is dropped)."""
    return "#" + re.sub(r"[^a-z0-9_ -]", "", figure.lower()).replace(" ", "-")


def crops_parts(extra):
    """The sources, region and zoom of a composite figure's arguments."""
    parts = extra.split()
    size, x, y = re.fullmatch(r"(\d+x\d+)\+(\d+)\+(\d+)", parts[-2]).groups()
    return parts[:-2], size, x, y, parts[-1]


def run_line(chapter, extra, t):
    """The command line of a rendered figure, with its settings and time."""
    command = f"build/release/chapters/{chapter}" + (f" {extra}" if extra else "")
    return (f"`{command}` ({t['size']}, {t['spp']} spp, max depth {t['depth']}, "
            f"seed {t['seed']}): {t['seconds']} s on {t['threads']} threads, "
            f"{t['rate']} M samples/s.")


def benchmark_section():
    path = os.path.join(REPORT, "figures", "benchmarks.txt")
    if not os.path.exists(path):
        return []
    out = ["", "## Single-thread benchmarks against the book's code", "",
           "Measured by `tools/benchmark` with `--threads 1`. The book's column is the speed of",
           "the book's own code (*Ray Tracing in One Weekend* series, v4.0.0-alpha.1) on one core",
           "of this kind of machine, at the book's settings: book 1's final scene at 1200x675,",
           "10 spp, max depth 20 (487 spheres, no acceleration structure), and book 2's bouncing",
           "spheres at 400x225, 200 spp, max depth 50 with its BVH; `tools/benchmark` lists both.",
           "Its `rand()` and scenes differ from ours in detail, so compare orders of magnitude.", "",
           "| benchmark | settings | M samples/s (ours, 1 thread) | book's code | ours / book |",
           "|---|---|---|---|---|"]
    rates = {}
    with open(path) as f:
        for line in f:
            name, description, book, args, record = line.rstrip("\n").split("|", 4)
            t = timing(record, f"benchmark {name}")
            rate = float(t["rate"])
            rates[name] = rate
            book_cell = f"{book}" if book else "-"
            ratio = f"{rate / float(book):.2f}" if book else "-"
            out.append(f"| {description} | `{args}` ({t['size']}, {t['spp']} spp) | "
                       f"{rate:.3f} | {book_cell} | {ratio} |")
    if "bouncing_bvh" in rates and "bouncing_list" in rates:
        out += ["", f"The BVH renders the bouncing spheres "
                    f"{rates['bouncing_bvh'] / rates['bouncing_list']:.1f} times faster than the "
                    "flat list on one thread, with byte-identical images (CTest "
                    "`bvh_matches_flat_list_ch07`)."]
    return out


# The scenes of the "Speed against error" section, as tools/render-report measures them with
# tools/convergence (report/convergence/SCENE.*), and what each is.
CONVERGENCE_SCENES = [("ch10", "book 2's simple light"), ("ch11", "the Cornell box"),
                      ("ch12", "the Cornell smoke"), ("ch13", "book 2's final scene")]
# The targets: the Cornell box's RMSE within 1.7 s (1/40 of the book's code's 66.7 s),
# the smoke's speed-up at the baseline's 1024-spp error.
CORNELL_RMSE, CORNELL_SECONDS, SMOKE_SPEED_UP = 0.0246, 1.7, 10


def best_method(summary, key):
    """The method with the least seconds by key(method), and those seconds (None if none)."""
    timed = [(key(m), m) for m in summary["methods"] if key(m) is not None]
    return min(timed, key=lambda t: t[0], default=(None, None))


def convergence_section():
    folder = os.path.join(REPORT, "convergence")
    runs = []
    for scene, what in CONVERGENCE_SCENES:
        path = os.path.join(folder, f"{scene}.json")
        if os.path.exists(path):
            with open(path) as f:
                runs.append((scene, what, json.load(f)))
    if not runs:
        return []
    out = ["", open(os.path.join(REPORT, "speed_against_error.md")).read().rstrip(), ""]
    out += ["| scene | baseline: path + independent | fastest to the baseline's RMSE | "
            "its time | speed-up |", "|---|---|---|---|---|"]
    summaries = {}
    for scene, what, run in runs:
        s = run["summary"]
        summaries[scene] = s
        seconds, m = best_method(s, lambda m: m.get("time_to_baseline_error"))
        out.append(f"| [{scene}]({anchor(f'Scene {scene}: {what}')}) ({what}) | "
                   f"RMSE {s['baseline_rmse']:.4f} at {s['max_spp']} spp in "
                   f"{s['baseline_seconds']:.2f} s | "
                   + (f"{m['method']} | {seconds:.2f} s | {m['speed_up']:.1f}x |" if m
                      else "- | - | - |"))
    out.append("")
    if "ch11" in summaries:
        key = f"{CORNELL_RMSE:g}"
        seconds, m = best_method(summaries["ch11"],
                                 lambda m: m["targets"].get(key, {}).get("seconds"))
        if m:
            verdict = "met" if seconds <= CORNELL_SECONDS else "not met"
            out.append(f"Target (a), the Cornell box: RMSE {CORNELL_RMSE} within "
                       f"{CORNELL_SECONDS} s. The fastest, {m['method']}, takes {seconds:.2f} s: "
                       f"{verdict}.")
        else:
            out.append(f"Target (a), the Cornell box: no method reached RMSE {CORNELL_RMSE}.")
    if "ch12" in summaries:
        _seconds, m = best_method(summaries["ch12"], lambda m: m.get("time_to_baseline_error"))
        if m:
            verdict = "met" if m["speed_up"] >= SMOKE_SPEED_UP else "not met"
            out.append(f"Target (b), the smoke: the baseline's 1024-spp RMSE at least "
                       f"{SMOKE_SPEED_UP} times sooner. The fastest, {m['method']}, is "
                       f"{m['speed_up']:.1f} times sooner: {verdict}.")
    for scene, what, run in runs:
        out += ["", f"### Scene {scene}: {what}", "",
                f"![RMSE against seconds, {scene}](convergence/{scene}.png)", "",
                open(os.path.join(folder, f"{scene}.md")).read().rstrip()]
        if run.get("equal_time") and os.path.exists(os.path.join(folder,
                                                                 f"{scene}-equal-time.png")):
            left, right = run["equal_time"]
            out += ["", f"![{left['method']} beside {right['method']} in equal time]"
                        f"(convergence/{scene}-equal-time.png)", "",
                    f"Left: {left['method']}; right: {right['method']}; the same seconds "
                    "(spp, times and RMSE above)."]
        out += ["", "Data: [CSV](convergence/{0}.csv), [record](convergence/{0}.json); "
                    "command: `{1}`.".format(scene, " ".join(run["command"]))]
    return out


def machine():
    """The machine, and the compiler of build/release (the build tools/render-report renders
    the figures with)."""
    built = provenance.compiler(os.path.join(ROOT, "build", "release"))
    return f"{os.cpu_count()} cores, {provenance.cpu()}; {built['compiler']}"


MACHINE = os.path.join(REPORT, "figures", "machine.txt")


def main():
    # The machine the figures were timed on is recorded when they are rendered: the report may
    # be written again later, elsewhere (after tools/benchmark, say), and must not claim this one.
    if sys.argv[1:] == ["--record-machine"]:
        with open(MACHINE, "w") as f:
            f.write(machine() + "\n")
        return
    try:
        with open(MACHINE) as f:
            timed_on = f.read().strip()
    except OSError:
        raise SystemExit(f"make_report: {MACHINE} is missing: run tools/render-report")
    figures = read_figures()
    timings = {figure: (extra, t) for figure, extra, t in read_timings()}
    for figure, chapter, _extra, _caption in figures:
        if chapter != "crops" and figure not in timings:
            raise SystemExit(f"make_report: {figure} has no timing: run tools/render-report")
    # Where each rendered figure is shown: under its own heading, or in a composite using it.
    shown_in = {figure: figure for figure, _chapter, _extra, caption in figures if caption}
    for figure, chapter, extra, _caption in figures:
        if chapter == "crops":
            for source in crops_parts(extra)[0]:
                shown_in.setdefault(source, figure)

    out = [open(os.path.join(REPORT, "intro.md")).read().rstrip(), ""]
    out += ["## Speed of every figure", "",
            f"Measured by `tools/render-report` on {timed_on}, Release build, double scalars.",
            "A sample is one camera path.", "",
            "| figure | size | spp | max depth | threads | time (s) | M samples/s |",
            "|---|---|---|---|---|---|---|"]
    for figure, _chapter, _extra, _caption in figures:
        if figure not in timings:
            continue
        t = timings[figure][1]
        out.append(f"| [{figure}]({anchor(shown_in.get(figure, figure))}) | {t['size']} | "
                   f"{t['spp']} | "
                   f"{t['depth']} | {t['threads']} | {t['seconds']} | {t['rate']} |")
    out += benchmark_section()
    out += convergence_section()
    out += ["", "## Figures", ""]
    for figure, chapter, extra, caption in figures:
        if chapter == "crops":
            sources, size, x, y, zoom = crops_parts(extra)
            out += [f"### {figure}", "", f"![{figure}](figures/{figure}.png)", "", caption, ""]
            made = ", ".join(f"[{s}]({anchor(s)})" if shown_in.get(s) == s else f"`{s}`"
                             for s in sources)
            out += [f"Made by `tools/render-report` with `oiiotool` from {made}: side by side, "
                    f"and below each the {size} pixels at ({x}, {y}), outlined in red, enlarged "
                    f"{zoom} times (nearest pixel).", ""]
            for source in sources:
                if shown_in.get(source) != source and source in timings:
                    src_chapter = next(c for f, c, _e, _c in figures if f == source)
                    src_extra, t = timings[source]
                    out += [f"`{source}`: " + run_line(src_chapter, src_extra, t), ""]
            out += [f"Chapter notes: [chapters/{chapter_of(figures, sources[0])}]"
                    f"(../chapters/{chapter_of(figures, sources[0])}/README.md).", ""]
            continue
        if not caption:
            continue
        extra, t = timings[figure]
        out += [f"### {figure}", "",
                f"![{figure}](figures/{figure}.png)", "",
                caption, "",
                run_line(chapter, extra, t) + " Chapter notes: "
                f"[chapters/{chapter}](../chapters/{chapter}/README.md).", ""]
    with open(os.path.join(REPORT, "README.md"), "w") as f:
        f.write("\n".join(out))


def chapter_of(figures, figure):
    return next(c for f, c, _e, _c in figures if f == figure)


if __name__ == "__main__":
    main()
