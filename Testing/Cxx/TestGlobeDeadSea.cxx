// Hard case: a viewer below the datum. A flat in-memory height layer puts the Dead Sea at
// -430 m (35.40..35.60 E, 31.10..31.80 N, feathered over two texels) over the 2-degree relief;
// the camera stands 2 m over the water at 31.3 N looking north along the lake, 3 degrees down,
// at -428 m: below the ellipsoid, above the local terrain. The primary sphere lies under the
// datum and the reference distance d < 1 in scaled units. (This scene found the float
// cancellation of s * r_p + nadir * d past the blend start, 0.4 m of noise on flat ground, now
// the E1 form in globe_pgm.glsl.) In each depth mode: no error, no GL
// error, no NaN in depth, G-buffer or PGM textures, terrain from depth within CheckTerrain's
// bound.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"
#include "vtkTestErrorObserver.h"

int TestGlobeDeadSea(int, char*[])
{
  bool ok = true;
  for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
  {
    vtkGlobeTest::Scene scene;
    scene.AddEarthLayers(true, false);
    const int w = 8, h = 28;
    std::vector<float> lake(w * h, -430.0f);
    vtkNew<vtkGlobeLayer> deadSea;
    deadSea->SetHeightData(w, h, lake.data(), 35.40, 35.60, 31.10, 31.80);
    deadSea->SetFeatherWidth(2.0);
    scene.Mapper->AddLayer(deadSea);
    vtkNew<vtkTest::ErrorObserver> errors;
    scene.Mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
    const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
    for (vtkGlobeLayer* layer : layers)
    {
      layer->Update();
    }
    const double lon = 35.5, lat = 31.3;
    const double ground = vtkGlobeTest::ComposedHeight(layers, lon, lat);
    double eye[3], east[3], north[3], up[3];
    scene.Body->GeodeticToCartesian(lon, lat, ground + 2.0, eye);
    scene.Body->ComputeEastNorthUp(lon, lat, east, north, up);
    const double tilt = vtkMath::RadiansFromDegrees(-3.0);
    double view[3];
    for (int i = 0; i < 3; ++i)
    {
      view[i] = std::cos(tilt) * north[i] + std::sin(tilt) * up[i];
    }
    vtkGlobeTest::LookAlong(scene.Renderer, eye, view, up, 50.0);
    scene.Renderer->ResetCameraClippingRange();
    scene.Render();
    std::printf("mode %s: camera at %.1f m (ground %.1f m)\n", vtkGlobeDepthPass::GetModeAsString(mode),
      ground + 2.0, ground);
    const vtkGlobeTest::HardCaseResult r = vtkGlobeTest::CheckHardCase(scene, pass, 2);
    ok &= vtkGlobeTest::HardCasePassed(r, 8000) && !errors->GetError() && ground + 2.0 < -400.0;
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
