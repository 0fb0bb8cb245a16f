// Interactive detail (Documentation/rendering.md "Interactive detail"): a frame allocated less
// time than the globe's last full-detail frame took (VTK's DesiredUpdateRate, which interactor
// styles raise while the camera moves) is drawn with a grid twice as coarse and without
// terrain refinement; a still render is full detail again. Checked on a close view of Mount
// Rainier, through the window's update rate and through vtkGlobeInteractorStyle's drag:
// - the level follows the allocated time, and AutoAdjustDetailOff keeps full detail;
// - the interactive grid is the automatic grid at twice its pixels per cell (or half the fixed
//   size), and its composition does not refine;
// - the still frame after interactive frames shows exactly (0 px) what the still frames before
//   them showed, and the frames after it the same;
// - after the first switch, switching levels compiles nothing;
// - the interactive picture is the same terrain: coverage and colour close to full detail.
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeInteractorStyle.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkGenericRenderWindowInteractor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace
{
// Mean absolute difference per channel (0..255) over the pixels both frames cover, and the
// pixels one frame covers and the other does not (background black).
void Compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
  double& meanDifference, int& coverageDiffers)
{
  double sum = 0.0;
  long long count = 0;
  coverageDiffers = 0;
  for (size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3)
  {
    const bool inA = a[i] || a[i + 1] || a[i + 2], inB = b[i] || b[i + 1] || b[i + 2];
    if (inA != inB)
    {
      ++coverageDiffers;
    }
    else if (inA)
    {
      for (int k = 0; k < 3; ++k)
      {
        sum += std::abs(static_cast<int>(a[i + k]) - static_cast<int>(b[i + k]));
      }
      count += 3;
    }
  }
  meanDifference = count ? sum / count : 0.0;
}

struct DragLog
{
  vtkGlobeMapper* Mapper = nullptr;
  int Moves = 0;
  int InteractiveMoves = 0;
};

void OnInteraction(vtkObject*, unsigned long, void* data, void*)
{
  auto* log = static_cast<DragLog*>(data);
  ++log->Moves;
  log->InteractiveMoves += log->Mapper->GetLastFrameInteractive() ? 1 : 0;
}
} // namespace

int TestGlobeInteractiveDetail(int, char*[])
{
  vtkGlobeTest::Checklist check;
  const auto Differing = vtkGlobeTest::DifferingPixels;
  const int width = 400, height = 300;
  vtkGlobeTest::Scene scene(width, height);
  scene.AddEarthLayers();
  vtkGlobeMapper* mapper = scene.Mapper;
  mapper->SetGridPixelsPerCell(1.6); // the default automatic grid, not the scenes' fixed one
  const double camera[3] = { -121.86, 46.75, 16000.0 }, target[3] = { -121.7603, 46.8523, 4392.0 };
  vtkGlobeTest::LookAt(scene.Renderer, scene.Body, camera, target, 40.0);
  scene.Renderer->GetActiveCamera()->SetClippingRange(20.0, 4.0e5);
  vtkGlobeCompositePass* composite = mapper->GetCompositePass();

  // Still frames (the window's default rate, 0.0001/s) until the full-detail time is measured.
  bool anyInteractive = false;
  for (int frame = 0; frame < 20 && !(mapper->GetFullDetailTime() > 0.0); ++frame)
  {
    scene.Window->Render();
    anyInteractive = anyInteractive || mapper->GetLastFrameInteractive();
  }
  scene.Window->Render();
  const std::vector<unsigned char> still = vtkGlobeTest::ReadPixels(scene.Window);
  const int fullGrid = mapper->GetGridResolution();
  check.Expect(!anyInteractive && !mapper->GetLastFrameInteractive() &&
      mapper->GetFullDetailTime() > 0.0 && composite->Refines() && fullGrid == 250,
    vtkGlobeTest::Printf("still frames are full detail: grid %d^2 (250^2 at 1.6 px per cell), "
                         "refined %d, full-detail frame %.1f ms (GPU)",
      fullGrid, composite->Refines() ? 1 : 0, 1e3 * mapper->GetFullDetailTime()));

  // A rate no frame can meet: interactive detail.
  scene.Window->SetDesiredUpdateRate(1e6);
  const int builds = composite->GetNumberOfShaderBuilds();
  scene.Window->Render();
  const std::vector<unsigned char> interactive = vtkGlobeTest::ReadPixels(scene.Window);
  const int interactiveGrid = mapper->GetGridResolution();
  check.Expect(mapper->GetLastFrameInteractive() && mapper->GetLastFrameDrewGlobe() &&
      !composite->Refines() && interactiveGrid == 125 &&
      composite->GetNumberOfShaderBuilds() == builds + 1,
    vtkGlobeTest::Printf("allocated %.2g s < %.1f ms: interactive, grid %d^2 (125^2 at 3.2 px per "
                         "cell), refined %d, %d program built",
      scene.Actor->GetAllocatedRenderTime(), 1e3 * mapper->GetFullDetailTime(), interactiveGrid,
      composite->Refines() ? 1 : 0, composite->GetNumberOfShaderBuilds() - builds));
  double mean = 0.0;
  int coverage = 0;
  Compare(still, interactive, mean, coverage);
  check.Expect(mean < 3.0 && coverage <= width * height / 200,
    vtkGlobeTest::Printf("the interactive picture: %d px differ from the still one, mean "
                         "difference %.2f of 255 where both show terrain (< 3), coverage differs "
                         "at %d px (<= 0.5 %%)",
      Differing(still, interactive), mean, coverage));
  for (int frame = 0; frame < 20 && !(mapper->GetInteractiveDetailTime() > 0.0); ++frame)
  {
    scene.Window->Render();
  }
  check.Expect(mapper->GetLastFrameInteractive() && mapper->GetInteractiveDetailTime() > 0.0,
    vtkGlobeTest::Printf("interactive frames measured: %.1f ms (GPU; full detail %.1f ms)",
      1e3 * mapper->GetInteractiveDetailTime(), 1e3 * mapper->GetFullDetailTime()));

  // Back to still: the picture of before, exactly, and the frames after it the same; the
  // levels alternate without a compile.
  int worst = 0;
  bool levels = true;
  for (int round = 0; round < 3; ++round)
  {
    scene.Window->SetDesiredUpdateRate(0.0001);
    scene.Window->Render();
    const bool full = !mapper->GetLastFrameInteractive();
    const std::vector<unsigned char> first = vtkGlobeTest::ReadPixels(scene.Window);
    scene.Window->Render();
    const std::vector<unsigned char> second = vtkGlobeTest::ReadPixels(scene.Window);
    worst = std::max(worst, std::max(Differing(still, first), Differing(first, second)));
    scene.Window->SetDesiredUpdateRate(1e6);
    scene.Window->Render();
    levels = levels && full && mapper->GetLastFrameInteractive() &&
      mapper->GetGridResolution() == interactiveGrid;
  }
  check.Expect(worst == 0 && levels && composite->GetNumberOfShaderBuilds() == builds + 1,
    vtkGlobeTest::Printf("3 rounds still -> interactive: the still frames differ from the first "
                         "still picture at %d px at most (0), levels as allocated %d, programs "
                         "built since the first switch %d (0)",
      worst, levels ? 1 : 0, composite->GetNumberOfShaderBuilds() - builds - 1));

  // AutoAdjustDetailOff: full detail at any rate.
  mapper->AutoAdjustDetailOff();
  scene.Window->Render();
  const std::vector<unsigned char> off = vtkGlobeTest::ReadPixels(scene.Window);
  check.Expect(!mapper->GetLastFrameInteractive() && mapper->GetGridResolution() == fullGrid &&
      Differing(still, off) == 0,
    vtkGlobeTest::Printf("AutoAdjustDetailOff at the same rate: full detail, %d px differ from "
                         "the still picture",
      Differing(still, off)));
  mapper->AutoAdjustDetailOn();

  // A fixed grid is halved (rounded up).
  mapper->SetGridResolution(301);
  scene.Window->Render();
  const int fixedInteractive = mapper->GetGridResolution();
  scene.Window->SetDesiredUpdateRate(0.0001);
  scene.Window->Render();
  check.Expect(fixedInteractive == 151 && mapper->GetGridResolution() == 301,
    vtkGlobeTest::Printf("fixed grid 301^2: %d^2 interactive (151), %d^2 still",
      fixedInteractive, mapper->GetGridResolution()));
  mapper->SetGridPixelsPerCell(1.6);
  scene.Window->Render();

  // Through the globe's interactor style: a drag at a rate the globe cannot meet draws its
  // moves at interactive detail and ends with a full-detail still frame that the next frame
  // repeats.
  vtkNew<vtkGlobeInteractorStyle> style;
  vtkNew<vtkGenericRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(scene.Window);
  interactor->SetInteractorStyle(style);
  interactor->SetDesiredUpdateRate(1e6);
  interactor->Enable();
  DragLog log;
  log.Mapper = mapper;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(OnInteraction);
  observer->SetClientData(&log);
  style->AddObserver(vtkCommand::InteractionEvent, observer);
  interactor->SetEventInformation(200, 150);
  interactor->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  for (int step = 1; step <= 4; ++step)
  {
    interactor->SetEventInformation(200 + 6 * step, 150 + 3 * step);
    interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
  }
  interactor->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
  const bool stillAfterDrag = !mapper->GetLastFrameInteractive();
  const std::vector<unsigned char> afterDrag = vtkGlobeTest::ReadPixels(scene.Window);
  scene.Window->Render();
  const std::vector<unsigned char> next = vtkGlobeTest::ReadPixels(scene.Window);
  check.Expect(log.Moves == 4 && log.InteractiveMoves == 4 && stillAfterDrag &&
      Differing(afterDrag, next) == 0 && Differing(still, afterDrag) > 0,
    vtkGlobeTest::Printf("a drag of %d moves: %d drawn at interactive detail; the release "
                         "renders full detail %d; the next frame differs at %d px (0)",
      log.Moves, log.InteractiveMoves, stillAfterDrag ? 1 : 0, Differing(afterDrag, next)));
  return check.Result();
}
