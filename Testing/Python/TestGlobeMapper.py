"""The globe mapper from Python, as issue #3's example writes it: an ellipsoid, height and colour
layers, a vtkActor in a plain vtkRenderer next to another actor; rendered offscreen.

Checks that the globe covers the expected disc, that the centre pixel's depth reconstructs to
the ground below the camera, and that a cone in front of the globe occludes it.
"""
import math
import os
import sys
import unittest

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL backend)
from vtkmodules.vtkFiltersSources import vtkConeSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer)

from vtkglobe import vtkGlobeEllipsoid, vtkGlobeLayer, vtkGlobeMapper

DATA = os.environ.get("VTKGLOBE_DATA_DIR",
                      os.path.join(os.path.dirname(__file__), "..", "..", "Data"))


def layer(path, height):
    result = vtkGlobeLayer()
    result.SetFileName(os.path.join(DATA, path))
    if height:
        result.SetRoleToHeight()
    else:
        result.SetRoleToColor()
    return result


class TestGlobeMapper(unittest.TestCase):
    def test_earth_from_python(self):
        wgs84 = vtkGlobeEllipsoid()
        mapper = vtkGlobeMapper()
        mapper.SetEllipsoid(wgs84)
        mapper.AddLayer(layer("earth/relief_2deg.tif", True))
        mapper.AddLayer(layer("earth/world.tif", False))
        mapper.SetGridResolution(256)
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer = vtkRenderer()
        renderer.AddActor(actor)

        # The camera 20,000 km over (0 E, 0 N), looking at the centre.
        eye = [0.0, 0.0, 0.0]
        wgs84.GeodeticToCartesian(0.0, 0.0, 2.0e7, eye)
        camera = renderer.GetActiveCamera()
        camera.SetPosition(eye)
        camera.SetFocalPoint(0.0, 0.0, 0.0)
        camera.SetViewUp(0.0, 0.0, 1.0)
        camera.SetViewAngle(30.0)

        # A cone between the camera and the globe, off the centre line.
        cone = vtkConeSource()
        cone.SetCenter(1.5e7, 1.5e6, 0.0)
        cone.SetHeight(5.0e5)
        cone.SetRadius(3.0e5)
        cone_mapper = vtkPolyDataMapper()
        cone_mapper.SetInputConnection(cone.GetOutputPort())
        cone_actor = vtkActor()
        cone_actor.SetMapper(cone_mapper)
        renderer.AddActor(cone_actor)
        renderer.ResetCameraClippingRange()

        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(200, 200)
        window.AddRenderer(renderer)
        window.Render()
        window.Render()

        width, height = window.GetSize()
        depth = [window.GetZbufferDataAtPoint(x, y) for y in range(0, height, 4)
                 for x in range(0, width, 4)]
        covered = sum(1 for d in depth if d < 1.0)
        # The Earth's disc: asin(a / d) of a 15-degree half angle, about 70 % of the area.
        angular = math.degrees(math.asin(6378137.0 / (6378137.0 + 2.0e7)))
        expected = math.pi * (angular / 15.0 * width / 2) ** 2 / 16
        print("covered samples %d, expected about %.0f" % (covered, expected))
        self.assertGreater(covered, 0.9 * expected)
        self.assertLess(covered, 1.1 * expected)

        # The centre pixel reconstructs to the ground below the camera (relief there: < 5 km).
        x, y = width // 2, height // 2
        renderer.SetDisplayPoint(x + 0.5, y + 0.5, window.GetZbufferDataAtPoint(x, y))
        renderer.DisplayToWorld()
        p = renderer.GetWorldPoint()
        point = [p[i] / p[3] for i in range(3)]
        llh = [0.0, 0.0, 0.0]
        wgs84.CartesianToGeodetic(point, llh)
        print("centre pixel: lon %.3f lat %.3f h %.0f m" % tuple(llh))
        self.assertLess(abs(llh[0]), 0.5)
        self.assertLess(abs(llh[1]), 0.5)
        self.assertLess(abs(llh[2]), 5000.0)

        # The cone occludes the globe: at its centre pixel the depth is the cone's.
        renderer.SetWorldPoint(1.5e7, 1.5e6, 0.0, 1.0)
        renderer.WorldToDisplay()
        cx, cy, _ = renderer.GetDisplayPoint()
        renderer.SetDisplayPoint(int(cx) + 0.5, int(cy) + 0.5,
                                 window.GetZbufferDataAtPoint(int(cx), int(cy)))
        renderer.DisplayToWorld()
        p = renderer.GetWorldPoint()
        seen = [p[i] / p[3] for i in range(3)]
        print("at the cone: a surface %.0f km from the centre of the Earth"
              % (math.dist(seen, (0, 0, 0)) / 1000))
        self.assertGreater(math.dist(seen, (0, 0, 0)), 1.4e7)
        self.assertTrue(mapper.GetLastFrameDrewGlobe())


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
