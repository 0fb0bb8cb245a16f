// Whole-Earth view (Mahsman's TC1): the relief, the SRTM insets and the Blue Marble imagery,
// from 22,000 km. Numeric: every covered pixel's depth-reconstructed position has the
// composed data height at its geodetic position, within the bound of the depth buffer and of
// what the PGM mesh can represent there (vtkGlobeTest::CheckTerrain); the second frame's
// primary sphere comes from the GPU reduction of the first.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkRegressionTestImage.h"

int TestGlobeWholeEarth(int argc, char* argv[])
{
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  const double camera[3] = { -40.0, 25.0, 2.2e7 }, target[3] = { -40.0, 25.0, 0.0 };
  scene.Look(camera, target, 30.0);
  scene.Render();

  bool ok = true;
  const vtkGlobeTest::TerrainCheck check = vtkGlobeTest::CheckTerrain(scene, 3);
  ok &= check.Pixels > 2000 && check.Failures == 0 && check.NaNs == 0;

  ok &= scene.Mapper->GetPrimaryFromReduction();

  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
