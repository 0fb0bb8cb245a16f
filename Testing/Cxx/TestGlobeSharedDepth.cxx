// The globe shares the depth buffer with ordinary VTK actors: a cone half buried in the flank
// of Mount Rainier, a sphere "satellite" in front of the horizon, and a sphere behind the
// planet's curvature. Depth readback at chosen pixels says which surface is in front:
//  - the cone's tip (above ground) is the cone, its buried base centre is terrain;
//  - the satellite's centre is the satellite, in front of the sky line;
//  - the hidden sphere's centre is terrain, nearer than the sphere.
#include "vtkConeSource.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMath.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkSphereSource.h"

namespace
{
vtkSmartPointer<vtkActor> AddActor(vtkRenderer* renderer, vtkPolyDataAlgorithm* source, double r,
  double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  renderer->AddActor(actor);
  return actor;
}

/// The pixel a world point projects to, and the world point the depth buffer has there.
bool SurfaceAt(vtkGlobeTest::Scene& scene, const std::vector<float>& depth, const double world[3],
  double seen[3], int pixel[2])
{
  scene.Renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
  scene.Renderer->WorldToDisplay();
  const double* d = scene.Renderer->GetDisplayPoint();
  const int* size = scene.Window->GetSize();
  pixel[0] = static_cast<int>(std::floor(d[0]));
  pixel[1] = static_cast<int>(std::floor(d[1]));
  if (pixel[0] < 0 || pixel[1] < 0 || pixel[0] >= size[0] || pixel[1] >= size[1])
  {
    return false;
  }
  const float z = depth[static_cast<size_t>(pixel[1]) * size[0] + pixel[0]];
  if (!(z < 1.0f))
  {
    return false;
  }
  vtkGlobeTest::UnprojectPixel(scene.Renderer, pixel[0] + 0.5, pixel[1] + 0.5, z, seen);
  return true;
}
} // namespace

int TestGlobeSharedDepth(int argc, char* argv[])
{
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  vtkGlobeEllipsoid* body = scene.Body;
  const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
  for (vtkGlobeLayer* layer : layers)
  {
    layer->Update();
  }
  // Camera 6 km up, 20 km south-west of the summit, looking at the mountain with the horizon
  // in view.
  const double camera[3] = { -121.93, 46.72, 6000.0 }, target[3] = { -121.7603, 46.8523, 3800.0 };
  scene.Look(camera, target, 50.0, 50.0, 2.0e6);
  double eye[3];
  body->GeodeticToCartesian(camera, eye);

  // A cone 1.6 km tall on the west flank, its centre at ground level: half buried.
  const double coneLon = -121.80, coneLat = 46.85;
  const double ground = vtkGlobeTest::ComposedHeight(layers, coneLon, coneLat);
  double base[3], east[3], north[3], up[3];
  body->GeodeticToCartesian(coneLon, coneLat, ground, base);
  body->ComputeEastNorthUp(coneLon, coneLat, east, north, up);
  vtkNew<vtkConeSource> cone;
  cone->SetCenter(base);
  cone->SetDirection(up);
  cone->SetHeight(1600.0);
  cone->SetRadius(500.0);
  cone->SetResolution(32);
  AddActor(scene.Renderer, cone, 1.0, 0.3, 0.1);
  double tip[3], buried[3];
  for (int i = 0; i < 3; ++i)
  {
    tip[i] = base[i] + 300.0 * up[i]; // 500 m below the apex, where the cone is 310 m wide
    buried[i] = base[i] - 700.0 * up[i];
  }

  // A satellite 2 km across, 30 km out, straddling the horizon line.
  double ahead[3];
  body->GeodeticToCartesian(-121.5, 46.95, 6000.0, ahead);
  double toAhead[3] = { ahead[0] - eye[0], ahead[1] - eye[1], ahead[2] - eye[2] };
  vtkMath::Normalize(toAhead);
  double eyeUp[3];
  body->GeodeticSurfaceNormal(camera[0], camera[1], eyeUp);
  double satellite[3];
  for (int i = 0; i < 3; ++i)
  {
    satellite[i] = eye[i] + 30000.0 * (toAhead[i] - 0.0175 * eyeUp[i]);
  }
  vtkNew<vtkSphereSource> satelliteSource;
  satelliteSource->SetCenter(satellite);
  satelliteSource->SetRadius(1000.0);
  satelliteSource->SetThetaResolution(32);
  satelliteSource->SetPhiResolution(32);
  AddActor(scene.Renderer, satelliteSource, 0.9, 0.9, 0.2);

  // A sphere of 5 km radius 800 km away at sea level: the Earth's curvature hides 21 km there
  // from a 6 km eye, so it is entirely behind the planet.
  double hidden[3];
  body->GeodeticToCartesian(-114.2, 51.5, 0.0, hidden);
  vtkNew<vtkSphereSource> hiddenSource;
  hiddenSource->SetCenter(hidden);
  hiddenSource->SetRadius(5000.0);
  AddActor(scene.Renderer, hiddenSource, 0.2, 0.5, 1.0);

  scene.Render();
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  bool ok = true;
  int pixel[2];
  double seen[3], llh[3];

  // Cone tip: the cone (within the depth bound of the tip point or nearer on the cone).
  ok &= SurfaceAt(scene, depth, tip, seen, pixel);
  const double tipDistance = std::sqrt(vtkMath::Distance2BetweenPoints(tip, eye));
  const double seenTip = std::sqrt(vtkMath::Distance2BetweenPoints(seen, eye));
  body->CartesianToGeodetic(seen, llh);
  const bool tipIsCone = llh[2] > vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]) + 50.0;
  std::printf("  cone tip at pixel (%d, %d): surface %.1f m away (tip %.1f m), %.0f m above the "
              "ground -> %s\n",
    pixel[0], pixel[1], seenTip, tipDistance,
    llh[2] - vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]), tipIsCone ? "cone" : "TERRAIN");
  ok &= tipIsCone && std::abs(seenTip - tipDistance) < 600.0;

  // Buried base: terrain in front of the point inside the mountain.
  ok &= SurfaceAt(scene, depth, buried, seen, pixel);
  const double buriedDistance = std::sqrt(vtkMath::Distance2BetweenPoints(buried, eye));
  const double seenBuried = std::sqrt(vtkMath::Distance2BetweenPoints(seen, eye));
  body->CartesianToGeodetic(seen, llh);
  const double dh = llh[2] - vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]);
  std::printf("  buried point at pixel (%d, %d): surface %.1f m away (point %.1f m), %.1f m from "
              "the terrain -> %s\n",
    pixel[0], pixel[1], seenBuried, buriedDistance, dh,
    seenBuried < buriedDistance && std::abs(dh) < 30.0 ? "terrain" : "WRONG");
  ok &= seenBuried < buriedDistance - 50.0 && std::abs(dh) < 30.0;

  // Satellite: its own surface.
  ok &= SurfaceAt(scene, depth, satellite, seen, pixel);
  const double offSphere = std::sqrt(vtkMath::Distance2BetweenPoints(seen, satellite)) - 1000.0;
  std::printf("  satellite centre at pixel (%d, %d): surface %.2f m from the sphere -> %s\n",
    pixel[0], pixel[1], offSphere, std::abs(offSphere) < 5.0 ? "satellite" : "WRONG");
  ok &= std::abs(offSphere) < 5.0;

  // Hidden sphere: terrain, nearer than the sphere's front.
  const bool covered = SurfaceAt(scene, depth, hidden, seen, pixel);
  const double hiddenFront = std::sqrt(vtkMath::Distance2BetweenPoints(hidden, eye)) - 5000.0;
  const double seenHidden = covered ? std::sqrt(vtkMath::Distance2BetweenPoints(seen, eye)) : 0.0;
  body->CartesianToGeodetic(seen, llh);
  const double dhHidden = llh[2] - vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1]);
  std::printf("  hidden sphere centre at pixel (%d, %d): surface %.0f m away, sphere front %.0f m, "
              "%.1f m from the terrain -> %s\n",
    pixel[0], pixel[1], seenHidden, hiddenFront, dhHidden,
    covered && seenHidden < hiddenFront && std::abs(dhHidden) < 200.0 ? "terrain" : "WRONG");
  ok &= covered && seenHidden < hiddenFront && std::abs(dhHidden) < 200.0;

  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
