// Colour match of an imagery inset to the base (issue 14, "insets without walls": "colour
// insets get an optional colour match to the base ... so an aerial photo does not show as a
// rectangle"). The Boston aerial inset (0.0018 deg/px) over the Blue Marble, unlit, rendered
// without and with vtkGlobeLayer::ColorMatch. Measured on the rendered pixels, each placed on
// the inset by its depth-reconstructed position: the colour step across the border (the mean
// colour just inside the feather, 8-12 texels in, against the base just outside, 0-4 texels
// out) falls by more than half; pixels deeper inside than ColorMatchWidth (64 texels) plus a
// margin do not change at all; the program is rebuilt once and nothing is uploaded.
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include <cstdio>
#include <cstring>

int TestGlobeColorMatch(int, char*[])
{
  vtkGlobeTest::Checklist check;
  vtkGlobeTest::Scene scene(400, 300, 256);
  scene.Mapper->LightingOff();
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/world.tif", false));
  auto boston = vtkGlobeTest::FileLayer("earth/boston-inset-wgs84.tif", false);
  scene.Mapper->AddLayer(boston);
  const double camera[3] = { -71.02, 41.90, 140000.0 }, target[3] = { -71.07, 42.33, 0.0 };
  scene.Look(camera, target, 40.0, 1000.0, 1.0e6);

  struct Band
  {
    double Sum[3] = { 0, 0, 0 };
    int N = 0;
    void Add(const unsigned char* p)
    {
      for (int k = 0; k < 3; ++k)
      {
        this->Sum[k] += p[k];
      }
      ++this->N;
    }
    double Mean(int k) const { return this->Sum[k] / std::max(1, this->N); }
  };
  double e[4];
  std::vector<unsigned char> pixels[2];
  std::vector<std::array<double, 3>> where;
  int uploads[2] = { 0, 0 }, builds[2] = { 0, 0 };
  for (int on = 0; on < 2; ++on)
  {
    boston->SetColorMatch(on == 1);
    const int u0 = scene.Mapper->GetLayerSet()->GetNumberOfUploads();
    const int b0 = scene.Mapper->GetCompositePass()->GetNumberOfShaderBuilds();
    scene.Render();
    uploads[on] = scene.Mapper->GetLayerSet()->GetNumberOfUploads() - u0;
    builds[on] = scene.Mapper->GetCompositePass()->GetNumberOfShaderBuilds() - b0;
    pixels[on] = vtkGlobeTest::ReadPixels(scene.Window);
    if (on == 0)
    {
      where = vtkGlobeTest::GeodeticPixels(scene);
    }
  }
  boston->GetGeographicExtent(e);
  const int cols = boston->GetNumberOfColumns(), rows = boston->GetNumberOfRows();
  Band inside[2], outside[2];
  int deep = 0, deepChanged = 0;
  for (size_t i = 0; i < where.size(); ++i)
  {
    if (!std::isfinite(where[i][0]))
    {
      continue;
    }
    const double u = (where[i][0] - e[0]) / (e[1] - e[0]) * cols;
    const double v = (e[3] - where[i][1]) / (e[3] - e[2]) * rows;
    // Signed distance to the border in texels: positive inside.
    const double dx = std::min(u, cols - u), dy = std::min(v, rows - v);
    double d = std::min(dx, dy);
    if (d < 0.0)
    {
      d = -std::sqrt(std::pow(std::min(0.0, dx), 2) + std::pow(std::min(0.0, dy), 2));
    }
    for (int on = 0; on < 2; ++on)
    {
      const unsigned char* p = &pixels[on][3 * i];
      if (d > 8.0 && d <= 12.0)
      {
        inside[on].Add(p);
      }
      else if (d < 0.0 && d >= -4.0)
      {
        outside[on].Add(p);
      }
    }
    if (d > 64.0 + 4.0)
    {
      ++deep;
      deepChanged += std::memcmp(&pixels[0][3 * i], &pixels[1][3 * i], 3) != 0 ? 1 : 0;
    }
  }
  double step[2] = { 0, 0 };
  for (int on = 0; on < 2; ++on)
  {
    for (int k = 0; k < 3; ++k)
    {
      step[on] += std::pow(inside[on].Mean(k) - outside[on].Mean(k), 2);
    }
    step[on] = std::sqrt(step[on]);
    std::printf("%s: mean colour 8-12 texels inside (%d px) %.1f %.1f %.1f, 0-4 outside (%d px) "
                "%.1f %.1f %.1f: step %.1f\n",
      on ? "matched" : "plain", inside[on].N, inside[on].Mean(0), inside[on].Mean(1),
      inside[on].Mean(2), outside[on].N, outside[on].Mean(0), outside[on].Mean(1),
      outside[on].Mean(2), step[on]);
  }
  check.Expect(inside[0].N > 50 && outside[0].N > 50 && step[1] < 0.5 * step[0],
    vtkGlobeTest::Printf("the colour step across the border falls from %.1f to %.1f (%.1fx)",
      step[0], step[1], step[0] / std::max(step[1], 1e-9)));
  check.Expect(deep > 1000 && deepChanged == 0,
    vtkGlobeTest::Printf("%d of %d pixels deeper than 68 texels changed", deepChanged, deep));
  check.Expect(uploads[1] == 0 && builds[1] == 1,
    vtkGlobeTest::Printf("turning it on: %d uploads, %d composite program build", uploads[1],
      builds[1]));
  return check.Result();
}
