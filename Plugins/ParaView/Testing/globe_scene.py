"""The globe scene the plugin's rendering tests share: Data/earth's relief (heights) and
Blue Marble imagery (colour) shown as "Globe" in a 400 x 300 render view, with VTK geometry
around it that must occlude it or be occluded by it:

- a grey cone between the camera and the globe (in front of Africa);
- a red sphere straight behind the globe (hidden by it), unlit;
- a yellow sphere at the limb, partly behind the globe's edge, unlit;
- a slice through a wavelet data set, scaled to 4,000 km, beside the globe (distributed over
  the ranks under MPI, as the yellow sphere is).
"""
import os

from paraview.simple import (CreateRenderView, Cone, Sphere, Wavelet, Transform, Slice, Show,
                             ColorBy, Render)

SIZE = [400, 300]
# What the plugin's tests share: the plugin, the data, where pictures go, the scene's baseline
# and VTK's regression threshold for it.
PLUGIN = os.environ.get("VTKGLOBE_PARAVIEW_PLUGIN", "")
DATA = os.environ.get("VTKGLOBE_DATA_DIR", "Data")
OUTPUT = os.environ.get("VTKGLOBE_PARAVIEW_OUTPUT", ".")
BASELINE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "Baseline",
                        "TestGlobeParaViewRepresentation.png")
THRESHOLD = 0.15
failures = []


def expect(condition, what, prefix=""):
    """One check: printed "ok"/"FAIL" with what it asserts; failures are collected."""
    print("%s%s %s" % (prefix, "ok  " if condition else "FAIL", what))
    if not condition:
        failures.append(what)


CAMERA = dict(CameraPosition=[2.5e7, 0.8e7, 0.6e7], CameraFocalPoint=[0.0, 0.0, 0.0],
              CameraViewUp=[0.0, 0.0, 1.0], CameraViewAngle=30.0)


def build(ns, data):
    """Builds the scene with the plugin's proxies from `ns` (LoadPlugin's namespace)."""
    relief = ns["GlobeRasterReader"](FileName=os.path.join(data, "earth", "relief_2deg.tif"))
    world = ns["GlobeRasterReader"](FileName=os.path.join(data, "earth", "world.tif"))
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.05, 0.05, 0.1]
    heights = Show(relief, view)
    heights.Representation = "Globe"
    heights.GlobeLayerRole = "Height"
    colours = Show(world, view)
    colours.Representation = "Globe"
    colours.GlobeLayerRole = "Color"

    def solid(source, rgb, flat=False):
        display = Show(source, view)
        display.ColorArrayName = ["POINTS", ""]
        display.AmbientColor = rgb
        display.DiffuseColor = rgb
        if flat:
            # Unlit, so that its pixels are exactly its colour, which no imagery has.
            display.Ambient = 1.0
            display.Diffuse = 0.0
        return display

    solid(Cone(Radius=1.5e6, Height=3e6, Center=[1.0e7, 3.2e6, 2.4e6], Resolution=32),
          [0.6, 0.6, 0.6])
    solid(Sphere(Radius=1.5e6, Center=[-1.0e7, -3.2e6, -2.4e6], ThetaResolution=32,
                 PhiResolution=32), [1.0, 0.0, 0.0], flat=True)
    limb = Sphere(Radius=1.2e6, Center=[-2.0e6, 6.0e6, 1.5e6], ThetaResolution=32,
                  PhiResolution=32)
    solid(limb, [1.0, 1.0, 0.0], flat=True)
    scaled = Transform(Input=Wavelet())
    scaled.Transform.Scale = [2.0e5, 2.0e5, 2.0e5]
    scaled.Transform.Translate = [0.0, -9.0e6, 0.0]
    cut = Slice(Input=scaled)
    cut.SliceType.Origin = [0.0, -9.0e6, 0.0]
    cut.SliceType.Normal = [1.0, 0.0, 0.0]
    sliced = Show(cut, view)
    ColorBy(sliced, ("POINTS", "RTData"))
    for key, value in CAMERA.items():
        setattr(view, key, value)
    Render(view)
    return dict(view=view, heights=heights, colours=colours, limb=limb, slice=cut)


def read_png(path):
    """(width, height, rgb bytes) of a PNG."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    n = scalars.GetNumberOfComponents()
    data = bytes(memoryview(scalars))
    w, h = image.GetDimensions()[:2]
    return w, h, bytes(b for k in range(0, len(data), n) for b in data[k:k + 3])


def image_error(a, b):
    """VTK's regression-test measure between two PNGs (vtkImageDifference's thresholded error,
    the number vtkRegressionTestImage compares with its threshold)."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkImagingCore import vtkImageDifference
    readers = []
    for path in (a, b):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        readers.append(reader)
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[0].GetOutputPort())
    difference.SetImageConnection(readers[1].GetOutputPort())
    difference.Update()
    return difference.GetThresholdedError()


def count(rgb, test):
    """Pixels of a packed RGB byte string for which test(r, g, b) holds."""
    return sum(1 for k in range(0, len(rgb), 3) if test(rgb[k], rgb[k + 1], rgb[k + 2]))


# The spheres are unlit: pure red and yellow. The cone is lit by ParaView's light kit: a grey
# whose shade varies.
def red(r, g, b):
    return r > 245 and g < 10 and b < 10


def yellow(r, g, b):
    return r > 245 and g > 245 and b < 10


def grey(r, g, b):
    return 40 < r < 230 and abs(r - g) < 12 and abs(g - b) < 16


def close(view):
    """Deletes the view and what it shows. Left to pvpython's exit, a render view ends the
    process with an X error (GLXBadContext) under Xvfb."""
    from paraview.simple import Delete
    for representation in list(view.Representations):
        Delete(representation)
    Delete(view)
