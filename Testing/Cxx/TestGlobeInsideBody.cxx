// Hard case: cameras inside the body (1,000 km under the surface, looking out at a cone 1 km
// away, and 10 m under Rainier's summit looking at the sky) in each depth mode: the globe
// reports at most one error over several frames, nothing crashes, there is no GL error and no
// NaN in the depth buffer, the G-buffer or the PGM textures, and the cone still renders.
#include "vtkConeSource.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkTestErrorObserver.h"

int TestGlobeInsideBody(int, char*[])
{
  bool ok = true;
  for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
  {
    for (int where = 0; where < 2; ++where)
    {
      vtkGlobeTest::Scene scene;
      scene.AddEarthLayers(true, false);
      vtkNew<vtkTest::ErrorObserver> errors;
      scene.Mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
      const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
      for (vtkGlobeLayer* layer : layers)
      {
        layer->Update();
      }
      double eye[3], east[3], north[3], up[3];
      if (where == 0)
      {
        scene.Body->GeodeticToCartesian(10.0, 20.0, -1.0e6, eye);
        scene.Body->ComputeEastNorthUp(10.0, 20.0, east, north, up);
      }
      else
      {
        const double ground = vtkGlobeTest::ComposedHeight(layers, -121.7603, 46.8523);
        scene.Body->GeodeticToCartesian(-121.7603, 46.8523, ground - 10.0, eye);
        scene.Body->ComputeEastNorthUp(-121.7603, 46.8523, east, north, up);
      }
      vtkNew<vtkConeSource> cone;
      cone->SetCenter(eye[0] + 1000.0 * up[0], eye[1] + 1000.0 * up[1], eye[2] + 1000.0 * up[2]);
      cone->SetHeight(200.0);
      cone->SetRadius(100.0);
      cone->SetDirection(-up[0], -up[1], -up[2]);
      scene.Renderer->AddActor(vtkGlobeTest::FlatActor(cone, 1, 0, 0));
      vtkGlobeTest::LookAlong(scene.Renderer, eye, up, north, 50.0);
      scene.Renderer->ResetCameraClippingRange();
      int reported = 0;
      for (int frame = 0; frame < 3; ++frame)
      {
        scene.Window->Render();
        reported += errors->GetError() ? 1 : 0;
        errors->Clear();
      }
      const vtkGlobeTest::HardCaseResult r = vtkGlobeTest::CheckHardCase(scene, pass, 0);
      const int covered = vtkGlobeTest::CoveredPixels(vtkGlobeTest::ReadDepth(scene.Window));
      std::printf("mode %s, %s: %d error report(s) in 3 frames, %d pixels drawn\n",
        vtkGlobeDepthPass::GetModeAsString(mode),
        where == 0 ? "1000 km deep" : "10 m under Rainier", reported, covered);
      ok &= reported <= 1 && covered > 500 && r.GLOk && r.DepthNaN == 0 && r.GBufferNaN == 0 &&
        r.GridNaN == 0;
    }
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
