// A time-varying layer through the pipeline, rendered: a vtkGlobeRasterReader given a series of
// three global images with their dates, and a colour vtkGlobeLayer fed by it that follows its
// UpdateTime (Core.TestGlobeRasterReaderSeries checks the reader and the layer without
// rendering).
// - The rendered globe: at every step the frame equals, pixel for pixel, a globe whose colour
//   layer reads that step's file directly; the steps' frames differ from each other.
// - Uploads: a change of step re-uploads that layer alone (the height layer stays), a time within
//   the same step uploads and reads nothing.
// - Bad steps: a file whose grid differs from the first step's, a missing file: each an error
//   naming the problem; the other steps and the rest of the scene still render.
#include "vtkGlobeErrorTestHelpers.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

const std::string Temp = VTKGLOBE_TEMP_DIR;
const auto& Times = vtkGlobeTest::SeriesTimes;

/// A global w x h PNG with a world file (plate carree, WGS 84 degrees): step k's pattern.
std::string WriteStep(const std::string& name, int k, int w = 64, int h = 32)
{
  const std::string base = Temp + "/" + name;
  const std::string png = vtkGlobeTest::WriteWorldFilePNG(base, 4326, w, h, -180.0, 90.0,
    360.0 / w, [k](int i, int j) {
      return std::array<unsigned char, 3>{ static_cast<unsigned char>((i * 4 + 85 * k) % 256),
        static_cast<unsigned char>((j * 8 + 40 * k) % 256),
        static_cast<unsigned char>(60 + 70 * k) };
    });
  std::remove((base + ".prj").c_str()); // a world file in degrees: WGS 84
  vtkGlobeTest::WriteGlobalWorldFile(base + ".pgw", w, h);
  return png;
}

/// The number of bytes that differ between two frames.
int Differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  int n = a.size() == b.size() ? 0 : static_cast<int>(std::max(a.size(), b.size()));
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    n += a[i] != b[i] ? 1 : 0;
  }
  return n;
}

} // namespace

int TestGlobeTimeSeries(int, char*[])
{
  const std::string steps[3] = { WriteStep("series_a", 0), WriteStep("series_b", 1),
    WriteStep("series_c", 2) };

  vtkNew<vtkGlobeRasterReader> reader;
  vtkGlobeTest::AddSeriesOutOfOrder(reader, steps);
  vtkGlobeTest::ExecutionCounter executions(reader);

  // A colour layer fed by the series, over static heights, against a globe reading each step's
  // file directly.
  vtkGlobeTest::Scene scene(240, 180);
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
  vtkNew<vtkGlobeLayer> series;
  series->SetRoleToColor();
  series->SetInputConnection(reader->GetOutputPort());
  scene.Mapper->AddLayer(series);
  vtkGlobeLayer* heights = scene.Mapper->GetLayer(0);
  vtkGlobeTest::Scene reference(240, 180);
  reference.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
  vtkNew<vtkGlobeLayer> direct;
  direct->SetRoleToColor();
  reference.Mapper->AddLayer(direct);
  const double camera[3] = { 20.0, 10.0, 2.0e7 }, target[3] = { 20.0, 10.0, 0.0 };
  scene.Look(camera, target, 40.0);
  reference.Look(camera, target, 40.0);
  auto expected = [&](int step) {
    direct->SetFileName(steps[step].c_str());
    reference.Render();
    return vtkGlobeTest::ReadPixels(reference.Window);
  };
  const std::vector<unsigned char> frames[3] = { expected(0), expected(1), expected(2) };
  Expect(Differing(frames[0], frames[1]) > 10000 && Differing(frames[1], frames[2]) > 10000,
    vtkGlobeTest::Printf("the steps' frames differ (%d and %d bytes)", Differing(frames[0], frames[1]),
      Differing(frames[1], frames[2])));

  vtkGlobeLayerSet* set = scene.Mapper->GetLayerSet();
  series->SetUpdateTime(0.0); // before the first step: the first step
  scene.Render();
  int uploads = set->GetNumberOfUploads();
  vtkMTimeType heightData = heights->GetData() ? heights->GetData()->GetMTime() : 0;
  Expect(uploads == 2 && series->GetDataTime() == Times[0] &&
      Differing(vtkGlobeTest::ReadPixels(scene.Window), frames[0]) == 0,
    vtkGlobeTest::Printf("time 0: step 1 (data time %.2f), %d uploads, the frame is step 1's "
                         "(%d bytes differ)",
      series->GetDataTime(), uploads, Differing(vtkGlobeTest::ReadPixels(scene.Window), frames[0])));
  struct Move
  {
    double Time;
    int Step;
    int Uploads; // of the series layer
    int Reads;
  };
  const Move moves[] = { { 2026.3, 1, 1, 1 }, { 2026.4, 1, 0, 0 }, { 2026.25, 1, 0, 0 },
    { 2031.0, 2, 1, 1 }, { 2026.1, 0, 1, 1 } };
  for (const auto& m : moves)
  {
    const int loads = series->GetNumberOfLoads(), runs = executions.Count;
    series->SetUpdateTime(m.Time);
    scene.Render();
    const int diff = Differing(vtkGlobeTest::ReadPixels(scene.Window), frames[m.Step]);
    const int uploaded = set->GetNumberOfUploads() - uploads;
    uploads = set->GetNumberOfUploads();
    const bool heightsKept = heights->GetData() && heights->GetData()->GetMTime() == heightData;
    Expect(diff == 0 && uploaded == m.Uploads && series->GetNumberOfLoads() - loads == m.Reads &&
        executions.Count - runs == m.Reads && series->GetDataTime() == Times[m.Step] && heightsKept,
      vtkGlobeTest::Printf("time %.2f: step %d, %d upload(s), %d read(s) by the reader, the "
                           "frame is the step's (%d bytes differ), heights not reloaded",
        m.Time, m.Step + 1, uploaded, executions.Count - runs, diff));
  }

  // Bad series.
  vtkNew<vtkTest::ErrorObserver> errors;
  const std::string coarse = WriteStep("series_coarse", 1, 32, 16);
  const std::string missing = Temp + "/series_missing.png";
  std::remove(missing.c_str());
  vtkNew<vtkGlobeRasterReader> bad;
  bad->AddObserver(vtkCommand::ErrorEvent, errors);
  bad->AddFileName(steps[0].c_str());
  bad->AddFileName(coarse.c_str());
  bad->AddFileName(missing.c_str());
  series->SetInputConnection(bad->GetOutputPort());
  vtkNew<vtkTest::ErrorObserver> layerErrors;
  series->AddObserver(vtkCommand::ErrorEvent, layerErrors);
  heights->AddObserver(vtkCommand::ErrorEvent, layerErrors);
  series->SetUpdateTime(0.0);
  scene.Render();
  Expect(series->IsValid() && series->GetDataTime() == 0.0 && !errors->GetError() &&
      Differing(vtkGlobeTest::ReadPixels(scene.Window), frames[0]) == 0,
    "a series without times: step 0 at time 0, the frame is the first file's");
  series->SetUpdateTime(1.0);
  scene.Render();
  const bool coarseSaid = vtkGlobeTest::ErrorSaid(errors,
    { "series_coarse", "does not match the first step", "series_a", "32 x 16", "not 64 x 32" });
  layerErrors->Clear();
  Expect(coarseSaid && !series->IsValid() && heights->IsValid() &&
      vtkGlobeTest::CoveredPixels(vtkGlobeTest::ReadDepth(scene.Window)) > 10000,
    "a step whose grid differs: an error naming both files and the sizes; the layer is invalid, "
    "the heights and the globe still render");
  series->SetUpdateTime(2.0);
  scene.Render();
  Expect(vtkGlobeTest::ErrorSaid(errors, { "series_missing", "does not exist" }) &&
      !series->IsValid() &&
      vtkGlobeTest::CoveredPixels(vtkGlobeTest::ReadDepth(scene.Window)) > 10000,
    "a missing file: an error naming it; the globe still renders");
  layerErrors->Clear();
  series->SetUpdateTime(0.5);
  scene.Render();
  Expect(series->IsValid() && series->GetDataTime() == 0.0 &&
      Differing(vtkGlobeTest::ReadPixels(scene.Window), frames[0]) == 0,
    "back to step 0: valid again, the first file's frame");
  return Checks.Result();
}
