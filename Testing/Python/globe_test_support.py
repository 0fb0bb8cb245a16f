"""What the Python tests share: the C++ tests' scene (vtkGlobeRenderingTestHelpers.h's Scene, line
for line), VTK's image comparison against Testing/Baseline, depth readback, running an example
as a user would, and reading its PNG back.
"""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL backend)
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkImagingCore import vtkImageDifference
from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)

from vtkglobe import vtkGlobeEllipsoid, vtkGlobeLayer, vtkGlobeMapper

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
DATA = os.environ.get("VTKGLOBE_DATA_DIR", os.path.join(SOURCE, "Data"))
BASELINES = os.environ.get("VTKGLOBE_BASELINE_DIR", os.path.join(SOURCE, "Testing", "Baseline"))
TEMPORARY = os.environ.get("VTKGLOBE_TEMP_DIR", os.path.join(os.getcwd(), "Testing", "Temporary"))
EXAMPLES = os.path.join(SOURCE, "Examples", "Python")


def file_layer(path, height):
    layer = vtkGlobeLayer()
    layer.SetFileName(os.path.join(DATA, path))
    if height:
        layer.SetRoleToHeight()
    else:
        layer.SetRoleToColor()
    return layer


class Scene:
    """vtkGlobeTest::Scene: the mapper, its actor, a renderer and a 300x225 offscreen window,
    no explicit light (VTK's automatic headlight), black background, no multisampling."""

    def __init__(self, width=300, height=225, grid=256):
        self.body = vtkGlobeEllipsoid()
        self.mapper = vtkGlobeMapper()
        self.mapper.SetEllipsoid(self.body)
        self.mapper.SetGridResolution(grid)
        self.actor = vtkActor()
        self.actor.SetMapper(self.mapper)
        self.renderer = vtkRenderer()
        self.renderer.AddActor(self.actor)
        self.renderer.SetBackground(0.0, 0.0, 0.0)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetMultiSamples(0)
        self.window.SetSize(width, height)
        self.window.AddRenderer(self.renderer)

    def add_earth_layers(self):
        for name in ("relief_2deg", "mt_rainier_90m", "mt_everest_90m"):
            self.mapper.AddLayer(file_layer("earth/%s.tif" % name, True))
        self.mapper.AddLayer(file_layer("earth/world.tif", False))

    def look(self, camera, target, angle, near=0.0, far=0.0):
        """vtkGlobeTest::LookAt, then the clipping range (VTK's when near is 0)."""
        eye, focus = [0.0] * 3, [0.0] * 3
        self.body.GeodeticToCartesian(camera, eye)
        self.body.GeodeticToCartesian(target, focus)
        east, north, up = [0.0] * 3, [0.0] * 3, [0.0] * 3
        self.body.ComputeEastNorthUp(camera[0], camera[1], east, north, up)
        c = self.renderer.GetActiveCamera()
        c.SetPosition(eye)
        c.SetFocalPoint(focus)
        view = [f - e for f, e in zip(focus, eye)]
        along = sum(v * u for v, u in zip(view, up)) / math.sqrt(sum(v * v for v in view))
        c.SetViewUp(north if abs(along) > 0.999 else up)
        c.SetViewAngle(angle)
        c.OrthogonalizeViewUp()
        if near > 0:
            c.SetClippingRange(near, far)
        else:
            self.renderer.ResetCameraClippingRange()

    def render(self):
        """Two frames: the second uses the first one's GPU reduction for the primary sphere."""
        self.window.Render()
        self.window.Render()


def compare_with_baseline(window, name, threshold=0.05):
    """VTK's regression comparison (vtkTesting::RegressionTest, as
    vtkRegressionTestImageThreshold and vtk.test.Testing.compareImage do it): vtkImageDifference
    of the back buffer against Testing/Baseline/<name>.png (or its _N alternatives), thresholded
    error compared with threshold. Returns the error; on failure writes the image and the
    difference to the temporary folder."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    candidates = [os.path.join(BASELINES, name + ".png")]
    k = 1
    while os.path.exists(os.path.join(BASELINES, "%s_%d.png" % (name, k))):
        candidates.append(os.path.join(BASELINES, "%s_%d.png" % (name, k)))
        k += 1
    best, best_diff = float("inf"), None
    for baseline in candidates:
        if not os.path.exists(baseline):
            continue
        reader = vtkPNGReader()
        reader.SetFileName(baseline)
        diff = vtkImageDifference()
        diff.SetInputConnection(grab.GetOutputPort())
        diff.SetImageConnection(reader.GetOutputPort())
        diff.Update()
        error = diff.GetThresholdedError()
        if error < best:
            best, best_diff = error, diff
    if best > threshold:
        os.makedirs(TEMPORARY, exist_ok=True)
        for suffix, port in (("", grab.GetOutputPort()),
                             (".diff", best_diff.GetOutputPort() if best_diff else None)):
            if port is None:
                continue
            writer = vtkPNGWriter()
            writer.SetFileName(os.path.join(TEMPORARY, "Python%s%s.png" % (name, suffix)))
            writer.SetInputConnection(port)
            writer.Write()
        print("image comparison with %s: error %.4f > %.2f; the image is in %s"
              % (name, best, threshold, TEMPORARY))
    else:
        print("image comparison with %s: error %.4f (threshold %.2f)" % (name, best, threshold))
    return best


def read_depth(window):
    """The z-buffer (0 near .. 1 far) as a list, row 0 at the bottom."""
    width, height = window.GetSize()
    depth = vtkFloatArray()
    window.GetZbufferData(0, 0, width - 1, height - 1, depth)
    return list(memoryview(depth))


def unproject(renderer, x, y, depth):
    renderer.SetDisplayPoint(x, y, depth)
    renderer.DisplayToWorld()
    p = renderer.GetWorldPoint()
    return [p[i] / p[3] for i in range(3)]


def run_example(script, *arguments):
    """Runs Examples/Python/<script> with Debian's interpreter as a user would; returns
    (exit code, stdout, stderr)."""
    result = subprocess.run([sys.executable, os.path.join(EXAMPLES, script)] + list(arguments),
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True, timeout=300)
    sys.stdout.write(result.stdout)
    sys.stdout.write("".join(line + "\n" for line in result.stderr.splitlines()
                             if "texCoordIn" not in line))
    return result.returncode, result.stdout, result.stderr


class ExampleTest(unittest.TestCase):
    """A test of one example script: a temporary folder with the picture's path, and --help."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.out = os.path.join(self.tmp.name, "out.png")

    def tearDown(self):
        self.tmp.cleanup()

    def check_help(self, script, words):
        code, stdout, _ = run_example(script, "--help")
        self.assertEqual(code, 0)
        for word in words:
            self.assertIn(word, stdout)


class Image:
    """A PNG read back: size and RGB(A) pixels, row 0 at the bottom (VTK's convention)."""

    def __init__(self, path):
        reader = vtkPNGReader()
        if not reader.CanReadFile(path):
            raise AssertionError("%s is not a readable PNG" % path)
        reader.SetFileName(path)
        reader.Update()
        data = reader.GetOutput()
        self.width, self.height, _ = data.GetDimensions()
        scalars = data.GetPointData().GetScalars()
        self.components = scalars.GetNumberOfComponents()
        self.bytes = bytes(memoryview(scalars))

    def __call__(self, x, y):
        k = (y * self.width + x) * self.components
        return tuple(self.bytes[k:k + 3])

    def pixels(self):
        for y in range(self.height):
            for x in range(self.width):
                yield x, y, self(x, y)

    def count(self, predicate):
        return sum(1 for _, _, p in self.pixels() if predicate(p))

    def near(self, x, y, predicate, radius=1):
        """Whether any pixel within radius of (x, y) satisfies predicate."""
        for j in range(max(0, y - radius), min(self.height, y + radius + 1)):
            for i in range(max(0, x - radius), min(self.width, x + radius + 1)):
                if predicate(self(i, j)):
                    return True
        return False


def project(renderer, point):
    """Display coordinates (x, y) of a world point."""
    renderer.SetWorldPoint(point[0], point[1], point[2], 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    return x, y
