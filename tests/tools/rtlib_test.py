#!/usr/bin/python3
"""tools/rtlib, the tools' shared module: PFM files read and written in either byte order with
rows the way round the renderer means them, the provenance of a tree, and the render checker's
block test leaving out rare samples but not a region that differs.
  rtlib_test.py RENDERER      (a chapter's program: ch01_background renders a vertical gradient)
"""
import os
import struct
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # leave no __pycache__ in tools/
sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "tools"))
from rtlib import block_test, pfm, provenance  # noqa: E402
import numpy as np  # noqa: E402

RENDERER = None  # set from the command line


class Pfm(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.TemporaryDirectory(prefix="rtlib-test.")
        self.dir = self.work.name

    def tearDown(self):
        self.work.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def render(self, name, *args):
        subprocess.run([RENDERER, "--width", "16", "--spp", "1", "--quiet", *args,
                        "--out", self.path(name)], check=True)
        return pfm.read(self.path(name))

    def test_rows_top_first_as_the_renderer_counts_them(self):
        # --crop counts rows from the top: the crop of row 0 is the image's first row, and the
        # crop of the last row its last, whatever the file's order of rows.
        full = self.render("full.pfm")
        self.assertEqual((full.width, full.channels), (16, 3))
        row = 16 * 3
        top = self.render("top.pfm", "--crop", "0,0,16,1")
        bottom = self.render("bottom.pfm", "--crop", f"0,{full.height - 1},16,{full.height}")
        self.assertEqual(full.pixels[:row], top.pixels)
        self.assertEqual(full.pixels[-row:], bottom.pixels)
        self.assertNotEqual(top.pixels, bottom.pixels, "the gradient must tell the rows apart")

    def test_write_gives_the_renderers_bytes(self):
        full = self.render("full.pfm")
        pfm.write(self.path("again.pfm"), full)
        with open(self.path("full.pfm"), "rb") as a, open(self.path("again.pfm"), "rb") as b:
            self.assertEqual(a.read(), b.read())

    def test_big_endian_round_trip(self):
        full = self.render("full.pfm")
        pfm.write(self.path("big.pfm"), full, byteorder="big")
        with open(self.path("big.pfm"), "rb") as f:
            self.assertEqual(f.read(20).split(b"\n")[2], b"1.0")  # positive scale: big endian
        self.assertEqual(pfm.read(self.path("big.pfm")), full)

    def test_one_channel_big_endian_by_hand(self):
        # 2 x 2, top row (1, 2), bottom row (3, 4): the file holds the bottom row first.
        with open(self.path("grey.pfm"), "wb") as f:
            f.write(b"Pf\n2 2\n1.0\n" + struct.pack(">4f", 3, 4, 1, 2))
        image = pfm.read(self.path("grey.pfm"))
        self.assertEqual((image.width, image.height, image.channels), (2, 2, 1))
        self.assertEqual(list(image.pixels), [1, 2, 3, 4])
        self.assertEqual(pfm.as_array(image)[:, :, 0].tolist(), [[1, 2], [3, 4]])

    def test_as_array_is_height_by_width_by_channels(self):
        full = self.render("full.pfm")
        array = pfm.as_array(full)
        self.assertEqual(array.shape, (full.height, 16, 3))
        self.assertEqual(array[0, 5].tolist(), list(full.pixels[15:18]))

    def test_refuses_what_is_no_pfm(self):
        for name, data in (("cut.pfm", b"PF\n2 2\n-1.0\n" + bytes(20)),
                           ("header.pfm", b"PF\n2"), ("magic.pfm", b"P6\n2 2\n255\n" + bytes(12)),
                           ("size.pfm", b"PF\n2 x\n-1.0\n" + bytes(48))):
            with open(self.path(name), "wb") as f:
                f.write(data)
            with self.assertRaises(pfm.FormatError, msg=name) as caught:
                pfm.read(self.path(name))
            self.assertIn(name, str(caught.exception))


class Provenance(unittest.TestCase):
    def test_commit_and_changed_sources(self):
        with tempfile.TemporaryDirectory(prefix="rtlib-test.") as repo:
            def git(*words):
                return subprocess.run(["git", "-C", repo, *words], check=True,
                                      capture_output=True, text=True).stdout.strip()
            git("init", "-q")
            os.makedirs(os.path.join(repo, "rt"))
            for name in ("rt/a.h", "notes.md"):
                with open(os.path.join(repo, name), "w") as f:
                    f.write("one\n")
            git("add", ".")
            git("-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "one")
            head = git("rev-parse", "HEAD")
            self.assertEqual(provenance.tree_state(repo), (head, []))
            self.assertEqual(provenance.tree_state(repo, abbrev=12).commit, head[:12])
            # Only the programs' sources count, and only tracked files.
            for name in ("notes.md", "rt/new.h"):
                with open(os.path.join(repo, name), "w") as f:
                    f.write("two\n")
            self.assertEqual(provenance.tree_state(repo).label("+dirty"), head)
            with open(os.path.join(repo, "rt/a.h"), "w") as f:
                f.write("two\n")
            self.assertEqual(provenance.tree_state(repo), (head, ["rt/a.h"]))
            self.assertEqual(provenance.tree_state(repo).label("+dirty"), head + "+dirty")
            # A folder inside the checkout is not a checkout of its own; its .commit says.
            copy = os.path.join(repo, "rt", "copy")
            os.makedirs(copy)
            self.assertEqual(provenance.tree_state(copy), ("unknown", []))
            with open(os.path.join(copy, ".commit"), "w") as f:
                f.write("0123456789abcdef\n")
            self.assertEqual(provenance.tree_state(copy, abbrev=7), ("0123456", []))

    def test_compiler_of_a_build(self):
        with tempfile.TemporaryDirectory(prefix="rtlib-test.") as build:
            self.assertEqual(provenance.compiler(build)["compiler"], "unknown compiler")
            with open(os.path.join(build, "CMakeCache.txt"), "w") as f:
                f.write("// a comment\nCMAKE_CXX_COMPILER:FILEPATH=/no/such/c++\n"
                        "CMAKE_BUILD_TYPE:STRING=Release\nCMAKE_CXX_FLAGS:STRING=-g\n"
                        "CMAKE_CXX_FLAGS_RELEASE:STRING=-O3 -DNDEBUG\nRT_SCALAR:STRING=float\n"
                        "CMAKE_HOME_DIRECTORY:INTERNAL=/src\n")
            self.assertEqual(provenance.compiler(build),
                             {"compiler": "/no/such/c++", "path": "/no/such/c++",
                              "build_type": "Release", "flags": "-g -O3 -DNDEBUG",
                              "scalar": "float"})
            self.assertEqual(provenance.source_of(build), "/src")

    def test_machine(self):
        m = provenance.machine()
        self.assertEqual(set(m), {"cpu", "cores", "system", "platform", "host"})
        self.assertTrue(m["cpu"] and m["cores"] >= 1)



class RareSamples(unittest.TestCase):
    """block_test.forgive_rare on one 8 x 8 block (channel 0 of 3), our renders having seen
    codes 0..90 around it."""
    low, high = np.zeros((1, 1, 3)), np.full((1, 1, 3), 90.0)

    def forgiven(self, pixels):
        return block_test.forgive_rare(pixels - 0.0, pixels, self.low, self.high, 8)

    def test_two_rare_samples_left_out(self):
        pixels = np.zeros((8, 8, 3))
        pixels[2, 3, 0] = pixels[5, 5, 0] = 90
        self.assertEqual(np.abs(self.forgiven(pixels)).max(), 0)

    def test_a_third_is_kept(self):
        pixels = np.zeros((8, 8, 3))
        pixels[2, 3, 0] = pixels[5, 5, 0] = 90
        pixels[7, 0, 0] = 40
        out = self.forgiven(pixels)
        self.assertEqual(out[7, 0, 0], 40)
        self.assertEqual(np.count_nonzero(out), 1)

    def test_a_value_never_seen_is_kept(self):
        pixels = np.zeros((8, 8, 3))
        pixels[2, 3, 0] = 255  # beyond the 90 our renders reached: a speck, not a rare sample
        self.assertEqual(self.forgiven(pixels)[2, 3, 0], 255)

    def test_a_block_off_by_one_code_loses_two_pixels_only(self):
        # Ties of 8-bit codes: exactly two of the 64 equal deviations are left out.
        out = self.forgiven(np.ones((8, 8, 3)))
        self.assertEqual(np.count_nonzero(out[..., 0] == 0), 2)
        self.assertEqual(np.count_nonzero(out[..., 0] == 1), 62)

    def test_a_nan_is_never_left_out(self):
        pixels = np.zeros((8, 8, 3))
        pixels[1, 1, 0] = np.nan
        self.assertFalse(np.isfinite(self.forgiven(pixels)[1, 1, 0]))

    def test_skew_moves_only_the_long_side(self):
        z = np.array([[[5.0, -5.0, 5.0]]])
        out = block_test.skew_adjusted(z, np.array([[[1.0, 1.0, 0.0]]]))
        self.assertLess(out[0, 0, 0], 5.0)      # the long side's bound moved out
        self.assertEqual(out[0, 0, 1], -5.0)   # the short side's kept
        self.assertEqual(out[0, 0, 2], 5.0)    # no skew, no change


class ZScale(unittest.TestCase):
    """The block test's z is standard normal for a render of the same scene, whether our renders
    are made at the student's spp or at fewer and scaled: pixels are means of independent
    samples (normal, by the central limit theorem), ours K renders of them, the student's one.
    Over 3,072 block tests the spread of z is 1 within 15 %: a little below 1 (0.90 to 0.95
    measured), since each block's two pixels farthest from our mean are left out as possibly
    rare, and the skew's correction, estimated from K renders, narrows z further; both err on
    the side of fewer false alarms. (Its sampling error is about 2 %.)"""

    def spread(self, spp, rendered, k, seed):
        from rtlib import display_codes
        rng = np.random.default_rng(seed)
        mean, sigma, size, b = 0.4, 0.3, 512, 16
        # Each pixel its own brightness, so that the blocks differ as a scene's do.
        light = mean + 0.1 * rng.random((size, size, 3))
        renders = light + rng.normal(0, sigma / np.sqrt(rendered), (k, size, size, 3))
        student = light + rng.normal(0, sigma / np.sqrt(spp), (size, size, 3))
        exp = block_test.Expectation(renders, rendered, spp, "float", b, display_codes.encode,
                                     display_codes.encode_continuous)
        z = exp.z(student)
        self.assertEqual(z.size, 3072)
        return float(np.std(z))

    def test_renders_at_the_students_spp(self):
        self.assertAlmostEqual(self.spread(64, 64, 8, 1), 1, delta=0.15)

    def test_renders_at_fewer_spp_scaled(self):
        # 10,000 spp from 4 renders at 500: our mean's own error is five times the student's.
        self.assertAlmostEqual(self.spread(10000, 500, 4, 2), 1, delta=0.15)
        self.assertAlmostEqual(self.spread(200, 55, 4, 3), 1, delta=0.15)


if __name__ == "__main__":
    RENDERER = sys.argv.pop(1)
    unittest.main()
