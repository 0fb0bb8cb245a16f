#!/usr/bin/python3
"""The Earth with insets: a 2-degree global relief, 90 m SRTM terrain insets (Mount Rainier,
Everest), Blue Marble imagery, and high-resolution imagery insets of New York and Boston composed
on top of it. Layers compose bottom first: each inset replaces what is below it where it has data.

  earth_insets.py [--view earth|boston|nyc] [--no-insets] [--out FILE.png | --interactive]
"""
import sys

from vtkmodules.vtkRenderingCore import vtkRenderer

import globe_scene
from vtkglobe import vtkGlobeEllipsoid

# Viewpoints: camera and target (lon, lat, height), view angle, clipping range (None: VTK's).
VIEWS = {
    "earth": ((-60.0, 35.0, 2.2e7), (-60.0, 35.0, 0.0), 30.0, None),
    "boston": ((-71.07, 42.33, 1.2e5), (-71.07, 42.33, 0.0), 40.0, (1.0e3, 1.0e6)),
    "nyc": ((-74.007, 40.7145, 2.0e4), (-74.007, 40.7145, 0.0), 40.0, (1.0e2, 1.0e6)),
}
SUN = (140.0, 50.0)  # azimuth, elevation seen from the target


def build(view, data, size, grid, insets=True, interactive=False):
    """The scene for a viewpoint: returns (window, renderer, body)."""
    wgs84 = vtkGlobeEllipsoid()
    mapper, actor = globe_scene.globe(wgs84, grid)
    globe_scene.add_earth_layers(mapper, data, insets)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.0, 0.0, 0.02)
    camera, target, angle, clipping = VIEWS[view]
    globe_scene.add_sun(renderer, wgs84, target, *SUN)
    globe_scene.look_at(renderer, wgs84, camera, target, angle, clipping)
    return globe_scene.window_for(renderer, size, interactive), renderer, wgs84


def main(argv=None):
    parser = globe_scene.arguments(__doc__, "earth_insets.png")
    parser.add_argument("--view", choices=sorted(VIEWS), default="earth",
                        help="viewpoint (default: %(default)s)")
    parser.add_argument("--no-insets", action="store_true",
                        help="leave out the New York and Boston imagery insets")
    args = parser.parse_args(argv)
    size = globe_scene.parse_size(parser, args.size)
    globe_scene.require_display()
    window, _, _ = build(args.view, args.data, size, args.grid, not args.no_insets, args.interactive)
    globe_scene.show(window, args.out, args.interactive)
    return 0


if __name__ == "__main__":
    sys.exit(main())
