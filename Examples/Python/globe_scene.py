"""What the Python examples share: where Data/ is, geodetic camera and sun placement, layers from
files, the common command line (--out, --interactive, --size, --grid, --data) and the end of
every example (write a PNG offscreen, or open a window).

Copy this file next to your script, or copy the few functions you need.
"""
import argparse
import math
import os
import sys

import vtkmodules.vtkInteractionStyle  # noqa: F401  (the interactor's default style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL backend)
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkWindowToImageFilter)
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera

try:
    import vtkglobe
except ImportError:
    sys.exit("error: cannot import vtkglobe. Set PYTHONPATH to the build's Python package, e.g.\n"
             "  export PYTHONPATH=$PWD/build/lib/python3/dist-packages\n"
             "and use Debian's /usr/bin/python3 (the interpreter VTK is built for), or run\n"
             "  bash Utilities/globe.sh python " + " ".join(sys.argv))

# Data/ is found relative to this file: Examples/Python/../../Data.
DATA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data"))


def arguments(doc, default_out, size=(800, 600), grid=512):
    """The command line every example shares; add your own options to the returned parser.
    doc: the script's docstring; --help shows its first paragraph, joined into one."""
    parser = argparse.ArgumentParser(description=" ".join(doc.strip().split("\n\n")[0].split()))
    parser.add_argument("--out", default=default_out,
                        help="PNG file to write offscreen (default: %(default)s)")
    parser.add_argument("--interactive", action="store_true",
                        help="open a window instead of writing a PNG")
    parser.add_argument("--size", default="%dx%d" % size, metavar="WxH",
                        help="window size in pixels (default: %(default)s)")
    parser.add_argument("--grid", type=int, default=grid,
                        help="projective grid resolution (default: %(default)s)")
    parser.add_argument("--data", default=DATA, help="the Data/ folder (default: %(default)s)")
    return parser


def parse_size(parser, text):
    try:
        width, height = (int(v) for v in text.lower().split("x"))
        if width > 0 and height > 0:
            return width, height
    except ValueError:
        pass
    parser.error("--size must look like 800x600, not %r" % text)


def file_layer(path, role):
    """A vtkGlobeLayer reading a GeoTIFF; role is 'height' or 'color'."""
    layer = vtkglobe.vtkGlobeLayer()
    layer.SetFileName(path)
    if role == "height":
        layer.SetRoleToHeight()
    else:
        layer.SetRoleToColor()
    return layer


def add_earth_layers(mapper, data, insets=True):
    """The demo's Earth: 2-degree relief, SRTM insets of Rainier and Everest, Blue Marble
    imagery, and (insets=True) the New York and Boston imagery insets on top."""
    for name in ("relief_2deg", "mt_rainier_90m", "mt_everest_90m"):
        mapper.AddLayer(file_layer(os.path.join(data, "earth", name + ".tif"), "height"))
    mapper.AddLayer(file_layer(os.path.join(data, "earth", "world.tif"), "color"))
    if insets:
        for name in ("nyc-inset-wgs84", "boston-inset-wgs84"):
            mapper.AddLayer(file_layer(os.path.join(data, "earth", name + ".tif"), "color"))


def look_at(renderer, body, camera, target, view_angle, clipping=None):
    """Points the camera from a geodetic (lon, lat, height) position at a geodetic target with
    the local vertical as view-up (north when looking straight down). clipping: (near, far) in
    metres, or None to let VTK fit it to the bounds (fine from far away only)."""
    eye, focus = [0.0] * 3, [0.0] * 3
    body.GeodeticToCartesian(camera, eye)
    body.GeodeticToCartesian(target, focus)
    east, north, up = [0.0] * 3, [0.0] * 3, [0.0] * 3
    body.ComputeEastNorthUp(camera[0], camera[1], east, north, up)
    view = [f - e for f, e in zip(focus, eye)]
    along = sum(v * u for v, u in zip(view, up)) / math.sqrt(sum(v * v for v in view))
    c = renderer.GetActiveCamera()
    c.SetPosition(eye)
    c.SetFocalPoint(focus)
    c.SetViewUp(north if abs(along) > 0.999 else up)
    c.SetViewAngle(view_angle)
    c.OrthogonalizeViewUp()
    if clipping:
        c.SetClippingRange(*clipping)
    else:
        renderer.ResetCameraClippingRange()


def add_sun(renderer, body, target, azimuth, elevation):
    """A directional sun seen from the geodetic target at azimuth (deg from north, clockwise)
    and elevation (deg)."""
    focus, east, north, up = [0.0] * 3, [0.0] * 3, [0.0] * 3, [0.0] * 3
    body.GeodeticToCartesian(target, focus)
    body.ComputeEastNorthUp(target[0], target[1], east, north, up)
    a, e = math.radians(azimuth), math.radians(elevation)
    to_sun = [math.cos(e) * (math.sin(a) * ea + math.cos(a) * no) + math.sin(e) * u
              for ea, no, u in zip(east, north, up)]
    sun = vtkLight()
    sun.SetLightTypeToSceneLight()
    sun.SetPositional(False)
    sun.SetIntensity(1.1)
    sun.SetFocalPoint(focus)
    sun.SetPosition([f + 1.0e7 * t for f, t in zip(focus, to_sun)])
    renderer.AddLight(sun)
    return sun


def globe(body, grid):
    """The globe mapper for a body, in an actor."""
    mapper = vtkglobe.vtkGlobeMapper()
    mapper.SetEllipsoid(body)
    mapper.SetGridResolution(grid)
    actor = vtkActor()
    actor.SetMapper(mapper)
    return mapper, actor


def window_for(renderer, size, interactive):
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*size)
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(0 if interactive else 1)
    return window


def require_display():
    """VTK on Debian renders through X even offscreen: without a display it would abort."""
    if not os.environ.get("DISPLAY"):
        sys.exit("error: no X display (DISPLAY is not set). Run under Xvfb, e.g.\n"
                 "  xvfb-run -a -s '-screen 0 1280x1024x24 -noreset' /usr/bin/python3 " + " ".join(sys.argv)
                 + "\nor: bash Utilities/globe.sh python " + " ".join(sys.argv))


def show(window, out, interactive, on_timer=None):
    """The end of every example: an interactive window, or two frames offscreen and a PNG (the
    second frame uses the first one's lowest visible terrain, read back from the GPU).
    on_timer: called every 50 ms in the interactive window (e.g. to render again while
    streamed pages come in)."""
    if interactive:
        interactor = vtkRenderWindowInteractor()
        interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
        interactor.SetRenderWindow(window)
        if on_timer:
            interactor.Initialize()
            interactor.AddObserver("TimerEvent", lambda obj, event: on_timer())
            interactor.CreateRepeatingTimer(50)
        window.Render()
        interactor.Start()
        return
    window.Render()
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    writer = vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    if writer.GetErrorCode():
        sys.exit("error: cannot write %s" % out)
    print("wrote %s (%dx%d)" % (out, *window.GetSize()))
