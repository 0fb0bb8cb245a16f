/**
 * @class   vtkGlobeMapperTesting
 * @brief   Access to a vtkGlobeMapper's internal frame state, for tests and benchmarks only.
 *
 * The G-buffer (the per-pixel direction + height texture and its depth) is how the mapper's
 * passes talk to each other (Documentation/architecture.md, "One frame"): its layout changes
 * with the precision mode and may change between releases, so it is not part of the mapper's
 * public API. Tests that read every texel back (no NaN in the hard cases, addressing) and the
 * benchmark's memory table reach it through this accessor. It is C++ only (not wrapped).
 */
#ifndef vtkGlobeMapperTesting_h
#define vtkGlobeMapperTesting_h

#include "vtkGlobeRenderingModule.h" // for export macro

class vtkGlobeMapper;
class vtkTextureObject;

class VTKGLOBERENDERING_EXPORT vtkGlobeMapperTesting
{
public:
  ///@{
  /// The last frame's G-buffer (window-sized: direction, or its offset from the local origin
  /// with HighPrecisionGeodetic, + height) and its depth; nullptr before the first frame.
  static vtkTextureObject* GetGBufferTexture(vtkGlobeMapper* mapper);
  static vtkTextureObject* GetGBufferDepthTexture(vtkGlobeMapper* mapper);
  ///@}
};

#endif
