// Depth for the whole scene in each depth mode of vtkGlobeDepthPass, with the clipping policy
// (no explicit range): a camera 2 m above the Rainier inset looking east, a 100 m cube half
// buried in the ground 1.5 km ahead, and a "satellite" sphere (100 km radius, 400 km up) rising
// over the limb, its lower part behind the Earth. Per mode:
//  - wrong-surface pixels: for every pixel whose exact ray (double) meets the cube or the
//    satellite, the exact nearest surface (the object, or terrain crossing the ray before it:
//    the composed data marched along the ray) against the colour drawn (objects are flat pure
//    green / red). Pixels on an exact silhouette, or where the ray passes the terrain within a
//    margin, are left out. Must be 0;
//  - depth-reconstructed terrain (vtkGlobeTest::CheckTerrain, reading depth in the mode)
//    within its bound: the mode's depth quantization plus what the PGM mesh can represent;
//  - picking: vtkGlobePointPicker at terrain pixels in the lower half of the view against the
//    exact ray/terrain intersection (double); and vtkWorldPointPicker's error in the same mode.
#include "vtkCubeSource.h"
#include "vtkGlobeClippingRange.h"
#include "vtkGlobeDepthPass.h"
#include "vtkGlobePointPicker.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWorldPointPicker.h"

namespace
{
struct Object
{
  double Centre[3];
  double Axes[3][3]; // unit axes (cube) in the world
  double Half = 0;   // half side (cube) or radius (sphere)
  bool Sphere = false;
};

/// Eye distance of a ray's first hit with an object, or -1.
double Hit(const Object& o, const double eye[3], const double ray[3])
{
  double rel[3] = { eye[0] - o.Centre[0], eye[1] - o.Centre[1], eye[2] - o.Centre[2] };
  if (o.Sphere)
  {
    const double b = vtkMath::Dot(rel, ray), c = vtkMath::Dot(rel, rel) - o.Half * o.Half;
    const double disc = b * b - c;
    if (disc < 0)
    {
      return -1;
    }
    const double t = -b - std::sqrt(disc);
    return t > 0 ? t : -1;
  }
  double t0 = 0, t1 = 1e300;
  for (int a = 0; a < 3; ++a)
  {
    const double p = vtkMath::Dot(rel, o.Axes[a]), d = vtkMath::Dot(ray, o.Axes[a]);
    if (std::abs(d) < 1e-15)
    {
      if (std::abs(p) > o.Half)
      {
        return -1;
      }
      continue;
    }
    double ta = (-o.Half - p) / d, tb = (o.Half - p) / d;
    if (ta > tb)
    {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1 && t0 > 0 ? t0 : -1;
}

/// The ray's height over the composed terrain up to distance `t` (m), marched in steps of
/// 0.2 % of the distance (at least 1 m), relative to a margin for what the PGM mesh can
/// represent (1 m + 2 % of the distance: at a 256^2 grid the mesh's vertices carry
/// mipmap-filtered heights, and Rainier's summit 15 km away is drawn up to 250 m low): the
/// smallest ratio. Above 1: the ray passes clear
/// of the terrain; below -1: it goes under the terrain first; else too close to call.
double Clearance(vtkGlobeEllipsoid* body, const std::vector<vtkGlobeLayer*>& layers,
  const double eye[3], const double ray[3], double t)
{
  double lowest = 1e300;
  for (double s = 1.0;; s = std::min(t, s + std::max(1.0, 0.002 * s)))
  {
    const double p[3] = { eye[0] + s * ray[0], eye[1] + s * ray[1], eye[2] + s * ray[2] };
    double llh[3];
    body->CartesianToGeodeticQuiet(p, llh);
    const double over = llh[2] - vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]);
    lowest = std::min(lowest, over / (1.0 + 0.02 * s));
    if (s >= t)
    {
      return lowest;
    }
  }
}

/// The exact ray/terrain intersection (double): march, then bisect. -1 when none within tMax.
double TerrainHit(vtkGlobeEllipsoid* body, const std::vector<vtkGlobeLayer*>& layers,
  const double eye[3], const double ray[3], double tMax)
{
  auto above = [&](double s) {
    const double p[3] = { eye[0] + s * ray[0], eye[1] + s * ray[1], eye[2] + s * ray[2] };
    double llh[3];
    body->CartesianToGeodeticQuiet(p, llh);
    return llh[2] - vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]);
  };
  double previous = 0.0;
  for (double s = 0.5; s < tMax; s += std::max(0.5, 0.001 * s))
  {
    if (above(s) < 0.0)
    {
      double lo = previous, hi = s;
      for (int i = 0; i < 60; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (above(mid) < 0.0 ? hi : lo) = mid;
      }
      return 0.5 * (lo + hi);
    }
    previous = s;
  }
  return -1.0;
}

vtkSmartPointer<vtkActor> FlatActor(vtkPolyDataAlgorithm* source, const double colour[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}
} // namespace

int TestGlobeDepthModes(int, char*[])
{
  bool ok = true;
  for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
  {
    std::printf("mode %s\n", vtkGlobeDepthPass::GetModeAsString(mode));
    vtkGlobeTest::Scene scene;
    scene.AddEarthLayers();
    vtkGlobeEllipsoid* body = scene.Body;
    const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
    for (vtkGlobeLayer* layer : layers)
    {
      layer->Update();
    }
    vtkNew<vtkGlobeDepthPass> depthPass;
    depthPass->SetMode(mode);
    scene.Renderer->SetPass(depthPass);
    vtkGlobeClippingRange::Install(scene.Renderer);

    const double lon = -121.95, lat = 46.85;
    const double ground = vtkGlobeTest::ComposedHeight(layers, lon, lat);
    // Looking east at the summit.
    const double cam[3] = { lon, lat, ground + 2.0 }, target[3] = { -121.0, 46.85, ground + 2.0 };
    vtkGlobeTest::LookAt(scene.Renderer, body, cam, target, 50.0);
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    double eye[3], view[3];
    camera->GetPosition(eye);
    camera->GetDirectionOfProjection(view);

    // Rays along the view's vertical plane, at an elevation (degrees) from the view axis.
    double viewUp[3];
    camera->GetViewUp(viewUp);
    auto elevated = [&](double degrees, double ray[3]) {
      const double a = vtkMath::RadiansFromDegrees(degrees);
      for (int i = 0; i < 3; ++i)
      {
        ray[i] = std::cos(a) * view[i] + std::sin(a) * viewUp[i];
      }
    };

    // The cube: 100 m, axes east/north/up, centred on the ground where the ray 12 degrees
    // below the view axis meets it (half buried).
    Object cube;
    cube.Half = 50.0;
    {
      double ray[3];
      elevated(-12.0, ray);
      const double t = TerrainHit(body, layers, eye, ray, 5.0e4);
      double p[3] = { eye[0] + t * ray[0], eye[1] + t * ray[1], eye[2] + t * ray[2] };
      double llh[3];
      body->CartesianToGeodetic(p, llh);
      llh[2] = vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]);
      body->GeodeticToCartesian(llh, cube.Centre);
      body->ComputeEastNorthUp(llh[0], llh[1], cube.Axes[0], cube.Axes[1], cube.Axes[2]);
      std::printf("  cube on the ground %.0f m ahead\n", t);
    }
    vtkNew<vtkCubeSource> cubeSource;
    cubeSource->SetXLength(100.0);
    cubeSource->SetYLength(100.0);
    cubeSource->SetZLength(100.0);
    const double green[3] = { 0, 1, 0 }, red[3] = { 1, 0, 0 };
    auto cubeActor = FlatActor(cubeSource, green);
    vtkNew<vtkMatrix4x4> place; // points are floats: the placement is in the (double) matrix
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        place->SetElement(r, c, cube.Axes[c][r]);
      }
      place->SetElement(r, 3, cube.Centre[r]);
    }
    cubeActor->SetUserMatrix(place);
    scene.Renderer->AddActor(cubeActor);

    // The satellite: on the view's vertical plane 1 degree above the skyline (the first ray
    // from above that meets terrain within 300 km), where that ray is 400 km up: with its
    // 2.4-degree radius, its lower part is behind the terrain.
    Object satellite;
    satellite.Sphere = true;
    satellite.Half = 1.0e5;
    {
      double skyline = 10.0, ray[3];
      for (; skyline > -20.0; skyline -= 0.1)
      {
        elevated(skyline, ray);
        if (TerrainHit(body, layers, eye, ray, 3.0e5) > 0)
        {
          break;
        }
      }
      elevated(skyline + 1.0, ray);
      double lo = 1e4, hi = 1e7; // the ray rises through 400 km between these
      for (int i = 0; i < 80; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        const double p[3] = { eye[0] + mid * ray[0], eye[1] + mid * ray[1], eye[2] + mid * ray[2] };
        double llh[3];
        body->CartesianToGeodetic(p, llh);
        (llh[2] < 4.0e5 ? lo : hi) = mid;
      }
      for (int i = 0; i < 3; ++i)
      {
        satellite.Centre[i] = eye[i] + lo * ray[i];
      }
      std::printf("  skyline %.1f degrees from the view axis; satellite %.0f km away\n", skyline,
        lo / 1000.0);
    }
    vtkNew<vtkSphereSource> sphereSource;
    sphereSource->SetRadius(satellite.Half);
    sphereSource->SetThetaResolution(128);
    sphereSource->SetPhiResolution(128);
    auto satelliteActor = FlatActor(sphereSource, red);
    satelliteActor->SetPosition(satellite.Centre);
    scene.Renderer->AddActor(satelliteActor);

    scene.Renderer->ResetCameraClippingRange();
    double range[2];
    camera->GetClippingRange(range);
    scene.Render();
    std::printf("  clipping range [%.3f, %.0f] m; log far %.0f m\n", range[0], range[1],
      depthPass->GetLastFar());

    // Wrong-surface pixels.
    const int* size = scene.Window->GetSize();
    vtkNew<vtkUnsignedCharArray> rgb;
    scene.Window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, rgb);
    const Object* objects[2] = { &cube, &satellite };
    std::vector<int> hitObject(static_cast<size_t>(size[0]) * size[1], -1);
    std::vector<double> hitDistance(hitObject.size(), -1.0);
    for (int y = 0; y < size[1]; ++y)
    {
      for (int x = 0; x < size[0]; ++x)
      {
        double ray[3];
        vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
        const size_t at = static_cast<size_t>(y) * size[0] + x;
        for (int k = 0; k < 2; ++k)
        {
          const double t = Hit(*objects[k], eye, ray);
          if (t > 0 && (hitDistance[at] < 0 || t < hitDistance[at]))
          {
            hitDistance[at] = t;
            hitObject[at] = k;
          }
        }
      }
    }
    int checked[2] = { 0, 0 }, wrong[2] = { 0, 0 }, grazing = 0, hidden[2] = { 0, 0 };
    for (int y = 1; y + 1 < size[1]; ++y)
    {
      for (int x = 1; x + 1 < size[0]; ++x)
      {
        const size_t at = static_cast<size_t>(y) * size[0] + x;
        const int k = hitObject[at];
        if (k < 0)
        {
          continue;
        }
        bool edge = false;
        for (int j = -1; j <= 1; ++j)
        {
          for (int i = -1; i <= 1; ++i)
          {
            edge = edge || hitObject[at + j * size[0] + i] != k;
          }
        }
        if (edge)
        {
          continue;
        }
        double ray[3];
        vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
        const double t = hitDistance[at];
        const double clearance = Clearance(body, layers, eye, ray, t);
        if (std::abs(clearance) < 1.0)
        {
          ++grazing;
          continue;
        }
        const bool objectInFront = clearance > 0;
        const unsigned char* c = rgb->GetPointer(3 * static_cast<vtkIdType>(at));
        const bool objectDrawn = k == 0 ? (c[1] > 200 && c[0] < 60 && c[2] < 60)
                                        : (c[0] > 200 && c[1] < 60 && c[2] < 60);
        ++checked[k];
        hidden[k] += objectInFront ? 0 : 1;
        wrong[k] += objectInFront != objectDrawn ? 1 : 0;
        if (objectInFront != objectDrawn && std::getenv("VTKGLOBE_TEST_VERBOSE"))
        {
          std::printf("    wrong: pixel (%d, %d) object %d clearance/margin %.2f drawn %d %d %d\n", x, y, k,
            clearance, c[0], c[1], c[2]);
        }
      }
    }
    std::printf("  wrong-surface pixels: cube %d of %d (%d behind terrain), satellite %d of %d (%d "
                "behind terrain); %d near a terrain crossing left out\n",
      wrong[0], checked[0], hidden[0], wrong[1], checked[1], hidden[1], grazing);
    ok &= checked[0] > 30 && checked[1] > 100 && wrong[0] == 0 && wrong[1] == 0;

    // Terrain from depth, read in the mode, and picking: the terrain alone.
    cubeActor->VisibilityOff();
    satelliteActor->VisibilityOff();
    scene.Render();
    const vtkGlobeTest::TerrainCheck terrain = vtkGlobeTest::CheckTerrain(scene, 2, depthPass);
    ok &= terrain.Pixels > 5000 && terrain.NaNs == 0;
    if (mode == vtkGlobeDepthPass::Logarithmic)
    {
      ok &= terrain.Failures == 0;
    }

    // Picking terrain pixels in the lower half of the view.
    vtkNew<vtkGlobePointPicker> picker;
    vtkNew<vtkWorldPointPicker> plain;
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    double worstRatio = 0.0, worstPlain = 0.0, worstPick = 0.0;
    int picks = 0;
    for (int y = 3; y < size[1] / 2; y += 9)
    {
      for (int x = 5; x < size[0]; x += 13)
      {
        const size_t at = static_cast<size_t>(y) * size[0] + x;
        if (hitObject[at] >= 0 || !(depth[at] < 1.0f))
        {
          continue;
        }
        double ray[3];
        vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
        const double t = TerrainHit(body, layers, eye, ray, 2.0e5);
        if (t < 0)
        {
          continue;
        }
        const double exact[3] = { eye[0] + t * ray[0], eye[1] + t * ray[1], eye[2] + t * ray[2] };
        picker->Pick(x + 0.5, y + 0.5, 0.0, scene.Renderer);
        plain->Pick(x + 0.5, y + 0.5, 0.0, scene.Renderer);
        const double error = std::sqrt(vtkMath::Distance2BetweenPoints(picker->GetPickPosition(), exact));
        const double plainError = std::sqrt(vtkMath::Distance2BetweenPoints(plain->GetPickPosition(), exact));
        // The mesh's height error (a few metres, more with distance) seen along a ray that
        // meets the ground at the angle of this pixel, plus the mode's depth quantization.
        double up[3];
        body->GeodeticSurfaceNormalAt(exact, up);
        const double incidence = std::max(std::abs(vtkMath::Dot(ray, up)), 0.02);
        const double quantization = mode == vtkGlobeDepthPass::Logarithmic
          ? vtkGlobeTest::LogDepthBound(depthPass, t)
          : vtkGlobeTest::DepthBound(camera, t);
        const double bound = (3.0 + 2e-4 * t) / incidence + quantization / incidence;
        worstRatio = std::max(worstRatio, error / bound);
        worstPick = std::max(worstPick, error);
        worstPlain = std::max(worstPlain, plainError);
        ++picks;
      }
    }
    std::printf("  picking %d terrain pixels: vtkGlobePointPicker worst %.2f m (worst/bound %.2f), "
                "vtkWorldPointPicker worst %.1f m\n",
      picks, worstPick, worstRatio, worstPlain);
    ok &= picks > 50 && worstRatio <= 1.0;
  }
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
