"""A time series of rasters in ParaView: the Globe Raster Reader given several files is one
time-varying source, and ParaView's animation steps through it.

- Three global 16 x 8 float rasters (TIFF + world file, plate carree) are written to a scratch
  folder; step k holds the values 100 k + 0 .. 100 k + 127.
- The proxy's FileNames takes them all: TimestepValues is (0, 1, 2), and ParaView's time keeper
  and animation scene take those steps from it.
- UpdatePipeline(t) reads the step at or before t: its file (GlobeFileName in the field data),
  its value range and DATA_TIME_STEP, for t = 0, 1, 2 and times in between and beyond.
- The animation: with the reader shown in a render view, moving the scene's time to each step
  renders the view with that step's data (the representation's data information follows); a
  time within the same step decodes nothing (the reader gives the same arrays again).
- A series whose second file has another grid fails at that step with an error naming both
  files, and the first step still reads.
- On the globe: a series of red, green and blue global images shown as "Globe" (Color) paints
  the globe with each step's colour as the animation moves; a new step uploads 1 texture, a
  time within the same step none.
"""
import os
import shutil
import sys
import tempfile

from paraview.simple import (LoadPlugin, GetAnimationScene, GetTimeKeeper, CreateRenderView,
                             Show, Render, Delete, SaveScreenshot)
from vtkmodules.util.vtkConstants import VTK_STRING, VTK_UNSIGNED_CHAR
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkTIFFWriter
from vtkmodules.util.misc import calldata_type

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from globe_scene import PLUGIN, expect, failures  # noqa: E402


def write_global_tiff(folder, name, image):
    """`image` as a TIFF with a world file that spreads it over the globe (plate carree)."""
    w, h = image.GetDimensions()[:2]
    path = os.path.join(folder, name + ".tif")
    writer = vtkTIFFWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.Write()
    with open(os.path.join(folder, name + ".tfw"), "w") as world:
        world.write("%r\n0\n0\n%r\n%r\n%r\n" % (360.0 / w, -180.0 / h, -180.0 + 180.0 / w,
                                                 90.0 - 90.0 / h))
    return path


def write_step(folder, name, k, w=16, h=8):
    """A global w x h float raster: values 100 k + (0 .. w h - 1)."""
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    values = vtkFloatArray()
    values.SetNumberOfValues(w * h)
    for n in range(w * h):
        values.SetValue(n, 100.0 * k + n)
    image.GetPointData().SetScalars(values)
    return write_global_tiff(folder, name, image)


def write_colour_step(folder, name, k, w=16, h=8):
    """A global w x h RGB raster: pure red, green or blue for k = 0, 1, 2."""
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    image.AllocateScalars(VTK_UNSIGNED_CHAR, 3)
    rgb = image.GetPointData().GetScalars()
    for n in range(w * h):
        rgb.SetTuple3(n, *(255.0 if c == k else 0.0 for c in range(3)))
    return write_global_tiff(folder, name, image)


def step_pixels(path):
    """Pixels of a screenshot that are each step's pure colour (red, green, blue)."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    counts = [0, 0, 0]
    for n in range(scalars.GetNumberOfTuples()):
        rgb = scalars.GetTuple(n)[:3]
        for c in range(3):
            if rgb[c] > 200 and all(rgb[o] < 40 for o in range(3) if o != c):
                counts[c] += 1
    return counts


def output_of(proxy):
    data = proxy.GetClientSideObject().GetOutputDataObject(0)
    names = data.GetFieldData().GetAbstractArray("GlobeFileName")
    scalars = data.GetPointData().GetScalars()
    info = data.GetInformation()
    return (os.path.basename(names.GetValue(0)) if names else None,
            scalars.GetRange() if scalars else None,
            info.Get(data.DATA_TIME_STEP()) if info.Has(data.DATA_TIME_STEP()) else None)


LoadPlugin(PLUGIN, remote=False, ns=globals())
folder = tempfile.mkdtemp(prefix="globe-series-")
try:
    files = [write_step(folder, "sst_%d" % k, k) for k in range(3)]
    series = GlobeRasterReader(FileNames=files)  # noqa: F821 (defined by LoadPlugin)
    series.UpdatePipelineInformation()
    steps = list(series.TimestepValues)
    expect(steps == [0.0, 1.0, 2.0], "TimestepValues %s: one step per file" % steps)
    keeper = GetTimeKeeper()
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    expect(list(keeper.TimestepValues) == steps and scene.EndTime == 2.0,
           "the time keeper has the steps %s, the animation ends at %s"
           % (list(keeper.TimestepValues), scene.EndTime))

    # Each requested time: the file of the last step at or before it.
    for time, k in ((0.0, 0), (0.7, 0), (1.0, 1), (1.99, 1), (2.0, 2), (5.0, 2), (-1.0, 0)):
        series.UpdatePipeline(time)
        name, value_range, data_time = output_of(series)
        expect(name == "sst_%d.tif" % k and value_range == (100.0 * k, 100.0 * k + 127) and
               data_time == float(k),
               "UpdatePipeline(%.2f): %s, values %s, DATA_TIME_STEP %s"
               % (time, name, value_range, data_time))

    # ParaView's animation drives the view's time, and the representation follows.
    view = CreateRenderView()
    display = Show(series, view)
    display.Representation = "Slice"  # the data as a flat image (Globe is the default)
    values_before = None
    for time, k in ((0.0, 0), (1.0, 1), (1.5, 1), (2.0, 2)):
        scene.AnimationTime = time
        Render(view)
        name, value_range, data_time = output_of(series)
        shown = display.GetRepresentedDataInformation().GetPointDataInformation() \
            .GetArrayInformation("Values").GetComponentRange(0)
        values = series.GetClientSideObject().GetOutputDataObject(0).GetPointData().GetScalars()
        # 1.5 lies within step 1: the reader runs (a new time), but decodes nothing.
        same = values_before is not None and values_before == (values, values.GetMTime())
        values_before = (values, values.GetMTime())
        expect(view.ViewTime == time and name == "sst_%d.tif" % k and
               tuple(shown) == (100.0 * k, 100.0 * k + 127) and (time != 1.5 or same),
               "animation time %.1f: the view shows %s, values %s%s"
               % (time, name, tuple(shown), "; the same arrays as at 1.0" if time == 1.5 else ""))

    # A series whose files do not share a grid.
    odd = write_step(folder, "sst_coarse", 1, w=8, h=4)
    broken = GlobeRasterReader(FileNames=[files[0], odd])  # noqa: F821
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        errors.append(message)

    broken.GetClientSideObject().AddObserver("ErrorEvent", on_error)
    broken.UpdatePipeline(1.0)
    error = errors[0] if errors else ""
    expect("sst_coarse.tif" in error and "sst_0.tif" in error and "8 x 4" in error and
           broken.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints() == 0,
           "a file with another grid fails its step: %s" % error)
    broken.UpdatePipeline(0.0)
    name, value_range, data_time = output_of(broken)
    expect(name == "sst_0.tif" and value_range == (0.0, 127.0),
           "the first step of that series still reads: %s, %s" % (name, value_range))
    # Deleted here: left to pvpython's exit, this view ends the process with an X error
    # (GLXBadContext) under Xvfb.
    Delete(display)
    Delete(view)

    # A colour series on the globe: red, green, blue steps shown as "Globe" (Color).
    colour_files = [write_colour_step(folder, "colour_%d" % k, k) for k in range(3)]
    colour_series = GlobeRasterReader(FileNames=colour_files)  # noqa: F821
    scene.UpdateAnimationUsingDataTimeSteps()
    view = CreateRenderView()
    view.ViewSize = [200, 150]
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [3.0e7, 0.0, 0.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    globe = Show(colour_series, view)  # on the globe by default, as colour: 3 channels
    globe.UpdatePropertyInformation()
    expect(globe.Representation == "Globe" and globe.GlobeLayerRole == "Automatic",
           "a raster is shown as %s by default, role %s" % (globe.Representation,
                                                           globe.GlobeLayerRole))
    globe.GlobeLighting = 0  # unlit: each pixel is the step's pure colour
    uploads = None
    for time, k, uploaded in ((0.0, 0, None), (1.0, 1, 1), (1.5, 1, 0), (2.0, 2, 1), (0.0, 0, 1)):
        scene.AnimationTime = time
        Render(view)
        path = os.path.join(folder, "globe.png")
        SaveScreenshot(path, view, ImageResolution=[200, 150])
        pixels = step_pixels(path)
        globe.UpdatePropertyInformation()
        now = globe.GetPropertyValue("GlobeUploads")
        count = None if uploads is None else now - uploads
        uploads = now
        expect(pixels[k] > 5000 and sum(pixels) == pixels[k] and
               (uploaded is None or count == uploaded),
               "globe at time %.1f: %d pixels of step %d's colour (%s by step), %s upload(s)"
               % (time, pixels[k], k, pixels, "the first" if count is None else count))
    Delete(globe)
    Delete(view)
finally:
    shutil.rmtree(folder)

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
