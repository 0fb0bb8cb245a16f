// Composition rules on analytic scenes: in-memory layers of constant values on a flat-topped
// planet, so every composed value is known exactly. Heights are reconstructed from depth
// (double) at the view's centre and compared with the expected value and with the C++ mirror
// of the generated GLSL; colours are read from the framebuffer with lighting off (the albedo).
// Covers replace, add, weighted average, opacity, gamma, valid range, NaN voids, draw order,
// disabled layers, hard and feathered borders, and the base that shows where all weights are 0.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeCompositePass.h"
#include "vtkGlobeGridPass.h"
#include "vtkUnsignedCharArray.h"

#include <cstdio>
#include <limits>

namespace
{
vtkSmartPointer<vtkGlobeLayer> Heights(double west, double east, double value, int w = 8, int h = 8)
{
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  std::vector<float> v(static_cast<size_t>(w) * h, static_cast<float>(value));
  layer->SetHeightData(w, h, v.data(), west, east, 0.0, 2.0);
  return layer;
}

vtkSmartPointer<vtkGlobeLayer> Colors(
  double west, double east, unsigned char r, unsigned char g, unsigned char b, unsigned char a = 255)
{
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  std::vector<unsigned char> v;
  for (int i = 0; i < 64; ++i)
  {
    v.insert(v.end(), { r, g, b, a });
  }
  layer->SetColorData(8, 8, 4, v.data(), west, east, -4.0, -2.0);
  layer->SetFeatherWidth(0.0);
  return layer;
}

// Looks almost straight down at (lon, lat) from `altitude`, renders, and returns the height
// reconstructed from depth at the centre pixel, and its colour.
double CentreHeight(vtkGlobeTest::Scene& scene, double lon, double lat, double altitude, double rgb[3])
{
  const double camera[3] = { lon - 0.02, lat, altitude }, target[3] = { lon, lat, 0.0 };
  scene.Look(camera, target, 20.0, 1000.0, 1.0e6);
  scene.Render();
  const int* size = scene.Window->GetSize();
  const int x = size[0] / 2, y = size[1] / 2;
  float depth = 1.0f;
  scene.Window->GetZbufferData(x, y, x, y, &depth);
  unsigned char* pixel = scene.Window->GetPixelData(x, y, x, y, 0);
  for (int i = 0; i < 3; ++i)
  {
    rgb[i] = pixel[i] / 255.0;
  }
  delete[] pixel;
  if (depth >= 1.0f)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double p[3], llh[3];
  vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, depth, p);
  scene.Body->CartesianToGeodetic(p, llh);
  return llh[2];
}
} // namespace

int TestGlobeComposition(int, char*[])
{
  vtkGlobeTest::Checklist check;

  // ---- Heights (grid pass) -------------------------------------------------------------
  {
    vtkGlobeTest::Scene scene;
    auto base = vtkSmartPointer<vtkGlobeLayer>::New();
    std::vector<float> flat(36 * 18, 100.0f);
    base->SetHeightData(36, 18, flat.data(), -180, 180, -90, 90);
    scene.Mapper->AddLayer(base);

    auto below = Heights(0, 2, 7777); // composed first (DrawOrder -1), then covered by `a`
    auto a = Heights(0, 2, 1000);
    auto add = Heights(4, 6, 50);
    auto avg1 = Heights(8, 10, 200);
    auto avg2 = Heights(8, 10, 400);
    auto range = Heights(12, 14, 5000);
    auto half = Heights(16, 18, 300);
    auto off = Heights(20, 22, 9999);
    auto top = Heights(24, 26, 600); // added before `under`, but a higher DrawOrder
    auto under = Heights(24, 26, 800);
    for (auto* l : { a.Get(), add.Get(), avg1.Get(), avg2.Get(), range.Get(), half.Get(),
           off.Get(), top.Get(), under.Get(), below.Get() })
    {
      l->SetFeatherWidth(0.0);
    }
    below->SetDrawOrder(-1);
    add->SetBlendModeToAdd();
    avg1->SetBlendModeToAverage();
    avg2->SetBlendModeToAverage();
    range->SetValidRange(0.0, 1000.0);
    half->SetOpacity(0.5);
    off->EnabledOff();
    top->SetDrawOrder(5);
    // NaN voids (FillVoids off): the west half of the layer is void, so the base shows there.
    auto voids = vtkSmartPointer<vtkGlobeLayer>::New();
    voids->FillVoidsOff();
    std::vector<float> v(8 * 8, 700.0f);
    for (int row = 0; row < 8; ++row)
    {
      for (int col = 0; col < 4; ++col)
      {
        v[row * 8 + col] = std::numeric_limits<float>::quiet_NaN();
      }
    }
    voids->SetHeightData(8, 8, v.data(), 28, 30, 0, 2);
    voids->SetFeatherWidth(0.0);
    for (auto* l : { top.Get(), a.Get(), add.Get(), avg1.Get(), avg2.Get(), range.Get(),
           half.Get(), off.Get(), under.Get(), below.Get(), voids.Get() })
    {
      scene.Mapper->AddLayer(l);
    }

    struct Case
    {
      double Lon;
      double Expected;
      const char* What;
    };
    const Case cases[] = { { 1, 1000, "replace over a lower DrawOrder" }, { 5, 150, "add" },
      { 9, 300, "weighted average" }, { 13, 100, "outside the valid range: the base shows" },
      { 17, 200, "opacity 0.5" }, { 21, 100, "disabled: the base shows" },
      { 25, 600, "DrawOrder beats the order added" }, { 28.5, 100, "NaN voids: the base shows" },
      { 29.5, 700, "valid half of the voided layer" }, { 40, 100, "no inset: the base" } };
    const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
    for (const Case& c : cases)
    {
      double rgb[3];
      const double h = CentreHeight(scene, c.Lon, 1.0, 20000.0, rgb);
      const double mirror = vtkGlobeTest::ComposedHeight(layers, c.Lon, 1.0);
      char what[160];
      std::snprintf(what, sizeof(what), "height %s: %.3f m (expect %.0f, mirror %.3f)", c.What, h,
        c.Expected, mirror);
      check.Expect(std::abs(h - c.Expected) < 0.5 && std::abs(mirror - c.Expected) < 1e-3, what);
    }
    std::printf("  grid-pass height programs built: %d\n",
      scene.Mapper->GetGridPass()->GetNumberOfShaderBuilds());
  }

  // ---- Colours (screen pass), lighting off: the framebuffer holds the albedo ------------
  {
    vtkGlobeTest::Scene scene;
    scene.Mapper->LightingOff();
    scene.Mapper->SetBaseColor(0.2, 0.3, 0.4);
    auto replace = Colors(0, 2, 255, 0, 0);
    auto add = Colors(4, 6, 26, 26, 26);
    auto avg1 = Colors(8, 10, 255, 0, 0);
    auto avg2 = Colors(8, 10, 0, 0, 255);
    auto gamma = Colors(12, 14, 128, 128, 128);
    auto half = Colors(16, 18, 255, 255, 255);
    auto clear = Colors(20, 22, 255, 0, 255, 0); // alpha 0: not covered
    add->SetBlendModeToAdd();
    avg1->SetBlendModeToAverage();
    avg2->SetBlendModeToAverage();
    gamma->SetGamma(2.0);
    half->SetOpacity(0.5);
    for (auto* l :
      { replace.Get(), add.Get(), avg1.Get(), avg2.Get(), gamma.Get(), half.Get(), clear.Get() })
    {
      scene.Mapper->AddLayer(l);
    }
    const double g = std::pow(128.0 / 255.0, 2.0);
    struct Case
    {
      double Lon;
      double Rgb[3];
      const char* What;
    };
    const Case cases[] = { { 1, { 1, 0, 0 }, "replace" },
      { 5, { 0.2 + 26 / 255.0, 0.3 + 26 / 255.0, 0.4 + 26 / 255.0 }, "add" },
      { 9, { 0.5, 0, 0.5 }, "weighted average" }, { 13, { g, g, g }, "gamma 2" },
      { 17, { 0.6, 0.65, 0.7 }, "opacity 0.5" }, { 21, { 0.2, 0.3, 0.4 }, "alpha 0: base" },
      { 40, { 0.2, 0.3, 0.4 }, "no layer: base" } };
    for (const Case& c : cases)
    {
      double rgb[3];
      CentreHeight(scene, c.Lon, -3.0, 20000.0, rgb);
      double worst = 0;
      for (int i = 0; i < 3; ++i)
      {
        worst = std::max(worst, std::abs(rgb[i] - c.Rgb[i]));
      }
      char what[160];
      std::snprintf(what, sizeof(what), "colour %s: (%.3f %.3f %.3f), worst %.4f", c.What, rgb[0],
        rgb[1], rgb[2], worst);
      check.Expect(worst <= 2.5 / 255.0, what);
    }

    // Feathered border: across the west edge of an 8 x 8 texel inset (0.25 deg/texel) the
    // colour ramps over FeatherWidth texels; with no feather it steps within a texel.
    for (double feather : { 0.0, 4.0 })
    {
      replace->SetFeatherWidth(feather);
      double rgb[3];
      // Half a texel inside: weight 0.5 / feather of the way (hard: fully red).
      CentreHeight(scene, 0.125, -3.0, 20000.0, rgb);
      const double weight = feather > 0 ? 0.5 / feather : 1.0;
      const double expected = 0.2 + (1.0 - 0.2) * weight;
      char what[160];
      std::snprintf(what, sizeof(what), "feather %.0f texels: red %.3f half a texel in (expect %.3f)",
        feather, rgb[0], expected);
      check.Expect(std::abs(rgb[0] - expected) < 0.02, what);
    }
  }
  return check.Result();
}
