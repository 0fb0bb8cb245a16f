// Bad input to the globe mapper: no layers; missing, corrupt, non-georeferenced rasters,
// contradictory georeferencing, an extent outside its projection's domain, and a raster of NaN
// among good ones (one of them UTM, one in EPSG:8857, Equal Earth,
// which is reprojected on load); a camera
// at the centre of the body, inside
// it, and at NaN; a viewport without area. Each case: a clear error where it is one, no GL
// error, no NaN in the depth buffer, no crash, and the rest of the scene still renders.
#include "vtkConeSource.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkTestErrorObserver.h"
#include "vtk_glew.h"

#include <fstream>
#include <limits>

namespace
{
// Every error and warning message, from any object observed.
class Collector : public vtkCommand
{
public:
  static Collector* New() { return new Collector; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    if (data)
    {
      this->Messages.emplace_back(static_cast<const char*>(data));
    }
  }
  std::vector<std::string> Messages;
};

vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
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
    vtkNew<Collector> all;
    scene.Mapper->GetLayerSet()->AddObserver(vtkCommand::ErrorEvent, all);
    auto addLayer = [&](vtkSmartPointer<vtkGlobeLayer> layer) {
      layer->AddObserver(vtkCommand::ErrorEvent, all);
      layer->AddObserver(vtkCommand::ErrorEvent, errors);
      layer->AddObserver(vtkCommand::WarningEvent, errors);
      scene.Mapper->AddLayer(layer);
    };
    scene.Mapper->GetLayerSet()->AddObserver(vtkCommand::ErrorEvent, errors);
    scene.Mapper->GetLayerSet()->AddObserver(vtkCommand::WarningEvent, errors);
    addLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
    addLayer(vtkGlobeTest::FileLayer("earth/no_such_file.tif", true));
    addLayer(vtkGlobeTest::FileLayer("README.md", false)); // not an image at all
    addLayer(vtkGlobeTest::FileLayer("earth/mt_rainier_utm10n.tif", true)); // projected, good
    addLayer(vtkGlobeTest::FileLayer("earth/world.tif", false));
    struct Bad
    {
      vtkSmartPointer<vtkGlobeLayer> Layer;
      const char* What;
      std::vector<const char*> Words;
    };
    std::vector<Bad> bad;
    vtkSmartPointer<vtkGlobeLayer> reprojected;
    auto addBad = [&](vtkSmartPointer<vtkGlobeLayer> layer, const char* what,
                    std::vector<const char*> words) {
      addLayer(layer);
      bad.push_back({ layer, what, words });
    };
    {
      const auto grey = [](int, int) { return std::array<unsigned char, 3>{ 200, 200, 200 }; };
      auto equalEarth = vtkSmartPointer<vtkGlobeLayer>::New();
      equalEarth->SetRoleToColor();
      // Equal Earth (EPSG:8857) around (10 E, 52 N).
      equalEarth->SetFileName(
        vtkGlobeTest::WriteWorldFilePNG(
          std::string(VTKGLOBE_TEMP_DIR) + "/equal_earth", 8857, 16, 16, 778000, 6185000, 1000, grey)
          .c_str());
      // Not bad any more: a CRS the GPU does not project is reprojected on load.
      addLayer(equalEarth);
      reprojected = equalEarth;
      auto outside = vtkSmartPointer<vtkGlobeLayer>::New();
      outside->SetRoleToColor();
      outside->SetFileName(
        vtkGlobeTest::WriteWorldFilePNG(
          std::string(VTKGLOBE_TEMP_DIR) + "/utm_far_away", 32610, 16, 16, 5.0e7, 9.0e7, 1000, grey)
          .c_str());
      addBad(outside, "an extent outside its projection's domain", { "utm_far_away.png", "EPSG:32610" });
      auto contradictory = vtkGlobeTest::FileLayer("earth/mt_rainier_utm10n.tif", true);
      contradictory->GetFileReader()->SetEPSG(3413);
      addBad(contradictory, "contradictory georeferencing (tags 32610, asked 3413)",
        { "mt_rainier_utm10n.tif", "3413" });
      auto nans = vtkSmartPointer<vtkGlobeLayer>::New();
      std::vector<float> values(64, std::numeric_limits<float>::quiet_NaN());
      nans->SetHeightData(8, 8, values.data(), 10, 12, 10, 12);
      addBad(nans, "only NaN heights", { "valid" });
    }
    const double camera[3] = { -100, 40, 2.0e7 }, target[3] = { -100, 40, 0 };
    scene.Look(camera, target, 30);
    scene.Render();
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    Expect(errors->GetError(), "the bad layers are reported, e.g. \"" + Reason(errors) + "\"");
    for (const Bad& b : bad)
    {
      // Find the message about this layer among all those reported.
      bool named = false;
      std::string said;
      for (const std::string& message : all->Messages)
      {
        bool all = true;
        for (const char* word : b.Words)
        {
          all &= message.find(word) != std::string::npos;
        }
        if (all)
        {
          named = true;
          const size_t at = message.find("): ");
          said = message.substr(at == std::string::npos ? 0 : at + 3, 160);
          while (!said.empty() && (said.back() == '\n' || said.back() == ' '))
          {
            said.pop_back();
          }
          break;
        }
      }
      Expect(named && !b.Layer->IsValid() == (std::string(b.What).find("NaN") != std::string::npos ||
                        std::string(b.What).find("contradictory") != std::string::npos),
        std::string(b.What) + ": reported with the file and the reason" + (named ? ": " + said : ""));
    }
    Expect(scene.Mapper->GetLayerSet()->GetNumberOfActiveHeightLayers() == 2 &&
        scene.Mapper->GetLayerSet()->GetNumberOfActiveColorLayers() == 2 &&
        reprojected->GetReprojectedFromEPSG() == 8857,
      "the good layers stay active (2 height, one of them UTM; 2 colour, one of them EPSG:8857 "
      "reprojected on load)");
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
  return Checks.Result();
}
