// The atmosphere from space (issue "Pictures": "from space, the limb glow"): the whole Earth
// from 22,000 km (2-degree relief, Blue Marble, 300 x 225) with the sun over 20 N, 10 E, so
// that the terminator crosses the disc and one limb is lit, the other in the night. Rendered
// without and with the atmosphere:
//  - the depth buffer is the same (the glow is colour only: it occludes nothing);
//  - with it, a glow surrounds the disc: background pixels next to the disc turn non-black
//    and blue-dominant on the day side, and the day side's glow is brighter than the night
//    side's (the glow is scattered sunlight, not a painted ring);
//  - pixels more than 4 % of the Earth's radius outside the disc stay black (the shell is
//    2.5 % thick; TestGlobeEffects checks its silhouette exactly).
// The picture with the atmosphere is the regression baseline.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkLight.h"
#include "vtkRegressionTestImage.h"

#include <cmath>
#include <cstdio>

int TestGlobeLimb(int argc, char* argv[])
{
  vtkGlobeTest::Checklist check;
  constexpr int W = 300, H = 225;
  vtkGlobeTest::Scene scene(W, H, 256);
  scene.AddEarthLayers(true, true);
  double sunPosition[3];
  vtkGlobeTest::AddSunOver(scene, 10.0, 20.0, sunPosition);
  const double camera[3] = { -40.0, 25.0, 2.2e7 }, target[3] = { -40.0, 25.0, 0.0 };
  scene.Look(camera, target, 30.0);

  std::vector<unsigned char> rgb[2];
  std::vector<float> depth[2];
  vtkGlobeTest::RenderWithoutAndWithAtmosphere(scene, rgb, depth);
  check.Expect(depth[0] == depth[1], "the atmosphere changes no depth");

  // The disc's centre and radius in pixels, from the covered pixels.
  double cx = 0, cy = 0, area = 0;
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      if (depth[1][y * W + x] < 1.0f)
      {
        cx += x;
        cy += y;
        ++area;
      }
    }
  }
  cx /= area;
  cy /= area;
  const double radius = std::sqrt(area / vtkMath::Pi());
  // The sun's side of the disc: the image of a step from the centre towards the sun (a point
  // 7,000 km out, in front of the camera; the sun itself is behind it).
  double sunDisplay[3], centreWorld[3] = { 0, 0, 0 }, centreDisplay[3], towards[3];
  const double sunDistance = vtkMath::Norm(sunPosition);
  for (int i = 0; i < 3; ++i)
  {
    towards[i] = 7.0e6 * sunPosition[i] / sunDistance;
  }
  scene.Renderer->SetWorldPoint(towards[0], towards[1], towards[2], 1.0);
  scene.Renderer->WorldToDisplay();
  scene.Renderer->GetDisplayPoint(sunDisplay);
  scene.Renderer->SetWorldPoint(centreWorld[0], centreWorld[1], centreWorld[2], 1.0);
  scene.Renderer->WorldToDisplay();
  scene.Renderer->GetDisplayPoint(centreDisplay);
  double toSun[2] = { sunDisplay[0] - centreDisplay[0], sunDisplay[1] - centreDisplay[1] };
  const double length = std::hypot(toSun[0], toSun[1]);
  toSun[0] /= length;
  toSun[1] /= length;

  int ringDay = 0, ringNight = 0, blueDay = 0, beyondLit = 0, beyond = 0;
  double lumDay = 0, lumNight = 0;
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      const int i = y * W + x;
      if (depth[1][i] < 1.0f)
      {
        continue;
      }
      const double r = std::hypot(x - cx, y - cy);
      const unsigned char* p = &rgb[1][3 * i];
      const double lum = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      if (r > radius * 1.04 + 1.5)
      {
        ++beyond;
        beyondLit += p[0] + p[1] + p[2] > 0;
        continue;
      }
      if (r > radius + 1.5)
      {
        continue; // the glow's fading edge
      }
      const double side = ((x - cx) * toSun[0] + (y - cy) * toSun[1]) / r;
      if (side > 0.5)
      {
        ++ringDay;
        lumDay += lum;
        blueDay += p[2] > p[0] && p[2] > 0;
      }
      else if (side < -0.5)
      {
        ++ringNight;
        lumNight += lum;
      }
    }
  }
  lumDay /= std::max(1, ringDay);
  lumNight /= std::max(1, ringNight);
  check.Expect(ringDay > 20 && ringNight > 20 && blueDay == ringDay && lumDay > 2.0 * lumNight + 1.0,
    vtkGlobeTest::Printf("the ring just outside the disc (radius %.1f px): %d day-side pixels, "
                         "%d of them blue-dominant, mean luminance %.1f; %d night-side pixels, %.1f",
      radius, ringDay, blueDay, lumDay, ringNight, lumNight));
  check.Expect(beyond > 1000 && beyondLit == 0,
    vtkGlobeTest::Printf("%d of %d pixels beyond 1.04 radii are lit", beyondLit, beyond));

  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  return (check.Result() == 0 && image == vtkTesting::PASSED) ? 0 : 1;
}
