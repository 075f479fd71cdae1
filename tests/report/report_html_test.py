#!/usr/bin/python3
"""tools/rtlib/report_html, the HTML report's making: the maps of where two images differ (their
scale, their colours, one size required), the halves of a side-by-side image, and the page (a
comparison placed where the Markdown has it, the Markdown report's links kept working, headings
with GitHub's ids, no image shown that is not there)."""
import os
import re
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # leave no __pycache__ in tools/
sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "tools"))
from rtlib import report_html  # noqa: E402
from rtlib.report_html import Comparison, Gallery  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import colormaps  # noqa: E402
from PIL import Image  # noqa: E402


class ReportHtml(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.TemporaryDirectory(prefix="report-html-test.")
        self.root = self.work.name

    def tearDown(self):
        self.work.cleanup()

    def image(self, name, pixels):
        Image.fromarray(np.asarray(pixels, dtype=np.uint8)).save(os.path.join(self.root, name))
        return name

    def noise(self, seed, shape=(12, 16, 3)):
        return np.random.default_rng(seed).integers(0, 256, size=shape)

    def test_map_of_identical_images_is_black_and_says_so(self):
        a = self.image("a.png", self.noise(1))
        scale, differing = report_html.difference_map(
            os.path.join(self.root, a), os.path.join(self.root, a), self.path("map.png"))
        self.assertEqual(differing, 0.0)
        self.assertEqual(scale, 1 / 255)
        rgb = np.asarray(Image.open(self.path("map.png")).convert("RGB"))
        self.assertTrue((rgb == rgb[0, 0]).all())
        self.assertLess(rgb[0, 0].max(), 8)  # the scale's first colour, nearly black

    def test_map_colours_each_pixel_by_its_largest_channel_difference(self):
        pixels = self.noise(2)
        changed = pixels.copy()
        changed[3, 5, 1] = (changed[3, 5, 1] + 128) % 256     # the largest difference, 128
        changed[7, 2, 2] = (changed[7, 2, 2] + 64) % 256      # half of it
        a, b = self.image("a.png", pixels), self.image("b.png", changed)
        scale, differing = report_html.difference_map(
            *(os.path.join(self.root, p) for p in (a, b)), self.path("map.png"))
        self.assertAlmostEqual(differing, 2 / (12 * 16))
        # The 99th percentile of the two differences 128 and 64: nearly 128.
        self.assertAlmostEqual(scale * 255, 64 + 0.99 * 64, places=6)
        rgb = np.asarray(Image.open(self.path("map.png")).convert("RGB")).astype(int)
        colours = np.round(colormaps[report_html.COLOURS](np.arange(256) / 255)[:, :3] * 255)
        self.assertEqual(list(rgb[3, 5]), list(colours[255]))
        self.assertEqual(list(rgb[7, 2]), list(colours[round(64 / (scale * 255) * 255)]))
        self.assertEqual(list(rgb[0, 0]), list(colours[0]))

    def test_map_refuses_two_sizes(self):
        a = self.image("a.png", self.noise(3))
        b = self.image("b.png", self.noise(4, (16, 12, 3)))
        with self.assertRaisesRegex(ValueError, "16x12 but .* is 12x16"):
            report_html.difference_map(*(os.path.join(self.root, p) for p in (a, b)),
                                       self.path("map.png"))
        self.assertFalse(os.path.exists(self.path("map.png")))

    def test_halves_of_a_side_by_side_image(self):
        left, right = self.noise(5), self.noise(6)
        row = np.concatenate([left, np.zeros((12, 4, 3)), right], axis=1)
        self.image("row.png", row)
        outs = [self.path("l.png"), self.path("r.png")]
        report_html.split_side_by_side(self.path("row.png"), outs)
        self.assertTrue((np.asarray(Image.open(outs[0])) == left).all())
        self.assertTrue((np.asarray(Image.open(outs[1])) == right).all())
        self.image("odd.png", np.zeros((12, 35, 3)))
        with self.assertRaisesRegex(ValueError, "not 2 images 4 apart"):
            report_html.split_side_by_side(self.path("odd.png"), outs)

    def test_page_places_comparisons_and_keeps_the_markdown_report_links(self):
        a, b = self.image("a.png", self.noise(7)), self.image("b.png", self.noise(8))
        c = self.image("c.png", self.noise(9, (5, 5, 3)))
        pair = Comparison(self.root, "pair", a, b, "left one", "right one",
                          markdown_lines=["![b](b.png)"])
        sizes = Gallery(["| a | c |"], [Comparison(self.root, "sizes", a, c, "a", "c")])
        lines = ["# Title", "", "See [the pair](README.md#ch06_defocus_aperture_0.5-figure).",
                 "", "### ch06_defocus_aperture_0.5 figure", "", pair, "", "after", "", sizes]
        self.assertEqual(report_html.markdown_of(lines).splitlines()[6:],
                         ["![b](b.png)", "", "after", "", "| a | c |"])
        page = report_html.page(lines, "Title", self.root)
        self.assertIn('href="#ch06_defocus_aperture_05-figure"', page)
        self.assertIn('id="ch06_defocus_aperture_05-figure"', page)
        # The comparison sits between its heading and the next paragraph.
        self.assertRegex(page, r'(?s)aperture_05-figure".*<figure class="compare" '
                               r'id="compare-pair">.*</figure>\s*<p>after</p>')
        self.assertIn('data-width="16" data-height="12"', page)
        self.assertTrue(os.path.exists(self.path("html/maps/pair.png")))
        # Images of two sizes are shown side by side, not as a comparison.
        self.assertIn('<figure class="pair" id="pair-sizes">', page)
        self.assertNotIn("compare-sizes", page)
        self.assertNotRegex(page, "PLACEHOLDER")

    def test_page_refuses_an_image_that_is_not_there(self):
        with self.assertRaisesRegex(ValueError, "not there: figures/gone.png"):
            report_html.page(["# T", "", "![gone](figures/gone.png)"], "T", self.root)

    def test_ids_are_github_s(self):
        for heading, slug in (("Scene ch11: the Cornell box", "scene-ch11-the-cornell-box"),
                              ("ch06_defocus_aperture_0.5", "ch06_defocus_aperture_05"),
                              ("1. The object-oriented design: hittable, hit_record",
                               "1-the-object-oriented-design-hittable-hit_record")):
            self.assertEqual(report_html.slug(heading), slug)
            page = report_html.page([f"## {heading}"], "T", self.root)
            self.assertEqual(re.search(r'<h2 id="([^"]+)"', page).group(1), slug)

    def path(self, name):
        return os.path.join(self.root, name)


if __name__ == "__main__":
    unittest.main()
