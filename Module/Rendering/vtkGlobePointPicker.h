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
 *
 * The cursor readout: after a pick that hit, the picked point in the globe's terms (the
 * mapper set with SetMapper, else the first visible vtkGlobeMapper actor of the renderer,
 * through its actor's matrix): longitude, latitude and ellipsoidal height
 * (GetPickGeodetic), the orthometric height above the vertical datum of the globe's layers
 * (GetPickOrthometricHeight: h - N, vtkGlobeTerrain::GetGeoidUndulation; NaN without a geoid
 * datum), the composed terrain there (GetPickTerrainHeight) and the distance from the camera
 * (GetPickDistance). Without a hit or a globe they are NaN and GetGeodeticHit() is false.
 */
#ifndef vtkGlobePointPicker_h
#define vtkGlobePointPicker_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkWorldPointPicker.h"

class vtkGlobeDepthPass;
class vtkGlobeMapper;

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

  ///@{
  /// The globe of the geodetic readout (default: the first visible globe in the renderer).
  void SetMapper(vtkGlobeMapper* mapper);
  vtkGetObjectMacro(Mapper, vtkGlobeMapper);
  ///@}

  ///@{
  /**
   * The last pick in the globe's terms (see the class description): longitude and latitude
   * (degrees) and ellipsoidal height (m); the orthometric height (m, NaN without a geoid
   * datum); the composed terrain height at that longitude and latitude (m); the distance from
   * the camera (m). NaN, and GetGeodeticHit() false, without a hit on a globe's scene.
   */
  vtkGetMacro(GeodeticHit, bool);
  vtkGetVector3Macro(PickGeodetic, double);
  vtkGetMacro(PickOrthometricHeight, double);
  vtkGetMacro(PickTerrainHeight, double);
  vtkGetMacro(PickDistance, double);
  ///@}

protected:
  vtkGlobePointPicker();
  ~vtkGlobePointPicker() override;

  void ComputeGeodetic(vtkRenderer* renderer);

  vtkGlobeDepthPass* DepthPass = nullptr;
  vtkGlobeMapper* Mapper = nullptr;
  bool Hit = false;
  bool GeodeticHit = false;
  double PickGeodetic[3] = { 0, 0, 0 };
  double PickOrthometricHeight = 0;
  double PickTerrainHeight = 0;
  double PickDistance = 0;

private:
  vtkGlobePointPicker(const vtkGlobePointPicker&) = delete;
  void operator=(const vtkGlobePointPicker&) = delete;
};

#endif
