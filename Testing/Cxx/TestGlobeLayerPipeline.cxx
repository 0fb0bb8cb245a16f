// Layers fed by pipelines in a rendered globe: heights from vtkGlobeRasterReader ->
// vtkImageShiftScale -> vtkGlobeLayer, colour from a second reader -> layer. Changing the
// filter's shift re-uploads exactly one texture (the height layer's), and the depth-
// reconstructed terrain follows: +1000 m raises it by 1000 m and every checked pixel stays
// within its bound of the (shifted) composed data. Modified() on the colour reader re-uploads
// that layer alone; a frame with nothing changed uploads nothing.
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkImageShiftScale.h"

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

/// Mean geodetic height (m) of the depth-reconstructed points of every 4th covered pixel.
double MeanRenderedHeight(vtkGlobeTest::Scene& scene, int& pixels)
{
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const int* size = scene.Window->GetSize();
  double sum = 0.0;
  pixels = 0;
  for (int y = 2; y < size[1]; y += 4)
  {
    for (int x = 2; x < size[0]; x += 4)
    {
      const float d = depth[static_cast<size_t>(y) * size[0] + x];
      double p[3], llh[3];
      if (!(d < 1.0f))
      {
        continue;
      }
      vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, d, p);
      if (scene.Body->CartesianToGeodeticQuiet(p, llh))
      {
        sum += llh[2];
        ++pixels;
      }
    }
  }
  return pixels > 0 ? sum / pixels : NAN;
}
} // namespace

int TestGlobeLayerPipeline(int, char*[])
{
  const std::string data = VTKGLOBE_DATA_DIR;
  vtkGlobeTest::Scene scene;

  vtkNew<vtkGlobeRasterReader> heightReader;
  heightReader->SetFileName((data + "/earth/relief_2deg.tif").c_str());
  vtkNew<vtkImageShiftScale> shift;
  shift->SetInputConnection(heightReader->GetOutputPort());
  shift->SetShift(0.0);
  vtkNew<vtkGlobeLayer> heights;
  heights->SetRoleToHeight();
  heights->SetInputConnection(shift->GetOutputPort());

  vtkNew<vtkGlobeRasterReader> colorReader;
  colorReader->SetFileName((data + "/earth/world.tif").c_str());
  vtkNew<vtkGlobeLayer> colors;
  colors->SetRoleToColor();
  colors->SetInputConnection(colorReader->GetOutputPort());

  scene.Mapper->AddLayer(heights);
  scene.Mapper->AddLayer(colors);
  vtkGlobeLayerSet* set = scene.Mapper->GetLayerSet();

  // 600 km above the Great Plains and the Rockies, looking down.
  const double camera[3] = { -104.0, 40.0, 6.0e5 }, target[3] = { -104.0, 40.0, 0.0 };
  scene.Look(camera, target, 40.0, 1.0e5, 1.0e6);
  scene.Render();
  const int uploads = set->GetNumberOfUploads();
  Expect(uploads == 2 && heights->IsValid() && colors->IsValid(),
    "two pipeline layers, each uploaded once (" + std::to_string(uploads) + " uploads)");
  int pixels = 0;
  const double before = MeanRenderedHeight(scene, pixels);
  const vtkGlobeTest::TerrainCheck check0 = vtkGlobeTest::CheckTerrain(scene, 4);
  Expect(pixels > 2000 && check0.Failures == 0 && check0.NaNs == 0,
    "before: every checked pixel within its bound of the data");

  scene.Render();
  Expect(set->GetNumberOfUploads() == uploads, "a frame with nothing changed uploads nothing");

  shift->SetShift(1000.0);
  scene.Render();
  Expect(set->GetNumberOfUploads() == uploads + 1 && heights->GetNumberOfLoads() == 2 &&
      colors->GetNumberOfLoads() == 1,
    "shift->SetShift(1000): exactly one texture re-uploaded (" +
      std::to_string(set->GetNumberOfUploads() - uploads) + "), the height layer's");
  const double after = MeanRenderedHeight(scene, pixels);
  const vtkGlobeTest::TerrainCheck check1 = vtkGlobeTest::CheckTerrain(scene, 4);
  char text[200];
  std::snprintf(text, sizeof(text),
    "the rendered terrain rose by %.2f m (mean depth-reconstructed height %.1f -> %.1f m over "
    "%d pixels; expected 1000 +- 5)",
    after - before, before, after, pixels);
  Expect(std::abs(after - before - 1000.0) <= 5.0, text);
  Expect(check1.Failures == 0 && check1.NaNs == 0,
    "after: every checked pixel within its bound of the shifted data");

  colorReader->Modified();
  scene.Render();
  Expect(set->GetNumberOfUploads() == uploads + 2 && colors->GetNumberOfLoads() == 2 &&
      heights->GetNumberOfLoads() == 2,
    "colorReader->Modified(): the colour layer alone re-loaded and re-uploaded");

  return Checks.Result();
}
