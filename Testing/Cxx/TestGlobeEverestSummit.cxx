// Hard case: a camera 1.5 m above the Everest summit (SRTM inset over the 2-degree relief),
// looking 20 degrees down, the horizon ~330 km away in view (3 degrees down), and a 1 m cube
// standing on the ground 4 m ahead. In each depth mode (Default with the clipping policy,
// Logarithmic): no GL error, no NaN in the depth buffer, G-buffer or PGM textures; terrain from
// depth within CheckTerrain's bound from 2 m to the horizon; and no wrong-surface pixel of the
// cube against the exact (double) ray/cube and ray/terrain intersections.
#include "vtkCubeSource.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMatrix4x4.h"

int TestGlobeEverestSummit(int, char*[])
{
  bool ok = true;
  for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
  {
    vtkGlobeTest::Scene scene;
    scene.AddEarthLayers(true, false);
    auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
    vtkGlobeEllipsoid* body = scene.Body;
    const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
    for (vtkGlobeLayer* layer : layers)
    {
      layer->Update();
    }
    // The summit of the composed data (bilinear 90 m posts): the highest point near Everest's.
    double lon = 86.925, lat = 27.9881;
    const double ground = vtkGlobeTest::ComposedSummit(layers, lon, lat);
    double eye[3], east[3], north[3], up[3];
    body->GeodeticToCartesian(lon, lat, ground + 1.5, eye);
    body->ComputeEastNorthUp(lon, lat, east, north, up);
    // The azimuth where the ground 4 m away drops least (the summit falls ~50 degrees on most
    // sides at 90 m posts), so a cube on it is in view.
    // (azimuths in 10 degree steps)
    double azimuth = 0.0, best = -1e300;
    for (int k = 0; k < 36; ++k)
    {
      double p[3], llh[3];
      const double az = vtkMath::RadiansFromDegrees(10.0 * k);
      for (int i = 0; i < 3; ++i)
      {
        p[i] = eye[i] + 4.0 * (std::sin(az) * east[i] + std::cos(az) * north[i]);
      }
      body->CartesianToGeodetic(p, llh);
      const double g = vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]);
      if (g > best)
      {
        best = g;
        azimuth = az;
      }
    }
    const double tilt = vtkMath::RadiansFromDegrees(-20.0);
    double view[3];
    for (int i = 0; i < 3; ++i)
    {
      view[i] = std::cos(tilt) * (std::sin(azimuth) * east[i] + std::cos(azimuth) * north[i]) +
        std::sin(tilt) * up[i];
    }
    vtkGlobeTest::LookAlong(scene.Renderer, eye, view, up, 60.0);

    // The cube: 1 m, axes east/north/up, standing on the ground 4 m away along that azimuth.
    double centre[3], axes[3][3];
    {
      double p[3], llh[3];
      for (int i = 0; i < 3; ++i)
      {
        p[i] = eye[i] + 4.0 * (std::sin(azimuth) * east[i] + std::cos(azimuth) * north[i]);
      }
      body->CartesianToGeodetic(p, llh);
      llh[2] = vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]) + 0.5;
      body->GeodeticToCartesian(llh, centre);
      body->ComputeEastNorthUp(llh[0], llh[1], axes[0], axes[1], axes[2]);
      std::printf("mode %s: summit of the data %.1f m at %.5f, %.5f; looking at azimuth %.0f "
                  "degrees; cube 4 m away, its base %.2f m below the summit\n",
        vtkGlobeDepthPass::GetModeAsString(mode), ground, lon, lat,
        vtkMath::DegreesFromRadians(azimuth), ground - best);
    }
    vtkNew<vtkCubeSource> cubeSource;
    auto cube = vtkGlobeTest::FlatActor(cubeSource, 0, 1, 0);
    vtkNew<vtkMatrix4x4> place; // the placement stays in the (double) matrix
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        place->SetElement(r, c, axes[c][r]);
      }
      place->SetElement(r, 3, centre[r]);
    }
    cube->SetUserMatrix(place);
    scene.Renderer->AddActor(cube);
    scene.Renderer->ResetCameraClippingRange();
    scene.Render();

    // The margin: what the drawn terrain may differ from the data near the cube, the same in
    // both modes (not depth): the GPU samples heights at (lon, lat) from the frame's local
    // origin (HighPrecisionGeodetic: within 0.1 mm + 3e-7 of the distance, TestGlobeGeodetic-
    // Precision; with float (lon, lat) it was 2 ulps of 1.5 rad, 1.14 m, 0.43 m here) with
    // 8-bit bilinear weights (1/256 of a 90 m post), both times the local slope; plus a few cm
    // of mesh chord; farther, 0.2 % of the distance covers the chords.
    double slope = 0.0, texel = 0.0;
    {
      double llh[3];
      body->CartesianToGeodetic(centre, llh);
      const double dDeg = 10.0 / 111000.0;
      const double gx = (vtkGlobeTest::ComposedHeight(layers, llh[0] + dDeg, llh[1]) -
        vtkGlobeTest::ComposedHeight(layers, llh[0] - dDeg, llh[1])) / (20.0 * std::cos(vtkMath::RadiansFromDegrees(llh[1])));
      const double gy = (vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1] + dDeg) -
        vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1] - dDeg)) / 20.0;
      slope = std::sqrt(gx * gx + gy * gy);
      texel = vtkGlobeTest::FinestTexel(layers, llh[0], llh[1], body->GetMinimumRadius());
    }
    const double sampling = slope * (1e-3 + texel / 256.0);
    std::printf("  slope at the cube %.2f, posts %.0f m: sampling margin %.2f m (geodetic %.4f m)\n",
      slope, texel, sampling, slope * 1e-3);
    const vtkGlobeTest::SurfaceCount count = vtkGlobeTest::CountWrongSurface(
      scene,
      [&](const double* e, const double* r) { return vtkGlobeTest::RayBoxHit(centre, axes, 0.5, e, r); },
      [](const unsigned char* c) { return c[1] > 200 && c[0] < 60 && c[2] < 60; },
      [&](double s) { return 0.06 + sampling + 0.002 * s; }, 0.01, 0.002);
    std::printf("  cube: %d wrong of %d checked (%d behind terrain, %d near a crossing left out)\n",
      count.Wrong, count.Checked, count.Hidden, count.Grazing);
    ok &= count.Checked > 1000 && count.Wrong == 0;

    cube->VisibilityOff();
    scene.Renderer->ResetCameraClippingRange();
    scene.Render();
    const vtkGlobeTest::HardCaseResult r = vtkGlobeTest::CheckHardCase(scene, pass, 2);
    ok &= vtkGlobeTest::HardCasePassed(r, 8000) && r.Farthest > 2.0e5;
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
