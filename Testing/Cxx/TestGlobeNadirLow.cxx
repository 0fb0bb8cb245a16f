// Hard case: straight down the nadir from 100 m over Mount Rainier's summit massif, where the
// PGM cross-section basis degenerates for the central rays (the ray is parallel to the nadir)
// and the grid's footprint is only ~100 m wide. In each depth mode: no GL error, no NaN in
// depth, G-buffer or PGM textures, terrain from depth within CheckTerrain's bound, and the
// centre pixel reconstructs to the point below the camera.
#include "vtkGlobeRenderingTestHelpers.h"

int TestGlobeNadirLow(int, char*[])
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
    const double lon = -121.7603, lat = 46.8523;
    const double ground = vtkGlobeTest::ComposedHeight(layers, lon, lat);
    const double camera[3] = { lon, lat, ground + 100.0 }, target[3] = { lon, lat, ground - 1000.0 };
    vtkGlobeTest::LookAt(scene.Renderer, scene.Body, camera, target, 50.0);
    scene.Renderer->ResetCameraClippingRange();
    scene.Render();
    std::printf("mode %s: 100 m over the ground at %.1f m\n", vtkGlobeDepthPass::GetModeAsString(mode),
      ground);
    const vtkGlobeTest::HardCaseResult r = vtkGlobeTest::CheckHardCase(scene, pass, 2);
    ok &= vtkGlobeTest::HardCasePassed(r, 15000);

    // The centre pixel: the ground below the camera.
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    const int* size = scene.Window->GetSize();
    const int cx = size[0] / 2, cy = size[1] / 2;
    const float d = depth[static_cast<size_t>(cy) * size[0] + cx];
    double p[3], llh[3];
    vtkGlobeTest::UnprojectPixel(scene.Renderer, cx + 0.5, cy + 0.5,
      pass->GetPerspectiveDepth(d, scene.Renderer->GetActiveCamera()), p);
    scene.Body->CartesianToGeodetic(p, llh);
    const double below = vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]);
    std::printf("  centre pixel: %.2f m below the camera, %.3f m from the data\n",
      ground + 100.0 - llh[2], llh[2] - below);
    ok &= std::abs(llh[2] - below) < 0.5 && std::abs(ground + 100.0 - llh[2] - 100.0) < 20.0;
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
