// Insets without walls (issue "Pictures", done means: "at the edges of the Rainier and Everest
// insets, the steepest rendered slope across the border is no steeper than the data's own
// steepest slope nearby"). Each of the eight borders of the two SRTM insets of Data/earth is
// seen straight down from 45 km (240 x 240 px, about 85 m per pixel, the insets' 90 m texels):
// the rendered surface comes from the G-buffer (each pixel's ground point and the mesh's
// height there), and the slope between neighbouring pixels across the border is measured in a
// band 7 km either side of it. The data's own steepest slope nearby is that of the inset's
// texels along the same axis, within 10 km inside the border and along the stretch in view.
//  - The default, an automatic skirt (vtkGlobeLayer::SkirtDistance, 5 km outside these
//    insets): every border's rendered slope is at most the data's, and the insets keep all
//    their data (Everest's summit, 1.35 km inside the north border, keeps its height).
//  - The previous default, 8 texels of feather inside the border: the 2-degree base and the
//    insets disagree by up to 5.4 km (Everest's north border: the Tibetan plateau against the
//    base's mean), and the measure shows walls, so the check can fail.
//  - FeatherDistance 20 km inside: no walls either, but the summit is blended away.
#include "vtkGlobeMapperTesting.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeTerrain.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
constexpr int Size = 240;
constexpr int Configurations = 3;

// 0: the default (automatic skirt); 1: the previous default (8 texels of feather inside);
// 2: FeatherDistance 20 km inside.
void Configure(vtkGlobeLayer* inset, int configuration)
{
  inset->SetSkirtDistance(configuration == 0 ? vtkGlobeLayer::AutomaticSkirt : 0.0);
  inset->SetFeatherWidth(8.0);
  inset->SetFeatherDistance(configuration == 2 ? 20000.0 : 0.0);
}


struct Edge
{
  const char* Name;
  bool EastWest; // the border runs north-south: profiles go east-west
  bool Low;      // the west or south border
};
const Edge Edges[4] = { { "west", true, true }, { "east", true, false }, { "south", false, true },
  { "north", false, false } };

// The inset's texel-to-texel slope along the profiles' axis, within 10 km inside the border
// and `along` metres either side of its middle (the data at texel centres, through a terrain
// whose inset has a hard edge, so inside it the values are the texels').
double DataSlope(vtkGlobeTerrain* data, const double e[4], int cols, int rows, const Edge& edge,
  double along)
{
  const double dx = (e[1] - e[0]) / cols, dy = (e[3] - e[2]) / rows;
  double parallel, meridian;
  vtkGlobeTest::WGS84Radii(0.5 * (e[2] + e[3]), parallel, meridian);
  const double stepAcross = edge.EastWest ? vtkMath::RadiansFromDegrees(dx) * parallel
                                          : vtkMath::RadiansFromDegrees(dy) * meridian;
  const double stepAlong = edge.EastWest ? vtkMath::RadiansFromDegrees(dy) * meridian
                                         : vtkMath::RadiansFromDegrees(dx) * parallel;
  const int across = static_cast<int>(10000.0 / stepAcross), half = static_cast<int>(along / stepAlong);
  const int n = edge.EastWest ? cols : rows, m = edge.EastWest ? rows : cols;
  double worst = 0.0;
  for (int j = m / 2 - half; j <= m / 2 + half; ++j)
  {
    double previous = 0.0;
    for (int k = 0; k <= across; ++k)
    {
      // Texel index across, from the border inwards (columns count from the west, rows from
      // the north).
      const int i = edge.Low == edge.EastWest ? k : n - 1 - k;
      const double lon = e[0] + ((edge.EastWest ? i : j) + 0.5) * dx;
      const double lat = e[3] - ((edge.EastWest ? j : i) + 0.5) * dy;
      const double h = data->GetHeight(lon, lat);
      if (k > 0 && std::isfinite(h) && std::isfinite(previous))
      {
        worst = std::max(worst, std::abs(h - previous) / stepAcross);
      }
      previous = h;
    }
  }
  return worst;
}
} // namespace

int TestGlobeInsetWalls(int, char*[])
{
  vtkGlobeTest::Checklist check;
  vtkGlobeTest::Scene scene(Size, Size, 512);
  scene.AddEarthLayers(true, false);
  int walls[Configurations] = { 0, 0, 0 }; // borders steeper than the data, per configuration
  for (int insetIndex : { 1, 2 })
  {
    vtkGlobeLayer* inset = scene.Mapper->GetLayer(insetIndex);
    inset->Update();
    double e[4];
    inset->GetGeographicExtent(e);
    const int cols = inset->GetNumberOfColumns(), rows = inset->GetNumberOfRows();
    // The data: the same file with a hard edge (in-core, whatever the test variant).
    auto hard = vtkGlobeTest::FileLayer(insetIndex == 1 ? "earth/mt_rainier_90m.tif" : "earth/mt_everest_90m.tif", true);
    hard->SetFeatherDistance(0.0);
    hard->SetFeatherWidth(0.0);
    vtkNew<vtkGlobeTerrain> data;
    data->AddLayer(scene.Mapper->GetLayer(0));
    data->AddLayer(hard);
    data->Update();
    const std::string name = insetIndex == 1 ? "Rainier" : "Everest";
    for (const Edge& edge : Edges)
    {
      // Nadir over the border's middle.
      const double lon = edge.EastWest ? (edge.Low ? e[0] : e[1]) : 0.5 * (e[0] + e[1]);
      const double lat = edge.EastWest ? 0.5 * (e[2] + e[3]) : (edge.Low ? e[2] : e[3]);
      const double camera[3] = { lon, lat, 45000.0 }, target[3] = { lon, lat, 0.0 };
      scene.Look(camera, target, 30.0);
      double parallel, meridian;
      vtkGlobeTest::WGS84Radii(lat, parallel, meridian);
      double rendered[Configurations] = { 0.0, 0.0, 0.0 }, along = 0.0;
      for (int f = 0; f < Configurations; ++f)
      {
        Configure(inset, f);
        scene.Render();
        const std::vector<float> g = vtkGlobeTest::ReadTexture(vtkGlobeMapperTesting::GetGBufferTexture(scene.Mapper));
        // Each pixel's ground point: lon, lat (degrees), the mesh's height.
        std::vector<std::array<double, 3>> llh(static_cast<size_t>(Size) * Size);
        for (size_t p = 0; p < llh.size(); ++p)
        {
          llh[p][2] = std::nan("");
          if (g[4 * p + 3] > -1e6)
          {
            double x[3];
            vtkGlobeTest::GBufferPoint(scene, &g[4 * p], false, x);
            scene.Body->CartesianToGeodetic(x, llh[p].data());
            llh[p][2] = g[4 * p + 3];
          }
        }
        auto inside = [&](const std::array<double, 3>& q) { // signed distance inside the border (m)
          return edge.EastWest
            ? (edge.Low ? q[0] - e[0] : e[1] - q[0]) * vtkMath::Pi() / 180.0 * parallel
            : (edge.Low ? q[1] - e[2] : e[3] - q[1]) * vtkMath::Pi() / 180.0 * meridian;
        };
        for (int a = 0; a < Size; ++a)
        {
          for (int b = 0; b + 1 < Size; ++b)
          {
            // East-west profiles are image rows (north is up), north-south ones columns.
            const size_t p0 = edge.EastWest ? static_cast<size_t>(a) * Size + b : static_cast<size_t>(b) * Size + a;
            const size_t p1 = edge.EastWest ? p0 + 1 : p0 + Size;
            const auto &q0 = llh[p0], &q1 = llh[p1];
            if (!std::isfinite(q0[2]) || !std::isfinite(q1[2]))
            {
              continue;
            }
            const double d0 = inside(q0), d1 = inside(q1);
            if (std::min(d0, d1) < -7000.0 || std::max(d0, d1) > 7000.0)
            {
              continue;
            }
            const double ground = std::hypot(vtkMath::RadiansFromDegrees(q1[0] - q0[0]) * parallel,
              vtkMath::RadiansFromDegrees(q1[1] - q0[1]) * meridian);
            rendered[f] = std::max(rendered[f], std::abs(q1[2] - q0[2]) / ground);
            // How far along the border the view reaches.
            along = std::max(along, edge.EastWest
                ? std::abs(q0[1] - lat) * vtkMath::Pi() / 180.0 * meridian
                : std::abs(q0[0] - lon) * vtkMath::Pi() / 180.0 * parallel);
          }
        }
      }
      Configure(inset, 0);
      const double own = DataSlope(data, e, cols, rows, edge, along);
      for (int f = 0; f < Configurations; ++f)
      {
        walls[f] += rendered[f] > own;
      }
      check.Expect(own > 0.1 && rendered[0] > 0.0 && rendered[0] <= own,
        vtkGlobeTest::Printf("%s, %s border: steepest rendered slope %.3f (default), %.3f (8 "
                             "texels inside), %.3f (20 km inside); the data's own within 10 km: %.3f",
          name.c_str(), edge.Name, rendered[0], rendered[1], rendered[2], own));
    }
  }
  // What each keeps of the data near the border.
  {
    vtkGlobeLayer* everest = scene.Mapper->GetLayer(2);
    vtkNew<vtkGlobeTerrain> terrain;
    terrain->AddLayer(scene.Mapper->GetLayer(0));
    terrain->AddLayer(everest);
    const double summit[2] = { 86.925278, 27.988056 };
    double h[Configurations];
    for (int f = 0; f < Configurations; ++f)
    {
      Configure(everest, f);
      terrain->Update();
      h[f] = terrain->GetHeight(summit[0], summit[1]);
    }
    Configure(everest, 0);
    const double data = h[1]; // 8 texels end 0.72 km inside: the data themselves
    check.Expect(std::abs(h[0] - data) < 0.01,
      vtkGlobeTest::Printf("Everest's summit (1.35 km inside the north border): %.0f m (default), "
                           "%.0f m (8 texels inside), %.0f m (20 km inside)",
        h[0], h[1], h[2]));
  }
  check.Expect(walls[0] == 0 && walls[1] >= 2,
    vtkGlobeTest::Printf("borders steeper than the data: %d (default), %d (8 texels inside: the "
                         "walls the measure must see), %d (20 km inside)",
      walls[0], walls[1], walls[2]));
  return check.Result();
}
