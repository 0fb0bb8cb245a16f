"""Imports the installed Python package (not the build tree's) and uses it."""
import os
import sys

import vtkglobe

prefix = os.environ["PYTHONPATH"]
if not vtkglobe.__file__.startswith(prefix):
    sys.exit("imported %s, not the installed package under %s" % (vtkglobe.__file__, prefix))
moon = vtkglobe.vtkGlobeEllipsoid()
moon.SetToMoon()
print("installed package:", vtkglobe.__file__, moon.GetRadii())
