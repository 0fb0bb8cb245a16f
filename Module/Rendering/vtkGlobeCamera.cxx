#include "vtkGlobeCamera.h"

#include "vtkCamera.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

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
