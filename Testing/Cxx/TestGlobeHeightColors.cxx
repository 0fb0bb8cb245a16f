// Heights in colour (issue "Pictures a user would be proud of"): a vtkColorTransferFunction
// hypsometric tint on the 2-degree relief, unlit, seen whole. Every covered pixel away from the
// limb shows the map's colour at the composed height of its own (lon, lat) (CPU, double), within
// 8-bit rounding plus how much the map changes over the pixel; a map with opacity 0.5 over the
// Blue Marble gives the mean of the two pictures; without a map the composition shader has no
// height-colour code and the picture is the plain one; changing the map re-samples it.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkColorTransferFunction.h"
#include "vtkGlobeCompositePass.h"

#include <algorithm>
#include <cstdio>

namespace
{
vtkGlobeTest::Checklist Checks;
using vtkGlobeTest::Printf;

struct Comparison
{
  int Pixels = 0, Within = 0;
  double Median = 0.0, Worst = 0.0;
};

// Each covered pixel whose neighbours are covered too (away from the limb) against `expected`
// (0..1 RGB at the pixel's composed height, filtered to its footprint); tolerance: 1.5/255 plus half the spread of the
// expected colour over the pixel and its 4 neighbours' heights.
template <typename Expected>
Comparison Compare(vtkGlobeTest::Scene& scene, const std::vector<unsigned char>& rgb,
  const std::vector<vtkGlobeLayer*>& layers, Expected expected)
{
  const int* size = scene.Window->GetSize();
  const auto llh = vtkGlobeTest::GeodeticPixels(scene);
  // The heights the screen pass composes: filtered to each pixel's footprint.
  const std::vector<double> height = vtkGlobeTest::PixelHeights(scene, layers, llh);
  Comparison c;
  std::vector<double> diffs;
  for (int y = 1; y + 1 < size[1]; ++y)
  {
    for (int x = 1; x + 1 < size[0]; ++x)
    {
      const size_t i = static_cast<size_t>(y) * size[0] + x;
      const size_t around[4] = { i - 1, i + 1, i - size[0], i + size[0] };
      bool inside = !std::isnan(height[i]);
      for (size_t j : around)
      {
        inside = inside && !std::isnan(height[j]);
      }
      if (!inside)
      {
        continue;
      }
      const std::array<double, 3> want = expected(height[i], i);
      double spread = 0.0;
      for (size_t j : around)
      {
        const std::array<double, 3> there = expected(height[j], i);
        for (int k = 0; k < 3; ++k)
        {
          spread = std::max(spread, std::abs(there[k] - want[k]));
        }
      }
      double diff = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        diff = std::max(diff, std::abs(rgb[3 * i + k] / 255.0 - want[k]));
      }
      ++c.Pixels;
      c.Within += diff <= 1.5 / 255.0 + 0.5 * spread ? 1 : 0;
      c.Worst = std::max(c.Worst, diff);
      diffs.push_back(diff);
    }
  }
  if (!diffs.empty())
  {
    std::nth_element(diffs.begin(), diffs.begin() + diffs.size() / 2, diffs.end());
    c.Median = diffs[diffs.size() / 2];
  }
  return c;
}
} // namespace

int TestGlobeHeightColors(int, char*[])
{
  vtkGlobeTest::Scene scene(200, 150, 128);
  scene.Mapper->LightingOff();
  auto relief = vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true);
  scene.Mapper->AddLayer(relief);
  const std::vector<vtkGlobeLayer*> layers = { relief };
  const double camera[3] = { 80.0, 20.0, 2.0e7 }, target[3] = { 80.0, 20.0, 0.0 };
  scene.Look(camera, target, 30.0);
  scene.Render();
  vtkGlobeCompositePass* composite = scene.Mapper->GetCompositePass();
  const std::vector<unsigned char> plain = vtkGlobeTest::ReadPixels(scene.Window);
  Checks.Expect(composite->GetFragmentShaderSource().find("globeHeightColors") == std::string::npos,
    "no height-colour code without a map");

  vtkNew<vtkColorTransferFunction> tint;
  tint->AddRGBPoint(-8000.0, 0.0, 0.0, 0.3);
  tint->AddRGBPoint(-200.0, 0.3, 0.6, 0.9);
  tint->AddRGBPoint(0.0, 0.1, 0.45, 0.15);
  tint->AddRGBPoint(1500.0, 0.85, 0.75, 0.35);
  tint->AddRGBPoint(4000.0, 0.55, 0.35, 0.25);
  tint->AddRGBPoint(6500.0, 1.0, 1.0, 1.0);
  composite->SetHeightColors(tint);
  scene.Render();
  auto colour = [&](double h, size_t) {
    double rgb[3];
    tint->GetColor(h, rgb);
    return std::array<double, 3>{ rgb[0], rgb[1], rgb[2] };
  };
  const std::vector<unsigned char> tinted = vtkGlobeTest::ReadPixels(scene.Window);
  const Comparison full = Compare(scene, tinted, layers, colour);
  std::printf("  tint alone: %d of %d pixels within 1.5/255 + half the map's spread over the "
              "pixel, median |diff| %.2f/255, worst %.1f/255\n",
    full.Within, full.Pixels, 255 * full.Median, 255 * full.Worst);
  Checks.Expect(full.Pixels > 10000, "the globe covers the view");
  Checks.Expect(full.Within >= 0.995 * full.Pixels && full.Median <= 1.0 / 255.0,
    "each pixel shows the map's colour at its composed height");

  // Heights beyond the map's range take its end colours (the Himalaya above 6,500 m is white;
  // the ocean floor below -8,000 m dark blue) and the map's changes are picked up.
  tint->AddRGBPoint(6500.0, 1.0, 0.0, 1.0);
  scene.Render();
  const std::vector<unsigned char> changed = vtkGlobeTest::ReadPixels(scene.Window);
  const Comparison after = Compare(scene, changed, layers, colour);
  Checks.Expect(after.Within >= 0.995 * after.Pixels,
    Printf("a changed map is sampled again (%d of %d pixels within)", after.Within, after.Pixels));

  // Half opacity over imagery: the mean of the imagery alone and the tint alone.
  auto world = vtkGlobeTest::FileLayer("earth/world.tif", false);
  scene.Mapper->AddLayer(world);
  composite->SetHeightColors(nullptr);
  scene.Render();
  const std::vector<unsigned char> imagery = vtkGlobeTest::ReadPixels(scene.Window);
  composite->SetHeightColors(tint);
  composite->SetHeightColorOpacity(0.5);
  scene.Render();
  const std::vector<unsigned char> half = vtkGlobeTest::ReadPixels(scene.Window);
  const Comparison mean = Compare(scene, half, layers, [&](double h, size_t i) {
    std::array<double, 3> c = colour(h, i);
    for (int k = 0; k < 3; ++k)
    {
      c[k] = 0.5 * c[k] + 0.5 * imagery[3 * i + k] / 255.0;
    }
    return c;
  });
  std::printf("  half opacity over imagery: %d of %d pixels within, median |diff| %.2f/255\n",
    mean.Within, mean.Pixels, 255 * mean.Median);
  Checks.Expect(mean.Within >= 0.99 * mean.Pixels,
    "opacity 0.5 gives the mean of the imagery and the tint");

  // Off again: the shader loses the code and the plain picture (imagery) comes back exactly.
  composite->SetHeightColors(nullptr);
  scene.Render();
  Checks.Expect(vtkGlobeTest::ReadPixels(scene.Window) == imagery &&
      composite->GetFragmentShaderSource().find("globeHeightColors") == std::string::npos,
    "without a map the picture is the imagery's, pixel for pixel");
  Checks.Expect(plain != tinted, "the tint changed the picture");
  Checks.Expect(vtkGlobeTest::NoGLError(), "no OpenGL error");
  return Checks.Result();
}
