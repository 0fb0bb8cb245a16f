#include "vtkGlobeCamera.h"

#include "vtkCamera.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkGlobeCamera);

bool vtkGlobeCamera::LookAt(vtkCamera* camera, vtkGlobeEllipsoid* body, const double view[6])
{
  return LookAt(camera, body, view[0], view[1], view[2], view[3], view[4], view[5]);
}

bool vtkGlobeCamera::LookAt(vtkCamera* camera, vtkGlobeEllipsoid* body, double lon, double lat,
  double height, double heading, double tilt, double range)
{
  if (!camera || !body)
  {
    vtkGenericWarningMacro(<< "vtkGlobeCamera::LookAt: no " << (camera ? "body" : "camera"));
    return false;
  }
  if (!std::isfinite(lon + lat + height + heading + tilt + range) || !(range > 0.0) ||
    !(tilt >= 0.0 && tilt < 90.0))
  {
    vtkErrorWithObjectMacro(camera, << "vtkGlobeCamera::LookAt: bad view (lon " << lon << ", lat "
                                    << lat << ", height " << height << ", heading " << heading
                                    << ", tilt " << tilt << ", range " << range << ")");
    return false;
  }
  double target[3], east[3], north[3], up[3];
  body->GeodeticToCartesian(lon, lat, height, target);
  body->ComputeEastNorthUp(lon, lat, east, north, up);
  const double h = vtkMath::RadiansFromDegrees(heading), t = vtkMath::RadiansFromDegrees(tilt);
  // The view direction: along the heading on the ground, tilted from straight down.
  double forward[3], view[3], position[3], viewUp[3];
  for (int i = 0; i < 3; ++i)
  {
    forward[i] = std::cos(h) * north[i] + std::sin(h) * east[i];
    view[i] = std::sin(t) * forward[i] - std::cos(t) * up[i];
    position[i] = target[i] - range * view[i];
    // The local vertical projected on the view plane; forward when looking straight down.
    viewUp[i] = std::cos(t) * forward[i] + std::sin(t) * up[i];
  }
  camera->SetPosition(position);
  camera->SetFocalPoint(target);
  camera->SetViewUp(viewUp);
  camera->OrthogonalizeViewUp();
  return true;
}

bool vtkGlobeCamera::FrameExtent(vtkGlobeEllipsoid* body, const double extent[4], double height,
  double viewAngle, double aspect, double view[6])
{
  if (!body || !extent || !view)
  {
    vtkGenericWarningMacro(<< "vtkGlobeCamera::FrameExtent: no " << (body ? "extent" : "body"));
    return false;
  }
  const double west = extent[0], south = extent[2], north = extent[3];
  if (!std::isfinite(west + extent[1] + south + north + height) || !(south < north) ||
    south < -90.0 || north > 90.0 || !(viewAngle > 0.0 && viewAngle < 180.0) || !(aspect > 0.0))
  {
    vtkErrorWithObjectMacro(body, << "vtkGlobeCamera::FrameExtent: bad extent (west " << west
                                  << ", east " << extent[1] << ", south " << south << ", north "
                                  << north << "), height " << height << ", view angle "
                                  << viewAngle << " or aspect " << aspect);
    return false;
  }
  // East of west by up to a turn: west > east crosses 180 degrees.
  double span = std::fmod(extent[1] - west, 360.0);
  span = span <= 0.0 ? span + 360.0 : span;
  // The extent sampled 17 x 17 at the height; its centre is the direction of the samples'
  // mean (a polar cap's is the pole, an extent across 180 degrees is centred there).
  const int n = 17;
  std::vector<std::array<double, 3>> samples;
  double mean[3] = { 0.0, 0.0, 0.0 };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      std::array<double, 3> p;
      body->GeodeticToCartesian(
        west + span * i / (n - 1.0), south + (north - south) * j / (n - 1.0), height, p.data());
      samples.push_back(p);
      vtkMath::Add(mean, p.data(), mean);
    }
  }
  // The mean lies inside the body, near the extent's middle (far outside, its geodetic
  // latitude would tend to the geocentric one).
  vtkMath::MultiplyScalar(mean, 1.0 / samples.size());
  double centre[3];
  if (!(vtkMath::Norm(mean) > 0.0) || !body->CartesianToGeodeticQuiet(mean, centre))
  {
    centre[0] = std::remainder(west + 0.5 * span, 360.0);
    centre[1] = 0.5 * (south + north);
  }
  const double tanV = std::tan(vtkMath::RadiansFromDegrees(0.5 * viewAngle));
  const double tanH = tanV * aspect;
  view[0] = centre[0];
  view[1] = centre[1];
  view[2] = height;
  view[3] = 0.0;
  view[4] = 0.0;
  double target[3], east[3], northDir[3], up[3];
  body->GeodeticToCartesian(centre[0], centre[1], height, target);
  body->ComputeEastNorthUp(centre[0], centre[1], east, northDir, up);
  // Looking down -up from target + r up: a point p is in view when its east and north offsets
  // stay within tan(half angle) times its depth r - (p - target) . up. Points more than 60
  // degrees around the body from the centre are near or past its horizon: frame the disc.
  double range = 0.0;
  bool disc = false;
  const double* radii = body->GetRadii();
  const double largest = std::max({ radii[0], radii[1], radii[2] }) + std::max(height, 0.0);
  for (const auto& p : samples)
  {
    const double d[3] = { p[0] - target[0], p[1] - target[1], p[2] - target[2] };
    const double x = vtkMath::Dot(d, east), y = vtkMath::Dot(d, northDir), z = vtkMath::Dot(d, up);
    disc |= vtkMath::Dot(p.data(), up) < 0.5 * vtkMath::Norm(p.data());
    range = std::max(range, std::max(std::abs(x) / tanH, std::abs(y) / tanV) + z);
  }
  if (disc)
  {
    // The whole disc: the body's bounding sphere inside the narrower half-angle.
    const double half = std::atan(std::min(tanV, tanH));
    view[5] = 1.05 * largest / std::sin(half) - largest;
    return true;
  }
  view[5] = std::max(1.05 * range, 1.0);
  return true;
}

void vtkGlobeCamera::InterpolateView(
  vtkGlobeEllipsoid* body, const double from[6], const double to[6], double t, double view[6])
{
  t = std::max(0.0, std::min(1.0, t));
  const double s = t * t * (3.0 - 2.0 * t); // smoothstep
  auto shorter = [](double a, double b) { return std::remainder(b - a, 360.0); };
  view[0] = from[0] + s * shorter(from[0], to[0]);
  view[0] = std::remainder(view[0], 360.0);
  view[1] = from[1] + s * (to[1] - from[1]);
  view[2] = from[2] + s * (to[2] - from[2]);
  view[3] = from[3] + s * shorter(from[3], to[3]);
  view[4] = from[4] + s * (to[4] - from[4]);
  const double r0 = std::max(from[5], 1e-3), r1 = std::max(to[5], 1e-3);
  double range = r0 * std::pow(r1 / r0, s);
  if (body)
  {
    double a[3], b[3];
    body->GeodeticToCartesian(from[0], from[1], from[2], a);
    body->GeodeticToCartesian(to[0], to[1], to[2], b);
    range += std::sin(vtkMath::Pi() * s) * 0.5 * std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
  }
  view[5] = range;
}

void vtkGlobeCamera::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
