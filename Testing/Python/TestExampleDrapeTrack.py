"""Examples/Python/drape_track.py run as a user runs it (headless, --out): lon/lat/height data
put on the body by vtkTransformFilter + vtkGlobeGeodeticTransform, occluded by the terrain.

The reference is a CPU ray march in double, independent of the renderer: for each of 360 track
points, 400 samples along the ray from the eye are converted to geodetic coordinates
(vtkGlobeEllipsoid) and compared with the SRTM heights of Mount Rainier (the vtkGlobeLayer's
filled posts, bilinear between post centres as the GPU samples them). A point is hidden when the
terrain rises more than 150 m above some sample, visible when every sample clears the terrain by
150 m (the margin covers the projective grid's approximation of the terrain); hidden points must
show no track colour within a pixel, visible ones must show it. Both kinds must be numerous: the
far side of the loop passes behind the mountain. Also: the transform's output points are where
the geodetic formulas put them, and a bad --track file is refused with a message.
"""
import math
import os
import sys
import tempfile
import unittest

from globe_test_support import EXAMPLES, Image, file_layer, project, run_example

sys.path.insert(0, EXAMPLES)
import drape_track as dt  # noqa: E402

SIZE = (400, 300)
MARGIN = 150.0


def is_track(p):
    return p[0] > 200 and p[2] > 200 and p[1] < 60


class Terrain:
    """Bilinear heights of a geographic height layer, between post centres."""

    def __init__(self, layer):
        self.assertion = layer.Update()
        self.extent = [0.0] * 4
        layer.GetGeographicExtent(self.extent)
        self.w, self.h = layer.GetNumberOfColumns(), layer.GetNumberOfRows()
        self.values = memoryview(layer.GetData()).cast("B").cast("f")

    def __call__(self, lon, lat):
        west, east, south, north = self.extent
        x = (lon - west) / (east - west) * self.w - 0.5
        y = (north - lat) / (north - south) * self.h - 0.5
        i, j = int(math.floor(x)), int(math.floor(y))
        fx, fy = x - i, y - j

        def at(i, j):
            i = min(max(i, 0), self.w - 1)
            j = min(max(j, 0), self.h - 1)
            return self.values[j * self.w + i]
        return ((1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) +
                fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1)))


class TestExampleDrapeTrack(unittest.TestCase):
    def test_terrain_occludes_track(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "drape.png")
            code, _, _ = run_example("drape_track.py", "--out", out, "--size", "%dx%d" % SIZE,
                                     "--grid", "256")
            self.assertEqual(code, 0)
            image = Image(out)
        self.assertEqual((image.width, image.height), SIZE)

        terrain = Terrain(file_layer("earth/mt_rainier_90m.tif", True))
        self.assertTrue(terrain.assertion)
        _, renderer, body = dt.build(SIZE, 256)
        eye = renderer.GetActiveCamera().GetPosition()
        samples = []
        llh = [0.0] * 3
        for lon, lat, h in dt.loop_track()[:-1]:
            p = [0.0] * 3
            body.GeodeticToCartesian(lon, lat, h, p)
            x, y = project(renderer, p)
            if not (2 <= x < SIZE[0] - 2 and 2 <= y < SIZE[1] - 2):
                continue
            lowest_clearance = float("inf")
            for k in range(1, 400):
                t = k / 400.0
                body.CartesianToGeodetic([e + t * (q - e) for e, q in zip(eye, p)], llh)
                lowest_clearance = min(lowest_clearance, llh[2] - terrain(llh[0], llh[1]))
            if lowest_clearance < -MARGIN:
                samples.append((int(x), int(y), "hidden"))
            elif lowest_clearance > MARGIN:
                samples.append((int(x), int(y), "visible"))
            else:
                samples.append((int(x), int(y), "grazing"))
        shown = [(x, y) for x, y, kind in samples if kind != "hidden"]
        counts = {"visible ok": 0, "visible bad": 0, "hidden ok": 0, "hidden bad": 0}
        for x, y, kind in samples:
            if kind == "visible":
                counts["visible ok" if image.near(x, y, is_track, 1) else "visible bad"] += 1
            elif kind == "hidden" and not any(abs(x - u) <= 4 and abs(y - v) <= 4 for u, v in shown):
                counts["hidden bad" if image.near(x, y, is_track, 1) else "hidden ok"] += 1
        print("track points: %(visible ok)d visible and drawn, %(visible bad)d visible but missing, "
              "%(hidden ok)d hidden by terrain, %(hidden bad)d hidden but drawn" % counts)
        self.assertGreater(counts["visible ok"], 100)
        self.assertGreater(counts["hidden ok"], 20)
        self.assertEqual(counts["visible bad"], 0)
        self.assertEqual(counts["hidden bad"], 0)

    def test_transform_places_points(self):
        """The pipeline's points against the textbook geodetic formula."""
        from vtkglobe import vtkGlobeEllipsoid
        body = vtkGlobeEllipsoid()
        track = dt.loop_track(12)
        f = dt.on_body(dt.geodetic_polydata(track, True), body)
        f.Update()
        a, _, c = body.GetRadii()
        e2 = 1.0 - c * c / (a * a)
        worst = 0.0
        for k, (lon, lat, h) in enumerate(track):
            phi, lam = math.radians(lat), math.radians(lon)
            n = a / math.sqrt(1.0 - e2 * math.sin(phi) ** 2)
            ref = ((n + h) * math.cos(phi) * math.cos(lam), (n + h) * math.cos(phi) * math.sin(lam),
                   (n * (1.0 - e2) + h) * math.sin(phi))
            worst = max(worst, math.dist(f.GetOutput().GetPoint(k), ref))
        print("worst |transformed - formula| = %.2e m" % worst)
        self.assertLess(worst, 1e-6)
        self.assertEqual(f.GetOutput().GetNumberOfLines(), 1)

    def test_bad_track_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            bad = os.path.join(tmp, "bad.csv")
            with open(bad, "w") as f:
                f.write("# lon,lat,height\n-121.7,46.8,3000\nnot a number\n")
            code, _, stderr = run_example("drape_track.py", "--track", bad,
                                          "--out", os.path.join(tmp, "x.png"))
            self.assertEqual(code, 1)
            self.assertIn("bad.csv:3: expected 'lon,lat,height'", stderr)
            self.assertFalse(os.path.exists(os.path.join(tmp, "x.png")))
            code, _, stderr = run_example("drape_track.py", "--track", os.path.join(tmp, "none.csv"))
            self.assertEqual(code, 1)
            self.assertIn("none.csv: No such file or directory", stderr)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
