// Hard case: the Earth from 1e9 m and 1e11 m, a disc ~16 pixels wide (the view angle shrinks
// with the distance). The secondary sphere is gone, the eye's scaled distance is 157 and
// 15,700; float eye-relative positions are ~1e11 m. In each depth mode: no GL error, no NaN in
// depth, G-buffer or PGM textures, the disc is drawn, and terrain from depth is within
// CheckTerrain's bound (the mesh chord and the depth quantization dominate).
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"

int TestGlobeVeryFar(int, char*[])
{
  bool ok = true;
  for (double distance : { 1.0e9, 1.0e11 })
  {
    for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
    {
      vtkGlobeTest::Scene scene;
      scene.AddEarthLayers(true, false);
      auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
      // The disc spans ~16 of the 225 rows.
      const double angle =
        vtkMath::DegreesFromRadians(2.0 * std::atan(6.4e6 / distance)) * 225.0 / 16.0;
      const double camera[3] = { 20.0, 10.0, distance }, target[3] = { 20.0, 10.0, 0.0 };
      vtkGlobeTest::LookAt(scene.Renderer, scene.Body, camera, target, angle);
      scene.Renderer->ResetCameraClippingRange();
      scene.Render();
      const int covered = vtkGlobeTest::CoveredPixels(vtkGlobeTest::ReadDepth(scene.Window));
      std::printf("%.0e m, mode %s: view angle %.4g degrees, %d pixels covered\n", distance,
        vtkGlobeDepthPass::GetModeAsString(mode), angle, covered);
      const vtkGlobeTest::HardCaseResult r = vtkGlobeTest::CheckHardCase(scene, pass, 1);
      // A disc 16 pixels across covers ~200.
      ok &= vtkGlobeTest::HardCasePassed(r, 120) && covered > 120 && covered < 300;
    }
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
