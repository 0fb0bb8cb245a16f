"""Examples/Python/view_geotiff.py run as a user runs it: --help, bad paths, and a real GeoTIFF.

- --help exits 0 and explains the arguments.
- A missing path, a folder, a file that is not a TIFF, and a TIFF without georeferencing each
  exit 1 with a one-line message naming the file and the reason, and write no image.
- The Rainier SRTM tile: the script reports the raster's size and extent (1201x1201, the pixel
  edges of Data/README.md's georeferencing), frames the camera on it (the extent's corners
  project inside the window and span at least 60 % of its height), and the picture is ground
  from edge to edge (no background pixel: the framing looks at the raster, not at space).
- The Moon's map names its own 1,737,400 m sphere: the script puts it on that body.
- Projected rasters are drawn as the library draws them, without reprojection. The Rainier tile
  in UTM zone 10N: framed like the geographic one (its map corners, mapped back to lon/lat,
  project inside the window and span at least 60 % of its height; ground from edge to edge).
  The EPSG:3413 polar cap: the camera looks down on the pole, which is the window's centre, and
  every one of 17 x 17 points spread over the raster lands on a drawn (not background) pixel.
  Neither run reports an error (a layer the globe cannot draw is reported and skipped).
- A projection the globe does not draw directly (EPSG:8857, Equal Earth, from a world file
  and .prj) is reprojected on load and shown, and the script says so; a raster outside its projection's
  domain is refused like the bad paths.
"""
import os
import sys
import unittest

from globe_test_support import DATA, EXAMPLES, ExampleTest, Image, project, run_example
from vtkglobe import vtkGlobeEllipsoid

sys.path.insert(0, EXAMPLES)
import view_geotiff as vg  # noqa: E402

SIZE = (400, 300)


class TestExampleViewGeoTIFF(ExampleTest):
    def test_help(self):
        self.check_help("view_geotiff.py", ("geotiff", "--out", "--interactive", "--role"))

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

    def write_world_file_tiff(self, name, x0, y0, pixel, epsg):
        """A 16 x 16 RGB TIFF georeferenced by a world file and a .prj naming epsg."""
        from vtkmodules.vtkImagingSources import vtkImageCanvasSource2D
        from vtkmodules.vtkIOImage import vtkTIFFWriter
        canvas = vtkImageCanvasSource2D()
        canvas.SetExtent(0, 15, 0, 15, 0, 0)
        canvas.SetScalarTypeToUnsignedChar()
        canvas.SetNumberOfScalarComponents(3)
        base = os.path.join(self.tmp.name, name)
        writer = vtkTIFFWriter()
        writer.SetFileName(base + ".tif")
        writer.SetInputConnection(canvas.GetOutputPort())
        writer.Write()
        with open(base + ".tfw", "w") as f:
            f.write("%r\n0\n0\n%r\n%r\n%r\n" % (pixel, -pixel, x0, y0))
        with open(base + ".prj", "w") as f:
            f.write('PROJCS["%d",GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,'
                    '298.257223563]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]],'
                    'UNIT["metre",1],AUTHORITY["EPSG","%d"]]' % (epsg, epsg))
        return base + ".tif"

    def test_other_crs_reprojected_and_outside_domain_refused(self):
        equal_earth = self.write_world_file_tiff("equal_earth", 778000.0, 6185000.0, 1000.0, 8857)
        code, stdout, stderr = run_example("view_geotiff.py", equal_earth, "--out", self.out)
        self.assertEqual(code, 0, stderr)
        self.assertIn("reprojected from EPSG:8857", stdout)
        self.assertTrue(os.path.exists(self.out))
        os.remove(self.out)
        far = self.write_world_file_tiff("utm_far_away", 5.0e7, 9.0e7, 1000.0, 32610)
        self.refused(far, "the raster lies outside the domain of its projection (EPSG:32610)")

    def run_projected(self, name, size_line):
        """Runs the script on Data/earth/<name>; returns the layer, the script's scene (its
        window is kept by the test: a renderer projects points only while it has one) and the
        picture."""
        path = os.path.join(DATA, "earth", name)
        code, stdout, stderr = run_example("view_geotiff.py", path, "--out", self.out,
                                           "--size", "%dx%d" % SIZE, "--grid", "256")
        self.assertEqual(code, 0)
        self.assertIn(size_line, stdout)
        self.assertIn("body WGS84", stdout)
        self.assertNotIn("ERROR", stderr)
        self.assertNotIn("skipped", stderr)
        image = Image(self.out)
        self.assertEqual((image.width, image.height), SIZE)
        layer = vg.load(path, "auto")
        self.window, renderer, body, _ = vg.build(layer, SIZE, 256)
        return layer, renderer, body, image

    def map_points(self, layer, n):
        """(lon, lat) of n x n points spread over the projected raster, edges included."""
        projection = vg.projection_of(layer)
        origin, pixel = [0.0] * 2, [0.0] * 2
        layer.GetProjectedGeoTransform(origin, pixel)
        width, height = layer.GetNumberOfColumns() * pixel[0], layer.GetNumberOfRows() * pixel[1]
        points = []
        for j in range(n):
            for i in range(n):
                lonlat = [0.0] * 2
                self.assertTrue(projection.Inverse(origin[0] + width * i / (n - 1),
                                                   origin[1] - height * j / (n - 1), lonlat))
                points.append(tuple(lonlat))
        return points

    def pixel_of(self, renderer, body, lon, lat):
        p = [0.0] * 3
        body.GeodeticToCartesian(lon, lat, 0.0, p)
        return project(renderer, p)

    def test_projected_utm_framed(self):
        layer, renderer, body, image = self.run_projected(
            "mt_rainier_utm10n.tif", "876x1252 height raster in EPSG:32610")
        background = image.count(lambda p: p == (0, 0, 0))
        print("background pixels: %d" % background)
        self.assertEqual(background, 0)
        ys = []
        for lon, lat in self.map_points(layer, 2):  # the four map corners
            x, y = self.pixel_of(renderer, body, lon, lat)
            print("corner (%.3f, %.3f) at pixel (%.0f, %.0f)" % (lon, lat, x, y))
            self.assertTrue(0 <= x <= SIZE[0] and 0 <= y <= SIZE[1])
            ys.append(y)
        self.assertGreater(max(ys) - min(ys), 0.6 * SIZE[1])

    def test_projected_polar_cap(self):
        layer, renderer, body, image = self.run_projected(
            "world_north_polar_3413.tif", "1024x1024 color raster in EPSG:3413")
        x, y = self.pixel_of(renderer, body, 0.0, 90.0)
        print("the pole at pixel (%.1f, %.1f)" % (x, y))
        self.assertLess(abs(x - SIZE[0] / 2), 2.0)
        self.assertLess(abs(y - SIZE[1] / 2), 2.0)
        uncovered = []
        points = self.map_points(layer, 17)
        for lon, lat in points:
            x, y = self.pixel_of(renderer, body, lon, lat)
            self.assertTrue(0 <= x < SIZE[0] and 0 <= y < SIZE[1], (lon, lat, x, y))
            if image(int(x), int(y)) == (0, 0, 0):
                uncovered.append((lon, lat))
        print("%d of %d points of the raster on background pixels" % (len(uncovered), len(points)))
        self.assertEqual(uncovered, [])
        background = image.count(lambda p: p == (0, 0, 0))
        print("background pixels: %d (space around the globe)" % background)
        self.assertGreater(background, 0)

    def test_moon_body(self):
        layer = vg.load(os.path.join(DATA, "moon", "moon_1024x512.tif"), "auto")
        self.assertEqual(layer.GetRoleAsString().lower(), "color")
        body = vg.body_for(layer)
        self.assertEqual(body.GetRadii(), (1737400.0, 1737400.0, 1737400.0))


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
