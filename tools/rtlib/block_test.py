"""Is an image a render of a scene, within the noise its samples must have?

The expectation is measured, never guessed: K renders of our own scene at the student's size
and samples per pixel, with independent seeds, each encoded as the student's file is. Per block
of B x B pixels and channel, E is the mean of the K renders' block means and V the variance of
one render's block mean, from the per-pixel variances across the K renders (pixels are
independent, so a block's variance is the sum of its pixels' over B^4; each pixel's estimate
has K - 1 degrees of freedom, a block's about B^2 (K - 1)). The student's block mean S gives

    z = (S - E) / sqrt(V (1 + 1/K)),

standard normal for a render of the same scene by the same estimator (the 1/K: E's own
error). A block fails beyond the Bonferroni bound that keeps the chance of any false alarm in a
whole image at 1e-3.

Above `cap` samples per pixel the renders are made at cap and scaled: the variance of a pixel's
mean of independent samples falls as 1/spp, and so does, to first order, the bias the encoding's
curve gives a noisy value (E[f(X)] - f(E[X]) = f''/2 Var X). With A the mean of the encoded
renders and C the encoding of their mean (itself a mean of K cap samples, biased by 1/K of A's
bias b), b = (A - C) K / (K - 1), f(mu) = C - b / K and the expectation at n samples is
f(mu) + b cap / n; the code's rounding adds a variance of 1/12 per pixel that does not scale.

Float images (PFM, EXR) at the rendered spp are compared capped at 1, as 8-bit ones are by
their code 255: a heavy tail of rare bright samples is what K renders measure worst.
"""
import math
import statistics

import numpy as np

FAMILY_ALARM = 1e-3
CAP = 1.0  # float pixels are compared at most this bright (at the rendered spp)


def block_size(width, height):
    """16-pixel blocks, smaller for small images so that there are at least 4 x 4 of them."""
    b = 16
    while b > 4 and min(width, height) < 4 * b:
        b //= 2
    return b


def blocks(x, b):
    """Block means of x, shape (..., H, W, 3) -> (..., H // b, W // b, 3); edge pixels that fill
    no whole block are left out."""
    h, w = x.shape[-3] // b * b, x.shape[-2] // b * b
    x = x[..., :h, :w, :]
    shape = x.shape[:-3] + (h // b, b, w // b, b, 3)
    return x.reshape(shape).mean(axis=(-4, -2))


def bound(tests):
    """The |z| beyond which one of `tests` block tests fails: Bonferroni at FAMILY_ALARM."""
    return statistics.NormalDist().inv_cdf(1 - FAMILY_ALARM / (2 * tests))


class Expectation:
    """E and V per block for one encoding, from K linear renders made at `rendered` spp, for a
    student's render of `spp` samples."""

    def __init__(self, renders, rendered, spp, encoding, b, encode, encode_continuous):
        k = renders.shape[0]
        self.b = b
        self.cap = None
        if spp <= rendered:
            codes = encode(renders, encoding)
            if encoding == "float":
                # Float pixels have no ceiling, and an estimator with rare bright samples (a
                # light reached through a mixture pdf, caustics) has a heavy tail that K renders
                # measure badly and whose block means are far from normal. Capped at 1, as the
                # book's 8-bit file is by its code 255, ours and the student's are bounded; the
                # expectation is still measured, of the capped value (a NaN or an infinity is
                # left as it is, and fails).
                self.cap = CAP
                codes = np.minimum(codes, self.cap)
            self.mean_pixels = codes.mean(axis=0)
            pixel_var = codes.var(axis=0, ddof=1)
            self.E = blocks(self.mean_pixels, b)
            self.V = blocks(pixel_var, b) / (b * b)
        else:
            codes = encode_continuous(renders, encoding)
            a = codes.mean(axis=0)
            c = encode_continuous(renders.mean(axis=0), encoding)
            bias = (a - c) * k / (k - 1)
            scale = rendered / spp
            self.mean_pixels = c - bias / k + bias * scale
            pixel_var = codes.var(axis=0, ddof=1) * scale
            if encoding != "float":
                pixel_var = pixel_var + 1.0 / 12
            self.E = blocks(self.mean_pixels, b)
            self.V = blocks(pixel_var, b) / (b * b)
        # A floor under V: a block that our renders never vary (a plain background) may still
        # differ by a last-bit rounding, one code in a few of its pixels, or 1e-6 of a float.
        # (1e-12 more for floats: a block black in every render of ours is judged, not 0 / 0.)
        floor = ((0.5 ** 2) / (b * b) if encoding != "float"
                 else (1e-6 * np.abs(self.E)) ** 2 + 1e-24)
        self.V = np.maximum(self.V, floor)
        self.k = k

    def z(self, student_pixels):
        if self.cap is not None:
            student_pixels = np.where(np.isfinite(student_pixels),
                                      np.minimum(student_pixels, self.cap), student_pixels)
        s = blocks(student_pixels, self.b)
        return (s - self.E) / np.sqrt(self.V * (1 + 1 / self.k))


def judge(z):
    """(passes, share of failing block tests, worst |z|, its (block row, block column, channel),
    the bound)."""
    limit = bound(z.size)
    a = np.abs(np.nan_to_num(z, nan=math.inf))
    worst = np.unravel_index(int(np.argmax(a)), a.shape)
    failing = float((a > limit).mean())
    return failing == 0, failing, float(a[worst]), tuple(int(i) for i in worst), limit
