// vtkGlobeCamera (issue 13): views given as (lon, lat, height, heading, tilt, range), against
// the geometry they name, in double, on WGS84, the Moon and a triaxial body:
//  - LookAt: the focal point is the target (1e-6 m), the camera is `range` from it (1e-6 m),
//    the view makes `tilt` with the downward vertical and points along `heading` on the
//    ground (1e-9 degrees, from the ellipsoid's east-north-up frame), and the view-up lies in
//    the vertical plane of the view (no roll, 1e-9);
//  - InterpolateView: the two ends are the two views; longitude and heading take the shorter
//    way across 180 degrees; the range climbs in the middle of a long flight;
//  - bad views are refused with an error.
#include "vtkGlobeTestHelpers.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkGlobeCamera.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
vtkGlobeTest::Checklist Check;

void CheckLookAt(vtkGlobeEllipsoid* body, const double v[6], const std::string& what)
{
  vtkNew<vtkCamera> camera;
  const bool ok = vtkGlobeCamera::LookAt(camera, body, v);
  double target[3], east[3], north[3], up[3], d[3];
  body->GeodeticToCartesian(v[0], v[1], v[2], target);
  body->ComputeEastNorthUp(v[0], v[1], east, north, up);
  const double* position = camera->GetPosition();
  const double* focal = camera->GetFocalPoint();
  camera->GetDirectionOfProjection(d);
  const double focusError = std::sqrt(vtkMath::Distance2BetweenPoints(focal, target));
  const double rangeError = std::abs(std::sqrt(vtkMath::Distance2BetweenPoints(position, target)) - v[5]);
  const double tilt = vtkMath::DegreesFromRadians(std::acos(-vtkMath::Dot(d, up)));
  double tiltError = std::abs(tilt - v[4]);
  double headingError = 0.0;
  if (v[4] > 1e-6)
  {
    const double heading = vtkMath::DegreesFromRadians(std::atan2(vtkMath::Dot(d, east), vtkMath::Dot(d, north)));
    headingError = std::abs(std::remainder(heading - v[3], 360.0));
  }
  // No roll: the view-up is in the plane of the view direction and the vertical.
  double normal[3];
  vtkMath::Cross(d, v[4] > 1e-6 ? up : north, normal);
  vtkMath::Normalize(normal);
  const double roll = std::abs(vtkMath::Dot(camera->GetViewUp(), normal));
  char text[300];
  std::snprintf(text, sizeof(text),
    "%s: focus %.1e m, range %.1e m, tilt %.1e deg, heading %.1e deg, roll %.1e", what.c_str(),
    focusError, rangeError, tiltError, headingError, roll);
  Check.Expect(ok && focusError <= 1e-6 && rangeError <= 1e-6 && tiltError <= 1e-9 &&
      headingError <= 1e-9 && roll <= 1e-9,
    text);
}
}

int TestGlobeCamera(int, char*[])
{
  vtkNew<vtkGlobeEllipsoid> wgs84, moon, triaxial;
  moon->SetToMoon();
  triaxial->SetRadii(3000.0, 2500.0, 2000.0);
  const double views[][6] = { { -121.7603, 46.8523, 4392.0, 30.0, 60.0, 15000.0 },
    { 179.9, -89.5, 0.0, 250.0, 10.0, 3.0e6 }, { 0.0, 0.0, -100.0, 0.0, 0.0, 500.0 },
    { 86.925, 27.988, 8848.0, -170.0, 85.0, 2.0e5 } };
  for (const auto& v : views)
  {
    CheckLookAt(wgs84, v, "WGS84 " + std::to_string(v[0]) + ", " + std::to_string(v[1]));
  }
  const double lunar[6] = { 23.47, 0.67, -1900.0, 45.0, 70.0, 5000.0 };
  CheckLookAt(moon, lunar, "the Moon, Apollo 11");
  const double small[6] = { 40.0, 30.0, 10.0, 300.0, 50.0, 800.0 };
  CheckLookAt(triaxial, small, "a triaxial body");

  // The fly-to: its ends, the shorter way, the climb.
  const double from[6] = { 170.0, 10.0, 0.0, 350.0, 30.0, 1000.0 };
  const double to[6] = { -170.0, 20.0, 100.0, 10.0, 60.0, 4000.0 };
  double a[6], b[6], mid[6];
  vtkGlobeCamera::InterpolateView(wgs84, from, to, 0.0, a);
  vtkGlobeCamera::InterpolateView(wgs84, from, to, 1.0, b);
  vtkGlobeCamera::InterpolateView(wgs84, from, to, 0.5, mid);
  double endError = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    endError = std::max({ endError, std::abs(std::remainder(a[i] - from[i], 360.0)),
      std::abs(std::remainder(b[i] - to[i], 360.0)) });
  }
  char text[300];
  std::snprintf(text, sizeof(text),
    "fly-to: ends within %.1e; midway lon %.6f (want 180), heading %.6f (want 0), range %.0f m "
    "(ends 1000 and 4000 m, the targets ~2,400 km apart)",
    endError, mid[0], mid[3], mid[5]);
  Check.Expect(endError <= 1e-9 && std::abs(std::remainder(mid[0] - 180.0, 360.0)) <= 1e-9 &&
      std::abs(std::remainder(mid[3], 360.0)) <= 1e-9 && mid[5] > 1.0e6,
    text);

  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkCamera> camera;
  camera->AddObserver(vtkCommand::ErrorEvent, errors);
  const double bad[6] = { 0.0, 0.0, 0.0, 0.0, 90.0, 100.0 };
  Check.Expect(!vtkGlobeCamera::LookAt(camera, wgs84, bad) && errors->GetError(),
    "a tilt of 90 degrees is refused with an error");
  // Framing an extent: every sample of its boundary inside the view, and the view no wider
  // than needed (some sample within 10 % of the edge of the normalized view).
  struct Frame
  {
    const char* Name;
    double Extent[4];
    double Height, Aspect;
  };
  const Frame frames[] = { { "Rainier inset", { -122.0, -121.0, 46.0, 47.0 }, 0.0, 4.0 / 3.0 },
    { "across 180 degrees", { 170.0, -170.0, -10.0, 5.0 }, 0.0, 1.0 },
    { "polar cap", { -180.0, 180.0, 70.0, 90.0 }, 0.0, 0.5 },
    { "a tall, narrow strip", { 10.0, 11.0, -40.0, 40.0 }, 1000.0, 2.0 } };
  for (const Frame& f : frames)
  {
    double view[6];
    const bool ok = vtkGlobeCamera::FrameExtent(wgs84, f.Extent, f.Height, 30.0, f.Aspect, view);
    vtkNew<vtkCamera> framing;
    framing->SetViewAngle(30.0);
    vtkGlobeCamera::LookAt(framing, wgs84, view);
    framing->SetClippingRange(1.0, 1e8);
    vtkMatrix4x4* m = framing->GetCompositeProjectionTransformMatrix(f.Aspect, -1.0, 1.0);
    double extreme = 0.0;
    for (int j = 0; j <= 20; ++j)
    {
      for (int i = 0; i <= 20; ++i)
      {
        double span = std::fmod(f.Extent[1] - f.Extent[0], 360.0);
        span = span <= 0.0 ? span + 360.0 : span;
        double p[4] = { 0, 0, 0, 1 };
        wgs84->GeodeticToCartesian(f.Extent[0] + span * i / 20.0,
          f.Extent[2] + (f.Extent[3] - f.Extent[2]) * j / 20.0, f.Height, p);
        m->MultiplyPoint(p, p);
        extreme = std::max({ extreme, std::abs(p[0] / p[3]), std::abs(p[1] / p[3]) });
      }
    }
    std::snprintf(text, sizeof(text),
      "FrameExtent, %s: range %.0f m, every boundary sample in view (largest |ndc| %.3f <= 1, "
      "and >= 0.9: tight)",
      f.Name, view[5], extreme);
    Check.Expect(ok && extreme <= 1.0 && extreme >= 0.9, text);
  }
  const double badExtent[4] = { 0.0, 10.0, 20.0, 10.0 };
  double unused[6];
  vtkNew<vtkTest::ErrorObserver> bodyErrors;
  wgs84->AddObserver(vtkCommand::ErrorEvent, bodyErrors);
  Check.Expect(!vtkGlobeCamera::FrameExtent(wgs84, badExtent, 0.0, 30.0, 1.0, unused) &&
      bodyErrors->GetError(),
    "FrameExtent refuses an extent whose south lies north of its north, with an error");
  return Check.Result();
}
