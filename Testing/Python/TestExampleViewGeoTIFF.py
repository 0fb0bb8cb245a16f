"""Examples/Python/view_geotiff.py run as a user runs it: --help, bad paths, and a real GeoTIFF.

- --help exits 0 and explains the arguments.
- A missing path, a folder, a file that is not a TIFF, and a TIFF without georeferencing each
  exit 1 with a one-line message naming the file and the reason, and write no image.
- The Rainier SRTM tile: the script reports the raster's size and extent (1201x1201, the pixel
  edges of Data/README.md's georeferencing), frames the camera on it (the extent's corners
  project inside the window and span at least 60 % of its height), and the picture is ground
  from edge to edge (no background pixel: the framing looks at the raster, not at space).
- The Moon's map names its own 1,737,400 m sphere: the script puts it on that body.
"""
import os
import sys
import tempfile
import unittest

from globe_test_support import DATA, EXAMPLES, Image, project, run_example

sys.path.insert(0, EXAMPLES)
import view_geotiff as vg  # noqa: E402

SIZE = (400, 300)


class TestExampleViewGeoTIFF(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.out = os.path.join(self.tmp.name, "out.png")

    def tearDown(self):
        self.tmp.cleanup()

    def test_help(self):
        code, stdout, _ = run_example("view_geotiff.py", "--help")
        self.assertEqual(code, 0)
        for word in ("geotiff", "--out", "--interactive", "--role"):
            self.assertIn(word, stdout)

    def refused(self, path, message):
        code, _, stderr = run_example("view_geotiff.py", path, "--out", self.out)
        self.assertEqual(code, 1)
        self.assertIn("error: %s: %s" % (path, message), stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_bad_paths(self):
        self.refused(os.path.join(self.tmp.name, "missing.tif"), "no such file")
        self.refused(self.tmp.name, "not a file")
        self.refused(os.path.join(DATA, "README.md"), "not a GeoTIFF")
        # A TIFF that is not a GeoTIFF: the layer's own error reaches the user.
        from vtkmodules.vtkImagingSources import vtkImageCanvasSource2D
        from vtkmodules.vtkIOImage import vtkTIFFWriter
        canvas = vtkImageCanvasSource2D()
        canvas.SetExtent(0, 15, 0, 15, 0, 0)
        canvas.SetScalarTypeToUnsignedChar()
        canvas.SetNumberOfScalarComponents(3)
        plain = os.path.join(self.tmp.name, "plain.tif")
        writer = vtkTIFFWriter()
        writer.SetFileName(plain)
        writer.SetInputConnection(canvas.GetOutputPort())
        writer.Write()
        self.refused(plain, "cannot be shown: Cannot load '%s': it has no GeoTIFF georeferencing"
                     % plain)

    def test_rainier_framed(self):
        path = os.path.join(DATA, "earth", "mt_rainier_90m.tif")
        code, stdout, _ = run_example("view_geotiff.py", path, "--out", self.out,
                                      "--size", "%dx%d" % SIZE, "--grid", "256")
        self.assertEqual(code, 0)
        # Data/README.md: origin (-122.000417, 47.000417), 1201 posts of 0.000833333 degrees.
        self.assertIn("1201x1201 height raster, lon [-122.000417, -120.999583], "
                      "lat [45.999583, 47.000417]", stdout)
        self.assertIn("body WGS84", stdout)
        image = Image(self.out)
        self.assertEqual((image.width, image.height), SIZE)
        background = image.count(lambda p: p == (0, 0, 0))
        print("background pixels: %d" % background)
        self.assertEqual(background, 0)

        layer = vg.load(path, "auto")
        _, renderer, body, camera = vg.build(layer, SIZE, 256)
        extent = [0.0] * 4
        layer.GetGeographicExtent(extent)
        ys = []
        for lon in extent[:2]:
            for lat in extent[2:]:
                p = [0.0] * 3
                body.GeodeticToCartesian(lon, lat, 0.0, p)
                x, y = project(renderer, p)
                print("corner (%.3f, %.3f) at pixel (%.0f, %.0f)" % (lon, lat, x, y))
                self.assertTrue(0 <= x <= SIZE[0] and 0 <= y <= SIZE[1])
                ys.append(y)
        self.assertGreater(max(ys) - min(ys), 0.6 * SIZE[1])

    def test_moon_body(self):
        layer = vg.load(os.path.join(DATA, "moon", "moon_1024x512.tif"), "auto")
        self.assertEqual(layer.GetRoleAsString().lower(), "color")
        body = vg.body_for(layer)
        self.assertEqual(body.GetRadii(), (1737400.0, 1737400.0, 1737400.0))


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
