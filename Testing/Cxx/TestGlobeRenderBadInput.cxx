// Bad input to the globe mapper: no layers; missing, corrupt, non-georeferenced and
// unsupported-projection rasters among good ones; a camera at the centre of the body, inside
// it, and at NaN; a viewport without area. Each case: a clear error where it is one, no GL
// error, no NaN in the depth buffer, no crash, and the rest of the scene still renders.
#include "vtkConeSource.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkPolyDataMapper.h"
#include "vtkTestErrorObserver.h"
#include "vtk_glew.h"

#include <fstream>
#include <limits>

namespace
{
int Failures = 0;

void Expect(bool condition, const std::string& what)
{
  std::printf("  %-4s %s\n", condition ? "ok" : "FAIL", what.c_str());
  Failures += condition ? 0 : 1;
}

bool NoNaN(const std::vector<float>& depth)
{
  for (float d : depth)
  {
    if (std::isnan(d))
    {
      return false;
    }
  }
  return true;
}

/// The text of an error message after VTK's "ERROR: In file, line N\nclass (address): ".
std::string Reason(vtkTest::ErrorObserver* observer)
{
  const std::string m = observer->GetErrorMessage();
  const size_t at = m.find("): ");
  std::string reason = at == std::string::npos ? m : m.substr(at + 3);
  while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' '))
  {
    reason.pop_back();
  }
  return reason.substr(0, 110);
}

bool NoGLError()
{
  bool clean = true;
  while (glGetError() != GL_NO_ERROR)
  {
    clean = false;
  }
  return clean;
}
} // namespace

int TestGlobeRenderBadInput(int, char*[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  {
    std::printf("No layers:\n");
    vtkGlobeTest::Scene scene;
    const double camera[3] = { 0, 20, 2.0e7 }, target[3] = { 0, 20, 0 };
    scene.Look(camera, target, 30);
    scene.Render();
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    Expect(vtkGlobeTest::CoveredPixels(depth) > 5000 && NoNaN(depth) && NoGLError(),
      "a plain ellipsoid renders");
  }
  {
    std::printf("Broken layers among good ones:\n");
    const std::string temp = std::string(VTKGLOBE_DATA_DIR) + "/../build-temporary-not-here";
    vtkGlobeTest::Scene scene;
    vtkNew<vtkTest::ErrorObserver> errors;
    auto addLayer = [&](vtkSmartPointer<vtkGlobeLayer> layer) {
      layer->AddObserver(vtkCommand::ErrorEvent, errors);
      layer->AddObserver(vtkCommand::WarningEvent, errors);
      scene.Mapper->AddLayer(layer);
    };
    scene.Mapper->GetLayerSet()->AddObserver(vtkCommand::ErrorEvent, errors);
    scene.Mapper->GetLayerSet()->AddObserver(vtkCommand::WarningEvent, errors);
    addLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
    addLayer(vtkGlobeTest::FileLayer("earth/no_such_file.tif", true));
    addLayer(vtkGlobeTest::FileLayer("README.md", false)); // not an image at all
    addLayer(vtkGlobeTest::FileLayer("earth/mt_rainier_utm10n.tif", true)); // projected
    addLayer(vtkGlobeTest::FileLayer("earth/world.tif", false));
    const double camera[3] = { -100, 40, 2.0e7 }, target[3] = { -100, 40, 0 };
    scene.Look(camera, target, 30);
    scene.Render();
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    Expect(errors->GetError(), "the bad layers are reported, e.g. \"" + Reason(errors) + "\"");
    Expect(scene.Mapper->GetLayerSet()->GetNumberOfActiveHeightLayers() == 1 &&
        scene.Mapper->GetLayerSet()->GetNumberOfActiveColorLayers() == 1,
      "the good layers stay active (1 height, 1 colour)");
    Expect(vtkGlobeTest::CoveredPixels(depth) > 5000 && NoNaN(depth) && NoGLError(),
      "the globe still renders");
  }

  // Cameras the mapper cannot draw from; a cone in the scene must still render.
  struct BadCamera
  {
    const char* Name;
    double Position[3];
    bool ExpectError;
    const char* Words;
  };
  const BadCamera cameras[] = { { "at the centre of the body", { 0, 0, 0 }, true, "centre" },
    { "inside the body, 1000 km deep", { 5.378e6, 0, 0 }, false, "" },
    { "at NaN", { nan, 0, 0 }, true, "not finite" } };
  for (const BadCamera& c : cameras)
  {
    std::printf("Camera %s:\n", c.Name);
    vtkGlobeTest::Scene scene;
    scene.AddEarthLayers(true, false);
    vtkNew<vtkTest::ErrorObserver> errors;
    scene.Mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkNew<vtkConeSource> cone;
    cone->SetCenter(c.Position[0] + 1000.0, 0, 0);
    if (std::isnan(c.Position[0]))
    {
      cone->SetCenter(7.0e6, 0, 0);
    }
    cone->SetHeight(200.0);
    cone->SetRadius(100.0);
    cone->SetDirection(-1, 0, 0);
    vtkNew<vtkPolyDataMapper> coneMapper;
    coneMapper->SetInputConnection(cone->GetOutputPort());
    vtkNew<vtkActor> coneActor;
    coneActor->SetMapper(coneMapper);
    scene.Renderer->AddActor(coneActor);
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    if (std::isnan(c.Position[0]))
    {
      camera->SetPosition(6.0e6, 0, 0);
      camera->SetFocalPoint(7.0e6, 0, 0);
      camera->SetClippingRange(1.0, 1.0e7);
      scene.Window->Render(); // a good frame first
      camera->SetPosition(c.Position);
    }
    else
    {
      camera->SetPosition(c.Position);
      camera->SetFocalPoint(c.Position[0] + 1000.0, 0, 0);
      camera->SetViewUp(0, 0, 1);
      camera->SetClippingRange(1.0, 1.0e7);
    }
    scene.Window->Render();
    scene.Window->Render();
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    if (c.ExpectError)
    {
      Expect(errors->GetError() && errors->GetErrorMessage().find(c.Words) != std::string::npos,
        "reported: \"" + Reason(errors) + "\"");
      // Reported once, not every frame.
      errors->Clear();
      scene.Window->Render();
      Expect(!errors->GetError(), "not reported again on the next frame");
    }
    Expect(NoNaN(depth) && NoGLError(), "no NaN depth, no GL error");
    if (!std::isnan(c.Position[0]))
    {
      Expect(vtkGlobeTest::CoveredPixels(depth) > 0, "the cone in front of the camera renders");
    }
  }

  {
    std::printf("A viewport without area, and a 1x1 window:\n");
    vtkGlobeTest::Scene scene;
    scene.AddEarthLayers();
    scene.Renderer->SetViewport(0.5, 0.5, 0.5, 0.5);
    const double camera[3] = { 0, 20, 2.0e7 }, target[3] = { 0, 20, 0 };
    scene.Look(camera, target, 30);
    scene.Render();
    Expect(NoGLError(), "no GL error with an empty viewport");
    scene.Renderer->SetViewport(0, 0, 1, 1);
    scene.Window->SetSize(1, 1);
    scene.Render();
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    Expect(NoNaN(depth) && NoGLError(), "a 1x1 window renders without NaN or GL error");
  }
  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? 0 : 1;
}
