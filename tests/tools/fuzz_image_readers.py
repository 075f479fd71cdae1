#!/usr/bin/python3
"""Fuzz test of tools/check-render's image readers (tools/rtlib/student_image.py, over
OpenImageIO's): mutated PPM (P3 and P6), PNG and PFM files, made by Hypothesis (Debian's
python3-hypothesis) from valid ones, are either read as an image of the size their header
says or refused with BadImage and one line naming the file; never a crash, a hang or another
exception. A few of them then go through the whole checker: exit 2 and one line, or a verdict
(exit 0 or 1), and nothing but the map written.

  fuzz_image_readers.py [EXAMPLES]     (default 400 mutated files in-process)
"""
import io
import os
import subprocess
import sys
import tempfile

import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.realpath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from rtlib import student_image  # noqa: E402

CHECK = os.path.join(ROOT, "tools", "check-render")


def seeds():
    """Valid small images in each format, 16 x 9 (chapter 04's aspect ratio)."""
    rng = np.random.default_rng(3)
    codes = rng.integers(0, 256, (9, 16, 3))
    p3 = "P3\n16 9\n255\n" + "\n".join(" ".join(str(int(v)) for v in row.ravel())
                                       for row in codes) + "\n"
    p6 = b"P6\n16 9\n255\n" + codes.astype(np.uint8).tobytes()
    from PIL import Image
    png = io.BytesIO()
    Image.fromarray(codes.astype(np.uint8)).save(png, "PNG")
    pfm = b"PF\n16 9\n-1.0\n" + rng.random((9, 16, 3)).astype("<f4").tobytes()
    return {".ppm": [p3.encode(), p6], ".png": [png.getvalue()], ".pfm": [pfm]}


SEEDS = seeds()


@st.composite
def mutated(draw):
    ext = draw(st.sampled_from(sorted(SEEDS)))
    data = bytearray(draw(st.sampled_from(SEEDS[ext])))
    for _ in range(draw(st.integers(1, 4))):
        how = draw(st.sampled_from(["flip", "cut", "insert", "delete", "header"]))
        at = draw(st.integers(0, max(0, len(data) - 1)))
        if how == "flip" and data:
            data[at] ^= 1 << draw(st.integers(0, 7))
        elif how == "cut":
            del data[at:]
        elif how == "insert":
            data[at:at] = draw(st.binary(min_size=1, max_size=16))
        elif how == "delete":
            del data[at:at + draw(st.integers(1, 16))]
        else:  # a header field rewritten: sizes, maxval, scale (huge, zero, negative, junk)
            field = draw(st.sampled_from([b"16", b"9", b"255", b"-1.0"]))
            value = draw(st.sampled_from([b"0", b"-5", b"99999999", b"65535", b"1e300", b"x",
                                          b"nan", b"3"]))
            data = bytearray(bytes(data).replace(field, value, 1))
    return ext, bytes(data)


def read_one(folder, ext, data):
    path = os.path.join(folder, "student" + ext)
    with open(path, "wb") as f:
        f.write(data)
    try:
        image = student_image.read(path)
    except student_image.BadImage as e:
        message = str(e)
        assert "\n" not in message and path in message, message
        return "refused"
    h, w, c = image.pixels.shape
    assert c == 3 and 0 < w <= student_image.MAX_SIDE and 0 < h <= student_image.MAX_SIDE
    return "read"


def main():
    examples = int(sys.argv[1]) if len(sys.argv) > 1 else 400
    outcomes = {"read": 0, "refused": 0}
    through_checker = []
    with tempfile.TemporaryDirectory() as folder:
        @settings(max_examples=examples, deadline=None, database=None, derandomize=True,
                  suppress_health_check=list(HealthCheck))
        @given(mutated())
        def reader_never_crashes(case):
            ext, data = case
            outcome = read_one(folder, ext, data)
            outcomes[outcome] += 1
            # Through the checker: 8 that the readers take (they reach its verdicts), 4 not.
            if sum(o == outcome for o, _ in through_checker) < (8 if outcome == "read" else 4):
                through_checker.append((outcome, case))

        reader_never_crashes()
        failures = 0
        for i, (_, (ext, data)) in enumerate(through_checker):
            d = os.path.join(folder, f"checker{i}")
            os.makedirs(d)
            path = os.path.join(d, "student" + ext)
            with open(path, "wb") as f:
                f.write(data)
            run = subprocess.run([CHECK, "ch04", path, "--spp", "4", "--renders", "4"],
                                 capture_output=True, text=True, timeout=600)
            written = sorted(set(os.listdir(d)) - {"student" + ext})
            ok = (run.returncode == 2 and len(run.stderr.strip().splitlines()) == 1
                  and not written and not run.stdout) or (
                run.returncode in (0, 1) and written == ["student.check.png"])
            if not ok:
                failures += 1
                print(f"FAIL: checker on mutated {ext} #{i}: exit {run.returncode}, stderr "
                      f"{run.stderr.strip()[-300:]!r}, wrote {written}")
    print(f"fuzzed {examples} files: {outcomes['read']} read, {outcomes['refused']} refused with "
          f"one line; {len(through_checker)} through the whole checker, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
