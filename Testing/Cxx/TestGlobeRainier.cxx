// Near-surface steep view over Mount Rainier (Mahsman's TC2): the 90 m SRTM inset composed over
// the 2-degree relief, from 20 km. Numeric: every checked pixel within its terrain bound; the
// summit region is drawn at the summit's height.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkRegressionTestImage.h"

int TestGlobeRainier(int argc, char* argv[])
{
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  const double camera[3] = { -121.86, 46.75, 16000.0 }, target[3] = { -121.7603, 46.8523, 4392.0 };
  scene.Look(camera, target, 40.0, 100.0, 1.0e6);
  scene.Render();
  const vtkGlobeTest::TerrainCheck check = vtkGlobeTest::CheckTerrain(scene, 2);
  bool ok = check.Pixels > 10000 && check.Failures == 0 && check.NaNs == 0;
  // The data's summit (4,371 m) is in view: the highest reconstructed point reaches it.
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const int* size = scene.Window->GetSize();
  double highest = -1e9;
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      const float d = depth[static_cast<size_t>(y) * size[0] + x];
      if (d < 1.0f)
      {
        double p[3], llh[3];
        vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, d, p);
        scene.Body->CartesianToGeodetic(p, llh);
        highest = std::max(highest, llh[2]);
      }
    }
  }
  std::printf("  highest rendered point %.1f m (data summit 4371 m)\n", highest);
  ok &= highest > 4250.0 && highest < 4400.0;
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
