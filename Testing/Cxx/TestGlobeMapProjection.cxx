// vtkGlobeMapProjection on the CPU: published reference points (IOGP Guidance Note 7-2 worked
// examples, GeographicLib's GeoConvert manual),
// the defining scale of each polar projection measured with geodesics, Forward/Inverse round
// trips over each valid domain, both longitude domains, and bad input (errors, NaN, no crash).
// EPSG codes outside the built-in table (the conics, equal-area kinds, national transverse
// Mercator grids) against PROJ's own transformation at random points of their areas of use,
// and codes it must refuse (a datum shift, an oblique aspect).
#include "vtkGlobeTestHelpers.h"
#include "vtkGlobeMapProjection.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <GeographicLib/Geodesic.hpp>

#include <proj.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

bool ErrorSaid(vtkTest::ErrorObserver* observer, const std::string& words)
{
  const bool said =
    observer->GetError() && observer->GetErrorMessage().find(words) != std::string::npos;
  observer->Clear();
  return said;
}

double Dms(double d, double m, double s)
{
  return d + m / 60.0 + s / 3600.0;
}

// A published point: projects to (E, N) within the published rounding.
void ExpectPoint(vtkGlobeMapProjection* p, const char* what, double lon, double lat, double e,
  double n, double tolerance)
{
  double xy[2];
  const bool ok = p->Forward(lon, lat, xy);
  const double error = std::max(std::abs(xy[0] - e), std::abs(xy[1] - n));
  char text[256];
  std::snprintf(text, sizeof(text), "%s: (%.9g, %.9g) -> (%.3f, %.3f), published (%.2f, %.2f), "
    "off %.2e m (bound %.2g)", what, lon, lat, xy[0], xy[1], e, n, error, tolerance);
  Expect(ok && error <= tolerance, text);
  double back[2];
  p->Inverse(e, n, back);
  const double angle = std::max(std::abs(std::remainder(back[0] - lon, 360.0)) *
      std::cos(lat * 3.14159265358979323846 / 180.0), std::abs(back[1] - lat));
  std::snprintf(text, sizeof(text), "  its inverse is (%.9g, %.9g), off %.2e deg", back[0],
    back[1], angle);
  Expect(angle < 2 * tolerance / 111000.0 + 1e-9, text);
}

// The scale factor at (lon, lat): map distance over geodesic distance for a short step.
double Scale(vtkGlobeMapProjection* p, double lon, double lat)
{
  const GeographicLib::Geodesic g(p->GetSemiMajorAxis(), p->GetFlattening());
  double a[2], b[2], s12 = 0.0;
  const double dLat = 1e-4;
  p->Forward(lon, lat, a);
  p->Forward(lon, lat + dLat, b);
  g.Inverse(lat, lon, lat + dLat, lon, s12);
  return std::hypot(b[0] - a[0], b[1] - a[1]) / s12;
}

// An EPSG code from PROJ's database: Forward agrees with PROJ's transformation from EPSG:4326
// at 400 random points of the CRS's area of use (bound 1 mm), and Inverse with PROJ's inverse
// (bound 1e-9 degrees; 1e-7 for the equal-area kinds, where PROJ's series for the latitude
// from the authalic latitude is off by 1.4e-8 degrees, 1.6 mm: the round trips below show
// GeographicLib's inverse to 5e-12).
// A CRS without a code: `definition` (SetFromDefinition), with code 0.
void ExpectLikePROJ(int code, int kind, const char* what, const char* definition = nullptr)
{
  vtkNew<vtkGlobeMapProjection> p;
  const bool set = definition ? p->SetFromDefinition(definition) : p->SetFromEPSG(code);
  PJ_CONTEXT* ctx = proj_context_create();
  const std::string name = definition ? definition : "EPSG:" + std::to_string(code);
  PJ* crs = proj_create(ctx, name.c_str());
  double west = -180, south = -90, east = 180, north = 90;
  proj_get_area_of_use(ctx, crs, &west, &south, &east, &north, nullptr);
  east = east < west ? east + 360.0 : east;
  PJ* raw = proj_create_crs_to_crs(ctx, "EPSG:4326", name.c_str(), nullptr);
  PJ* t = proj_normalize_for_visualization(ctx, raw);
  std::mt19937_64 rng(static_cast<unsigned>(code));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0, worstBack = 0.0;
  int points = 0;
  for (int i = 0; set && t && i < 400; ++i)
  {
    const double lon = std::remainder(west + (east - west) * unit(rng), 360.0);
    const double lat = south + (north - south) * unit(rng);
    double xy[2], back[2];
    if (!p->IsInValidDomain(lon, lat) || !p->Forward(lon, lat, xy) ||
      !p->Inverse(xy[0], xy[1], back))
    {
      continue;
    }
    PJ_COORD c = proj_trans(t, PJ_FWD, proj_coord(lon, lat, 0.0, 0.0));
    PJ_COORD b = proj_trans(t, PJ_INV, proj_coord(xy[0], xy[1], 0.0, 0.0));
    worst = std::max(worst, std::hypot(c.xy.x - xy[0], c.xy.y - xy[1]));
    const double cl = std::cos(lat * 3.14159265358979323846 / 180.0);
    worstBack = std::max(worstBack, std::max(std::abs(std::remainder(b.lp.lam - back[0], 360.0)) *
        cl, std::abs(b.lp.phi - back[1])));
    ++points;
  }
  proj_destroy(t);
  proj_destroy(raw);
  proj_destroy(crs);
  proj_context_destroy(ctx);
  char text[320];
  const bool equalArea = kind == vtkGlobeMapProjection::AlbersEqualArea ||
    kind == vtkGlobeMapProjection::LambertAzimuthalEqualArea ||
    kind == vtkGlobeMapProjection::CylindricalEqualArea;
  std::snprintf(text, sizeof(text), "%s (%s) is %s: %d points of its area of use, Forward "
    "%.2e m from PROJ (bound 1e-3), Inverse %.2e deg (bound %g)", definition ? "definition" : name.c_str(), what,
    set ? p->GetKindAsString() : "refused", points, worst, worstBack,
    equalArea ? 1e-7 : 1e-9);
  Expect(set && p->GetKind() == kind && p->GetEPSG() == code && points >= 300 && worst <= 1e-3 &&
      worstBack <= (equalArea ? 1e-7 : 1e-9),
    text);
}

// Forward, Inverse, Forward over the valid domain's grid. The west edge is nudged inside: on
// a conic it is the cut, whose two images share one longitude. An Albers conic maps a pole to
// an arc, where the latitude is ill-conditioned (rho^2 is flat in it: the inverse holds ~1e-6
// degrees, 1e-8 m on the map): its poles are left out.
void RoundTrips(vtkGlobeMapProjection* p, const char* what)
{
  const bool poleIsArc = p->GetKind() == vtkGlobeMapProjection::AlbersEqualArea;
  double box[4];
  p->GetValidDomain(box);
  double worstAngle = 0.0, worstMap = 0.0;
  int points = 0;
  for (int i = 0; i <= 60; ++i)
  {
    for (int j = 0; j <= 60; ++j)
    {
      const double lon =
        box[0] + (box[1] - box[0]) * (i == 60 ? 0.9999999 : i == 0 ? 1e-7 : i / 60.0);
      const double lat = box[2] + (box[3] - box[2]) * j / 60.0;
      // (The domain's box, and for oblique Lambert azimuthal equal-area less its antipode cap.)
      if ((poleIsArc && std::abs(lat) == 90.0) || !p->IsInValidDomain(lon, lat))
      {
        continue;
      }
      double xy[2], back[2], xy2[2];
      if (!p->Forward(lon, lat, xy) || !p->Inverse(xy[0], xy[1], back) ||
        !p->Forward(back[0], back[1], xy2))
      {
        ++Checks.Failures;
        std::printf("  FAIL %s: round trip failed at (%g, %g)\n", what, lon, lat);
        continue;
      }
      const double c = std::cos(lat * 3.14159265358979323846 / 180.0);
      worstAngle = std::max(worstAngle,
        std::max(std::abs(std::remainder(back[0] - lon, 360.0)) * c, std::abs(back[1] - lat)));
      worstMap = std::max(worstMap, std::hypot(xy2[0] - xy[0], xy2[1] - xy[1]));
      ++points;
    }
  }
  char text[200];
  std::snprintf(text, sizeof(text),
    "%s round trips (%d points): angle %.2e deg (bound 1e-9), map %.2e m (bound 1e-5)", what,
    points, worstAngle, worstMap);
  Expect(worstAngle <= 1e-9 && worstMap <= 1e-5, text);
}
} // namespace

int TestGlobeMapProjection(int, char*[])
{
  vtkNew<vtkGlobeMapProjection> p;
  vtkNew<vtkTest::ErrorObserver> observer;
  p->AddObserver(vtkCommand::ErrorEvent, observer);

  std::printf("Published points:\n");
  // IOGP GN 7-2, Polar Stereographic variant A: WGS 84 / UPS North (N,E).
  Expect(p->SetFromEPSG(32661), "SetFromEPSG(32661)");
  ExpectPoint(p, "UPS North (GN 7-2)", 44.0, 73.0, 3320416.75, 632668.43, 0.01);
  // IOGP GN 7-2, Polar Stereographic variant B: WGS 84 / Australian Antarctic (EPSG:3032).
  Expect(p->SetFromEPSG(3032), "SetFromEPSG(3032)");
  ExpectPoint(p, "EPSG:3032 (GN 7-2)", 120.0, -75.0, 7255380.79, 7053389.56, 0.01);
  // IOGP GN 7-2, Mercator variant A: Makassar / NEIEZ (Bessel 1841).
  p->SetToMercator(110.0, 0.0, 0.997, 3900000.0, 900000.0);
  p->SetEllipsoid(6377397.155, 1.0 / 299.1528128);
  ExpectPoint(p, "Mercator A, NEIEZ (GN 7-2)", 120.0, -3.0, 5009726.58, 569150.82, 0.01);
  // IOGP GN 7-2, Mercator variant B: Pulkovo 1942 / Caspian Sea Mercator (Krassowsky).
  p->SetToMercator(51.0, 42.0);
  p->SetEllipsoid(6378245.0, 1.0 / 298.3);
  ExpectPoint(p, "Mercator B, Caspian Sea (GN 7-2)", 53.0, 53.0, 165704.29, 5171848.07, 0.01);
  // IOGP GN 7-2, Lambert Azimuthal Equal Area: ETRS89 / LAEA Europe (EPSG:3035).
  Expect(p->SetFromEPSG(3035), "SetFromEPSG(3035)");
  ExpectPoint(p, "EPSG:3035 (GN 7-2)", 5.0, 50.0, 3962799.45, 2999718.85, 0.01);
  // IOGP GN 7-2, Popular Visualisation Pseudo Mercator (EPSG:3857).
  Expect(p->SetFromEPSG(3857), "SetFromEPSG(3857)");
  ExpectPoint(p, "EPSG:3857 (GN 7-2)", -Dms(100, 20, 0), Dms(24, 22, 54.433), -11169055.58,
    2800000.00, 0.01);
  // IOGP GN 7-2, Transverse Mercator: OSGB 1936 / British National Grid (Airy 1830).
  p->SetToTransverseMercator(-2.0, 0.9996012717, 400000.0, -100000.0, 49.0);
  p->SetEllipsoid(6377563.396, 1.0 / 299.3249646);
  ExpectPoint(p, "British National Grid (GN 7-2)", Dms(0, 30, 0), Dms(50, 30, 0), 577274.99,
    69740.50, 0.01);
  // GeographicLib's GeoConvert manual: 33.3 44.4 -> 38n 444140.54 3684706.36.
  Expect(p->SetFromEPSG(32638), "SetFromEPSG(32638)");
  ExpectPoint(p, "UTM 38N (GeoConvert)", 44.4, 33.3, 444140.54, 3684706.36, 0.01);
  Expect(p->SetToUTM(31, true), "SetToUTM(31, north)");
  ExpectPoint(p, "UTM 31N central meridian on the equator", 3.0, 0.0, 500000.0, 0.0, 1e-6);
  Expect(p->SetFromEPSG(32731), "SetFromEPSG(32731)");
  ExpectPoint(p, "UTM 31S central meridian on the equator", 3.0, 0.0, 500000.0, 1e7, 1e-6);

  std::printf("Defining properties:\n");
  const struct
  {
    int Code;
    double Lat, Lon, K;
  } scales[] = { { 3413, 70.0, -45.0, 1.0 }, { 3413, 70.0, 100.0, 1.0 }, { 3031, -71.0, 30.0, 1.0 },
    { 3995, 71.0, 0.0, 1.0 }, { 3976, -70.0, 0.0, 1.0 }, { 32661, 89.999, 0.0, 0.994 },
    { 32761, -89.999, 0.0, 0.994 }, { 3395, 0.0, 10.0, 1.0 }, { 32610, 0.0, -123.0, 0.9996 } };
  for (const auto& s : scales)
  {
    p->SetFromEPSG(s.Code);
    const double k = Scale(p, s.Lon, s.Lat);
    char text[160];
    std::snprintf(text, sizeof(text), "EPSG:%d scale at (%g, %g) = %.9f (defined %.4f)", s.Code,
      s.Lon, s.Lat, k, s.K);
    Expect(std::abs(k - s.K) < 2e-6, text);
  }
  // EPSG:3413: the pole at the origin, the -45 meridian pointing down (negative y, x = 0).
  p->SetFromEPSG(3413);
  double xy[2];
  p->Forward(-45.0, 75.0, xy);
  Expect(std::abs(xy[0]) < 1e-6 && xy[1] < -1e6, "EPSG:3413: 75N on the -45 meridian at x = 0, y < 0");
  p->Forward(123.0, 90.0, xy);
  Expect(std::abs(xy[0]) < 1e-6 && std::abs(xy[1]) < 1e-6, "EPSG:3413: the pole at (0, 0)");
  p->SetFromEPSG(3031);
  p->Forward(0.0, -75.0, xy);
  Expect(std::abs(xy[0]) < 1e-6 && xy[1] > 1e6, "EPSG:3031: 75S on the 0 meridian at x = 0, y > 0");
  Expect(std::string(p->GetShaderFunctionName()) == "globe_projectPolarStereographic",
    "EPSG:3031 shader function globe_projectPolarStereographic");

  std::printf("Round trips:\n");
  const int codes[] = { 4326, 4087, 3413, 3031, 3995, 32661, 32761, 3395, 3857, 32601, 32610,
    32631, 32660, 32701, 32731, 32760 };
  for (int code : codes)
  {
    p->SetFromEPSG(code);
    RoundTrips(p, ("EPSG:" + std::to_string(code)).c_str());
  }
  p->SetToEquirectangular(-60.0, 37.5, 1000.0, -2000.0);
  RoundTrips(p, "equirectangular phi1 37.5 lon0 -60");
  p->SetToMercator(20.0, -45.0, 1.0, 100.0, 200.0);
  RoundTrips(p, "Mercator phi1 45 S");
  p->SetToPolarStereographic(-60.0, 45.0, 1.0, 1e5, -1e5);
  RoundTrips(p, "polar stereographic 60 S");

  std::printf("Longitude domains:\n");
  p->SetFromEPSG(4326);
  p->Forward(-10.0, 5.0, xy);
  Expect(xy[0] == -10.0 && xy[1] == 5.0, "EPSG:4326 -180..180: lon -10 -> x = -10");
  p->SetLongitudeDomainTo0To360();
  p->Forward(-10.0, 5.0, xy);
  Expect(xy[0] == 350.0, "EPSG:4326 0..360: lon -10 -> x = 350");
  double ll[2];
  p->Inverse(350.0, 5.0, ll);
  Expect(ll[0] == 350.0 && ll[1] == 5.0, "EPSG:4326 0..360: x = 350 -> lon 350");
  p->SetFromEPSG(3395);
  p->SetLongitudeDomainTo0To360();
  double xyWest[2];
  p->Forward(190.0, 10.0, xy);
  p->Forward(-170.0, 10.0, xyWest);
  Expect(xy[0] == xyWest[0] && xy[0] > 2.0e7, "EPSG:3395 0..360: lon -170 and 190 give x > 2e7");
  p->SetLongitudeDomainToMinus180To180();

  std::printf("Valid domains:\n");
  p->SetFromEPSG(32631);
  Expect(p->IsInValidDomain(9.0, 80.0) && !p->IsInValidDomain(14.0, 10.0) &&
      !p->IsInValidDomain(3.0, 85.0),
    "UTM 31N: 6 E 80 N inside; 14 E and 85 N outside");
  p->SetFromEPSG(3413);
  Expect(p->IsInValidDomain(-170.0, 1.0) && !p->IsInValidDomain(0.0, -1.0),
    "EPSG:3413: the northern hemisphere");
  p->SetFromEPSG(3857);
  Expect(p->IsInValidDomain(179.0, 85.0) && !p->IsInValidDomain(0.0, 85.1),
    "EPSG:3857: up to 85.0511");

  std::printf("Rasters that wrap east-west:\n");
  const double turn = 2.0 * 3.14159265358979323846 * 6378137.0;
  Expect(vtkGlobeMapProjection::SpansAllLongitudes(3857, turn / 256, 256) &&
      vtkGlobeMapProjection::SpansAllLongitudes(4087, turn / 1000, 1000) &&
      vtkGlobeMapProjection::SpansAllLongitudes(3395, turn / 100, 100),
    "EPSG:3857, 4087 and 3395 rasters one whole turn wide wrap");
  Expect(vtkGlobeMapProjection::SpansAllLongitudes(3857, turn / 256 * (1 - 0.4 / 256), 256) &&
      !vtkGlobeMapProjection::SpansAllLongitudes(3857, turn / 256 * (1 - 0.6 / 256), 256),
    "EPSG:3857: a raster 0.4 pixel short of a turn wraps, 0.6 pixel short does not");
  Expect(!vtkGlobeMapProjection::SpansAllLongitudes(3857, turn / 256 * (1 + 0.6 / 256), 256) &&
      !vtkGlobeMapProjection::SpansAllLongitudes(3857, turn / 256 * 1.5, 256),
    "EPSG:3857: 0.6 pixel or half a turn too wide does not wrap (the overlap would misregister)");
  Expect(vtkGlobeMapProjection::IsGlobalRaster(true, 4326, 360.0 / 2048, 2048) &&
      !vtkGlobeMapProjection::IsGlobalRaster(true, 4326, 0.1, 3599) &&
      vtkGlobeMapProjection::IsGlobalRaster(false, 4087, turn / 1000, 1000),
    "IsGlobalRaster: geographic 360 degrees yes, 359.9 no; projected by SpansAllLongitudes");
  Expect(!vtkGlobeMapProjection::SpansAllLongitudes(3413, 1e5, 1000) &&
      !vtkGlobeMapProjection::SpansAllLongitudes(32633, 1e5, 1000) && !observer->GetError(),
    "polar stereographic and UTM rasters never wrap");
  Expect(!vtkGlobeMapProjection::SpansAllLongitudes(12345, 1.0, 1000) && !observer->GetError(),
    "an unknown EPSG code does not wrap (and says nothing)");
  p->SetToEquirectangular(0.0, 60.0);
  Expect(p->SpansAllLongitudes(turn / 2 / 512, 512) && !p->SpansAllLongitudes(turn / 2 / 512, 500),
    "equirectangular with a 60 degree standard parallel: a turn is half the equator");

  // IOGP GN 7-2, Lambert Conic Conformal (1SP): JAD69 / Jamaica National Grid (Clarke 1866).
  p->SetToLambertConformalConic1SP(18.0, -77.0, 1.0, 250000.0, 150000.0);
  p->SetEllipsoid(6378206.400, 1.0 / 294.978698213898);
  ExpectPoint(p, "LCC 1SP, Jamaica (GN 7-2)", -Dms(76, 56, 37.26), Dms(17, 55, 55.80), 255966.58,
    142493.51, 0.01);
  // IOGP GN 7-2, Lambert Conic Conformal (2SP): NAD27 / Texas South Central, in US feet.
  const double usFoot = 1200.0 / 3937.0;
  p->SetToLambertConformalConic(Dms(28, 23, 0), Dms(30, 17, 0), Dms(27, 50, 0), -99.0,
    2000000.0 * usFoot, 0.0);
  p->SetEllipsoid(6378206.400, 1.0 / 294.978698213898);
  ExpectPoint(p, "LCC 2SP, Texas South Central (GN 7-2)", -96.0, 28.5, 2963503.91 * usFoot,
    254759.80 * usFoot, 0.01 * usFoot);

  // The table's own codes, then codes from PROJ's database.
  struct Code
  {
    int EPSG;
    int Kind;
    const char* Name;
  };
  const Code againstPROJ[] = {
    { 4087, vtkGlobeMapProjection::Equirectangular, "WGS 84 / World Equidistant Cylindrical" },
    { 3395, vtkGlobeMapProjection::Mercator, "WGS 84 / World Mercator" },
    { 3857, vtkGlobeMapProjection::WebMercator, "WGS 84 / Pseudo-Mercator" },
    { 3413, vtkGlobeMapProjection::PolarStereographic, "NSIDC Sea Ice Polar Stereographic North" },
    { 3031, vtkGlobeMapProjection::PolarStereographic, "Antarctic Polar Stereographic" },
    { 32661, vtkGlobeMapProjection::PolarStereographic, "UPS North" },
    { 32631, vtkGlobeMapProjection::TransverseMercator, "UTM zone 31N" },
    { 32760, vtkGlobeMapProjection::TransverseMercator, "UTM zone 60S" },
    { 2154, vtkGlobeMapProjection::LambertConformalConic, "RGF93 / Lambert-93" },
    { 3034, vtkGlobeMapProjection::LambertConformalConic, "ETRS89 / LCC Europe" },
    { 3112, vtkGlobeMapProjection::LambertConformalConic, "GDA94 / Geoscience Australia Lambert" },
    { 5070, vtkGlobeMapProjection::AlbersEqualArea, "NAD83 / Conus Albers" },
    { 3577, vtkGlobeMapProjection::AlbersEqualArea, "GDA94 / Australian Albers" },
    { 6931, vtkGlobeMapProjection::LambertAzimuthalEqualArea, "EASE-Grid 2.0 North" },
    { 6932, vtkGlobeMapProjection::LambertAzimuthalEqualArea, "EASE-Grid 2.0 South" },
    { 3035, vtkGlobeMapProjection::LambertAzimuthalEqualArea, "ETRS89-extended / LAEA Europe" },
    { 6933, vtkGlobeMapProjection::CylindricalEqualArea, "EASE-Grid 2.0 Global" },
    { 25832, vtkGlobeMapProjection::TransverseMercator, "ETRS89 / UTM zone 32N" },
    { 2193, vtkGlobeMapProjection::TransverseMercator, "NZGD2000 / NZTM 2000" },
    { 3347, vtkGlobeMapProjection::LambertConformalConic, "NAD83 / Statistics Canada Lambert" },
  };
  std::printf("The table's codes, then codes from PROJ's database, against PROJ:\n");
  for (const Code& c : againstPROJ)
  {
    ExpectLikePROJ(c.EPSG, c.Kind, c.Name);
  }
  // MODIS's sinusoidal grid has no EPSG code: its PROJ string, and the same as WKT.
  const char* modis = "+proj=sinu +lon_0=0 +x_0=0 +y_0=0 +R=6371007.181 +units=m +no_defs +type=crs";
  ExpectLikePROJ(0, vtkGlobeMapProjection::Sinusoidal, "MODIS sinusoidal, PROJ string", modis);
  {
    PJ_CONTEXT* ctx = proj_context_create();
    PJ* crs = proj_create(ctx, modis);
    const std::string wkt = crs ? proj_as_wkt(ctx, crs, PJ_WKT1_GDAL, nullptr) : "";
    proj_destroy(crs);
    proj_context_destroy(ctx);
    ExpectLikePROJ(0, vtkGlobeMapProjection::Sinusoidal, "MODIS sinusoidal, WKT1", wkt.c_str());
    vtkNew<vtkGlobeMapProjection> q;
    q->SetFromDefinition(modis);
    RoundTrips(q, "MODIS sinusoidal");
    q->AddObserver(vtkCommand::ErrorEvent, observer);
    // The ellipsoidal sinusoidal (ESRI:54008, World Sinusoidal on WGS 84) is not the sphere's.
    Expect(!q->SetFromDefinition("ESRI:54008") && ErrorSaid(observer, "ESRI:54008") &&
        q->GetKind() == vtkGlobeMapProjection::Sinusoidal && q->GetSemiMajorAxis() == 6371007.181,
      "ESRI:54008 (ellipsoidal sinusoidal) refused with an error naming it; MODIS kept");
    Expect(!q->SetFromDefinition("+proj=nonsense") && ErrorSaid(observer, "nonsense"),
      "SetFromDefinition('+proj=nonsense') refused with an error naming it");
    Expect(!q->SetFromDefinition("") && ErrorSaid(observer, "SetFromDefinition"),
      "SetFromDefinition('') refused");
  }
  for (int code : { 27700, 8857, 2056 })
  {
    vtkNew<vtkGlobeMapProjection> q;
    q->AddObserver(vtkCommand::ErrorEvent, observer);
    char text[200];
    std::snprintf(text, sizeof(text), "EPSG:%d (%s) refused with an error naming it", code,
      code == 27700 ? "OSGB 36: PROJ shifts its datum"
                    : code == 8857 ? "Equal Earth" : "oblique Mercator");
    Expect(!q->SetFromEPSG(code) && ErrorSaid(observer, "EPSG:" + std::to_string(code)) &&
        q->GetEPSG() == 4326,
      text);
  }
  for (int code : { 2154, 3112, 5070, 3577, 6931, 6932, 6933, 3035 })
  {
    const std::string what = "EPSG:" + std::to_string(code);
    Expect(p->SetFromEPSG(code), "SetFromEPSG(" + std::to_string(code) + ")");
    RoundTrips(p, what.c_str());
  }

  std::printf("Bad input:\n");
  p->SetFromEPSG(3413);
  Expect(!p->SetFromEPSG(12345) && ErrorSaid(observer, "EPSG:12345") &&
      p->GetEPSG() == 3413 && p->GetKind() == vtkGlobeMapProjection::PolarStereographic,
    "SetFromEPSG(12345) refused with an error naming it; EPSG:3413 kept");
  Expect(p->SetFromEPSG(32761) && !observer->GetError(), "SetFromEPSG(32761) (UPS South) accepted");
  Expect(!p->SetFromEPSG(32600) && ErrorSaid(observer, "EPSG:32600"), "SetFromEPSG(32600) refused");
  Expect(!p->SetFromEPSG(32761 + 100) && ErrorSaid(observer, "EPSG:32861"), "SetFromEPSG(32861) refused");
  Expect(!p->SetToUTM(61, true) && ErrorSaid(observer, "zone 61"), "SetToUTM(61) refused");
  Expect(!p->SetEllipsoid(-1.0, 0.0) && ErrorSaid(observer, "semi-major axis") &&
      p->GetSemiMajorAxis() == 6378137.0,
    "SetEllipsoid(-1, 0) refused, WGS84 kept");
  Expect(!p->SetEllipsoid(6e6, 1.5) && ErrorSaid(observer, "flattening"), "SetEllipsoid(6e6, 1.5) refused");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Expect(!p->Forward(nan, 10.0, xy) && std::isnan(xy[0]) && std::isnan(xy[1]) &&
      ErrorSaid(observer, "Forward"),
    "Forward(NaN, 10): false, NaN, error");
  Expect(!p->Forward(0.0, 90.5, xy) && ErrorSaid(observer, "90.5"), "Forward(0, 90.5): false, error");
  Expect(!p->Inverse(std::numeric_limits<double>::infinity(), 0.0, ll) && std::isnan(ll[0]) &&
      ErrorSaid(observer, "Inverse"),
    "Inverse(inf, 0): false, NaN, error");
  p->SetFromEPSG(4087);
  Expect(!p->Inverse(0.0, 1.2e7, ll) && ErrorSaid(observer, "outside"),
    "EPSG:4087 Inverse(0, 1.2e7) (beyond the pole): false, error");
  float parameters[28];
  const double origin[2] = { 0.0, 0.0 }, badPixel[2] = { 0.0, 1.0 }, pixel[2] = { 1.0, 1.0 };
  Expect(!p->ComputeShaderParameters(origin, badPixel, 10, 10, parameters) &&
      std::isnan(parameters[0]) && ErrorSaid(observer, "pixel"),
    "ComputeShaderParameters with a zero pixel size: false, NaN, error");
  Expect(!p->ComputeShaderParameters(origin, pixel, 0, 10, parameters) &&
      ErrorSaid(observer, "0 x 10"),
    "ComputeShaderParameters with 0 x 10 pixels: false, error");
  p->SetFromEPSG(4326);
  const double farOrigin[2] = { 0.0, 500.0 };
  Expect(!p->ComputeShaderParameters(farOrigin, pixel, 10, 10, parameters) &&
      ErrorSaid(observer, "outside"),
    "EPSG:4326 raster centred at latitude 495: false, error");

  p->Print(std::cout);
  return Checks.Result();
}
