#include "vtkGlobeMapProjection.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <GeographicLib/LambertConformalConic.hpp>
#include <GeographicLib/PolarStereographic.hpp>
#include <GeographicLib/TransverseMercator.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

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
    kind == vtkGlobeMapProjection::WebMercator;
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

//------------------------------------------------------------------------------
bool vtkGlobeMapProjection::SetFromEPSG(int code)
{
  if (!this->SetFromEPSGQuietly(code))
  {
    vtkErrorMacro(<< "SetFromEPSG: EPSG:" << code
                  << " is not a supported projection (supported: 4326, 4087, 32662, 3413, 3031, "
                     "3995, 3976, 3032, 32661, 32761, 3395, 3857, 326zz and 327zz); the "
                     "projection is unchanged.");
    return false;
  }
  return true;
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
  else
  {
    this->SemiMajorAxis = a;
    this->Flattening = f;
    return false;
  }
  this->EPSG = code;
  return true;
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
  // The reference point: the raster's centre. Polar stereographic needs one away from the
  // pole (its formulas scale the reference's offset from the pole).
  double xr = origin[0] + 0.5 * mapWidth, yr = origin[1] - 0.5 * mapHeight;
  const double hemi =
    (this->Kind == PolarStereographic && this->LatitudeOfTrueScale < 0.0) ? -1.0 : 1.0;
  if (this->Kind == PolarStereographic)
  {
    const double fx = xr - this->FalseEasting, fy = yr - this->FalseNorthing;
    const double rho = std::hypot(fx, fy), half = 0.5 * std::max(mapWidth, mapHeight);
    if (rho < half)
    {
      const double ux = rho > 0.0 ? fx / rho : 1.0, uy = rho > 0.0 ? fy / rho : 0.0;
      xr = this->FalseEasting + ux * half;
      yr = this->FalseNorthing + uy * half;
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
                     this->Kind == Equirectangular)
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
    {
      // F_r: the reference's offset from the pole in the north-pole frame (y mirrored south).
      const double fx = xr - this->FalseEasting, fy = hemi * (yr - this->FalseNorthing);
      m[0] = fx / mapWidth;
      m[1] = -fy / mapWidth;
      m[2] = -hemi * fy / mapHeight;
      m[3] = -hemi * fx / mapHeight;
      const double s = std::sin(latR);
      const double colat = 0.5 * Pi - latR;
      P[20] = std::sin(colat) / (1.0 + std::cos(colat)) * std::exp(e * std::atanh(e * s));
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
  os << indent << "LatitudeOfTrueScale: " << this->LatitudeOfTrueScale << "\n";
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "LatitudeOfOrigin: " << this->LatitudeOfOrigin << "\n";
  os << indent << "FalseEasting: " << this->FalseEasting << "\n";
  os << indent << "FalseNorthing: " << this->FalseNorthing << "\n";
  os << indent << "LongitudeWest: " << this->LongitudeWest << "\n";
  os << indent << "UTM: " << (this->UTM ? "yes" : "no") << "\n";
}
