#!/usr/bin/python3
"""The Moon: a global albedo map on the Moon's sphere, whose radius is read from the GeoTIFF's
own datum (1,737,400 m) rather than assumed.

  moon.py [--distance METRES] [--out FILE.png | --interactive]
"""
import os
import sys

from vtkmodules.vtkRenderingCore import vtkRenderer

import globe_scene
from vtkglobe import vtkGlobeEllipsoid

DISTANCE = 8.0e6      # camera distance from the Moon's centre (m)
VIEW_ANGLE = 30.0
LOOK_AT = (20.0, 10.0)  # the sub-camera point (lon, lat)


def build(data, size, grid, distance=DISTANCE, interactive=False):
    """Returns (window, renderer, body)."""
    albedo = globe_scene.file_layer(os.path.join(data, "moon", "moon_1024x512.tif"), "color")
    if not albedo.Update():
        sys.exit("error: cannot read the Moon's map (see the message above)")
    moon = vtkGlobeEllipsoid()
    moon.SetToMoon()
    a, b = albedo.GetDatumSemiMajorAxis(), albedo.GetDatumSemiMinorAxis()
    if a > 0 and b > 0:
        moon.SetRadii(a, a, b)  # the raster's datum: the Moon 2000 sphere
        moon.SetName("Moon (from the GeoTIFF)")
    mapper, actor = globe_scene.globe(moon, grid)
    mapper.AddLayer(albedo)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.0, 0.0, 0.0)
    altitude = distance - moon.GetRadii()[0]
    target = (LOOK_AT[0], LOOK_AT[1], 0.0)
    globe_scene.add_sun(renderer, moon, target, 250.0, 40.0)
    globe_scene.look_at(renderer, moon, (LOOK_AT[0], LOOK_AT[1], altitude), target, VIEW_ANGLE)
    return globe_scene.window_for(renderer, size, interactive), renderer, moon


def main(argv=None):
    parser = globe_scene.arguments(__doc__, "moon.png")
    parser.add_argument("--distance", type=float, default=DISTANCE,
                        help="camera distance from the centre in metres (default: %(default)g)")
    args = parser.parse_args(argv)
    size = globe_scene.parse_size(parser, args.size)
    if args.distance <= 1737400.0:
        parser.error("--distance must be outside the Moon (> 1737400 m)")
    globe_scene.require_display()
    window, _, _ = build(args.data, size, args.grid, args.distance, args.interactive)
    globe_scene.show(window, args.out, args.interactive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
