#include "vtkGlobeMapProjection.h"
#include "vtkGlobeShaderMath.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <GeographicLib/AlbersEqualArea.hpp>
#include <GeographicLib/LambertConformalConic.hpp>
#include <GeographicLib/PolarStereographic.hpp>
#include <GeographicLib/TransverseMercator.hpp>

#include <proj.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkGlobeMapProjection);

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Deg = Pi / 180.0;
const double NaN = std::numeric_limits<double>::quiet_NaN();

bool Finite(double v)
{
  return std::isfinite(v);
}

// The longitude in [west, west + 360).
double WrapInto(double lon, double west)
{
  double d = std::fmod(lon - west, 360.0);
  if (d < 0.0)
  {
    d += 360.0;
  }
  return west + d;
}

// hi = the nearest float, lo = the rest (exact in double, nearly exact in float).
void Split(double v, double& hi, double& lo)
{
  hi = static_cast<double>(static_cast<float>(v));
  lo = v - hi;
}

bool IsCylindrical(int kind)
{
  return kind == vtkGlobeMapProjection::Geographic ||
    kind == vtkGlobeMapProjection::Equirectangular || kind == vtkGlobeMapProjection::Mercator ||
    kind == vtkGlobeMapProjection::WebMercator ||
    kind == vtkGlobeMapProjection::CylindricalEqualArea;
}

// Cylindrical equal-area: the scale along the equator that makes it 1 on the standard parallel.
double CylindricalEqualAreaScale(double f, double standardParallel)
{
  const double e2 = f * (2.0 - f), s = std::sin(standardParallel * Deg);
  return std::cos(standardParallel * Deg) / std::sqrt(1.0 - e2 * s * s);
}

// The conics in map coordinates, with the false origin: GeographicLib's y is 0 at its own
// origin (the cone's latitude of tangency), the false northing belongs to the latitude of
// origin. One standard parallel (with a scale there) when both are equal, else two (scale 1
// on both); polar Lambert azimuthal equal-area is the Albers conic with its standard parallel
// at the pole. A cone with its apex at the south pole is computed as the mirror image of the
// northern one (y -> -y, exact by symmetry): GeographicLib 1.51's AlbersEqualArea put
// EPSG:3577's (140 E, 30 S) 6.2 Mm from PROJ's point.
class Conic
{
public:
  Conic(bool conformal, double a, double f, double phi1, double phi2, double k, double lat0,
    double lon0, double fe, double fn)
    : Mirror(phi1 + phi2 >= 0.0 ? 1.0 : -1.0)
    , Lon0(lon0)
    , FE(fe)
    , FN(fn)
  {
    phi1 *= this->Mirror;
    phi2 *= this->Mirror;
    if (conformal)
    {
      this->LCC = phi1 == phi2
        ? std::make_unique<GeographicLib::LambertConformalConic>(a, f, phi1, k)
        : std::make_unique<GeographicLib::LambertConformalConic>(a, f, phi1, phi2, 1.0);
    }
    else
    {
      this->Albers = phi1 == phi2
        ? std::make_unique<GeographicLib::AlbersEqualArea>(a, f, phi1, 1.0)
        : std::make_unique<GeographicLib::AlbersEqualArea>(a, f, phi1, phi2, 1.0);
    }
    double x0 = 0.0, gamma = 0.0;
    this->Raw(this->Mirror * lat0, lon0, x0, this->Y0, gamma);
  }
  // Map (x, y) of (lat, lon) in degrees; n: the cone constant (meridian convergence per
  // degree of longitude).
  void Forward(double lat, double lon, double& x, double& y) const
  {
    double gamma = 0.0;
    this->Raw(this->Mirror * lat, lon, x, y, gamma);
    x += this->FE;
    y = this->FN + this->Mirror * (y - this->Y0);
  }
  double ConeConstant(double lat) const
  {
    double x = 0.0, y = 0.0, gamma = 0.0;
    this->Raw(this->Mirror * lat, this->Lon0 + 1.0, x, y, gamma);
    return std::abs(gamma);
  }
  // The map northing of the cone's apex, the centre of the parallels' circles, from the
  // radius rho = k a m / n (Snyder 14-16, 15-4) of the parallel at `lat` (north of it for a
  // northern cone). The pole is the apex of a conformal conic and of the azimuthal
  // projection, but an arc around it on an Albers conic with two standard parallels.
  double ApexNorthing(double a, double f, double lat) const
  {
    double x = 0.0, y = 0.0, gamma = 0.0, k = 1.0;
    const double latM = this->Mirror * lat;
    if (this->LCC)
    {
      this->LCC->Forward(this->Lon0, latM, this->Lon0, x, y, gamma, k);
    }
    else
    {
      this->Albers->Forward(this->Lon0, latM, this->Lon0, x, y, gamma, k);
    }
    const double e2 = f * (2.0 - f), s = std::sin(latM * Deg);
    const double m = std::cos(latM * Deg) / std::sqrt(1.0 - e2 * s * s);
    const double rho = k * a * m / this->ConeConstant(lat);
    return this->FN + this->Mirror * (y + rho - this->Y0);
  }
  // False where GeographicLib's inverse does not project back to (x, y): it returns the
  // nearest pole for points outside the image (beyond the cone's cut, the azimuthal disc).
  bool Reverse(double x, double y, double& lat, double& lon) const
  {
    const double xm = x - this->FE, ym = this->Mirror * (y - this->FN) + this->Y0;
    double gamma = 0.0, k = 1.0, xb = 0.0, yb = 0.0;
    if (this->LCC)
    {
      this->LCC->Reverse(this->Lon0, xm, ym, lat, lon, gamma, k);
    }
    else
    {
      this->Albers->Reverse(this->Lon0, xm, ym, lat, lon, gamma, k);
    }
    this->Raw(lat, lon, xb, yb, gamma);
    lat *= this->Mirror;
    // On the cut (180 degrees from the central meridian) a longitude has two images.
    const bool cut = std::abs(std::remainder(lon - this->Lon0, 360.0)) > 180.0 - 1e-7;
    return cut || std::hypot(xb - xm, yb - ym) <= 1e-6 * (1.0 + std::hypot(xb, yb));
  }

private:
  void Raw(double lat, double lon, double& x, double& y, double& gamma) const
  {
    double k = 1.0;
    if (this->LCC)
    {
      this->LCC->Forward(this->Lon0, lat, lon, x, y, gamma, k);
    }
    else
    {
      this->Albers->Forward(this->Lon0, lat, lon, x, y, gamma, k);
    }
  }
  double Mirror, Lon0, FE, FN, Y0 = 0.0;
  std::unique_ptr<GeographicLib::LambertConformalConic> LCC;
  std::unique_ptr<GeographicLib::AlbersEqualArea> Albers;
};

Conic MakeConic(vtkGlobeMapProjection* p)
{
  return Conic(p->GetKind() == vtkGlobeMapProjection::LambertConformalConic,
    p->GetSemiMajorAxis(), p->GetFlattening(), p->GetStandardParallel(),
    p->GetStandardParallel2(), p->GetScaleFactor(), p->GetLatitudeOfOrigin(),
    p->GetCentralMeridian(), p->GetFalseEasting(), p->GetFalseNorthing());
}

// The authalic function q of sin(lat) (Snyder 3-12), e2 the squared eccentricity.
double AuthalicQ(double e2, double s)
{
  const double e = std::sqrt(e2);
  return (1.0 - e2) * (s / (1.0 - e2 * s * s) + (e > 0.0 ? std::atanh(e * s) / e : s));
}

// Lambert azimuthal equal-area in an oblique or equatorial aspect on the ellipsoid (Snyder,
// USGS PP 1395, eqs. 3-12, 24-19 to 24-21 and 24-25 to 24-30): the spherical azimuthal
// projection of the authalic sphere (radius Rq, authalic latitude beta, sin beta = q / q_p),
// stretched by D along x and 1 / D along y so that the centre keeps scale 1 on its meridian and
// parallel. GeographicLib has the polar aspect only (AlbersEqualArea).
class ObliqueAzimuthal
{
public:
  ObliqueAzimuthal(double a, double f, double lat0, double lon0, double fe, double fn)
    : E2(f * (2.0 - f))
    , E(std::sqrt(f * (2.0 - f)))
    , Lat0(lat0)
    , Lon0(lon0)
    , FE(fe)
    , FN(fn)
  {
    this->Qp = this->Q(1.0);
    this->Rq = a * std::sqrt(0.5 * this->Qp);
    const double s0 = std::sin(lat0 * Deg);
    this->SinB1 = this->Q(s0) / this->Qp;
    this->CosB1 = this->CosBeta(lat0);
    this->D = a * std::cos(lat0 * Deg) / std::sqrt(1.0 - this->E2 * s0 * s0) / (this->Rq * this->CosB1);
  }
  double Q(double s) const { return AuthalicQ(this->E2, s); }
  // 1 + cos of the angle from the centre on the authalic sphere: the oblique aspects' valid
  // domain leaves out a cap of 5 degrees around the antipode, which maps to the image's rim
  // (radial scale cos(c / 2) -> 0: the inverse loses its accuracy there).
  double OnePlusCosFromCentre(double lat, double lon) const
  {
    return 1.0 + this->SinB1 * this->SinBeta(lat) +
      this->CosB1 * this->CosBeta(lat) * std::cos((lon - this->Lon0) * Deg);
  }
  static constexpr double AntipodeCap = 0.0038053019082548; // 1 - cos(5 degrees)
  double SinBeta(double lat) const { return this->Q(std::sin(lat * Deg)) / this->Qp; }
  // cos(beta), relatively accurate up to the poles: from 1 - |sin beta| = (q_p - |q|) / q_p,
  // with q_p - q from 1 - |sin lat| = cos^2 / (1 + |sin lat|) through the shaders' own
  // difference formula (its double mirror), as the GPU computes it.
  double CosBeta(double lat) const
  {
    const double s = std::abs(std::sin(lat * Deg)), c = std::cos(lat * Deg);
    const double t = (1.0 - this->E2) *
      vtkGlobeShaderMath::d::globe_equalAreaDifference(c * c / (1.0 + s), 1.0, s, this->E) /
      this->Qp;
    return std::sqrt(std::max(0.0, t * (2.0 - t)));
  }
  // False at the antipode of the centre, which has no image.
  bool Forward(double lat, double lon, double& x, double& y) const
  {
    const double sb = this->SinBeta(lat), cb = this->CosBeta(lat);
    const double dl = (lon - this->Lon0) * Deg;
    const double vz = this->SinB1 * sb + this->CosB1 * cb * std::cos(dl);
    if (!(1.0 + vz > 1e-15))
    {
      return false;
    }
    const double k = std::sqrt(2.0 / (1.0 + vz));
    x = this->FE + this->Rq * this->D * k * cb * std::sin(dl);
    y = this->FN + this->Rq / this->D * k * (this->CosB1 * sb - this->SinB1 * cb * std::cos(dl));
    return true;
  }
  // False outside the image (the disc of radius 2 Rq on the authalic sphere's azimuthal plane).
  bool Reverse(double x, double y, double& lat, double& lon) const
  {
    const double X = (x - this->FE) / (this->Rq * this->D), Y = (y - this->FN) * this->D / this->Rq;
    const double rho = std::hypot(X, Y);
    if (!(rho <= 2.0))
    {
      return false;
    }
    if (rho == 0.0)
    {
      lat = this->Lat0;
      lon = this->Lon0;
      return true;
    }
    const double c = 2.0 * std::asin(0.5 * rho), sc = std::sin(c), cc = std::cos(c);
    const double sb = std::max(-1.0, std::min(1.0, cc * this->SinB1 + Y * sc * this->CosB1 / rho));
    lon = this->Lon0 + std::atan2(X * sc, rho * this->CosB1 * cc - Y * this->SinB1 * sc) / Deg;
    lat = this->Latitude(sb * this->Qp);
    return true;
  }
  // The latitude whose authalic function is q: Newton's method on q (Snyder 3-16), from the
  // sphere's value.
  double Latitude(double q) const
  {
    if (std::abs(q) >= this->Qp)
    {
      return q > 0.0 ? 90.0 : -90.0;
    }
    double phi = std::asin(std::max(-1.0, std::min(1.0, 0.5 * q)));
    for (int i = 0; i < 20; ++i)
    {
      const double s = std::sin(phi), c = std::cos(phi);
      if (!(c > 1e-12))
      {
        break;
      }
      const double w = 1.0 - this->E2 * s * s;
      const double step = w * w / (2.0 * c) * (q - this->Q(s)) / (1.0 - this->E2);
      phi += step;
      if (std::abs(step) < 1e-15)
      {
        break;
      }
    }
    return std::max(-90.0, std::min(90.0, phi / Deg));
  }
  double E2, E, Lat0, Lon0, FE, FN, Qp = 0.0, Rq = 0.0, SinB1 = 0.0, CosB1 = 1.0, D = 1.0;
};

ObliqueAzimuthal MakeObliqueAzimuthal(vtkGlobeMapProjection* p)
{
  return ObliqueAzimuthal(p->GetSemiMajorAxis(), p->GetFlattening(), p->GetLatitudeOfOrigin(),
    p->GetCentralMeridian(), p->GetFalseEasting(), p->GetFalseNorthing());
}

// What SetFromPROJ found for one CRS (cached: PROJ's database is read once per CRS).
struct PROJDefinition
{
  bool Usable = false;
  int Kind = 0;
  double A = 0.0, F = 0.0;
  double CentralMeridian = 0.0, StandardParallel = 0.0, StandardParallel2 = 0.0;
  double LatitudeOfTrueScale = 90.0, ScaleFactor = 1.0, LatitudeOfOrigin = 0.0;
  double FalseEasting = 0.0, FalseNorthing = 0.0;
  // The CRS's area of use (degrees), where the definition is checked against PROJ.
  double Area[4] = { 0.0, 0.0, 0.0, 0.0 };
};

std::mutex PROJMutex;
std::map<std::string, PROJDefinition>& PROJDefinitions()
{
  static std::map<std::string, PROJDefinition> definitions;
  return definitions;
}

// A PROJ context and the objects made in it, released together.
struct PROJScope
{
  PJ_CONTEXT* Context = proj_context_create();
  std::vector<PJ*> Objects;
  PROJScope() { proj_log_level(this->Context, PJ_LOG_NONE); }
  ~PROJScope()
  {
    for (PJ* o : this->Objects)
    {
      proj_destroy(o);
    }
    proj_context_destroy(this->Context);
  }
  PJ* Keep(PJ* o)
  {
    if (o)
    {
      this->Objects.push_back(o);
    }
    return o;
  }
};

// +-90 for a latitude within rounding of a pole (PROJ gives degrees through radians).
double Pole(double lat)
{
  return std::abs(std::abs(lat) - 90.0) < 1e-9 ? std::copysign(90.0, lat) : lat;
}

// The conversion's parameters by EPSG parameter code, in degrees and metres, of the CRS PROJ
// makes from `name` ("EPSG:code", a PROJ string, WKT).
bool ReadPROJDefinition(const std::string& name, PROJDefinition& d)
{
  PROJScope scope;
  PJ_CONTEXT* ctx = scope.Context;
  PJ* crs = scope.Keep(proj_create(ctx, name.c_str()));
  if (!crs || proj_get_type(crs) != PJ_TYPE_PROJECTED_CRS)
  {
    return false;
  }
  // Easting and northing in metres: the raster's map units are then the projection's.
  PJ* cs = scope.Keep(proj_crs_get_coordinate_system(ctx, crs));
  if (!cs || proj_cs_get_axis_count(ctx, cs) != 2)
  {
    return false;
  }
  for (int i = 0; i < 2; ++i)
  {
    double factor = 0.0;
    if (!proj_cs_get_axis_info(ctx, cs, i, nullptr, nullptr, nullptr, &factor, nullptr,
          nullptr, nullptr) ||
      factor != 1.0)
    {
      return false;
    }
  }
  PJ* ellipsoid = scope.Keep(proj_get_ellipsoid(ctx, crs));
  double a = 0.0, b = 0.0, inverseFlattening = 0.0;
  int computed = 0;
  if (!ellipsoid ||
    !proj_ellipsoid_get_parameters(ctx, ellipsoid, &a, &b, &computed, &inverseFlattening))
  {
    return false;
  }
  d.A = a;
  d.F = (a - b) / a;
  PJ* conversion = scope.Keep(proj_crs_get_coordoperation(ctx, crs));
  const char* methodName = nullptr;
  const char* methodCode = nullptr;
  if (!conversion ||
    !proj_coordoperation_get_method_info(ctx, conversion, &methodName, nullptr, &methodCode) ||
    !(methodCode || methodName))
  {
    return false;
  }
  std::map<int, double> values;
  const int count = proj_coordoperation_get_param_count(ctx, conversion);
  for (int i = 0; i < count; ++i)
  {
    const char* parameterCode = nullptr;
    const char* category = nullptr;
    double value = NaN, toSI = NaN;
    if (!proj_coordoperation_get_param(ctx, conversion, i, nullptr, nullptr, &parameterCode,
          &value, nullptr, &toSI, nullptr, nullptr, nullptr, &category) ||
      !parameterCode || !category)
    {
      return false;
    }
    const std::string c = category;
    values[std::atoi(parameterCode)] = c == "angular" ? value * toSI / Deg
      : (c == "linear" || c == "scale")                ? value * toSI
                                                       : NaN;
  }
  auto get = [&](std::initializer_list<int> codes, double fallback) {
    for (int c : codes)
    {
      auto it = values.find(c);
      if (it != values.end())
      {
        return it->second;
      }
    }
    return fallback;
  };
  // EPSG parameters: 8801/8802 latitude/longitude of natural origin, 8805 its scale,
  // 8806/8807 false easting/northing, 8821/8822 latitude/longitude of false origin, 8823/8824
  // first/second standard parallel, 8826/8827 easting/northing at the false origin, 8832
  // latitude and 8833 longitude of the standard parallel's origin (polar stereographic B).
  d.FalseEasting = get({ 8806, 8826 }, 0.0);
  d.FalseNorthing = get({ 8807, 8827 }, 0.0);
  d.CentralMeridian = get({ 8802, 8822, 8833 }, 0.0);
  // Methods without an EPSG code go by PROJ's name for them.
  const int method = methodCode ? std::atoi(methodCode)
    : std::string(methodName) == "Sinusoidal" ? -1
                                               : 0;
  switch (method)
  {
    case -1: // sinusoidal: the spherical formulas only (MODIS), as PROJ's +R
      if (d.F != 0.0)
      {
        return false;
      }
      d.Kind = vtkGlobeMapProjection::Sinusoidal;
      break;
    case 9807: // transverse Mercator
      d.Kind = vtkGlobeMapProjection::TransverseMercator;
      d.LatitudeOfOrigin = get({ 8801 }, NaN);
      d.ScaleFactor = get({ 8805 }, NaN);
      break;
    case 9810: // polar stereographic (variant A): the scale at the pole
    {
      const double lat0 = Pole(get({ 8801 }, NaN));
      if (std::abs(lat0) != 90.0)
      {
        return false;
      }
      d.Kind = vtkGlobeMapProjection::PolarStereographic;
      d.LatitudeOfTrueScale = lat0;
      d.ScaleFactor = get({ 8805 }, NaN);
      break;
    }
    case 9829: // polar stereographic (variant B): true scale at a standard parallel
      d.Kind = vtkGlobeMapProjection::PolarStereographic;
      d.LatitudeOfTrueScale = get({ 8832 }, NaN);
      d.ScaleFactor = 1.0;
      break;
    case 9804: // Mercator (variant A): the scale on the equator
      d.Kind = vtkGlobeMapProjection::Mercator;
      d.ScaleFactor = get({ 8805 }, NaN);
      break;
    case 9805: // Mercator (variant B): true scale on a standard parallel
      d.Kind = vtkGlobeMapProjection::Mercator;
      d.StandardParallel = get({ 8823 }, NaN);
      break;
    case 9801: // Lambert conformal conic (1SP)
      d.Kind = vtkGlobeMapProjection::LambertConformalConic;
      d.LatitudeOfOrigin = d.StandardParallel = d.StandardParallel2 = get({ 8801 }, NaN);
      d.ScaleFactor = get({ 8805 }, NaN);
      break;
    case 9802: // Lambert conformal conic (2SP)
    case 9822: // Albers equal area
      d.Kind = method == 9802 ? vtkGlobeMapProjection::LambertConformalConic
                              : vtkGlobeMapProjection::AlbersEqualArea;
      d.LatitudeOfOrigin = get({ 8821 }, NaN);
      d.StandardParallel = get({ 8823 }, NaN);
      d.StandardParallel2 = get({ 8824 }, NaN);
      break;
    case 9820: // Lambert azimuthal equal area: any aspect
    {
      const double lat0 = Pole(get({ 8801 }, NaN));
      d.Kind = vtkGlobeMapProjection::LambertAzimuthalEqualArea;
      d.LatitudeOfOrigin = d.StandardParallel = d.StandardParallel2 = lat0;
      break;
    }
    case 9835: // Lambert cylindrical equal area
      d.Kind = vtkGlobeMapProjection::CylindricalEqualArea;
      d.StandardParallel = get({ 8823 }, NaN);
      break;
    default:
      return false;
  }
  for (double v : { d.CentralMeridian, d.StandardParallel, d.StandardParallel2,
         d.LatitudeOfTrueScale, d.ScaleFactor, d.LatitudeOfOrigin, d.FalseEasting,
         d.FalseNorthing })
  {
    if (!Finite(v))
    {
      return false;
    }
  }
  double west = -180.0, south = -90.0, east = 180.0, north = 90.0;
  if (proj_get_area_of_use(ctx, crs, &west, &south, &east, &north, nullptr) && west > -1000.0)
  {
    d.Area[0] = west;
    d.Area[1] = east < west ? east + 360.0 : east;
    d.Area[2] = south;
    d.Area[3] = north;
  }
  else
  {
    d.Area[0] = -180.0;
    d.Area[1] = 180.0;
    d.Area[2] = -90.0;
    d.Area[3] = 90.0;
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkGlobeMapProjection::vtkGlobeMapProjection() = default;
vtkGlobeMapProjection::~vtkGlobeMapProjection() = default;

//------------------------------------------------------------------------------
const char* vtkGlobeMapProjection::GetKindAsString()
{
  switch (this->Kind)
  {
    case Geographic:
      return "Geographic";
    case Equirectangular:
      return "Equirectangular";
    case PolarStereographic:
      return "PolarStereographic";
    case Mercator:
      return "Mercator";
    case WebMercator:
      return "WebMercator";
    case TransverseMercator:
      return "TransverseMercator";
    case LambertConformalConic:
      return "LambertConformalConic";
    case AlbersEqualArea:
      return "AlbersEqualArea";
    case LambertAzimuthalEqualArea:
      return "LambertAzimuthalEqualArea";
    case CylindricalEqualArea:
      return "CylindricalEqualArea";
    case Sinusoidal:
      return "Sinusoidal";
  }
  return "unknown";
}

//------------------------------------------------------------------------------
bool vtkGlobeMapProjection::SetEllipsoid(double semiMajorAxis, double flattening)
{
  if (!Finite(semiMajorAxis) || !(semiMajorAxis > 0.0) || !Finite(flattening) ||
    !(flattening >= 0.0) || !(flattening < 1.0))
  {
    vtkErrorMacro(<< "SetEllipsoid: the semi-major axis must be finite and positive and the "
                     "flattening in [0, 1); got a = "
                  << semiMajorAxis << ", f = " << flattening << ". The ellipsoid is unchanged.");
    return false;
  }
  this->SemiMajorAxis = semiMajorAxis;
  this->Flattening = flattening;
  this->EPSG = 0;
  this->Modified();
  return true;
}

void vtkGlobeMapProjection::SetEllipsoidToWGS84()
{
  this->SetEllipsoid(6378137.0, 1.0 / 298.257223563);
}

//------------------------------------------------------------------------------
void vtkGlobeMapProjection::SetParameters(int kind, double centralMeridian,
  double standardParallel, double latitudeOfTrueScale, double scaleFactor,
  double latitudeOfOrigin, double falseEasting, double falseNorthing)
{
  // Every parameter is set, the ones the kind does not use to their neutral values, so no
  // earlier projection's values linger in the state (or in PrintSelf).
  this->Kind = kind;
  this->CentralMeridian = centralMeridian;
  this->StandardParallel = standardParallel;
  this->StandardParallel2 = standardParallel;
  this->LatitudeOfTrueScale = latitudeOfTrueScale;
  this->ScaleFactor = scaleFactor;
  this->LatitudeOfOrigin = latitudeOfOrigin;
  this->FalseEasting = falseEasting;
  this->FalseNorthing = falseNorthing;
  this->UTM = false;
  this->EPSG = 0;
  this->Modified();
}

void vtkGlobeMapProjection::SetToGeographic()
{
  this->SetParameters(Geographic, 0.0, 0.0, 90.0, 1.0, 0.0, 0.0, 0.0);
}

void vtkGlobeMapProjection::SetToEquirectangular(
  double centralMeridian, double standardParallel, double falseEasting, double falseNorthing)
{
  this->SetParameters(
    Equirectangular, centralMeridian, standardParallel, 90.0, 1.0, 0.0, falseEasting, falseNorthing);
}

void vtkGlobeMapProjection::SetToPolarStereographic(double latitudeOfTrueScale,
  double centralMeridian, double scaleFactor, double falseEasting, double falseNorthing)
{
  this->SetParameters(PolarStereographic, centralMeridian, 0.0, latitudeOfTrueScale, scaleFactor,
    0.0, falseEasting, falseNorthing);
}

void vtkGlobeMapProjection::SetToMercator(double centralMeridian, double standardParallel,
  double scaleFactor, double falseEasting, double falseNorthing)
{
  this->SetParameters(Mercator, centralMeridian, standardParallel, 90.0, scaleFactor, 0.0,
    falseEasting, falseNorthing);
}

void vtkGlobeMapProjection::SetToWebMercator(double centralMeridian)
{
  this->SetParameters(WebMercator, centralMeridian, 0.0, 90.0, 1.0, 0.0, 0.0, 0.0);
}

void vtkGlobeMapProjection::SetToTransverseMercator(double centralMeridian, double scaleFactor,
  double falseEasting, double falseNorthing, double latitudeOfOrigin)
{
  this->SetParameters(TransverseMercator, centralMeridian, 0.0, 90.0, scaleFactor,
    latitudeOfOrigin, falseEasting, falseNorthing);
}

bool vtkGlobeMapProjection::SetToUTM(int zone, bool north)
{
  if (zone < 1 || zone > 60)
  {
    vtkErrorMacro(<< "SetToUTM: zone " << zone << " is not in 1..60; the projection is unchanged.");
    return false;
  }
  this->SetToTransverseMercator(6.0 * zone - 183.0, 0.9996, 500000.0, north ? 0.0 : 10000000.0);
  this->UTM = true;
  return true;
}

void vtkGlobeMapProjection::SetToLambertConformalConic(double standardParallel1,
  double standardParallel2, double latitudeOfOrigin, double centralMeridian, double falseEasting,
  double falseNorthing)
{
  this->SetToConic(LambertConformalConic, standardParallel1, standardParallel2, latitudeOfOrigin,
    centralMeridian, falseEasting, falseNorthing);
}

void vtkGlobeMapProjection::SetToConic(int kind, double standardParallel1,
  double standardParallel2, double latitudeOfOrigin, double centralMeridian, double falseEasting,
  double falseNorthing)
{
  this->SetParameters(kind, centralMeridian, standardParallel1, 90.0, 1.0, latitudeOfOrigin,
    falseEasting, falseNorthing);
  this->StandardParallel2 = standardParallel2;
}

void vtkGlobeMapProjection::SetToLambertConformalConic1SP(double latitudeOfOrigin,
  double centralMeridian, double scaleFactor, double falseEasting, double falseNorthing)
{
  this->SetParameters(LambertConformalConic, centralMeridian, latitudeOfOrigin, 90.0,
    scaleFactor, latitudeOfOrigin, falseEasting, falseNorthing);
}

void vtkGlobeMapProjection::SetToAlbersEqualArea(double standardParallel1,
  double standardParallel2, double latitudeOfOrigin, double centralMeridian, double falseEasting,
  double falseNorthing)
{
  this->SetToConic(AlbersEqualArea, standardParallel1, standardParallel2, latitudeOfOrigin,
    centralMeridian, falseEasting, falseNorthing);
}

void vtkGlobeMapProjection::SetToLambertAzimuthalEqualArea(
  double latitudeOfOrigin, double centralMeridian, double falseEasting, double falseNorthing)
{
  const double lat0 = Pole(latitudeOfOrigin);
  this->SetParameters(LambertAzimuthalEqualArea, centralMeridian, lat0, 90.0, 1.0, lat0,
    falseEasting, falseNorthing);
}

void vtkGlobeMapProjection::SetToCylindricalEqualArea(
  double standardParallel, double centralMeridian, double falseEasting, double falseNorthing)
{
  this->SetParameters(CylindricalEqualArea, centralMeridian, standardParallel, 90.0, 1.0, 0.0,
    falseEasting, falseNorthing);
}

void vtkGlobeMapProjection::SetToSinusoidal(
  double sphereRadius, double centralMeridian, double falseEasting, double falseNorthing)
{
  if (!this->SetEllipsoid(sphereRadius, 0.0))
  {
    return;
  }
  this->SetParameters(Sinusoidal, centralMeridian, 0.0, 90.0, 1.0, 0.0, falseEasting,
    falseNorthing);
}

double vtkGlobeMapProjection::GetApexHemisphere()
{
  switch (this->Kind)
  {
    case PolarStereographic:
      return this->LatitudeOfTrueScale > 0.0 ? 1.0 : -1.0;
    case LambertConformalConic:
    case AlbersEqualArea:
      return this->StandardParallel + this->StandardParallel2 >= 0.0 ? 1.0 : -1.0;
    case LambertAzimuthalEqualArea:
      return this->LatitudeOfOrigin <= -90.0 ? -1.0 : 1.0;
    default:
      return 1.0;
  }
}

bool vtkGlobeMapProjection::IsConic()
{
  return this->Kind == LambertConformalConic || this->Kind == AlbersEqualArea ||
    (this->Kind == LambertAzimuthalEqualArea && std::abs(this->LatitudeOfOrigin) == 90.0);
}

bool vtkGlobeMapProjection::HasMapCut()
{
  return this->Kind == Sinusoidal || this->IsConic();
}

//------------------------------------------------------------------------------
bool vtkGlobeMapProjection::SetFromEPSG(int code)
{
  if (!this->SetFromEPSGQuietly(code))
  {
    vtkErrorMacro(<< "SetFromEPSG: EPSG:" << code
                  << " is not a supported projection (supported: 4326, 4087, 32662, 3413, 3031, "
                     "3995, 3976, 3032, 32661, 32761, 3395, 3857, 326zz and 327zz, and codes "
                     "whose definition in PROJ's database is transverse Mercator, polar "
                     "stereographic, Mercator, Lambert conformal conic, Albers, Lambert "
                     "azimuthal equal-area or Lambert cylindrical equal-area in metres on a "
                     "datum PROJ does not shift against WGS 84); the projection is unchanged.");
    return false;
  }
  return true;
}

bool vtkGlobeMapProjection::SetFromDefinition(const char* definition)
{
  const double a = this->SemiMajorAxis, f = this->Flattening;
  if (!definition || !*definition || !this->SetFromPROJ(definition))
  {
    this->SemiMajorAxis = a;
    this->Flattening = f;
    vtkErrorMacro(<< "SetFromDefinition: '" << (definition ? definition : "(null)")
                  << "' is not a CRS this class draws (a projected CRS in metres whose method "
                     "is one of the kinds in the class description, agreeing with PROJ's own "
                     "transformation from EPSG:4326); the projection is unchanged.");
    return false;
  }
  this->EPSG = 0;
  return true;
}

bool vtkGlobeMapProjection::IsSupportedDefinition(const char* definition)
{
  vtkNew<vtkGlobeMapProjection> projection;
  return definition && *definition && projection->SetFromPROJ(definition);
}

bool vtkGlobeMapProjection::SetFromEPSGQuietly(int code)
{
  const double a = this->SemiMajorAxis, f = this->Flattening;
  this->SemiMajorAxis = 6378137.0;
  this->Flattening = 1.0 / 298.257223563;
  if (code == 4326)
  {
    this->SetToGeographic();
  }
  else if (code == 4087 || code == 32662)
  {
    this->SetToEquirectangular(0.0, 0.0);
  }
  else if (code == 3413)
  {
    this->SetToPolarStereographic(70.0, -45.0);
  }
  else if (code == 3995)
  {
    this->SetToPolarStereographic(71.0, 0.0);
  }
  else if (code == 3031)
  {
    this->SetToPolarStereographic(-71.0, 0.0);
  }
  else if (code == 3976)
  {
    this->SetToPolarStereographic(-70.0, 0.0);
  }
  else if (code == 3032)
  {
    this->SetToPolarStereographic(-71.0, 70.0, 1.0, 6000000.0, 6000000.0);
  }
  else if (code == 32661)
  {
    this->SetToPolarStereographic(90.0, 0.0, 0.994, 2000000.0, 2000000.0);
  }
  else if (code == 32761)
  {
    this->SetToPolarStereographic(-90.0, 0.0, 0.994, 2000000.0, 2000000.0);
  }
  else if (code == 3395)
  {
    this->SetToMercator(0.0, 0.0, 1.0);
  }
  else if (code == 3857 || code == 900913 || code == 3785)
  {
    this->SetToWebMercator(0.0);
  }
  else if ((code > 32600 && code <= 32660) || (code > 32700 && code <= 32760))
  {
    this->SetToUTM(code % 100, code < 32700);
  }
  else if (code <= 0 || !this->SetFromPROJ("EPSG:" + std::to_string(code)))
  {
    this->SemiMajorAxis = a;
    this->Flattening = f;
    return false;
  }
  this->EPSG = code;
  return true;
}

bool vtkGlobeMapProjection::SetFromPROJ(const std::string& name)
{
  // The definition's projection on `p` (the candidate checked against PROJ, then this one).
  const auto apply = [](vtkGlobeMapProjection* p, const PROJDefinition& d) {
    p->SemiMajorAxis = d.A;
    p->Flattening = d.F;
    p->SetParameters(d.Kind, d.CentralMeridian, d.StandardParallel, d.LatitudeOfTrueScale,
      d.ScaleFactor, d.LatitudeOfOrigin, d.FalseEasting, d.FalseNorthing);
    p->StandardParallel2 = d.StandardParallel2;
  };
  PROJDefinition d;
  {
    std::lock_guard<std::mutex> lock(PROJMutex);
    auto& definitions = PROJDefinitions();
    auto it = definitions.find(name);
    if (it != definitions.end())
    {
      d = it->second;
    }
    else
    {
      d.Usable = ReadPROJDefinition(name, d);
      // Checked against PROJ's own transformation from EPSG:4326 (with whatever datum shift
      // PROJ applies): a grid over the CRS's area of use must agree within 1 mm.
      if (d.Usable)
      {
        vtkNew<vtkGlobeMapProjection> candidate;
        apply(candidate, d);
        PROJScope scope;
        PJ* raw = scope.Keep(
          proj_create_crs_to_crs(scope.Context, "EPSG:4326", name.c_str(), nullptr));
        PJ* t = raw ? scope.Keep(proj_normalize_for_visualization(scope.Context, raw)) : nullptr;
        int checked = 0;
        const int n = 8;
        for (int i = 0; t && d.Usable && i <= n; ++i)
        {
          for (int j = 0; d.Usable && j <= n; ++j)
          {
            // Cell centres: a whole-world area's edges are the same meridian twice.
            const double lon = d.Area[0] + (d.Area[1] - d.Area[0]) * (i + 0.5) / (n + 1);
            const double lat = d.Area[2] + (d.Area[3] - d.Area[2]) * (j + 0.5) / (n + 1);
            double xy[2];
            if (!candidate->ForwardInDomain(lon, lat, xy))
            {
              continue;
            }
            PJ_COORD c = proj_coord(std::remainder(lon, 360.0), lat, 0.0, 0.0);
            c = proj_trans(t, PJ_FWD, c);
            if (!Finite(c.xy.x) || !Finite(c.xy.y) || c.xy.x == HUGE_VAL)
            {
              continue;
            }
            d.Usable = std::hypot(c.xy.x - xy[0], c.xy.y - xy[1]) <= 1e-3;
            ++checked;
          }
        }
        d.Usable = d.Usable && t && checked >= 10;
      }
      definitions[name] = d;
    }
  }
  if (d.Usable)
  {
    apply(this, d);
  }
  return d.Usable;
}

//------------------------------------------------------------------------------
double vtkGlobeMapProjection::GetMapUnitsPerRadianOfLongitude()
{
  const double a = this->SemiMajorAxis, f = this->Flattening;
  switch (this->Kind)
  {
    case Geographic:
      return 1.0 / Deg;
    case Equirectangular:
      return a * std::cos(this->StandardParallel * Deg);
    case Mercator:
    case WebMercator:
    {
      // Web Mercator: spherical formulas (e = 0) on the ellipsoid's semi-major axis.
      const double e2 = this->Kind == WebMercator ? 0.0 : f * (2.0 - f);
      const double s1 = std::sin(this->StandardParallel * Deg);
      return a * this->ScaleFactor * std::cos(this->StandardParallel * Deg) /
        std::sqrt(1.0 - e2 * s1 * s1);
    }
    case CylindricalEqualArea:
      return a * CylindricalEqualAreaScale(f, this->StandardParallel);
    default:
      return 0.0;
  }
}

bool vtkGlobeMapProjection::SpansAllLongitudes(double pixelWidth, int width)
{
  const double turn = 2.0 * Pi * this->GetMapUnitsPerRadianOfLongitude();
  // Within half a pixel of a whole turn the wrap's misregistration is below half a pixel,
  // where a feathered seam would fade a whole band to the base colour.
  return turn > 0.0 && Finite(pixelWidth) && pixelWidth > 0.0 && width > 0 &&
    std::abs(pixelWidth * width - turn) <= 0.5 * pixelWidth;
}

bool vtkGlobeMapProjection::IsGlobalRaster(bool geographic, int code, double pixelWidth, int width)
{
  if (geographic)
  {
    return Finite(pixelWidth) && width * pixelWidth >= 360.0 - 1e-7;
  }
  return SpansAllLongitudes(code, pixelWidth, width);
}

bool vtkGlobeMapProjection::IsSupportedEPSG(int code)
{
  vtkNew<vtkGlobeMapProjection> projection;
  return projection->SetFromEPSGQuietly(code);
}

bool vtkGlobeMapProjection::SpansAllLongitudes(int code, double pixelWidth, int width)
{
  vtkNew<vtkGlobeMapProjection> projection;
  return projection->SetFromEPSGQuietly(code) && projection->SpansAllLongitudes(pixelWidth, width);
}

//------------------------------------------------------------------------------
bool vtkGlobeMapProjection::Forward(double lon, double lat, double xy[2])
{
  xy[0] = xy[1] = NaN;
  if (!Finite(lon) || !Finite(lat) || std::abs(lat) > 90.0)
  {
    vtkErrorMacro(<< "Forward: (lon " << lon << ", lat " << lat
                  << ") is not a geodetic position (finite, |lat| <= 90).");
    return false;
  }
  if (!this->ForwardUnchecked(lon, lat, xy))
  {
    vtkErrorMacro(<< "Forward: (lon " << lon << ", lat " << lat << ") has no finite image in "
                  << this->GetKindAsString() << ".");
    xy[0] = xy[1] = NaN;
    return false;
  }
  return true;
}

bool vtkGlobeMapProjection::ForwardUnchecked(double lon, double lat, double xy[2])
{
  const double a = this->SemiMajorAxis, f = this->Flattening;
  const double lam = IsCylindrical(this->Kind) ? WrapInto(lon, this->LongitudeWest) : lon;
  double x = NaN, y = NaN, gamma = 0.0, k = 1.0;
  try
  {
    switch (this->Kind)
    {
      case Geographic:
        x = lam;
        y = lat;
        break;
      case Equirectangular:
        x = this->FalseEasting +
          a * std::cos(this->StandardParallel * Deg) * (lam - this->CentralMeridian) * Deg;
        y = this->FalseNorthing + a * lat * Deg;
        break;
      case Mercator:
      case WebMercator:
      {
        const bool web = this->Kind == WebMercator;
        const double ff = web ? 0.0 : f;
        const double e2 = ff * (2.0 - ff);
        const double s1 = std::sin(this->StandardParallel * Deg);
        const double k0 = this->ScaleFactor * std::cos(this->StandardParallel * Deg) /
          std::sqrt(1.0 - e2 * s1 * s1);
        const GeographicLib::LambertConformalConic lcc(a, ff, 0.0, k0);
        // Unwrapped longitude: x follows the chosen longitude domain.
        lcc.Forward(0.0, lat, 0.0, x, y, gamma, k);
        x = this->FalseEasting + a * k0 * (lam - this->CentralMeridian) * Deg;
        y += this->FalseNorthing;
        break;
      }
      case PolarStereographic:
      {
        const bool north = this->LatitudeOfTrueScale > 0.0;
        GeographicLib::PolarStereographic ps(a, f, 1.0);
        ps.SetScale(std::abs(this->LatitudeOfTrueScale), this->ScaleFactor);
        ps.Forward(north, lat, lon - this->CentralMeridian, x, y, gamma, k);
        x += this->FalseEasting;
        y += this->FalseNorthing;
        break;
      }
      case TransverseMercator:
      {
        const GeographicLib::TransverseMercator tm(a, f, this->ScaleFactor);
        double x0 = 0.0, y0 = 0.0;
        tm.Forward(this->CentralMeridian, this->LatitudeOfOrigin, this->CentralMeridian, x0, y0,
          gamma, k);
        tm.Forward(this->CentralMeridian, lat, lon, x, y, gamma, k);
        x += this->FalseEasting;
        y += this->FalseNorthing - y0;
        break;
      }
      case LambertConformalConic:
      case AlbersEqualArea:
      case LambertAzimuthalEqualArea:
        if (!this->IsConic())
        {
          if (!MakeObliqueAzimuthal(this).Forward(lat, lon, x, y))
          {
            return false;
          }
          break;
        }
        MakeConic(this).Forward(lat, lon, x, y);
        break;
      case Sinusoidal:
      {
        // The sphere's formulas (Flattening 0 by construction), lon - lon0 in [-180, 180).
        const double dLon = WrapInto(lon - this->CentralMeridian, -180.0);
        x = this->FalseEasting + a * dLon * Deg * std::cos(lat * Deg);
        y = this->FalseNorthing + a * lat * Deg;
        break;
      }
      case CylindricalEqualArea:
      {
        const double k0 = CylindricalEqualAreaScale(f, this->StandardParallel);
        const GeographicLib::AlbersEqualArea cea(a, f, 0.0, k0);
        cea.Forward(0.0, lat, 0.0, x, y, gamma, k);
        x = this->FalseEasting + a * k0 * (lam - this->CentralMeridian) * Deg;
        y += this->FalseNorthing;
        break;
      }
    }
  }
  catch (const std::exception&)
  {
    return false;
  }
  xy[0] = x;
  xy[1] = y;
  return Finite(x) && Finite(y);
}

//------------------------------------------------------------------------------
bool vtkGlobeMapProjection::Inverse(double x, double y, double lonLat[2])
{
  lonLat[0] = lonLat[1] = NaN;
  if (!Finite(x) || !Finite(y))
  {
    vtkErrorMacro(<< "Inverse: map point (" << x << ", " << y << ") is not finite.");
    return false;
  }
  if (!this->InverseUnchecked(x, y, lonLat))
  {
    vtkErrorMacro(<< "Inverse: map point (" << x << ", " << y << ") is outside the image of "
                  << this->GetKindAsString() << " (latitude beyond 90 degrees).");
    lonLat[0] = lonLat[1] = NaN;
    return false;
  }
  return true;
}

bool vtkGlobeMapProjection::ForwardInDomain(double lon, double lat, double xy[2])
{
  xy[0] = xy[1] = NaN;
  if (!this->IsInValidDomain(lon, lat) || !this->ForwardUnchecked(lon, lat, xy))
  {
    xy[0] = xy[1] = NaN;
    return false;
  }
  return true;
}

bool vtkGlobeMapProjection::InverseInDomain(double x, double y, double lonLat[2])
{
  lonLat[0] = lonLat[1] = NaN;
  if (!Finite(x) || !Finite(y) || !this->InverseUnchecked(x, y, lonLat) ||
    !this->IsInValidDomain(lonLat[0], lonLat[1]))
  {
    lonLat[0] = lonLat[1] = NaN;
    return false;
  }
  return true;
}

bool vtkGlobeMapProjection::InverseUnchecked(double x, double y, double lonLat[2])
{
  const double a = this->SemiMajorAxis, f = this->Flattening;
  double lon = NaN, lat = NaN, gamma = 0.0, k = 1.0;
  try
  {
    switch (this->Kind)
    {
      case Geographic:
        lon = x;
        lat = y;
        break;
      case Equirectangular:
        lon = this->CentralMeridian +
          (x - this->FalseEasting) / (a * std::cos(this->StandardParallel * Deg) * Deg);
        lat = (y - this->FalseNorthing) / (a * Deg);
        // a * 90 deg in radians and back may come out an ulp beyond the pole.
        lat = std::abs(lat) <= 90.0 + 1e-12 ? std::max(-90.0, std::min(90.0, lat)) : lat;
        break;
      case Mercator:
      case WebMercator:
      {
        const bool web = this->Kind == WebMercator;
        const double ff = web ? 0.0 : f;
        const double e2 = ff * (2.0 - ff);
        const double s1 = std::sin(this->StandardParallel * Deg);
        const double k0 = this->ScaleFactor * std::cos(this->StandardParallel * Deg) /
          std::sqrt(1.0 - e2 * s1 * s1);
        const GeographicLib::LambertConformalConic lcc(a, ff, 0.0, k0);
        double dummy = 0.0;
        lcc.Reverse(0.0, 0.0, y - this->FalseNorthing, lat, dummy, gamma, k);
        lon = this->CentralMeridian + (x - this->FalseEasting) / (a * k0 * Deg);
        break;
      }
      case PolarStereographic:
      {
        const bool north = this->LatitudeOfTrueScale > 0.0;
        GeographicLib::PolarStereographic ps(a, f, 1.0);
        ps.SetScale(std::abs(this->LatitudeOfTrueScale), this->ScaleFactor);
        ps.Reverse(north, x - this->FalseEasting, y - this->FalseNorthing, lat, lon, gamma, k);
        lon += this->CentralMeridian;
        break;
      }
      case TransverseMercator:
      {
        const GeographicLib::TransverseMercator tm(a, f, this->ScaleFactor);
        double x0 = 0.0, y0 = 0.0;
        tm.Forward(this->CentralMeridian, this->LatitudeOfOrigin, this->CentralMeridian, x0, y0,
          gamma, k);
        tm.Reverse(this->CentralMeridian, x - this->FalseEasting, y - this->FalseNorthing + y0,
          lat, lon, gamma, k);
        break;
      }
      case LambertConformalConic:
      case AlbersEqualArea:
      case LambertAzimuthalEqualArea:
        if (!(this->IsConic() ? MakeConic(this).Reverse(x, y, lat, lon)
                              : MakeObliqueAzimuthal(this).Reverse(x, y, lat, lon)))
        {
          return false;
        }
        break;
      case Sinusoidal:
      {
        lat = (y - this->FalseNorthing) / (a * Deg);
        lat = std::abs(lat) <= 90.0 + 1e-12 ? std::max(-90.0, std::min(90.0, lat)) : lat;
        const double c = std::cos(lat * Deg);
        const double dLon = c > 0.0 ? (x - this->FalseEasting) / (a * Deg * c) : 0.0;
        // Outside the map's outline (the sinusoids at +-180 degrees) there is no inverse.
        if (!(std::abs(dLon) <= 180.0 * (1.0 + 1e-12)) || std::abs(lat) > 90.0)
        {
          return false;
        }
        lon = this->CentralMeridian + dLon;
        break;
      }
      case CylindricalEqualArea:
      {
        const double k0 = CylindricalEqualAreaScale(f, this->StandardParallel);
        const GeographicLib::AlbersEqualArea cea(a, f, 0.0, k0);
        double dummy = 0.0;
        const double yb = y - this->FalseNorthing;
        cea.Reverse(0.0, 0.0, yb, lat, dummy, gamma, k);
        // Beyond the poles' northing the inverse clamps to a pole: no inverse there.
        double xp = 0.0, yp = 0.0;
        cea.Forward(0.0, lat < 0.0 ? -90.0 : 90.0, 0.0, xp, yp, gamma, k);
        if (std::abs(yb) > std::abs(yp) * (1.0 + 1e-12))
        {
          return false;
        }
        lon = this->CentralMeridian + (x - this->FalseEasting) / (a * k0 * Deg);
        break;
      }
    }
  }
  catch (const std::exception&)
  {
    return false;
  }
  if (!Finite(lon) || !Finite(lat) || std::abs(lat) > 90.0)
  {
    return false;
  }
  lonLat[0] = IsCylindrical(this->Kind) ? WrapInto(lon, this->LongitudeWest)
                                        : std::remainder(lon, 360.0);
  lonLat[1] = lat;
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeMapProjection::GetValidDomain(double box[4])
{
  const double lon0 = this->CentralMeridian;
  box[0] = lon0 - 180.0;
  box[1] = lon0 + 180.0;
  box[2] = -90.0;
  box[3] = 90.0;
  switch (this->Kind)
  {
    case Mercator:
      box[2] = -89.5;
      box[3] = 89.5;
      break;
    case WebMercator:
      // The square world: atan(sinh(pi)).
      box[2] = -85.051128779806592;
      box[3] = 85.051128779806592;
      break;
    case PolarStereographic:
      box[0] = -180.0;
      box[1] = 180.0;
      if (this->LatitudeOfTrueScale > 0.0)
      {
        box[2] = 0.0;
      }
      else
      {
        box[3] = 0.0;
      }
      break;
    case TransverseMercator:
      box[0] = lon0 - 10.0;
      box[1] = lon0 + 10.0;
      box[2] = this->UTM ? -80.0 : -89.0;
      box[3] = this->UTM ? 84.0 : 89.0;
      break;
    case LambertConformalConic:
    case AlbersEqualArea:
    case LambertAzimuthalEqualArea:
      if (!this->IsConic())
      {
        break; // the oblique aspects: the whole globe but a cap around the centre's antipode
      }
      // Short of the pole opposite the apex (infinitely far on the conformal conic, a
      // circle on the azimuthal projection).
      if (this->GetApexHemisphere() > 0.0)
      {
        box[2] = -89.5;
      }
      else
      {
        box[3] = 89.5;
      }
      break;
    default:
      break;
  }
}

bool vtkGlobeMapProjection::IsInValidDomain(double lon, double lat)
{
  if (!Finite(lon) || !Finite(lat))
  {
    return false;
  }
  double box[4];
  this->GetValidDomain(box);
  const double centre = 0.5 * (box[0] + box[1]);
  const double halfWidth = 0.5 * (box[1] - box[0]);
  if (this->Kind == LambertAzimuthalEqualArea && !this->IsConic() &&
    !(MakeObliqueAzimuthal(this).OnePlusCosFromCentre(lat, lon) > ObliqueAzimuthal::AntipodeCap))
  {
    return false;
  }
  return std::abs(std::remainder(lon - centre, 360.0)) <= halfWidth && lat >= box[2] &&
    lat <= box[3];
}

//------------------------------------------------------------------------------
const char* vtkGlobeMapProjection::GetShaderFunctionName()
{
  switch (this->Kind)
  {
    case Geographic:
    case Equirectangular:
      return "globe_projectEquirectangular";
    case Mercator:
    case WebMercator:
      return "globe_projectMercator";
    case PolarStereographic:
      return "globe_projectPolarStereographic";
    case TransverseMercator:
      return "globe_projectTransverseMercator";
    case LambertConformalConic:
      return "globe_projectConformalConic";
    case AlbersEqualArea:
      return "globe_projectAlbersEqualArea";
    case LambertAzimuthalEqualArea:
      return this->IsConic() ? "globe_projectAlbersEqualArea"
                             : "globe_projectObliqueAzimuthalEqualArea";
    case CylindricalEqualArea:
      return "globe_projectCylindricalEqualArea";
    case Sinusoidal:
      return "globe_projectSinusoidal";
  }
  return "";
}

//------------------------------------------------------------------------------
bool vtkGlobeMapProjection::ComputeShaderParameters(const double origin[2],
  const double pixelSize[2], int width, int height, float parameters[28])
{
  double p[NumberOfShaderParameters];
  const bool ok = this->ComputeShaderParametersDouble(origin, pixelSize, width, height, p);
  for (int i = 0; i < NumberOfShaderParameters; ++i)
  {
    parameters[i] = static_cast<float>(p[i]);
  }
  return ok;
}

bool vtkGlobeMapProjection::ComputeShaderParametersDouble(const double origin[2],
  const double pixelSize[2], int width, int height, double P[28])
{
  return this->ComputeShaderParametersAt(origin, pixelSize, width, height, nullptr, P);
}

bool vtkGlobeMapProjection::ComputeShaderParametersAt(const double origin[2],
  const double pixelSize[2], int width, int height, const double reference[2], double P[28])
{
  std::fill(P, P + NumberOfShaderParameters, NaN);
  if (!origin || !pixelSize || !Finite(origin[0]) || !Finite(origin[1]) ||
    !Finite(pixelSize[0]) || !Finite(pixelSize[1]) || !(pixelSize[0] > 0.0) ||
    !(pixelSize[1] > 0.0) || width < 1 || height < 1)
  {
    vtkErrorMacro(<< "ComputeShaderParameters: the raster needs a finite origin, positive "
                     "pixel sizes and at least one pixel; got "
                  << width << " x " << height << " pixels.");
    return false;
  }
  const double a = this->SemiMajorAxis, f = this->Flattening;
  const double mapWidth = pixelSize[0] * width, mapHeight = pixelSize[1] * height;
  // The reference point: the raster's centre, or the one asked for, inside the raster. The
  // kinds with an apex need one away from it (their formulas scale the reference's offset from
  // the apex).
  double xr = origin[0] + 0.5 * mapWidth, yr = origin[1] - 0.5 * mapHeight;
  if (reference && Finite(reference[0]) && Finite(reference[1]))
  {
    xr = std::max(origin[0], std::min(origin[0] + mapWidth, reference[0]));
    yr = std::max(origin[1] - mapHeight, std::min(origin[1], reference[1]));
  }
  const bool apexKind = this->Kind == PolarStereographic || this->IsConic();
  const double hemi = this->GetApexHemisphere();
  double apex[2] = { this->FalseEasting, this->FalseNorthing };
  if (this->Kind == AlbersEqualArea)
  {
    apex[1] = MakeConic(this).ApexNorthing(a, f, this->StandardParallel);
  }
  else if (this->IsConic() &&
    !this->ForwardUnchecked(this->CentralMeridian, 90.0 * hemi, apex))
  {
    vtkErrorMacro(<< "ComputeShaderParameters: the apex of " << this->GetKindAsString()
                  << " has no map coordinates.");
    return false;
  }
  if (apexKind)
  {
    const double fx = xr - apex[0], fy = yr - apex[1];
    const double rho = std::hypot(fx, fy), half = 0.5 * std::max(mapWidth, mapHeight);
    if (rho < half)
    {
      const double ux = rho > 0.0 ? fx / rho : 1.0, uy = rho > 0.0 ? fy / rho : 0.0;
      xr = apex[0] + ux * half;
      yr = apex[1] + uy * half;
    }
  }
  double lonLat[2];
  if (!this->InverseUnchecked(xr, yr, lonLat))
  {
    vtkErrorMacro(<< "ComputeShaderParameters: the raster's reference point (" << xr << ", "
                  << yr << ") is outside the image of " << this->GetKindAsString() << ".");
    return false;
  }
  const double lonR = std::remainder(lonLat[0], 360.0) * Deg;
  const double latR = hemi * lonLat[1] * Deg;
  const double e = (this->Kind == WebMercator || this->Kind == Geographic ||
                     this->Kind == Equirectangular || this->Kind == Sinusoidal)
    ? 0.0
    : std::sqrt(f * (2.0 - f));

  Split(lonR, P[0], P[1]);
  Split(lonR - (lonR >= 0.0 ? 2.0 * Pi : -2.0 * Pi), P[2], P[3]);
  Split(latR, P[4], P[5]);
  P[6] = std::sin(latR);
  P[7] = std::cos(latR);
  P[8] = (xr - origin[0]) / mapWidth;
  P[9] = (origin[1] - yr) / mapHeight;
  P[10] = e;
  P[11] = hemi;
  double box[4];
  this->GetValidDomain(box);
  const bool allLongitudes = box[1] - box[0] >= 360.0;
  P[16] = std::remainder(0.5 * (box[0] + box[1]), 360.0) * Deg;
  P[17] = allLongitudes ? 4.0 : 0.5 * (box[1] - box[0]) * Deg;
  // A little slack: float(pi/2) and float(84 deg) lie beyond their double values.
  P[18] = box[2] * Deg - 1e-6;
  P[19] = box[3] * Deg + 1e-6;
  for (int i = 20; i < NumberOfShaderParameters; ++i)
  {
    P[i] = 0.0;
  }

  // M: (du, dv) = M (X, Y), X and Y the GLSL function's two offsets (map units per radian).
  double m[4] = { 0.0, 0.0, 0.0, 0.0 };
  switch (this->Kind)
  {
    case Geographic:
      m[0] = this->GetMapUnitsPerRadianOfLongitude() / mapWidth;
      m[3] = -1.0 / Deg / mapHeight;
      break;
    case Equirectangular:
      m[0] = this->GetMapUnitsPerRadianOfLongitude() / mapWidth;
      m[3] = -a / mapHeight;
      break;
    case Mercator:
    case WebMercator:
    {
      const double aK0 = this->GetMapUnitsPerRadianOfLongitude();
      m[0] = aK0 / mapWidth;
      m[3] = -aK0 / mapHeight;
      break;
    }
    case PolarStereographic:
    case LambertConformalConic:
    case AlbersEqualArea:
    case LambertAzimuthalEqualArea:
    {
      if (this->Kind == LambertAzimuthalEqualArea && !this->IsConic())
      {
        // The authalic sphere's unit azimuthal offsets (X, Y), then x = Rq D X, y = Rq Y / D.
        const ObliqueAzimuthal o = MakeObliqueAzimuthal(this);
        m[0] = o.Rq * o.D / mapWidth;
        m[3] = -o.Rq / (o.D * mapHeight);
        const double sb = o.SinBeta(latR / Deg);
        const double L = std::remainder(lonR - this->CentralMeridian * Deg, 2.0 * Pi);
        P[20] = sb;
        P[21] = o.CosBeta(latR / Deg);
        P[22] = o.SinB1;
        P[23] = o.CosB1;
        P[24] = L;
        P[25] = (1.0 - e * e) / o.Qp;
        P[26] = std::sin(L);
        P[27] = std::cos(L);
        break;
      }
      // F_r: the reference's offset from the apex in the north-apex frame (y mirrored south).
      const double fx = xr - apex[0], fy = hemi * (yr - apex[1]);
      m[0] = fx / mapWidth;
      m[1] = -fy / mapWidth;
      m[2] = -hemi * fy / mapHeight;
      m[3] = -hemi * fx / mapHeight;
      // The cone constant n: the meridian convergence per unit of longitude.
      const double n = (this->Kind == LambertConformalConic || this->Kind == AlbersEqualArea)
        ? MakeConic(this).ConeConstant(lonLat[1])
        : 1.0;
      const double sr = std::sin(latR);
      if (this->Kind == PolarStereographic || this->Kind == LambertConformalConic)
      {
        // t(lat_r) = tan(colat_r / 2) exp(e atanh(e sin lat_r)).
        const double colat = 0.5 * Pi - latR;
        P[20] = std::sin(colat) / (1.0 + std::cos(colat)) * std::exp(e * std::atanh(e * sr));
      }
      else
      {
        // rho^2 = (a^2 / n^2)(C - n q): u = rho^2 / rho_r^2 - 1 = K (q - q_r) / (1 - e^2).
        P[20] = -(1.0 - e * e) * a * a / (n * (fx * fx + fy * fy));
      }
      if (this->Kind != PolarStereographic)
      {
        P[21] = n;
        P[24] = std::remainder(lonR - this->CentralMeridian * Deg, 2.0 * Pi);
      }
      if (this->Kind == LambertAzimuthalEqualArea)
      {
        // 1 / ((q_p - q_r) / (1 - e^2)), the difference written in 1 - sin = cos^2 / (1 + sin).
        const double cr = std::cos(latR);
        P[25] = 1.0 /
          vtkGlobeShaderMath::d::globe_equalAreaDifference(cr * cr / (1.0 + sr), 1.0, sr, e);
      }
      break;
    }
    case Sinusoidal:
      // X = (lon - lon_r) cos lat + (lon_r - lon0)(cos lat - cos lat_r), Y = lat - lat_r.
      m[0] = a / mapWidth;
      m[3] = -a / mapHeight;
      P[24] = std::remainder(lonR - this->CentralMeridian * Deg, 2.0 * Pi);
      break;
    case CylindricalEqualArea:
    {
      // y = a q / (2 k0): dv from (q - q_r) / (1 - e^2).
      const double k0 = CylindricalEqualAreaScale(f, this->StandardParallel);
      m[0] = this->GetMapUnitsPerRadianOfLongitude() / mapWidth;
      m[3] = -a * (1.0 - e * e) / (2.0 * k0) / mapHeight;
      break;
    }
    case TransverseMercator:
    {
      const double n = f / (2.0 - f), n2 = n * n;
      // Krueger's alpha_1, alpha_2 (Karney 2011, eq. 35) and the rectifying radius A.
      const double alpha1 = n / 2.0 - 2.0 * n2 / 3.0 + 5.0 * n2 * n / 16.0 +
        41.0 * n2 * n2 / 180.0 - 127.0 * n2 * n2 * n / 288.0 + 7891.0 * n2 * n2 * n2 / 37800.0;
      const double alpha2 = 13.0 * n2 / 48.0 - 3.0 * n2 * n / 5.0 + 557.0 * n2 * n2 / 1440.0 +
        281.0 * n2 * n2 * n / 630.0 - 1983433.0 * n2 * n2 * n2 / 1935360.0;
      const double A = a / (1.0 + n) *
        (1.0 + n2 / 4.0 + n2 * n2 / 64.0 + n2 * n2 * n2 / 256.0 + 25.0 * n2 * n2 * n2 * n2 / 16384.0);
      const double kA = this->ScaleFactor * A;
      m[1] = kA / mapWidth;
      m[2] = -kA / mapHeight;
      const double psi = std::asinh(std::tan(latR)) - e * std::atanh(e * std::sin(latR));
      const double b = std::remainder(lonR / Deg - this->CentralMeridian, 360.0) * Deg;
      const double xi = std::atan2(std::sinh(psi), std::cos(b));
      const double eta =
        std::asinh(std::sin(b) / std::hypot(std::sinh(psi), std::cos(b)));
      // C_r = alpha_1 sin(2 zeta'_r) + alpha_2 sin(4 zeta'_r), complex.
      const double c2r = std::sin(2.0 * xi) * std::cosh(2.0 * eta);
      const double c2i = std::cos(2.0 * xi) * std::sinh(2.0 * eta);
      const double c4r = std::sin(4.0 * xi) * std::cosh(4.0 * eta);
      const double c4i = std::cos(4.0 * xi) * std::sinh(4.0 * eta);
      P[20] = psi;
      P[21] = b;
      P[22] = xi;
      P[23] = eta;
      P[24] = alpha1 * c2r + alpha2 * c4r;
      P[25] = alpha1 * c2i + alpha2 * c4i;
      P[26] = alpha1;
      P[27] = alpha2;
      break;
    }
  }
  for (int i = 0; i < 4; ++i)
  {
    P[12 + i] = m[i];
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeMapProjection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Kind: " << this->GetKindAsString() << "\n";
  os << indent << "EPSG: " << this->EPSG << "\n";
  os << indent << "SemiMajorAxis: " << this->SemiMajorAxis << "\n";
  os << indent << "Flattening: " << this->Flattening << "\n";
  os << indent << "CentralMeridian: " << this->CentralMeridian << "\n";
  os << indent << "StandardParallel: " << this->StandardParallel << "\n";
  os << indent << "StandardParallel2: " << this->StandardParallel2 << "\n";
  os << indent << "LatitudeOfTrueScale: " << this->LatitudeOfTrueScale << "\n";
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "LatitudeOfOrigin: " << this->LatitudeOfOrigin << "\n";
  os << indent << "FalseEasting: " << this->FalseEasting << "\n";
  os << indent << "FalseNorthing: " << this->FalseNorthing << "\n";
  os << indent << "LongitudeWest: " << this->LongitudeWest << "\n";
  os << indent << "UTM: " << (this->UTM ? "yes" : "no") << "\n";
}
