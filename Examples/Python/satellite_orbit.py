#!/usr/bin/python3
"""A satellite orbit around the Earth: a circular orbit drawn as a polyline and a satellite
(a sphere) on it, in the same renderer as the globe. The globe writes real depth, so the part of
the orbit behind the Earth is hidden by the ordinary depth test; nothing is clipped by hand.

  satellite_orbit.py [--anomaly DEG] [--out FILE.png | --interactive]
"""
import math
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

import globe_scene
from vtkglobe import vtkGlobeEllipsoid

# The orbit (body-fixed frame, metres and degrees): radius, inclination, longitude of the
# ascending node. The camera looks at the Earth's centre from a point 20 degrees above the
# orbital plane, so the orbit crosses in front of the globe and behind it.
ORBIT_RADIUS = 6378137.0 + 3.0e6
INCLINATION = 51.6
NODE = -30.0
CAMERA_DISTANCE = 2.4e7
CAMERA_ELEVATION = 20.0  # above the orbital plane, degrees
CAMERA_ANOMALY = 60.0    # along the orbit, degrees from the node
VIEW_ANGLE = 36.0
SATELLITE_RADIUS = 2.5e5
ORBIT_COLOR = (1.0, 0.0, 1.0)
SATELLITE_COLOR = (0.0, 1.0, 1.0)


def orbit_point(anomaly, radius=ORBIT_RADIUS):
    """Position on the orbit at an argument of latitude (degrees from the ascending node)."""
    u, i, node = math.radians(anomaly), math.radians(INCLINATION), math.radians(NODE)
    return (radius * (math.cos(u) * math.cos(node) - math.sin(u) * math.cos(i) * math.sin(node)),
            radius * (math.cos(u) * math.sin(node) + math.sin(u) * math.cos(i) * math.cos(node)),
            radius * math.sin(u) * math.sin(i))


def orbit_normal():
    i, node = math.radians(INCLINATION), math.radians(NODE)
    return (math.sin(i) * math.sin(node), -math.sin(i) * math.cos(node), math.cos(i))


def camera_position():
    """CAMERA_DISTANCE from the centre, CAMERA_ELEVATION above the plane at CAMERA_ANOMALY."""
    p = orbit_point(CAMERA_ANOMALY, 1.0)
    n = orbit_normal()
    e = math.radians(CAMERA_ELEVATION)
    return tuple(CAMERA_DISTANCE * (math.cos(e) * a + math.sin(e) * b) for a, b in zip(p, n))


def orbit_polydata(samples=720):
    points = vtkPoints()
    lines = vtkCellArray()
    lines.InsertNextCell(samples + 1)
    for k in range(samples + 1):
        lines.InsertCellPoint(k % samples)
        if k < samples:
            points.InsertNextPoint(orbit_point(360.0 * k / samples))
    orbit = vtkPolyData()
    orbit.SetPoints(points)
    orbit.SetLines(lines)
    return orbit


def flat_actor(mapper, color):
    """An unlit actor: exactly its colour in every pixel it covers."""
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(color)
    actor.GetProperty().SetLighting(False)
    return actor


def build(size, grid, anomaly, data=globe_scene.DATA, interactive=False):
    """Returns (window, renderer, body)."""
    wgs84 = vtkGlobeEllipsoid()
    mapper, actor = globe_scene.globe(wgs84, grid)
    globe_scene.add_earth_layers(mapper, data, insets=False)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.0, 0.0, 0.0)

    orbit_mapper = vtkPolyDataMapper()
    orbit_mapper.SetInputData(orbit_polydata())
    orbit = flat_actor(orbit_mapper, ORBIT_COLOR)
    orbit.GetProperty().SetLineWidth(3.0)
    renderer.AddActor(orbit)

    sphere = vtkSphereSource()
    sphere.SetCenter(orbit_point(anomaly))
    sphere.SetRadius(SATELLITE_RADIUS)
    sphere.SetThetaResolution(24)
    sphere.SetPhiResolution(24)
    satellite_mapper = vtkPolyDataMapper()
    satellite_mapper.SetInputConnection(sphere.GetOutputPort())
    renderer.AddActor(flat_actor(satellite_mapper, SATELLITE_COLOR))

    eye = camera_position()
    llh = [0.0] * 3
    wgs84.CartesianToGeodetic(eye, llh)
    globe_scene.add_sun(renderer, wgs84, (llh[0] + 30.0, llh[1], 0.0), 0.0, 60.0)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(eye)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewUp(orbit_normal())
    camera.SetViewAngle(VIEW_ANGLE)
    camera.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange()
    return globe_scene.window_for(renderer, size, interactive), renderer, wgs84


def main(argv=None):
    parser = globe_scene.arguments(__doc__, "satellite_orbit.png")
    parser.add_argument("--anomaly", type=float, default=CAMERA_ANOMALY,
                        help="where the satellite is, degrees along the orbit from its ascending "
                        "node (default %(default)g: in front of the globe; +180: behind it)")
    args = parser.parse_args(argv)
    size = globe_scene.parse_size(parser, args.size)
    globe_scene.require_display()
    window, _, _ = build(size, args.grid, args.anomaly, args.data, args.interactive)
    globe_scene.show(window, args.out, args.interactive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
