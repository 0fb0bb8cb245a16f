// vtkGlobeGridPass on its own terms: after a frame, its PGM textures (read back from the GPU,
// float) match vtkGlobeProjectiveGrid::ComputeGridPoint (the same math in double) at every
// grid point, for several cameras: the whole Earth, near the ground, straight down the nadir
// and a distant one without a secondary sphere.
#include "vtkActor.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include <cmath>
#include <cstdio>

using vtkGlobeTest::Worst;

int TestGlobeGridPass(int, char*[])
{
  vtkNew<vtkGlobeEllipsoid> wgs84;
  vtkNew<vtkGlobeMapper> mapper;
  mapper->SetEllipsoid(wgs84);
  mapper->SetGridResolution(64);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(200, 150);
  window->AddRenderer(renderer);

  struct View
  {
    const char* Name;
    double Camera[3], Target[3], Angle;
  };
  const View views[] = { { "whole Earth", { -40, 25, 2.2e7 }, { -40, 25, 0 }, 30 },
    { "1 km over the ground, oblique", { 10, 45, 1000 }, { 10.1, 45.1, 0 }, 60 },
    { "down the nadir from 100 m", { 0, 0, 100 }, { 0, 0, 0 }, 45 },
    { "1e9 m away", { 120, -30, 1e9 }, { 120, -30, 0 }, 5 } };
  bool ok = true;
  for (const View& v : views)
  {
    vtkGlobeTest::LookAt(renderer, wgs84, v.Camera, v.Target, v.Angle);
    renderer->ResetCameraClippingRange();
    window->Render();
    vtkGlobeGridPass* pass = mapper->GetGridPass();
    vtkGlobeProjectiveGrid* grid = mapper->GetProjectiveGrid();
    const int n = pass->GetResolution();
    const std::vector<float> direction = vtkGlobeTest::ReadTexture(pass->GetDirectionTexture());
    const std::vector<float> position = vtkGlobeTest::ReadTexture(pass->GetPositionTexture());
    // Before the blend start a grid point is the exact ray hit: GPU and double agree to float
    // rounding. Past it the sampled direction also depends on the GPU's sin/atan (approximate
    // by design, see globe_pgm.glsl): there each GPU point must be self-consistent (on the
    // primary sphere, along its direction), and sample close to the double reference.
    const double fu = 1.0 / 16777216.0;
    const double d = grid->GetDistance(), rp = grid->GetPrimaryRadius();
    const double* eyeScaled = grid->GetEyeScaled();
    Worst dirError("direction, primary region: GPU vs double / bound", "");
    Worst posError("position, primary region: GPU vs double / bound", "");
    Worst sphereError("blend region: GPU point off the sphere / ulp d", "");
    Worst alongError("blend region: GPU point vs its direction", "rad");
    Worst sampleError("blend region: sampled direction GPU vs double", "rad");
    Worst flagError("hit flags that differ (not at the tangent)", "");
    int hits = 0;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const size_t at = 4 * (static_cast<size_t>(j) * n + i);
        const double u = static_cast<double>(i) / (n - 1), w = static_cast<double>(j) / (n - 1);
        double s[3], p[3], ray[3];
        const bool hit = grid->ComputeGridPoint(u, w, s, p);
        grid->ComputeGridRay(u, w, ray);
        const double* nadir = grid->GetNadir();
        const double omega = std::acos(
          std::max(-1.0, std::min(1.0, ray[0] * nadir[0] + ray[1] * nadir[1] + ray[2] * nadir[2])));
        const bool gpuHit = direction[at + 3] > 0.5f;
        const std::string where = vtkGlobeTest::Format("grid point (%g, %g), omega %g", i, j, omega);
        if (hit != gpuHit)
        {
          // Only a ray within float rounding of the tangent may disagree.
          flagError.Add(std::abs(omega - grid->GetPrimaryTangentAngle()) > 1e-5 ? 1.0 : 0.0, where);
          continue;
        }
        if (!hit)
        {
          continue;
        }
        ++hits;
        const double sg[3] = { direction[at], direction[at + 1], direction[at + 2] };
        const double pg[3] = { position[at], position[at + 1], position[at + 2] };
        double pn = 0, diff = 0;
        for (int c = 0; c < 3; ++c)
        {
          pn += p[c] * p[c];
          diff += (p[c] - pg[c]) * (p[c] - pg[c]);
        }
        const double angle = vtkGlobeTest::Angle(s, sg);
        if (omega <= grid->GetBlendStart() * (1.0 - 1e-6) || grid->GetSecondaryRadius() <= 0)
        {
          // Bounds: 16 ulp of the arithmetic, plus the float ray's own rounding (2 ulp of angle)
          // times the conditioning of the hit, |dt/dw| = d sin w (d cos w / S - 1), which
          // grows without bound at the tangent (S -> 0) where the ray grazes the sphere.
          const double sw = std::sin(omega), cw = std::cos(omega);
          const double S = std::sqrt(std::max(rp * rp - d * d * sw * sw, 1e-30));
          const double t = std::sqrt(pn);
          const double dtdw = std::abs(d * sw * (d * cw / S - 1.0));
          const double rayError = 2.0 * fu;
          posError.Add(std::sqrt(diff) / (16.0 * fu * t + rayError * (t + dtdw)), where);
          dirError.Add(angle / (16.0 * fu * (1.0 + d / rp) + rayError * (t + dtdw) / rp), where);
        }
        else
        {
          const double q[3] = { eyeScaled[0] + pg[0], eyeScaled[1] + pg[1], eyeScaled[2] + pg[2] };
          const double qn = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
          sphereError.Add(std::abs(qn - rp) / (fu * d), where);
          alongError.Add(vtkGlobeTest::Angle(q, sg), where);
          sampleError.Add(angle, where);
        }
      }
    }
    std::printf("%s: %d of %d grid points hit\n", v.Name, hits, n * n);
    ok &= hits > 0;
    ok &= dirError.Check(1.0);
    ok &= posError.Check(1.0);
    ok &= sphereError.Check(16.0);
    ok &= alongError.Check(16.0 * fu * (1.0 + d / rp));
    ok &= sampleError.Check(1e-3);
    ok &= flagError.Check(0.0);
  }
  std::printf("%s\n", ok ? "GPU grid matches the double reference" : "FAILED");

  // By default the grid follows the viewport (ceil(larger side / 1.6) points per side), or,
  // where the grid's own span on screen is shorter (the whole Earth in part of the window),
  // that span: a multiple of 16 points, at least span / 1.6. A fixed resolution stays fixed
  // whatever the window; SetGridPixelsPerCell follows it again.
  {
    vtkNew<vtkGlobeMapper> automatic;
    automatic->SetEllipsoid(wgs84);
    const bool defaults = automatic->GetGridPixelsPerCell() == 1.6 &&
      automatic->GetGridResolution() == 512 && automatic->GetTerrainRefinement() == 1;
    std::printf("default: %g pixels per cell, %d before the first frame, %d refinement step\n",
      automatic->GetGridPixelsPerCell(), automatic->GetGridResolution(),
      automatic->GetTerrainRefinement());
    ok &= defaults;
    vtkNew<vtkActor> globe;
    globe->SetMapper(automatic);
    vtkNew<vtkRenderer> r;
    r->AddActor(globe);
    vtkNew<vtkRenderWindow> w;
    w->SetOffScreenRendering(1);
    w->AddRenderer(r);
    auto frame = [&](int width, int height, int low, int high, const char* what) {
      w->SetSize(width, height);
      r->ResetCameraClippingRange();
      w->Render();
      const int n = automatic->GetGridResolution();
      const bool good = n >= low && n <= high && automatic->GetLastFrameDrewGlobe();
      std::printf("%s, %d x %d: grid %d (expected %d..%d)%s\n", what, width, height, n, low,
        high, good ? "" : " FAILED");
      ok &= good;
    };
    // Looking down at the ground, no sky (the grid reaches past the window): the window's
    // rule, exactly.
    const double low[3] = { -121.86, 46.75, 16000.0 }, ahead[3] = { -121.80, 46.80, 0.0 };
    vtkGlobeTest::LookAt(r, wgs84, low, ahead, 30);
    frame(400, 300, 250, 250, "following the window");
    frame(800, 600, 500, 500, "following the window");
    frame(1600, 1200, 1000, 1000, "following the window");
    frame(300, 500, 313, 313, "following the window (portrait)");
    frame(2, 2, 2, 2, "following the window (clamped)");
    // The whole Earth from 22,000 km in a 30 degree view: a disc tan(asin(a / d)) / tan(15
    // deg) of the window's height across (a sphere of the equatorial radius: the grid's span
    // is the limb's bounding square, within a few pixels of it). Its points: the disc's
    // diameter / 1.6, rounded up to 16, give or take one step of 16 for the fit's slack.
    const double camera[3] = { -40, 25, 2.2e7 }, target[3] = { -40, 25, 0 };
    vtkGlobeTest::LookAt(r, wgs84, camera, target, 30);
    const double a = wgs84->GetRadii()[0], d = a + 2.2e7;
    const double disc = std::tan(std::asin(a / d)) / std::tan(vtkMath::RadiansFromDegrees(15.0));
    auto points = [&](int height) {
      return 16 * static_cast<int>(std::ceil(disc * height / 1.6 / 16.0));
    };
    frame(400, 300, points(300) - 16, points(300) + 16, "the whole Earth's disc");
    frame(800, 600, points(600) - 16, points(600) + 16, "the whole Earth's disc");
    frame(1600, 1200, points(1200) - 16, points(1200) + 16, "the whole Earth's disc");
    frame(300, 500, points(500) - 16, std::min(313, points(500) + 16),
      "the whole Earth's disc (portrait)");
    automatic->SetGridResolution(128);
    frame(640, 480, 128, 128, "fixed");
    frame(320, 240, 128, 128, "fixed");
    automatic->SetGridPixelsPerCell(4.0);
    vtkGlobeTest::LookAt(r, wgs84, low, ahead, 30);
    frame(640, 480, 160, 160, "4 pixels per cell");
  }
  return ok ? 0 : 1;
}
