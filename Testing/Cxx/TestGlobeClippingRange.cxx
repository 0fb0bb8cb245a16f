// The clipping-range policy of scenes with a globe (vtkGlobeClippingRange), with a plain
// renderer and no explicit range:
//  - a camera 2 m above the terrain west of Mount Rainier, looking at the horizon. VTK's own
//    range (before the globe first renders) starts hundreds of metres out and clips the
//    ground under the camera. After the first render the globe's policy is installed; the
//    next ResetCameraClippingRange() gives a near plane below the nearest terrain in view:
//    the bottom rows of the picture are terrain, and every pixel whose ray meets the body's
//    lowest possible surface (the ellipsoid lowered by the lowest data, exact, double) shows
//    terrain, so nothing up to the far horizon is clipped;
//  - from 22,000 km the range is tight around the body (far / near < 1.6) and the disk is
//    whole;
//  - another actor nearer than the terrain pulls the near plane in;
//  - on a summit looking at the horizon, the near plane is where the frustum's steepest ray
//    can first reach terrain, not the height over the summit.
#include "vtkGlobeClippingRange.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"

#include <chrono>

namespace
{
/// Eye distance of the first hit of a ray with the ellipsoid raised by h (approximately the
/// parallel surface, exact for a sphere); -1 when it misses.
double HitOffsetEllipsoid(const double* radii, double h, const double eye[3], const double ray[3])
{
  double o[3], d[3];
  for (int c = 0; c < 3; ++c)
  {
    o[c] = eye[c] / (radii[c] + h);
    d[c] = ray[c] / (radii[c] + h);
  }
  const double A = vtkMath::Dot(d, d), B = vtkMath::Dot(o, d), C = vtkMath::Dot(o, o) - 1.0;
  const double disc = B * B - A * C;
  if (disc < 0.0)
  {
    return -1.0;
  }
  // The root that does not cancel.
  const double q = -(B + (B < 0 ? -1.0 : 1.0) * std::sqrt(disc));
  const double t0 = C / q, t1 = q / A;
  const double t = std::min(t0, t1) > 0 ? std::min(t0, t1) : std::max(t0, t1);
  return t > 0 ? t : -1.0;
}

/// Pixels whose ray meets the lowered ellipsoid, and how many of them show nothing; pixels
/// within two of the set's border are left out (the mesh's chords at the skyline).
void CheckCoverage(vtkGlobeTest::Scene& scene, double lowest, int& inside, int& missing,
  double& farthest)
{
  const int* size = scene.Window->GetSize();
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const double* eye = scene.Renderer->GetActiveCamera()->GetPosition();
  double view[3];
  scene.Renderer->GetActiveCamera()->GetDirectionOfProjection(view);
  std::vector<char> hit(static_cast<size_t>(size[0]) * size[1], 0);
  farthest = 0.0;
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      double ray[3];
      vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
      const double t = HitOffsetEllipsoid(scene.Body->GetRadii(), lowest, eye, ray);
      hit[static_cast<size_t>(y) * size[0] + x] = t > 0 ? 1 : 0;
      if (t > 0)
      {
        farthest = std::max(farthest, t * vtkMath::Dot(ray, view));
      }
    }
  }
  inside = missing = 0;
  for (int y = 2; y < size[1] - 2; ++y)
  {
    for (int x = 2; x < size[0] - 2; ++x)
    {
      bool all = true;
      for (int j = -2; j <= 2; ++j)
      {
        for (int i = -2; i <= 2; ++i)
        {
          all = all && hit[static_cast<size_t>(y + j) * size[0] + x + i];
        }
      }
      if (all)
      {
        ++inside;
        missing += depth[static_cast<size_t>(y) * size[0] + x] < 1.0f ? 0 : 1;
      }
    }
  }
}

/// The nearest exact terrain hit, as z along the view, of every 4th ray of the bottom `rows`
/// rows (where the nearest terrain in view is); 1e300 when none within tMax.
double NearestBottomHit(vtkGlobeTest::Scene& scene, const std::vector<vtkGlobeLayer*>& layers,
  int rows, double tMax)
{
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  double view[3];
  camera->GetDirectionOfProjection(view);
  double nearest = 1e300;
  for (int y = 0; y < rows; ++y)
  {
    for (int x = 0; x < scene.Window->GetSize()[0]; x += 4)
    {
      double ray[3];
      vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
      const double t =
        vtkGlobeTest::RayTerrainHit(scene.Body, layers, camera->GetPosition(), ray, tMax);
      if (t > 0.0)
      {
        nearest = std::min(nearest, t * vtkMath::Dot(ray, view));
      }
    }
  }
  return nearest;
}

/// Covered pixels in the bottom `rows` rows.
int BottomCovered(vtkGlobeTest::Scene& scene, int rows)
{
  const int* size = scene.Window->GetSize();
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  int n = 0;
  for (int y = 0; y < rows; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      n += depth[static_cast<size_t>(y) * size[0] + x] < 1.0f ? 1 : 0;
    }
  }
  return n;
}
} // namespace

int TestGlobeClippingRange(int, char*[])
{
  bool ok = true;
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
  for (vtkGlobeLayer* layer : layers)
  {
    layer->Update();
  }
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const double lowest = scene.Mapper->GetLayerSet()->GetMinimumHeight();

  // 2 m above the ground of the Rainier inset, west of the summit, looking east at the horizon (the summit in view).
  const double lon = -121.95, lat = 46.85;
  const double ground = vtkGlobeTest::ComposedHeight(layers, lon, lat);
  const double cam[3] = { lon, lat, ground + 2.0 }, target[3] = { -121.0, 46.85, ground + 2.0 };
  scene.Look(cam, target, 50.0); // VTK's own ResetCameraClippingRange: no policy yet
  double vtkRange[2];
  camera->GetClippingRange(vtkRange);
  scene.Render();
  const int vtkBottom = BottomCovered(scene, 4);
  const int width = scene.Window->GetSize()[0];
  std::printf("  2 m up, VTK's range [%.1f, %.0f] m: %d of %d pixels of the bottom 4 rows "
              "covered\n",
    vtkRange[0], vtkRange[1], vtkBottom, 4 * width);
  // The problem is real: VTK's near plane is beyond the ground at the bottom of the view.
  ok &= vtkBottom < width;

  vtkGlobeClippingRange* policy = vtkGlobeClippingRange::GetInstalled(scene.Renderer);
  std::printf("  policy installed by the first render: %s\n", policy ? "yes" : "NO");
  ok &= policy != nullptr;
  if (!policy)
  {
    return 1;
  }
  scene.Renderer->ResetCameraClippingRange();
  double range[2];
  camera->GetClippingRange(range);
  scene.Render();
  const int bottom = BottomCovered(scene, 4);
  int inside, missing;
  double farthest;
  CheckCoverage(scene, lowest, inside, missing, farthest);
  // The ground falls away east of the camera faster than the bottom edge's rays (25 degrees
  // down): the nearest terrain in view is tens of metres ahead. The near plane stays in front
  // of it (the frustum's bound, not the 0.62 m of the height over the ground), and the terrain
  // read back from depth lies where the exact ray cast puts it at every second pixel.
  const double nearestHit = NearestBottomHit(scene, layers, 4, 2000.0);
  const vtkGlobeTest::TerrainCheck terrain = vtkGlobeTest::CheckTerrain(scene, 2);
  std::printf("  policy range [%.3f, %.0f] m (%d applications): bottom 4 rows %d of %d covered "
              "(nearest terrain there %.2f m along the view); %d pixels see the lowest surface "
              "(farthest %.0f m along the view), %d of them empty; terrain from depth: %d of %d "
              "pixels beyond the bound\n",
    range[0], range[1], policy->GetNumberOfApplications(), bottom, 4 * width, nearestHit,
    inside, farthest, missing, terrain.Failures, terrain.Pixels);
  ok &= range[0] > 10.0 && range[0] <= nearestHit;
  const double lowNear = range[0];
  ok &= bottom == 4 * width;
  ok &= inside > 10000 && missing == 0 && range[1] >= farthest;
  ok &= terrain.Pixels > 10000 && terrain.Failures == 0 && terrain.NaNs == 0;

  // Another actor 0.5 m in front of the low camera pulls the near plane in.
  double eye[3], direction[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  vtkNew<vtkSphereSource> pebble;
  pebble->SetRadius(0.05);
  vtkNew<vtkPolyDataMapper> pebbleMapper;
  pebbleMapper->SetInputConnection(pebble->GetOutputPort());
  vtkNew<vtkActor> pebbleActor;
  pebbleActor->SetMapper(pebbleMapper);
  // Points are floats (0.5 m apart at the Earth's radius): place the pebble with the actor.
  pebbleActor->SetPosition(eye[0] + 0.5 * direction[0], eye[1] + 0.5 * direction[1], eye[2] + 0.5 * direction[2]);
  scene.Renderer->AddActor(pebbleActor);
  scene.Look(cam, target, 50.0);
  camera->GetClippingRange(range);
  std::printf("  with a pebble 0.45 m in front: near %.3f m\n", range[0]);
  ok &= range[0] < 0.45 && range[0] > 0.3;


  // The same from ResetCamera(): it fires ResetCameraEvent, the policy answers it too.
  const int applied = policy->GetNumberOfApplications();
  scene.Renderer->ResetCamera();
  ok &= policy->GetNumberOfApplications() == applied + 1;

  // From 22,000 km above the Pacific, looking at the centre: a tight range, the whole disk.
  vtkGlobeTest::Scene high;
  high.AddEarthLayers();
  const double far[3] = { -150.0, 20.0, 2.2e7 }, centre[3] = { -150.0, 20.0, -6.0e6 };
  vtkGlobeTest::LookAt(high.Renderer, high.Body, far, centre, 40.0);
  high.Renderer->ResetCameraClippingRange();
  double vtkHigh[2];
  high.Renderer->GetActiveCamera()->GetClippingRange(vtkHigh);
  vtkGlobeClippingRange::Install(high.Renderer); // the one call, before any render
  high.Renderer->ResetCameraClippingRange();
  double highRange[2];
  high.Renderer->GetActiveCamera()->GetClippingRange(highRange);
  high.Render();
  int highInside, highMissing;
  double highFarthest;
  CheckCoverage(high, lowest, highInside, highMissing, highFarthest);
  const double top = high.Mapper->GetLayerSet()->GetMaximumHeight();
  std::printf("  22,000 km up: VTK's range [%.0f, %.0f] (far/near %.0f), policy [%.0f, %.0f] "
              "(far/near %.2f); disk %d pixels, %d empty, farthest %.0f m\n",
    vtkHigh[0], vtkHigh[1], vtkHigh[1] / vtkHigh[0], highRange[0], highRange[1],
    highRange[1] / highRange[0], highInside, highMissing, highFarthest);
  ok &= highRange[0] <= 2.2e7 - top && highRange[0] > 0.8 * (2.2e7 - top);
  ok &= highRange[1] / highRange[0] < 1.6 && highRange[1] >= highFarthest;
  ok &= highInside > 5000 && highMissing == 0;

  // Blend modes: a +300 m Add layer over the Rainier window (0.4 degrees square, 111 m texels):
  // the ground is the inset plus 300 m. The old replace-only rule took the layer's 300 m for the
  // ground and put the near plane ~1,700 m beyond it.
  {
    vtkGlobeTest::Scene added;
    added.AddEarthLayers(true, false);
    std::vector<float> raise(400 * 400, 300.0f);
    vtkNew<vtkGlobeLayer> addLayer;
    addLayer->SetHeightData(400, 400, raise.data(), lon - 0.2, lon + 0.2, lat - 0.2, lat + 0.2);
    addLayer->SetBlendModeToAdd();
    added.Mapper->AddLayer(addLayer);
    const std::vector<vtkGlobeLayer*> addedLayers = vtkGlobeTest::HeightLayers(added.Mapper);
    for (vtkGlobeLayer* layer : addedLayers)
    {
      layer->Update();
    }
    const double raised = vtkGlobeTest::ComposedHeight(addedLayers, lon, lat);
    const double cam2[3] = { lon, lat, raised + 2.0 }, target2[3] = { -121.0, 46.85, raised + 2.0 };
    vtkGlobeClippingRange::Install(added.Renderer);
    added.Look(cam2, target2, 50.0);
    double addedRange[2];
    added.Renderer->GetActiveCamera()->GetClippingRange(addedRange);
    added.Render();
    const int addedBottom = BottomCovered(added, 4);
    std::printf("  2 m over an Add layer (ground %.1f + 300 = %.1f m): near %.3f m, bottom 4 rows "
                "%d of %d covered\n",
      ground, raised, addedRange[0], addedBottom, 4 * width);
    // The Add layer raises all of the window alike: the same near plane as without it.
    ok &= std::abs(raised - ground - 300.0) < 1e-3;
    ok &= std::abs(addedRange[0] - lowNear) < 0.01 * lowNear && addedBottom == 4 * width;
  }

  // 1.5 m above the Everest summit, looking ESE 4 degrees down at the horizon: the ground under
  // the camera is out of view, and the summit falls away faster than the bottom edge's rays
  // (19 degrees down), which meet terrain kilometres away. The bound from the eye's height
  // alone gave a near plane of 1.2 m; the terrain inside the frustum gives kilometres, and
  // Default depth resolves the 330 km to the horizon thousands of times more finely.
  {
    vtkGlobeTest::Scene summit;
    summit.AddEarthLayers(true, false);
    const std::vector<vtkGlobeLayer*> summitLayers = vtkGlobeTest::HeightLayers(summit.Mapper);
    for (vtkGlobeLayer* layer : summitLayers)
    {
      layer->Update();
    }
    double sLon = 86.925, sLat = 27.9881;
    const double top = vtkGlobeTest::ComposedSummit(summitLayers, sLon, sLat);
    double sEye[3], east[3], north[3], up[3], view[3];
    summit.Body->GeodeticToCartesian(sLon, sLat, top + 1.5, sEye);
    summit.Body->ComputeEastNorthUp(sLon, sLat, east, north, up);
    const double azimuth = vtkMath::RadiansFromDegrees(112.5);
    const double tilt = vtkMath::RadiansFromDegrees(-4.0), angle = 30.0;
    for (int i = 0; i < 3; ++i)
    {
      view[i] = std::cos(tilt) * (std::sin(azimuth) * east[i] + std::cos(azimuth) * north[i]) +
        std::sin(tilt) * up[i];
    }
    vtkGlobeTest::LookAlong(summit.Renderer, sEye, view, up, angle);
    vtkGlobeClippingRange::Install(summit.Renderer);
    summit.Renderer->ResetCameraClippingRange();
    double summitRange[2];
    summit.Renderer->GetActiveCamera()->GetClippingRange(summitRange);
    // What the search costs per reset (printed, not asserted: timing is the benchmarks' job).
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < 50; ++k)
    {
      summit.Renderer->ResetCameraClippingRange();
    }
    const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - start;
    std::printf("  a reset of the range from the summit takes %.2f ms\n", spent.count() / 50);
    summit.Render();
    const double summitHit = NearestBottomHit(summit, summitLayers, 4, 6e4);
    const vtkGlobeTest::TerrainCheck summitTerrain = vtkGlobeTest::CheckTerrain(summit, 2);
    int summitInside, summitMissing;
    double summitFarthest;
    CheckCoverage(summit, summit.Mapper->GetLayerSet()->GetMinimumHeight(), summitInside,
      summitMissing, summitFarthest);
    std::printf("  1.5 m over the Everest summit (%.1f m), 4 deg down: near %.1f m, nearest "
                "terrain of the bottom rows %.1f m along the view; %d pixels see the lowest "
                "surface, %d empty; terrain from depth: %d of %d pixels beyond the bound\n",
      top, summitRange[0], summitHit, summitInside, summitMissing, summitTerrain.Failures,
      summitTerrain.Pixels);
    ok &= summitRange[0] > 1000.0 && summitRange[0] <= summitHit;
    ok &= summitInside > 10000 && summitMissing == 0 && summitRange[1] >= summitFarthest;
    ok &= summitTerrain.Pixels > 5000 && summitTerrain.Failures == 0 && summitTerrain.NaNs == 0;
  }

  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
