// Looking straight down the nadir from 12 km over Mount Rainier, where the cross-section basis
// of PGM degenerates for the central ray (Documentation/rendering.md, "Errata and degenerate
// cases"). Numeric: the terrain bound at every checked pixel, no NaN, and the centre pixel lies
// below the camera on the summit massif.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkRegressionTestImage.h"

int TestGlobeNadir(int argc, char* argv[])
{
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  const double camera[3] = { -121.7603, 46.8523, 12000.0 }, target[3] = { -121.7603, 46.8523, 0.0 };
  scene.Look(camera, target, 50.0, 100.0, 1.0e6);
  scene.Render();
  const vtkGlobeTest::TerrainCheck check = vtkGlobeTest::CheckTerrain(scene, 2);
  bool ok = check.Pixels > 15000 && check.Failures == 0 && check.NaNs == 0;
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const int* size = scene.Window->GetSize();
  const int cx = size[0] / 2, cy = size[1] / 2;
  double p[3], llh[3];
  vtkGlobeTest::UnprojectPixel(scene.Renderer, cx + 0.5, cy + 0.5, depth[static_cast<size_t>(cy) * size[0] + cx], p);
  scene.Body->CartesianToGeodetic(p, llh);
  std::printf("  centre pixel: lon %.5f lat %.5f h %.1f m\n", llh[0], llh[1], llh[2]);
  ok &= std::abs(llh[0] + 121.7603) < 0.01 && std::abs(llh[1] - 46.8523) < 0.01 && llh[2] > 4000.0;
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
