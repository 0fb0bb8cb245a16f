"""Examples/Python/navigate.py run as a user runs it (headless, --out): the readout under the
cursor, the draped track, the fly-to keys' flight (--fly), and bad arguments.

- The readout at the window's centre, which looks at the view's target: its longitude and
  latitude are the target's within 0.02 degrees, its orthometric height is the ellipsoidal one
  less EGM96's N (vtkGlobeGeoid, which TestGlobeVerticalDatum checks against PROJ) to the
  printed decimetre, and the distance is the view's range within 5 %.
- The draped track shows: over 300 pixels of its magenta (the gaps are TestGlobeDrapedTrack's).
- The views' targets are on the composed terrain (vtkGlobeTerrain of the same layers); after
  --fly everest the camera is where vtkGlobeCamera puts the Everest view (1 mm), and the
  readout is at Everest.
"""
import math
import os
import re
import sys
import unittest

from globe_test_support import EXAMPLES, ExampleTest, Image, file_layer, run_example

sys.path.insert(0, EXAMPLES)
import navigate  # noqa: E402

from vtkmodules.vtkRenderingCore import vtkCamera  # noqa: E402
from vtkglobe import (vtkGlobeCamera, vtkGlobeEllipsoid, vtkGlobeGeoid,  # noqa: E402
                      vtkGlobeTerrain)

SIZE = (400, 300)
READOUT = re.compile(r"readout at \((\d+), (\d+)\): lon (\S+)  lat (\S+)  h (\S+) m  H (\S+) m  "
                     r"distance (\S+) km")
CAMERA = re.compile(r"camera: (\S+) (\S+) (\S+)")
VIEW = re.compile(r"view: (\S+) (\S+) (\S+) (\S+) (\S+) (\S+)")


def is_track(p):
    return p[0] > 200 and p[1] < 80 and p[2] > 200


class TestExampleNavigate(ExampleTest):
    def run_navigate(self, *extra):
        code, stdout, _ = run_example("navigate.py", "--out", self.out, "--size", "%dx%d" % SIZE,
                                      "--grid", "256", *extra)
        self.assertEqual(code, 0)
        readout = READOUT.search(stdout)
        camera = CAMERA.search(stdout)
        view = VIEW.search(stdout)
        self.assertIsNotNone(readout, stdout)
        self.assertIsNotNone(camera, stdout)
        self.assertIsNotNone(view, stdout)
        image = Image(self.out)
        self.assertEqual((image.width, image.height), SIZE)
        values = [float(v) for v in readout.groups()[2:]]
        return (image, values, [float(v) for v in camera.groups()],
                [float(v) for v in view.groups()])

    def check_view(self, name, view):
        """The view is VIEWS[name] with its target on the composed terrain."""
        terrain = vtkGlobeTerrain()
        for file in ("relief_2deg", "mt_rainier_90m", "mt_everest_90m"):
            terrain.AddLayer(file_layer("earth/%s.tif" % file, True))
            if file.startswith("mt_"):
                terrain.GetLayer(terrain.GetNumberOfLayers() - 1).SetVerticalDatumToEGM96()
        want = list(navigate.VIEWS[name])
        want[2] = terrain.GetHeight(want[0], want[1])
        for got, expected in zip(view, want):
            self.assertLess(abs(got - expected), 1e-6 * max(1.0, abs(expected)))

    def check_readout(self, values, view):
        lon, lat, h, orthometric, distance = values
        geoid = vtkGlobeGeoid()
        geoid.SetFileName(vtkGlobeGeoid.GetEGM96FileName())
        self.assertTrue(geoid.Update())
        n = geoid.GetUndulation(lon, lat)
        print("readout: lon %.5f lat %.5f h %.1f H %.1f (h - H %.2f, N %.3f), %.1f km (range %.1f)"
              % (lon, lat, h, orthometric, h - orthometric, n, distance, view[5] / 1000.0))
        self.assertLess(abs(lon - view[0]), 0.02)
        self.assertLess(abs(lat - view[1]), 0.02)
        self.assertLess(abs((h - orthometric) - n), 0.11)  # both printed to 0.1 m
        self.assertLess(abs(distance * 1000.0 - view[5]), 0.05 * view[5])

    def test_readout_and_track(self):
        image, values, _, view = self.run_navigate()
        self.check_view("rainier", view)
        self.check_readout(values, view)
        track = image.count(is_track)
        print("track pixels: %d" % track)
        self.assertGreater(track, 300)

    def test_fly_to_everest(self):
        _, values, position, view = self.run_navigate("--fly", "everest")
        self.check_view("everest", view)
        self.check_readout(values, view)
        camera = vtkCamera()
        self.assertTrue(vtkGlobeCamera.LookAt(camera, vtkGlobeEllipsoid(), view))
        error = math.dist(camera.GetPosition(), position)
        print("camera after the flight: %.2g m from the Everest view" % error)
        self.assertLess(error, 1e-3 + 1e-9 * max(abs(v) for v in position))

    def test_arguments(self):
        self.check_help("navigate.py", ["--fly", "--pick", "readout"])
        code, _, stderr = run_example("navigate.py", "--pick", "abc", "--out", self.out)
        self.assertEqual(code, 2)
        self.assertIn("--pick must look like", stderr)
        self.assertFalse(os.path.exists(self.out))


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
