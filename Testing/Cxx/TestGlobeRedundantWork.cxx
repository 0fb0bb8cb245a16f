// Work done only when needed: textures are uploaded once per layer and again only for the
// layer whose data changed; the shader programs, generated from the active layers, are built
// once and again only when the set of layers composed changes (layers added or removed, or
// culled out of the view or back into it), not for a camera move within the same layers, a grid
// resolution, a light or colour setting. The composition source holds one block per active layer.
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}
} // namespace

int TestGlobeRedundantWork(int, char*[])
{
  vtkGlobeTest::Scene scene;
  scene.AddEarthLayers();
  vtkGlobeLayerSet* layers = scene.Mapper->GetLayerSet();
  vtkGlobeGridPass* grid = scene.Mapper->GetGridPass();
  vtkGlobeCompositePass* composite = scene.Mapper->GetCompositePass();
  // The clipping policy from the start, so the first frames have the far plane (before the
  // horizon) that culls the Everest inset on the far side, as the frames after them do.
  vtkGlobeClippingRange::Install(scene.Renderer);
  const double camera[3] = { -100, 40, 2.0e7 }, target[3] = { -100, 40, 0 };
  scene.Look(camera, target, 30);
  scene.Render();
  const int uploads = layers->GetNumberOfUploads();
  const int gridBuilds = grid->GetNumberOfShaderBuilds();
  const int compositeBuilds = composite->GetNumberOfShaderBuilds();
  std::printf("after two frames: %d uploads, %d grid and %d composite shader builds\n", uploads,
    gridBuilds, compositeBuilds);
  Expect(uploads == 4, "each of the 4 layers uploaded once");
  Expect(gridBuilds == 2 && compositeBuilds == 1, "PGM, height and composite programs built once");
  const std::string source = composite->GetFragmentShaderSource();
  Expect(source.find("globeHeight1") != std::string::npos &&
      source.find("globeHeight2") == std::string::npos &&
      source.find("globeColor0") != std::string::npos &&
      source.find("globeColor1") == std::string::npos && layers->GetNumberOfCulledLayers() == 1,
    "the composition source has one block per composed layer (2 heights: the Everest inset is "
    "culled; 1 colour)");

  // Nothing about the layers changes: no upload, no build (the same layers are in view: all
  // but the Everest inset, on the far side of the body beyond the far plane).
  const double elsewhere[3] = { -60, 10, 2.0e7 }, there[3] = { -60, 10, 0 };
  scene.Look(elsewhere, there, 30);
  scene.Mapper->SetAmbient(0.3);
  scene.Mapper->SetBaseColor(0.2, 0.2, 0.2);
  scene.Mapper->SetGridResolution(128);
  scene.Render();
  scene.Window->Render();
  Expect(layers->GetNumberOfUploads() == uploads,
    "a camera move, light, colour and grid resolution change upload nothing");
  Expect(grid->GetNumberOfShaderBuilds() == gridBuilds &&
      composite->GetNumberOfShaderBuilds() == compositeBuilds && layers->GetNumberOfCulledLayers() == 1,
    vtkGlobeTest::Printf("... and rebuild no shader (%d grid and %d composite builds, %d layers "
                         "culled)", grid->GetNumberOfShaderBuilds(),
      composite->GetNumberOfShaderBuilds(), layers->GetNumberOfCulledLayers()));

  // A move that takes the insets out of the view culls them: the programs without them are
  // built once; back again, the programs with them are built once more (a pass keeps one).
  const double close[3] = { 10, 45, 3.0e5 }, below[3] = { 10, 46, 0 };
  scene.Look(close, below, 40);
  scene.Render();
  const int culled = layers->GetNumberOfCulledLayers();
  Expect(culled == 2 && grid->GetNumberOfShaderBuilds() == gridBuilds + 1 &&
      composite->GetNumberOfShaderBuilds() == compositeBuilds + 1 &&
      layers->GetNumberOfUploads() == uploads,
    vtkGlobeTest::Printf("over the Alps: %d layers culled (the Rainier and Everest insets), "
                         "one more build per generated program, no upload", culled));
  scene.Look(elsewhere, there, 30);
  scene.Render();
  Expect(layers->GetNumberOfCulledLayers() == 1 && grid->GetNumberOfShaderBuilds() == gridBuilds + 2 &&
      composite->GetNumberOfShaderBuilds() == compositeBuilds + 2,
    "back to the whole Earth: Everest culled again (beyond the far plane), each program built "
    "once more");
  const int gridBuildsNow = grid->GetNumberOfShaderBuilds();
  const int compositeBuildsNow = composite->GetNumberOfShaderBuilds();

  // One layer's data changes: that layer alone is uploaded again, nothing is rebuilt.
  scene.Mapper->GetLayer(0)->SetValueScale(2.0);
  scene.Render();
  Expect(layers->GetNumberOfUploads() == uploads + 1, "a changed layer is uploaded again, alone");
  Expect(grid->GetNumberOfShaderBuilds() == gridBuildsNow &&
      composite->GetNumberOfShaderBuilds() == compositeBuildsNow,
    "a changed layer rebuilds no shader");

  // The set of colour layers changes: the composite program, which samples them, is rebuilt
  // once; the grid's height program, which does not, is kept.
  scene.Mapper->RemoveLayer(scene.Mapper->GetLayer(3));
  scene.Render();
  Expect(grid->GetNumberOfShaderBuilds() == gridBuildsNow &&
      composite->GetNumberOfShaderBuilds() == compositeBuildsNow + 1,
    "removing the colour layer rebuilds the composite program once, not the height program");
  // The set of height layers in view changes (the Rainier inset goes): both generated programs
  // are rebuilt once.
  scene.Mapper->RemoveLayer(scene.Mapper->GetLayer(1));
  scene.Render();
  Expect(grid->GetNumberOfShaderBuilds() == gridBuildsNow + 1 &&
      composite->GetNumberOfShaderBuilds() == compositeBuildsNow + 2,
    "removing a height layer rebuilds the height and composite programs once");
  Expect(composite->GetFragmentShaderSource().find("globeColor0") == std::string::npos,
    "the composition source no longer samples a colour layer");

  return Checks.Result();
}
