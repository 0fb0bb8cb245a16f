// Internal (not installed): raster sample types shared by vtkGlobeRasterReader,
// vtkGlobePageSource and vtkGlobeRasterPreparer. Samples are read in their native type and
// converted here: OpenImageIO's own conversion to float would normalise integers.
#ifndef vtkGlobeRasterSamples_h
#define vtkGlobeRasterSamples_h

#include "vtkType.h"
#include "vtkTemplateAliasMacro.h" // vtkTemplateMacro

#include <OpenImageIO/typedesc.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace vtkGlobeRasterSamples
{
/// The VTK scalar type that holds OpenImageIO's format exactly (half widens to float); 0 when
/// none does.
inline int ScalarTypeOf(OIIO::TypeDesc format)
{
  switch (format.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      return VTK_UNSIGNED_CHAR;
    case OIIO::TypeDesc::INT8:
      return VTK_SIGNED_CHAR;
    case OIIO::TypeDesc::UINT16:
      return VTK_UNSIGNED_SHORT;
    case OIIO::TypeDesc::INT16:
      return VTK_SHORT;
    case OIIO::TypeDesc::UINT32:
      return VTK_UNSIGNED_INT;
    case OIIO::TypeDesc::INT32:
      return VTK_INT;
    case OIIO::TypeDesc::HALF: // widened exactly, never rescaled
    case OIIO::TypeDesc::FLOAT:
      return VTK_FLOAT;
    case OIIO::TypeDesc::DOUBLE:
      return VTK_DOUBLE;
    default:
      return 0;
  }
}

/// The format to ask OpenImageIO for, so that samples arrive as the VTK type.
inline OIIO::TypeDesc ReadTypeOf(int scalarType)
{
  switch (scalarType)
  {
    case VTK_UNSIGNED_CHAR:
      return OIIO::TypeDesc::UINT8;
    case VTK_SIGNED_CHAR:
      return OIIO::TypeDesc::INT8;
    case VTK_UNSIGNED_SHORT:
      return OIIO::TypeDesc::UINT16;
    case VTK_SHORT:
      return OIIO::TypeDesc::INT16;
    case VTK_UNSIGNED_INT:
      return OIIO::TypeDesc::UINT32;
    case VTK_INT:
      return OIIO::TypeDesc::INT32;
    case VTK_FLOAT:
      return OIIO::TypeDesc::FLOAT;
    default:
      return OIIO::TypeDesc::DOUBLE;
  }
}

/// One sample of VTK type `scalarType` at p (any alignment), as double.
inline double ToDouble(const void* p, int scalarType)
{
  double value = 0.0;
  switch (scalarType)
  {
    vtkTemplateMacro(VTK_TT sample; std::memcpy(&sample, p, sizeof(sample));
                     value = static_cast<double>(sample));
  }
  return value;
}

/// The nodata value in a raster's sample type, when it is one of its values.
template <typename T>
inline bool NoDataAs(double noData, T& value)
{
  if constexpr (std::is_integral_v<T>)
  {
    // Out-of-range or fractional values cannot occur in the raster (and the cast would be
    // undefined).
    if (!(noData == std::floor(noData)) ||
      noData < static_cast<double>(std::numeric_limits<T>::lowest()) ||
      noData > static_cast<double>(std::numeric_limits<T>::max()))
    {
      return false;
    }
    value = static_cast<T>(noData);
    return true;
  }
  else
  {
    if (std::isnan(noData))
    {
      return false; // NaN samples are voids anyway
    }
    const double max = static_cast<double>(std::numeric_limits<T>::max());
    if (std::isfinite(noData) && std::abs(noData) > max)
    {
      // Text that rounds just past the largest float (e.g. "3.40282347e+38") means it.
      if (std::abs(noData) > max * (1.0 + 1e-7))
      {
        return false;
      }
      noData = std::copysign(max, noData);
    }
    value = static_cast<T>(noData);
    return true;
  }
}

/**
 * The nodata value as a sample of VTK type `scalarType` holds it, as double (what ToDouble
 * gives for a nodata sample), so that samples compare exactly (a float raster's nodata text
 * -9999.9 is stored as -9999.900390625); false when no sample of the type can be it.
 */
inline bool NoDataSample(double noData, int scalarType, double& sample)
{
  switch (scalarType)
  {
    vtkTemplateMacro(VTK_TT value{}; if (!NoDataAs(noData, value)) { return false; }
                     sample = static_cast<double>(value); return true;);
  }
  return false;
}
}

#endif
