// Hard case: a camera on the date line (longitude 180) 1 km from the North Pole, 100 m over
// the composed terrain (the Arctic sea floor of the 2-degree relief), looking across the pole
// 10 degrees down: the view spans longitudes from -180 to 180 and the pole itself, where
// geodetic longitude is singular and the grid's directions wrap. In each depth mode: no GL
// error, no NaN in depth, G-buffer or PGM textures, terrain from depth within CheckTerrain's
// bound.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"

int TestGlobeNorthPole(int, char*[])
{
  bool ok = true;
  for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
  {
    vtkGlobeTest::Scene scene;
    scene.AddEarthLayers(true, false);
    auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
    const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
    for (vtkGlobeLayer* layer : layers)
    {
      layer->Update();
    }
    // 1 km from the pole along the meridian (GeographicLib-exact enough: 1 km is 0.00899 deg).
    const double lat = 90.0 - 1000.0 / 111694.0;
    const double ground = vtkGlobeTest::ComposedHeight(layers, 180.0, lat);
    double eye[3], east[3], north[3], up[3];
    scene.Body->GeodeticToCartesian(180.0, lat, ground + 100.0, eye);
    scene.Body->ComputeEastNorthUp(180.0, lat, east, north, up);
    const double tilt = vtkMath::RadiansFromDegrees(-10.0);
    double view[3];
    for (int i = 0; i < 3; ++i)
    {
      view[i] = std::cos(tilt) * north[i] + std::sin(tilt) * up[i];
    }
    vtkGlobeTest::LookAlong(scene.Renderer, eye, view, up, 50.0);
    scene.Renderer->ResetCameraClippingRange();
    scene.Render();
    std::printf("mode %s: 100 m over the sea floor at %.0f m, 1 km from the pole\n",
      vtkGlobeDepthPass::GetModeAsString(mode), ground);
    const vtkGlobeTest::HardCaseResult r = vtkGlobeTest::CheckHardCase(scene, pass, 2);
    ok &= vtkGlobeTest::HardCasePassed(r, 8000);
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
