"""The Globe representation in ParaView's render view (pvpython, one process).

- Data/earth's relief (Height) and Blue Marble imagery (Color) shown as "Globe" are the two
  layers of one globe (the view's), uploaded once each.
- The picture matches Baseline/TestGlobeParaViewRepresentation.png within VTK's regression
  threshold; it is written as globe-1rank.png for the 2-rank test to compare with.
- Depth is shared with ParaView's other representations: the red sphere behind the globe is
  hidden (0 red pixels) and appears when the globe's layers are hidden; the yellow sphere at the
  limb is partly hidden; the grey cone in front of the globe covers the globe where it stands.
- Layer settings are uniforms: opacity 0 on the imagery changes the picture and uploads
  nothing; opacity 1 gives the first picture back.
- The globe's settings, set on either representation, reach the view's one globe: GlobeBody
  "Moon" shrinks it, GlobeGraticule draws lines, and back to WGS 84 the first picture returns.
- Interactive detail: an interactive render asks VTK for 5 frames/s, the still render after
  it gives the first picture back, and GlobeAutoAdjustDetail reaches the globe.
- Bad input: a 3D image (a wavelet) shown as Globe is refused with an error and the picture is
  unchanged; deleting its representation removes its layer.
"""
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import LoadPlugin, SaveScreenshot, Render  # noqa: E402
import globe_scene  # noqa: E402

from globe_scene import PLUGIN, DATA, OUTPUT, BASELINE, THRESHOLD, expect, failures  # noqa: E402


def property_value(display, name):
    display.UpdatePropertyInformation()
    return display.GetPropertyValue(name)


def shot(view, name):
    path = os.path.join(OUTPUT, name)
    SaveScreenshot(path, view, ImageResolution=globe_scene.SIZE)
    return path, globe_scene.read_png(path)[2]


LoadPlugin(PLUGIN, remote=False, ns=globals())
os.makedirs(OUTPUT, exist_ok=True)
scene = globe_scene.build(globals(), DATA)
view, heights, colours = scene["view"], scene["heights"], scene["colours"]
first, rgb = shot(view, "globe-1rank.png")
layers = property_value(heights, "GlobeLayers")
uploads = property_value(heights, "GlobeUploads")
expect(layers == 2 and uploads == 2,
       "two Globe representations are the %d layers of one globe, %d uploads" % (layers, uploads))

if os.path.exists(BASELINE):
    error = globe_scene.image_error(first, BASELINE)
    expect(error <= THRESHOLD, "the picture matches the baseline: error %.4f (threshold %.2f)"
           % (error, THRESHOLD))
else:
    shutil.copy(first, os.path.join(OUTPUT, os.path.basename(BASELINE)))
    expect(False, "no baseline: %s written to %s" % (os.path.basename(BASELINE), OUTPUT))

# Depth shared with the other representations.
reds, yellows = globe_scene.count(rgb, globe_scene.red), globe_scene.count(rgb, globe_scene.yellow)
renderer = view.GetClientSideObject().GetRenderer()
renderer.SetWorldPoint(1.0e7, 3.2e6, 2.4e6, 1.0)  # the cone's centre
renderer.WorldToDisplay()
x, y = [int(round(v)) for v in renderer.GetDisplayPoint()[:2]]
k = 3 * ((globe_scene.SIZE[1] - 1 - y) * globe_scene.SIZE[0] + x)  # PNG rows run top down
cone_pixel = tuple(rgb[k:k + 3])
heights.Visibility = 0
colours.Visibility = 0
Render(view)
_, bare = shot(view, "globe-hidden.png")
reds_bare = globe_scene.count(bare, globe_scene.red)
yellows_bare = globe_scene.count(bare, globe_scene.yellow)
hidden_pixel = tuple(bare[k:k + 3])
expect(reds == 0 and reds_bare > 50,
       "the red sphere behind the globe: %d red pixels, %d with the globe hidden" %
       (reds, reds_bare))
expect(0 < yellows < yellows_bare,
       "the yellow sphere at the limb is partly hidden: %d of its %d pixels show" %
       (yellows, yellows_bare))
expect(globe_scene.grey(*cone_pixel) and globe_scene.grey(*hidden_pixel),
       "the cone in front of the globe: its centre pixel (%d, %d) is the cone's grey %s "
       "(%s without the globe)" % (x, y, cone_pixel, hidden_pixel))
heights.Visibility = 1
colours.Visibility = 1
Render(view)

# A layer setting is a uniform: no upload, the picture changes and comes back.
before = property_value(heights, "GlobeUploads")
colours.GlobeOpacity = 0.0
Render(view)
_, transparent = shot(view, "globe-opacity0.png")
colours.GlobeOpacity = 1.0
Render(view)
back, _ = shot(view, "globe-opacity1.png")
after = property_value(heights, "GlobeUploads")
changed = sum(1 for a, b in zip(transparent, rgb) if a != b)
error = globe_scene.image_error(back, first)
expect(after == before and changed > 10000 and error == 0.0,
       "imagery opacity 0 and back to 1: %d uploads, %d values changed, then error %.4f "
       "against the first picture" % (after - before, changed, error))

# The globe's settings reach the view's one globe: the Moon's body under the same imagery,
# the graticule, and back to WGS 84.
def globe_pixels(rgb):
    return globe_scene.count(rgb, lambda r, g, b: (r, g, b) != (13, 13, 26) and
                             not globe_scene.red(r, g, b) and not globe_scene.yellow(r, g, b))


earth = globe_pixels(rgb)
heights.GlobeBody = "Moon"
Render(view)
_, moon = shot(view, "globe-moon.png")
colours.GlobeGraticule = 1  # on the other representation: the body stays the Moon
Render(view)
_, graticule = shot(view, "globe-graticule.png")
colours.GlobeGraticule = 0
heights.GlobeBody = "Earth (WGS 84)"
Render(view)
again, _ = shot(view, "globe-earth-again.png")
ratio = globe_pixels(moon) / float(earth)
lines = sum(1 for a, b in zip(moon, graticule) if a != b)
moon_again = globe_pixels(graticule) / float(earth)
expect(0.05 < ratio < 0.4 and lines > 200 and abs(moon_again - ratio) < 0.05 and
       globe_scene.image_error(again, first) == 0.0,
       "GlobeBody Moon: %.2f of the Earth's pixels (the cone and slice stay); GlobeGraticule set "
       "on the other representation draws lines (%d values change) on the Moon (%.2f); back to "
       "WGS 84, the first picture" % (ratio, lines, moon_again))

# Interactive detail: ParaView's interactive renders ask VTK for 5 frames/s (still renders
# 0.002/s), the budget vtkGlobeMapper::AutoAdjustDetail spends; the still render after one gives
# the first picture back, and GlobeAutoAdjustDetail reaches the view's globe.
window = view.GetClientSideObject().GetRenderWindow()
globe_mapper = [a.GetMapper() for a in renderer.GetActors()
                if a.GetMapper() and a.GetMapper().GetClassName() == "vtkGlobeMapper"][0]
view.SMProxy.InteractiveRender()
rate = window.GetDesiredUpdateRate()
Render(view)
after, _ = shot(view, "globe-after-interaction.png")
heights.GlobeAutoAdjustDetail = 0
Render(view)
off = "AutoAdjustDetail: 0" in str(globe_mapper)
heights.GlobeAutoAdjustDetail = 1
Render(view)
expect(rate == 5.0 and globe_scene.image_error(after, first) == 0.0 and off and
       "AutoAdjustDetail: 1" in str(globe_mapper),
       "an interactive render asks for %g frames/s (5); the still render after it is the first "
       "picture; GlobeAutoAdjustDetail off and on reach the globe" % rate)

# Bad input: a 3D image data set shown as Globe is refused with an error naming the problem,
# and the rest of the scene renders as before.
from paraview.simple import Wavelet, Show, Delete  # noqa: E402
wavelet = Wavelet()
bad = Show(wavelet, view)
bad.Representation = "Globe"
Render(view)
with_bad, _ = shot(view, "globe-bad-input.png")
error = globe_scene.image_error(with_bad, first)
layers = property_value(heights, "GlobeLayers")
expect(error == 0.0 and layers == 3,
       "a 3D wavelet as Globe: refused (an error says why), the picture unchanged (error %.4f), "
       "%d layers" % (error, layers))
Delete(bad)
Render(view)
expect(property_value(heights, "GlobeLayers") == 2, "deleted, it leaves the globe: 2 layers")

globe_scene.close(view)
print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
