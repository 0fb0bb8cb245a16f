// Hard case: the Moon (1,737.4 km sphere, albedo only) from 1 m over its surface, looking
// 5 degrees down: ground from ~1.5 m to the horizon 1.86 km away. Scaled altitude 5.8e-7, the
// smallest the grid meets (ground beyond ~260 m lies within one pixel row of the horizon).
// In each depth mode: no GL error, no NaN in depth, G-buffer or PGM
// textures, terrain from depth (the sphere) within CheckTerrain's bound.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"

int TestGlobeMoonSurface(int, char*[])
{
  bool ok = true;
  for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
  {
    vtkGlobeTest::Scene scene;
    scene.Body->SetToMoon();
    scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("moon/moon_1024x512.tif", false));
    auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
    double eye[3], east[3], north[3], up[3];
    scene.Body->GeodeticToCartesian(30.0, 15.0, 1.0, eye);
    scene.Body->ComputeEastNorthUp(30.0, 15.0, east, north, up);
    const double tilt = vtkMath::RadiansFromDegrees(-5.0);
    double view[3];
    for (int i = 0; i < 3; ++i)
    {
      view[i] = std::cos(tilt) * east[i] + std::sin(tilt) * up[i];
    }
    vtkGlobeTest::LookAlong(scene.Renderer, eye, view, up, 50.0);
    scene.Renderer->ResetCameraClippingRange();
    scene.Render();
    std::printf("mode %s: 1 m over the Moon\n", vtkGlobeDepthPass::GetModeAsString(mode));
    const vtkGlobeTest::HardCaseResult r = vtkGlobeTest::CheckHardCase(scene, pass, 2);
    ok &= vtkGlobeTest::HardCasePassed(r, 8000) && r.Farthest > 200.0;
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
