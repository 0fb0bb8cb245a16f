// The Moon as a second body: a 1,737.4 km sphere with its albedo map (geographic, Moon 2000
// datum). Numeric: with no height layer every covered pixel lies on the sphere within the depth
// and mesh bounds, and its reconstructed position is the analytic ray-sphere intersection.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"
#include "vtkRegressionTestImage.h"

int TestGlobeMoon(int argc, char* argv[])
{
  vtkGlobeTest::Scene scene(300, 225, 512);
  scene.Body->SetToMoon();
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("moon/moon_1024x512.tif", false));
  const double camera[3] = { 30.0, 15.0, 4.0e6 }, target[3] = { 10.0, 0.0, 0.0 };
  scene.Look(camera, target, 45.0);
  scene.Render();
  const vtkGlobeTest::TerrainCheck check = vtkGlobeTest::CheckTerrain(scene, 2);
  bool ok = check.Pixels > 3000 && check.Failures == 0 && check.NaNs == 0;

  // Against the analytic ray-sphere intersection, along each checked ray.
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const std::vector<double> edges = vtkGlobeTest::MeshEdgeMap(scene);
  const int* size = scene.Window->GetSize();
  const double* eye = scene.Renderer->GetActiveCamera()->GetPosition();
  double worstRatio = 0.0, worst = 0.0;
  for (int y = 1; y < size[1]; y += 4)
  {
    for (int x = 1; x < size[0]; x += 4)
    {
      const size_t at = static_cast<size_t>(y) * size[0] + x;
      if (!(depth[at] < 1.0f))
      {
        continue;
      }
      double ray[3], p[3], t[2];
      vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
      vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, depth[at], p);
      if (scene.Body->IntersectRay(eye, ray, t) == 0)
      {
        continue; // the silhouette pixel's centre ray misses; its depth is the mesh edge's
      }
      const double along = std::sqrt(vtkMath::Distance2BetweenPoints(p, eye));
      const double error = std::abs(along - t[0]);
      // A chord of the sphere lies inside it by up to L^2/6R; seen along a ray at incidence i
      // that is L^2/(6R cos i); plus the depth quantization.
      double hit[3] = { eye[0] + t[0] * ray[0], eye[1] + t[0] * ray[1], eye[2] + t[0] * ray[2] };
      const double cosIncidence = std::abs(vtkMath::Dot(hit, ray)) / vtkMath::Norm(hit);
      const double bound = vtkGlobeTest::DepthBound(scene.Renderer->GetActiveCamera(), along) +
        edges[at] * edges[at] / (6.0 * 1737400.0 * std::max(cosIncidence, 0.05)) + 1e-3;
      worst = std::max(worst, error);
      worstRatio = std::max(worstRatio, error / bound);
    }
  }
  std::printf("  analytic ray-sphere: worst %.2f m along the ray, worst/bound %.3f\n", worst, worstRatio);
  ok &= worstRatio <= 1.0;
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
