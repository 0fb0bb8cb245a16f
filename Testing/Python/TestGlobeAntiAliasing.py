"""Anti-aliasing with VTK's own FXAA (vtkRenderer.UseFXAAOn) on the globe.

The whole Earth (2-degree relief, Blue Marble) on black, 300 x 225, once plain and once with
FXAA, otherwise identical:
- the depth buffer is the same, value for value (FXAA filters colour only: the globe still
  shares its depth with every other actor);
- every pixel FXAA changed lies on a luminance edge of the plain picture (a neighbour within
  one pixel differs in luminance by more than 1/16): nothing is blurred where there is no edge;
- the silhouette against the sky is smoothed: more limb pixels (covered, next to the
  background) take a value between the background and their inner neighbour's, and the limb's
  step from the background shrinks on average.
Multisampled windows are described in Documentation/rendering.md: the globe is deferred, so its
composition writes one colour and depth per pixel and a multisampled framebuffer gains nothing
on its silhouette. The C++ regression scenes run with FXAA and with 8 samples asked for
(CTest's AntiAliased.* and Multisampled.*) against their terrain checks and baselines.
"""
import sys
import unittest

from globe_test_support import Scene, read_depth
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter


def render(fxaa):
    scene = Scene(300, 225, 256)
    scene.add_earth_layers()
    if fxaa:
        scene.renderer.UseFXAAOn()
    scene.look((-60.0, 20.0, 2.2e7), (-60.0, 20.0, 0.0), 40.0)
    scene.render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(scene.window)
    grab.ReadFrontBufferOff()
    grab.Update()
    rgb = bytes(memoryview(grab.GetOutput().GetPointData().GetScalars()))
    return rgb, read_depth(scene.window)


def luminance(rgb, i):
    return (0.299 * rgb[3 * i] + 0.587 * rgb[3 * i + 1] + 0.114 * rgb[3 * i + 2]) / 255.0


class TestGlobeAntiAliasing(unittest.TestCase):
    def test_fxaa(self):
        w, h = 300, 225
        plain, plain_depth = render(False)
        smooth, smooth_depth = render(True)
        self.assertEqual(plain_depth, smooth_depth, "FXAA leaves the depth buffer as it is")
        covered = [d < 1.0 for d in plain_depth]
        self.assertGreater(sum(covered), 10000)

        changed = off_edge = 0
        for y in range(h):
            for x in range(w):
                i = y * w + x
                if plain[3 * i:3 * i + 3] == smooth[3 * i:3 * i + 3]:
                    continue
                changed += 1
                near = [luminance(plain, j * w + k) for j in range(max(0, y - 1), min(h, y + 2))
                        for k in range(max(0, x - 1), min(w, x + 2))]
                if max(near) - min(near) <= 1.0 / 16.0:
                    off_edge += 1
        print("FXAA changed %d pixels, %d of them off a luminance edge" % (changed, off_edge))
        self.assertGreater(changed, 100, "FXAA ran")
        self.assertEqual(off_edge, 0, "FXAA changes only pixels on an edge")

        # The limb: covered pixels with a background neighbour (4-connected).
        def limb(rgb):
            between, steps = 0, []
            for y in range(1, h - 1):
                for x in range(1, w - 1):
                    i = y * w + x
                    if not covered[i]:
                        continue
                    outside = [j for j in (i - 1, i + 1, i - w, i + w) if not covered[j]]
                    inside = [j for j in (i - 1, i + 1, i - w, i + w) if covered[j]]
                    if not outside or not inside:
                        continue
                    here = luminance(rgb, i)
                    core = max(luminance(rgb, j) for j in inside)
                    between += 1 if 0.0 < here < 0.8 * core else 0
                    steps.append(here - max(luminance(rgb, j) for j in outside))
            return between, sum(steps) / len(steps), len(steps)

        plain_between, plain_step, n = limb(plain)
        smooth_between, smooth_step, _ = limb(smooth)
        print("limb (%d pixels): %d -> %d between background and inside, mean step %.3f -> %.3f"
              % (n, plain_between, smooth_between, plain_step, smooth_step))
        self.assertGreater(smooth_between, plain_between)
        self.assertLess(smooth_step, plain_step)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
