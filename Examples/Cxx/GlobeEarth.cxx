// GlobeEarth: the main demo. Renders the Earth from the data in Data/ (a 2-degree global
// relief, SRTM insets of Mount Rainier and Mount Everest, Blue Marble imagery) and the Moon
// with the Projective Grid Mapping globe mapper, as a gallery of five pictures:
//   earth       the whole Earth with its atmosphere (limb glow, sunlit sea glint);
//   rainier     Mount Rainier from 3 km, under a sky, its relief tinted by height;
//   everest     Everest rising from behind the horizon, 200 km away, through the haze;
//   moon        the Moon on its own 1,737.4 km sphere, lit from the side;
//   companions  the Earth with a satellite on a drawn orbit: ordinary VTK actors in front of
//               and behind the globe, sharing its depth buffer.
//
//   GlobeEarth [--data DIR] [--out DIR] [--view NAME|all] [--size WxH] [--grid N]
//              [--interactive] [--no-filtering]
//
// Without --interactive it renders each viewpoint offscreen and writes globe-NAME.png files (no
// display needed); with it, it opens a window navigated by vtkGlobeInteractorStyle (drag the
// ground, wheel to zoom toward the cursor, Ctrl+drag to tilt and turn; n north up, u look down,
// r the whole Earth; 1/2/3 for the Earth's viewpoints, q to quit). The grid follows the window
// (the mapper's default) unless --grid fixes it. --no-filtering reads the Earth's layers at
// full resolution whatever the footprint (vtkGlobeMapper::FootprintFilteringOff): the
// "before" pictures of Documentation/composition.md "Filtering to the footprint".
#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeInteractorStyle.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#ifndef VTKGLOBE_DATA_DIR
#define VTKGLOBE_DATA_DIR "Data"
#endif

namespace
{
struct Viewpoint
{
  const char* Name;
  const char* Description;
  // Camera and target in geodetic coordinates (deg, deg, m); view angle (deg); clipping range
  // (m), or 0 to let VTK choose from the bounds.
  double Camera[3];
  double Target[3];
  double ViewAngle;
  double Near, Far;
  // The sun seen from the target: azimuth (deg from north, clockwise) and elevation (deg).
  double SunAzimuth, SunElevation;
  // What the scene calls for: the atmosphere (sky, haze, limb), a hypsometric tint of this
  // opacity over the imagery (0: none) with snow above SnowLine (m), the Moon instead of the
  // Earth, the satellite.
  bool Atmosphere;
  double Tint, SnowLine;
  bool Moon;
  bool Companions;
};

const Viewpoint Viewpoints[] = {
  { "earth", "the whole Earth with its atmosphere (Mahsman's TC1)", { -40.0, 25.0, 2.2e7 },
    { -40.0, 25.0, 0.0 }, 30.0, 0, 0, 120.0, 40.0, true, 0.0, 0.0, false, false },
  { "rainier", "Mount Rainier from 3 km under a sky, relief tinted by height",
    { -121.97, 46.70, 3000.0 }, { -121.7603, 46.8523, 3600.0 }, 45.0, 10.0, 1.0e6, 150.0, 35.0,
    true, 0.55, 3300.0, false, false },
  { "everest", "Everest on the horizon, 60 km away, from 4,000 m, through the haze, tinted",
    { 86.55, 27.55, 4000.0 }, { 86.925, 27.9881, 7500.0 }, 30.0, 10.0, 1.0e6, 240.0, 20.0, true,
    0.5, 5500.0, false, false },
  { "moon", "the Moon on its 1,737.4 km sphere", { 20.0, 10.0, 4.6e6 }, { 20.0, 10.0, 0.0 },
    30.0, 0, 0, 270.0, 45.0, false, 0.0, 0.0, true, false },
  { "companions", "the Earth with a satellite on its orbit (VTK actors sharing the depth)",
    { -3.2, 58.2, 1.76e7 }, { -3.2, 58.2, 0.0 }, 36.0, 0, 0, 200.0, 40.0, true, 0.0, 0.0, false,
    true },
};

// The orbit of the companions view: a circle 3,000 km up, inclined 51.6 degrees, its ascending
// node at 30 W, seen from 20 degrees above its plane (the camera's (-3.2, 58.2)), so that it
// passes in front of the Earth and behind it; the satellite is on it, 80 degrees from the node.
void OrbitPoint(double anomalyDeg, double radius, double p[3])
{
  const double deg = 3.14159265358979 / 180.0;
  const double u = anomalyDeg * deg, i = 51.6 * deg, node = -30.0 * deg;
  p[0] = radius * (std::cos(u) * std::cos(node) - std::sin(u) * std::cos(i) * std::sin(node));
  p[1] = radius * (std::cos(u) * std::sin(node) + std::sin(u) * std::cos(i) * std::cos(node));
  p[2] = radius * std::sin(u) * std::sin(i);
}

// An atlas tint for land and sea floor (metres), as in Examples/Python/relief_map.py, with
// rock below the snow line and snow above it.
void FillTint(vtkColorTransferFunction* tint, double snowLine)
{
  tint->RemoveAllPoints();
  const double stops[][4] = { { -6000, 0.05, 0.15, 0.45 }, { -150, 0.45, 0.70, 0.90 },
    { 0, 0.12, 0.42, 0.20 }, { 500, 0.45, 0.62, 0.30 }, { 1500, 0.85, 0.78, 0.45 },
    { snowLine - 1200, 0.62, 0.42, 0.25 }, { snowLine - 300, 0.58, 0.52, 0.48 },
    { snowLine, 0.95, 0.95, 0.95 }, { 9000, 1.0, 1.0, 1.0 } };
  for (const auto& stop : stops)
  {
    tint->AddRGBPoint(stop[0], stop[1], stop[2], stop[3]);
  }
}

/// A directional sun for the viewpoint, placed from its azimuth and elevation at the target.
void PlaceSun(vtkLight* sun, vtkGlobeEllipsoid* body, const Viewpoint& v)
{
  double target[3], east[3], north[3], up[3];
  body->GeodeticToCartesian(v.Target, target);
  body->ComputeEastNorthUp(v.Target[0], v.Target[1], east, north, up);
  const double deg = 3.14159265358979 / 180.0;
  const double a = v.SunAzimuth * deg, e = v.SunElevation * deg;
  double position[3];
  for (int i = 0; i < 3; ++i)
  {
    const double toSun = std::cos(e) * (std::sin(a) * east[i] + std::cos(a) * north[i]) + std::sin(e) * up[i];
    position[i] = target[i] + 1.0e7 * toSun;
  }
  sun->SetPosition(position);
  sun->SetFocalPoint(target);
}

void PlaceCamera(vtkRenderer* renderer, vtkGlobeEllipsoid* body, const Viewpoint& v)
{
  double eye[3], target[3], east[3], north[3], up[3];
  body->GeodeticToCartesian(v.Camera, eye);
  body->GeodeticToCartesian(v.Target, target);
  body->ComputeEastNorthUp(v.Camera[0], v.Camera[1], east, north, up);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(eye);
  camera->SetFocalPoint(target);
  // Looking down the vertical, "up" is the view direction itself: use north instead.
  double view[3] = { target[0] - eye[0], target[1] - eye[1], target[2] - eye[2] };
  const double length = std::sqrt(view[0] * view[0] + view[1] * view[1] + view[2] * view[2]);
  const double along = (view[0] * up[0] + view[1] * up[1] + view[2] * up[2]) / length;
  camera->SetViewUp(std::abs(along) > 0.999 ? north : up);
  camera->SetViewAngle(v.ViewAngle);
  camera->OrthogonalizeViewUp();
  if (v.Near > 0)
  {
    camera->SetClippingRange(v.Near, v.Far);
  }
  else
  {
    renderer->ResetCameraClippingRange();
  }
}

vtkGlobeLayer* AddLayer(vtkGlobeMapper* mapper, const std::string& file, bool height)
{
  vtkGlobeLayer* layer = vtkGlobeLayer::New();
  layer->SetFileName(file.c_str());
  if (height)
  {
    layer->SetRoleToHeight();
  }
  else
  {
    layer->SetRoleToColor();
  }
  mapper->AddLayer(layer);
  layer->Delete();
  return layer;
}
} // namespace

int main(int argc, char* argv[])
{
  std::string data = VTKGLOBE_DATA_DIR, out = ".", view = "all";
  int width = 800, height = 600, grid = 0;
  bool interactive = false, filtering = true;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--data" && hasValue)
    {
      data = argv[++i];
    }
    else if (arg == "--out" && hasValue)
    {
      out = argv[++i];
    }
    else if (arg == "--view" && hasValue)
    {
      view = argv[++i];
    }
    else if (arg == "--size" && hasValue && std::sscanf(argv[i + 1], "%dx%d", &width, &height) == 2)
    {
      ++i;
    }
    else if (arg == "--grid" && hasValue)
    {
      grid = std::atoi(argv[++i]);
    }
    else if (arg == "--interactive")
    {
      interactive = true;
    }
    else if (arg == "--no-filtering")
    {
      filtering = false; // level 0 whatever the footprint: the "before" of the filtering
    }
    else
    {
      std::printf("usage: %s [--data DIR] [--out DIR] "
                  "[--view earth|rainier|everest|moon|companions|all] [--size WxH] [--grid N] "
                  "[--interactive] [--no-filtering]\n",
        argv[0]);
      return arg == "--help" || arg == "-h" ? 0 : 2;
    }
  }

  vtkNew<vtkGlobeEllipsoid> wgs84;
  vtkNew<vtkGlobeMapper> mapper;
  mapper->SetEllipsoid(wgs84);
  if (grid > 0)
  {
    mapper->SetGridResolution(grid);
  }
  mapper->SetFootprintFiltering(filtering);
  AddLayer(mapper, data + "/earth/relief_2deg.tif", true);
  AddLayer(mapper, data + "/earth/mt_rainier_90m.tif", true);
  AddLayer(mapper, data + "/earth/mt_everest_90m.tif", true);
  AddLayer(mapper, data + "/earth/world.tif", false);
  mapper->SpecularWaterOn();
  vtkNew<vtkColorTransferFunction> tint;

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);

  // The Moon: its own body and mapper, shown in its own view.
  vtkNew<vtkGlobeEllipsoid> moonBody;
  moonBody->SetToMoon();
  vtkNew<vtkGlobeMapper> moonMapper;
  moonMapper->SetFootprintFiltering(filtering);
  moonMapper->SetEllipsoid(moonBody);
  if (grid > 0)
  {
    moonMapper->SetGridResolution(grid);
  }
  AddLayer(moonMapper, data + "/moon/moon_1024x512.tif", false);
  vtkNew<vtkActor> moon;
  moon->SetMapper(moonMapper);
  moon->VisibilityOff();
  renderer->AddActor(moon);

  // The companions: the orbit as a polyline and the satellite as a sphere, plain VTK actors.
  vtkNew<vtkPoints> orbitPoints;
  vtkNew<vtkCellArray> orbitLine;
  const int samples = 720;
  orbitLine->InsertNextCell(samples + 1);
  for (int k = 0; k <= samples; ++k)
  {
    double p[3];
    OrbitPoint(360.0 * k / samples, 6378137.0 + 3.0e6, p);
    orbitLine->InsertCellPoint(k < samples ? orbitPoints->InsertNextPoint(p) : 0);
  }
  vtkNew<vtkPolyData> orbitData;
  orbitData->SetPoints(orbitPoints);
  orbitData->SetLines(orbitLine);
  vtkNew<vtkPolyDataMapper> orbitMapper;
  orbitMapper->SetInputData(orbitData);
  vtkNew<vtkActor> orbit;
  orbit->SetMapper(orbitMapper);
  orbit->GetProperty()->SetColor(1.0, 0.8, 0.2);
  orbit->GetProperty()->SetLineWidth(3.0);
  orbit->GetProperty()->LightingOff();
  vtkNew<vtkSphereSource> satelliteShape;
  double satellitePosition[3];
  OrbitPoint(80.0, 6378137.0 + 3.0e6, satellitePosition);
  satelliteShape->SetCenter(satellitePosition);
  satelliteShape->SetRadius(4.0e5);
  satelliteShape->SetThetaResolution(32);
  satelliteShape->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> satelliteMapper;
  satelliteMapper->SetInputConnection(satelliteShape->GetOutputPort());
  vtkNew<vtkActor> satellite;
  satellite->SetMapper(satelliteMapper);
  satellite->GetProperty()->SetColor(0.9, 0.9, 0.95);
  for (vtkActor* a : { orbit.Get(), satellite.Get() })
  {
    a->VisibilityOff();
    renderer->AddActor(a);
  }
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetIntensity(1.1);
  renderer->AddLight(sun);
  renderer->SetBackground(0.0, 0.0, 0.02);
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(interactive ? 0 : 1);

  if (interactive)
  {
    PlaceCamera(renderer, wgs84, Viewpoints[0]);
    PlaceSun(sun, wgs84, Viewpoints[0]);
    vtkNew<vtkRenderWindowInteractor> interactor;
    vtkNew<vtkGlobeInteractorStyle> style;
    style->SetMapper(mapper);
    interactor->SetInteractorStyle(style);
    interactor->SetRenderWindow(window);
    struct Context
    {
      vtkRenderer* Renderer;
      vtkGlobeEllipsoid* Body;
      vtkLight* Sun;
    } context{ renderer, wgs84, sun };
    vtkNew<vtkCallbackCommand> keys;
    keys->SetClientData(&context);
    keys->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void*) {
      auto* c = static_cast<Context*>(clientData);
      auto* iren = static_cast<vtkRenderWindowInteractor*>(caller);
      const char key = iren->GetKeyCode();
      if (key >= '1' && key <= '3')
      {
        PlaceCamera(c->Renderer, c->Body, Viewpoints[key - '1']);
        PlaceSun(c->Sun, c->Body, Viewpoints[key - '1']);
        iren->Render();
      }
    });
    interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
    window->Render();
    interactor->Start();
    return 0;
  }

  int written = 0;
  for (const Viewpoint& v : Viewpoints)
  {
    if (view != "all" && view != v.Name)
    {
      continue;
    }
    vtkGlobeEllipsoid* body = v.Moon ? moonBody.Get() : wgs84.Get();
    actor->SetVisibility(!v.Moon);
    moon->SetVisibility(v.Moon);
    orbit->SetVisibility(v.Companions);
    satellite->SetVisibility(v.Companions);
    mapper->SetAtmosphere(v.Atmosphere);
    FillTint(tint, v.SnowLine);
    mapper->GetCompositePass()->SetHeightColors(v.Tint > 0.0 ? tint.Get() : nullptr);
    mapper->GetCompositePass()->SetHeightColorOpacity(v.Tint);
    PlaceCamera(renderer, body, v);
    PlaceSun(sun, body, v);
    // Two frames: the second uses the first one's lowest visible terrain (GPU reduction).
    window->Render();
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkNew<vtkPNGWriter> writer;
    const std::string file = out + "/globe-" + v.Name + ".png";
    writer->SetFileName(file.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    // A picture that is nearly all background means something failed to draw: say so.
    vtkImageData* picture = grab->GetOutput();
    const vtkIdType pixels = picture->GetNumberOfPoints();
    vtkIdType drawn = 0;
    for (vtkIdType i = 0; i < pixels; ++i)
    {
      const auto* rgb = static_cast<unsigned char*>(picture->GetScalarPointer()) +
        i * picture->GetNumberOfScalarComponents();
      drawn += (rgb[0] > 12 || rgb[1] > 12 || rgb[2] > 12) ? 1 : 0;
    }
    if (writer->GetErrorCode() != 0 || drawn < pixels / 10)
    {
      std::fprintf(stderr, "error: %s: %s (%lld of %lld pixels drawn)\n", file.c_str(),
        writer->GetErrorCode() != 0 ? "could not be written" : "the picture is nearly empty",
        static_cast<long long>(drawn), static_cast<long long>(pixels));
      return 1;
    }
    vtkGlobeMapper* shown = v.Moon ? moonMapper.Get() : mapper.Get();
    std::printf("wrote %s: %s (grid %d^2, %dx%d)\n", file.c_str(), v.Description,
      shown->GetGridResolution(), width, height);
    ++written;
  }
  if (written == 0)
  {
    std::fprintf(stderr, "Unknown view '%s' (earth, rainier, everest, moon, companions or all).\n",
      view.c_str());
    return 2;
  }
  return 0;
}
