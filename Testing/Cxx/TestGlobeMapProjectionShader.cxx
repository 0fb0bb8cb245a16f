// globe_projection.glsl, compiled as C++ in float (what the GPU computes) through
// vtkGlobeShaderMath.h, against vtkGlobeMapProjection's GeographicLib projections in double.
//
// Requirement: every texture coordinate within 0.01 source pixel of the double reference, for
// rasters with 16384 pixels along their longer side (square pixels), over each projection's
// typical full domain and over insets (16384 px over 1 and 0.1 degree) at the hard places:
// the date line, +-80 degrees, the poles and the conics' apexes. The conics, Albers, polar
// Lambert azimuthal and cylindrical equal-area come from EPSG codes through PROJ's database
// (vtkGlobeMapProjection::SetFromEPSG checks them against PROJ; the reference here is
// GeographicLib). Inputs are float-representable longitudes and
// latitudes (lo = 0), and hi + lo pairs; both sides get the same values. The double mirror
// (exact library transcendentals) checks the formulas themselves (bound 1e-3 px: Krueger's
// series stops at alpha_2 on the GPU, and alpha_3's share of a difference is ~1e-8 of it).
// Points outside a projection's valid domain must come back as (-1, -1).
#include "vtkGlobeMapProjection.h"
#include "vtkGlobeShaderMath.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Deg = Pi / 180.0;
constexpr int LongSide = 16384;

using Setup = std::function<void(vtkGlobeMapProjection*)>;

struct Raster
{
  std::string Name;
  Setup Configure;
  // Geographic box (west, east, south, north) in degrees, or, for polar caps and insets, a
  // map box around a map point: (x centre, y centre, half width, half height) with MapBox.
  double Box[4];
  bool MapBox = false;
};

bool IsCylindrical(int kind)
{
  return kind == vtkGlobeMapProjection::Geographic ||
    kind == vtkGlobeMapProjection::Equirectangular || kind == vtkGlobeMapProjection::Mercator ||
    kind == vtkGlobeMapProjection::WebMercator ||
    kind == vtkGlobeMapProjection::CylindricalEqualArea;
}

// The map box of a geographic box: cylindrical kinds are linear in longitude (the box may
// span 360 degrees); others are sampled along the boundary and inside.
bool MapBoxOf(vtkGlobeMapProjection* p, const double geo[4], double box[4])
{
  box[0] = box[2] = 1e300;
  box[1] = box[3] = -1e300;
  const int kind = p->GetKind();
  double xy[2];
  if (IsCylindrical(kind))
  {
    double xy2[2];
    if (!p->Forward(geo[0], geo[2], xy) || !p->Forward(0.5 * (geo[0] + geo[1]), geo[3], xy2))
    {
      return false;
    }
    box[0] = xy[0];
    box[1] = xy[0] + 2.0 * (xy2[0] - xy[0]);
    box[2] = xy[1];
    box[3] = xy2[1];
    return true;
  }
  const int n = 400;
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= n; ++j)
    {
      const double lon = geo[0] + (geo[1] - geo[0]) * i / n;
      const double lat = geo[2] + (geo[3] - geo[2]) * j / n;
      if (!p->Forward(lon, lat, xy))
      {
        return false;
      }
      box[0] = std::min(box[0], xy[0]);
      box[1] = std::max(box[1], xy[0]);
      box[2] = std::min(box[2], xy[1]);
      box[3] = std::max(box[3], xy[1]);
    }
  }
  return true;
}

namespace F = vtkGlobeShaderMath::f;
namespace D = vtkGlobeShaderMath::d;

// The function the renderer calls: the one vtkGlobeMapProjection names.
#define GLOBE_PROJECTION_FUNCTIONS(NS)                                                            \
  {                                                                                              \
    { "globe_projectEquirectangular", NS::globe_projectEquirectangular },                        \
      { "globe_projectMercator", NS::globe_projectMercator },                                    \
      { "globe_projectPolarStereographic", NS::globe_projectPolarStereographic },                \
      { "globe_projectTransverseMercator", NS::globe_projectTransverseMercator },                \
      { "globe_projectConformalConic", NS::globe_projectConformalConic },                        \
      { "globe_projectAlbersEqualArea", NS::globe_projectAlbersEqualArea },                      \
      { "globe_projectObliqueAzimuthalEqualArea", NS::globe_projectObliqueAzimuthalEqualArea },  \
      { "globe_projectSinusoidal", NS::globe_projectSinusoidal },                                \
    {                                                                                            \
      "globe_projectCylindricalEqualArea", NS::globe_projectCylindricalEqualArea                 \
    }                                                                                            \
  }

template <typename Real, typename Vec2, typename Vec4>
using Function = Vec2 (*)(Real, Real, Real, Real, Vec4, Vec4, Vec4, Vec4, Vec4, Vec4, Vec4);

F::vec2 ProjectF(const std::string& name, float lonHi, float lonLo, float latHi, float latLo,
  const F::vec4 p[7])
{
  static const std::map<std::string, Function<float, F::vec2, F::vec4>> functions =
    GLOBE_PROJECTION_FUNCTIONS(F);
  return functions.at(name)(lonHi, lonLo, latHi, latLo, p[0], p[1], p[2], p[3], p[4], p[5], p[6]);
}

D::vec2 ProjectD(const std::string& name, double lonHi, double lonLo, double latHi,
  double latLo, const D::vec4 p[7])
{
  static const std::map<std::string, Function<double, D::vec2, D::vec4>> functions =
    GLOBE_PROJECTION_FUNCTIONS(D);
  return functions.at(name)(lonHi, lonLo, latHi, latLo, p[0], p[1], p[2], p[3], p[4], p[5], p[6]);
}

// Worst errors over all rasters of one projection family.
struct Family
{
  std::string Name;
  double WorstFloat = 0.0;
  double WorstHiLo = 0.0;
  double WorstDouble = 0.0;
};

int Failures = 0;

bool RunRaster(const Raster& r, Family& family)
{
  vtkNew<vtkGlobeMapProjection> p;
  // Sample points beyond the poles are refused by Inverse (tested elsewhere): keep them quiet.
  vtkNew<vtkTest::ErrorObserver> quiet;
  p->AddObserver(vtkCommand::ErrorEvent, quiet);
  r.Configure(p);
  const int kind = p->GetKind();
  const std::string function = p->GetShaderFunctionName();
  double box[4];
  if (r.MapBox)
  {
    box[0] = r.Box[0] - r.Box[2];
    box[1] = r.Box[0] + r.Box[2];
    box[2] = r.Box[1] - r.Box[3];
    box[3] = r.Box[1] + r.Box[3];
  }
  else if (!MapBoxOf(p, r.Box, box))
  {
    std::printf("  FAIL %s: no map box\n", r.Name.c_str());
    return false;
  }
  const double mapW = box[1] - box[0], mapH = box[3] - box[2];
  const double px = std::max(mapW, mapH) / LongSide;
  const int width = std::max(1, static_cast<int>(std::lround(mapW / px)));
  const int height = std::max(1, static_cast<int>(std::lround(mapH / px)));
  const double origin[2] = { box[0], box[3] };
  const double pixel[2] = { mapW / width, mapH / height };

  float pf[28];
  double pd[28];
  if (!p->ComputeShaderParameters(origin, pixel, width, height, pf) ||
    !p->ComputeShaderParametersDouble(origin, pixel, width, height, pd))
  {
    std::printf("  FAIL %s: no shader parameters\n", r.Name.c_str());
    return false;
  }
  F::vec4 vf[7];
  D::vec4 vd[7];
  for (int i = 0; i < 7; ++i)
  {
    vf[i] = F::vec4(pf[4 * i], pf[4 * i + 1], pf[4 * i + 2], pf[4 * i + 3]);
    vd[i] = D::vec4(pd[4 * i], pd[4 * i + 1], pd[4 * i + 2], pd[4 * i + 3]);
  }

  vtkGlobeTest::Worst wf(r.Name + " float", "px");
  vtkGlobeTest::Worst wh(r.Name + " hi+lo", "px");
  vtkGlobeTest::Worst wd(r.Name + " double", "px");
  int samples = 0;

  // The reference: pixel coordinates of GeographicLib's map point of (lon, lat).
  auto reference = [&](double lonRad, double latRad, double& col, double& row) {
    double xy[2];
    if (!p->Forward(lonRad / Deg, std::max(-90.0, std::min(90.0, latRad / Deg)), xy))
    {
      return false;
    }
    col = (xy[0] - origin[0]) / pixel[0];
    row = (origin[1] - xy[1]) / pixel[1];
    return true;
  };
  // A raster spanning the whole period of a cylindrical projection: its west and east edges
  // are the same meridian, so u = 0 and u = 1 are the same answer there.
  const bool periodic = IsCylindrical(kind) && !r.MapBox && r.Box[1] - r.Box[0] >= 360.0;
  auto error = [&](double u, double v, double col, double row) {
    double du = std::abs(u * width - col);
    if (periodic)
    {
      du = std::min(du, std::abs(du - width));
    }
    return std::max(du, std::abs(v * height - row));
  };
  auto measure = [&](double lon, double lat) {
    // Float-representable inputs (lo = 0) and hi + lo pairs of the same point.
    const float lonHi = static_cast<float>(lon * Deg), latHi = static_cast<float>(lat * Deg);
    const float lonLo = static_cast<float>(lon * Deg - lonHi);
    const float latLo = static_cast<float>(lat * Deg - latHi);
    const std::string where = vtkGlobeTest::Format("lon %.10g lat %.10g", lon, lat, 0.0);
    double col = 0.0, row = 0.0;
    if (!reference(lonHi, latHi, col, row))
    {
      return;
    }
    const F::vec2 uv = ProjectF(function, lonHi, 0.0f, latHi, 0.0f, vf);
    wf.Add(error(uv.x, uv.y, col, row), where);
    const D::vec2 uvd = ProjectD(function, lonHi, 0.0, latHi, 0.0, vd);
    wd.Add(error(uvd.x, uvd.y, col, row), where);
    if (!reference(static_cast<double>(lonHi) + lonLo, static_cast<double>(latHi) + latLo, col, row))
    {
      return;
    }
    const F::vec2 uvh = ProjectF(function, lonHi, lonLo, latHi, latLo, vf);
    wh.Add(error(uvh.x, uvh.y, col, row), where);
    ++samples;
  };

  // A grid over the raster and 2% beyond its edges, and random points in it.
  const int n = 120;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(-0.02, 1.02);
  for (int k = 0; k < (n + 1) * (n + 1) + 6000; ++k)
  {
    double s, t;
    if (k < (n + 1) * (n + 1))
    {
      s = -0.02 + 1.04 * (k % (n + 1)) / n;
      t = -0.02 + 1.04 * (k / (n + 1)) / n;
    }
    else
    {
      s = unit(rng);
      t = unit(rng);
    }
    double lonLat[2];
    if (!p->Inverse(origin[0] + s * mapW, origin[1] - t * mapH, lonLat) ||
      !p->IsInValidDomain(lonLat[0], lonLat[1]))
    {
      continue;
    }
    measure(lonLat[0], lonLat[1]);
  }
  // The raster's geographic corners and edges exactly, and the pole when it is inside.
  if (!r.MapBox)
  {
    for (double lon : { r.Box[0], 0.5 * (r.Box[0] + r.Box[1]), r.Box[1] })
    {
      for (double lat : { r.Box[2], 0.5 * (r.Box[2] + r.Box[3]), r.Box[3] })
      {
        if (p->IsInValidDomain(lon, lat))
        {
          measure(lon, lat);
        }
      }
    }
  }
  else
  {
    // The apex (polar stereographic, conics, polar azimuthal) when the raster holds it.
    for (double pole : { 90.0, -90.0 })
    {
      double xy[2];
      if (IsCylindrical(kind) || kind == vtkGlobeMapProjection::TransverseMercator ||
        !p->ForwardInDomain(p->GetCentralMeridian(), pole, xy) ||
        std::abs(r.Box[0] - xy[0]) >= 1.02 * r.Box[2] ||
        std::abs(r.Box[1] - xy[1]) >= 1.02 * r.Box[3])
      {
        continue;
      }
      for (double lon : { -180.0, -135.0, -45.0, 0.0, 10.0, 179.9 })
      {
        measure(lon, pole);
      }
    }
  }

  std::printf("  %s: %d x %d px of %.4g x %.4g map units, %d points\n", r.Name.c_str(), width,
    height, pixel[0], pixel[1], samples);
  const bool ok = samples > 1000 && wf.Check(0.01) && wh.Check(0.01) && wd.Check(1e-3);
  family.WorstFloat = std::max(family.WorstFloat, wf.Value);
  family.WorstHiLo = std::max(family.WorstHiLo, wh.Value);
  family.WorstDouble = std::max(family.WorstDouble, wd.Value);
  return ok;
}

Setup EPSG(int code, double lonWest = -180.0)
{
  return [code, lonWest](vtkGlobeMapProjection* p) {
    p->SetFromEPSG(code);
    p->SetLongitudeWest(lonWest);
  };
}

// Half the map distance from the pole to a latitude on a polar projection.
double PolarRadius(int code, double lat)
{
  vtkNew<vtkGlobeMapProjection> p;
  p->SetFromEPSG(code);
  double xy[2];
  p->Forward(p->GetCentralMeridian(), lat, xy);
  return std::hypot(xy[0] - p->GetFalseEasting(), xy[1] - p->GetFalseNorthing());
}

// A map box of the given half size around a geographic point.
Raster PolarInset(const std::string& name, int code, double lon, double lat, double halfSize,
  Setup setup = nullptr)
{
  vtkNew<vtkGlobeMapProjection> p;
  const Setup configure = setup ? setup : EPSG(code);
  configure(p);
  double xy[2];
  p->Forward(lon, lat, xy);
  return { name, configure, { xy[0], xy[1], halfSize, halfSize }, true };
}

// MODIS's sinusoidal grid, from its PROJ string (it has no EPSG code).
constexpr double ModisRadius = 6371007.181;
Setup Modis()
{
  return [](vtkGlobeMapProjection* p) {
    p->SetFromDefinition("+proj=sinu +lon_0=0 +x_0=0 +y_0=0 +R=6371007.181 +units=m +no_defs +type=crs");
  };
}

// MODIS tile hHHvVV: 36 x 18 tiles of 1111950.519667 m over the sinusoidal map.
Raster ModisTile(const std::string& name, int h, int v)
{
  const double tile = 1111950.519667, west = -Pi * ModisRadius, north = 0.5 * Pi * ModisRadius;
  return { name, Modis(),
    { west + (h + 0.5) * tile, north - (v + 0.5) * tile, 0.5 * tile, 0.5 * tile }, true };
}

// Points outside the valid domain come back as (-1, -1).
bool CheckOutsideDomain()
{
  struct Case
  {
    int Code;
    double Lon, Lat;
  };
  const Case cases[] = { { 3413, 0.0, -30.0 }, { 3031, 20.0, 10.0 }, { 32631, 30.0, 45.0 },
    { 32601, 10.0, 0.0 }, { 3395, 0.0, 89.9 }, { 3857, 0.0, -86.0 }, { 2154, 0.0, -89.9 },
    { 3577, 0.0, 89.9 }, { 6931, 10.0, -89.9 }, { 3035, -170.0, -52.0 }, { 3035, -166.0, -50.0 } };
  bool ok = true;
  for (const Case& c : cases)
  {
    vtkNew<vtkGlobeMapProjection> p;
    p->SetFromEPSG(c.Code);
    const double origin[2] = { -1e6, 1e6 }, pixel[2] = { 1000.0, 1000.0 };
    float pf[28];
    p->ComputeShaderParameters(origin, pixel, 2000, 2000, pf);
    F::vec4 v[7];
    for (int i = 0; i < 7; ++i)
    {
      v[i] = F::vec4(pf[4 * i], pf[4 * i + 1], pf[4 * i + 2], pf[4 * i + 3]);
    }
    const F::vec2 uv = ProjectF(p->GetShaderFunctionName(), static_cast<float>(c.Lon * Deg), 0.0f,
      static_cast<float>(c.Lat * Deg), 0.0f, v);
    const bool outside = uv.x == -1.0f && uv.y == -1.0f && !p->IsInValidDomain(c.Lon, c.Lat);
    std::printf("  %-4s EPSG:%d (%g, %g) outside the domain -> (%g, %g)\n", outside ? "ok" : "FAIL",
      c.Code, c.Lon, c.Lat, uv.x, uv.y);
    ok = ok && outside;
  }
  return ok;
}
} // namespace

int TestGlobeMapProjectionShader(int, char*[])
{
  const double capN = PolarRadius(3413, 50.0), capS = PolarRadius(3031, -50.0);
  const double capU = PolarRadius(32661, 50.0), capUS = PolarRadius(32761, -50.0);
  const double cap3995 = PolarRadius(3995, 50.0);
  auto utm = [](int zone, bool north) -> Setup {
    return EPSG(north ? 32600 + zone : 32700 + zone);
  };
  const std::vector<std::pair<std::string, std::vector<Raster>>> families = {
    { "equirectangular",
      {
        { "EPSG:4326 global -180..180", EPSG(4326, -180.0), { -180, 180, -90, 90 } },
        { "EPSG:4326 global 0..360", EPSG(4326, 0.0), { 0, 360, -90, 90 } },
        { "equirect. phi1 45, lon0 10, global", [](vtkGlobeMapProjection* p) {
            p->SetToEquirectangular(10.0, 45.0);
            p->SetLongitudeWest(-170.0);
          },
          { -170, 190, -90, 90 } },
        { "EPSG:4326 1 deg over the date line at 80N", EPSG(4326, 0.0), { 179.5, 180.5, 79.5, 80.5 } },
        { "EPSG:4326 0.1 deg at -179.99, -80", EPSG(4326, -270.0), { -180.04, -179.94, -80.05, -79.95 } },
        { "EPSG:4326 0.1 deg at 179.99, 89.9", EPSG(4326, 0.0), { 179.94, 180.04, 89.85, 89.95 } },
      } },
    { "Mercator (3395)",
      {
        { "EPSG:3395 +-85", EPSG(3395), { -180, 180, -85, 85 } },
        { "EPSG:3395 0..360 +-85", EPSG(3395, 0.0), { 0, 360, -85, 85 } },
        { "EPSG:3395 1 deg over the date line at 80N", EPSG(3395, 0.0), { 179.5, 180.5, 79.5, 80.5 } },
        { "EPSG:3395 0.1 deg at -179.99, -80", EPSG(3395, -270.0), { -180.04, -179.94, -80.05, -79.95 } },
        { "Mercator phi1 60 S, 1 deg at 60S", [](vtkGlobeMapProjection* p) {
            p->SetToMercator(100.0, -60.0);
          },
          { 120.0, 121.0, -60.5, -59.5 } },
      } },
    { "Web Mercator (3857)",
      {
        { "EPSG:3857 +-85.05", EPSG(3857), { -180, 180, -85.0511287798, 85.0511287798 } },
        { "EPSG:3857 0.1 deg at 179.99, 85", EPSG(3857, 0.0), { 179.94, 180.04, 84.95, 85.04 } },
        { "EPSG:3857 1 deg at -179.99, -80", EPSG(3857, -270.0), { -180.49, -179.49, -80.5, -79.5 } },
      } },
    { "polar stereographic",
      {
        { "EPSG:3413 cap to 50N", EPSG(3413), { 0.0, 0.0, capN, capN }, true },
        { "EPSG:3031 cap to 50S", EPSG(3031), { 0.0, 0.0, capS, capS }, true },
        { "EPSG:3995 cap to 50N", EPSG(3995), { 0.0, 0.0, cap3995, cap3995 }, true },
        { "EPSG:32661 (UPS N) cap to 50N", EPSG(32661), { 2e6, 2e6, capU, capU }, true },
        { "EPSG:32761 (UPS S) cap to 50S", EPSG(32761), { 2e6, 2e6, capUS, capUS }, true },
        PolarInset("EPSG:3413 111 km around the pole", 3413, 0.0, 90.0, 55500.0),
        PolarInset("EPSG:3413 11 km at 89.9N", 3413, 135.0, 89.9, 5550.0),
        PolarInset("EPSG:3031 11 km around the pole", 3031, 0.0, -90.0, 5550.0),
        PolarInset("EPSG:3413 1 deg at 60N, 179.99", 3413, 179.99, 60.0, 27800.0),
        PolarInset("EPSG:3031 0.1 deg at 80S, -179.99", 3031, -179.99, -80.0, 1100.0),
      } },
    { "transverse Mercator (UTM)",
      {
        { "UTM 1N", utm(1, true), { -180.5, -173.5, 0, 84 } },
        { "UTM 10N", utm(10, true), { -126.5, -119.5, 0, 84 } },
        { "UTM 31N", utm(31, true), { -0.5, 6.5, 0, 84 } },
        { "UTM 60N", utm(60, true), { 173.5, 180.5, 0, 84 } },
        { "UTM 1S", utm(1, false), { -180.5, -173.5, -80, 0 } },
        { "UTM 10S", utm(10, false), { -126.5, -119.5, -80, 0 } },
        { "UTM 31S", utm(31, false), { -0.5, 6.5, -80, 0 } },
        { "UTM 60S", utm(60, false), { 173.5, 180.5, -80, 0 } },
        { "UTM 1N 1 deg at -179.99, 80N", utm(1, true), { -180.49, -179.49, 79.5, 80.5 } },
        { "UTM 60S 1 deg at 179.99, 80S", utm(60, false), { 179.49, 180.49, -80.5, -79.5 } },
        { "UTM 1S 0.1 deg at -179.99, 80S", utm(1, false), { -180.04, -179.94, -80.05, -79.95 } },
        { "UTM 60N 0.1 deg at 179.99, 84N", utm(60, true), { 179.94, 180.04, 83.9, 84.0 } },
        { "UTM 31N 0.1 deg on the equator", utm(31, true), { 2.95, 3.05, -0.05, 0.05 } },
      } },
    { "Lambert conformal conic",
      {
        { "EPSG:2154 France", EPSG(2154), { -5.5, 10.0, 41.0, 51.5 } },
        { "EPSG:3034 Europe", EPSG(3034), { -10.0, 40.0, 30.0, 70.0 } },
        { "EPSG:2154 0.1 deg at the origin", EPSG(2154), { 2.95, 3.05, 46.45, 46.55 } },
        { "LCC -20/-40 S, 1 deg at 179.99, 30S", [](vtkGlobeMapProjection* p) {
            p->SetToLambertConformalConic(-20.0, -40.0, -30.0, 150.0, 1e6, 1e6);
          },
          { 179.5, 180.5, -30.5, -29.5 } },
        PolarInset("LCC 1SP 60N (k0 0.9998), 111 km around the apex", 0, 0.0, 90.0, 55500.0,
          [](vtkGlobeMapProjection* p) { p->SetToLambertConformalConic1SP(60.0, 10.0, 0.9998); }),
        PolarInset("EPSG:3034 1 deg at 80N, 179.99", 3034, 179.99, 80.0, 27800.0),
      } },
    { "Albers equal-area",
      {
        { "EPSG:5070 CONUS", EPSG(5070), { -125.0, -66.0, 24.0, 50.0 } },
        { "EPSG:3577 Australia", EPSG(3577), { 112.0, 154.0, -44.0, -10.0 } },
        { "EPSG:5070 0.1 deg", EPSG(5070), { -96.05, -95.95, 39.95, 40.05 } },
        PolarInset("EPSG:5070 111 km around the apex", 5070, 0.0, 90.0, 55500.0),
        PolarInset("EPSG:3577 1 deg at 60S, -179.99", 3577, -179.99, -60.0, 27800.0),
      } },
    { "Lambert azimuthal equal-area (polar)",
      {
        PolarInset("EPSG:6931 (EASE-Grid 2.0 N) to the equator", 6931, 0.0, 90.0, 9.1e6),
        PolarInset("EPSG:6932 (EASE-Grid 2.0 S) to 50S", 6932, 0.0, -90.0, 4.5e6),
        PolarInset("EPSG:6931 11 km around the pole", 6931, 0.0, 90.0, 5550.0),
        PolarInset("EPSG:6932 1 deg at 70S, -179.99", 6932, -179.99, -70.0, 27800.0),
      } },
    { "Lambert azimuthal equal-area (oblique)",
      {
        { "EPSG:3035 (LAEA Europe) 30W..45E, 25N..84N", EPSG(3035), { -30.0, 45.0, 25.0, 84.0 } },
        { "EPSG:3035 0.1 deg at the centre", EPSG(3035), { 9.95, 10.05, 51.95, 52.05 } },
        PolarInset("EPSG:3035 11 km around the north pole", 3035, 0.0, 90.0, 5550.0),
        { "LAEA equatorial, lon0 100E, 60E..140E, +-40", [](vtkGlobeMapProjection* p) {
            p->SetToLambertAzimuthalEqualArea(0.0, 100.0);
          },
          { 60.0, 140.0, -40.0, 40.0 } },
        PolarInset("LAEA 70N 40W, 1 deg at 179.99W, 60N", 0, -179.99, 60.0, 27800.0,
          [](vtkGlobeMapProjection* p) { p->SetToLambertAzimuthalEqualArea(70.0, -40.0); }),
        PolarInset("LAEA 30S 60E, 11 km at the south pole", 0, 0.0, -90.0, 5550.0,
          [](vtkGlobeMapProjection* p) { p->SetToLambertAzimuthalEqualArea(-30.0, 60.0); }),
      } },
    { "cylindrical equal-area",
      {
        { "EPSG:6933 (EASE-Grid 2.0 global)", EPSG(6933), { -180, 180, -90, 90 } },
        { "EPSG:6933 0..360 +-85", EPSG(6933, 0.0), { 0, 360, -85, 85 } },
        { "EPSG:6933 0.1 deg at 179.99, 80N", EPSG(6933, 0.0), { 179.94, 180.04, 79.95, 80.05 } },
        { "EPSG:6933 1 deg at the south pole", EPSG(6933), { 10.0, 11.0, -90.0, -89.0 } },
      } },
    { "sinusoidal (MODIS sphere)",
      {
        { "MODIS global mosaic", Modis(), { 0.0, 0.0, Pi * ModisRadius, 0.5 * Pi * ModisRadius },
          true },
        ModisTile("MODIS tile h08v05", 8, 5),
        ModisTile("MODIS tile h35v08 (across the cut)", 35, 8),
        ModisTile("MODIS tile h17v00 (the north pole)", 17, 0),
        PolarInset("MODIS 1 deg at 60S, -100", 0, -100.0, -60.0, 0.5 * ModisRadius * Deg, Modis()),
        PolarInset("MODIS 0.1 deg at 80N, 179.99", 0, 179.99, 80.0, 0.05 * ModisRadius * Deg, Modis()),
        PolarInset("MODIS 0.1 deg at 89.9S, 0", 0, 0.0, -89.9, 0.05 * ModisRadius * Deg, Modis()),
        { "sinusoidal lon0 -60, FE 1e6, global", [](vtkGlobeMapProjection* p) {
            p->SetToSinusoidal(6371007.181, -60.0, 1e6, -2e6);
          },
          { 1e6, -2e6, Pi * ModisRadius, 0.5 * Pi * ModisRadius }, true },
      } },
  };

  bool ok = true;
  std::vector<Family> summary;
  for (const auto& family : families)
  {
    std::printf("%s:\n", family.first.c_str());
    Family f;
    f.Name = family.first;
    for (const Raster& r : family.second)
    {
      ok = RunRaster(r, f) && ok;
    }
    summary.push_back(f);
  }
  std::printf("Outside the valid domain:\n");
  ok = CheckOutsideDomain() && ok;

  std::printf("Worst error per projection (source pixels, rasters %d px on the long side):\n",
    LongSide);
  for (const Family& f : summary)
  {
    std::printf("  %-28s float %.2e  hi+lo %.2e  double mirror %.2e\n", f.Name.c_str(),
      f.WorstFloat, f.WorstHiLo, f.WorstDouble);
  }
  return ok ? 0 : 1;
}
