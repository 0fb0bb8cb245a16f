// Everest rising from behind the horizon: seen from 1,000 m, 200 km away, the peak stands
// above a horizon 113 km away. Only the secondary reference sphere lets the grid sample terrain
// past the primary sphere's horizon: with it, covered pixels above that horizon reconstruct to
// the Everest massif; without it (UseSecondarySphere off) the massif is gone: what rises above
// that horizon then is the horizon's own terrain (grid points past the limb take their horizon
// point, Documentation/rendering.md "The limb"), none of it beyond the horizon's distance.
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"
#include "vtkRegressionTestImage.h"

namespace
{
/// Covered pixels whose view ray misses the primary reference sphere (they lie above its
/// horizon), how many of them reconstruct to terrain beyond that horizon's distance, and how
/// many to within 60 km of the summit.
void AboveHorizon(vtkGlobeTest::Scene& scene, int& count, int& beyond, int& nearEverest)
{
  count = beyond = nearEverest = 0;
  vtkGlobeProjectiveGrid* grid = scene.Mapper->GetProjectiveGrid();
  const double* radii = scene.Body->GetRadii();
  const double rp = grid->GetPrimaryRadius();
  const double* eye = scene.Renderer->GetActiveCamera()->GetPosition();
  double summit[3];
  scene.Body->GeodeticToCartesian(86.925, 27.9881, 8848.0, summit);
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const int* size = scene.Window->GetSize();
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      const float d = depth[static_cast<size_t>(y) * size[0] + x];
      if (!(d < 1.0f))
      {
        continue;
      }
      double ray[3];
      vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
      // The ray against the primary sphere in the scaled space.
      double o[3], dir[3];
      for (int c = 0; c < 3; ++c)
      {
        o[c] = eye[c] / radii[c];
        dir[c] = ray[c] / radii[c];
      }
      const double A = vtkMath::Dot(dir, dir), B = vtkMath::Dot(o, dir), C = vtkMath::Dot(o, o) - rp * rp;
      if (B * B - A * C >= 0.0)
      {
        continue;
      }
      ++count;
      double p[3];
      vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, d, p);
      // The primary sphere's horizon distance, sqrt(d^2 - r^2), in metres (scaled by c).
      const double dist = std::sqrt(vtkMath::Dot(o, o));
      const double horizon = std::sqrt(dist * dist - rp * rp) * radii[2];
      beyond += std::sqrt(vtkMath::Distance2BetweenPoints(p, eye)) > horizon ? 1 : 0;
      nearEverest += std::sqrt(vtkMath::Distance2BetweenPoints(p, summit)) < 60000.0 ? 1 : 0;
    }
  }
}
} // namespace

int TestGlobeEverestHorizon(int argc, char* argv[])
{
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  const double camera[3] = { 85.2, 26.6, 1000.0 }, target[3] = { 86.925, 27.9881, 6000.0 };
  scene.Look(camera, target, 12.0, 100.0, 1.0e6);
  scene.Render();
  int above = 0, beyond = 0, nearEverest = 0;
  AboveHorizon(scene, above, beyond, nearEverest);
  std::printf("  with the secondary sphere: %d covered pixels above the primary horizon, %d of "
              "them terrain beyond its distance, %d within 60 km of the summit\n",
    above, beyond, nearEverest);
  const vtkGlobeTest::TerrainCheck check = vtkGlobeTest::CheckTerrain(scene, 2);
  bool ok = above > 500 && nearEverest > 100 && check.Failures == 0 && check.NaNs == 0;
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);

  scene.Mapper->GetProjectiveGrid()->UseSecondarySphereOff();
  scene.Render();
  int aboveWithout = 0, beyondWithout = 0, nearWithout = 0;
  AboveHorizon(scene, aboveWithout, beyondWithout, nearWithout);
  std::printf("  without it: %d covered pixels above the primary horizon, %d of them terrain "
              "beyond its distance, %d within 60 km of the summit\n",
    aboveWithout, beyondWithout, nearWithout);
  ok &= beyondWithout < beyond / 10 && nearWithout < nearEverest / 10;

  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
