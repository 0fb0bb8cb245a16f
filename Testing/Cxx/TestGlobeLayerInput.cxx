// vtkGlobeLayer as the end of a pipeline: reader -> vtkImageShiftScale -> layer. The layer's
// values follow the filter (every post = raw + shift); changing the shift, or Modified() on the
// reader, re-loads this layer (a new, newer data array) and not an unrelated layer; Update()
// with nothing changed re-loads nothing. Also: vtkImageGaussianSmooth in between, a crop
// (vtkExtractVOI) that keeps the georeferencing, SetInputData, a failing upstream reader
// reported by the layer with the file and the reason, and an image without georeferencing.
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkExtractVOI.h"
#include "vtkFloatArray.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeRasterReader.h"
#include "vtkImageData.h"
#include "vtkImageGaussianSmooth.h"
#include "vtkImageShiftScale.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"
#include "vtkGlobeTestHelpers.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

using vtkGlobeTest::Printf;

const std::string Data = VTKGLOBE_DATA_DIR;

std::vector<float> Values(vtkGlobeLayer* layer)
{
  auto* a = vtkFloatArray::SafeDownCast(layer->GetData());
  return a ? std::vector<float>(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfValues())
           : std::vector<float>();
}

/// Worst |a - float(b + shift)| over all posts (the filter's float output); inf when the
/// sizes differ.
double WorstShift(const std::vector<float>& a, const std::vector<float>& b, double shift)
{
  if (a.size() != b.size() || a.empty())
  {
    return INFINITY;
  }
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    worst = std::max(worst, std::abs(static_cast<double>(a[i] - static_cast<float>(b[i] + shift))));
  }
  return worst;
}
} // namespace

int TestGlobeLayerInput(int, char*[])
{
  const std::string relief = Data + "/earth/relief_2deg.tif";
  vtkNew<vtkTest::ErrorObserver> errors;

  // The reference: the same file through FileName.
  vtkNew<vtkGlobeLayer> plain;
  plain->SetFileName(relief.c_str());
  const bool plainOk = plain->Update();
  const std::vector<float> raw = Values(plain);
  double plainExtent[4];
  plain->GetGeographicExtent(plainExtent);

  std::printf("reader -> vtkImageShiftScale -> layer:\n");
  vtkNew<vtkGlobeRasterReader> reader;
  reader->SetFileName(relief.c_str());
  vtkNew<vtkImageShiftScale> shift;
  shift->SetInputConnection(reader->GetOutputPort());
  shift->SetShift(1000.0);
  shift->SetScale(1.0);
  vtkNew<vtkGlobeLayer> layer;
  layer->AddObserver(vtkCommand::ErrorEvent, errors);
  layer->SetInputConnection(shift->GetOutputPort());
  Expect(layer->GetInputAlgorithm() == shift.Get() && !layer->GetFileName(),
    "SetInputConnection: the input algorithm is the filter, no FileName");
  Expect(plainOk && layer->Update() && !errors->GetError() && layer->GetNumberOfLoads() == 1,
    "Update() succeeds (1 load)");
  double extent[4];
  layer->GetGeographicExtent(extent);
  Expect(layer->GetModelType() == vtkGlobeLayer::Geographic && layer->GetEPSG() == 4326 &&
      layer->GetNumberOfColumns() == 180 && layer->GetNumberOfRows() == 90 && extent[0] == plainExtent[0] &&
      extent[1] == plainExtent[1] && extent[2] == plainExtent[2] && extent[3] == plainExtent[3] &&
      layer->IsGlobal() && std::string(layer->GetName()) == "relief_2deg",
    Printf("the field data passed the filter: geographic EPSG %d, 180 x 90, extent %g %g %g %g, "
           "global, name '%s'",
      layer->GetEPSG(), extent[0], extent[1], extent[2], extent[3], layer->GetName()));
  double worst = WorstShift(Values(layer), raw, 1000.0);
  Expect(worst == 0.0 && layer->GetMaximumValue() == plain->GetMaximumValue() + 1000.0,
    Printf("every post = file + 1000 m (worst difference %g m), row 0 north as with FileName; "
           "max %.1f m",
      worst, layer->GetMaximumValue()));

  // An unrelated layer, with its own reader.
  vtkNew<vtkGlobeRasterReader> otherReader;
  otherReader->SetFileName((Data + "/earth/mt_rainier_90m.tif").c_str());
  vtkNew<vtkGlobeLayer> other;
  other->SetInputConnection(otherReader->GetOutputPort());
  other->Update();
  const vtkMTimeType otherTime = other->GetData()->GetMTime();

  vtkMTimeType time = layer->GetData()->GetMTime();
  layer->Update();
  other->Update();
  Expect(layer->GetNumberOfLoads() == 1 && layer->GetData()->GetMTime() == time &&
      other->GetNumberOfLoads() == 1,
    "Update() with nothing changed: no re-load, the same data array");

  shift->SetShift(-500.0);
  layer->Update();
  other->Update();
  worst = WorstShift(Values(layer), raw, -500.0);
  Expect(layer->GetNumberOfLoads() == 2 && worst == 0.0 && layer->GetData()->GetMTime() > time,
    Printf("SetShift(-500): re-loaded (%d loads), every post = file - 500 m (worst %g), newer "
           "data MTime",
      layer->GetNumberOfLoads(), worst));
  time = layer->GetData()->GetMTime();

  reader->Modified();
  layer->Update();
  other->Update();
  Expect(layer->GetNumberOfLoads() == 3 && layer->GetData()->GetMTime() > time &&
      other->GetNumberOfLoads() == 1 && other->GetData()->GetMTime() == otherTime,
    Printf("reader->Modified(): this layer re-loads (%d loads, newer data), the unrelated one "
           "does not (%d load, same data)",
      layer->GetNumberOfLoads(), other->GetNumberOfLoads()));

  layer->SetValueScale(2.0);
  layer->Update();
  bool scaled = true;
  const std::vector<float> v = Values(layer);
  for (size_t i = 0; i < v.size(); ++i)
  {
    scaled = scaled && v[i] == static_cast<float>(2.0 * static_cast<float>(raw[i] - 500.0));
  }
  Expect(layer->GetNumberOfLoads() == 3 && scaled,
    "the layer's ValueScale(2) applies after the filter: 2 (file - 500), mapped in place "
    "(no re-load)");
  layer->SetValueScale(1.0);

  std::printf("Other filters:\n");
  {
    vtkNew<vtkImageGaussianSmooth> smooth;
    smooth->SetInputConnection(reader->GetOutputPort());
    smooth->SetDimensionality(2);
    smooth->SetStandardDeviations(2.0, 2.0);
    vtkNew<vtkGlobeLayer> smoothed;
    smoothed->AddObserver(vtkCommand::ErrorEvent, errors);
    smoothed->SetInputConnection(smooth->GetOutputPort());
    const bool ok = smoothed->Update();
    Expect(ok && !errors->GetError() && smoothed->GetMaximumValue() < plain->GetMaximumValue() &&
        smoothed->GetMinimumValue() > plain->GetMinimumValue(),
      Printf("vtkImageGaussianSmooth: the range shrinks to %.1f .. %.1f m (file %.1f .. %.1f)",
        smoothed->GetMinimumValue(), smoothed->GetMaximumValue(), plain->GetMinimumValue(),
        plain->GetMaximumValue()));

    // A crop: columns 90..179 (the eastern half), rows 45..89 (VTK rows: the northern half).
    vtkNew<vtkExtractVOI> crop;
    crop->SetInputConnection(reader->GetOutputPort());
    crop->SetVOI(90, 179, 45, 89, 0, 0);
    vtkNew<vtkGlobeLayer> cropped;
    cropped->AddObserver(vtkCommand::ErrorEvent, errors);
    cropped->SetInputConnection(crop->GetOutputPort());
    const bool cropOk = cropped->Update();
    cropped->GetGeographicExtent(extent);
    const std::vector<float> c = Values(cropped);
    bool same = c.size() == 90 * 45;
    for (int r = 0; same && r < 45; ++r)
    {
      for (int col = 0; col < 90; ++col)
      {
        same = same && c[r * 90 + col] == raw[r * 180 + 90 + col];
      }
    }
    Expect(cropOk && !errors->GetError() && extent[0] == 0 && extent[1] == 180 &&
        extent[2] == 0 && extent[3] == 90 && same,
      Printf("vtkExtractVOI (north-east quarter): extent %g %g %g %g, the posts of the file's "
             "quarter",
        extent[0], extent[1], extent[2], extent[3]));
  }

  std::printf("SetInputData, sources replacing each other:\n");
  {
    reader->Update();
    vtkNew<vtkImageData> copy;
    copy->DeepCopy(reader->GetOutput());
    vtkNew<vtkGlobeLayer> data;
    data->SetInputData(copy);
    Expect(data->Update() && WorstShift(Values(data), raw, 0.0) == 0.0,
      "SetInputData(a copy of the reader's output): the file's values");
    const int loads = data->GetNumberOfLoads();
    static_cast<vtkFloatArray*>(copy->GetPointData()->GetScalars())->SetValue(0, 1.0f);
    copy->GetPointData()->GetScalars()->Modified();
    copy->Modified();
    data->Update();
    Expect(data->GetNumberOfLoads() == loads + 1, "modifying the data set re-loads");
    data->SetFileName((Data + "/earth/mt_rainier_90m.tif").c_str());
    Expect(data->Update() && data->GetNumberOfColumns() == 1201 && data->GetInputAlgorithm() &&
        data->GetInputAlgorithm() == data->GetFileReader(),
      "SetFileName after SetInputData: the file, through the internal reader");
    data->SetInputConnection(shift->GetOutputPort());
    Expect(data->Update() && data->GetNumberOfColumns() == 180 && !data->GetFileName(),
      "SetInputConnection after SetFileName: the connection, FileName cleared");
  }

  std::printf("Failures upstream:\n");
  {
    vtkNew<vtkGlobeRasterReader> missing;
    vtkNew<vtkTest::ErrorObserver> quiet;
    missing->AddObserver(vtkCommand::ErrorEvent, quiet);
    missing->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
    missing->SetFileName((Data + "/earth/no_such.tif").c_str());
    vtkNew<vtkImageShiftScale> filter;
    filter->SetInputConnection(missing->GetOutputPort());
    vtkNew<vtkGlobeLayer> broken;
    broken->AddObserver(vtkCommand::ErrorEvent, errors);
    broken->SetInputConnection(filter->GetOutputPort());
    const bool ok = broken->Update();
    const std::string message = errors->GetErrorMessage();
    Expect(!ok && !broken->IsValid() && !broken->GetData() &&
        message.find("no_such.tif") != std::string::npos &&
        message.find("does not exist") != std::string::npos,
      "a missing file two steps upstream: the layer fails, naming the file and the reason");
    errors->Clear();

    vtkNew<vtkImageData> bare;
    bare->SetDimensions(4, 3, 1);
    bare->AllocateScalars(VTK_FLOAT, 1);
    broken->SetInputData(bare);
    Expect(!broken->Update() && errors->GetError() &&
        errors->GetErrorMessage().find("no georeferencing") != std::string::npos,
      "an image without the georeferencing field data: 'no georeferencing'");
    errors->Clear();
  }

  return Checks.Result();
}
