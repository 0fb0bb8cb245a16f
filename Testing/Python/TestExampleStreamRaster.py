"""Examples/Python/stream_raster.py run as a user runs it (issue "Planetary-scale data").

- --help exits 0 and explains the arguments.
- A missing file exits 1 with a message naming it, and writes no image.
- Blue Marble (Data/earth/world.tif, 2048 x 1024) streamed in pages of 64 through a 1 MiB GPU
  cache, from 2,000 km over Africa: the script reports the pyramid (6 levels), frames load pages
  until the picture is final, the GPU layer memory stays within the cache (1 MiB and the page
  table), and the picture is the imagery: the view is covered, and its colours are Blue
  Marble's (Africa and the Gulf of Guinea), not the bare globe's blue base colour (mean blue
  about 17 against 96 for the base colour, which an inset elsewhere on the Earth leaves).
"""
import os
import re
import unittest

from globe_test_support import DATA, ExampleTest, Image, run_example


class TestExampleStreamRaster(ExampleTest):
    def test_help(self):
        self.check_help("stream_raster.py", ("raster", "--gpu", "--page", "--view", "prepare"))

    def test_missing(self):
        missing = os.path.join(self.tmp.name, "nothing.tif")
        code, _, stderr = run_example("stream_raster.py", missing, "--out", self.out)
        self.assertEqual(code, 1)
        self.assertIn("nothing.tif", stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_world(self):
        code, stdout, stderr = run_example(
            "stream_raster.py", os.path.join(DATA, "earth", "world.tif"), "--out", self.out,
            "--size", "200x150", "--page", "64", "--gpu", "1", "--view", "20,0,2000000",
            "--data", DATA)
        self.assertEqual(code, 0, stderr)
        self.assertIn("2048x1024 color, 6 levels of 64-texel pages", stdout)
        final = re.search(r"final after (\d+) frames", stdout)
        self.assertIsNotNone(final, stdout)
        loaded = [int(m.group(1)) for m in re.finditer(r"^\s*\d+\s+[\d.]+\s+\d+\s+(\d+)", stdout, re.M)]
        self.assertTrue(loaded, stdout)
        self.assertGreater(loaded[-1], 1, stdout)
        memory = re.search(r"GPU page cache ([\d.]+) MiB", stdout)
        self.assertIsNotNone(memory, stdout)
        self.assertLessEqual(float(memory.group(1)), 1.02, stdout)
        image = Image(self.out)
        pixels = [p for _, _, p in image.pixels()]
        dark = sum(1 for p in pixels if max(p) < 8)
        self.assertLess(dark, len(pixels) // 20, "the globe covers the view")
        mean = [sum(p[k] for p in pixels) / len(pixels) for k in range(3)]
        self.assertLess(mean[2], 50, mean)


if __name__ == "__main__":
    unittest.main()
