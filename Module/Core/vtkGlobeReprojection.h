// vtkGlobeReprojection: rasters in a CRS the GPU does not project, resampled on load into a
// geographic (EPSG:4326) grid through PROJ (Documentation/projections.md "Any other CRS").
// Private to VTKGlobe::Core (vtkGlobeLayer uses it); not wrapped.
#ifndef vtkGlobeReprojection_h
#define vtkGlobeReprojection_h

#include "vtkSmartPointer.h"

#include <string>

class vtkDataArray;

namespace vtkGlobeReprojection
{
/// A geographic grid: size in texels, north-west outer corner and texel size in degrees.
struct Grid
{
  int Width = 0;
  int Height = 0;
  double West = 0.0;
  double North = 0.0;
  double DLon = 0.0;
  double DLat = 0.0;
};

/**
 * Resamples a raster in the CRS `crs` ("EPSG:code", or a definition PROJ reads) (row 0 north; north-west outer corner `origin` and pixel
 * size `pixel` in the CRS's units; `data` float heights with NaN voids, or RGBA bytes) into a
 * geographic grid that covers it, with texels about as large on the ground as the source's
 * (fewer where `maxBytes` would be exceeded). Each output texel centre is transformed into the
 * source CRS by PROJ and sampled there: bilinearly (`nearest` false; over the finite heights
 * or all four RGBA channels) or from the nearest texel. Outside the source: NaN heights,
 * transparent pixels. False with `why` when PROJ has no transformation or the raster does not
 * map to the globe.
 */
bool ToGeographic(const std::string& crs, const double origin[2], const double pixel[2], int width, int height,
  vtkDataArray* data, bool nearest, double maxBytes, vtkSmartPointer<vtkDataArray>& out,
  Grid& grid, std::string& why);
}

#endif
