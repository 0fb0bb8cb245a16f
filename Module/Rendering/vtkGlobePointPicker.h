/**
 * @class   vtkGlobePointPicker
 * @brief   vtkWorldPointPicker that reads the depth buffer in the scene's depth mode.
 *
 * vtkWorldPointPicker turns the z-buffer value under the cursor into a world point through
 * the camera's perspective projection, which is wrong once a vtkGlobeDepthPass writes
 * logarithmic depth. This picker finds the renderer's vtkGlobeDepthPass (the renderer's pass,
 * or the one set with SetDepthPass), converts the depth value back to VTK's convention in
 * double, and unprojects it: a click on the terrain returns the terrain point, in every mode.
 * Where nothing was drawn it behaves as vtkWorldPointPicker (the focal plane's depth) and
 * GetHit() is false.
 */
#ifndef vtkGlobePointPicker_h
#define vtkGlobePointPicker_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkWorldPointPicker.h"

class vtkGlobeDepthPass;

class VTKGLOBERENDERING_EXPORT vtkGlobePointPicker : public vtkWorldPointPicker
{
public:
  static vtkGlobePointPicker* New();
  vtkTypeMacro(vtkGlobePointPicker, vtkWorldPointPicker);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int Pick(double selectionX, double selectionY, double selectionZ, vtkRenderer* renderer) override;
  int Pick(double selectionPt[3], vtkRenderer* renderer)
  {
    return this->Pick(selectionPt[0], selectionPt[1], selectionPt[2], renderer);
  }

  ///@{
  /// The depth pass to invert (default: the renderer's pass, when it is a vtkGlobeDepthPass).
  void SetDepthPass(vtkGlobeDepthPass* pass);
  vtkGetObjectMacro(DepthPass, vtkGlobeDepthPass);
  ///@}

  /// True when the last pick found something drawn under the cursor.
  vtkGetMacro(Hit, bool);

protected:
  vtkGlobePointPicker();
  ~vtkGlobePointPicker() override;

  vtkGlobeDepthPass* DepthPass = nullptr;
  bool Hit = false;

private:
  vtkGlobePointPicker(const vtkGlobePointPicker&) = delete;
  void operator=(const vtkGlobePointPicker&) = delete;
};

#endif
