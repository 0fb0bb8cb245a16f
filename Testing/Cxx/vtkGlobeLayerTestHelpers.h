// Helpers shared by the Core and Rendering tests: in-memory projected rasters as a reader
// would give them, and colours that tell neighbouring texels apart.
#ifndef vtkGlobeLayerTestHelpers_h
#define vtkGlobeLayerTestHelpers_h

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeRasterReader.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <functional>

namespace vtkGlobeTest
{
/// The reader's georeferencing field data on `image`: projected, EPSG:`epsg`, north-west outer
/// corner (west, north) and square pixels of `pixel` map units. EPSG 0 with a CRS definition
/// `crs`: a CRS without a code (the reader's GlobeCRS).
inline void Georeference(
  vtkImageData* image, int epsg, double west, double north, double pixel, const char* crs = nullptr)
{
  if (crs)
  {
    vtkNew<vtkStringArray> definition;
    definition->SetName(vtkGlobeRasterReader::GetCRSDefinitionArrayName());
    definition->InsertNextValue(crs);
    image->GetFieldData()->AddArray(definition);
  }
  vtkNew<vtkIntArray> model, code;
  model->SetName(vtkGlobeRasterReader::GetModelTypeArrayName());
  model->InsertNextValue(vtkGlobeRasterReader::Projected);
  code->SetName(vtkGlobeRasterReader::GetEPSGArrayName());
  code->InsertNextValue(epsg);
  vtkNew<vtkDoubleArray> transform;
  transform->SetName(vtkGlobeRasterReader::GetGeoTransformArrayName());
  for (double v : { west, north, pixel, pixel })
  {
    transform->InsertNextValue(v);
  }
  image->GetFieldData()->AddArray(model);
  image->GetFieldData()->AddArray(code);
  image->GetFieldData()->AddArray(transform);
}

/// An in-memory projected height raster: value(i, j) for column i (east) and row j (north
/// first).
inline vtkSmartPointer<vtkGlobeLayer> ProjectedHeights(int epsg, int w, int h, double west,
  double north, double pixel, const std::function<float(int, int)>& value)
{
  vtkNew<vtkImageData> image;
  image->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  image->SetSpacing(pixel, pixel, 1.0);
  image->SetOrigin(west + 0.5 * pixel, north - (h - 0.5) * pixel, 0.0);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* scalars = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      scalars->SetValue(static_cast<vtkIdType>(h - 1 - j) * w + i, value(i, j)); // south first
    }
  }
  Georeference(image, epsg, west, north, pixel);
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetRoleToHeight();
  layer->SetInputData(image);
  return layer;
}

/// An in-memory projected RGB raster: colour(i, j) for column i (east) and row j (north
/// first), its north-west outer corner and pixel size in metres, as a reader would give it.
inline vtkSmartPointer<vtkGlobeLayer> ProjectedImage(int epsg, int w, int h, double west, double north,
  double pixel, const std::function<std::array<unsigned char, 3>(int, int)>& colour,
  const char* crs = nullptr)
{
  vtkNew<vtkImageData> image;
  image->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  image->SetSpacing(pixel, pixel, 1.0);
  image->SetOrigin(west + 0.5 * pixel, north - (h - 0.5) * pixel, 0.0);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const auto c = colour(i, j);
      const vtkIdType id = static_cast<vtkIdType>(h - 1 - j) * w + i; // VTK rows: south first
      for (int k = 0; k < 3; ++k)
      {
        scalars->SetComponent(id, k, c[k]);
      }
    }
  }
  Georeference(image, epsg, west, north, pixel, crs);
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetRoleToColor();
  layer->SetInputData(image);
  layer->SetFeatherWidth(0.0);
  layer->SetInterpolationToNearest();
  return layer;
}

/// Distinct colours for neighbouring texels (a hash), so a misregistration by one texel shows.
inline std::array<unsigned char, 3> TexelColour(int layer, int i, int j)
{
  unsigned int hsh = static_cast<unsigned int>(i) * 73856093u ^
    static_cast<unsigned int>(j) * 19349663u ^ static_cast<unsigned int>(layer) * 83492791u;
  hsh *= 2654435761u;
  return { static_cast<unsigned char>(40 + (hsh >> 24) % 200),
    static_cast<unsigned char>(40 + (hsh >> 16) % 200), static_cast<unsigned char>(40 + (hsh >> 8) % 200) };
}

} // namespace vtkGlobeTest

#endif
