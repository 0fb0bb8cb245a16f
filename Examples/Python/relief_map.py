#!/usr/bin/python3
"""A relief map: heights coloured by a hypsometric tint and hill-shaded by the sun, from a
digital elevation model alone (by default the Earth's 2-degree relief with the Everest SRTM
inset, topography and bathymetry).

Colour maps come for the Earth (land and sea floor), the Moon (LOLA's range about the
1,737.4 km sphere) and Mars (MOLA's range about the 3,396.19 km areoid sphere); use --dem with
--body to colour a DEM of your own, e.g.
  relief_map.py --dem mola.tif --body mars --lon -130 --lat 15 --altitude 6e6

  relief_map.py [--dem FILE ...] [--body earth|moon|mars] [--colors earth|moon|mars]
                [--lon DEG --lat DEG --altitude M] [--opacity 0..1] [--out FILE.png | --interactive]
"""
import os
import sys

from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkRenderer

import globe_scene
from vtkglobe import vtkGlobeEllipsoid

# (height in metres above the body's sphere or ellipsoid, r, g, b).
COLOR_MAPS = {
    # Sea floor in blues (trenches to shelf), land from lowland green through ochre and brown to
    # snow: the classic atlas tint.
    "earth": [(-11000, 0.02, 0.02, 0.20), (-6000, 0.05, 0.15, 0.45), (-2000, 0.15, 0.40, 0.70),
              (-150, 0.45, 0.70, 0.90), (0, 0.12, 0.42, 0.20), (500, 0.45, 0.62, 0.30),
              (1500, 0.85, 0.78, 0.45), (3000, 0.62, 0.42, 0.25), (4500, 0.50, 0.40, 0.38),
              (6000, 0.95, 0.95, 0.95), (9000, 1.00, 1.00, 1.00)],
    # The Moon's -9.1 km (South Pole-Aitken) to +10.8 km (Selenean summit): violet to white.
    "moon": [(-9100, 0.25, 0.10, 0.45), (-5000, 0.10, 0.25, 0.75), (-2000, 0.10, 0.60, 0.70),
             (0, 0.30, 0.75, 0.30), (2000, 0.90, 0.85, 0.30), (5000, 0.90, 0.45, 0.15),
             (8000, 0.70, 0.25, 0.20), (10800, 1.00, 1.00, 1.00)],
    # Mars: -8.2 km (Hellas) to +21.2 km (Olympus Mons), MOLA's blue-green-yellow-red-white.
    "mars": [(-8200, 0.10, 0.05, 0.45), (-4000, 0.10, 0.35, 0.85), (-1000, 0.10, 0.70, 0.65),
             (1000, 0.45, 0.80, 0.25), (3000, 0.95, 0.85, 0.25), (6000, 0.90, 0.45, 0.15),
             (12000, 0.60, 0.25, 0.15), (21200, 1.00, 1.00, 1.00)],
}


def height_colors(name):
    """The hypsometric tint `name` as a vtkColorTransferFunction (metres)."""
    tint = vtkColorTransferFunction()
    for h, r, g, b in COLOR_MAPS[name]:
        tint.AddRGBPoint(h, r, g, b)
    return tint


def build(data, size, grid, dems=None, body_name="earth", colors=None, view=(86.9, 27.0, 9.0e6),
          opacity=1.0, interactive=False):
    """Returns (window, renderer, mapper)."""
    body = vtkGlobeEllipsoid()
    {"earth": body.SetToWGS84, "moon": body.SetToMoon, "mars": body.SetToMars}[body_name]()
    mapper, actor = globe_scene.globe(body, grid)
    if not dems:
        dems = [os.path.join(data, "earth", name + ".tif") for name in ("relief_2deg", "mt_everest_90m")]
    for path in dems:
        layer = globe_scene.file_layer(path, "height")
        if not layer.Update():
            sys.exit("error: cannot read the DEM %r (see the message above)" % path)
        mapper.AddLayer(layer)
    composite = mapper.GetCompositePass()
    composite.SetHeightColors(height_colors(colors or body_name))
    composite.SetHeightColorOpacity(opacity)
    composite.SetAmbient(0.25)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.0, 0.0, 0.0)
    target = (view[0], view[1], 0.0)
    # A sun from the north-west, as relief maps are shaded.
    globe_scene.add_sun(renderer, body, target, 315.0, 35.0)
    globe_scene.look_at(renderer, body, (view[0], view[1] - 8.0, view[2]), target, 30.0)
    window = globe_scene.window_for(renderer, size, interactive)
    return window, renderer, mapper


def main(argv=None):
    parser = globe_scene.arguments(__doc__, "relief_map.png")
    parser.add_argument("--dem", action="append", metavar="FILE",
                        help="a height GeoTIFF (repeat for insets; default: the Earth's 2-degree "
                             "relief and the Everest inset from --data)")
    parser.add_argument("--body", choices=sorted(COLOR_MAPS), default="earth",
                        help="the body the DEM belongs to (default: %(default)s)")
    parser.add_argument("--colors", choices=sorted(COLOR_MAPS),
                        help="the colour map (default: the body's)")
    parser.add_argument("--lon", type=float, default=86.9, help="longitude looked at (deg)")
    parser.add_argument("--lat", type=float, default=27.0, help="latitude looked at (deg)")
    parser.add_argument("--altitude", type=float, default=9.0e6,
                        help="camera height above the body (m, default: %(default)g)")
    parser.add_argument("--opacity", type=float, default=1.0,
                        help="the tint's opacity over the body's base colour (0..1)")
    args = parser.parse_args(argv)
    size = globe_scene.parse_size(parser, args.size)
    if not 0.0 <= args.opacity <= 1.0:
        parser.error("--opacity must lie in [0, 1]")
    if args.altitude <= 0.0:
        parser.error("--altitude must be above the body (> 0 m)")
    globe_scene.require_display()
    window, _, _ = build(args.data, size, args.grid, args.dem, args.body, args.colors,
                         (args.lon, args.lat, args.altitude), args.opacity, args.interactive)
    globe_scene.show(window, args.out, args.interactive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
