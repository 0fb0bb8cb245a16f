// Internal (not installed): raster sample types shared by vtkGlobeRasterReader,
// vtkGlobePageSource and vtkGlobeRasterPreparer. Samples are read in their native type and
// converted here: OpenImageIO's own conversion to float would normalise integers.
#ifndef vtkGlobeRasterSamples_h
#define vtkGlobeRasterSamples_h

#include "vtkType.h"
#include "vtkTemplateAliasMacro.h" // vtkTemplateMacro

#include <OpenImageIO/typedesc.h>

#include <cstring>

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
}

#endif
