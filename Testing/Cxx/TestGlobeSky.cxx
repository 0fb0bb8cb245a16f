// The sky from the ground (issue "Pictures": "from the ground and from low altitude, the sky
// and aerial perspective come from the atmosphere effect"), in the demo's Rainier view: 3 km
// up, 25 km from the summit, the sun at azimuth 150 and 35 degrees up, the relief tinted by
// height (a vtkColorTransferFunction at opacity 0.55 over the imagery). Rendered without and
// with the atmosphere, otherwise identical (300 x 225):
//  - without it, every pixel the terrain leaves uncovered is the black background; with it,
//    every one is sky, blue-dominant (B > R);
//  - the sky is brighter and less saturated towards the horizon than towards the zenith
//    (Rayleigh scattering along a longer path), as the physical sky is;
//  - aerial perspective: the atmosphere changes distant terrain more than near terrain (the
//    farthest quarter of the terrain pixels by eye distance against the nearest quarter), and
//    moves it towards the colour of the sky at the horizon.
// The picture with the atmosphere is the regression baseline: the sky from the ground over a
// hypsometric tint (the atmosphere from space is TestGlobeLimb's).
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkColorTransferFunction.h"
#include "vtkGlobeCompositePass.h"
#include "vtkLight.h"
#include "vtkRegressionTestImage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

int TestGlobeSky(int argc, char* argv[])
{
  vtkGlobeTest::Checklist check;
  constexpr int W = 300, H = 225;
  vtkGlobeTest::Scene scene(W, H, 256);
  scene.AddEarthLayers(true, true);
  // The sun over the target: azimuth 150 degrees from north, 35 degrees up.
  const double camera[3] = { -121.97, 46.70, 3000.0 }, target[3] = { -121.7603, 46.8523, 3600.0 };
  {
    double t[3], east[3], north[3], up[3], position[3];
    scene.Body->GeodeticToCartesian(target, t);
    scene.Body->ComputeEastNorthUp(target[0], target[1], east, north, up);
    const double a = vtkMath::RadiansFromDegrees(150.0), e = vtkMath::RadiansFromDegrees(35.0);
    for (int i = 0; i < 3; ++i)
    {
      position[i] = t[i] + 1.0e7 * (std::cos(e) * (std::sin(a) * east[i] + std::cos(a) * north[i]) + std::sin(e) * up[i]);
    }
    vtkNew<vtkLight> sun;
    sun->SetPosition(position);
    sun->SetFocalPoint(t);
    sun->SetLightTypeToSceneLight();
    scene.Renderer->AddLight(sun);
  }
  vtkNew<vtkColorTransferFunction> tint;
  tint->AddRGBPoint(0.0, 0.12, 0.42, 0.20);
  tint->AddRGBPoint(1500.0, 0.85, 0.78, 0.45);
  tint->AddRGBPoint(2100.0, 0.62, 0.42, 0.25);
  tint->AddRGBPoint(3300.0, 0.95, 0.95, 0.95);
  scene.Mapper->GetCompositePass()->SetHeightColors(tint);
  scene.Mapper->GetCompositePass()->SetHeightColorOpacity(0.55);
  scene.Look(camera, target, 45.0, 10.0, 1.0e6);

  std::vector<unsigned char> rgb[2];
  std::vector<float> depth[2];
  vtkGlobeTest::RenderWithoutAndWithAtmosphere(scene, rgb, depth);
  check.Expect(depth[0] == depth[1], "the atmosphere changes no depth");
  auto luminance = [](const unsigned char* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };

  // The sky.
  int sky = 0, blackWithout = 0, blue = 0;
  for (int i = 0; i < W * H; ++i)
  {
    if (depth[1][i] < 1.0f)
    {
      continue;
    }
    ++sky;
    const unsigned char* off = &rgb[0][3 * i];
    const unsigned char* p = &rgb[1][3 * i];
    blackWithout += off[0] == 0 && off[1] == 0 && off[2] == 0;
    blue += p[2] > p[0];
  }
  check.Expect(sky > W * H / 10 && blackWithout == sky && blue == sky,
    vtkGlobeTest::Printf("%d sky pixels: %d black without the atmosphere, %d blue-dominant with it",
      sky, blackWithout, blue));

  // Horizon against zenith: the 8 sky pixels above the terrain's top in each column, and the
  // top 8 rows of the window.
  double horizonL = 0, horizonS = 0, topL = 0, topS = 0;
  int horizonN = 0, topN = 0;
  double horizonRGB[3] = { 0, 0, 0 };
  auto saturation = [](const unsigned char* p) {
    const double hi = std::max({ p[0], p[1], p[2] }), lo = std::min({ p[0], p[1], p[2] });
    return hi > 0 ? (hi - lo) / hi : 0.0;
  };
  for (int x = 0; x < W; ++x)
  {
    int top = -1;
    for (int y = H - 1; y >= 0; --y)
    {
      if (depth[1][y * W + x] < 1.0f)
      {
        top = y;
        break;
      }
    }
    for (int y = top + 2; y < std::min(H - 8, top + 10); ++y)
    {
      const unsigned char* p = &rgb[1][3 * (y * W + x)];
      horizonL += luminance(p);
      horizonS += saturation(p);
      for (int c = 0; c < 3; ++c)
      {
        horizonRGB[c] += p[c];
      }
      ++horizonN;
    }
    for (int y = H - 8; y < H; ++y)
    {
      if (depth[1][y * W + x] >= 1.0f)
      {
        const unsigned char* p = &rgb[1][3 * (y * W + x)];
        topL += luminance(p);
        topS += saturation(p);
        ++topN;
      }
    }
  }
  const bool measured = horizonN > 100 && topN > 100;
  if (measured)
  {
    horizonL /= horizonN;
    horizonS /= horizonN;
    topL /= topN;
    topS /= topN;
    for (double& c : horizonRGB)
    {
      c /= horizonN;
    }
  }
  check.Expect(measured && horizonL > topL && horizonS < topS,
    vtkGlobeTest::Printf("sky at the horizon (%d px): luminance %.1f, saturation %.3f; towards "
                         "the zenith (%d px): %.1f, %.3f",
      horizonN, horizonL, horizonS, topN, topL, topS));

  // Aerial perspective: eye distance of each terrain pixel from its depth.
  std::vector<std::pair<double, int>> terrain;
  const double* eye = scene.Renderer->GetActiveCamera()->GetPosition();
  for (int y = 0; y < H; y += 2)
  {
    for (int x = 0; x < W; x += 2)
    {
      const int i = y * W + x;
      if (depth[1][i] >= 1.0f)
      {
        continue;
      }
      double world[3];
      vtkGlobeTest::UnprojectPixel(scene.Renderer, x, y, depth[1][i], world);
      terrain.emplace_back(std::sqrt(vtkMath::Distance2BetweenPoints(world, eye)), i);
    }
  }
  std::sort(terrain.begin(), terrain.end());
  const size_t quarter = terrain.size() / 4;
  auto change = [&](size_t from, size_t to, double& toHorizonOff, double& toHorizonOn) {
    double sum = 0.0;
    toHorizonOff = toHorizonOn = 0.0;
    for (size_t k = from; k < to; ++k)
    {
      const int i = terrain[k].second;
      for (int c = 0; c < 3; ++c)
      {
        sum += std::abs(rgb[1][3 * i + c] - rgb[0][3 * i + c]);
        toHorizonOff += std::abs(rgb[0][3 * i + c] - horizonRGB[c]);
        toHorizonOn += std::abs(rgb[1][3 * i + c] - horizonRGB[c]);
      }
    }
    const double n = static_cast<double>(std::max<size_t>(1, to - from));
    toHorizonOff /= n;
    toHorizonOn /= n;
    return sum / n;
  };
  double nearOff, nearOn, farOff, farOn;
  const double nearChange = change(0, quarter, nearOff, nearOn);
  const double farChange = change(terrain.size() - quarter, terrain.size(), farOff, farOn);
  check.Expect(quarter > 500 && farChange > 2.0 * nearChange && farOn < farOff,
    vtkGlobeTest::Printf("aerial perspective: the atmosphere changes the nearest quarter of the "
                         "terrain (%.1f-%.1f km) by %.1f and the farthest (%.1f-%.1f km) by %.1f "
                         "(RGB sum, 0-765); the farthest's distance to the horizon's sky %.1f "
                         "without, %.1f with",
      terrain.front().first / 1000.0, terrain[quarter].first / 1000.0, nearChange,
      terrain[terrain.size() - quarter].first / 1000.0, terrain.back().first / 1000.0, farChange,
      farOff, farOn));

  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  (void)argc;
  (void)argv;
  return (check.Result() == 0 && image == vtkTesting::PASSED) ? 0 : 1;
}
