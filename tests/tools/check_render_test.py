#!/usr/bin/python3
"""Tests of tools/check-render: the verdicts on renders of the right scene, on image-level
mistakes made from a right render, and on bad input.

  check_render_test.py match SCENE WIDTH SPP...   our own renders (another seed than the
                                                  checker's) at each spp: judged a match,
                                                  as a book-style PPM and as a PFM
  check_render_test.py mistakes SCENE WIDTH SPP   gamma missing or twice, sRGB for gamma 2,
                                                  flipped, mirrored, darker by 0.9, shifted a
                                                  pixel, speckled: each judged a mismatch and
                                                  named
  check_render_test.py layout SCENE WIDTH SPP     our render of another layout (as where rand()
                                                  differs): --layout other judges it a match and
                                                  its gamma mistake a mismatch, named; without
                                                  --layout the cause named is the layout
  check_render_test.py zoo-images CHAPTER        the zoo catalogue's images of the chapter's
                                                  mistakes and its correct image (64 spp, sRGB):
                                                  the correct one judged a match; a mistake
                                                  whose trait the checker names in its own
                                                  words (SHARED) named so; no other said to
                                                  have it
  check_render_test.py bad-input                  each trouble row: exit 2, one line, no map
  check_render_test.py false-alarms SCENES WIDTH SPP N [LIMIT [BUDGET]]
                                                  N renders with independent seeds of each scene
                                                  (a comma list, or all): the share judged a
                                                  mismatch (the statistic promises at most 1e-3
                                                  per image); fails above LIMIT (1) in N; with
                                                  BUDGET (the checker's --budget), ours are
                                                  made at fewer spp and scaled

A "student's" render here is our chapter program's, drawn with another seed than the
checker's own renders, with the book's glass and texture forms (the checker's defaults), and
written as the book writes it (P3, gamma 2)."""
import os
import shutil
import subprocess
import sys
import tempfile
import tomllib

import numpy as np

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.realpath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from rtlib import display_codes, pfm  # noqa: E402

import checker_in_process  # noqa: E402

CHECK = checker_in_process.CHECK
TEXTURE = os.path.join(ROOT, "assets", "globe.png")
failures = []


def fail(message):
    print(f"FAIL: {message}")
    failures.append(message)


def scenes():
    with open(os.path.join(ROOT, "tools", "check", "scenes.toml"), "rb") as f:
        return tomllib.load(f)


def render(scene, width, spp, seed, out, layout_seed=None):
    """Our render of SCENE as a student's program would make it: linear pixels."""
    entry = scenes()[scene]
    exe = os.path.join(ROOT, "build", "release", "chapters", entry["program"])
    command = [exe, *entry["args"], "--width", str(width), "--spp", str(spp), "--seed",
               str(seed), "--max-depth", str(entry["max_depth"]), "--quiet", "--out", out]
    if entry.get("glass"):
        command += ["--fresnel", "book"]
    if entry.get("texture"):
        command += ["--texture", TEXTURE, "--texture-decoding", "book"]
    if layout_seed is not None:
        command += ["--layout-seed", str(layout_seed)]
    subprocess.run(command, check=True)
    image = pfm.read(out)
    return np.asarray(pfm.as_array(image), dtype=np.float64).reshape(image.height,
                                                                      image.width, 3)


def book_encoding(scene):
    """How the book writes SCENE's image: linear before its gamma section, gamma 2 after."""
    return {"linear": "linear8"}.get(scenes()[scene]["encoding"], scenes()[scene]["encoding"])


def write_ppm(path, codes):
    """P3 text, as the book's program writes it."""
    h, w, _ = codes.shape
    with open(path, "w") as f:
        f.write(f"P3\n{w} {h}\n255\n")
        for row in codes.astype(int):
            f.write("\n".join(f"{r} {g} {b}" for r, g, b in row) + "\n")


def write_pfm(path, linear):
    h, w, _ = linear.shape
    with open(path, "wb") as f:
        f.write(f"PF\n{w} {h}\n-1.0\n".encode())
        f.write(np.ascontiguousarray(linear[::-1], dtype="<f4").tobytes())


def checker(scene, image, *flags):
    extra = ["--texture", TEXTURE] if scenes()[scene].get("texture") else []
    return checker_in_process.run([scene, image, *extra, *flags])


def match(scene, width, spps):
    with tempfile.TemporaryDirectory() as d:
        for spp in spps:
            linear = render(scene, width, spp, 1, os.path.join(d, "ours.pfm"))
            ppm, own_pfm = os.path.join(d, "student.ppm"), os.path.join(d, "student.pfm")
            write_ppm(ppm, display_codes.encode(linear, book_encoding(scene)))
            write_pfm(own_pfm, linear)
            for image in (ppm, own_pfm):
                code, out, err = checker(scene, image, "--spp", str(spp))
                verdict = next((line for line in out.splitlines() if "verdict" in line), err)
                if code != 0:
                    fail(f"{scene} {width} wide, {spp} spp, {os.path.basename(image)}: "
                         f"exit {code}: {verdict}\n{out}")
                else:
                    print(f"ok: {scene} {width} wide, {spp} spp, "
                          f"{os.path.basename(image)}: {verdict.strip()}")


MISTAKES = [
    # name, how the image is made from the linear render, words the likely cause must hold
    ("gamma missing", lambda x, rng: display_codes.encode(x, "linear8"), "gamma missing"),
    ("gamma twice", lambda x, rng: display_codes.encode(x, "gamma4"), "gamma applied twice"),
    ("sRGB for gamma 2", lambda x, rng: display_codes.encode(x, "srgb"), "sRGB"),
    ("upside down", lambda x, rng: display_codes.encode(x[::-1], "gamma2"), "upside down"),
    ("mirrored", lambda x, rng: display_codes.encode(x[:, ::-1], "gamma2"), "mirrored"),
    ("darker by 0.9", lambda x, rng: display_codes.encode(0.9 * x, "gamma2"),
     "brightness scale"),
    ("shifted a pixel right", lambda x, rng: display_codes.encode(
        np.roll(x, 1, axis=1), "gamma2"), "shifted one pixel right"),
    ("speckles", lambda x, rng: speckled(display_codes.encode(x, "gamma2"), rng), "speckles"),
]


def speckled(codes, rng):
    """0.5 % of the pixels black or white, as a NaN (black) or an infinity (white) leaves them."""
    codes = codes.copy()
    h, w, _ = codes.shape
    n = max(8, h * w // 200)
    ys, xs = rng.integers(0, h, n), rng.integers(0, w, n)
    codes[ys, xs] = np.where(rng.random(n) < 0.5, 0, 255)[:, np.newaxis]
    return codes


def mistakes(scene, width, spp):
    rng = np.random.default_rng(5)
    with tempfile.TemporaryDirectory() as d:
        linear = render(scene, width, spp, 1, os.path.join(d, "ours.pfm"))
        for name, make, words in MISTAKES:
            image = os.path.join(d, "student.ppm")
            write_ppm(image, make(linear, rng))
            code, out, err = checker(scene, image, "--spp", str(spp))
            cause = next((line for line in out.splitlines() if "likely cause" in line), "")
            if code != 1 or words not in cause or "it matches" not in cause:
                fail(f"{scene}, {name}: exit {code} (want 1), cause '{cause}' (want '{words}')"
                     f"\n{out}{err}")
            else:
                print(f"ok: {scene}, {name}: {cause.strip()}")


def layout(scene, width, spp):
    """A layout none of the checker's own renders has (seed 1000; they take 1 and 2..17)."""
    with tempfile.TemporaryDirectory() as d:
        linear = render(scene, width, spp, 1, os.path.join(d, "ours.pfm"), layout_seed=1000)
        right, gamma = os.path.join(d, "other.ppm"), os.path.join(d, "other-no-gamma.ppm")
        write_ppm(right, display_codes.encode(linear, "gamma2"))
        write_ppm(gamma, display_codes.encode(linear, "linear8"))
        cases = [("another layout, --layout other", right, ["--layout", "other"], 0,
                  "MATCHES"),
                 ("another layout, judged as the book's", right, [], 1, "another layout"),
                 ("another layout without gamma, --layout other", gamma, ["--layout", "other"],
                  1, "linear")]
        for what, image, flags, want, words in cases:
            code, out, err = checker(scene, image, "--spp", str(spp), *flags)
            said = [line for line in out.splitlines()
                    if line.startswith(("verdict", "likely cause"))]
            if code != want or not any(words in line for line in said):
                fail(f"{scene}, {what}: exit {code} (want {want}), said {said} (want "
                     f"'{words}')\n{out}{err}")
            else:
                print(f"ok: {scene}, {what}: {' / '.join(said)}")


# Mistakes whose image shows a trait the checker names itself, not only through the zoo's
# image of them (which cannot explain it: the pattern changes with the seed); and its words.
SHARED = {"sobol-one-scramble-for-every-pixel": "neighbouring pixels share their errors"}


def zoo_images(chapter):
    import json
    with open(os.path.join(ROOT, "report", "zoo", "catalogue.json")) as f:
        catalogue = json.load(f)
    spp = str(catalogue["settings"]["spp"])
    entries = [m for m in catalogue["mistakes"] if m["chapter"] == chapter]
    if not entries:
        fail(f"the zoo's catalogue has no mistake of {chapter}")
        return
    scene = next(name for name, entry in scenes().items()
                 if [chapter, entries[0].get("scene") or ""] in entry.get("zoo", []))
    cases = [("correct", entries[0]["correct"])] + [(m["name"], m["image"]) for m in entries]
    with tempfile.TemporaryDirectory() as d:
        for name, file in cases:
            image = os.path.join(d, os.path.basename(file))
            shutil.copyfile(os.path.join(ROOT, "report", "zoo", file), image)
            # 8 renders of ours, not the 32 the budget allows at this size: a quarter of the
            # time, and the same 8 serve the catalogue's noise (the same settings).
            code, out, err = checker(scene, image, "--spp", spp, "--encoding", "srgb",
                                     "--fresnel", "schlick", "--texture-decoding", "srgb",
                                     "--renders", "8")
            said = [line.strip() for line in out.splitlines()
                    if line.startswith(("verdict", "likely cause", "  or:"))]
            claims = {words for words in SHARED.values() if any(words in x for x in said)}
            want = {SHARED[name]} if name in SHARED else set()
            if name == "correct" and code != 0:
                fail(f"{chapter}'s correct image ({file}): exit {code}, want 0\n{out}{err}")
            elif name != "correct" and code not in (0, 1):
                fail(f"{chapter} {name}: exit {code}\n{out}{err}")
            elif claims != want:
                fail(f"{chapter} {name}: said {said}, want the traits {sorted(want)} and no "
                     f"other\n{out}{err}")
            else:
                print(f"ok: {chapter} {name}: {' / '.join(said[:2])}")


def bad_input():
    with tempfile.TemporaryDirectory() as d:
        good = os.path.join(d, "good.ppm")
        linear = render("ch04", 64, 4, 1, os.path.join(d, "ours.pfm"))
        write_ppm(good, display_codes.encode(linear, "gamma2"))
        with open(good, "rb") as f:
            data = f.read()
        files = {"truncated.ppm": data[: len(data) // 2], "empty.png": b"",
                 "text.ppm": b"hello, world\n", "png-cut.png": b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR"}
        for name, content in files.items():
            with open(os.path.join(d, name), "wb") as f:
                f.write(content)
        tiny = os.path.join(d, "tiny.ppm")
        write_ppm(tiny, display_codes.encode(linear[:4, :7], "gamma2"))
        tall = os.path.join(d, "tall.ppm")
        write_ppm(tall, display_codes.encode(linear[:, :32], "gamma2"))
        rows = [
            ("a truncated PPM", ["ch04", os.path.join(d, "truncated.ppm"), "--spp", "4"],
             "truncated.ppm"),
            ("an empty file", ["ch04", os.path.join(d, "empty.png"), "--spp", "4"], "empty.png"),
            ("not an image", ["ch04", os.path.join(d, "text.ppm"), "--spp", "4"], "text.ppm"),
            ("a PNG cut in its header", ["ch04", os.path.join(d, "png-cut.png"), "--spp", "4"],
             "png-cut.png"),
            ("a missing file", ["ch04", os.path.join(d, "missing.ppm"), "--spp", "4"],
             "missing.ppm"),
            ("the wrong aspect ratio", ["ch04", tall, "--spp", "4"], "aspect ratio"),
            ("an image too small to judge", ["ch04", tiny, "--spp", "4"], "too small"),
            ("--spp missing at another size", ["ch04", good], "--spp missing"),
            ("an unknown scene", ["ch99", good, "--spp", "4"], "unknown scene 'ch99'"),
            ("--spp 0", ["ch04", good, "--spp", "0"], "--spp must be at least 1"),
            ("--budget 0", ["ch04", good, "--spp", "4", "--budget", "0"],
             "--budget must be at least 1"),
            ("a texture scene without --texture", ["ch08", good, "--spp", "4"], "--texture"),
            ("--layout other for a scene without one", ["ch04", good, "--spp", "4", "--layout",
                                                         "other"], "no random layout"),
            ("--encoding for a float image", ["ch04", os.path.join(d, "ours.pfm"), "--spp", "4",
                                              "--encoding", "srgb"], "8-bit"),
        ]
        for what, args, words in rows:
            before = set(os.listdir(d))
            run = subprocess.run([CHECK, *args], capture_output=True, text=True)
            lines = run.stderr.strip().splitlines()
            written = set(os.listdir(d)) - before
            if (run.returncode != 2 or len(lines) != 1 or words not in lines[0] or written
                    or run.stdout):
                fail(f"{what}: exit {run.returncode} (want 2), stderr {lines!r} (want one line "
                     f"naming '{words}'), wrote {sorted(written)}")
            else:
                print(f"ok: {what}: {lines[0]}")


def false_alarms(scene_names, width, spp, n, limit, budget=None):
    """N renders of ours with independent seeds (101..100 + N, none of them the checker's own),
    each written as the book writes it and judged by the checker's verdict on an image as given
    (the same Expectation and bound, in this process: the checker's own renders are made once
    and cached, as a student's run makes them). Prints the share judged a mismatch per scene;
    fails when a scene has more than `limit` in N. `budget` (the checker's --budget) makes our
    renders fewer spp than the student's, scaled: the expectation a student's large render
    gets, at a small render's cost."""
    import types
    check = checker_in_process.module()
    from rtlib import block_test
    registry = scenes()
    for name in scene_names:
        entry = registry[name]
        flags = types.SimpleNamespace(max_depth=None, texture=TEXTURE if entry.get("texture")
                                      else None, texture_decoding="book", fresnel="book")
        scene = check.Scene(name, entry, flags)
        height = scene.height(width)
        k, rendered = check.measurement(width, height, spp, budget=budget or check.BUDGET)
        ours = scene.renders(width, height, rendered, k, "book")
        encoding = book_encoding(name)
        b = block_test.block_size(width, height)
        expected = check.expectation(ours, rendered, spp, encoding, b)
        alarms, worst = 0, 0.0
        with tempfile.TemporaryDirectory() as d:
            for seed in range(101, 101 + n):
                linear = render(name, width, spp, seed, os.path.join(d, "student.pfm"))
                verdict = check.Check("as given", display_codes.encode(linear, encoding),
                                      expected)
                alarms += not verdict.ok
                worst = max(worst, verdict.worst)
        scaled = f" at {rendered} spp, scaled" if rendered < spp else ""
        print(f"false alarms: {name}, {width} x {height}, {spp} spp, {k} renders of ours{scaled}: "
              f"{alarms} of {n} judged a mismatch (largest worst |z| {worst:.2f}, bound "
              f"{verdict.limit:.2f}; the bound promises 1e-3 per image)", flush=True)
        if alarms > limit:
            fail(f"{name}: {alarms} false alarms in {n} renders, more than {limit}")


def main():
    mode = sys.argv[1]
    if mode == "match":
        match(sys.argv[2], int(sys.argv[3]), [int(s) for s in sys.argv[4:]])
    elif mode == "zoo-images":
        zoo_images(sys.argv[2])
    elif mode == "mistakes":
        mistakes(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    elif mode == "layout":
        layout(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    elif mode == "bad-input":
        bad_input()
    elif mode == "false-alarms":
        names = sys.argv[2].split(",") if sys.argv[2] != "all" else list(scenes())
        false_alarms(names, int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]),
                     int(sys.argv[6]) if len(sys.argv) > 6 else 1,
                     int(sys.argv[7]) if len(sys.argv) > 7 else None)
    else:
        raise SystemExit(f"unknown mode {mode}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
