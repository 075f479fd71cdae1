"""Does an image match a scene whose objects lie elsewhere? The statistics that do not depend on
the layout.

The book lays out book 1's final scene, the bouncing spheres and book 2's final scene, and draws
its Perlin tables, with rand(). A student whose rand() is another generator (MSVC's, macOS's)
or whose compiler draws a call's arguments in another order (clang: left to right) renders
another layout of the same scene, which no pixel-by-pixel test can match. What such a render
still shares with ours is the distribution of what the layout changes: how bright the picture
is, per channel, over the whole image and over its top, middle and bottom thirds (sky, the big
spheres, the ground). Those means are measured over K renders of ours, each with another layout
(--layout-seed), so their spread holds both the layouts' variation and the noise. A student's
statistic s is judged by

    t = (s - mean) / (sd sqrt(1 + 1/K)),

Student's t with K - 1 degrees of freedom for one more layout of the same scene, against the
Bonferroni bound that keeps a false alarm over all the statistics at 1e-3. This test is far
weaker than the block test (a layout varies the brightness by a few percent), so it catches
what changes the whole picture (gamma, a brightness scale, a missing light, wrong colours) and
not a mistake in one small sphere.
"""
import numpy as np

FAMILY_ALARM = 1e-3
REGIONS = ("the whole image", "the top third", "the middle third", "the bottom third")


def statistics_of(linear):
    """(..., H, W, 3) linear light -> (..., 4, 3): the mean of each region, per channel."""
    h = linear.shape[-3]
    thirds = [linear[..., i * h // 3:(i + 1) * h // 3, :, :] for i in range(3)]
    means = [linear.mean(axis=(-3, -2))] + [t.mean(axis=(-3, -2)) for t in thirds]
    return np.stack(means, axis=-2)


class Verdict:
    def __init__(self, student, layouts):
        k = layouts.shape[0]
        mean = layouts.mean(axis=0)
        sd = np.maximum(layouts.std(axis=0, ddof=1), 1e-4 * np.abs(mean) + 1e-9)
        self.t = (student - mean) / (sd * np.sqrt(1 + 1 / k))
        self.ratio = student / np.maximum(mean, 1e-12)
        self.spread = sd / np.maximum(np.abs(mean), 1e-12)
        # scipy is imported here: it takes most of a plain check's start-up, which needs none
        # of it.
        from scipy import stats
        self.limit = float(stats.t.ppf(1 - FAMILY_ALARM / (2 * self.t.size), k - 1))
        a = np.abs(np.nan_to_num(self.t, nan=np.inf))
        self.worst_at = tuple(int(i) for i in np.unravel_index(int(np.argmax(a)), a.shape))
        self.worst = float(a[self.worst_at])
        self.ok = bool(np.all(a <= self.limit))

    def worst_region(self):
        region, channel = self.worst_at
        return (f"{REGIONS[region]}, {'RGB'[channel]}: {self.ratio[self.worst_at]:.3f} of ours, "
                f"t = {self.t[self.worst_at]:+.1f} (our layouts vary it by "
                f"{100 * self.spread[self.worst_at]:.1f} %)")
