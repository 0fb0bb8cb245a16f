// Fuzz target: vtkGlobeLayer loading a file (input.tif), as heights (voids filled, the
// plausible range of the Earth) and as colour; on success its values and georeferencing are
// read back.
#include "GlobeFuzz.h"

#include "vtkDataArray.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeRasterReader.h"
#include "vtkNew.h"

namespace
{
void Load(const std::string& file, bool heights)
{
  vtkNew<vtkGlobeLayer> layer;
  if (heights)
  {
    layer->SetRoleToHeight();
    layer->SetFillVoids(true);
    layer->SetPlausibleRange(-317838.0, 317838.0);
  }
  else
  {
    layer->SetRoleToColor();
  }
  // Streamed layers are the page-source target's; here the whole raster is loaded.
  layer->SetStreamingToOff();
  layer->SetFileName(file.c_str());
  layer->GetFileReader()->SetMaximumMemory(GlobeFuzz::MaximumMemoryMiB);
  if (layer->Update() && layer->IsValid())
  {
    double sum = 0.0;
    if (vtkDataArray* values = layer->GetData())
    {
      const vtkIdType n = values->GetNumberOfValues();
      for (vtkIdType i = 0; i < n; ++i)
      {
        sum += values->GetVariantValue(i).ToDouble();
      }
    }
    double extent[4], origin[2], pixel[2];
    layer->GetGeographicExtent(extent);
    layer->GetProjectedGeoTransform(origin, pixel);
    volatile double all = sum + extent[0] + origin[0] + pixel[0] + layer->GetNumberOfVoids();
    (void)all;
    // A second Update with nothing changed must not reload (and must not crash).
    layer->Update();
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  GlobeFuzz::Setup();
  const std::string& dir = GlobeFuzz::Directory("layer");
  const std::string file = dir + "/input.tif";
  if (GlobeFuzz::WriteFile(file, data, size))
  {
    Load(file, true);
    Load(file, false);
  }
  GlobeFuzz::Clear(dir);
  return 0;
}
