// A camera 200,000 km away: beyond ~92,000 km the secondary sphere's radius d cos(gamma_0) is
// negative and it vanishes (Documentation/rendering.md, "Errata and degenerate cases"); the
// planet is a small disc, still exact.
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkRegressionTestImage.h"

int TestGlobeFarAway(int argc, char* argv[])
{
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  const double camera[3] = { 20.0, 10.0, 2.0e8 }, target[3] = { 20.0, 10.0, 0.0 };
  scene.Look(camera, target, 5.0);
  scene.Render();
  vtkGlobeProjectiveGrid* grid = scene.Mapper->GetProjectiveGrid();
  std::printf("  secondary sphere radius %.4f (scaled; <= 0: none)\n", grid->GetSecondaryRadius());
  const vtkGlobeTest::TerrainCheck check = vtkGlobeTest::CheckTerrain(scene, 1);
  bool ok = grid->GetSecondaryRadius() <= 0.0 && check.Pixels > 1000 && check.Failures == 0 &&
    check.NaNs == 0;
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
