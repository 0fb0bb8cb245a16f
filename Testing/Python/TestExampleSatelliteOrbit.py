"""Examples/Python/satellite_orbit.py run as a user runs it (headless, --out): occlusion between
the globe and ordinary VTK actors through the shared depth buffer.

The reference is exact geometry, not a picture: for each of 720 points of the orbit, the ray
from the eye to it is intersected with the WGS84 ellipsoid (vtkGlobeEllipsoid::IntersectRay,
double). Points the ellipsoid hides even when shrunk by 50 km must show no orbit colour within
a pixel; points it does not hide even when grown by 50 km must show it (the 50 km keep terrain
and the limb's anti-aliasing out of the question). The satellite, in front of the globe at the
default anomaly, is drawn at its projected centre; moved to the far side it is nowhere.
"""
import os
import sys
import tempfile
import unittest

from globe_test_support import EXAMPLES, Image, project, run_example

sys.path.insert(0, EXAMPLES)
import satellite_orbit as so  # noqa: E402
from vtkglobe import vtkGlobeEllipsoid  # noqa: E402

SIZE = (400, 300)


def is_orbit(p):
    return p[0] > 200 and p[2] > 200 and p[1] < 60


def is_satellite(p):
    return p[1] > 200 and p[2] > 200 and p[0] < 60


def hidden(body, eye, point):
    """Whether the ellipsoid is hit between the eye and the point."""
    direction = [p - e for p, e in zip(point, eye)]
    t = [0.0, 0.0]
    return body.IntersectRay(eye, direction, t) > 0 and t[0] < 1.0


class TestExampleSatelliteOrbit(unittest.TestCase):
    def run_example(self, tmp, anomaly):
        out = os.path.join(tmp, "orbit-%g.png" % anomaly)
        code, _, _ = run_example("satellite_orbit.py", "--out", out, "--size", "%dx%d" % SIZE,
                                 "--grid", "256", "--anomaly", str(anomaly))
        self.assertEqual(code, 0)
        image = Image(out)
        self.assertEqual((image.width, image.height), SIZE)
        return image

    def test_occlusion(self):
        with tempfile.TemporaryDirectory() as tmp:
            front = self.run_example(tmp, so.CAMERA_ANOMALY)
            back = self.run_example(tmp, so.CAMERA_ANOMALY + 180.0)
        _, renderer, wgs84 = so.build(SIZE, 256, so.CAMERA_ANOMALY)
        eye = renderer.GetActiveCamera().GetPosition()
        smaller, larger = vtkGlobeEllipsoid(), vtkGlobeEllipsoid()
        a, b, c = wgs84.GetRadii()
        smaller.SetRadii(a - 5e4, b - 5e4, c - 5e4)
        larger.SetRadii(a + 5e4, b + 5e4, c + 5e4)

        samples = []
        for k in range(720):
            p = so.orbit_point(k / 2.0)
            x, y = project(renderer, p)
            if not (2 <= x < SIZE[0] - 2 and 2 <= y < SIZE[1] - 2):
                continue
            if hidden(smaller, eye, p):
                samples.append((int(x), int(y), "hidden"))
            elif not hidden(larger, eye, p):
                samples.append((int(x), int(y), "visible"))
            else:
                samples.append((int(x), int(y), "limb"))
        shown = [(x, y) for x, y, kind in samples if kind != "hidden"]
        visible_ok = visible_bad = hidden_ok = hidden_bad = 0
        for x, y, kind in samples:
            if kind == "visible":
                if front.near(x, y, is_orbit, 1):
                    visible_ok += 1
                elif not front.near(x, y, is_satellite, 0):  # the satellite sits on the orbit
                    visible_bad += 1
                    print("  missing orbit at pixel (%d, %d): %s" % (x, y, front(x, y)))
            elif kind == "hidden":
                # Skip where the front arc crosses the back one on screen.
                if any(abs(x - u) <= 4 and abs(y - v) <= 4 for u, v in shown):
                    continue
                if front.near(x, y, is_orbit, 1):
                    hidden_bad += 1
                else:
                    hidden_ok += 1
        print("orbit points in front: %d drawn, %d missing; behind the globe: %d hidden, %d "
              "drawn" % (visible_ok, visible_bad, hidden_ok, hidden_bad))
        self.assertGreater(visible_ok, 150)
        self.assertGreater(hidden_ok, 100)
        self.assertEqual(visible_bad, 0)
        self.assertEqual(hidden_bad, 0)

        # The satellite: in front at the default anomaly, hidden on the far side.
        x, y = project(renderer, so.orbit_point(so.CAMERA_ANOMALY))
        self.assertFalse(hidden(wgs84, eye, so.orbit_point(so.CAMERA_ANOMALY)))
        self.assertTrue(hidden(smaller, eye, so.orbit_point(so.CAMERA_ANOMALY + 180.0)))
        print("satellite at pixel (%.0f, %.0f): %s; %d satellite pixels in front, %d behind"
              % (x, y, front(int(x), int(y)), front.count(is_satellite), back.count(is_satellite)))
        self.assertTrue(is_satellite(front(int(x), int(y))))
        self.assertGreater(front.count(is_satellite), 10)
        self.assertEqual(back.count(is_satellite), 0)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
