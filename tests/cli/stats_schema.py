#!/usr/bin/python3
"""The record of a run (--stats-out FILE.json) has every key with the right type, and values
that agree with each other and with the run's settings.
  stats_schema.py EXE INTEGRATOR [SAMPLER]
INTEGRATOR is the name the chapter's estimator gives: sky traces no ray into the world, normals
exactly one per camera sample, path (and mis) at least one. SAMPLER is the program's default
sampler's name (independent unless given). A program with adaptive sampling (--noise-threshold)
also records a run whose pixels stop early: camera_samples counts the samples they took."""
import json
import math
import os
import subprocess
import sys
import tempfile

# Key: type, for the record and its settings (bool is not an int here).
SCHEMA = {"program": str, "integrator": str, "sampler": str, "scalar": str, "options": dict,
          "settings": dict, "camera_samples": int, "rays": int, "seconds": float,
          "process_seconds": float, "samples_per_second": float, "rays_per_second": float,
          "outputs": list, "variance_out": (str, type(None)), "command": list}
SETTINGS = {"width": int, "height": int, "spp": int, "max_depth": int, "seed": int,
            "threads": int, "crop": list, "samples": list}

failures = []
SAMPLER = "independent"  # main() sets it from the command line


def check(ok, what):
    if not ok:
        failures.append(what)


def has_type(value, kind):
    if isinstance(value, bool):
        return kind is bool
    if kind is float:
        return isinstance(value, (int, float))  # JSON writes 2.0 as 2
    return isinstance(value, kind)


def check_record(path, exe, integrator, args, expect):
    with open(path) as f:
        record = json.load(f)
    for table, schema in ((record, SCHEMA), (record.get("settings", {}), SETTINGS)):
        for key, kind in schema.items():
            check(key in table, f"{path}: no key '{key}'")
            if key in table:
                check(has_type(table[key], kind), f"{path}: '{key}' is {table[key]!r}, not {kind}")
    if failures:
        return
    s = record["settings"]
    program = os.path.basename(exe)
    check(record["program"] == program, f"program {record['program']!r}, not {program!r}")
    check(record["integrator"] == integrator, f"integrator {record['integrator']!r}")
    check(record["sampler"] == SAMPLER, f"sampler {record['sampler']!r}, not {SAMPLER!r}")
    check(record["scalar"] in ("double", "float"), f"scalar {record['scalar']!r}")
    check(all(isinstance(v, str) for v in record["options"].values()), "options not strings")
    for key, value in expect.items():
        check(s[key] == value, f"settings.{key} is {s[key]!r}, not {value!r}")
    x0, y0, x1, y1 = s["crop"]
    first, end = s["samples"]
    check(0 <= x0 < x1 <= s["width"] and 0 <= y0 < y1 <= s["height"], f"crop {s['crop']}")
    check(0 <= first < end <= s["spp"], f"samples {s['samples']}")
    check(s["threads"] >= 1, f"threads {s['threads']}")
    samples = (x1 - x0) * (y1 - y0) * (end - first)
    if "--noise-threshold" in args:  # adaptive sampling: pixels may stop after --min-spp
        least = (x1 - x0) * (y1 - y0) * min(int(args[args.index("--min-spp") + 1]), end)
        check(least <= record["camera_samples"] <= samples,
              f"camera_samples {record['camera_samples']}, not in [{least}, {samples}]")
    else:
        check(record["camera_samples"] == samples,
              f"camera_samples {record['camera_samples']}, not {samples} (crop x samples)")
    rays, camera_samples = record["rays"], record["camera_samples"]
    if integrator == "sky":
        check(rays == 0, f"rays {rays}: the sky alone traces none")
    elif integrator == "normals":
        check(rays == camera_samples, f"rays {rays}, not one per camera sample ({camera_samples})")
    else:
        check(rays >= camera_samples, f"rays {rays} < camera_samples {camera_samples}")
    seconds = record["seconds"]
    check(0 < seconds <= record["process_seconds"],
          f"seconds {seconds}, process_seconds {record['process_seconds']}")
    check(math.isclose(record["samples_per_second"], camera_samples / seconds, rel_tol=1e-9),
          f"samples_per_second {record['samples_per_second']} is not camera_samples / seconds")
    check(math.isclose(record["rays_per_second"], rays / seconds, rel_tol=1e-9, abs_tol=1e-9),
          f"rays_per_second {record['rays_per_second']} is not rays / seconds")
    check(record["command"][1:] == args, f"command {record['command']}, not {args}")


def run(exe, args):
    result = subprocess.run([exe, *args], capture_output=True, text=True)
    check(result.returncode == 0, f"{args}: exit code {result.returncode}: {result.stderr}")
    return result.returncode == 0


def main():
    global SAMPLER
    exe, integrator = os.path.abspath(sys.argv[1]), sys.argv[2]
    SAMPLER = sys.argv[3] if len(sys.argv) > 3 else "independent"
    with tempfile.TemporaryDirectory() as work:
        os.chdir(work)
        # The whole image.
        args = ["--quiet", "--width", "24", "--spp", "3", "--seed", "7", "--threads", "2",
                "--out", "a.png", "--out", "a.pfm", "--stats-out", "a.json"]
        if run(exe, args):
            check_record("a.json", exe, integrator, args,
                         {"width": 24, "spp": 3, "seed": 7, "threads": 2, "samples": [0, 3]})
            with open("a.json") as f:
                record = json.load(f)
            height = record["settings"]["height"]
            check(record["settings"]["crop"] == [0, 0, 24, height], "crop of the whole image")
            check(record["outputs"] == ["a.png", "a.pfm"], f"outputs {record['outputs']}")
            check(record["variance_out"] is None, "variance_out given without --variance-out")
        # A part, written into a folder: its paths are relative to the record's folder.
        os.mkdir("part")
        args = ["--quiet", "--width", "24", "--spp", "5", "--crop", "3,1,20,4", "--samples",
                "1:4", "--out", "part/b.pfm", "--variance-out", "part/b-var.pfm",
                "--stats-out", "part/b.json"]
        if run(exe, args):
            check_record("part/b.json", exe, integrator, args,
                         {"width": 24, "spp": 5, "crop": [3, 1, 20, 4], "samples": [1, 4]})
            with open("part/b.json") as f:
                record = json.load(f)
            check(record["camera_samples"] == 17 * 3 * 3, "camera_samples of the part")
            check(record["outputs"] == ["b.pfm"], f"outputs {record['outputs']}")
            check(record["variance_out"] == "b-var.pfm", f"variance_out {record['variance_out']}")
        # Adaptive sampling (chapter 17 on): the samples the pixels took, fewer than all.
        helps = subprocess.run([exe, "--help"], capture_output=True, text=True).stdout
        if "--noise-threshold" in helps:
            args = ["--quiet", "--width", "24", "--spp", "64", "--noise-threshold", "0.5",
                    "--min-spp", "4", "--out", "c.pfm", "--stats-out", "c.json"]
            if run(exe, args):
                check_record("c.json", exe, integrator, args, {"width": 24, "spp": 64})
                with open("c.json") as f:
                    record = json.load(f)
                pixels = 24 * record["settings"]["height"]
                check(record["camera_samples"] < pixels * 64,
                      f"camera_samples {record['camera_samples']}: no pixel stopped early at "
                      "a threshold of half of white")
    for failure in failures:
        print(f"FAIL: {failure}")
    if not failures:
        print(f"ok: {os.path.basename(exe)}'s --stats-out records have every key, consistent")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
