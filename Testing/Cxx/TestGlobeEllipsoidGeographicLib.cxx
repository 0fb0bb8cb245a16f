// Round trips geodetic <-> Cartesian against GeographicLib (the exact reference) over a dense
// set of points: poles, date line, prime meridian, heights from -11 km (and deep inside the
// body) to 1e11 m, points near and at the centre and on the polar axis. Both solver paths of
// vtkGlobeEllipsoid are checked: GeographicLib's (biaxial default) and the general solver that
// triaxial bodies use, run here on biaxial bodies so GeographicLib can judge it.
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkNew.h"

#include <GeographicLib/Geocentric.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

using vtkGlobeTest::Format;
using vtkGlobeTest::Worst;

namespace
{
constexpr double Deg = 3.14159265358979323846 / 180.0;
constexpr double Eps = std::numeric_limits<double>::epsilon();

// Positions are held to 1 um. Beyond |P| ~ 1e9 m one double ulp exceeds 1 um, so there the
// bound is 4 ulp of |P| (8.9e-5 m at 1e11 m): the resolution of the reference itself.
constexpr double FarAway = 1.0e9;
double PositionBound(double norm)
{
  return std::max(1e-6, 4.0 * Eps * norm);
}

struct PathResult
{
  Worst Lat{ "latitude vs GeographicLib", "rad" };
  Worst Lon{ "longitude vs GeographicLib", "rad" };
  Worst Height{ "height vs GeographicLib, |P| <= 1e9 m", "m" };
  Worst Forward{ "forward position vs GeographicLib, |P| <= 1e9", "m" };
  Worst RoundTrip{ "round trip position, |P| <= 1e9 m", "m" };
  Worst FarHeight{ "height, |P| > 1e9 m, in units of 4 ulp(|P|)", "" };
  Worst FarForward{ "forward, |P| > 1e9 m, in units of 4 ulp(|P|)", "" };
  Worst FarTrip{ "round trip, |P| > 1e9 m, in 4 ulp(|P|)", "" };
  Worst CentralLat{ "latitude within 50 km of the centre", "rad" };
  Worst CentralTrip{ "round trip within 50 km of the centre", "m" };
};

void CompareReverse(const GeographicLib::Geocentric& ref, vtkGlobeEllipsoid* e, const double p[3],
  PathResult& r, bool central)
{
  double refLat, refLon, refH;
  ref.Reverse(p[0], p[1], p[2], refLat, refLon, refH);
  double llh[3];
  e->CartesianToGeodetic(p, llh);
  const std::string where = Format("P=(%.9g, %.9g, %.9g)", p[0], p[1], p[2]);
  const double norm = vtkGlobeTest::Norm(p);

  // Where the nearest foot point is not unique (on the equatorial plane inside the evolute,
  // and at the centre) both answers are right up to the sign of the latitude.
  const bool mirrorAmbiguous = p[2] == 0.0;
  double dLat = std::abs(llh[1] - refLat) * Deg;
  if (mirrorAmbiguous)
  {
    dLat = std::abs(std::abs(llh[1]) - std::abs(refLat)) * Deg;
  }
  const bool onAxis = p[0] == 0.0 && p[1] == 0.0;
  const bool centre = onAxis && p[2] == 0.0;
  const bool sphere = e->IsSphere();
  if (!(centre && sphere)) // every direction is nearest from the centre of a sphere
  {
    (central ? r.CentralLat : r.Lat).Add(dLat, where);
  }
  if (!onAxis && std::abs(refLat) < 90.0 - 1e-7)
  {
    r.Lon.Add(std::abs(vtkGlobeTest::WrapPi((llh[0] - refLon) * Deg)), where);
  }
  if (norm <= FarAway)
  {
    r.Height.Add(std::abs(llh[2] - refH), where);
  }
  else
  {
    r.FarHeight.Add(std::abs(llh[2] - refH) / PositionBound(norm), where);
  }

  double back[3];
  e->GeodeticToCartesian(llh, back);
  const double trip = vtkGlobeTest::Distance(back, p);
  if (central)
  {
    r.CentralTrip.Add(trip, where);
  }
  if (norm <= FarAway)
  {
    r.RoundTrip.Add(trip, where);
  }
  else
  {
    r.FarTrip.Add(trip / PositionBound(norm), where);
  }
}

bool RunBody(vtkGlobeEllipsoid* e, bool useGeographicLib)
{
  e->SetUseGeographicLib(useGeographicLib);
  const double* radii = e->GetRadii();
  GeographicLib::Geocentric ref(radii[0], (radii[0] - radii[2]) / radii[0]);
  std::printf("%s (a = %.3f m, c = %.3f m), %s solver:\n", e->GetName() ? e->GetName() : "custom",
    radii[0], radii[2], useGeographicLib ? "GeographicLib" : "general (triaxial)");

  PathResult r;
  int count = 0;
  for (double lon : vtkGlobeTest::SweepLongitudes())
  {
    for (double lat : vtkGlobeTest::SweepLatitudes())
    {
      for (double h : vtkGlobeTest::SweepHeights())
      {
        double p[3];
        ref.Forward(lat, lon, h, p[0], p[1], p[2]);
        double mine[3];
        e->GeodeticToCartesian(lon, lat, h, mine);
        const double norm = vtkGlobeTest::Norm(p);
        const double error = vtkGlobeTest::Distance(mine, p);
        const std::string where = Format("lon %.9g lat %.9g h %.9g", lon, lat, h);
        if (norm <= FarAway)
        {
          r.Forward.Add(error, where);
        }
        else
        {
          r.FarForward.Add(error / PositionBound(norm), where);
        }
        CompareReverse(ref, e, p, r, false);
        ++count;
      }
    }
  }
  for (const auto& c : vtkGlobeTest::CentralPoints(7))
  {
    CompareReverse(ref, e, c.data(), r, vtkGlobeTest::Norm(c.data()) <= 5.0e4 * std::sqrt(3.0));
    ++count;
  }
  std::printf("  %d points\n", count);
  bool ok = true;
  ok &= r.Lat.Check(1e-12);
  ok &= r.Lon.Check(1e-12);
  ok &= r.Height.Check(1e-6);
  ok &= r.Forward.Check(1e-6);
  ok &= r.RoundTrip.Check(1e-6);
  ok &= r.FarHeight.Check(1.0);
  ok &= r.FarForward.Check(1.0);
  ok &= r.FarTrip.Check(1.0);
  // Near the centre the latitude is ill-conditioned (the foot point moves fast near the
  // evolute), yet both solvers still agree to 1e-12 rad.
  ok &= r.CentralLat.Check(1e-12);
  ok &= r.CentralTrip.Check(1e-6);
  return ok;
}
} // namespace

int TestGlobeEllipsoidGeographicLib(int, char*[])
{
  bool ok = true;
  vtkNew<vtkGlobeEllipsoid> e;
  const char* presets[] = { "WGS84", "GRS80", "Mars", "Moon", "prolate" };
  for (const char* preset : presets)
  {
    const std::string name = preset;
    if (name == "WGS84")
    {
      e->SetToWGS84();
    }
    else if (name == "GRS80")
    {
      e->SetToGRS80();
    }
    else if (name == "Mars")
    {
      e->SetToMars();
    }
    else if (name == "Moon")
    {
      e->SetToMoon();
    }
    else
    {
      e->SetRadii(6.0e6, 6.0e6, 6.6e6);
    }
    ok &= RunBody(e, true);
    ok &= RunBody(e, false);
  }
  std::printf("%s\n", ok ? "all within bounds" : "FAILED");
  return ok ? 0 : 1;
}
