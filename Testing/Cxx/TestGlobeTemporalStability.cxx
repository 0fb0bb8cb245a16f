// The first frame after a camera move is final (issue 19, Documentation/rendering.md "The first
// frame after a move"): the frames after it, with the camera still, show the same pixels. The
// grid's primary sphere is the lowest visible terrain, a GPU reduction; a frame of a new view
// reads its own back and casts the grid again when it asks for another sphere, and frames of
// one view keep their sphere while the reduction stays in a band, so no frame changes the
// picture of the one before it. Close views of Mount Rainier and Everest (ridges at grazing
// angles, where the grid's samples move most with the sphere), after small moves, a turn, a
// jump and the first frame; 0 pixels may differ between frames 1, 2 and 3 after each.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include <algorithm>
#include <cstdio>

int TestGlobeTemporalStability(int, char*[])
{
  vtkGlobeTest::Checklist check;
  vtkGlobeTest::Scene scene(400, 300);
  scene.AddEarthLayers();
  struct View
  {
    const char* Name;
    double Camera[3];
    double Target[3];
  };
  // lon, lat, height (m): one after the other, each a move from the last.
  const View views[] = {
    { "Rainier, first frame", { -121.86, 46.75, 16000.0 }, { -121.7603, 46.8523, 4392.0 } },
    { "Rainier, 200 m closer", { -121.858, 46.752, 15800.0 }, { -121.7603, 46.8523, 4392.0 } },
    { "Rainier, turned", { -121.858, 46.752, 15800.0 }, { -121.70, 46.90, 2000.0 } },
    { "Rainier, low over the valley", { -121.80, 46.70, 2500.0 }, { -121.7603, 46.8523, 4392.0 } },
    { "Everest, a jump", { 86.80, 27.90, 9500.0 }, { 86.925, 27.9881, 8848.0 } },
    { "Everest, 50 m lower", { 86.80, 27.90, 9450.0 }, { 86.925, 27.9881, 8848.0 } },
  };
  int worst = 0;
  for (const View& view : views)
  {
    vtkGlobeTest::LookAt(scene.Renderer, scene.Body, view.Camera, view.Target, 40.0);
    scene.Renderer->GetActiveCamera()->SetClippingRange(20.0, 4.0e5);
    const int recasts = scene.Mapper->GetNumberOfRecasts();
    scene.Window->Render();
    const std::vector<unsigned char> first = vtkGlobeTest::ReadPixels(scene.Window);
    scene.Window->Render();
    const std::vector<unsigned char> second = vtkGlobeTest::ReadPixels(scene.Window);
    scene.Window->Render();
    const std::vector<unsigned char> third = vtkGlobeTest::ReadPixels(scene.Window);
    const int d12 = vtkGlobeTest::DifferingPixels(first, second);
    const int d23 = vtkGlobeTest::DifferingPixels(second, third);
    worst = std::max(worst, std::max(d12, d23));
    check.Expect(d12 == 0 && d23 == 0 && scene.Mapper->GetLastFrameDrewGlobe(),
      vtkGlobeTest::Printf("%-30s frame 1 -> 2: %d px differ, 2 -> 3: %d px (%d recast)",
        view.Name, d12, d23, scene.Mapper->GetNumberOfRecasts() - recasts));
  }
  std::printf("worst: %d px of %d; %d frames read their reduction back at once, %d recast\n",
    worst, 400 * 300, scene.Mapper->GetNumberOfSynchronousReductions(),
    scene.Mapper->GetNumberOfRecasts());
  return check.Result();
}
