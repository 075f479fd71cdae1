#!/usr/bin/python3
"""compare_pfm.py A.pfm B.pfm BOUND [MEAN.pfm SPP]: exit 1 unless every value of B is within
BOUND relative of A's, |a - b| <= BOUND max(|a|, |b|) (so 0 only matches 0); prints the worst
relative difference, and where: pixel (x, y) from the top-left, as the renderer counts them.

With MEAN.pfm and SPP, A and B are variances of pixel means of SPP samples merged from parts
(tools/merge, Chan's formula), and each value may also differ by what the parts' means, stored
as 32-bit floats, carry into the between-part term sum_i n_i (m_i - m)^2 of M2 = V n (n - 1):
each m_i is off by up to 2^-24 |m_i|, which moves M2 by at most 2^-23 |m| sum_i n_i |m_i - m|
(the shift common to all parts cancels, as sum_i n_i (m_i - m) = 0), and by Cauchy-Schwarz
sum_i n_i |m_i - m| <= sqrt(n M2). So |dV| <= 2^-23 |m| sqrt(V / (n - 1)), doubled for the
second-order terms. A pixel whose variance is tiny beside its mean squared has a relative error
far above float rounding, and this is where it comes from."""
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
    means, spp = None, 0
    if len(sys.argv) == 6:
        (size_m, means), spp = read_pfm(sys.argv[4]), int(sys.argv[5])
        if size_m != size_a or spp < 2:
            print(f"FAIL: {sys.argv[4]} is {size_m}, need {size_a} and SPP >= 2, got {spp}")
            return 1
    width, channels = size_a[0], size_a[2]
    worst, where = 0.0, 0
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            largest = max(abs(x), abs(y))
            if means is not None:  # the part means' rounding, in units of bound * largest
                carried = 2 * 2.0**-23 * abs(means[i]) * (largest / (spp - 1)) ** 0.5
                largest_allowed = bound * largest + carried
                relative = abs(x - y) / largest_allowed * bound
            else:
                relative = abs(x - y) / largest
            if relative > worst:
                worst, where = relative, i
    pixel = where // channels
    kind = " (beyond what the parts' rounded means carry)" if means is not None else ""
    message = (f"{b_path} against {a_path}: worst relative difference{kind} {worst:.3g} "
               f"(pixel {pixel % width}, {pixel // width}, channel {where % channels}: "
               f"{a[where]!r} against {b[where]!r})")
    if worst > bound:
        print(f"FAIL: {message} > {bound}")
        return 1
    print(f"ok: {message}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
