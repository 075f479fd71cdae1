"""Is an image a render of a scene, within the noise its samples must have?

The expectation is measured, never guessed: K renders of our own scene at the student's size
and samples per pixel, with independent seeds, each encoded as the student's file is. Per block
of B x B pixels and channel, E is the mean of the K renders' block means and V the variance of
one render's block mean, from the per-pixel variances across the K renders (pixels are
independent, so a block's variance is the sum of its pixels' over B^4; each pixel's estimate
has K - 1 degrees of freedom, a block's about B^2 (K - 1)). The student's block mean S gives

    z = (S - E) / sqrt(V (1 + 1/K)),

standard normal for a render of the same scene by the same estimator (the 1/K: E's own
error, V / K, since E is a mean of K renders at the student's spp). A block fails beyond the
Bonferroni bound that keeps the chance of any false alarm in a whole image at 1e-3.

Rare samples break that normality: a pixel lit by a path that finds a small bright object once
in hundreds of samples is mostly one value and rarely a far one, and one such pixel in a block
of a correct render is "five standard deviations". So S leaves out the student's FORGIVEN (2)
pixels of each block that are farthest from our mean, when our renders gave their values too
around the block (its own and its eight neighbours' pixels, any render): a region that differs
moves many pixels and keeps its z, a lone value no render of ours came near (a NaN's black speck
in a bright region) is kept. Where noise is skewed, the pixels left out are mostly on one side:
the expectation is lowered by what the same rule does to each of our renders (against the mean
of the others). Measured: tests/tools/check_render_test.py false-alarms (tools/check/README.md).

Above `cap` samples per pixel the renders are made at cap and scaled: the variance of a pixel's
mean of independent samples falls as 1/spp, and so does, to first order, the bias the encoding's
curve gives a noisy value (E[f(X)] - f(E[X]) = f''/2 Var X). With A the mean of the encoded
renders and C the encoding of their mean (itself a mean of K cap samples, biased by 1/K of A's
bias b), b = (A - C) K / (K - 1), f(mu) = C - b / K and the expectation at n samples is
f(mu) + b cap / n; the code's rounding adds a variance of 1/12 per pixel that does not scale.
E is then a mean of K renders at cap spp, not at n: its own error is V n / (cap K), not V / K
(at n = 10,000 from K = 4 renders at 500, five times the student's own), and
z = (S - E) / sqrt(V (1 + n / (cap K))).

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
            self.own_error = 1 / k  # E's variance over V: K renders at the student's spp
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
            self.own_error = spp / (rendered * k)  # K renders at fewer spp than the student's
        # A floor under V: a block that our renders never vary (a plain background) may still
        # differ by a last-bit rounding, one code in a few of its pixels, or 1e-6 of a float.
        # (1e-12 more for floats: a block black in every render of ours is judged, not 0 / 0.)
        floor = ((0.5 ** 2) / (b * b) if encoding != "float"
                 else (1e-6 * np.abs(self.E)) ** 2 + 1e-24)
        self.V = np.maximum(self.V, floor)
        # The values our renders gave around each block (its own and its eight neighbours'),
        # per channel: a student's pixel within them may be a rare sample, one outside may not.
        lowest, highest = blocks_extreme(codes, b, np.min), blocks_extreme(codes, b, np.max)
        self.seen_low, self.seen_high = around(lowest, np.min), around(highest, np.max)
        # What leaving pixels out does to a correct render's block mean, on average: each render
        # of ours against the mean of the others (its deviation scaled by K / (K - 1)). Where a
        # pixel's noise is skewed (bright rare samples), its farthest pixels are mostly above
        # the mean and leaving them out lowers the block; the student's block is judged against
        # that same lowering. At more samples than rendered, the pixels' spread and so the
        # lowering shrink as 1 / sqrt(spp).
        spread_scale = 1.0 if spp <= rendered else math.sqrt(rendered / spp)
        centre = codes.mean(axis=0)
        # The block mean's skewness (its pixels' third central moments add up, as their
        # variances do), k-statistic per pixel; at more samples than rendered it falls as
        # 1 / sqrt(spp), as a mean's skewness does.
        spread = codes - centre
        third = ((spread * spread * spread).sum(axis=0) * k / ((k - 1) * (k - 2)) if k > 2
                 else np.zeros_like(centre))
        self.skew = (blocks(third, b) / (b * b) ** 2 / self.V ** 1.5) * spread_scale
        self.forgiveness = np.mean([
            blocks(forgive_rare((codes[i] - centre) * k / (k - 1), codes[i],
                                self.seen_low, self.seen_high, b), b)
            for i in range(k)], axis=0) * spread_scale

    def z(self, student_pixels):
        if self.cap is not None:
            student_pixels = np.where(np.isfinite(student_pixels),
                                      np.minimum(student_pixels, self.cap), student_pixels)
        deviation = forgive_rare(student_pixels - self.mean_pixels, student_pixels,
                                 self.seen_low, self.seen_high, self.b)
        z = ((blocks(deviation, self.b) - self.forgiveness)
             / np.sqrt(self.V * (1 + self.own_error)))
        return skew_adjusted(z, self.skew)


def skew_adjusted(z, skew):
    """z rescaled so that the bound of a normal test applies to a skewed block mean. The
    Cornish-Fisher expansion puts the tail quantile of a variable of skewness g at
    q + g (q^2 - 1) / 6, q the normal one: the bound of the side the skew lengthens moves out by
    that, the other side's is kept (never tightened, since g is estimated). z on that side is
    scaled by q / (q + |g| (q^2 - 1) / 6), so that judge()'s bound q stands for the moved one."""
    q = bound(z.size)
    widened = q / (q + np.abs(skew) * (q * q - 1) / 6)
    lengthened = np.sign(z) == np.sign(skew)
    return np.where(lengthened, z * widened, z)


FORGIVEN = 2  # pixels of each block that may be rare samples, at most


def blocks_extreme(x, b, reduce):
    """reduce (np.min or np.max) over the renders and the pixels of each block: (H//b, W//b, 3).
    The renders first, pixel by pixel, over whole images in memory order: a tenth of the time of
    one reduction over the renders and a block's rows and columns at once, and the same values
    (a minimum or maximum is exact in any order, and a NaN wins either way)."""
    if x.ndim > 3:
        x = reduce(x.reshape((-1,) + x.shape[-3:]), axis=0)
    h, w = x.shape[0] // b * b, x.shape[1] // b * b
    return reduce(x[:h, :w, :].reshape(h // b, b, w // b, b, 3), axis=(1, 3))


def around(x, reduce):
    """reduce over each block and its eight neighbours (those inside the image)."""
    padded = np.pad(x, ((1, 1), (1, 1), (0, 0)), mode="edge")
    h, w = x.shape[:2]
    return reduce(np.stack([padded[dy:dy + h, dx:dx + w] for dy in range(3) for dx in range(3)]),
                  axis=0)


def forgive_rare(deviation, pixels, low, high, b):
    """The student's deviations from our mean, less those of the FORGIVEN farthest pixels of each
    block whose values our renders also gave around that block.

    Why: a pixel whose light comes from rare samples (a path that finds a small bright object
    once in hundreds) is mostly one value and rarely a far one. A block that holds one such
    pixel is "five standard deviations" off for a normal test, and yet that happens to a correct
    render in one block in ten. A region that differs moves many pixels, and two forgiven ones
    hardly change its mean; a pixel no render of ours came near (a NaN's black speck in a bright
    region) is never forgiven."""
    h, w = deviation.shape[0] // b * b, deviation.shape[1] // b * b
    d = np.nan_to_num(deviation[:h, :w], nan=np.inf).reshape(h // b, b, w // b, b, 3)
    v = pixels[:h, :w].reshape(h // b, b, w // b, b, 3)
    plausible = ((v >= low[:, np.newaxis, :, np.newaxis, :])
                 & (v <= high[:, np.newaxis, :, np.newaxis, :]) & np.isfinite(d))
    size = np.where(plausible, np.abs(d), -1.0)
    # Per block and channel, the FORGIVEN largest plausible deviations (exactly that many:
    # ties of 8-bit codes must not forgive a whole block that is off by one code), of tied ones
    # the last: each pass takes the last of the largest left (a stable sort's choice, in linear
    # time).
    flat = size.transpose(0, 2, 4, 1, 3).reshape(h // b, w // b, 3, b * b)
    chosen = np.zeros(flat.shape, dtype=bool)
    left = flat.copy()
    for _ in range(FORGIVEN):
        last = b * b - 1 - np.argmax(left[..., ::-1], axis=-1)[..., np.newaxis]
        np.put_along_axis(chosen, last, True, axis=-1)
        np.put_along_axis(left, last, -np.inf, axis=-1)
    chosen &= flat > 0
    forgiven = chosen.reshape(h // b, w // b, 3, b, b).transpose(0, 3, 1, 4, 2)
    out = np.array(deviation, dtype=np.float64)
    out[:h, :w] = np.where(forgiven, 0.0, d).reshape(h, w, 3)
    return out


def judge(z):
    """(passes, share of failing block tests, worst |z|, its (block row, block column, channel),
    the bound)."""
    limit = bound(z.size)
    a = np.abs(np.nan_to_num(z, nan=math.inf))
    worst = np.unravel_index(int(np.argmax(a)), a.shape)
    failing = float((a > limit).mean())
    return failing == 0, failing, float(a[worst]), tuple(int(i) for i in worst), limit
