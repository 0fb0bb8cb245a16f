// Fuzz target: vtkGlobePageSource on one file (input.tif): open it, then read the first and
// the last page of the finest, a middle and the coarsest level, with their bounds, through
// small pages (16 texels and a border of 1) and a 16 MiB ImageCache.
#include "GlobeFuzz.h"

#include "vtkFloatArray.h"
#include "vtkGlobePageSource.h"
#include "vtkNew.h"
#include "vtkType.h"
#include "vtkUnsignedCharArray.h"

#include <set>

namespace
{
/// Rasters above this many texels are opened but not read: level 0 of a file without levels
/// is averaged whole into the coarser ones, which for a hostile header declaring 30000 x 30000
/// would be minutes of (failing) reads per input. The readers' MaximumMemory plays that role
/// for the other targets.
constexpr double MaximumTexels = 2048.0 * 2048.0;

void ReadPage(vtkGlobePageSource* source, vtkDataArray* out, int level, int column, int row)
{
  source->ReadPage(level, column, row, out);
  double bounds[4];
  source->GetPageBounds(level, column, row, bounds);
  double sum = 0.0;
  const vtkIdType n = out->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; i += 7)
  {
    sum += out->GetVariantValue(i).ToDouble();
  }
  volatile double all = sum + bounds[0];
  (void)all;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  GlobeFuzz::Setup();
  const std::string& dir = GlobeFuzz::Directory("pagesource");
  const std::string file = dir + "/input.tif";
  if (!GlobeFuzz::WriteFile(file, data, size))
  {
    return 0;
  }
  {
    vtkNew<vtkGlobePageSource> source;
    source->SetFileName(file.c_str());
    source->SetPageSize(16);
    source->SetBorder(1);
    source->SetCacheMemory(16.0);
    if (source->Open() &&
      static_cast<double>(source->GetNumberOfColumns()) * source->GetNumberOfRows() <= MaximumTexels)
    {
      double transform[4];
      source->GetGeoTransform(transform);
      vtkNew<vtkFloatArray> heights;
      vtkNew<vtkUnsignedCharArray> colors;
      vtkDataArray* out = source->GetPageDataType() == VTK_FLOAT
        ? static_cast<vtkDataArray*>(heights)
        : static_cast<vtkDataArray*>(colors);
      const int levels = source->GetNumberOfLevels();
      const std::set<int> chosen = { 0, levels / 2, levels - 1 };
      for (int level : chosen)
      {
        int count[2];
        if (level >= 0 && source->GetNumberOfPages(level, count))
        {
          ReadPage(source, out, level, 0, 0);
          ReadPage(source, out, level, count[0] - 1, count[1] - 1);
        }
      }
      // Out of range: refused with an error.
      source->ReadPage(levels, 0, 0, out);
      source->ReadPage(0, -1, 0, out);
    }
  }
  GlobeFuzz::Clear(dir);
  return 0;
}
