"""The Globe representation in ParaView's client/server mode: pvpython connected to a pvserver.

The test starts a pvserver (PVSERVER, on a free local port), connects to it, loads the plugin
on both sides and builds TestGlobeParaViewRepresentation's scene (globe_scene.py): the data and
the representations live on the server. Rendered on the server (remote rendering, the picture
sent to the client) and on the client (the rasters and geometry delivered to it), the picture
matches the same baseline within VTK's regression threshold.
"""
import os
import socket
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import Connect, LoadPlugin, Render, SaveScreenshot  # noqa: E402
import globe_scene  # noqa: E402

from globe_scene import PLUGIN, DATA, OUTPUT, BASELINE, THRESHOLD, expect, failures  # noqa: E402


with socket.socket() as probe:
    probe.bind(("localhost", 0))
    port = probe.getsockname()[1]
# The server ends when its client does (or after 5 minutes without one).
server = subprocess.Popen([os.environ["PVSERVER"], "--force-offscreen-rendering", "--timeout=5",
                           "--server-port=%d" % port], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True)
try:
    # The server says when it listens.
    for line in server.stdout:
        if "Accepting connection" in line:
            break
    Connect("localhost", port)
except BaseException:
    server.kill()
    raise
LoadPlugin(PLUGIN, remote=False, ns=globals())
LoadPlugin(PLUGIN, remote=True, ns=globals())
os.makedirs(OUTPUT, exist_ok=True)
scene = globe_scene.build(globals(), DATA)
view = scene["view"]
for mode, threshold in (("remote", 0.0), ("local", 1e9)):
    view.RemoteRenderThreshold = threshold  # MB of geometry above which the server renders
    Render(view)
    path = os.path.join(OUTPUT, "globe-client-server-%s.png" % mode)
    SaveScreenshot(path, view, ImageResolution=globe_scene.SIZE)
    error = globe_scene.image_error(path, BASELINE)
    expect(error <= THRESHOLD, "rendered on the %s: error %.4f against the baseline "
           "(threshold %.2f)" % ("server" if mode == "remote" else "client", error, THRESHOLD))
globe_scene.close(view)

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
