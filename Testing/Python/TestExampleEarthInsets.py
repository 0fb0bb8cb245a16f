"""Examples/Python/earth_insets.py run as a user runs it (headless, --out).

- The whole Earth: the PNG has the window's size and the globe covers the disc its angular
  radius predicts (within one perimeter of pixels).
- Boston: rendered with and without the imagery insets, the pictures differ inside the Boston
  inset's projected footprint and agree outside it (the inset is composed where it has data and
  nowhere else).
"""
import math
import os
import sys
import tempfile
import unittest

from globe_test_support import EXAMPLES, Image, project, run_example

sys.path.insert(0, EXAMPLES)
import earth_insets  # noqa: E402

SIZE = (400, 300)
BACKGROUND = (0, 0, 5)  # the example's (0, 0, 0.02)


class TestExampleEarthInsets(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def render(self, name, *arguments):
        out = os.path.join(self.tmp.name, name)
        code, _, _ = run_example("earth_insets.py", "--out", out, "--size", "%dx%d" % SIZE,
                                 "--grid", "256", *arguments)
        self.assertEqual(code, 0)
        self.assertGreater(os.path.getsize(out), 1000)
        image = Image(out)
        self.assertEqual((image.width, image.height), SIZE)
        return image

    def test_whole_earth_disc(self):
        image = self.render("earth.png", "--view", "earth")
        covered = image.count(lambda p: p != BACKGROUND)
        camera, _, angle, _ = earth_insets.VIEWS["earth"]
        distance = 6378137.0 + camera[2]
        f = SIZE[1] / 2.0 / math.tan(math.radians(angle / 2.0))
        radius = f * math.tan(math.asin(6371000.0 / distance))  # mean radius: 25..45 deg off the pole
        expected = math.pi * radius ** 2
        print("globe pixels %d, expected %.0f +- %.0f" % (covered, expected, 2 * math.pi * radius))
        self.assertLess(abs(covered - expected), 2.0 * math.pi * radius)

    def test_boston_inset(self):
        with_insets = self.render("boston.png", "--view", "boston")
        without = self.render("boston-no-insets.png", "--view", "boston", "--no-insets")

        # The inset's footprint on screen, from the example's own camera.
        window, renderer, body = earth_insets.build("boston", earth_insets.globe_scene.DATA,
                                                    SIZE, 256)
        corners = []
        for lon, lat in ((-71.498418, 42.614315), (-70.635076, 42.614315),
                         (-71.498418, 42.035672), (-70.635076, 42.035672)):
            p = [0.0] * 3
            body.GeodeticToCartesian(lon, lat, 0.0, p)
            corners.append(project(renderer, p))
        x0, x1 = min(c[0] for c in corners), max(c[0] for c in corners)
        y0, y1 = min(c[1] for c in corners), max(c[1] for c in corners)
        print("inset footprint x [%.0f, %.0f] y [%.0f, %.0f]" % (x0, x1, y0, y1))
        margin = 12  # the feathered border and the corners' curvature

        inside, outside = [], []
        for x, y, p in with_insets.pixels():
            q = without(x, y)
            d = sum(abs(a - b) for a, b in zip(p, q)) / 3.0
            if x0 + margin < x < x1 - margin and y0 + margin < y < y1 - margin:
                inside.append(d)
            elif not (x0 - margin < x < x1 + margin and y0 - margin < y < y1 + margin):
                outside.append(d)
        mean_in = sum(inside) / len(inside)
        changed_out = sum(1 for d in outside if d > 2.0)
        print("inside: %d pixels, mean |difference| %.1f; outside: %d pixels, %d changed"
              % (len(inside), mean_in, len(outside), changed_out))
        self.assertGreater(len(inside), 0.2 * SIZE[0] * SIZE[1])
        self.assertGreater(len(outside), 0.1 * SIZE[0] * SIZE[1])
        self.assertGreater(mean_in, 10.0)
        self.assertEqual(changed_out, 0)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
