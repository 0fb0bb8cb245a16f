// Per-frame layer culling (issue "Cost proportional to what the frame shows"): layers out of
// the view frustum are left out of the generated programs.
//  A. Close to Rainier (the relief, the Rainier inset and its UTM twin on screen), with 16
//     height insets and 4 colour insets in Asia and a UTM 33N inset in Europe off screen:
//     exactly those 21 are culled; the global layers and the on-screen insets are not.
//  B. The same frame with culling off is the same picture: 0 pixels and 0 depth values differ.
//  C. Looking at the Asian insets instead, none of them is culled, and again culling changes
//     no pixel. The composed counts say which layers the frames drew: culling off composes
//     all of them.
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include <cstdio>

namespace
{
vtkGlobeTest::Checklist Check;

// A small in-memory height inset: a 1 x 1 degree dome of `top` metres at (lon, lat).
vtkSmartPointer<vtkGlobeLayer> Dome(double lon, double lat, double top)
{
  const int n = 32;
  std::vector<float> h(n * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = (i + 0.5) / n - 0.5, y = (j + 0.5) / n - 0.5;
      h[j * n + i] = static_cast<float>(top * std::max(0.0, 1.0 - 4.0 * (x * x + y * y)));
    }
  }
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetHeightData(n, n, h.data(), lon - 0.5, lon + 0.5, lat - 0.5, lat + 0.5);
  return layer;
}

vtkSmartPointer<vtkGlobeLayer> Paint(double lon, double lat)
{
  const int n = 8;
  std::vector<unsigned char> rgb(n * n * 3, 200);
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetColorData(n, n, 3, rgb.data(), lon - 1.0, lon + 1.0, lat - 1.0, lat + 1.0);
  return layer;
}

// Renders with culling on, then off; returns culling on's counts (culled, composed height and
// colour layers) and the number of differing pixels and depths.
void Compare(vtkGlobeTest::Scene& scene, int& culled, int& pixels, int& depths, int& heights,
  int& colours)
{
  vtkGlobeLayerSet* set = scene.Mapper->GetLayerSet();
  set->LayerCullingOn();
  scene.Render();
  scene.Render(); // settled: the reduction of a frame shapes the next (issue 19's flicker)
  culled = set->GetNumberOfCulledLayers();
  heights = set->GetNumberOfComposedLayers(vtkGlobeLayer::Height);
  colours = set->GetNumberOfComposedLayers(vtkGlobeLayer::Color);
  const auto imageOn = vtkGlobeTest::ReadPixels(scene.Window);
  const auto depthOn = vtkGlobeTest::ReadDepth(scene.Window);
  set->LayerCullingOff();
  scene.Render();
  Check.Expect(set->GetNumberOfCulledLayers() == 0 &&
      set->GetNumberOfComposedLayers(vtkGlobeLayer::Height) == 20 &&
      set->GetNumberOfComposedLayers(vtkGlobeLayer::Color) == 6,
    "culling off: nothing culled, all 20 height and 6 colour layers composed");
  const auto imageOff = vtkGlobeTest::ReadPixels(scene.Window);
  const auto depthOff = vtkGlobeTest::ReadDepth(scene.Window);
  set->LayerCullingOn();
  vtkGlobeTest::CountDifferences(imageOn, depthOn, imageOff, depthOff, pixels, depths);
}
} // namespace

int TestGlobeLayerCulling(int, char*[])
{
  vtkGlobeTest::Scene scene(400, 300);
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/mt_rainier_90m.tif", true));
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/mt_rainier_utm10n.tif", true));
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/world.tif", false));
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/world_north_polar_3413.tif", false));
  for (int k = 0; k < 16; ++k)
  {
    scene.Mapper->AddLayer(Dome(100.0 + 2.0 * (k % 4), 30.0 + 2.0 * (k / 4), 3000.0));
  }
  for (int k = 0; k < 4; ++k)
  {
    scene.Mapper->AddLayer(Paint(101.0 + 2.0 * k, 31.0));
  }
  scene.Mapper->AddLayer(vtkGlobeTest::ProjectedHeights(32633, 20, 20, 400000.0, 5.4e6, 5000.0,
    [](int, int) { return 500.0f; }));

  std::printf("A/B. Close to Rainier:\n");
  const double camera[3] = { -121.86, 46.75, 16000.0 }, target[3] = { -121.7603, 46.8523, 4392.0 };
  scene.Look(camera, target, 40.0, 100.0, 1.0e6);
  int culled = 0, pixels = 0, depths = 0, heights = 0, colours = 0;
  Compare(scene, culled, pixels, depths, heights, colours);
  Check.Expect(culled == 21 && heights == 3 && colours == 2,
    vtkGlobeTest::Printf("%d layers culled (16 height and 4 colour insets in Asia, 1 UTM 33N "
                         "inset in Europe); composed: %d height (the relief and the two Rainier "
                         "insets), %d colour (the imagery and the polar cap)",
      culled, heights, colours));
  Check.Expect(pixels == 0 && depths == 0,
    vtkGlobeTest::Printf("culling off draws the same frame: %d pixels, %d depth values differ",
      pixels, depths));

  std::printf("C. Looking at the Asian insets:\n");
  const double asia[3] = { 104.0, 26.0, 8.0e5 }, insets[3] = { 104.0, 33.0, 0.0 };
  scene.Look(asia, insets, 50.0);
  Compare(scene, culled, pixels, depths, heights, colours);
  Check.Expect(culled <= 3 && heights >= 17 && colours >= 5,
    vtkGlobeTest::Printf("%d layers culled (the two Rainier insets and the UTM 33N inset may "
                         "be; none of the 20 Asian insets): %d height and %d colour composed",
      culled, heights, colours));
  Check.Expect(pixels == 0 && depths == 0,
    vtkGlobeTest::Printf("culling off draws the same frame: %d pixels, %d depth values differ",
      pixels, depths));
  Check.Expect(vtkGlobeTest::NoGLError(), "no GL error");
  return Check.Result();
}
