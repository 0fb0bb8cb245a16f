"""The C++ regression scenes rebuilt from Python and compared with the C++ tests' baselines,
unchanged, by VTK's image comparison with the same 0.05 threshold:
TestGlobeWholeEarth.cxx (the whole Earth from 22,000 km) and TestGlobeRainier.cxx (Mount Rainier
from 16 km up, clipping range 100 m .. 1,000 km). Same window (300x225), grid (256), layers,
camera, light (VTK's automatic headlight) and two frames.

Beyond the picture, numbers read back from the depth buffer: the whole Earth's disc covers the
area its angular radius predicts, and at Rainier the highest rendered point is the data's
summit (4,371 m), as the C++ test checks.
"""
import math
import sys
import unittest

from globe_test_support import Scene, compare_with_baseline, read_depth, unproject


class TestGlobeBaselinesPython(unittest.TestCase):
    def test_whole_earth(self):
        scene = Scene()
        scene.add_earth_layers()
        scene.look((-40.0, 25.0, 2.2e7), (-40.0, 25.0, 0.0), 30.0)
        scene.render()
        self.assertTrue(scene.mapper.GetLastFrameDrewGlobe())
        self.assertTrue(scene.mapper.GetPrimaryFromReduction())

        # The disc: a sphere of radius ~a seen from distance d under the angle asin(a / d); its
        # image radius is f tan(asin(a / d)) with f = (H / 2) / tan(15 deg).
        depth = read_depth(scene.window)
        covered = sum(1 for d in depth if d < 1.0)
        eye = scene.renderer.GetActiveCamera().GetPosition()
        distance = math.sqrt(sum(v * v for v in eye))
        a, _, c = scene.body.GetRadii()
        f = 225 / 2.0 / math.tan(math.radians(15.0))
        # Between the polar and the equatorial radius (the view is 25 degrees off the equator).
        low = math.pi * (f * math.tan(math.asin(c / distance))) ** 2
        high = math.pi * (f * math.tan(math.asin((a + 6000.0) / distance))) ** 2
        print("covered pixels %d, expected between %.0f and %.0f" % (covered, low, high))
        self.assertGreater(covered, low - 2.0 * math.pi * f * math.tan(math.asin(c / distance)))
        self.assertLess(covered, high + 2.0 * math.pi * f * math.tan(math.asin(a / distance)))

        self.assertLessEqual(compare_with_baseline(scene.window, "TestGlobeWholeEarth"), 0.05)

    def test_rainier(self):
        scene = Scene()
        scene.add_earth_layers()
        scene.look((-121.86, 46.75, 16000.0), (-121.7603, 46.8523, 4392.0), 40.0, 100.0, 1.0e6)
        scene.render()
        self.assertTrue(scene.mapper.GetLastFrameDrewGlobe())

        depth = read_depth(scene.window)
        width, height = scene.window.GetSize()
        covered = sum(1 for d in depth if d < 1.0)
        highest, llh = -1e9, [0.0] * 3
        for y in range(0, height):
            for x in range(0, width):
                d = depth[y * width + x]
                if d < 1.0:
                    scene.body.CartesianToGeodetic(unproject(scene.renderer, x + 0.5, y + 0.5, d), llh)
                    highest = max(highest, llh[2])
        print("covered pixels %d of %d; highest rendered point %.1f m (data summit 4371 m)"
              % (covered, width * height, highest))
        self.assertGreater(covered, 0.5 * width * height)
        self.assertGreater(highest, 4250.0)
        self.assertLess(highest, 4400.0)

        self.assertLessEqual(compare_with_baseline(scene.window, "TestGlobeRainier"), 0.05)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
