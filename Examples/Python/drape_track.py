#!/usr/bin/python3
"""Your own lon/lat/height data on the globe: a sightseeing flight's track around Mount Rainier
(a polyline) and a few places (points), put on the WGS84 body by vtkTransformFilter with
vtkGlobeGeodeticTransform, and drawn by ordinary VTK mappers next to the globe. The terrain
occludes them where it should: seen from the west, the far side of the loop is hidden behind
the mountain.

  drape_track.py [--track FILE.csv] [--out FILE.png | --interactive]

A track file has one "lon,lat,height" line per point (degrees, degrees, metres above the
ellipsoid); lines starting with # are skipped.
"""
import math
import sys

from vtkmodules.vtkCommonCore import VTK_DOUBLE, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
from vtkmodules.vtkFiltersCore import vtkGlyph3D
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

import globe_scene
from vtkglobe import vtkGlobeEllipsoid, vtkGlobeGeodeticTransform

SUMMIT = (-121.7603, 46.8523, 4392.0)
CAMERA = (-121.99, 46.84, 4500.0)        # 17.5 km west of the summit, 4,500 m up
VIEW_ANGLE = 40.0
CLIPPING = (50.0, 1.0e6)
LOOP_RADIUS = 6500.0                      # metres around the summit
LOOP_HEIGHT = 3000.0                      # metres above the ellipsoid
PLACES = {                                # lon, lat, height of the ground (m)
    "Paradise": (-121.7357, 46.7859, 1646.0),
    "Longmire": (-121.8115, 46.7504, 842.0),
    "Camp Muir": (-121.7316, 46.8355, 3100.0),
    "Sunrise": (-121.5245, 46.9144, 1950.0),
}
PLACE_RADIUS = 150.0                      # glyph radius, m; drawn this far above the ground
TRACK_COLOR = (1.0, 0.0, 1.0)
PLACE_COLOR = (0.0, 1.0, 1.0)


def loop_track(samples=360):
    """The built-in track: a circle around the summit at LOOP_HEIGHT (lon, lat, height)."""
    lat0 = math.radians(SUMMIT[1])
    metres_per_degree = 111320.0
    return [(SUMMIT[0] + LOOP_RADIUS * math.cos(t) / (metres_per_degree * math.cos(lat0)),
             SUMMIT[1] + LOOP_RADIUS * math.sin(t) / metres_per_degree, LOOP_HEIGHT)
            for t in (2.0 * math.pi * k / samples for k in range(samples + 1))]


def read_track(path):
    """lon,lat,height lines; raises ValueError naming the file and line on bad input."""
    track = []
    try:
        f = open(path, errors="replace")  # a binary file fails on its first line
    except OSError as error:
        raise ValueError("%s: %s" % (path, error.strerror))
    with f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            try:
                lon, lat, height = (float(v) for v in line.split(","))
            except ValueError:
                raise ValueError("%s:%d: expected 'lon,lat,height', got %r" % (path, number, line))
            if not (-180.0 <= lon <= 360.0 and -90.0 <= lat <= 90.0 and math.isfinite(height)):
                raise ValueError("%s:%d: out of range: %r" % (path, number, line))
            track.append((lon, lat, height))
    if len(track) < 2:
        raise ValueError("%s: a track needs at least two points" % path)
    return track


def geodetic_polydata(points_llh, polyline):
    """Points with (lon, lat, height) coordinates, as a polyline or as vertices."""
    points = vtkPoints()
    points.SetDataType(VTK_DOUBLE)
    cells = vtkCellArray()
    for p in points_llh:
        points.InsertNextPoint(p)
    data = vtkPolyData()
    data.SetPoints(points)
    if polyline:
        cells.InsertNextCell(len(points_llh))
        for k in range(len(points_llh)):
            cells.InsertCellPoint(k)
        data.SetLines(cells)
    return data


def on_body(data, body):
    """The pipeline step this example is about: lon/lat/height -> body-fixed metres."""
    transform = vtkGlobeGeodeticTransform()
    transform.SetEllipsoid(body)
    to_body = vtkTransformFilter()
    to_body.SetTransform(transform)
    to_body.SetInputData(data)
    to_body.SetOutputPointsPrecision(vtkAlgorithm.DOUBLE_PRECISION)  # float is 0.5 m at 6,400 km
    return to_body


def flat_actor(mapper, color):
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(color)
    actor.GetProperty().SetLighting(False)
    return actor


def build(size, grid, track=None, data=globe_scene.DATA, interactive=False):
    """Returns (window, renderer, body)."""
    wgs84 = vtkGlobeEllipsoid()
    mapper, actor = globe_scene.globe(wgs84, grid)
    globe_scene.add_earth_layers(mapper, data, insets=False)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.45, 0.6, 0.8)

    # Keep a reference to each filter: an output port does not keep its algorithm alive.
    track_on_body = on_body(geodetic_polydata(track or loop_track(), True), wgs84)
    track_mapper = vtkPolyDataMapper()
    track_mapper.SetInputConnection(track_on_body.GetOutputPort())
    track_actor = flat_actor(track_mapper, TRACK_COLOR)
    track_actor.GetProperty().SetLineWidth(3.0)
    renderer.AddActor(track_actor)

    raised = [(lon, lat, h + PLACE_RADIUS) for lon, lat, h in PLACES.values()]
    sphere = vtkSphereSource()
    sphere.SetRadius(PLACE_RADIUS)
    places_on_body = on_body(geodetic_polydata(raised, False), wgs84)
    glyphs = vtkGlyph3D()
    glyphs.SetInputConnection(places_on_body.GetOutputPort())
    glyphs.SetSourceConnection(sphere.GetOutputPort())
    glyphs.SetScaling(False)
    place_mapper = vtkPolyDataMapper()
    place_mapper.SetInputConnection(glyphs.GetOutputPort())
    renderer.AddActor(flat_actor(place_mapper, PLACE_COLOR))

    globe_scene.add_sun(renderer, wgs84, SUMMIT, 200.0, 40.0)
    globe_scene.look_at(renderer, wgs84, CAMERA, SUMMIT, VIEW_ANGLE, CLIPPING)
    return globe_scene.window_for(renderer, size, interactive), renderer, wgs84


def main(argv=None):
    parser = globe_scene.arguments(__doc__, "drape_track.png")
    parser.add_argument("--track", metavar="FILE.csv",
                        help="lon,lat,height lines (default: a loop around the summit)")
    args = parser.parse_args(argv)
    size = globe_scene.parse_size(parser, args.size)
    track = None
    if args.track:
        try:
            track = read_track(args.track)
        except ValueError as error:
            print("error: %s" % error, file=sys.stderr)
            return 1
    globe_scene.require_display()
    window, _, _ = build(size, args.grid, track, args.data, args.interactive)
    globe_scene.show(window, args.out, args.interactive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
