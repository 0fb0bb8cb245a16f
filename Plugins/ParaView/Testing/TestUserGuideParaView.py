"""Every ```pvpython block of Documentation/user-guide.md runs with ParaView's pvpython.

Each block runs on its own (a fresh pvpython, --force-offscreen-rendering) in a scratch folder
whose Data/ is the source tree's, with VTKGLOBE_PARAVIEW_PLUGIN naming the plugin built here, as
`bash Utilities/globe.sh pvpython` runs a user's script. It must exit 0 without a VTK error or
warning on its output, every PNG it writes must be a real picture (more than 50 colours), and
the numbers the guide's comments promise must be printed.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

from vtkmodules.vtkIOImage import vtkPNGReader

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
GUIDE = os.path.join(SOURCE, "Documentation", "user-guide.md")
# What the guide's blocks print, as their comments say (the block that holds the key).
PROMISED = {"relief.UpdatePipeline()": ["(0, 179, 0, 89, 0, 0)", "4326", "[-180.0, 90.0, 2.0, 2.0]"]}

with open(GUIDE) as f:
    text = f.read()
snippets = [(text.count("\n", 0, m.start()) + 2, m.group(1))
            for m in re.finditer(r"^```pvpython\n(.*?)^```", text, re.S | re.M)]
failures = []


def expect(condition, what):
    print("%s %s" % ("ok  " if condition else "FAIL", what))
    if not condition:
        failures.append(what)


def colours(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    data = bytes(memoryview(scalars))
    n = scalars.GetNumberOfComponents()
    return len({data[k:k + 3] for k in range(0, len(data), n)})


expect(len(snippets) >= 1, "user-guide.md has %d pvpython block(s)" % len(snippets))
for line, code in snippets:
    tmp = tempfile.mkdtemp(prefix="guide-pv-")
    try:
        os.symlink(os.path.join(SOURCE, "Data"), os.path.join(tmp, "Data"))
        result = subprocess.run([os.environ["PVPYTHON"], "--force-offscreen-rendering", "-c", code],
                                cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                universal_newlines=True, timeout=300)
        print("user-guide.md:%d -> exit %d\n%s" % (line, result.returncode, result.stdout.strip()))
        expect(result.returncode == 0, "user-guide.md:%d exits 0" % line)
        problems = [l for l in result.stdout.splitlines()
                    if re.search(r"\bERR\||\bWARN\||ERROR:|Warning:|Traceback", l)]
        expect(problems == [], "user-guide.md:%d: no errors or warnings %s" % (line, problems))
        for promise in [p for key, ps in PROMISED.items() if key in code for p in ps]:
            expect(promise in result.stdout.splitlines(),
                   "user-guide.md:%d prints %s" % (line, promise))
        for name in sorted(os.listdir(tmp)):
            if name.endswith(".png"):
                n = colours(os.path.join(tmp, name))
                expect(n > 50, "user-guide.md:%d: %s has %d colours" % (line, name, n))
    finally:
        shutil.rmtree(tmp)

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
