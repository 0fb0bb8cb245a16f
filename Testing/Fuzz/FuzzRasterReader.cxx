// Fuzz target: vtkGlobeRasterReader on one file, georeferencing included. The input is the
// whole file (input.tif; OpenImageIO falls back to every format it knows when the bytes are
// not a TIFF). Information, then data; on success every value and every field-data array is
// read, so a buffer shorter than it claims is caught by AddressSanitizer.
#include "GlobeFuzz.h"

#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkGlobeRasterReader.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

namespace
{
/// Reads every value of every array: the sum is returned so that nothing is optimised away.
double Touch(vtkImageData* image)
{
  double sum = 0.0;
  if (vtkDataArray* scalars = image->GetPointData()->GetScalars())
  {
    const vtkIdType n = scalars->GetNumberOfValues();
    for (vtkIdType i = 0; i < n; ++i)
    {
      sum += scalars->GetVariantValue(i).ToDouble();
    }
  }
  vtkFieldData* fields = image->GetFieldData();
  for (int a = 0; a < fields->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = fields->GetAbstractArray(a);
    for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
    {
      sum += static_cast<double>(array->GetVariantValue(i).ToString().size());
    }
  }
  return sum;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  GlobeFuzz::Setup();
  const std::string& dir = GlobeFuzz::Directory("reader");
  const std::string file = dir + "/input.tif";
  if (!GlobeFuzz::WriteFile(file, data, size))
  {
    return 0;
  }
  {
    vtkNew<vtkGlobeRasterReader> reader;
    reader->SetFileName(file.c_str());
    reader->SetMaximumMemory(GlobeFuzz::MaximumMemoryMiB);
    if (reader->GetExecutive()->UpdateInformation() && reader->GetExecutive()->Update())
    {
      volatile double sum = Touch(reader->GetOutput());
      (void)sum;
    }
    volatile size_t length = std::string(reader->GetLastError()).size();
    (void)length;
  }
  GlobeFuzz::Clear(dir);
  return 0;
}
