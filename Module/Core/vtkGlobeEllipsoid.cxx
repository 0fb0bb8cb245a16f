#include "vtkGlobeEllipsoid.h"

#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/Math.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkGlobeEllipsoid);

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

bool AllFinite(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void FillNaN(double v[3])
{
  v[0] = v[1] = v[2] = NaN;
}

/**
 * Root s > 0 of G(s) = sum_i (k_i / (s + d_i))^2 - 1 inside the bracket [lo, hi] where
 * G(lo) >= 0 >= G(hi). G is convex and decreasing there, so Newton steps taken from the
 * left of the root approach it monotonically; a bisection (geometric while the bracket spans
 * orders of magnitude) guards every step, and the loop is capped, so this always returns.
 */
double SolveFootParameter(int n, const double k[3], const double d[3], double lo, double hi,
  int& iterations)
{
  constexpr int maxIterations = 200;
  const double eps = std::numeric_limits<double>::epsilon();
  double s = lo;
  iterations = 0;
  while (iterations < maxIterations)
  {
    ++iterations;
    double g = -1.0;
    double dg = 0.0;
    for (int i = 0; i < n; ++i)
    {
      const double q = k[i] / (s + d[i]);
      g += q * q;
      dg -= 2.0 * q * q / (s + d[i]);
    }
    if (g == 0.0)
    {
      return s;
    }
    if (g > 0.0)
    {
      lo = s;
    }
    else
    {
      hi = s;
    }
    if (!(hi - lo > 4.0 * eps * hi))
    {
      break;
    }
    double next = dg < 0.0 ? s - g / dg : NaN;
    const bool newtonOk = next > lo && next < hi;
    if (!newtonOk || (g > 0.0 && next - s < 0.25 * (hi - lo) && hi > 4.0 * lo))
    {
      // Bisect: geometrically while the bracket spans a wide range of scales (a point
      // almost on a symmetry plane starts with lo ~ 0), arithmetically otherwise.
      const double bis = (hi > 4.0 * lo && lo > 0.0) ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
      next = newtonOk ? std::max(next, bis) : bis;
    }
    if (std::abs(next - s) <= 2.0 * eps * std::abs(s))
    {
      s = next;
      break;
    }
    s = next;
  }
  return s;
}

/// Nearest point on the ellipse (e0 >= e1) to y (first quadrant).
int NearestOnEllipse(const double e[2], const double y[2], double x[2])
{
  int iterations = 0;
  if (e[1] * y[1] > 0.0)
  {
    const double k[3] = { e[0] * y[0], e[1] * y[1], 0.0 };
    const double d[3] = { (e[0] - e[1]) * (e[0] + e[1]), 0.0, 0.0 };
    const double lo = k[1];
    const double hi = std::hypot(k[0], k[1]);
    const double s = SolveFootParameter(2, k, d, lo, hi, iterations);
    x[0] = e[0] * e[0] * y[0] / (s + d[0]);
    x[1] = e[1] * e[1] * y[1] / s;
    return iterations;
  }
  const double denom = (e[0] - e[1]) * (e[0] + e[1]);
  if (e[0] * y[0] < denom)
  {
    // Inside the evolute on the major axis: the nearest point is off the axis.
    const double xde = e[0] * y[0] / denom;
    x[0] = e[0] * xde;
    x[1] = e[1] * std::sqrt(std::max(0.0, 1.0 - xde * xde));
  }
  else
  {
    x[0] = e[0];
    x[1] = 0.0;
  }
  return iterations;
}

/// Nearest point on the ellipsoid (e0 >= e1 >= e2) to y (first octant).
int NearestOnSortedEllipsoid(const double e[3], const double y[3], double x[3])
{
  int iterations = 0;
  const double d[3] = { (e[0] - e[2]) * (e[0] + e[2]), (e[1] - e[2]) * (e[1] + e[2]), 0.0 };
  if (e[2] * y[2] > 0.0)
  {
    const double k[3] = { e[0] * y[0], e[1] * y[1], e[2] * y[2] };
    const double lo = k[2];
    const double hi = std::hypot(k[0], k[1], k[2]);
    const double s = SolveFootParameter(3, k, d, lo, hi, iterations);
    for (int i = 0; i < 3; ++i)
    {
      x[i] = e[i] * e[i] * y[i] / (s + d[i]);
    }
    return iterations;
  }
  // On the plane of the two larger axes: the nearest point may leave that plane when y is
  // inside the evolute (near the centre).
  if (e[0] * y[0] < d[0] && e[1] * y[1] < d[1])
  {
    const double xde0 = e[0] * y[0] / d[0];
    const double xde1 = e[1] * y[1] / d[1];
    const double discr = 1.0 - xde0 * xde0 - xde1 * xde1;
    if (discr > 0.0)
    {
      x[0] = e[0] * xde0;
      x[1] = e[1] * xde1;
      x[2] = e[2] * std::sqrt(discr);
      return iterations;
    }
  }
  const double e2d[2] = { e[0], e[1] };
  const double y2d[2] = { y[0], y[1] };
  double x2d[2];
  iterations = NearestOnEllipse(e2d, y2d, x2d);
  x[0] = x2d[0];
  x[1] = x2d[1];
  x[2] = 0.0;
  return iterations;
}
} // namespace

class vtkGlobeEllipsoid::vtkInternals
{
public:
  std::unique_ptr<GeographicLib::Geocentric> Geocentric;
};

//------------------------------------------------------------------------------
vtkGlobeEllipsoid::vtkGlobeEllipsoid()
  : Internals(new vtkInternals)
{
  this->Radii[0] = this->Radii[1] = this->Radii[2] = 1.0;
  this->SetToWGS84();
}

//------------------------------------------------------------------------------
vtkGlobeEllipsoid::~vtkGlobeEllipsoid()
{
  this->SetName(nullptr);
}

//------------------------------------------------------------------------------
void vtkGlobeEllipsoid::ApplyRadii(double a, double b, double c, const char* name)
{
  this->Radii[0] = a;
  this->Radii[1] = b;
  this->Radii[2] = c;
  this->Internals->Geocentric.reset();
  if (a == b)
  {
    // GeographicLib takes the equatorial radius and the flattening (negative: prolate).
    this->Internals->Geocentric.reset(new GeographicLib::Geocentric(a, (a - c) / a));
  }
  this->SetName(name);
  this->Modified();
}

void vtkGlobeEllipsoid::SetToWGS84()
{
  const double a = GeographicLib::Constants::WGS84_a();
  this->ApplyRadii(a, a, a * (1.0 - GeographicLib::Constants::WGS84_f()), "WGS84");
}

void vtkGlobeEllipsoid::SetToGRS80()
{
  const double a = GeographicLib::Constants::GRS80_a();
  // GRS80 is defined by J2; its derived flattening is 1/298.257222101 (Moritz, 1980).
  this->ApplyRadii(a, a, a * (1.0 - 1.0 / 298.257222101), "GRS80");
}

void vtkGlobeEllipsoid::SetToMars()
{
  this->ApplyRadii(3396190.0, 3396190.0, 3376200.0, "Mars");
}

void vtkGlobeEllipsoid::SetToMoon()
{
  this->ApplyRadii(1737400.0, 1737400.0, 1737400.0, "Moon");
}

//------------------------------------------------------------------------------
bool vtkGlobeEllipsoid::SetRadii(double a, double b, double c)
{
  const double r[3] = { a, b, c };
  for (int i = 0; i < 3; ++i)
  {
    if (!std::isfinite(r[i]) || r[i] <= 0.0)
    {
      vtkErrorMacro(<< "Invalid ellipsoid radii (" << a << ", " << b << ", " << c
                    << "): each semi-axis must be finite and positive; the ellipsoid is left as "
                    << this->Radii[0] << ", " << this->Radii[1] << ", " << this->Radii[2]);
      return false;
    }
  }
  if (a == this->Radii[0] && b == this->Radii[1] && c == this->Radii[2] && !this->Name)
  {
    return true;
  }
  this->ApplyRadii(a, b, c, nullptr);
  return true;
}

//------------------------------------------------------------------------------
bool vtkGlobeEllipsoid::IsSphere() const
{
  return this->Radii[0] == this->Radii[1] && this->Radii[1] == this->Radii[2];
}

bool vtkGlobeEllipsoid::IsBiaxial() const
{
  return this->Radii[0] == this->Radii[1];
}

bool vtkGlobeEllipsoid::IsTriaxial() const
{
  return this->Radii[0] != this->Radii[1];
}

bool vtkGlobeEllipsoid::IsProlate() const
{
  return this->Radii[2] > this->Radii[0] && this->Radii[2] > this->Radii[1];
}

double vtkGlobeEllipsoid::GetMinimumRadius() const
{
  return std::min({ this->Radii[0], this->Radii[1], this->Radii[2] });
}

double vtkGlobeEllipsoid::GetMaximumRadius() const
{
  return std::max({ this->Radii[0], this->Radii[1], this->Radii[2] });
}

double vtkGlobeEllipsoid::GetFlattening() const
{
  return (this->Radii[0] - this->Radii[2]) / this->Radii[0];
}

//------------------------------------------------------------------------------
bool vtkGlobeEllipsoid::GeodeticToCartesianQuiet(const double llh[3], double xyz[3]) const
{
  if (!AllFinite(llh))
  {
    FillNaN(xyz);
    return false;
  }
  if (this->UseGeographicLib && this->Internals->Geocentric)
  {
    this->Internals->Geocentric->Forward(llh[1], llh[0], llh[2], xyz[0], xyz[1], xyz[2]);
    return true;
  }
  double n[3];
  double sinLon, cosLon, sinLat, cosLat;
  GeographicLib::Math::sincosd(llh[0], sinLon, cosLon);
  GeographicLib::Math::sincosd(llh[1], sinLat, cosLat);
  n[0] = cosLat * cosLon;
  n[1] = cosLat * sinLon;
  n[2] = sinLat;
  double k[3];
  double g = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    k[i] = this->Radii[i] * this->Radii[i] * n[i];
    g += k[i] * n[i];
  }
  g = std::sqrt(g);
  for (int i = 0; i < 3; ++i)
  {
    xyz[i] = k[i] / g + llh[2] * n[i];
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkGlobeEllipsoid::NearestSurfacePoint(
  const double radii[3], const double xyz[3], double surface[3])
{
  if (!AllFinite(xyz) || !AllFinite(radii) || radii[0] <= 0 || radii[1] <= 0 || radii[2] <= 0)
  {
    FillNaN(surface);
    return -1;
  }
  // Sort the axes in decreasing length and fold the point into the first octant.
  std::array<int, 3> order = { 0, 1, 2 };
  std::stable_sort(
    order.begin(), order.end(), [radii](int i, int j) { return radii[i] > radii[j]; });
  // Work in units of the largest radius so that squares stay far from overflow.
  const double scale = radii[order[0]];
  double e[3], y[3], x[3];
  for (int i = 0; i < 3; ++i)
  {
    e[i] = radii[order[i]] / scale;
    y[i] = std::abs(xyz[order[i]]) / scale;
  }
  const int iterations = NearestOnSortedEllipsoid(e, y, x);
  for (int i = 0; i < 3; ++i)
  {
    surface[order[i]] = std::copysign(x[i] * scale, xyz[order[i]]);
  }
  return iterations;
}

//------------------------------------------------------------------------------
bool vtkGlobeEllipsoid::CartesianToGeodeticQuiet(const double xyz[3], double llh[3]) const
{
  if (!AllFinite(xyz))
  {
    FillNaN(llh);
    return false;
  }
  if (this->UseGeographicLib && this->Internals->Geocentric)
  {
    this->Internals->Geocentric->Reverse(xyz[0], xyz[1], xyz[2], llh[1], llh[0], llh[2]);
    return true;
  }
  double x[3];
  vtkGlobeEllipsoid::NearestSurfacePoint(this->Radii, xyz, x);
  double n[3];
  for (int i = 0; i < 3; ++i)
  {
    n[i] = x[i] / (this->Radii[i] * this->Radii[i]);
  }
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int i = 0; i < 3; ++i)
  {
    n[i] /= len;
  }
  llh[0] = GeographicLib::Math::atan2d(n[1], n[0]);
  llh[1] = GeographicLib::Math::atan2d(n[2], std::hypot(n[0], n[1]));
  llh[2] = (xyz[0] - x[0]) * n[0] + (xyz[1] - x[1]) * n[1] + (xyz[2] - x[2]) * n[2];
  return true;
}

//------------------------------------------------------------------------------
bool vtkGlobeEllipsoid::GeodeticToCartesian(const double llh[3], double xyz[3])
{
  if (!this->GeodeticToCartesianQuiet(llh, xyz))
  {
    vtkErrorMacro(<< "GeodeticToCartesian: non-finite input (" << llh[0] << ", " << llh[1]
                  << ", " << llh[2] << "); the result is NaN");
    return false;
  }
  return true;
}

bool vtkGlobeEllipsoid::GeodeticToCartesian(double lon, double lat, double height, double xyz[3])
{
  const double llh[3] = { lon, lat, height };
  return this->GeodeticToCartesian(llh, xyz);
}

double* vtkGlobeEllipsoid::GeodeticToCartesian(double lon, double lat, double height)
{
  const double llh[3] = { lon, lat, height };
  if (!this->GeodeticToCartesian(llh, this->Result))
  {
    std::fill(this->Result, this->Result + 3, std::numeric_limits<double>::quiet_NaN());
  }
  return this->Result;
}

double* vtkGlobeEllipsoid::CartesianToGeodetic(double x, double y, double z)
{
  const double xyz[3] = { x, y, z };
  if (!this->CartesianToGeodetic(xyz, this->Result))
  {
    std::fill(this->Result, this->Result + 3, std::numeric_limits<double>::quiet_NaN());
  }
  return this->Result;
}

bool vtkGlobeEllipsoid::CartesianToGeodetic(const double xyz[3], double llh[3])
{
  if (!this->CartesianToGeodeticQuiet(xyz, llh))
  {
    vtkErrorMacro(<< "CartesianToGeodetic: non-finite input (" << xyz[0] << ", " << xyz[1]
                  << ", " << xyz[2] << "); the result is NaN");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeEllipsoid::GeodeticSurfaceNormal(double lon, double lat, double normal[3])
{
  double east[3], north[3];
  this->ComputeEastNorthUp(lon, lat, east, north, normal);
}

bool vtkGlobeEllipsoid::GeodeticSurfaceNormalAt(const double xyz[3], double normal[3])
{
  double llh[3];
  if (!this->CartesianToGeodetic(xyz, llh))
  {
    FillNaN(normal);
    return false;
  }
  this->GeodeticSurfaceNormal(llh[0], llh[1], normal);
  return true;
}

bool vtkGlobeEllipsoid::ScaleToGeodeticSurface(const double xyz[3], double surface[3])
{
  double llh[3];
  if (!this->CartesianToGeodetic(xyz, llh))
  {
    FillNaN(surface);
    return false;
  }
  llh[2] = 0.0;
  return this->GeodeticToCartesianQuiet(llh, surface);
}

bool vtkGlobeEllipsoid::ScaleToGeocentricSurface(const double xyz[3], double surface[3])
{
  double q = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double u = xyz[i] / this->Radii[i];
    q += u * u;
  }
  if (!AllFinite(xyz) || !(q > 0.0))
  {
    vtkErrorMacro(<< "ScaleToGeocentricSurface: the point (" << xyz[0] << ", " << xyz[1] << ", "
                  << xyz[2] << ") is the centre or not finite; it has no geocentric direction");
    FillNaN(surface);
    return false;
  }
  const double beta = 1.0 / std::sqrt(q);
  for (int i = 0; i < 3; ++i)
  {
    surface[i] = beta * xyz[i];
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeEllipsoid::ComputeEastNorthUp(
  double lon, double lat, double east[3], double north[3], double up[3])
{
  double sinLon, cosLon, sinLat, cosLat;
  GeographicLib::Math::sincosd(lon, sinLon, cosLon);
  GeographicLib::Math::sincosd(lat, sinLat, cosLat);
  east[0] = -sinLon;
  east[1] = cosLon;
  east[2] = 0.0;
  north[0] = -sinLat * cosLon;
  north[1] = -sinLat * sinLon;
  north[2] = cosLat;
  up[0] = cosLat * cosLon;
  up[1] = cosLat * sinLon;
  up[2] = sinLat;
}

bool vtkGlobeEllipsoid::ComputeLocalFrame(
  double lon, double lat, double height, vtkMatrix4x4* enuToBody)
{
  const double llh[3] = { lon, lat, height };
  double origin[3];
  if (!enuToBody || !this->GeodeticToCartesian(llh, origin))
  {
    vtkErrorMacro(<< "ComputeLocalFrame: needs a matrix and finite coordinates");
    return false;
  }
  double axes[3][3];
  this->ComputeEastNorthUp(lon, lat, axes[0], axes[1], axes[2]);
  enuToBody->Identity();
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      enuToBody->SetElement(row, col, axes[col][row]);
    }
    enuToBody->SetElement(row, 3, origin[row]);
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkGlobeEllipsoid::IntersectRay(const double origin[3], const double direction[3], double t[2])
{
  t[0] = t[1] = NaN;
  if (!AllFinite(origin) || !AllFinite(direction))
  {
    vtkErrorMacro(<< "IntersectRay: non-finite ray");
    return 0;
  }
  // In the scaled space (x/a, y/b, z/c) the body is the unit sphere.
  double A = 0.0, B = 0.0, C = -1.0;
  for (int i = 0; i < 3; ++i)
  {
    const double o = origin[i] / this->Radii[i];
    const double d = direction[i] / this->Radii[i];
    A += d * d;
    B += o * d;
    C += o * o;
  }
  if (!(A > 0.0))
  {
    return 0;
  }
  const double disc = B * B - A * C;
  if (disc < 0.0)
  {
    return 0;
  }
  // The stable quadratic formula: no cancellation between B and the root.
  const double q = -(B + std::copysign(std::sqrt(disc), B));
  double t0 = q / A;
  double t1 = q != 0.0 ? C / q : t0;
  if (t0 > t1)
  {
    std::swap(t0, t1);
  }
  int count = 0;
  if (t0 >= 0.0)
  {
    t[count++] = t0;
  }
  if (t1 >= 0.0)
  {
    t[count++] = t1;
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkGlobeEllipsoid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << (this->Name ? this->Name : "(custom)") << "\n";
  const std::streamsize precision = os.precision(12);
  os << indent << "Radii: " << this->Radii[0] << ", " << this->Radii[1] << ", " << this->Radii[2]
     << " m\n";
  os.precision(precision);
  os << indent << "Shape: "
     << (this->IsSphere() ? "sphere"
                          : (this->IsTriaxial() ? "triaxial"
                                                : (this->IsProlate() ? "prolate spheroid"
                                                                     : "oblate spheroid")))
     << "\n";
  if (this->IsBiaxial())
  {
    os << indent << "Flattening: " << this->GetFlattening() << "\n";
  }
  os << indent << "UseGeographicLib: " << (this->UseGeographicLib ? "On" : "Off") << "\n";
}
