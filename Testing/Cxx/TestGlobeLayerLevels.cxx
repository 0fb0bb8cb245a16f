// The MIP pyramid whole-raster layers are filtered with (vtkGlobeLayer::GetLevelData;
// Documentation/composition.md "Filtering to the footprint") and its CPU mirror
// (vtkGlobeTerrain::GetFilteredHeight):
// A. each texel of an odd-sized level is the mean of the finer level over the texel's own area
//    (checked against the same mean integrated exactly by the midpoint rule),
//    voids left out, a texel of voids only a void; sizes as OpenGL's mipmaps;
// B. colour levels average each component, rounded;
// C. GetFilteredHeight takes the level the GPU's rules give: the pixel rule the longer axis, the
//    grid rule the shorter one within 16:1; trilinear between levels; a zero footprint is
//    GetHeight.
#include "vtkGlobeTestHelpers.h"

#include "vtkFloatArray.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeTerrain.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
// The mean of level-0 posts (w x h, row 0 north) over [x0, x1) x [y0, y1) in level-0 texels,
// voids left out, by the midpoint rule on 700 x 700 points: exact here, since a texel of
// level 1 spans 7/3 x 5/2 level-0 texels and the points' spacing (1/300, 1/280) divides one.
double BruteMean(const std::vector<float>& v, int w, double x0, double x1, double y0, double y1)
{
  const int n = 700;
  double sum = 0.0;
  int count = 0;
  for (int b = 0; b < n; ++b)
  {
    for (int a = 0; a < n; ++a)
    {
      const double x = x0 + (a + 0.5) * (x1 - x0) / n, y = y0 + (b + 0.5) * (y1 - y0) / n;
      const float value = v[static_cast<size_t>(std::floor(y)) * w + static_cast<int>(std::floor(x))];
      if (!std::isnan(value))
      {
        sum += value;
        ++count;
      }
    }
  }
  return count ? sum / count : std::nan("");
}
} // namespace

int TestGlobeLayerLevels(int, char*[])
{
  vtkGlobeTest::Checklist check;
  char what[300];

  // A. 7 x 5 heights, a void at (1, 0) and a 2 x 2 block of voids in the south-east corner.
  const int w = 7, h = 5;
  std::vector<float> v(static_cast<size_t>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      v[static_cast<size_t>(j) * w + i] = static_cast<float>(100.0 * i + 7.0 * j * j);
    }
  }
  const float nan = std::nanf("");
  v[1] = nan;
  for (int j = 3; j < 5; ++j)
  {
    for (int i = 5; i < 7; ++i)
    {
      v[static_cast<size_t>(j) * w + i] = nan;
    }
  }
  vtkNew<vtkGlobeLayer> layer;
  layer->FillVoidsOff();
  layer->SetHeightData(w, h, v.data(), -10.0, 4.0, 40.0, 50.0);
  layer->Update();
  check.Expect(layer->GetNumberOfLevels() == 3, "7 x 5 has 3 levels (7, 3, 1 columns)");
  int size1[2], size2[2];
  layer->GetLevelDimensions(1, size1);
  layer->GetLevelDimensions(2, size2);
  check.Expect(size1[0] == 3 && size1[1] == 2 && size2[0] == 1 && size2[1] == 1,
    "level sizes as OpenGL's: 3 x 2, then 1 x 1");
  auto* level1 = vtkFloatArray::SafeDownCast(layer->GetLevelData(1));
  double worst = 0.0;
  bool voids = true;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      const double rx = 7.0 / 3.0, ry = 5.0 / 2.0;
      const double want = BruteMean(v, w, i * rx, (i + 1) * rx, j * ry, (j + 1) * ry);
      const double got = level1 ? level1->GetValue(j * 3 + i) : std::nan("");
      if (std::isnan(want))
      {
        voids &= std::isnan(got);
      }
      else
      {
        worst = std::max(worst, std::abs(got - want));
      }
    }
  }
  std::snprintf(what, sizeof(what),
    "level 1: each texel the area mean of level 0 without its voids (worst |difference| from "
    "the exact mean: %.2g)", worst);
  check.Expect(level1 && worst < 1e-3, what);
  auto* level2 = vtkFloatArray::SafeDownCast(layer->GetLevelData(2));
  double want2 = 0.0, weight2 = 0.0;
  for (int k = 0; k < 6; ++k)
  {
    if (level1 && !std::isnan(level1->GetValue(k)))
    {
      want2 += level1->GetValue(k);
      weight2 += 1.0;
    }
  }
  want2 /= weight2;
  check.Expect(level2 && std::abs(level2->GetValue(0) - want2) < 1e-3,
    "level 2: the area mean of level 1's valid texels");
  check.Expect(!layer->GetLevelData(3) && !layer->GetLevelData(-1), "no level beyond the pyramid");

  // Voids only: a level-1 texel over voids alone is a void.
  std::vector<float> holes(4 * 2, nan);
  holes[0] = 5.0f;
  vtkNew<vtkGlobeLayer> sparse;
  sparse->FillVoidsOff();
  sparse->SetHeightData(4, 2, holes.data(), 0.0, 4.0, 0.0, 2.0);
  sparse->Update();
  auto* sparse1 = vtkFloatArray::SafeDownCast(sparse->GetLevelData(1));
  check.Expect(sparse1 && sparse1->GetValue(0) == 5.0f && std::isnan(sparse1->GetValue(1)),
    "voids stay out of the means, and a texel of voids only is a void");

  // B. Colour: 3 x 1 RGBA to 1 x 1, each component the mean of three, rounded.
  const unsigned char rgba[12] = { 10, 200, 0, 255, 20, 100, 1, 255, 31, 0, 1, 0 };
  vtkNew<vtkGlobeLayer> colour;
  colour->SetColorData(3, 1, 4, rgba, 0.0, 3.0, 0.0, 1.0);
  colour->Update();
  auto* c1 = vtkUnsignedCharArray::SafeDownCast(colour->GetLevelData(1));
  check.Expect(c1 && c1->GetValue(0) == 20 && c1->GetValue(1) == 100 && c1->GetValue(2) == 1 &&
      c1->GetValue(3) == 170,
    "colour level 1: (20.3, 100, 0.7, 170) rounded");

  // C. GetFilteredHeight on a global 256 x 128 layer of a smooth function.
  const int gw = 256, gh = 128;
  std::vector<float> g(static_cast<size_t>(gw) * gh);
  for (int j = 0; j < gh; ++j)
  {
    for (int i = 0; i < gw; ++i)
    {
      g[static_cast<size_t>(j) * gw + i] = static_cast<float>(1000.0 * std::sin(0.3 * i) + 50.0 * j);
    }
  }
  vtkNew<vtkGlobeLayer> global;
  global->SetHeightData(gw, gh, g.data(), -180.0, 180.0, -90.0, 90.0);
  vtkNew<vtkGlobeTerrain> terrain;
  terrain->AddLayer(global);
  terrain->Update();
  // Bilinear in a level, as the GPU samples it (texel centres at (k + 0.5) / size).
  auto bilinear = [&](int level, double lon, double lat) {
    int s[2];
    global->GetLevelDimensions(level, s);
    auto* data = vtkFloatArray::SafeDownCast(global->GetLevelData(level));
    const double x = (lon + 180.0) / 360.0 * s[0] - 0.5, y = (90.0 - lat) / 180.0 * s[1] - 0.5;
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    const double fx = x - i, fy = y - j;
    auto at = [&](int a, int b) {
      a = ((a % s[0]) + s[0]) % s[0];
      b = std::max(0, std::min(b, s[1] - 1));
      return static_cast<double>(data->GetValue(b * s[0] + a));
    };
    return (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) + fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
  };
  const double lon = 12.3, lat = 20.7, texel = 360.0 / gw; // 1.40625 degrees either way
  const double zero[4] = { 0, 0, 0, 0 };
  check.Expect(terrain->GetFilteredHeight(lon, lat, zero) == terrain->GetHeight(lon, lat),
    "a zero footprint gives GetHeight");
  // Two texels east per step along x, half a texel north per step along y.
  const double footprint[4] = { 2.0 * texel, 0.0, 0.0, 0.5 * texel };
  const double pixel = terrain->GetFilteredHeight(lon, lat, footprint, vtkGlobeTerrain::PixelFootprint);
  const double grid = terrain->GetFilteredHeight(lon, lat, footprint, vtkGlobeTerrain::GridFootprint);
  std::snprintf(what, sizeof(what),
    "pixel rule: the longer axis (2 texels, level 1): %.4f against level 1's %.4f", pixel, bilinear(1, lon, lat));
  check.Expect(std::abs(pixel - bilinear(1, lon, lat)) < 1e-6, what);
  std::snprintf(what, sizeof(what),
    "grid rule: the shorter axis within 16:1 (0.5 texel, level 0): %.4f against level 0's %.4f", grid, bilinear(0, lon, lat));
  check.Expect(std::abs(grid - bilinear(0, lon, lat)) < 1e-6, what);
  // 3 texels: level log2(3) = 1.585, between levels 1 and 2.
  const double three[4] = { 3.0 * texel, 0.0, 0.0, 3.0 * texel };
  const double f = std::log2(3.0) - 1.0;
  const double want = (1 - f) * bilinear(1, lon, lat) + f * bilinear(2, lon, lat);
  const double got = terrain->GetFilteredHeight(lon, lat, three, vtkGlobeTerrain::PixelFootprint);
  std::snprintf(what, sizeof(what), "3 texels: trilinear at level 1.585: %.4f against %.4f", got, want);
  check.Expect(std::abs(got - want) < 1e-6, what);
  return check.Result();
}
