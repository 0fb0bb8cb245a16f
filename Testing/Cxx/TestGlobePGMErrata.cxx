// The errata-prone spots of PGM (Documentation/rendering.md, "PGM as implemented" and "Errata
// and degenerate cases"), on the very text the GPU runs (globe_pgm.glsl compiled as C++ in
// float, vtkGlobeShaderMath::f) against a long-double reference ray/sphere intersection. No
// GL: the grid's CPU set-up (vtkGlobeProjectiveGrid) supplies the frame parameters as the
// mapper uploads them (rounded to float).
//  1. Near-nadir rays (omega 0 .. 1e-3 rad) and the ray exactly along the nadir (the
//     cross-section basis degenerates: any perpendicular), at 1 m .. 36,000 km.
//  2. Grazing rays at the tangent angle (tau0 (1 - 1e-2 .. 1e-7)) and just past it, with the eye
//     above the datum and below it (d < 1: the Dead Sea at -428 m).
//     Held to: the float hit lies on the sphere within 16 float ulps of (t + a) (the height
//     metric is well conditioned at the tangent: moving along a grazing ray keeps the height),
//     the hit flag agrees away from the tangent, and nothing is NaN.
//  2b. Past the blend start (the secondary sphere on): the float vertex on the primary sphere.
//  2c. The same region from 7 mm over the ground at (179.99 E, 80 N), where every component of
//     a float unit vector carries 6e-8 of noise and the normal angles are ~1e-8: along a grid
//     line the vertices must move outward monotonically (a fold put long triangles under the
//     camera, TestGlobeJitter at 1 cm).
//  2d. Rays past the tangent (globe_pgmGridPoint's miss, "The limb"): from 2 m to 200,000 km up,
//     rays just past tau0 and pointing away from the body all give the same finite vertex,
//     on the primary sphere (2b's bound), flagged 0.5, sampling the farthest normal angle
//     (gamma_0 with a secondary sphere, within the float noise of its tangent hit;
//     acos(r_p / d) without).
//  3. E4 on Mars above 1,000 km (tau_s < b, where the printed blend returned NaN): the blend
//     region sampled finely is finite, continuous at b and never folds back.
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeShaderMath.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include <cmath>
#include <cstdio>

namespace F = vtkGlobeShaderMath::f;

namespace
{
typedef long double L;

struct Frame
{
  double D, R, A; // eye distance, sphere radius, altitude a = D - R (exact), scaled units
  double Nadir[3], Perp[3], Other[3];
};

/// globe_pgmGridPoint in float for the ray at angle omega from the nadir towards `towards`,
/// with the grid's frame rounded to float as the mapper uploads it. Returns the hit flag.
float FloatGridPoint(vtkGlobeProjectiveGrid* grid, double omega, const double towards[3],
  F::vec3& s, F::vec3& p)
{
  const double* nadir = grid->GetNadir();
  const double* perp = grid->GetNadirPerpendicular();
  const F::vec3 nf(static_cast<float>(nadir[0]), static_cast<float>(nadir[1]), static_cast<float>(nadir[2]));
  const F::vec3 pf(static_cast<float>(perp[0]), static_cast<float>(perp[1]), static_cast<float>(perp[2]));
  const F::vec3 ray(static_cast<float>(std::cos(omega) * nadir[0] + std::sin(omega) * towards[0]),
    static_cast<float>(std::cos(omega) * nadir[1] + std::sin(omega) * towards[1]),
    static_cast<float>(std::cos(omega) * nadir[2] + std::sin(omega) * towards[2]));
  return F::globe_pgmGridPoint(ray, nf, pf, static_cast<float>(grid->GetDistance()),
    static_cast<float>(grid->GetPrimaryRadius()), static_cast<float>(grid->GetAltitude()),
    static_cast<float>(grid->GetPrimaryTangentAngle()), static_cast<float>(grid->GetBlendStart()),
    static_cast<float>(grid->GetSecondaryRadius()),
    static_cast<float>(grid->GetDistance() - grid->GetSecondaryRadius()),
    static_cast<float>(grid->GetSecondaryBlendStart()),
    static_cast<float>(grid->GetSecondaryTangentAngle()), s, p);
}

/// The grid of an eye `above` metres over ground 430 m below the datum (the Dead Sea), looking
/// along -x, with terrain from -431 to 8,848 m.
void LookDown(vtkGlobeProjectiveGrid* grid, double above)
{
  const double eye[3] = { 6378137.0 - 430.0 + above, 0.0, 0.0 };
  const double corners[12] = { -1, -0.5, -0.5, -1, 0.5, -0.5, -1, 0.5, 0.5, -1, -0.5, 0.5 };
  const double up[3] = { 0, 0, 1 };
  grid->Update(eye, corners, up, -431.0, 8848.0);
}

/// Float PGM hit for a ray at angle omega from the nadir (azimuth fixed), against the
/// long-double intersection of the float-rounded ray. Returns the height error (m) of the
/// float hit over the sphere, or -1 for a miss (both agree) / -2 for a flag disagreement.
double HeightError(const Frame& f, double omega, double metres, bool& nan, double& bound, double& t)
{
  const double ray[3] = { std::cos(omega) * f.Nadir[0] + std::sin(omega) * f.Perp[0],
    std::cos(omega) * f.Nadir[1] + std::sin(omega) * f.Perp[1],
    std::cos(omega) * f.Nadir[2] + std::sin(omega) * f.Perp[2] };
  const F::vec3 rf(static_cast<float>(ray[0]), static_cast<float>(ray[1]), static_cast<float>(ray[2]));
  const F::vec3 nf(static_cast<float>(f.Nadir[0]), static_cast<float>(f.Nadir[1]),
    static_cast<float>(f.Nadir[2]));
  const F::vec3 pf(static_cast<float>(f.Other[0]), static_cast<float>(f.Other[1]),
    static_cast<float>(f.Other[2]));
  const double tau0 = std::asin(f.R / f.D);
  F::vec3 s, p;
  const float hit = F::globe_pgmGridPoint(rf, nf, pf, static_cast<float>(f.D),
    static_cast<float>(f.R), static_cast<float>(f.A), static_cast<float>(tau0),
    static_cast<float>(0.9 * tau0), -1.0f, 0.0f, 0.0f, 0.0f, s, p);
  nan = std::isnan(hit) || std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z) ||
    std::isnan(s.x) || std::isnan(s.y) || std::isnan(s.z);
  // Reference: the float ray and nadir as given (normalized in long double), the exact d, r, a.
  L n[3] = { nf.x, nf.y, nf.z }, r[3] = { rf.x, rf.y, rf.z };
  const L nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const L rn = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  L cosW = 0;
  for (int i = 0; i < 3; ++i)
  {
    n[i] /= nn;
    r[i] /= rn;
    cosW += n[i] * r[i];
  }
  const L d = f.D, rad = f.R, a = f.A;
  const L q = d * d * cosW * cosW - a * (d + rad);
  const bool exactHit = q >= 0 && cosW > 0;
  if (exactHit != (hit > 0.5f))
  {
    return -2.0;
  }
  if (!exactHit)
  {
    return -1.0;
  }
  t = static_cast<double>(a * (d + rad) / (d * cosW + std::sqrt(q)));
  // The float hit relative to the centre: eye (-d n) + p.
  L c[3] = { -d * n[0] + p.x, -d * n[1] + p.y, -d * n[2] + p.z };
  const L height = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) - rad;
  bound = 16.0 / 16777216.0 * (t + f.A) * metres + 1e-9;
  return std::abs(static_cast<double>(height)) * metres;
}

Frame MakeFrame(double metres, double eyeHeight, double sphereHeight)
{
  Frame f;
  f.D = 1.0 + eyeHeight / metres;
  f.R = 1.0 + sphereHeight / metres;
  f.A = (eyeHeight - sphereHeight) / metres;
  // A nadir with no special components, and two perpendiculars.
  const double n[3] = { -0.6, -0.48, 0.64 }, p[3] = { 0.8, -0.36, 0.48 };
  for (int i = 0; i < 3; ++i)
  {
    f.Nadir[i] = n[i];
    f.Perp[i] = p[i];
  }
  f.Other[0] = n[1] * p[2] - n[2] * p[1];
  f.Other[1] = n[2] * p[0] - n[0] * p[2];
  f.Other[2] = n[0] * p[1] - n[1] * p[0];
  return f;
}
} // namespace

int TestGlobePGMErrata(int, char*[])
{
  bool ok = true;
  const double R = 6378137.0;
  struct Eye
  {
    const char* Name;
    double Height, Sphere; // eye height and primary-sphere height over the datum (m)
  };
  const Eye eyes[] = { { "1 m", 1.0, -1.5 }, { "100 m", 100.0, -3.0 }, { "10 km", 1.0e4, 0.0 },
    { "Dead Sea -428 m", -428.0, -431.0 }, { "Everest +8850 m", 8850.0, 8700.0 },
    { "400 km", 4.0e5, -1.0e4 }, { "36,000 km", 3.6e7, -1.0e4 } };

  std::printf("1-2. Near-nadir and grazing rays (float PGM vs long double): height error / bound\n");
  for (const Eye& e : eyes)
  {
    const Frame f = MakeFrame(R, e.Height, e.Sphere);
    const double tau0 = std::asin(f.R / f.D);
    double worstNadir = 0, worstGrazing = 0, worstGrazingM = 0, tWorst = 0;
    int nans = 0, flags = 0, hits = 0;
    auto check = [&](double omega, double& worst, bool grazing) {
      bool nan = false;
      double bound = 1, t = 0;
      const double err = HeightError(f, omega, R, nan, bound, t);
      nans += nan ? 1 : 0;
      // Only rays within float rounding of the tangent may disagree about the hit.
      if (err == -2.0 && std::abs(omega - tau0) > 1e-6 * tau0 + 3e-7)
      {
        ++flags;
      }
      if (err >= 0)
      {
        ++hits;
        if (err / bound > worst)
        {
          worst = err / bound;
          if (grazing)
          {
            worstGrazingM = err;
            tWorst = t * R;
          }
        }
      }
    };
    // The exact nadir (basis degenerates), then rays ever closer to it.
    check(0.0, worstNadir, false);
    for (double omega = 1e-12; omega <= 1e-3; omega *= 3.0)
    {
      check(omega, worstNadir, false);
    }
    for (double rel = 1e-2; rel >= 1e-7; rel /= 2.0)
    {
      check(tau0 * (1.0 - rel), worstGrazing, true);
      check(tau0 * (1.0 + rel), worstGrazing, true); // past the tangent: a miss
    }
    std::printf("  eye %-16s near nadir %.3f, grazing %.3f (%.3g m at %.4g m); %d hits, %d NaN, "
                "%d flags wrong\n",
      e.Name, worstNadir, worstGrazing, worstGrazingM, tWorst, hits, nans, flags);
    ok &= worstNadir <= 1.0 && worstGrazing <= 1.0 && nans == 0 && flags == 0;
  }

  // 2b. Past the blend start the vertex is the primary-sphere point in the blended direction.
  // Formed as s r_p + nadir d it carried 1 ulp of the radius (0.4 m on the Earth) of float
  // noise, which a camera 2 m over flat ground sees (TestGlobeDeadSea); held to the same bound.
  std::printf("2b. Blend region (the secondary sphere on): height of the float vertex\n");
  {
    vtkNew<vtkGlobeEllipsoid> wgs84;
    vtkNew<vtkGlobeProjectiveGrid> grid;
    grid->SetEllipsoid(wgs84);
    for (double above : { 2.0, 100.0, 1.0e4 })
    {
      LookDown(grid, above);
      const double* nadir = grid->GetNadir();
      const double* perp = grid->GetNadirPerpendicular();
      const double b = grid->GetBlendStart(), tau0 = grid->GetPrimaryTangentAngle();
      const double rP = grid->GetPrimaryRadius(), dd = grid->GetDistance();
      const F::vec3 nf(static_cast<float>(nadir[0]), static_cast<float>(nadir[1]), static_cast<float>(nadir[2]));
      double worst = 0.0, worstM = 0.0;
      int nans = 0;
      for (int i = 1; i < 200; ++i)
      {
        const double omega = b + (tau0 - b) * i / 200.0;
        F::vec3 sv, p;
        FloatGridPoint(grid, omega, perp, sv, p);
        if (std::isnan(p.x + p.y + p.z))
        {
          ++nans;
          continue;
        }
        // Height over the primary sphere, in long double from the (float) nadir frame.
        L c[3];
        L n2 = 0;
        for (int k = 0; k < 3; ++k)
        {
          n2 += static_cast<L>(nf[k]) * nf[k];
        }
        for (int k = 0; k < 3; ++k)
        {
          c[k] = -static_cast<L>(dd) * nf[k] / std::sqrt(n2) + p[k];
        }
        const L height = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) - rP;
        const L t = std::sqrt(static_cast<L>(p.x) * p.x + static_cast<L>(p.y) * p.y + static_cast<L>(p.z) * p.z);
        const double bound = 16.0 / 16777216.0 * static_cast<double>(t + grid->GetAltitude()) * R + 1e-9;
        const double err = std::abs(static_cast<double>(height)) * R;
        if (err / bound > worst)
        {
          worst = err / bound;
          worstM = err;
        }
      }
      std::printf("  %.0f m over the ground: worst %.3g m, worst/bound %.3f, NaN %d\n", above, worstM,
        worst, nans);
      ok &= worst <= 1.0 && nans == 0 && grid->GetSecondaryRadius() > 0;
    }
  }

  // 2d. Rays past the tangent take their plane's horizon point.
  std::printf("2d. Rays past the tangent: the horizon point\n");
  {
    vtkNew<vtkGlobeEllipsoid> wgs84;
    vtkNew<vtkGlobeProjectiveGrid> grid;
    grid->SetEllipsoid(wgs84);
    for (double above : { 2.0, 2000.0, 4.0e5, 2.2e7, 2.0e8 })
    {
      LookDown(grid, above);
      const double* nadir = grid->GetNadir();
      const double* perp = grid->GetNadirPerpendicular();
      const double tau0 = grid->GetPrimaryTangentAngle();
      const double rP = grid->GetPrimaryRadius(), dd = grid->GetDistance();
      const bool secondary = grid->GetSecondaryRadius() > 0;
      const double expected = secondary ? grid->GetMaximumNormalAngle() : std::acos(rP / dd);
      const F::vec3 nf(static_cast<float>(nadir[0]), static_cast<float>(nadir[1]), static_cast<float>(nadir[2]));
      double worst = 0.0, worstAngle = 0.0, spread = 0.0;
      int nans = 0, flags = 0;
      F::vec3 first(0.0f);
      const double omegas[] = { tau0 + 1e-6, tau0 + 1e-3, 0.5 * (tau0 + vtkMath::Pi() / 2),
        vtkMath::Pi() / 2, 2.0, 3.1 };
      for (double omega : omegas)
      {
        F::vec3 sv, p;
        flags += FloatGridPoint(grid, omega, perp, sv, p) == 0.5f ? 1 : 0;
        if (std::isnan(p.x + p.y + p.z + sv.x + sv.y + sv.z))
        {
          ++nans;
          continue;
        }
        if (omega == omegas[0])
        {
          first = p;
        }
        spread = std::max(spread, static_cast<double>(glm::length(p - first)) * R);
        L c[3];
        L n2 = 0;
        for (int k = 0; k < 3; ++k)
        {
          n2 += static_cast<L>(nf[k]) * nf[k];
        }
        L cosG = 0;
        for (int k = 0; k < 3; ++k)
        {
          c[k] = -static_cast<L>(dd) * nf[k] / std::sqrt(n2) + p[k];
          cosG -= static_cast<L>(sv[k]) * nf[k] / std::sqrt(n2);
        }
        const L height = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) - rP;
        const L t = std::sqrt(static_cast<L>(p.x) * p.x + static_cast<L>(p.y) * p.y + static_cast<L>(p.z) * p.z);
        const double bound = 16.0 / 16777216.0 * static_cast<double>(t + grid->GetAltitude()) * R + 1e-9;
        worst = std::max(worst, std::abs(static_cast<double>(height)) * R / bound);
        worstAngle = std::max(worstAngle,
          std::abs(std::acos(std::max(-1.0, std::min(1.0, static_cast<double>(cosG)))) - expected));
      }
      std::printf("  %.4g m over the ground (%s): %d of 6 rays flagged as horizon points, "
                  "height/bound %.3f, normal angle off by %.2e rad, spread %.3g m, NaN %d\n",
        above, secondary ? "secondary sphere" : "no secondary sphere", flags, worst, worstAngle,
        spread, nans);
      // The secondary sphere's own tangent hit carries one float ulp of sin(tau_s) as a chord
      // (as every grid ray next to tau0 does): about 2e-4 rad at 400 km.
      ok &= flags == 6 && nans == 0 && worst <= 1.0 && worstAngle < 5e-4;
    }
  }

  // 2c. Monotonic vertices along a grid line past the blend start, far from the axes.
  std::printf("2c. Blend region from 7 mm up at (179.99, 80): vertices along a grid line\n");
  {
    vtkNew<vtkGlobeEllipsoid> wgs84;
    vtkNew<vtkGlobeProjectiveGrid> grid;
    grid->SetEllipsoid(wgs84);
    for (double above : { 0.0071, 1.0, 100.0 })
    {
      double eye[3], east[3], north[3], up[3];
      wgs84->GeodeticToCartesian(179.99, 80.0, -0.5 + above, eye);
      wgs84->ComputeEastNorthUp(179.99, 80.0, east, north, up);
      // A view straight along east, from 45 degrees down to the horizon.
      double corners[12];
      const double cornerDirs[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
      for (int c = 0; c < 4; ++c)
      {
        for (int k = 0; k < 3; ++k)
        {
          corners[3 * c + k] = east[k] + 0.5 * cornerDirs[c][0] * north[k] +
            0.5 * (cornerDirs[c][1] - 1.0) * up[k];
        }
      }
      grid->Update(eye, corners, up, -0.5, -0.5);
      const double* nadir = grid->GetNadir();
      const double b = grid->GetBlendStart(), tau0 = grid->GetPrimaryTangentAngle();
      int folds = 0, nans = 0, steps = 0;
      L previous = -1;
      for (int i = 1; i < 2000; ++i)
      {
        const double omega = b + (tau0 - b) * i / 2000.0;
        F::vec3 sv, p;
        FloatGridPoint(grid, omega, east, sv, p);
        if (std::isnan(p.x + p.y + p.z))
        {
          ++nans;
          continue;
        }
        // Distance from the nadir line (long double): must grow along the line.
        L along = 0, p2 = 0;
        for (int k = 0; k < 3; ++k)
        {
          along += static_cast<L>(p[k]) * nadir[k];
          p2 += static_cast<L>(p[k]) * p[k];
        }
        const L across = std::sqrt(std::max(p2 - along * along, static_cast<L>(0)));
        if (across < previous)
        {
          ++folds;
        }
        previous = across;
        ++steps;
      }
      std::printf("  %.4g m over the ground: %d of %d steps fold back, NaN %d\n", above, folds,
        steps, nans);
      ok &= folds == 0 && nans == 0 && grid->GetSecondaryRadius() > 0;
    }
  }

  std::printf("3. E4 on Mars: the blend region where tau_s < b\n");
  vtkNew<vtkGlobeEllipsoid> mars;
  mars->SetToMars();
  vtkNew<vtkGlobeProjectiveGrid> grid;
  grid->SetEllipsoid(mars);
  int e4Cases = 0;
  for (double altitude : { 1.0e5, 1.0e6, 2.0e6, 5.0e6, 2.0e7 })
  {
    const double* radii = mars->GetRadii();
    const double eye[3] = { radii[0] + altitude, 0.0, 0.0 };
    // Looking at the centre: the whole visible cap.
    const double corners[12] = { -1, -0.5, -0.5, -1, 0.5, -0.5, -1, 0.5, 0.5, -1, -0.5, 0.5 };
    const double up[3] = { 0, 0, 1 };
    grid->Update(eye, corners, up, -8200.0, 21229.0);
    const double b = grid->GetBlendStart(), tau0 = grid->GetPrimaryTangentAngle();
    const double tauS = grid->GetSecondaryTangentAngle();
    if (grid->GetSecondaryRadius() <= 0)
    {
      std::printf("  %8.0f km: no secondary sphere\n", altitude / 1000.0);
      continue;
    }
    e4Cases += tauS < b ? 1 : 0;
    const double* nadir = grid->GetNadir();
    const double* perp = grid->GetNadirPerpendicular();
    const F::vec3 nf(static_cast<float>(nadir[0]), static_cast<float>(nadir[1]), static_cast<float>(nadir[2]));
    // Normal angle (from the anti-nadir) of the direction sampled by the ray at omega; -1: miss.
    auto gammaAt = [&](double omega, bool& nan) {
      F::vec3 s, p;
      const float hit = FloatGridPoint(grid, omega, perp, s, p);
      nan = std::isnan(hit) || std::isnan(s.x + s.y + s.z) || std::isnan(p.x + p.y + p.z);
      if (nan || !(hit > 0.5f)) // a miss (0.5: its horizon point)
      {
        return -1.0;
      }
      return std::acos(std::max(-1.0, std::min(1.0,
        -static_cast<double>(s.x * nf.x + s.y * nf.y + s.z * nf.z))));
    };
    double previousGamma = -1.0, foldBack = 0.0, largest = 0.0;
    int nans = 0, hits = 0;
    const int steps = 4000;
    for (int i = 0; i <= steps; ++i)
    {
      bool nan = false;
      const double gamma = gammaAt(b - 0.01 * (tau0 - b) + (tau0 - b) * 1.01 * i / steps, nan);
      nans += nan ? 1 : 0;
      if (gamma < 0.0)
      {
        continue;
      }
      ++hits;
      if (previousGamma >= 0.0)
      {
        foldBack = std::max(foldBack, previousGamma - gamma);
      }
      previousGamma = gamma;
      largest = std::max(largest, gamma);
    }
    // Continuity at b (f = 0): the sampled normal angle on both sides of b, 1e-6 (tau0 - b) apart.
    bool nanA = false, nanB = false;
    const double eps = 1e-6 * (tau0 - b);
    const double jumpAtB = std::abs(gammaAt(b + eps, nanA) - gammaAt(b - eps, nanB));
    std::printf("  %8.0f km: tau_s %.5f %s b %.5f; %d hits, NaN %d, across b %.1e rad, "
                "fold-back %.1e rad, farthest normal angle %.4f (gamma_0 %.4f)\n",
      altitude / 1000.0, tauS, tauS < b ? "<" : ">=", b, hits, nans + (nanA || nanB ? 1 : 0),
      jumpAtB, foldBack, largest, grid->GetMaximumNormalAngle());
    ok &= nans == 0 && !nanA && !nanB && hits > 3900 && jumpAtB < 1e-5 && foldBack < 1e-5 &&
      largest <= grid->GetMaximumNormalAngle() + 1e-4;
  }
  ok &= e4Cases >= 2;
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
