/**
 * @class   vtkGlobePageFeedback
 * @brief   The frame decides what streamed layers load: footprint samples of the G-buffer.
 *
 * After the G-buffer pass, Render() draws one sample per block of BlockSize x BlockSize
 * pixels into a small float target (glsl/vtkGlobePageFeedbackFS.glsl: the block's centre
 * pixel and its neighbours along x and y) and starts reading it back through a pixel-buffer
 * object, so the frame does not wait. Collect() (the next frame, or at once when asked to
 * wait) maps it and turns every covered sample into (lon, lat) and their derivatives per
 * pixel, in double: the footprints vtkGlobeLayerSet::RequestPages turns into each streamed
 * layer's level and pages. At 800 x 600 and blocks of 8 that is 7,500 samples, 360 KB read
 * back per frame.
 */
#ifndef vtkGlobePageFeedback_h
#define vtkGlobePageFeedback_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkDoubleArray;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class VTKGLOBERENDERING_EXPORT vtkGlobePageFeedback : public vtkObject
{
public:
  static vtkGlobePageFeedback* New();
  vtkTypeMacro(vtkGlobePageFeedback, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Pixels per block side (default 8).
  vtkSetClampMacro(BlockSize, int, 1, 64);
  vtkGetMacro(BlockSize, int);
  ///@}

  /**
   * Samples the G-buffer (xyz: the direction in the body's scaled space, or its offset from
   * `reference` when that is not zero; see vtkGlobeLayerSet::SetGeodeticReference) and its
   * depth, and starts the read-back. radii: the body's radii (m), for geodetic latitude.
   * Needs a current context; returns false if the shader did not compile.
   */
  bool Render(vtkOpenGLRenderWindow* window, vtkTextureObject* gbuffer, vtkTextureObject* depth,
    const double reference[3], const double radii[3]);

  /// True between Render() and Collect().
  bool IsPending();

  /**
   * Maps the read-back of the last Render() (waiting for it if needed) and fills footprints
   * with 6 components per covered sample: (lon, lat, dlon/dx, dlat/dx, dlon/dy, dlat/dy) in
   * radians. Returns false when nothing is pending.
   */
  bool Collect(vtkDoubleArray* footprints);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkGlobePageFeedback();
  ~vtkGlobePageFeedback() override;

  int BlockSize = 8;

private:
  vtkGlobePageFeedback(const vtkGlobePageFeedback&) = delete;
  void operator=(const vtkGlobePageFeedback&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
