#!/usr/bin/python3
"""Navigating the Earth: Google-Earth-like navigation (vtkGlobeInteractorStyle), a readout of
what is under the cursor (longitude, latitude, ellipsoidal and orthometric height, distance), a
GPS-like track draped on the terrain without gaps, and keys that fly to places.

  navigate.py [--fly rainier|everest|earth] [--pick X,Y] [--out FILE.png | --interactive]

In the window: left drag grabs the ground, the wheel zooms toward the cursor, Ctrl + drag tilts
and turns; n north up, u look down, r the whole Earth; 1 flies to Mount Rainier, 2 to Mount
Everest, 0 out to the whole Earth. Offscreen (--out), --fly runs the flight before the picture
and --pick puts the readout at that pixel (x right, y up; default the centre); the readout is
printed too.
"""
import math
import os
import sys

import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
from vtkmodules.vtkCommonCore import VTK_DOUBLE, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindowInteractor,
                                         vtkRenderer, vtkTextActor)

import globe_scene
from vtkglobe import (vtkGlobeCamera, vtkGlobeClippingRange, vtkGlobeDepthOffset,
                      vtkGlobeEllipsoid, vtkGlobeInteractorStyle, vtkGlobePointPicker,
                      vtkGlobeTerrainClamp)

SUMMIT = (-121.7603, 46.8523)
# Views: target lon, lat, height (m, ellipsoidal; None: the terrain there), heading and tilt
# (degrees), range (m).
VIEWS = {
    "rainier": (-121.7603, 46.8523, None, 20.0, 55.0, 30000.0),
    "everest": (86.9250, 27.9881, None, 200.0, 40.0, 40000.0),
    "earth": (-100.0, 30.0, 0.0, 0.0, 0.0, 2.0e7),
}
KEYS = {"1": "rainier", "2": "everest", "0": "earth"}
FLIGHT_FRAMES = 60
TRACK_COLOR = (1.0, 0.0, 1.0)
TRACK_RADIUS = 6500.0                     # metres around the summit
TRACK_HEIGHT = 5.0                        # metres above the terrain


def track_loop(samples=72):
    """A loop around Rainier's summit in (lon, lat, 0): the draped track's input."""
    lat0 = math.radians(SUMMIT[1])
    points = vtkPoints()
    points.SetDataType(VTK_DOUBLE)
    lines = vtkCellArray()
    lines.InsertNextCell(samples + 1)
    for k in range(samples + 1):
        t = 2.0 * math.pi * (k % samples) / samples
        if k < samples:
            points.InsertNextPoint(SUMMIT[0] + TRACK_RADIUS * math.cos(t) / (111320.0 * math.cos(lat0)),
                                   SUMMIT[1] + TRACK_RADIUS * math.sin(t) / 111320.0, 0.0)
        lines.InsertCellPoint(k % samples)
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetLines(lines)
    return data


def draped_track(mapper, body):
    """The loop on the composed terrain: clamped 5 m over it, densified every 50 m along the
    geodesics, and drawn a little nearer in depth (vtkGlobeDepthOffset) so the drawn terrain
    never hides it."""
    clamp = vtkGlobeTerrainClamp()
    clamp.SetInputData(track_loop())
    clamp.SetTerrain(mapper.GetTerrain())
    clamp.SetEllipsoid(body)
    clamp.SetHeightOffset(TRACK_HEIGHT)
    clamp.SetMaximumSegmentLength(50.0)
    track_mapper = vtkPolyDataMapper()
    track_mapper.SetInputConnection(clamp.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(track_mapper)
    actor.GetProperty().SetColor(TRACK_COLOR)
    actor.GetProperty().SetLighting(False)
    actor.GetProperty().SetLineWidth(3.0)
    vtkGlobeDepthOffset.Apply(actor, vtkGlobeDepthOffset.GetDefaultOffset())
    actor.clamp = clamp  # an output port does not keep its algorithm alive
    return actor


class Navigator:
    """The scene and what the keys and the mouse do to it."""

    def __init__(self, size, grid, data):
        self.body = vtkGlobeEllipsoid()
        self.mapper, globe = globe_scene.globe(self.body, grid)
        globe_scene.add_earth_layers(self.mapper, data, insets=False)
        for i in range(self.mapper.GetNumberOfLayers()):
            layer = self.mapper.GetLayer(i)
            if layer.GetName().startswith("mt_"):
                layer.SetVerticalDatumToEGM96()  # SRTM heights are above EGM96
        self.renderer = vtkRenderer()
        self.renderer.AddActor(globe)
        self.renderer.SetBackground(0.02, 0.02, 0.05)
        self.renderer.AddActor(draped_track(self.mapper, self.body))
        self.text = vtkTextActor()
        self.text.GetTextProperty().SetFontSize(14)
        self.text.GetTextProperty().SetColor(1.0, 1.0, 0.6)
        self.text.SetDisplayPosition(8, 8)
        self.renderer.AddActor2D(self.text)
        self.picker = vtkGlobePointPicker()
        self.picker.SetMapper(self.mapper)
        vtkGlobeClippingRange.Install(self.renderer)  # the policy before the first frame
        self.renderer.GetActiveCamera().SetViewAngle(40.0)
        self.view = self.resolve("rainier")
        vtkGlobeCamera.LookAt(self.renderer.GetActiveCamera(), self.body, self.view)
        self.renderer.ResetCameraClippingRange()
        self.window = None
        self.size = size

    def readout(self, x, y):
        """What is under pixel (x, y): one line of text, also shown in the corner."""
        self.picker.Pick(x + 0.5, y + 0.5, 0.0, self.renderer)
        if not self.picker.GetGeodeticHit():
            line = "nothing under the cursor"
        else:
            lon, lat, h = self.picker.GetPickGeodetic()
            orthometric = self.picker.GetPickOrthometricHeight()
            line = "lon %.5f  lat %.5f  h %.1f m  H %s  distance %.1f km" % (
                lon, lat, h, "%.1f m" % orthometric if math.isfinite(orthometric) else "-",
                self.picker.GetPickDistance() / 1000.0)
        self.text.SetInput(line)
        return line

    def resolve(self, name):
        """VIEWS[name] with its target on the composed terrain where it has no height."""
        view = list(VIEWS[name])
        if view[2] is None:
            view[2] = self.mapper.GetTerrain().GetHeight(view[0], view[1])
        return view

    def current_view(self):
        """The camera as a view (the focal point as target), where the user navigated to."""
        camera = self.renderer.GetActiveCamera()
        target = [0.0] * 3
        self.body.CartesianToGeodetic(camera.GetFocalPoint(), target)
        east, north, up = [0.0] * 3, [0.0] * 3, [0.0] * 3
        self.body.ComputeEastNorthUp(target[0], target[1], east, north, up)
        d = camera.GetDirectionOfProjection()
        dot = lambda a, b: sum(p * q for p, q in zip(a, b))  # noqa: E731
        tilt = math.degrees(math.acos(max(-1.0, min(1.0, -dot(d, up)))))
        heading = math.degrees(math.atan2(dot(d, east), dot(d, north)))
        return [target[0], target[1], target[2], heading, min(tilt, 89.0), camera.GetDistance()]

    def fly(self, name, render):
        """The fly-to: FLIGHT_FRAMES views from the current one to VIEWS[name]."""
        start, end = self.current_view(), self.resolve(name)
        camera = self.renderer.GetActiveCamera()
        view = [0.0] * 6
        for k in range(1, FLIGHT_FRAMES + 1):
            vtkGlobeCamera.InterpolateView(self.body, start, end, k / FLIGHT_FRAMES, view)
            vtkGlobeCamera.LookAt(camera, self.body, view)
            self.renderer.ResetCameraClippingRange()
            if render:
                self.window.Render()
        self.view = end


def main(argv=None):
    parser = globe_scene.arguments(__doc__, "navigate.png", size=(800, 600))
    parser.add_argument("--fly", choices=sorted(VIEWS), help="fly there before the picture")
    parser.add_argument("--pick", metavar="X,Y", help="readout at this pixel (default: the centre)")
    args = parser.parse_args(argv)
    size = globe_scene.parse_size(parser, args.size)
    pick = (size[0] // 2, size[1] // 2)
    if args.pick:
        try:
            pick = tuple(int(v) for v in args.pick.split(","))
            if len(pick) != 2:
                raise ValueError
        except ValueError:
            parser.error("--pick must look like 400,300, not %r" % args.pick)
    globe_scene.require_display()
    nav = Navigator(size, args.grid, args.data)
    nav.window = globe_scene.window_for(nav.renderer, size, args.interactive)
    if not args.interactive:
        if args.fly:
            nav.fly(args.fly, render=True)
        nav.window.Render()
        nav.window.Render()
        print("readout at (%d, %d): %s" % (pick[0], pick[1], nav.readout(*pick)))
        print("view: %s" % " ".join("%.10g" % v for v in nav.view))
        print("camera: %.4f %.4f %.4f" % tuple(nav.renderer.GetActiveCamera().GetPosition()))
        globe_scene.show(nav.window, args.out, False)
        return 0

    interactor = vtkRenderWindowInteractor()
    style = vtkGlobeInteractorStyle()
    style.SetMapper(nav.mapper)
    interactor.SetInteractorStyle(style)
    interactor.SetRenderWindow(nav.window)

    def on_move(obj, event):
        nav.readout(*obj.GetEventPosition())
        nav.window.Render()

    def on_key(obj, event):
        name = KEYS.get(obj.GetKeySym())
        if name:
            nav.fly(name, render=True)
            style.EnforceConstraints()
            nav.window.Render()

    interactor.AddObserver("MouseMoveEvent", on_move)
    interactor.AddObserver("KeyPressEvent", on_key)
    nav.window.Render()
    interactor.Start()
    return 0


if __name__ == "__main__":
    sys.exit(main())
