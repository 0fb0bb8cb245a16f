// The GLSL/C++ common-subset ellipsoid functions (globe_ellipsoid.glsl), compiled as C++ in
// float (what the GPU computes) and in double, against GeographicLib.
//
// Float bound: every float result is held to a stated number of float ulps of the scale of
// the problem, U = 2^-24 * max(|P|, a):
//   forward (lon, lat, h) -> P:             |P_f - P| <= 6 U
//   inverse P -> (lon, lat, h), judged by its backward error |forward_double(llh_f) - P| <= 8 U
//   angles outside the evolute (|h| < c/2): |lat_f - lat|, cos(lat)|lon_f - lon| <= 6 * 2^-24 rad
// Rounding the inputs to float alone costs up to ~2 U (an angle near pi moves by pi 2^-25), and
// each of the ~5 dependent operations adds half an ulp.
// and no result is NaN for any finite input, the centre and (0, 0, 1 m) included.
#include "vtkGlobeShaderMath.h"
#include "vtkGlobeTestHelpers.h"

#include <GeographicLib/Geocentric.hpp>

#include <cstdio>
#include <limits>
#include <vector>

using vtkGlobeTest::Format;
using vtkGlobeTest::Worst;
namespace F = vtkGlobeShaderMath::f;
namespace D = vtkGlobeShaderMath::d;

namespace
{
constexpr double Deg = 3.14159265358979323846 / 180.0;
constexpr double FloatUlp = 1.0 / 16777216.0; // 2^-24

struct Body
{
  const char* Name;
  double A, C;
};

bool RunBody(const Body& body)
{
  const double a = body.A, c = body.C;
  GeographicLib::Geocentric ref(a, (a - c) / a);
  const F::vec3 radiiF(static_cast<float>(a), static_cast<float>(a), static_cast<float>(c));
  const D::vec3 radiiD(a, a, c);

  Worst fForward("float forward |P_f - P| / U", "");
  Worst fBackward("float inverse backward error / U", "");
  Worst fLat("float latitude (|h| < c/2)", "rad");
  Worst fLon("float cos(lat) * longitude (|h| < c/2)", "rad");
  Worst fIterations("float Newton iterations", "");
  Worst dForward("double forward, |P| <= 1e9 m", "m");
  Worst dLat("double latitude (|h| < c/2)", "rad");
  Worst dHeight("double height (|h| < c/2)", "m");
  Worst dIterations("double Newton iterations", "");
  Worst dBackward("double inverse backward error", "m");
  double sumIterationsF = 0.0;
  Worst nan("NaN results for finite input", "");

  std::vector<std::vector<double>> points;
  for (double lon : vtkGlobeTest::SweepLongitudes())
  {
    for (double lat : vtkGlobeTest::SweepLatitudes())
    {
      for (double h : vtkGlobeTest::SweepHeights())
      {
        double p[3];
        ref.Forward(lat, lon, h, p[0], p[1], p[2]);
        const std::string where = Format("lon %.9g lat %.9g h %.9g", lon, lat, h);
        const double scale = std::max(vtkGlobeTest::Norm(p), a);

        const F::vec3 pf = F::globe_geodeticToCartesian(
          static_cast<float>(lon * Deg), static_cast<float>(lat * Deg), static_cast<float>(h), radiiF);
        const double pfd[3] = { pf.x, pf.y, pf.z };
        fForward.Add(vtkGlobeTest::Distance(pfd, p) / (FloatUlp * scale), where);

        const D::vec3 pd = D::globe_geodeticToCartesian(lon * Deg, lat * Deg, h, radiiD);
        const double pdd[3] = { pd.x, pd.y, pd.z };
        if (vtkGlobeTest::Norm(p) <= 1e9)
        {
          dForward.Add(vtkGlobeTest::Distance(pdd, p), where);
        }
        points.push_back({ p[0], p[1], p[2] });
      }
    }
  }
  for (const auto& q : vtkGlobeTest::CentralPoints(11))
  {
    points.push_back(q);
  }

  for (const auto& q : points)
  {
    const double* p = q.data();
    const std::string where = Format("P=(%.9g, %.9g, %.9g)", p[0], p[1], p[2]);
    const double scale = std::max(vtkGlobeTest::Norm(p), a);
    double refLat, refLon, refH;
    ref.Reverse(p[0], p[1], p[2], refLat, refLon, refH);
    const bool wellConditioned = std::abs(refH) < 0.5 * c;

    // Float: as the GPU does it.
    float lonF = 0, latF = 0, hF = 0;
    const F::vec3 pf(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
    F::globe_cartesianToGeodetic(pf, radiiF, lonF, latF, hF);
    int itF = 0;
    const F::vec3 sf = F::globe_scaleToGeodeticSurface(pf, radiiF, itF);
    fIterations.Add(itF, where);
    sumIterationsF += itF;
    const bool anyNaN = std::isnan(lonF) || std::isnan(latF) || std::isnan(hF) ||
      std::isnan(sf.x) || std::isnan(sf.y) || std::isnan(sf.z);
    nan.Add(anyNaN ? 1.0 : 0.0, where);
    double back[3];
    // latF may exceed pi/2 by an ulp; GeographicLib wants |lat| <= 90.
    const double latDeg = std::max(-90.0, std::min(90.0, latF / Deg));
    ref.Forward(latDeg, lonF / Deg, hF, back[0], back[1], back[2]);
    fBackward.Add(vtkGlobeTest::Distance(back, p) / (FloatUlp * scale), where);
    if (wellConditioned)
    {
      fLat.Add(std::abs(latF - refLat * Deg), where);
      if (std::abs(refLat) < 90.0)
      {
        fLon.Add(std::cos(refLat * Deg) * std::abs(vtkGlobeTest::WrapPi(lonF - refLon * Deg)), where);
      }
    }

    // Double: the same text without float rounding.
    double lonD = 0, latD = 0, hD = 0;
    D::globe_cartesianToGeodetic(D::vec3(p[0], p[1], p[2]), radiiD, lonD, latD, hD);
    int itD = 0;
    D::globe_scaleToGeodeticSurface(D::vec3(p[0], p[1], p[2]), radiiD, itD);
    dIterations.Add(itD, where);
    double backD[3];
    ref.Forward(std::max(-90.0, std::min(90.0, latD / Deg)), lonD / Deg, hD, backD[0], backD[1], backD[2]);
    if (vtkGlobeTest::Norm(p) <= 1e9)
    {
      dBackward.Add(vtkGlobeTest::Distance(backD, p), where);
    }
    if (wellConditioned)
    {
      dLat.Add(std::abs(latD - refLat * Deg), where);
      dHeight.Add(std::abs(hD - refH), where);
    }
  }

  std::printf("%s (a = %.1f m, c = %.1f m), %zu points, U = 2^-24 max(|P|, a):\n", body.Name, a,
    c, points.size());
  bool ok = true;
  ok &= fForward.Check(6.0);
  ok &= fBackward.Check(8.0);
  ok &= fLat.Check(6.0 * FloatUlp);
  ok &= fLon.Check(6.0 * FloatUlp);
  fIterations.Check(F::GLOBE_NEWTON_MAX_ITERATIONS); // reported: the cap makes it total
  std::printf("  %-46s mean %.4f\n", "float Newton iterations", sumIterationsF / points.size());
  ok &= nan.Check(0.0);
  ok &= dForward.Check(1e-6);
  ok &= dLat.Check(1e-12);
  ok &= dHeight.Check(1e-6);
  dIterations.Check(D::GLOBE_NEWTON_MAX_ITERATIONS);
  ok &= dBackward.Check(1e-6);
  return ok;
}

// Rays against the ellipsoid: float mirror vs the double formula, and never NaN.
bool RunRays()
{
  const double a = 6378137.0, c = 6356752.314245;
  const F::vec3 radiiF(static_cast<float>(a), static_cast<float>(a), static_cast<float>(c));
  Worst hit("float ray hit point vs double / U", "");
  Worst nan("NaN ray results", "");
  for (double dist : { 6.4e6, 7.0e6, 4.2e7, 1e9 })
  {
    for (double angle = 0.0; angle < 3.2; angle += 0.05)
    {
      const double o[3] = { dist, 0.0, 1000.0 };
      const double d[3] = { -std::cos(angle * 0.3), std::sin(angle * 0.3), 0.01 };
      float t0 = 0, t1 = 0;
      const int n = F::globe_intersectEllipsoid(F::vec3(o[0], o[1], o[2]),
        F::vec3(d[0], d[1], d[2]), radiiF, t0, t1);
      double tt0 = 0, tt1 = 0;
      const int nd = D::globe_intersectEllipsoid(D::vec3(o[0], o[1], o[2]),
        D::vec3(d[0], d[1], d[2]), D::vec3(a, a, c), tt0, tt1);
      const std::string where = Format("dist %.3g angle %.3g n %g", dist, angle, n);
      nan.Add(std::isnan(t0) || std::isnan(t1) ? 1.0 : 0.0, where);
      if (n == 2 && nd == 2)
      {
        // A hit point error of a few ulp of the origin distance (float cancellation).
        double pf[3], pd[3];
        for (int i = 0; i < 3; ++i)
        {
          pf[i] = o[i] + t0 * d[i];
          pd[i] = o[i] + tt0 * d[i];
        }
        hit.Add(vtkGlobeTest::Distance(pf, pd) / (FloatUlp * dist), where);
      }
    }
  }
  std::printf("Ray-ellipsoid (float vs double):\n");
  bool ok = hit.Check(16.0);
  ok &= nan.Check(0.0);
  return ok;
}
} // namespace

int TestGlobeShaderMathEllipsoid(int, char*[])
{
  const Body bodies[] = { { "WGS84", 6378137.0, 6378137.0 * (1.0 - 1.0 / 298.257223563) },
    { "Mars", 3396190.0, 3376200.0 }, { "Moon", 1737400.0, 1737400.0 },
    { "1 : 0.5 oblate", 1.0e6, 0.5e6 }, { "prolate", 6.0e6, 6.6e6 } };
  bool ok = true;
  for (const Body& body : bodies)
  {
    ok &= RunBody(body);
  }
  ok &= RunRays();
  std::printf("%s\n", ok ? "all within bounds" : "FAILED");
  return ok ? 0 : 1;
}
