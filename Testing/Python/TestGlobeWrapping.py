"""Every public class and method reaches Python, and the README's one line is all a user needs.

- Each class declared with an export macro in Module/*/vtkGlobe*.h imports from vtkglobe (and
  from its module, vtkglobe.vtkGlobeCore / vtkGlobeRendering), is created by New(), and has
  every method its header declares public (set/get/boolean macros expanded), except the two
  that VTK itself never wraps: PrintSelf (Python has Print) and vtkRenderPass::Render (its
  vtkRenderState argument is not wrapped by VTK).
- In-memory data crosses the wrapper: SetHeightData takes a Python sequence of exactly
  width * height numbers, and the wrong length is refused.
- From a fresh shell (an empty environment), the README's `export PYTHONPATH=...` line followed
  by the README's Python command imports the package with Debian's /usr/bin/python3.
- `bash Utilities/globe.sh python SCRIPT` runs a script with that path and a display.
"""
import glob
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

import vtkglobe
from globe_test_support import SOURCE

BUILD = os.environ.get("VTKGLOBE_BUILD_DIR", "")
NOT_WRAPPED_BY_VTK = {"PrintSelf", "Render"}


def nowrap_classes():
    """Classes a module's CMakeLists.txt keeps out of Python on purpose (NOWRAP_CLASSES)."""
    names = set()
    for cmake in glob.glob(os.path.join(SOURCE, "Module", "*", "CMakeLists.txt")):
        with open(cmake) as f:
            names |= set(re.findall(r"NOWRAP_CLASSES\s+([\w\s]+?)\n", f.read()))
    return {n for group in names for n in group.split()}


def public_api(header):
    """(class name, method names) of the exported class a header declares."""
    with open(header) as f:
        text = f.read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    match = re.search(r"class\s+VTKGLOBE\w+_EXPORT\s+(vtkGlobe\w+)[^{]*\{(.*)\n\};", text, re.S)
    if not match:
        return None, set()
    name, body = match.groups()
    public, state = "", "private"
    for part in re.split(r"\n\s*(public|protected|private):", body):
        if part in ("public", "protected", "private"):
            state = part
        elif state == "public":
            public += part
    methods = set()
    for macro, argument in re.findall(r"(vtk\w+Macro)\((\w+)", public):
        if macro.startswith("vtkSet"):
            methods.add("Set" + argument)
        elif macro.startswith("vtkGet"):
            methods.add("Get" + argument)
        elif macro == "vtkBooleanMacro":
            methods |= {argument + "On", argument + "Off"}
    methods |= {m for m in re.findall(r"\b([A-Z]\w*)\s*\(", public)
                if m != name and not m.startswith("VTK")}
    methods.discard("New")
    return name, methods


class TestGlobeWrapping(unittest.TestCase):
    def test_every_public_class_and_method(self):
        headers = sorted(glob.glob(os.path.join(SOURCE, "Module", "*", "vtkGlobe*.h")))
        nowrap = nowrap_classes()
        self.assertIn("vtkGlobeMapperTesting", nowrap)
        classes = 0
        for header in headers:
            name, methods = public_api(header)
            if name is None:
                continue
            if name in nowrap:
                self.assertFalse(hasattr(vtkglobe, name), "%s is NOWRAP but wrapped" % name)
                continue
            classes += 1
            module = "vtkGlobe" + os.path.basename(os.path.dirname(header))
            with self.subTest(cls=name):
                self.assertTrue(hasattr(vtkglobe, name), "%s is not in vtkglobe" % name)
                self.assertTrue(hasattr(getattr(vtkglobe, module), name))
                obj = getattr(vtkglobe, name)()
                self.assertEqual(obj.GetClassName(), name)
                missing = sorted(m for m in methods - NOT_WRAPPED_BY_VTK if not hasattr(obj, m))
                self.assertEqual(missing, [], "%s: not wrapped" % name)
                print("%-28s %2d public methods, all wrapped" % (name, len(methods)))
        self.assertGreaterEqual(classes, 8)

    def test_in_memory_heights_from_a_sequence(self):
        layer = vtkglobe.vtkGlobeLayer()
        values = [float(i) for i in range(6)]
        layer.SetHeightData(3, 2, values, -10.0, 20.0, 40.0, 50.0)
        self.assertTrue(layer.IsValid())
        self.assertEqual([layer.GetData().GetValue(i) for i in range(6)], values)
        extent = [0.0] * 4
        layer.GetGeographicExtent(extent)
        self.assertEqual(extent, [-10.0, 20.0, 40.0, 50.0])
        with self.assertRaises((ValueError, TypeError)):
            layer.SetHeightData(3, 2, values[:5], -10.0, 20.0, 40.0, 50.0)

    def test_return_value_forms(self):
        # Conversions and the extent as return values (tuples), next to the out-parameter forms.
        from vtkglobe import vtkGlobeEllipsoid, vtkGlobeLayer
        body = vtkGlobeEllipsoid()
        xyz = body.GeodeticToCartesian(0.0, 0.0, 0.0)
        self.assertEqual(tuple(xyz), (6378137.0, 0.0, 0.0))
        out = [0.0] * 3
        self.assertTrue(body.GeodeticToCartesian(0.0, 0.0, 0.0, out))
        self.assertEqual(out, [6378137.0, 0.0, 0.0])
        lon, lat, h = body.CartesianToGeodetic(0.0, 6378137.0, 0.0)
        self.assertAlmostEqual(lon, 90.0, places=12)
        self.assertAlmostEqual(h, 0.0, places=6)
        # Bad input: NaN, with the error the out-parameter form reports.
        from vtkmodules.vtkCommonCore import vtkCommand
        said = []
        body.AddObserver(vtkCommand.ErrorEvent, lambda o, e: said.append(e))
        self.assertTrue(all(math.isnan(v) for v in body.GeodeticToCartesian(float("nan"), 0.0, 0.0)))
        self.assertEqual(len(said), 1)
        layer = vtkGlobeLayer()
        layer.SetHeightData(3, 2, [1.0] * 6, -10.0, 20.0, 40.0, 50.0)
        self.assertTrue(layer.Update())
        self.assertEqual(tuple(layer.GetGeographicExtent()), (-10.0, 20.0, 40.0, 50.0))

    def test_names(self):
        # Raster size in rows and columns ("height" means terrain); roles by name.
        import warnings
        from vtkglobe import vtkGlobeLayer, vtkGlobeLayerSet
        layer = vtkGlobeLayer()
        layer.SetHeightData(3, 2, [1.0] * 6, -10.0, 20.0, 40.0, 50.0)
        self.assertTrue(layer.Update())
        self.assertEqual((layer.GetNumberOfColumns(), layer.GetNumberOfRows()), (3, 2))
        self.assertEqual(tuple(layer.GetDimensions()), (3, 2))
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            self.assertEqual((layer.GetWidth(), layer.GetHeight()), (3, 2))
        self.assertTrue(any(issubclass(w.category, DeprecationWarning) for w in caught),
                        "GetWidth/GetHeight are deprecated")
        layers = vtkGlobeLayerSet()
        layers.AddLayer(layer)
        self.assertEqual(layers.Update(), 1)
        self.assertEqual(layers.GetNumberOfActiveLayers(vtkGlobeLayer.Height), 1)
        self.assertEqual(layers.GetNumberOfActiveLayers(vtkGlobeLayer.Mask), 0)

    def test_one_owner_per_setting(self):
        # The mapper's shading and effect switches are the composite pass's values.
        from vtkglobe import vtkGlobeMapper
        mapper = vtkGlobeMapper()
        composite = mapper.GetCompositePass()
        before = mapper.GetMTime()
        composite.SetAmbient(0.4)
        composite.AtmosphereOn()
        composite.SetBaseColor(0.5, 0.25, 0.125)
        self.assertEqual(mapper.GetAmbient(), 0.4)
        self.assertTrue(mapper.GetAtmosphere())
        self.assertEqual(tuple(mapper.GetBaseColor()), (0.5, 0.25, 0.125))
        self.assertGreater(mapper.GetMTime(), before, "a change on the pass modifies the mapper")
        mapper.GraticuleOn()
        mapper.SetAmbient(0.2)
        self.assertTrue(composite.GetGraticule())
        self.assertEqual(composite.GetAmbient(), 0.2)

    def test_mapper_refuses_an_input(self):
        # The globe takes no input: an input is an error, not silently ignored.
        from vtkmodules.vtkFiltersSources import vtkConeSource
        from vtkglobe import vtkGlobeMapper
        from vtkmodules.vtkCommonCore import vtkCommand
        mapper = vtkGlobeMapper()
        errors = []
        mapper.AddObserver(vtkCommand.ErrorEvent, lambda o, e: errors.append(e))
        mapper.SetInputConnection(vtkConeSource().GetOutputPort())
        self.assertEqual(len(errors), 1)
        self.assertEqual(mapper.GetNumberOfInputConnections(0), 0)
        mapper.SetBaseColor(0.1, 0.2, 0.3)
        self.assertEqual(tuple(mapper.GetBaseColor()), (0.1, 0.2, 0.3))
        mapper.SetGridResolution(4096)
        self.assertEqual(mapper.GetGridResolution(), 2048)
        self.assertEqual(mapper.GetGridPass().GetResolution(), 2048)

    def test_readme_line_from_a_fresh_shell(self):
        with open(os.path.join(SOURCE, "README.md")) as f:
            readme = f.read()
        export = re.search(r"^export PYTHONPATH=\S+", readme, re.M).group(0)
        command = re.search(r"^/usr/bin/python3 -c .*$", readme, re.M).group(0)
        self.assertIn("$PWD/build/", export)
        with tempfile.TemporaryDirectory() as tmp:
            # The README's line is run in a folder whose build/ is this build tree.
            os.symlink(BUILD or os.path.join(SOURCE, "build"), os.path.join(tmp, "build"))
            result = subprocess.run(["/usr/bin/env", "-i", "PATH=/usr/bin:/bin", "/bin/bash",
                                     "--noprofile", "--norc", "-c", export + "\n" + command],
                                    cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                    universal_newlines=True, timeout=60)
        print("%s\n%s\n-> %s" % (export, command, result.stdout.strip()))
        self.assertEqual(result.returncode, 0)
        self.assertIn("(6378137.0, 6378137.0, 6356752.314245", result.stdout)

    @unittest.skipUnless(BUILD, "VTKGLOBE_BUILD_DIR not given")
    def test_globe_sh_python(self):
        with tempfile.TemporaryDirectory() as tmp:
            script = os.path.join(tmp, "script.py")
            with open(script, "w") as f:
                f.write("import sys, vtkglobe\nfrom vtkglobe import vtkGlobeMapper\n"
                        "print('interpreter', sys.executable, 'args', sys.argv[1:])\n")
            environment = {"PATH": "/usr/bin:/bin", "HOME": tmp, "VTKGLOBE_BUILD_DIR": BUILD}
            result = subprocess.run(["/bin/bash", os.path.join(SOURCE, "Utilities", "globe.sh"),
                                     "python", script, "--x", "1"], env=environment,
                                    stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                    universal_newlines=True, timeout=600)
        print(result.stdout[-2000:])
        self.assertEqual(result.returncode, 0)
        self.assertIn("interpreter /usr/bin/python3 args ['--x', '1']", result.stdout)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
