// Logarithmic depth (vtkGlobeDepthPass) for the kinds of VTK actor that write their own depth
// or project in a geometry shader: an impostor sphere (vtkOpenGLSphereMapper: its vertex
// shader outputs view coordinates, its geometry shader projects them, its fragment shader
// writes the sphere's depth), points drawn as spheres (vtkProperty::RenderPointsAsSpheres:
// depth moved to the sphere's surface in the fragment shader), and a surface with its edges
// (VTK's coincident-topology offset, written into gl_FragDepth). Each is drawn in Default and
// in Logarithmic mode next to the globe, with the clipping policy's range, and per mode:
//  - the pixels it covers: Logarithmic must draw the same as Default (within 1 %);
//  - the eye distance its depth gives at the object's centre pixel (the mode's depth turned
//    back into a distance, vtkGlobeDepthPass::GetViewDistance): the same in both modes, within
//    the modes' resolution, and for the impostor sphere the exact ray/sphere hit (double);
//  - the edges over their surface: Logarithmic keeps VTK's offset, so they show as in Default.
#include "vtkCellArray.h"
#include "vtkGlobeClippingRange.h"
#include "vtkGlobeDepthPass.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

namespace
{
struct Frame
{
  std::vector<unsigned char> Pixels;
  std::vector<float> Depth;
};

/// Pixels of a pure colour (each channel 0 or 255 as given, within 40 of it).
/// One vertex at the origin: each object's points are relative to its actor's position (a
/// double matrix), since points stored as floats 6,900 km from the body's centre would be
/// rounded by up to 0.5 m.
vtkSmartPointer<vtkPolyData> Vertex()
{
  vtkNew<vtkPoints> p;
  p->InsertNextPoint(0.0, 0.0, 0.0);
  vtkNew<vtkCellArray> v;
  vtkIdType id = 0;
  v->InsertNextCell(1, &id);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(p);
  data->SetVerts(v);
  return data;
}

/// The actor of a mapper at a position, in one flat colour.
vtkSmartPointer<vtkActor> FlatAt(vtkMapper* mapper, const double position[3], double r, double g, double b)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPosition(position[0], position[1], position[2]);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetAmbient(1);
  actor->GetProperty()->SetDiffuse(0);
  return actor;
}

int Count(const Frame& f, int r, int g, int b)
{
  int n = 0;
  for (size_t i = 0; i + 2 < f.Pixels.size(); i += 3)
  {
    n += std::abs(f.Pixels[i] - r) <= 40 && std::abs(f.Pixels[i + 1] - g) <= 40 &&
        std::abs(f.Pixels[i + 2] - b) <= 40
      ? 1
      : 0;
  }
  return n;
}
} // namespace

int TestGlobeDepthActors(int, char*[])
{
  const int width = 300, height = 225;
  vtkGlobeTest::Scene scene(width, height, 128);
  // The globe far behind the objects: a camera 500 km above the ground looking down, so the
  // clipping policy's range spans the objects (tens of metres) to the ground.
  const double camera[3] = { -121.76, 46.85, 5.0e5 }, target[3] = { -121.76, 46.85, 0.0 };
  scene.Look(camera, target, 30.0);
  vtkCamera* cam = scene.Renderer->GetActiveCamera();
  double eye[3], forward[3], up[3], right[3];
  cam->GetPosition(eye);
  cam->GetDirectionOfProjection(forward);
  cam->GetViewUp(up);
  vtkMath::Cross(forward, up, right);
  vtkMath::Normalize(right);
  vtkMath::Cross(right, forward, up);
  // A point d metres ahead, x to the right and y up (metres).
  auto ahead = [&](double d, double x, double y, double p[3]) {
    for (int k = 0; k < 3; ++k)
    {
      p[k] = eye[k] + d * forward[k] + x * right[k] + y * up[k];
    }
  };

  // Red: an impostor sphere, radius 4 m, 100 m ahead, to the left.
  const double radius = 4.0;
  double sphereCentre[3];
  ahead(100.0, -18.0, 8.0, sphereCentre);
  vtkNew<vtkOpenGLSphereMapper> impostorMapper;
  impostorMapper->SetInputData(Vertex());
  impostorMapper->SetRadius(radius);
  impostorMapper->ScalarVisibilityOff();
  scene.Renderer->AddActor(FlatAt(impostorMapper, sphereCentre, 1, 0, 0));

  // Green: a point drawn as a sphere, 30 px, 100 m ahead, to the right.
  double pointCentre[3];
  ahead(100.0, 18.0, 8.0, pointCentre);
  vtkNew<vtkPolyDataMapper> pointMapper;
  pointMapper->SetInputData(Vertex());
  vtkSmartPointer<vtkActor> pointActor = FlatAt(pointMapper, pointCentre, 0, 1, 0);
  pointActor->GetProperty()->SetPointSize(30);
  pointActor->GetProperty()->RenderPointsAsSpheresOn();
  scene.Renderer->AddActor(pointActor);

  // Blue with yellow edges: a 40 m square 120 m ahead, below, tilted 60 degrees away.
  vtkNew<vtkPlaneSource> plane;
  double planeOrigin[3];
  ahead(120.0, -20.0, -20.0, planeOrigin);
  {
    double o[3], a[3], b[3];
    const double tilt = vtkMath::RadiansFromDegrees(60.0);
    ahead(120.0, -20.0, -20.0, o);
    ahead(120.0, 20.0, -20.0, a);
    ahead(120.0 + 40.0 * std::sin(tilt), -20.0, -20.0 + 40.0 * std::cos(tilt), b);
    for (int k = 0; k < 3; ++k)
    {
      a[k] -= o[k];
      b[k] -= o[k];
    }
    plane->SetOrigin(0.0, 0.0, 0.0);
    plane->SetPoint1(a);
    plane->SetPoint2(b);
    plane->SetResolution(6, 6);
  }
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  planeMapper->ScalarVisibilityOff();
  vtkSmartPointer<vtkActor> planeActor = FlatAt(planeMapper, planeOrigin, 0, 0, 1);
  planeActor->GetProperty()->EdgeVisibilityOn();
  planeActor->GetProperty()->SetEdgeColor(1, 1, 0);
  planeActor->GetProperty()->SetLineWidth(1);
  scene.Renderer->AddActor(planeActor);

  vtkNew<vtkGlobeDepthPass> depthPass;
  scene.Renderer->SetPass(depthPass);
  // The clipping policy's range: it must hold the spheres' surfaces, which their bounds (a
  // point each) leave out.
  vtkGlobeClippingRange::Install(scene.Renderer);
  scene.Renderer->ResetCameraClippingRange();
  const double nearPlane = cam->GetClippingRange()[0];
  std::printf("clipping range [%.3f, %.1f] m\n", nearPlane, cam->GetClippingRange()[1]);

  // The pixel (x, y) where a world point projects, and the eye distance along the view axis
  // that the depth there gives in the current mode.
  auto pixelOf = [&](const double p[3], int& x, int& y) {
    scene.Renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
    scene.Renderer->WorldToDisplay();
    double d[3];
    scene.Renderer->GetDisplayPoint(d);
    x = static_cast<int>(std::floor(d[0]));
    y = static_cast<int>(std::floor(d[1]));
  };
  auto distanceAt = [&](const Frame& f, int x, int y) {
    return depthPass->GetViewDistance(f.Depth[static_cast<size_t>(y) * width + x], cam);
  };
  // The exact hit of the ray through the centre of pixel (x, y) with the impostor sphere,
  // as an eye distance along the view axis.
  auto sphereHit = [&](int x, int y) {
    scene.Renderer->SetDisplayPoint(x + 0.5, y + 0.5, 0.0);
    scene.Renderer->DisplayToWorld();
    double w[4];
    scene.Renderer->GetWorldPoint(w);
    double ray[3] = { w[0] / w[3] - eye[0], w[1] / w[3] - eye[1], w[2] / w[3] - eye[2] };
    vtkMath::Normalize(ray);
    double rel[3] = { eye[0] - sphereCentre[0], eye[1] - sphereCentre[1], eye[2] - sphereCentre[2] };
    const double b = vtkMath::Dot(rel, ray);
    const double c = vtkMath::Dot(rel, rel) - radius * radius;
    const double t = -b - std::sqrt(std::max(b * b - c, 0.0));
    return t * vtkMath::Dot(ray, forward);
  };

  Frame frames[2];
  const int modes[2] = { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic };
  for (int m = 0; m < 2; ++m)
  {
    depthPass->SetMode(modes[m]);
    scene.Render();
    scene.Render();
    frames[m].Pixels = vtkGlobeTest::ReadPixels(scene.Window);
    frames[m].Depth = vtkGlobeTest::ReadDepth(scene.Window);
  }
  vtkGlobeTest::Checklist checks;
  checks.Expect(vtkGlobeTest::NoGLError(), "no OpenGL error");
  int sx, sy, px, py;
  pixelOf(sphereCentre, sx, sy);
  pixelOf(pointCentre, px, py);
  const double exact = sphereHit(sx, sy);
  int red[2], green[2], yellow[2];
  double sphereW[2], pointW[2];
  for (int m = 0; m < 2; ++m)
  {
    depthPass->SetMode(modes[m]); // GetViewDistance reads depth in the mode
    const Frame& f = frames[m];
    red[m] = Count(f, 255, 0, 0);
    green[m] = Count(f, 0, 255, 0);
    yellow[m] = Count(f, 255, 255, 0);
    sphereW[m] = distanceAt(f, sx, sy);
    pointW[m] = distanceAt(f, px, py);
    std::printf("%s: impostor sphere %d px, at its centre %.4f m (exact hit %.4f m, its centre "
                "100 m); point sphere %d px, at its centre %.4f m; plane %d px, its edges %d px\n",
      vtkGlobeDepthPass::GetModeAsString(modes[m]), red[m], sphereW[m], exact, green[m],
      pointW[m], Count(f, 0, 0, 255), yellow[m]);
  }
  checks.Expect(red[0] > 100 && std::abs(red[1] - red[0]) <= 0.01 * red[0],
    "the impostor sphere covers what it covers in Default mode");
  checks.Expect(std::abs(sphereW[0] - exact) <= 0.01 && std::abs(sphereW[1] - exact) <= 0.01,
    "its depth is its surface's (within 1 cm of the exact hit, 4 m before its quad) in both modes");
  checks.Expect(green[0] > 100 && std::abs(green[1] - green[0]) <= 0.01 * green[0],
    "the point sphere covers what it covers in Default mode");
  checks.Expect(std::abs(pointW[1] - pointW[0]) <= 0.01 && pointW[0] < 100.0 - 1.0,
    "its depth is its surface's, as in Default mode (within 1 cm)");
  checks.Expect(nearPlane < exact && nearPlane < pointW[1],
    "the clipping policy's near plane is in front of both spheres' surfaces");
  checks.Expect(yellow[0] > 200 && yellow[1] >= 0.95 * yellow[0],
    "the plane's edges show over it as in Default mode (VTK's coincident offset kept)");
  return checks.Result();
}
