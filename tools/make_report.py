#!/usr/bin/python3
"""Writes report/README.md from report/intro.md, report/figures.txt (captions) and
report/figures/timings.txt (each figure's settings, time and speed, as tools/render-report
measured them on this machine)."""
import os
import platform
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPORT = os.path.join(ROOT, "report")

# e.g. "ch03_diffuse: 400x225, 100 spp, max depth 50, seed 1, 2 threads: 1.171 s, 7.683 M samples/s"
SUMMARY = re.compile(
    r"(?P<size>\d+x\d+), (?P<spp>\d+) spp, max depth (?P<depth>\d+), seed (?P<seed>\d+), "
    r"(?P<threads>\d+) threads: (?P<seconds>[\d.]+) s, (?P<rate>[\d.]+) M samples/s")


def read_captions():
    captions = {}
    with open(os.path.join(REPORT, "figures.txt")) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                figure, chapter, _extra, caption = [p.strip() for p in line.split("|", 3)]
                captions[figure] = (chapter, caption)
    return captions


def read_timings():
    rows = []
    with open(os.path.join(REPORT, "figures", "timings.txt")) as f:
        for line in f:
            figure, extra, summary = line.rstrip("\n").split("|", 2)
            match = SUMMARY.search(summary)
            if not match:
                raise SystemExit(f"make_report: no timing in the output of {figure}: {summary}")
            rows.append((figure, extra, match.groupdict()))
    return rows


def benchmark_section():
    path = os.path.join(REPORT, "figures", "benchmarks.txt")
    if not os.path.exists(path):
        return []
    out = ["", "## Single-thread benchmarks against the book's code", "",
           "Measured by `tools/benchmark` with `--threads 1`. The book's figures are those its",
           "own code reaches on one core of this kind of machine (quoted in the issues; its",
           "`rand()` and scenes differ in detail, so compare orders of magnitude).", "",
           "| benchmark | settings | M samples/s (ours, 1 thread) | book's code | ours / book |",
           "|---|---|---|---|---|"]
    rates = {}
    with open(path) as f:
        for line in f:
            name, description, book, args, summary = line.rstrip("\n").split("|", 4)
            match = SUMMARY.search(summary)
            if not match:
                raise SystemExit(f"make_report: no timing in benchmark {name}: {summary}")
            rate = float(match["rate"])
            rates[name] = rate
            book_cell = f"{book}" if book else "-"
            ratio = f"{rate / float(book):.2f}" if book else "-"
            out.append(f"| {description} | `{args}` ({match['size']}, {match['spp']} spp) | "
                       f"{rate:.3f} | {book_cell} | {ratio} |")
    if "bouncing_bvh" in rates and "bouncing_list" in rates:
        out += ["", f"The BVH renders the bouncing spheres "
                    f"{rates['bouncing_bvh'] / rates['bouncing_list']:.1f} times faster than the "
                    "flat list on one thread, with byte-identical images (CTest "
                    "`bvh_matches_flat_list_ch07`)."]
    return out


def machine():
    cpu = platform.processor() or "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    compiler = subprocess.run(["g++", "--version"], capture_output=True, text=True).stdout
    return f"{os.cpu_count()} cores, {cpu}; {compiler.splitlines()[0] if compiler else 'g++'}"


def main():
    captions = read_captions()
    timings = read_timings()
    out = [open(os.path.join(REPORT, "intro.md")).read().rstrip(), ""]
    out += ["## Speed of every figure", "",
            f"Measured by `tools/render-report` on {machine()}, Release build, double scalars.",
            "A sample is one camera path.", "",
            "| figure | size | spp | max depth | threads | time (s) | M samples/s |",
            "|---|---|---|---|---|---|---|"]
    for figure, _extra, t in timings:
        out.append(f"| [{figure}](#{figure}) | {t['size']} | {t['spp']} | {t['depth']} | "
                   f"{t['threads']} | {t['seconds']} | {t['rate']} |")
    out += benchmark_section()
    out += ["", "## Figures", ""]
    for figure, extra, t in timings:
        chapter, caption = captions[figure]
        command = f"build/release/chapters/{chapter}" + (f" {extra}" if extra else "")
        out += [f"### {figure}", "",
                f"![{figure}](figures/{figure}.png)", "",
                caption, "",
                f"`{command}` ({t['size']}, {t['spp']} spp, max depth {t['depth']}, "
                f"seed {t['seed']}): {t['seconds']} s on {t['threads']} threads, "
                f"{t['rate']} M samples/s. Chapter notes: "
                f"[chapters/{chapter}](../chapters/{chapter}/README.md).", ""]
    with open(os.path.join(REPORT, "README.md"), "w") as f:
        f.write("\n".join(out))


if __name__ == "__main__":
    main()
