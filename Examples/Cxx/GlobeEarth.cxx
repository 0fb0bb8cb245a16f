// GlobeEarth: the main demo. Renders the Earth from the data in Data/ (a 2-degree global
// relief, SRTM insets of Mount Rainier and Mount Everest, Blue Marble imagery) with the
// Projective Grid Mapping globe mapper.
//
//   GlobeEarth [--data DIR] [--out DIR] [--view earth|rainier|everest|all] [--size WxH]
//              [--grid N] [--interactive]
//
// Without --interactive it renders each viewpoint offscreen and writes PNG files (no display
// needed); with it, it opens a window navigated by vtkGlobeInteractorStyle (drag the ground,
// wheel to zoom toward the cursor, Ctrl+drag to tilt and turn; n north up, u look down, r the
// whole Earth; 1/2/3 for the viewpoints, q to quit).
#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeInteractorStyle.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeMapper.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
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
};

const Viewpoint Viewpoints[] = {
  { "earth", "the whole Earth (Mahsman's TC1)", { -40.0, 25.0, 2.2e7 }, { -40.0, 25.0, 0.0 }, 30.0,
    0, 0, 120.0, 60.0 },
  { "rainier", "Mount Rainier from 20 km (Mahsman's TC2)", { -121.86, 46.75, 16000.0 },
    { -121.7603, 46.8523, 4392.0 }, 40.0, 100.0, 1.0e6, 150.0, 35.0 },
  { "everest", "Everest rising from behind the horizon, 200 km away, from 1,000 m",
    { 85.2, 26.6, 1000.0 }, { 86.925, 27.9881, 6000.0 }, 12.0, 100.0, 1.0e6, 200.0, 30.0 },
};

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
  int width = 800, height = 600, grid = 512;
  bool interactive = false;
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
    else
    {
      std::printf("usage: %s [--data DIR] [--out DIR] [--view earth|rainier|everest|all] "
                  "[--size WxH] [--grid N] [--interactive]\n",
        argv[0]);
      return arg == "--help" || arg == "-h" ? 0 : 2;
    }
  }

  vtkNew<vtkGlobeEllipsoid> wgs84;
  vtkNew<vtkGlobeMapper> mapper;
  mapper->SetEllipsoid(wgs84);
  mapper->SetGridResolution(grid);
  AddLayer(mapper, data + "/earth/relief_2deg.tif", true);
  AddLayer(mapper, data + "/earth/mt_rainier_90m.tif", true);
  AddLayer(mapper, data + "/earth/mt_everest_90m.tif", true);
  AddLayer(mapper, data + "/earth/world.tif", false);

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
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
    PlaceCamera(renderer, wgs84, v);
    PlaceSun(sun, wgs84, v);
    // Two frames: the second uses the first one's lowest visible terrain (GPU reduction).
    window->Render();
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    const std::string file = out + "/globe-" + v.Name + ".png";
    writer->SetFileName(file.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    std::printf("wrote %s: %s (grid %d^2, %dx%d)\n", file.c_str(), v.Description, grid, width, height);
    ++written;
  }
  if (written == 0)
  {
    std::fprintf(stderr, "Unknown view '%s' (earth, rainier, everest or all).\n", view.c_str());
    return 2;
  }
  return 0;
}
