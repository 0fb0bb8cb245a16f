// Hard case: a satellite over the limb. The camera is 400 km up over India, looking north-north-
// east exactly along the skyline (the limb, ~2,300 km away, over the Himalaya and Tibet), and a
// 10 m cube (the "satellite") floats 40 m ahead on that line: its lower half is seen against
// terrain thousands of km behind it, its upper half against the sky. The clipping policy's range
// is then ~[30 m, 4,600 km] (far/near 1.5e5), and the PGM mesh at the limb has km-long
// triangles (grid 64, the coarse end of the dial, and 256). In each depth mode and grid:
//  - wrong-surface pixels (CountWrongSurface, exact double ray/box and ray/terrain): every
//    pixel whose 3x3 neighbourhood's exact rays meet the cube must show it, none hidden; and
//    every pixel whose 3x3 neighbourhood's rays miss it must not show it. Both counts 0;
//  - the cube's depth-reconstructed distance (in the pass's mode) within the mode's depth bound
//    of the exact ray/box hit;
//  - with the cube hidden and the same clipping range, CheckHardCase: no GL error, no NaN in
//    the depth buffer, G-buffer or PGM textures, terrain from depth within CheckTerrain's bound
//    out to the limb (> 2,000 km).
#include "vtkCubeSource.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMatrix4x4.h"

int TestGlobeSatelliteLimb(int, char*[])
{
  bool ok = true;
  for (int grid : { 64, 256 })
  {
    for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
    {
      vtkGlobeTest::Scene scene(300, 225, grid);
      // The global 2-degree relief only: with the 90 m Everest inset in view, a 64^2 grid puts
      // 38 km triangles over it whose relief CheckTerrain's mesh term (second differences at the
      // triangle's size) misses by up to 3.7x its bound (4 pixels, 1,000 km away; the depth is
      // not at fault: Default, with its coarser depth bound, passes there).
      scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
      auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
      vtkGlobeEllipsoid* body = scene.Body;
      const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
      for (vtkGlobeLayer* layer : layers)
      {
        layer->Update();
      }
      const double lon = 80.0, lat = 20.0, altitude = 4.0e5;
      double eye[3], east[3], north[3], up[3];
      body->GeodeticToCartesian(lon, lat, altitude, eye);
      body->ComputeEastNorthUp(lon, lat, east, north, up);
      const double azimuth = vtkMath::RadiansFromDegrees(20.0);
      auto direction = [&](double elevation, double v[3]) {
        for (int i = 0; i < 3; ++i)
        {
          v[i] = std::cos(elevation) * (std::sin(azimuth) * east[i] + std::cos(azimuth) * north[i]) +
            std::sin(elevation) * up[i];
        }
      };
      // The skyline: the highest elevation whose ray meets the composed terrain (bisection).
      double below = vtkMath::RadiansFromDegrees(-30.0), above = vtkMath::RadiansFromDegrees(-10.0);
      for (int it = 0; it < 30; ++it)
      {
        const double mid = 0.5 * (below + above);
        double v[3];
        direction(mid, v);
        (vtkGlobeTest::RayTerrainHit(body, layers, eye, v, 4.0e6, 200.0, 0.002) > 0 ? below : above) = mid;
      }
      double view[3];
      direction(below, view);
      const double limb = vtkGlobeTest::RayTerrainHit(body, layers, eye, view, 4.0e6, 200.0, 0.002);
      vtkGlobeTest::LookAlong(scene.Renderer, eye, view, up, 30.0);

      // The satellite: a 10 m cube 40 m ahead on the skyline, turned off the view's axes.
      double centre[3], axes[3][3];
      for (int i = 0; i < 3; ++i)
      {
        centre[i] = eye[i] + 40.0 * view[i];
      }
      {
        const double a = 0.4, b = 0.3;
        double e2[3], n2[3];
        for (int i = 0; i < 3; ++i)
        {
          e2[i] = std::cos(a) * east[i] + std::sin(a) * north[i];
          n2[i] = -std::sin(a) * east[i] + std::cos(a) * north[i];
        }
        for (int i = 0; i < 3; ++i)
        {
          axes[0][i] = e2[i];
          axes[1][i] = std::cos(b) * n2[i] + std::sin(b) * up[i];
          axes[2][i] = -std::sin(b) * n2[i] + std::cos(b) * up[i];
        }
      }
      double llh[3];
      body->CartesianToGeodetic(centre, llh);
      std::printf("grid %d, %s: skyline %.2f degrees below the horizontal, limb %.0f km away; "
                  "satellite at %.1f km altitude\n",
        grid, vtkGlobeDepthPass::GetModeAsString(mode), -vtkMath::DegreesFromRadians(below),
        limb / 1000.0, llh[2] / 1000.0);
      vtkNew<vtkCubeSource> cubeSource;
      cubeSource->SetXLength(10.0);
      cubeSource->SetYLength(10.0);
      cubeSource->SetZLength(10.0);
      auto cube = vtkGlobeTest::FlatActor(cubeSource, 1, 0, 0);
      vtkNew<vtkMatrix4x4> place;
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
      vtkCamera* camera = scene.Renderer->GetActiveCamera();
      double range[2];
      camera->GetClippingRange(range);

      auto hit = [&](const double* e, const double* r) {
        return vtkGlobeTest::RayBoxHit(centre, axes, 5.0, e, r);
      };
      auto isObject = [](const unsigned char* c) { return c[0] > 200 && c[1] < 60 && c[2] < 60; };
      // The terrain is >= 2,000 km behind the cube: any margin decides nothing here; the mesh's
      // km-size chords are covered by 1 % of the distance.
      const vtkGlobeTest::SurfaceCount count = vtkGlobeTest::CountWrongSurface(
        scene, hit, isObject, [](double s) { return 1.0 + 0.01 * s; }, 1.0, 0.002);

      // The other way round, and the cube's depth: pixels clear of the silhouette.
      const int* size = scene.Window->GetSize();
      const std::vector<unsigned char> rgb = vtkGlobeTest::ReadPixels(scene.Window);
      const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
      std::vector<double> distance(static_cast<size_t>(size[0]) * size[1]);
      for (int y = 0; y < size[1]; ++y)
      {
        for (int x = 0; x < size[0]; ++x)
        {
          double ray[3];
          vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
          distance[static_cast<size_t>(y) * size[0] + x] = hit(eye, ray);
        }
      }
      int outside = 0, falseObject = 0, terrainBehind = 0, depthChecked = 0, depthBeyond = 0;
      double worstDepthRatio = 0.0, worstDepthError = 0.0;
      const bool logDepth = mode == vtkGlobeDepthPass::Logarithmic;
      for (int y = 1; y + 1 < size[1]; ++y)
      {
        for (int x = 1; x + 1 < size[0]; ++x)
        {
          const size_t at = static_cast<size_t>(y) * size[0] + x;
          int inside = 0;
          for (int j = -1; j <= 1; ++j)
          {
            for (int i = -1; i <= 1; ++i)
            {
              inside += distance[at + j * size[0] + i] > 0 ? 1 : 0;
            }
          }
          const unsigned char* c = &rgb[3 * at];
          if (inside == 0)
          {
            ++outside;
            falseObject += isObject(c) ? 1 : 0;
            terrainBehind += (depth[at] < 1.0f && !isObject(c)) ? 1 : 0;
          }
          else if (inside == 9 && isObject(c))
          {
            double p[3];
            vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5,
              pass->GetPerspectiveDepth(depth[at], camera), p);
            double ray[3];
            vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
            const double t = distance[at];
            const double drawn = std::sqrt(vtkMath::Distance2BetweenPoints(p, eye));
            // Along the ray: the mode's depth steps at the view-axis distance z, over the cosine.
            double dop[3];
            camera->GetDirectionOfProjection(dop);
            const double cosine = vtkMath::Dot(ray, dop);
            const double z = t * cosine;
            const double bound =
              (logDepth ? vtkGlobeTest::LogDepthBound(pass, z) : vtkGlobeTest::DepthBound(camera, z)) /
                cosine + 1e-6 * t;
            const double error = std::abs(drawn - t);
            ++depthChecked;
            depthBeyond += error > bound ? 1 : 0;
            worstDepthRatio = std::max(worstDepthRatio, error / bound);
            worstDepthError = std::max(worstDepthError, error);
          }
        }
      }
      std::printf("  clip [%.4g, %.4g] m; satellite: %d wrong of %d checked (%d hidden, %d near a "
                  "crossing left out); drawn outside its silhouette: %d of %d pixels (%d of them "
                  "terrain); depth: worst %.2g m, worst/bound %.3f over %d pixels, %d beyond\n",
        range[0], range[1], count.Wrong, count.Checked, count.Hidden, count.Grazing, falseObject,
        outside, terrainBehind, worstDepthError, worstDepthRatio, depthChecked, depthBeyond);
      ok &= count.Checked > 5000 && count.Wrong == 0 && count.Hidden == 0 && falseObject == 0 &&
        terrainBehind > 5000 && depthChecked > 5000 && depthBeyond == 0;

      // The terrain alone under the satellite's clipping range.
      cube->VisibilityOff();
      camera->SetClippingRange(range);
      scene.Render();
      const vtkGlobeTest::HardCaseResult r = vtkGlobeTest::CheckHardCase(scene, pass, 2);
      ok &= vtkGlobeTest::HardCasePassed(r, 8000) && r.Farthest > 2.0e6;
    }
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
