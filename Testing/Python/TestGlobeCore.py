"""The wrapped Core module from Debian's /usr/bin/python3, next to vtkmodules.

Checks conversions against the closed-form geodetic formulas (independent of the C++ code),
the transform inside a vtkTransformFilter pipeline, and errors reaching Python observers.
"""
import math
import sys
import unittest

from vtkmodules.vtkCommonCore import vtkPoints, VTK_DOUBLE
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonTransforms import vtkAbstractTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm

import vtkglobe
from vtkglobe import vtkGlobeEllipsoid, vtkGlobeGeodeticTransform


def closed_form(a, c, lon, lat, h):
    """Geodetic -> Cartesian for a biaxial ellipsoid, the textbook formula."""
    e2 = 1.0 - (c * c) / (a * a)
    phi, lam = math.radians(lat), math.radians(lon)
    n = a / math.sqrt(1.0 - e2 * math.sin(phi) ** 2)
    return ((n + h) * math.cos(phi) * math.cos(lam),
            (n + h) * math.cos(phi) * math.sin(lam),
            (n * (1.0 - e2) + h) * math.sin(phi))


class TestGlobeCore(unittest.TestCase):
    def test_package(self):
        self.assertTrue(issubclass(vtkGlobeGeodeticTransform, vtkAbstractTransform))
        self.assertTrue(hasattr(vtkglobe, "__version__"))
        self.assertEqual(vtkGlobeEllipsoid().GetName(), "WGS84")

    def test_conversions_match_closed_form(self):
        e = vtkGlobeEllipsoid()
        worst = 0.0
        for body in ("SetToWGS84", "SetToMars", "SetToMoon"):
            getattr(e, body)()
            a, _, c = e.GetRadii()
            for lon in (-180.0, -122.31, 0.0, 86.925, 179.99):
                for lat in (-90.0, -45.0, 0.0, 27.9881, 89.9, 90.0):
                    for h in (-430.0, 0.0, 8848.86, 4.0e5):
                        xyz = [0.0, 0.0, 0.0]
                        self.assertTrue(e.GeodeticToCartesian(lon, lat, h, xyz))
                        ref = closed_form(a, c, lon, lat, h)
                        worst = max(worst, math.dist(xyz, ref))
                        llh = [0.0, 0.0, 0.0]
                        self.assertTrue(e.CartesianToGeodetic(xyz, llh))
                        self.assertAlmostEqual(llh[1], lat, delta=1e-9)
                        self.assertAlmostEqual(llh[2], h, delta=1e-6)
        print("worst |P - closed form| = %.3e m" % worst)
        self.assertLess(worst, 1e-6)

    def test_transform_in_pipeline(self):
        points = vtkPoints()
        points.SetDataType(VTK_DOUBLE)
        for lon, lat, h in ((0, 0, 0), (86.925, 27.9881, 8848.86), (-122.31, 47.45, 100)):
            points.InsertNextPoint(lon, lat, h)
        data = vtkPolyData()
        data.SetPoints(points)
        transform = vtkGlobeGeodeticTransform()
        f = vtkTransformFilter()
        f.SetInputData(data)
        f.SetTransform(transform)
        f.SetOutputPointsPrecision(vtkAlgorithm.DOUBLE_PRECISION)
        f.Update()
        out = f.GetOutput().GetPoints()
        a, _, c = transform.GetEllipsoid().GetRadii()
        for i in range(points.GetNumberOfPoints()):
            self.assertLess(math.dist(out.GetPoint(i), closed_form(a, c, *points.GetPoint(i))), 1e-6)
        back = transform.GetInverse().TransformPoint(out.GetPoint(1))
        self.assertLess(math.dist(back, points.GetPoint(1)), 1e-6)

        moon = vtkGlobeEllipsoid()
        moon.SetToMoon()
        transform.SetEllipsoid(moon)
        f.Update()
        self.assertAlmostEqual(f.GetOutput().GetPoint(0)[0], 1737400.0, delta=1e-6)

    def test_errors_reach_python(self):
        e = vtkGlobeEllipsoid()
        messages = []
        e.AddObserver("ErrorEvent", lambda obj, event: messages.append(event))
        self.assertFalse(e.SetRadii(-1.0, 1.0, 1.0))
        self.assertEqual(len(messages), 1)
        self.assertEqual(e.GetName(), "WGS84")
        out = [0.0, 0.0, 0.0]
        self.assertFalse(e.CartesianToGeodetic([float("nan"), 0.0, 0.0], out))
        self.assertTrue(all(math.isnan(v) for v in out))
        self.assertEqual(len(messages), 2)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
