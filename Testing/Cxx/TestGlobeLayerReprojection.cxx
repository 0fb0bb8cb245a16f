// Layers in a CRS the GPU does not project (issue "Geodetic correctness": any CRS that PROJ
// knows still works), reprojected on load into a geographic grid. The reference is
// independent of PROJ: the Equal Earth projection's published formulas (Šavrič, Patterson and
// Jenny 2018) on the ellipsoid through the authalic latitude (sin beta = q / q_p, Snyder 3-12),
// as EPSG:8857 (WGS 84 / Equal Earth Greenwich) defines it. (This test used LAEA Europe,
// EPSG:3035, until the GPU learned the oblique Lambert azimuthal projection.)
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

#include <cmath>
#include <cstdio>

namespace
{
vtkGlobeTest::Checklist Check;

// Equal Earth (EPSG:8857) in double.
struct EqualEarth
{
  static constexpr double Deg = 3.14159265358979323846 / 180.0;
  const double A = 6378137.0, F = 1.0 / 298.257223563;
  const double A1 = 1.340264, A2 = -0.081106, A3 = 0.000893, A4 = 0.003796;
  const double M = std::sqrt(3.0) / 2.0;
  double E = 0.0, Qp = 0.0, Rq = 0.0;
  double Q(double phi) const
  {
    const double s = std::sin(phi), e2 = this->E * this->E;
    return (1.0 - e2) *
      (s / (1.0 - e2 * s * s) -
        std::log((1.0 - this->E * s) / (1.0 + this->E * s)) / (2.0 * this->E));
  }
  EqualEarth()
  {
    this->E = std::sqrt(this->F * (2.0 - this->F));
    this->Qp = this->Q(90.0 * Deg);
    this->Rq = this->A * std::sqrt(this->Qp / 2.0);
  }
  void Forward(double lon, double lat, double& e, double& n) const
  {
    const double psi = std::asin(this->M * this->Q(lat * Deg) / this->Qp);
    const double p2 = psi * psi, p6 = p2 * p2 * p2;
    e = this->Rq * lon * Deg * std::cos(psi) /
      (this->M * (this->A1 + 3.0 * this->A2 * p2 + p6 * (7.0 * this->A3 + 9.0 * this->A4 * p2)));
    n = this->Rq * psi * (this->A1 + this->A2 * p2 + p6 * (this->A3 + this->A4 * p2));
  }
};
const EqualEarth Reference;
constexpr int Code = 8857;

// Source raster: 64 x 48 texels of 10 km from the map point of (2 E, 50 N): northern France
// to the Alps.
constexpr int W = 64, H = 48;
constexpr double Pixel = 10000.0;
double Corner(int axis)
{
  double x = 0.0, y = 0.0;
  Reference.Forward(2.0, 50.0, x, y);
  return std::round((axis == 0 ? x : y) / Pixel) * Pixel;
}
const double West = Corner(0), North = Corner(1);

// The geographic texel centres of a reprojected layer, each with its source texel
// coordinates (column, row from the north, texel centres at integers).
template <typename F>
void ForEachTexel(vtkGlobeLayer* layer, F&& f)
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
      Reference.Forward(lon, lat, x, y);
      f(static_cast<vtkIdType>(j) * w + i, (x - West) / Pixel - 0.5, (North - y) / Pixel - 0.5);
    }
  }
}
} // namespace

int TestGlobeLayerReprojection(int, char*[])
{
  std::printf("EPSG:%d is not drawn directly: %s\n", Code,
    vtkGlobeMapProjection::IsSupportedEPSG(Code) ? "it is (unexpected)" : "reprojected");
  Check.Expect(!vtkGlobeMapProjection::IsSupportedEPSG(Code) &&
      vtkGlobeMapProjection::IsSupportedEPSG(3413) &&
      vtkGlobeMapProjection::IsSupportedEPSG(3035),
    "IsSupportedEPSG: 8857 (Equal Earth) no; 3413 and 3035 (Lambert azimuthal equal-area) yes");

  std::printf("A. Texels (nearest):\n");
  auto image = vtkGlobeTest::ProjectedImage(Code, W, H, West, North, Pixel,
    [](int i, int j) { return vtkGlobeTest::TexelColour(3, i, j); });
  const bool loaded = image->Update() && image->IsValid();
  double e[4];
  image->GetGeographicExtent(e);
  Check.Expect(loaded && image->GetReprojectedFromEPSG() == Code &&
      image->GetModelType() == vtkGlobeLayer::Geographic && image->GetEPSG() == 4326 &&
      e[0] > 1.0 && e[0] < 3.0 && e[1] > 10.0 && e[1] < 14.0 && e[2] > 44.0 && e[2] < 47.0 &&
      e[3] > 49.5 && e[3] < 50.5,
    vtkGlobeTest::Printf("loaded, reprojected from EPSG:%d into %d x %d geographic texels, box "
                         "W %.3f E %.3f S %.3f N %.3f",
      image->GetReprojectedFromEPSG(), image->GetNumberOfColumns(), image->GetNumberOfRows(), e[0], e[1], e[2],
      e[3]));
  vtkDataArray* pixels = image->GetData();
  int checked = 0, wrong = 0, outside = 0, transparentOutside = 0;
  ForEachTexel(image, [&](vtkIdType id, double fx, double fy) {
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
    vtkGlobeTest::Printf("%d texels checked against Equal Earth's formulas, %d show another "
                         "source texel; %d outside the source, %d of them transparent",
      checked, wrong, outside, transparentOutside));

  std::printf("B. Heights linear in map coordinates (bilinear):\n");
  auto ramp = vtkGlobeTest::ProjectedHeights(Code, W, H, West, North, Pixel,
    [](int i, int j) { return static_cast<float>(3.0 * i + 7.0 * j); });
  ramp->FillVoidsOff();
  Check.Expect(ramp->Update() && ramp->GetReprojectedFromEPSG() == Code, "the ramp loaded and reprojected");
  vtkDataArray* heights = ramp->GetData();
  double worst = 0.0;
  int inside = 0, voids = 0, beyond = 0;
  ForEachTexel(ramp, [&](vtkIdType id, double fx, double fy) {
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
  std::printf("C. A CRS without an EPSG code that the GPU does not draw:\n");
  {
    // World Sinusoidal on WGS 84 (ESRI:54008): the ellipsoidal sinusoidal, which only the
    // sphere's (MODIS) is drawn of. 8 x 8 texels of 100 km around (1000 km E, 5000 km N).
    auto esri = vtkGlobeTest::ProjectedImage(0, 8, 8, 6.0e5, 5.4e6, 1.0e5,
      [](int i, int j) { return vtkGlobeTest::TexelColour(4, i, j); }, "ESRI:54008");
    const bool ok = esri->Update() && esri->IsValid();
    double box[4];
    esri->GetGeographicExtent(box);
    Check.Expect(ok && esri->IsReprojected() && esri->GetReprojectedFromEPSG() == 0 &&
        std::string(esri->GetReprojectedFromCRS()) == "ESRI:54008" &&
        esri->GetModelType() == vtkGlobeLayer::Geographic && box[2] > 40.0 && box[3] < 50.0,
      vtkGlobeTest::Printf("ESRI:54008 loaded and reprojected from its definition into %d x %d "
                           "geographic texels, S %.3f N %.3f",
        esri->GetNumberOfColumns(), esri->GetNumberOfRows(), box[2], box[3]));
    auto modis = vtkGlobeTest::ProjectedImage(0, 8, 8, 6.0e5, 5.4e6, 1.0e5,
      [](int i, int j) { return vtkGlobeTest::TexelColour(4, i, j); },
      "+proj=sinu +R=6371007.181 +units=m +type=crs");
    Check.Expect(modis->Update() && !modis->IsReprojected() &&
        modis->GetModelType() == vtkGlobeLayer::Projected && modis->GetEPSG() == 0,
      "MODIS's spherical sinusoidal is kept projected (the GPU draws it)");
  }
  return Check.Result();
}
