"""Examples/Python/moon.py run as a user runs it (headless, --out), from two distances.

The Moon has no height layer, so its image is the disc of a 1,737,400 m sphere (the radius the
example reads from the GeoTIFF's datum): at each distance the lit pixels cover
pi (f tan(asin(R / d)))^2 within one perimeter of pixels, and the ratio of the two areas is the
predicted one within 2 %.
"""
import math
import os
import sys
import tempfile
import unittest

from globe_test_support import Image, run_example

SIZE = (400, 300)
VIEW_ANGLE = 30.0
RADIUS = 1737400.0


class TestExampleMoon(unittest.TestCase):
    def test_disc(self):
        areas = []
        with tempfile.TemporaryDirectory() as tmp:
            for distance in (1.2e7, 8.0e6):  # the disc within the window
                out = os.path.join(tmp, "moon-%g.png" % distance)
                code, stdout, _ = run_example("moon.py", "--out", out, "--size", "%dx%d" % SIZE,
                                              "--grid", "256", "--distance", str(distance))
                self.assertEqual(code, 0)
                self.assertIn("wrote", stdout)
                image = Image(out)
                self.assertEqual((image.width, image.height), SIZE)
                covered = image.count(lambda p: p != (0, 0, 0))
                f = SIZE[1] / 2.0 / math.tan(math.radians(VIEW_ANGLE / 2.0))
                radius = f * math.tan(math.asin(RADIUS / distance))
                expected = math.pi * radius ** 2
                print("distance %.0f km: %d pixels, expected %.0f +- %.0f"
                      % (distance / 1000, covered, expected, 2 * math.pi * radius))
                self.assertLess(abs(covered - expected), 2.0 * math.pi * radius)
                # The disc is centred.
                self.assertNotEqual(image(SIZE[0] // 2, SIZE[1] // 2), (0, 0, 0))
                areas.append((covered, expected))
        ratio, predicted = areas[1][0] / areas[0][0], areas[1][1] / areas[0][1]
        print("area ratio %.4f, predicted %.4f" % (ratio, predicted))
        self.assertLess(abs(ratio / predicted - 1.0), 0.02)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
