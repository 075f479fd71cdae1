#!/usr/bin/python3
"""compare_pfm.py A.pfm B.pfm BOUND: exit 1 unless every value of B is within BOUND relative of
A's, |a - b| <= BOUND max(|a|, |b|) (so 0 only matches 0); prints the worst relative difference,
and where: pixel (x, y) from the top-left, as the renderer counts them."""
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in tools/
sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "tools"))
from rtlib import pfm  # noqa: E402  (tools/rtlib: the tools' PFM reader)


def read_pfm(path):
    try:
        image = pfm.read(path)
    except pfm.FormatError as e:
        raise SystemExit(f"compare_pfm: {e}")
    return (image.width, image.height, image.channels), image.pixels


def main():
    a_path, b_path, bound = sys.argv[1], sys.argv[2], float(sys.argv[3])
    (size_a, a), (size_b, b) = read_pfm(a_path), read_pfm(b_path)
    if size_a != size_b:
        print(f"FAIL: {b_path} is {size_b}, {a_path} is {size_a} (width, height, channels)")
        return 1
    width, channels = size_a[0], size_a[2]
    worst, where = 0.0, 0
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            relative = abs(x - y) / max(abs(x), abs(y))
            if relative > worst:
                worst, where = relative, i
    pixel = where // channels
    message = (f"{b_path} against {a_path}: worst relative difference {worst:.3g} "
               f"(pixel {pixel % width}, {pixel // width}, channel {where % channels}: "
               f"{a[where]!r} against {b[where]!r})")
    if worst > bound:
        print(f"FAIL: {message} > {bound}")
        return 1
    print(f"ok: {message}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
