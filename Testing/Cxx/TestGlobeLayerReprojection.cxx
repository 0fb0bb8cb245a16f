// Layers in a CRS the GPU does not project (issue "Geodetic correctness": any CRS that PROJ
// knows still works), reprojected on load into a geographic grid. The reference is
// independent of PROJ: GeographicLib's Lambert conformal conic for EPSG:2154 (RGF93 v1 /
// Lambert-93: GRS80, standard parallels 44 and 49 N, origin 46.5 N 3 E, false origin
// (700 km, 6,600 km); RGF93 and WGS 84 coincide here).
//  A. Distinct nearest-filtered texels: every texel of the geographic grid whose centre lies
//     inside a source texel (away from its edges by 2 %) holds that texel's colour.
//  B. Heights linear in the source's map coordinates: the bilinear resampling reproduces them
//     at every geographic texel centre inside the source (within 1 mm).
//  C. A CRS PROJ cannot take to (lon, lat) is refused with an error saying so. (A also checks
//     that the layer says what happened: GetReprojectedFromEPSG, geographic model, its box.)
#include "vtkGlobeLayerTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeMapProjection.h"
#include "vtkTestErrorObserver.h"

#include <GeographicLib/LambertConformalConic.hpp>

#include <cmath>
#include <cstdio>

namespace
{
vtkGlobeTest::Checklist Check;

// Lambert-93 (EPSG:2154) in double through GeographicLib.
struct Lambert93
{
  GeographicLib::LambertConformalConic Projection{ 6378137.0, 1.0 / 298.257222101, 44.0, 49.0,
    1.0 };
  double Y0 = 0.0; // GeographicLib's y at the false origin's latitude
  Lambert93()
  {
    double x, gamma, k;
    this->Projection.Forward(3.0, 46.5, 3.0, x, this->Y0, gamma, k);
  }
  void Forward(double lon, double lat, double& e, double& n) const
  {
    double x, y, gamma, k;
    this->Projection.Forward(3.0, lat, lon, x, y, gamma, k);
    e = 700000.0 + x;
    n = 6600000.0 + (y - this->Y0);
  }
};

// Source raster: 64 x 48 texels of 10 km from (300 km E, 7,000 km N): Brittany to the Alps.
constexpr int W = 64, H = 48;
constexpr double West = 300000.0, North = 7000000.0, Pixel = 10000.0;

// The geographic texel centres of a reprojected layer, each with its source texel
// coordinates (column, row from the north, texel centres at integers).
template <typename F>
void ForEachTexel(vtkGlobeLayer* layer, const Lambert93& l93, F&& f)
{
  double e[4];
  layer->GetGeographicExtent(e);
  const int w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const double lon = e[0] + (i + 0.5) * (e[1] - e[0]) / w;
      const double lat = e[3] - (j + 0.5) * (e[3] - e[2]) / h;
      double x, y;
      l93.Forward(lon, lat, x, y);
      f(static_cast<vtkIdType>(j) * w + i, (x - West) / Pixel - 0.5, (North - y) / Pixel - 0.5);
    }
  }
}
} // namespace

int TestGlobeLayerReprojection(int, char*[])
{
  const Lambert93 l93;
  std::printf("EPSG:2154 is not drawn directly: %s\n",
    vtkGlobeMapProjection::IsSupportedEPSG(2154) ? "it is (unexpected)" : "reprojected");
  Check.Expect(!vtkGlobeMapProjection::IsSupportedEPSG(2154) &&
      vtkGlobeMapProjection::IsSupportedEPSG(3413),
    "IsSupportedEPSG: 2154 no, 3413 yes");

  std::printf("A. Texels (nearest):\n");
  auto image = vtkGlobeTest::ProjectedImage(2154, W, H, West, North, Pixel,
    [](int i, int j) { return vtkGlobeTest::TexelColour(3, i, j); });
  const bool loaded = image->Update() && image->IsValid();
  double e[4];
  image->GetGeographicExtent(e);
  Check.Expect(loaded && image->GetReprojectedFromEPSG() == 2154 &&
      image->GetModelType() == vtkGlobeLayer::Geographic && image->GetEPSG() == 4326 &&
      e[0] > -6.0 && e[1] < 10.0 && e[2] > 41.0 && e[3] < 52.0,
    vtkGlobeTest::Printf("loaded, reprojected from EPSG:%d into %d x %d geographic texels, box "
                         "W %.3f E %.3f S %.3f N %.3f",
      image->GetReprojectedFromEPSG(), image->GetNumberOfColumns(), image->GetNumberOfRows(), e[0], e[1], e[2],
      e[3]));
  vtkDataArray* pixels = image->GetData();
  int checked = 0, wrong = 0, outside = 0, transparentOutside = 0;
  ForEachTexel(image, l93, [&](vtkIdType id, double fx, double fy) {
    const double x = fx + 0.5, y = fy + 0.5; // texel edges at integers
    if (x < 0 || y < 0 || x >= W || y >= H)
    {
      ++outside;
      transparentOutside += pixels->GetComponent(id, 3) == 0 ? 1 : 0;
      return;
    }
    const double margin = 0.02;
    if (x - std::floor(x) < margin || std::ceil(x) - x < margin || y - std::floor(y) < margin ||
      std::ceil(y) - y < margin)
    {
      return;
    }
    const auto c = vtkGlobeTest::TexelColour(3, static_cast<int>(x), static_cast<int>(y));
    ++checked;
    bool same = pixels->GetComponent(id, 3) == 255;
    for (int k = 0; k < 3; ++k)
    {
      same = same && pixels->GetComponent(id, k) == c[k];
    }
    wrong += same ? 0 : 1;
  });
  Check.Expect(checked > 2000 && wrong == 0 && outside > 0 && transparentOutside == outside,
    vtkGlobeTest::Printf("%d texels checked against GeographicLib's Lambert-93, %d show another "
                         "source texel; %d outside the source, %d of them transparent",
      checked, wrong, outside, transparentOutside));

  std::printf("B. Heights linear in map coordinates (bilinear):\n");
  auto ramp = vtkGlobeTest::ProjectedHeights(2154, W, H, West, North, Pixel,
    [](int i, int j) { return static_cast<float>(3.0 * i + 7.0 * j); });
  ramp->FillVoidsOff();
  Check.Expect(ramp->Update() && ramp->GetReprojectedFromEPSG() == 2154, "the ramp loaded and reprojected");
  vtkDataArray* heights = ramp->GetData();
  double worst = 0.0;
  int inside = 0, voids = 0, beyond = 0;
  ForEachTexel(ramp, l93, [&](vtkIdType id, double fx, double fy) {
    const double v = heights->GetComponent(id, 0);
    if (fx < -0.5 || fy < -0.5 || fx > W - 0.5 || fy > H - 0.5)
    {
      ++beyond;
      voids += std::isnan(v) ? 1 : 0;
      return;
    }
    if (fx < 0.0 || fy < 0.0 || fx > W - 1.0 || fy > H - 1.0)
    {
      return; // the half texel at the border is clamped, not extrapolated
    }
    ++inside;
    worst = std::max(worst, std::isnan(v) ? 1e9 : std::abs(v - (3.0 * fx + 7.0 * fy)));
  });
  Check.Expect(inside > 2000 && worst < 1e-3 && beyond > 0 && voids == beyond,
    vtkGlobeTest::Printf("%d texel centres inside the source: worst |h - ramp| %.2g m (ramp "
                         "slope 7 m per texel); outside the source: %d of %d NaN",
      inside, worst, voids, beyond));

  std::printf("C. A raster in a CRS PROJ cannot take to longitude and latitude:\n");
  // EPSG:5773 is a vertical CRS (EGM96 height): no horizontal transformation exists.
  auto far = vtkGlobeTest::ProjectedHeights(5773, 8, 8, 0.0, 8000.0, 1000.0,
    [](int, int) { return 1.0f; });
  vtkNew<vtkTest::ErrorObserver> errors;
  far->AddObserver(vtkCommand::ErrorEvent, errors);
  const bool farLoaded = far->Update();
  std::string said = errors->GetErrorMessage();
  said = said.substr(std::min(said.find("Cannot load"), said.size()));
  said = said.substr(0, said.find('\n'));
  Check.Expect(!farLoaded && errors->GetError() &&
      errors->GetErrorMessage().find("EPSG:5773 cannot be reprojected") != std::string::npos,
    "refused with an error that says why (" + said + ")");
  return Check.Result();
}
