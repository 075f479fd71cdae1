#!/usr/bin/python3
"""compare_pfm.py A.pfm B.pfm BOUND: exit 1 unless every value of B is within BOUND relative of
A's, |a - b| <= BOUND max(|a|, |b|) (so 0 only matches 0); prints the worst relative difference.
Reads the little-endian RGB PFM that image_io writes."""
import struct
import sys


def read_pfm(path):
    with open(path, "rb") as f:
        magic, size, scale = f.readline(), f.readline(), f.readline()
        width, height = map(int, size.split())
        if magic.strip() != b"PF" or float(scale) >= 0:
            raise SystemExit(f"compare_pfm: {path} is not a little-endian RGB PFM")
        data = f.read()
    count = width * height * 3
    if len(data) != 4 * count:
        raise SystemExit(f"compare_pfm: {path} has {len(data)} bytes of pixels, not {4 * count}")
    return (width, height), struct.unpack(f"<{count}f", data)


def main():
    a_path, b_path, bound = sys.argv[1], sys.argv[2], float(sys.argv[3])
    (size_a, a), (size_b, b) = read_pfm(a_path), read_pfm(b_path)
    if size_a != size_b:
        print(f"FAIL: {b_path} is {size_b}, {a_path} is {size_a}")
        return 1
    worst, where = 0.0, 0
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            relative = abs(x - y) / max(abs(x), abs(y))
            if relative > worst:
                worst, where = relative, i
    pixel = where // 3
    message = (f"{b_path} against {a_path}: worst relative difference {worst:.3g} "
               f"(pixel {pixel % size_a[0]}, {pixel // size_a[0]}, channel {where % 3}: "
               f"{a[where]!r} against {b[where]!r})")
    if worst > bound:
        print(f"FAIL: {message} > {bound}")
        return 1
    print(f"ok: {message}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
