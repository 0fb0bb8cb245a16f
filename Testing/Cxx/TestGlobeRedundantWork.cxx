// Work done only when needed: textures are uploaded once per layer and again only for the
// layer whose data changed; the shader programs, generated from the active layers, are built
// once and again only when the set of layers changes, not for a camera move, a grid resolution,
// a light or colour setting. The composition source holds one block per active layer.
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
  Expect(source.find("globeHeight2") != std::string::npos &&
      source.find("globeHeight3") == std::string::npos &&
      source.find("globeColor0") != std::string::npos &&
      source.find("globeColor1") == std::string::npos,
    "the composition source has one block per active layer (3 heights, 1 colour)");

  // Nothing about the layers changes: no upload, no build.
  const double elsewhere[3] = { 30, -10, 1.0e7 }, there[3] = { 30, -10, 0 };
  scene.Look(elsewhere, there, 40);
  scene.Mapper->SetAmbient(0.3);
  scene.Mapper->SetBaseColor(0.2, 0.2, 0.2);
  scene.Mapper->SetGridResolution(128);
  scene.Render();
  scene.Window->Render();
  Expect(layers->GetNumberOfUploads() == uploads,
    "a camera move, light, colour and grid resolution change upload nothing");
  Expect(grid->GetNumberOfShaderBuilds() == gridBuilds &&
      composite->GetNumberOfShaderBuilds() == compositeBuilds,
    "... and rebuild no shader");

  // One layer's data changes: that layer alone is uploaded again, nothing is rebuilt.
  scene.Mapper->GetLayer(0)->SetValueScale(2.0);
  scene.Render();
  Expect(layers->GetNumberOfUploads() == uploads + 1, "a changed layer is uploaded again, alone");
  Expect(grid->GetNumberOfShaderBuilds() == gridBuilds &&
      composite->GetNumberOfShaderBuilds() == compositeBuilds,
    "a changed layer rebuilds no shader");

  // The set of colour layers changes: the composite program, which samples them, is rebuilt
  // once; the grid's height program, which does not, is kept.
  scene.Mapper->RemoveLayer(scene.Mapper->GetLayer(3));
  scene.Render();
  Expect(grid->GetNumberOfShaderBuilds() == gridBuilds &&
      composite->GetNumberOfShaderBuilds() == compositeBuilds + 1,
    "removing the colour layer rebuilds the composite program once, not the height program");
  // The set of height layers changes: both generated programs are rebuilt once.
  scene.Mapper->RemoveLayer(scene.Mapper->GetLayer(2));
  scene.Render();
  Expect(grid->GetNumberOfShaderBuilds() == gridBuilds + 1 &&
      composite->GetNumberOfShaderBuilds() == compositeBuilds + 2,
    "removing a height layer rebuilds the height and composite programs once");
  Expect(composite->GetFragmentShaderSource().find("globeColor0") == std::string::npos,
    "the composition source no longer samples a colour layer");

  return Checks.Result();
}
