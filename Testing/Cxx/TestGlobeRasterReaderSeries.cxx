// vtkGlobeRasterReader given a series of files (AddFileName), and a vtkGlobeLayer fed by it,
// without rendering (so that the sanitizer subset covers them; Rendering.TestGlobeTimeSeries
// renders the same through the globe).
// - Three global 8 x 4 float TIFFs with world files, given out of order with their times: the
//   reader announces TIME_STEPS and TIME_RANGE in time order.
// - Each requested time reads the last step at or before it (the first before them all):
//   its file (GlobeFileName), its values and DATA_TIME_STEP, the step's own time.
// - The same time again runs nothing; another time within the step last read runs the reader
//   but gives the same arrays (nothing decoded).
// - Files without times are steps 0, 1, 2, or the dates their names hold (decimal years, leap
//   years counted) when every name holds one; a single file announces no time.
// - The layer follows UpdateTime by the step's own time: another time within a step loads
//   nothing, a new step loads once; GetDataTime is the step's time.
// - Refused, each with an error that names the problem: times for some files only, two files
//   at one time, a NaN time.
#include "vtkGlobeErrorTestHelpers.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

const std::string Temp = VTKGLOBE_TEMP_DIR;
const auto& Times = vtkGlobeTest::SeriesTimes;

/// A global 8 x 4 float TIFF with a world file: step k holds 100 k + 0 .. 31.
std::string WriteStep(const std::string& name, int k)
{
  const int w = 8, h = 4;
  const std::string path = Temp + "/" + name + ".tif";
  auto out = OIIO::ImageOutput::create(path);
  std::vector<float> values(w * h);
  for (int n = 0; n < w * h; ++n)
  {
    values[n] = static_cast<float>(100 * k + n);
  }
  if (!out || !out->open(path, OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::FLOAT)) ||
    !out->write_image(OIIO::TypeDesc::FLOAT, values.data()) || !out->close())
  {
    std::printf("cannot write %s\n", path.c_str());
  }
  vtkGlobeTest::WriteGlobalWorldFile(Temp + "/" + name + ".tfw", w, h);
  return path;
}

/// What the reader's output is after an update at `time`.
struct Output
{
  std::string File;
  double DataTime = NAN;
  double Range[2] = { NAN, NAN };
  vtkDataArray* Values = nullptr;
};

Output ReadAt(vtkGlobeRasterReader* reader, double time)
{
  reader->UpdateTimeStep(time);
  Output o;
  vtkImageData* image = reader->GetOutput();
  auto* names = vtkStringArray::SafeDownCast(
    image->GetFieldData()->GetAbstractArray(vtkGlobeRasterReader::GetFileNameArrayName()));
  o.File = names && names->GetNumberOfValues() > 0 ? names->GetValue(0) : "";
  if (image->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    o.DataTime = image->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP());
  }
  o.Values = image->GetPointData()->GetScalars();
  if (o.Values)
  {
    o.Values->GetRange(o.Range);
  }
  return o;
}

} // namespace

int TestGlobeRasterReaderSeries(int, char*[])
{
  const std::string steps[3] = { WriteStep("series_core_a", 0), WriteStep("series_core_b", 1),
    WriteStep("series_core_c", 2) };

  vtkNew<vtkGlobeRasterReader> reader;
  vtkGlobeTest::AddSeriesOutOfOrder(reader, steps);
  vtkGlobeTest::ExecutionCounter executions(reader);
  reader->UpdateInformation();
  vtkInformation* info = reader->GetOutputInformation(0);
  const int n = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* t = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* range = info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  Expect(n == 3 && t && t[0] == Times[0] && t[1] == Times[1] && t[2] == Times[2] && range &&
      range[0] == Times[0] && range[1] == Times[2] && reader->GetNumberOfFileNames() == 3 &&
      std::string(reader->GetSeriesFileName(0)) == steps[2] && !reader->GetSeriesFileName(3),
    vtkGlobeTest::Printf("TIME_STEPS in time order: %d steps (%.2f, %.2f, %.2f), range %.2f..%.2f",
      n, n > 0 ? t[0] : NAN, n > 1 ? t[1] : NAN, n > 2 ? t[2] : NAN, range ? range[0] : NAN,
      range ? range[1] : NAN));
  struct Request
  {
    double Time;
    int Step;
  };
  const Request requests[] = { { 2025.0, 0 }, { 2026.0, 0 }, { 2026.2, 0 }, { 2026.25, 1 },
    { 2026.3, 1 }, { 2026.5, 2 }, { 2030.0, 2 } };
  for (const auto& r : requests)
  {
    const Output o = ReadAt(reader, r.Time);
    Expect(o.File == steps[r.Step] && o.DataTime == Times[r.Step] &&
        o.Range[0] == 100.0 * r.Step && o.Range[1] == 100.0 * r.Step + 31,
      vtkGlobeTest::Printf("time %.2f reads step %d (%s, DATA_TIME_STEP %.2f, values %g..%g)",
        r.Time, r.Step, o.File.substr(o.File.rfind('/') + 1).c_str(), o.DataTime, o.Range[0],
        o.Range[1]));
  }
  const int executed = executions.Count;
  const Output before = ReadAt(reader, 2030.0);
  Expect(executions.Count == executed,
    vtkGlobeTest::Printf("the same time again runs nothing (%d runs before, %d after)", executed,
      executions.Count));
  const vtkMTimeType valuesTime = before.Values ? before.Values->GetMTime() : 0;
  const Output within = ReadAt(reader, 2026.6);
  Expect(executions.Count == executed + 1 && before.Values && within.Values == before.Values &&
      within.Values->GetMTime() == valuesTime && within.DataTime == Times[2],
    "another time within the step last read: the reader runs, and gives the same arrays "
    "(nothing decoded)");

  // Without times: positions; one file: no time.
  {
    vtkNew<vtkGlobeRasterReader> plain;
    plain->AddFileName(steps[1].c_str());
    plain->AddFileName(steps[0].c_str());
    plain->UpdateInformation();
    vtkInformation* plainInfo = plain->GetOutputInformation(0);
    const double* p = plainInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    const Output second = ReadAt(plain, 1.0);
    Expect(plainInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 2 && p &&
        p[0] == 0.0 && p[1] == 1.0 && second.File == steps[0],
      "files without times: steps 0 and 1 in the order given");
    vtkNew<vtkGlobeRasterReader> single;
    single->AddFileName(steps[0].c_str());
    single->UpdateInformation();
    Expect(!single->GetOutputInformation(0)->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()),
      "a single file announces no time");
  }

  // Dated names: the dates as decimal years, in date order.
  {
    const std::string april = WriteStep("sst_2026-04-01", 1);
    const std::string january = WriteStep("sst_20260101", 0);
    const std::string july = WriteStep("sst_2026_07", 2); // a month: its first day
    const std::string leap = WriteStep("sst_2024-12-31", 0);
    vtkNew<vtkGlobeRasterReader> dated;
    dated->AddFileName(april.c_str());
    dated->AddFileName(july.c_str());
    dated->AddFileName(january.c_str());
    dated->AddFileName(leap.c_str());
    dated->UpdateInformation();
    vtkInformation* datedInfo = dated->GetOutputInformation(0);
    const double* d = datedInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    const int m = datedInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    const double expected[4] = { 2024.0 + 365.0 / 366.0, 2026.0, 2026.0 + 90.0 / 365.0,
      2026.0 + 181.0 / 365.0 };
    bool same = m == 4 && d;
    for (int k = 0; same && k < 4; ++k)
    {
      same = std::abs(d[k] - expected[k]) < 1e-12;
    }
    const Output april1 = ReadAt(dated, 2026.3);
    Expect(same && april1.File == april,
      vtkGlobeTest::Printf("dated names: steps %.4f, %.4f, %.4f, %.4f (2024-12-31, 2026-01-01, "
                           "2026-04-01, 2026-07); 2026.3 reads 2026-04-01",
        m > 0 ? d[0] : NAN, m > 1 ? d[1] : NAN, m > 2 ? d[2] : NAN, m > 3 ? d[3] : NAN));
    dated->TimeFromFileNamesOff();
    dated->UpdateInformation();
    const double* off = datedInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    Expect(off && off[0] == 0.0 && off[3] == 3.0, "TimeFromFileNames off: positions 0..3");
    dated->TimeFromFileNamesOn();
    dated->AddFileName(steps[0].c_str()); // a name without a date
    dated->UpdateInformation();
    const double* mixed = datedInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    Expect(mixed && datedInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 5 &&
        mixed[0] == 0.0 && mixed[4] == 4.0,
      "one name without a date: the files' positions 0..4");
  }

  // The layer by the step's own time.
  vtkNew<vtkGlobeLayer> layer;
  layer->SetInputConnection(reader->GetOutputPort());
  struct Move
  {
    double Time;
    int Step;
    int Loads;
  };
  const Move moves[] = { { 0.0, 0, 1 }, { 2026.1, 0, 0 }, { 2026.3, 1, 1 }, { 2026.4, 1, 0 },
    { 2027.0, 2, 1 } };
  for (const auto& m : moves)
  {
    const int loads = layer->GetNumberOfLoads(), runs = executions.Count;
    layer->SetUpdateTime(m.Time);
    const bool ok = layer->Update();
    Expect(ok && layer->GetDataTime() == Times[m.Step] &&
        layer->GetNumberOfLoads() - loads == m.Loads && executions.Count - runs <= m.Loads &&
        layer->GetMaximumValue() == 100.0 * m.Step + 31,
      vtkGlobeTest::Printf("layer at %.2f: step %d (data time %.2f), %d load(s), %d reader run(s)",
        m.Time, m.Step + 1, layer->GetDataTime(), layer->GetNumberOfLoads() - loads,
        executions.Count - runs));
  }

  // Refused series.
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkGlobeRasterReader> bad;
  bad->AddObserver(vtkCommand::ErrorEvent, errors);
  bad->AddFileName(steps[0].c_str(), 1.0);
  bad->AddFileName(steps[1].c_str());
  bad->UpdateInformation();
  Expect(vtkGlobeTest::ErrorSaid(errors, { "times for 1 of its 2 files" }), "times for some files only: refused");
  bad->RemoveAllFileNames();
  bad->AddFileName(steps[0].c_str(), 1.0);
  bad->AddFileName(steps[1].c_str(), 1.0);
  bad->UpdateInformation();
  Expect(vtkGlobeTest::ErrorSaid(errors, { "two files have the time 1", "series_core_a", "series_core_b" }),
    "two files at one time: refused, naming both");
  bad->RemoveAllFileNames();
  bad->AddFileName(steps[0].c_str(), 1.0);
  bad->AddFileName(steps[1].c_str(), NAN);
  bad->UpdateInformation();
  Expect(vtkGlobeTest::ErrorSaid(errors, { "the time of", "series_core_b", "not a finite number" }),
    "a NaN time: refused, naming the file");
  return Checks.Result();
}
