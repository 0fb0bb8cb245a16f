// vtkGlobeInteractorStyle driven by vtkInteractorEventRecorder (issue 13): long random walks of
// drags, tilts, wheel notches and keys on the Earth near Mount Rainier (the SRTM inset over the
// 2-degree relief), on the Moon and on a triaxial body, each with height layers. After every
// event:
//  - the camera is at least MinimumHeightAboveTerrain over the composed terrain at its
//    sub-point (ComposedHeight: the tests' own mirror of the GPU composition);
//  - it is not rolled: its right vector is horizontal (|right . up| < 1e-6), so its view-up is
//    the local up's projection (checked too where the view is tilted more than 1 degree);
//  - during a drag the grabbed point projects within 1 px of the cursor;
//  - after a wheel notch the zoom's target (the terrain point under the cursor) projects within
//    1 px of the cursor.
// The Earth walk is the stream kept in Testing/Data/Events/GlobeInteractorEarth.log; the Moon's
// and the triaxial body's are generated with fixed seeds (the same generator wrote the file:
// run with -write-events FILE to write it again).
#include "vtkGlobeRenderingTestHelpers.h"

#include "vtkCallbackCommand.h"
#include "vtkFloatArray.h"
#include "vtkGlobeInteractorStyle.h"
#include "vtkImageData.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkPointData.h"
#include "vtkGenericRenderWindowInteractor.h"

#include <chrono>
#include <fstream>
#include <random>
#include <sstream>

namespace
{
const int Width = 200, Height = 150;

// One event line of vtkInteractorEventRecorder's stream (version 1.1, as VTK 9.1 records it):
// name, x, y, modifiers (shift 1, ctrl 2), key code (a number), repeat count, key symbol.
void Line(std::ostream& os, const char* name, int x, int y, int ctrl = 0, int key = 0)
{
  os << name << " " << x << " " << y << " " << (ctrl ? 2 : 0) << " " << key << " 0 ";
  if (key)
  {
    os << static_cast<char>(key) << "\n";
  }
  else
  {
    os << "0\n";
  }
}

// A random walk: drags (the ground grabbed), tilt drags (Ctrl), wheel notches (more in than
// out, so the camera comes down to the terrain), right-drag zooms and the keys n and u.
std::string RandomWalk(unsigned seed, int events)
{
  std::mt19937 random(seed);
  auto uniform = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(random); };
  std::ostringstream os;
  os << "# StreamVersion 1.1\n";
  int count = 0;
  while (count < events)
  {
    const int action = uniform(0, 99);
    int x = uniform(30, Width - 30), y = uniform(25, Height - 25);
    if (action < 35 || (action >= 45 && action < 55))
    {
      const bool tilt = action >= 45;
      Line(os, "LeftButtonPressEvent", x, y, tilt ? 1 : 0);
      const int moves = uniform(4, 10);
      for (int m = 0; m < moves; ++m)
      {
        x = std::max(2, std::min(Width - 3, x + uniform(-12, 12)));
        y = std::max(2, std::min(Height - 3, y + uniform(-12, 12)));
        Line(os, "MouseMoveEvent", x, y, tilt ? 1 : 0);
      }
      Line(os, "LeftButtonReleaseEvent", x, y, tilt ? 1 : 0);
      count += moves + 2;
    }
    else if (action < 85)
    {
      // Dives of up to 12 notches in: the walk spends most of its time near the margin.
      const bool in = uniform(0, 99) < 70;
      const int notches = in ? uniform(2, 12) : uniform(1, 4);
      for (int n = 0; n < notches; ++n)
      {
        Line(os, in ? "MouseWheelForwardEvent" : "MouseWheelBackwardEvent", x, y);
      }
      count += notches;
    }
    else if (action < 92)
    {
      Line(os, "RightButtonPressEvent", x, y);
      const int moves = uniform(2, 5);
      for (int m = 0; m < moves; ++m)
      {
        y = std::max(2, std::min(Height - 3, y + uniform(-15, 15)));
        Line(os, "MouseMoveEvent", x, y);
      }
      Line(os, "RightButtonReleaseEvent", x, y);
      count += moves + 2;
    }
    else
    {
      const int key = uniform(0, 1) ? 'n' : 'u';
      Line(os, "KeyPressEvent", x, y, 0, key);
      Line(os, "CharEvent", x, y, 0, key);
      Line(os, "KeyReleaseEvent", x, y, 0, key);
      count += 3;
    }
  }
  return os.str();
}

// A global geographic height layer in memory: value(lon, lat) at the post centres (rows from
// the north).
vtkSmartPointer<vtkGlobeLayer> SyntheticHeights(const std::function<double(double, double)>& value)
{
  const int w = 256, h = 128;
  const double pixel = 360.0 / w;
  std::vector<float> heights;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const double lon = -180.0 + (i + 0.5) * pixel, lat = 90.0 - (j + 0.5) * pixel;
      heights.push_back(static_cast<float>(value(lon, lat)));
    }
  }
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetHeightData(w, h, heights.data(), -180.0, 180.0, -90.0, 90.0);
  return layer;
}

struct Stats
{
  int Events = 0;
  double WorstMargin = 1e300; // least (height - terrain - minimum), m
  double LowestHeight = 1e300; // least height over the terrain, m
  double WorstRoll = 0;        // largest |right . up|
  double WorstUp = 0;          // largest |view-up - up's projection| where tilted > 1 degree
  double WorstGrab = 0;        // px
  int GrabMoves = 0;
  int InexactGrabMoves = 0;
  double WorstZoom = 0; // px
  int ZoomNotches = 0;
  int InexactZooms = 0;
  double MinTilt = 1e300, MaxTilt = 0; // degrees
  int Keys = 0;
  double WorstNadir = 0;   // tilt after 'u', degrees
  double WorstHeading = 0; // |heading| after 'n' at the eye (the turn is about the centre's
                           // vertical, so meridian convergence leaves a little), degrees
};

struct Context
{
  vtkGlobeTest::Scene* Scene;
  vtkGlobeInteractorStyle* Style;
  vtkRenderWindowInteractor* Interactor;
  std::vector<vtkGlobeLayer*> Layers;
  Stats S;
};

void Project(vtkRenderer* renderer, const double world[3], double display[3])
{
  renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
}

void Check(vtkObject*, unsigned long event, void* data, void*)
{
  auto* c = static_cast<Context*>(data);
  vtkRenderer* renderer = c->Scene->Renderer;
  vtkCamera* camera = renderer->GetActiveCamera();
  Stats& s = c->S;
  ++s.Events;
  double eye[3], focal[3], viewUp[3], llh[3];
  camera->GetPosition(eye);
  camera->GetFocalPoint(focal);
  camera->GetViewUp(viewUp);
  c->Scene->Body->CartesianToGeodetic(eye, llh);
  const double ground = vtkGlobeTest::ComposedHeight(c->Layers, llh[0], llh[1]);
  const double margin = llh[2] - ground - c->Style->GetMinimumHeightAboveTerrain();
  s.WorstMargin = std::min(s.WorstMargin, margin);
  s.LowestHeight = std::min(s.LowestHeight, llh[2] - ground);
  if (margin < -1e-3 && std::getenv("VTKGLOBE_TEST_VERBOSE"))
  {
    std::printf("    %s: %.3f m below the margin at (%.6f, %.6f)\n",
      vtkCommand::GetStringFromEventId(event), -margin, llh[0], llh[1]);
  }
  // Roll: the right vector against the local up.
  double east[3], north[3], up[3], view[3], right[3];
  c->Scene->Body->ComputeEastNorthUp(llh[0], llh[1], east, north, up);
  for (int i = 0; i < 3; ++i)
  {
    view[i] = focal[i] - eye[i];
  }
  vtkMath::Normalize(view);
  vtkMath::Normalize(viewUp);
  vtkMath::Cross(view, viewUp, right);
  vtkMath::Normalize(right);
  s.WorstRoll = std::max(s.WorstRoll, std::abs(vtkMath::Dot(right, up)));
  // atan2 of sine and cosine: acos of a cosine within an ulp of 1 resolves no angle below
  // 1.5e-8 rad (8.5e-7 degrees), too coarse for the nadir check below.
  double across[3];
  vtkMath::Cross(view, up, across);
  const double tilt =
    vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(across), -vtkMath::Dot(view, up)));
  s.MinTilt = std::min(s.MinTilt, tilt);
  s.MaxTilt = std::max(s.MaxTilt, tilt);
  if (tilt > 1.0)
  {
    double projection[3];
    const double along = vtkMath::Dot(up, view);
    for (int i = 0; i < 3; ++i)
    {
      projection[i] = up[i] - along * view[i];
    }
    vtkMath::Normalize(projection);
    double d[3] = { viewUp[0] - projection[0], viewUp[1] - projection[1],
      viewUp[2] - projection[2] };
    s.WorstUp = std::max(s.WorstUp, vtkMath::Norm(d));
  }
  if (event == vtkCommand::CharEvent)
  {
    ++s.Keys;
    const char key = c->Interactor->GetKeyCode();
    if (std::getenv("VTKGLOBE_TEST_VERBOSE"))
    {
      std::printf("    key %d (%c) tilt %.3f\n", key, key, tilt);
    }
    if (key == 'u')
    {
      s.WorstNadir = std::max(s.WorstNadir, tilt);
    }
    else if (key == 'n')
    {
      // Tilted: the heading of the view; at the nadir: where the screen's up points.
      const double heading = std::atan2(vtkMath::Dot(viewUp, east), vtkMath::Dot(viewUp, north));
      s.WorstHeading = std::max(s.WorstHeading, std::abs(vtkMath::DegreesFromRadians(heading)));
    }
  }
  const int* pos = c->Interactor->GetEventPosition();
  if (event == vtkCommand::InteractionEvent && c->Style->GetGrabbing())
  {
    ++s.GrabMoves;
    if (!c->Style->GetLastMoveExact())
    {
      ++s.InexactGrabMoves;
    }
    else
    {
      double p[3];
      Project(renderer, c->Style->GetGrabbedPoint(), p);
      s.WorstGrab = std::max(s.WorstGrab, std::hypot(p[0] - pos[0], p[1] - pos[1]));
    }
  }
  const bool wheel =
    event == vtkCommand::MouseWheelForwardEvent || event == vtkCommand::MouseWheelBackwardEvent;
  if (wheel && c->Style->GetZoomTargetValid())
  {
    ++s.ZoomNotches;
    if (!c->Style->GetLastMoveExact())
    {
      ++s.InexactZooms;
    }
    else
    {
      double p[3];
      Project(renderer, c->Style->GetZoomTarget(), p);
      s.WorstZoom = std::max(s.WorstZoom, std::hypot(p[0] - pos[0], p[1] - pos[1]));
    }
  }
}

// Plays a stream on a scene whose camera is placed; prints and checks the statistics.
bool Walk(const char* name, vtkGlobeTest::Scene& scene, const std::string& stream, bool setMapper)
{
  vtkNew<vtkGlobeInteractorStyle> style;
  if (setMapper)
  {
    style->SetMapper(scene.Mapper);
  }
  // A generic interactor: no X events, no Initialize()/Start(); the window stays offscreen and
  // Enable() lets the style's Render() calls through.
  vtkNew<vtkGenericRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(scene.Window);
  interactor->SetInteractorStyle(style);
  interactor->Enable();
  scene.Render();

  Context context;
  context.Scene = &scene;
  context.Style = style;
  context.Interactor = interactor;
  context.Layers = vtkGlobeTest::HeightLayers(scene.Mapper);
  vtkNew<vtkCallbackCommand> check;
  check->SetCallback(Check);
  check->SetClientData(&context);
  // After the style (lower priority runs later) for the events it does not grab (wheel, keys,
  // presses); a drag's moves go to the style alone (it grabs the focus, as VTK's styles do),
  // which reports each step with an InteractionEvent.
  const unsigned long tag = interactor->AddObserver(vtkCommand::AnyEvent, check, -10.0f);
  style->AddObserver(vtkCommand::InteractionEvent, check);

  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(interactor);
  recorder->ReadFromInputStringOn();
  recorder->SetInputString(stream.c_str());
  const auto start = std::chrono::steady_clock::now();
  recorder->Play();
  recorder->Off();

  // Reset, then the constraints once more.
  const int before = context.S.Events;
  interactor->SetKeyCode('r');
  interactor->InvokeEvent(vtkCommand::CharEvent);
  double eye[3], llh[3];
  scene.Renderer->GetActiveCamera()->GetPosition(eye);
  scene.Body->CartesianToGeodetic(eye, llh);
  interactor->RemoveObserver(tag); // the context dies with this function
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const Stats& s = context.S;
  std::printf("%s: %d events in %.1f s (%d checked after 'r'); tilt %.1f..%.1f degrees\n", name,
    s.Events, seconds, s.Events - before, s.MinTilt, s.MaxTilt);
  std::printf("  height over terrain + %.0f m margin: worst %.3g m (lowest height %.3f m over the "
              "terrain)\n",
    style->GetMinimumHeightAboveTerrain(), s.WorstMargin, s.LowestHeight);
  std::printf("  roll: worst |right . up| %.3g; worst |view-up - up's projection| (tilt > 1 "
              "degree) %.3g\n",
    s.WorstRoll, s.WorstUp);
  std::printf("  grab: %d drag moves, %d inexact (cursor beyond the grabbed sphere or lifted); "
              "worst drift %.3g px\n",
    s.GrabMoves, s.InexactGrabMoves, s.WorstGrab);
  std::printf("  zoom: %d notches on the ground, %d inexact (lifted); worst drift %.3g px\n",
    s.ZoomNotches, s.InexactZooms, s.WorstZoom);
  std::printf("  keys: %d; tilt after 'u' at most %.3g degrees, |heading| after 'n' at most %.3g "
              "degrees\n",
    s.Keys, s.WorstNadir, s.WorstHeading);
  std::printf("  after 'r': %.0f km above the ellipsoid\n", llh[2] / 1000.0);
  const double bodySize = scene.Body->GetMaximumRadius();
  bool ok = true;
  auto require = [&](bool condition, const char* what) {
    if (!condition)
    {
      std::printf("  FAIL %s: %s\n", name, what);
      ok = false;
    }
  };
  require(s.Events > 200, "fewer than 200 events were played");
  require(s.WorstMargin > -1e-3, "the camera went below the terrain plus the margin");
  require(s.WorstRoll < 1e-6, "the camera rolled");
  require(s.WorstUp < 1e-6, "the view-up left the local up's projection");
  require(s.GrabMoves > 50 && s.WorstGrab < 1.0, "a grabbed point left the cursor by 1 px or more");
  require(s.InexactGrabMoves * 10 <= s.GrabMoves, "more than 10 % of the drag moves inexact");
  require(s.ZoomNotches > 30 && s.WorstZoom < 1.0, "a zoom target left the cursor by 1 px or more");
  require(s.InexactZooms * 10 <= s.ZoomNotches, "more than 10 % of the notches inexact");
  require(s.Keys >= 5 && s.WorstNadir < 1e-9, "'u' did not look straight down");
  require(s.WorstHeading < 0.5, "'n' did not turn north up");
  require(s.LowestHeight < 2000.0, "the walk never came near the ground (it tests nothing)");
  require(llh[2] > bodySize, "'r' did not show the whole body");
  return ok;
}
} // namespace

int TestGlobeInteractorStyle(int argc, char* argv[])
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-write-events")
    {
      std::ofstream(argv[i + 1]) << RandomWalk(13, 400);
      std::printf("wrote %s\n", argv[i + 1]);
      return EXIT_SUCCESS;
    }
  }
  bool ok = true;
  {
    // The Earth near Mount Rainier, from the stream kept in the repository.
    const std::string file =
      std::string(VTKGLOBE_DATA_DIR) + "/../Testing/Data/Events/GlobeInteractorEarth.log";
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    if (text.str().size() < 1000)
    {
      std::printf("FAIL cannot read the event stream %s\n", file.c_str());
      return EXIT_FAILURE;
    }
    vtkGlobeTest::Scene scene(Width, Height, 64);
    scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
    scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/mt_rainier_90m.tif", true));
    const double camera[3] = { -121.85, 46.78, 6500.0 }, target[3] = { -121.76, 46.853, 3000.0 };
    scene.Look(camera, target, 40.0);
    ok = Walk("Earth (Rainier)", scene, text.str(), true) && ok;
  }
  {
    // The Moon, with a relief of +-4 km (no height data in the repository for it).
    vtkGlobeTest::Scene scene(Width, Height, 64);
    scene.Body->SetToMoon();
    scene.Mapper->AddLayer(SyntheticHeights([](double lon, double lat) {
      return 3000.0 * std::sin(vtkMath::RadiansFromDegrees(7 * lon)) *
        std::cos(vtkMath::RadiansFromDegrees(5 * lat)) +
        1000.0 * std::cos(vtkMath::RadiansFromDegrees(23 * lon + 11 * lat));
    }));
    const double camera[3] = { 20.0, -10.0, 60000.0 }, target[3] = { 21.0, -9.0, 0.0 };
    scene.Look(camera, target, 40.0);
    ok = Walk("Moon", scene, RandomWalk(2026, 400), false) && ok;
  }
  {
    // A triaxial body (1000 x 800 x 600 km), with a relief of +-2 km.
    vtkGlobeTest::Scene scene(Width, Height, 64);
    scene.Body->SetRadii(1000e3, 800e3, 600e3);
    scene.Mapper->AddLayer(SyntheticHeights([](double lon, double lat) {
      return 2000.0 * std::sin(vtkMath::RadiansFromDegrees(9 * lon + 4 * lat)) *
        std::cos(vtkMath::RadiansFromDegrees(6 * lat));
    }));
    const double camera[3] = { 60.0, 35.0, 40000.0 }, target[3] = { 61.0, 36.0, 0.0 };
    scene.Look(camera, target, 40.0);
    ok = Walk("Triaxial 1000 x 800 x 600 km", scene, RandomWalk(7, 400), false) && ok;
  }
  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
