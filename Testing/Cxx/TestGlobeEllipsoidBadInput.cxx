// Bad input to the geodesy core: non-finite coordinates, zero, negative and non-finite radii,
// prolate bodies (a < c, allowed), the centre, (0, 0, 1 m) where the book's Newton method
// never returns, and absurdly large values. Each gives defined output, an error through
// vtkErrorMacro where it is an error, and returns: no hang, no crash.
#include "vtkGlobeTestHelpers.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGeodeticTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <cstdio>
#include <limits>
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
  const bool said = observer->GetError() && observer->GetErrorMessage().find(words) != std::string::npos;
  observer->Clear();
  return said;
}

bool AllNaN(const double v[3])
{
  return std::isnan(v[0]) && std::isnan(v[1]) && std::isnan(v[2]);
}

bool AllFinite(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}
} // namespace

int TestGlobeEllipsoidBadInput(int, char*[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkGlobeEllipsoid> e;
  e->AddObserver(vtkCommand::ErrorEvent, observer);

  std::printf("Radii:\n");
  const double bad[][3] = { { 0, 1, 1 }, { 1, -1, 1 }, { 1, 1, nan }, { inf, 1, 1 }, { -0.0, 1, 1 } };
  for (const auto& r : bad)
  {
    const bool accepted = e->SetRadii(r[0], r[1], r[2]);
    char what[128];
    std::snprintf(what, sizeof(what), "SetRadii(%g, %g, %g) refused with an error, WGS84 kept", r[0], r[1], r[2]);
    Expect(!accepted && ErrorSaid(observer, "finite and positive") &&
        e->GetRadii()[0] == 6378137.0 && std::string(e->GetName()) == "WGS84",
      what);
  }
  Expect(e->SetRadii(6.0e6, 6.0e6, 6.6e6) && e->IsProlate() && e->GetFlattening() < 0 &&
      e->IsBiaxial() && !e->IsTriaxial() && !e->GetName() && !observer->GetError(),
    "a < c is accepted and reported as prolate, flattening < 0");
  std::ostringstream printed;
  e->Print(printed);
  Expect(printed.str().find("prolate spheroid") != std::string::npos, "PrintSelf names it a prolate spheroid");
  Expect(e->SetRadii(3.0e6, 2.0e6, 1.0e6) && e->IsTriaxial(), "a triaxial body is accepted");

  const char* bodies[] = { "WGS84 (GeographicLib)", "WGS84 (general solver)", "triaxial", "Moon" };
  for (int b = 0; b < 4; ++b)
  {
    std::printf("%s:\n", bodies[b]);
    e->SetUseGeographicLib(b != 1);
    if (b < 2)
    {
      e->SetToWGS84();
    }
    else if (b == 2)
    {
      e->SetRadii(3.0e6, 2.0e6, 1.0e6);
    }
    else
    {
      e->SetToMoon();
    }
    const double cMin = e->GetMinimumRadius();
    double out[3];
    const double badPoints[][3] = { { nan, 0, 0 }, { 0, inf, 0 }, { 0, 0, -inf } };
    bool allOk = true;
    for (const auto& p : badPoints)
    {
      allOk &= !e->CartesianToGeodetic(p, out) && AllNaN(out) && ErrorSaid(observer, "non-finite");
      allOk &= !e->GeodeticToCartesian(p, out) && AllNaN(out) && ErrorSaid(observer, "non-finite");
      allOk &= !e->ScaleToGeodeticSurface(p, out) && AllNaN(out) && ErrorSaid(observer, "non-finite");
    }
    Expect(allOk, "NaN/Inf coordinates: false, NaN output, an error naming non-finite input");

    const double centre[3] = { 0, 0, 0 };
    Expect(e->CartesianToGeodetic(centre, out) && AllFinite(out) &&
        std::abs(out[2] + cMin) < 1e-6 && !observer->GetError(),
      "the centre: finite geodetic coordinates, height = -(shortest radius)");
    Expect(!e->ScaleToGeocentricSurface(centre, out) && AllNaN(out) && ErrorSaid(observer, "centre"),
      "the centre has no geocentric direction: error, NaN");

    const double nearAxis[3] = { 0, 0, 1.0 };
    Expect(e->CartesianToGeodetic(nearAxis, out) && AllFinite(out) && !observer->GetError(),
      "(0, 0, 1 m), where Cozzi & Ring's loop never returns: finite answer");
    double back[3];
    e->GeodeticToCartesian(out, back);
    Expect(std::abs(back[2] - 1.0) < 1e-6 && std::abs(back[0]) < 1e-6 && std::abs(back[1]) < 1e-6,
      "(0, 0, 1 m) round trips to within 1 um");

    const double huge[3] = { 1e300, -1e300, 1e300 };
    const bool hugeOk = e->CartesianToGeodetic(huge, out);
    Expect(hugeOk && std::isfinite(out[0]) && std::isfinite(out[1]) && !std::isnan(out[2]),
      "(1e300, -1e300, 1e300): returns finite angles, no hang");
    const double tiny[3] = { 1e-300, 1e-300, -1e-300 };
    Expect(e->CartesianToGeodetic(tiny, out) && AllFinite(out), "(1e-300, 1e-300, -1e-300): finite");

    double t[2];
    const double origin[3] = { 1e7, 0, 0 };
    const double zero[3] = { 0, 0, 0 };
    Expect(e->IntersectRay(origin, zero, t) == 0 && !observer->GetError(), "a zero ray direction hits nothing");
    const double nanDir[3] = { nan, 0, 0 };
    Expect(e->IntersectRay(origin, nanDir, t) == 0 && ErrorSaid(observer, "non-finite"),
      "a NaN ray: no hit, an error");
    const double inward[3] = { -1, 0, 0 };
    Expect(e->IntersectRay(origin, inward, t) == 2 && std::abs(t[0] - (1e7 - e->GetRadii()[0])) < 1e-6,
      "a ray from outside towards the centre hits twice, first at 1e7 - a");
    const double inside[3] = { 0, 0, 0 };
    Expect(e->IntersectRay(inside, inward, t) == 1 && std::abs(t[0] - e->GetRadii()[0]) < 1e-6,
      "a ray from the centre hits once, at a");
  }

  std::printf("Local frame and transform:\n");
  e->SetToWGS84();
  Expect(!e->ComputeLocalFrame(0, 0, 0, nullptr) && ErrorSaid(observer, "matrix"),
    "ComputeLocalFrame without a matrix: error");
  vtkNew<vtkMatrix4x4> frame;
  Expect(!e->ComputeLocalFrame(nan, 0, 0, frame) && observer->GetError(), "ComputeLocalFrame at NaN: error");
  observer->Clear();

  vtkNew<vtkGlobeGeodeticTransform> transform;
  vtkNew<vtkTest::ErrorObserver> transformObserver;
  transform->AddObserver(vtkCommand::ErrorEvent, transformObserver);
  vtkNew<vtkPoints> in;
  in->SetDataTypeToDouble();
  in->InsertNextPoint(0, 0, 0);
  in->InsertNextPoint(nan, 10, 0);
  in->InsertNextPoint(10, inf, 0);
  vtkNew<vtkPoints> out;
  out->SetDataTypeToDouble();
  transform->TransformPoints(in, out);
  double p0[3], p1[3];
  out->GetPoint(0, p0);
  out->GetPoint(1, p1);
  Expect(out->GetNumberOfPoints() == 3 && std::abs(p0[0] - 6378137.0) < 1e-6 && AllNaN(p1) &&
      ErrorSaid(transformObserver, "2 of 3 input points"),
    "transform: bad points map to NaN, one error counts them, good points are right");
  transform->SetEllipsoid(nullptr);
  Expect(transform->GetEllipsoid() != nullptr && transform->GetEllipsoid()->GetRadii()[0] == 6378137.0,
    "SetEllipsoid(nullptr) restores WGS84");

  return Checks.Result();
}
