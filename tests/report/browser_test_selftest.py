#!/usr/bin/python3
"""Tests of tests/report/browser_test.py: it passes the fixture page (tests/report/fixture) and
fails each broken copy of it with the line that names the breakage, so that it cannot pass a
page without looking.

  browser_test_selftest.py [CASE...]      (no CASE: all of them; names in CASES below)

Each case runs browser_test.py on its own copy of the fixture, with the images written afresh
(the same every time). Prints "ok CASE" or "FAIL CASE: why"; exit 1 on any failure."""
import concurrent.futures
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.realpath(__file__))
TEST = os.path.join(HERE, "browser_test.py")
FIXTURE = os.path.join(HERE, "fixture")
TIMEOUT = 180  # seconds for one run of the test, far above its few seconds


def write_images(folder):
    """A and B share a noisy gradient (so that a view one pixel off shows) and differ in two
    discs and a square; diff.png is their difference, figure.png the gradient alone."""
    rng = np.random.default_rng(1)
    h, w = 120, 200
    y, x = np.mgrid[0:h, 0:w]
    base = np.stack([x * 255 // w, y * 255 // h, 128 + rng.integers(-20, 20, (h, w))], axis=2)
    a, b = base.copy(), base.copy()
    a[(x - 70) ** 2 + (y - 60) ** 2 < 30 ** 2] = [200, 60, 40]
    b[(x - 85) ** 2 + (y - 60) ** 2 < 30 ** 2] = [60, 200, 40]
    b[20:40, 150:170] = [255, 255, 255]
    for name, pixels in (("a", a), ("b", b), ("diff", np.abs(a - b)), ("figure", base)):
        Image.fromarray(pixels.astype(np.uint8)).save(os.path.join(folder, f"{name}.png"))


def edit(folder, name, old, new):
    """Replaces old, which must be in the file, by new."""
    path = os.path.join(folder, name)
    with open(path) as f:
        text = f.read()
    assert old in text, f"{name} has no '{old}'"
    with open(path, "w") as f:
        f.write(text.replace(old, new))


def fake_browser(folder, script):
    """A folder for PATH, beside folder, holding a 'chromium' that runs script."""
    path = os.path.join(os.path.dirname(folder), "bin", "chromium")
    os.makedirs(os.path.dirname(path))
    with open(path, "w") as f:
        f.write(f"#!/bin/sh\n{script}\n")
    os.chmod(path, 0o755)
    return os.path.dirname(path)


# Each case: how to break the copy (a function of its folder, returning the environment's
# changes or None) and the text the test's FAIL lines must hold (None: the test must pass).
BODY_END = "</body>"
CASES = {
    "good": (lambda d: None, None),
    "missing-image": (lambda d: os.remove(os.path.join(d, "figure.png")),
                      "FAIL images: not loaded: figure.png"),
    "link-to-no-file": (lambda d: edit(d, "index.html", BODY_END,
                                       '<a href="nowhere.html#x">x</a>' + BODY_END),
                        "FAIL links: href 'nowhere.html#x': no file nowhere.html"),
    "link-to-no-id": (lambda d: edit(d, "index.html", BODY_END, '<a href="#nowhere">x</a>'
                                     + BODY_END),
                      "FAIL links: href '#nowhere': no element of the page has id 'nowhere'"),
    "script-error": (lambda d: edit(d, "index.html", BODY_END,
                                    "<script>noSuchFunction();</script>" + BODY_END),
                     "FAIL load: uncaught exception: ReferenceError: noSuchFunction"),
    "console-error": (lambda d: edit(d, "index.html", BODY_END,
                                     "<script>console.error('broken');</script>" + BODY_END),
                      "FAIL load: console.error: broken"),
    "missing-script": (lambda d: os.remove(os.path.join(d, "report.js")),
                       "FAIL load: failed request: report.js"),
    # Mode b keeps the split: half of where A and B differ does not change.
    "b-keeps-split": (lambda d: edit(d, "index.html",
                                     '.compare[data-mode="b"] .compare-b { clip-path: none; }',
                                     ""),
                      "FAIL flip: the view changed at"),
    # Mode b moves B a pixel: the view changes where A and B are the same.
    "b-one-pixel-off": (lambda d: edit(d, "index.html", "clip-path: none;",
                                       "clip-path: none; left: 1px;"),
                        "pixels where A and B are the same"),
    # Mode a shows B, mode b shows A.
    "modes-swapped": (lambda d: [edit(d, "index.html", f'[data-mode="{old}"] .compare-b',
                                      f'[data-mode="{new}"] .compare-b')
                                 for old, new in (("a", "x"), ("b", "a"), ("x", "b"))],
                      "FAIL flip: mode a shows image A at only"),
    "split-does-not-follow": (lambda d: edit(d, "report.js", "if (dragging) follow(event);", ""),
                              "FAIL drag: between the splits the view changed at"),
    # Without it, pressing on the image starts dragging the image away, not the split.
    "image-drags-away": (lambda d: edit(d, "report.js", '"dragstart"', '"no-dragstart"'),
                         "FAIL drag: between the splits the view changed at"),
    "handle-left-behind": (lambda d: edit(d, "index.html", "left: var(--split); width: 1px;",
                                          "left: 50%; width: 1px;"),
                           "FAIL drag: the handle is at 50.2 % of the view, not at 25 %"),
    "handle-always-shown": (lambda d: edit(d, "index.html", ':not([data-mode="slider"])',
                                           '[data-mode="none"]'),
                            "FAIL flip: the handle shows in mode a"),
    "zoom-smooth": (lambda d: edit(d, "index.html", "image-rendering: pixelated",
                                   "image-rendering: auto"),
                    "FAIL zoom: images A and B have image-rendering auto"),
    "zoom-ignored": (lambda d: edit(d, "report.js", "a.naturalWidth * zoom", "a.naturalWidth"),
                     "FAIL zoom: at zoom 2 the view is 200 x 120 CSS pixels, not 400 x 240"),
    "no-browser": (lambda d: {"PATH": os.path.join(d, "empty")},
                   "FAIL browser: no browser found"),
    "browser-fails": (lambda d: {"PATH": fake_browser(d, "echo 'cannot open display' >&2")},
                      "FAIL browser: "),
}


def run_case(name):
    """'ok NAME' or 'FAIL NAME: why'."""
    breakage, expected = CASES[name]
    with tempfile.TemporaryDirectory() as work:
        page = os.path.join(work, "page")
        shutil.copytree(FIXTURE, page)
        write_images(page)
        changes = breakage(page)
        env = dict(os.environ, **(changes if isinstance(changes, dict) else {}))
        shots = os.path.join(work, "shots")
        try:
            done = subprocess.run([TEST, os.path.join(page, "index.html"), "--screenshots",
                                   shots], env=env, capture_output=True, text=True,
                                  timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            return f"FAIL {name}: no answer within {TIMEOUT} s"
        output = done.stdout + done.stderr
        fails = [line for line in output.splitlines() if line.startswith("FAIL")]
        if expected is None:
            if done.returncode != 0 or fails:
                return f"FAIL {name}: exit {done.returncode}:\n{output}"
            sizes = [Image.open(os.path.join(shots, f)).size if os.path.exists(
                os.path.join(shots, f)) else None for f in ("first-screen.png",
                                                            "comparison.png")]
            if sizes[0] != (1280, 900) or not sizes[1] or sizes[1][0] < 200:
                return f"FAIL {name}: screenshots of sizes {sizes}"
            return f"ok {name}"
        if done.returncode != 1 or not any(expected in line for line in fails):
            return f"FAIL {name}: exit {done.returncode}, no FAIL line with '{expected}':\n" \
                   f"{output}"
        if expected.startswith("FAIL browser") and len(fails) != 1:
            return f"FAIL {name}: {len(fails)} FAIL lines, not one:\n{output}"
        return f"ok {name}"


def main():
    names = sys.argv[1:] or list(CASES)
    unknown = [name for name in names if name not in CASES]
    if unknown:
        print(f"unknown cases: {', '.join(unknown)}; the cases: {', '.join(CASES)}")
        return 2
    # A few browsers at once: the runs wait on events, never on the clock, so load is harmless.
    with concurrent.futures.ThreadPoolExecutor(min(4, os.cpu_count() or 1)) as pool:
        results = list(pool.map(run_case, names))
    for line in results:
        print(line)
    return 1 if any(line.startswith("FAIL") for line in results) else 0


if __name__ == "__main__":
    sys.exit(main())
