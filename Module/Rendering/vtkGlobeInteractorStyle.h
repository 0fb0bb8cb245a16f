/**
 * @class   vtkGlobeInteractorStyle
 * @brief   Navigation around a planetary globe in the manner of Cesium and Google Earth:
 *          grab and drag the ground, zoom toward the cursor, tilt and turn, never underground,
 *          never rolled.
 *
 * The style works on the body of a vtkGlobeMapper (SetMapper, or the first globe found in the
 * renderer) and on its height layers:
 *  - left drag: the surface point under the cursor at the press (from the depth buffer through
 *    vtkGlobePointPicker; the ellipsoid where nothing was drawn) stays under the cursor. The
 *    camera turns about the body's centre so that the grabbed point's direction follows the
 *    cursor ray's intersection with the sphere through the grabbed point;
 *  - wheel, and right drag: zoom toward the terrain point under the cursor, moving along the
 *    cursor's ray (so that point stays under the cursor) by ZoomFactor of the distance to it,
 *    at most ZoomFactor times 10 heights above the terrain: the step shrinks with the height,
 *    so the ground is never reached;
 *  - Ctrl (or Shift) + left drag, or middle drag: tilt (vertical motion) and turn
 *    (horizontal motion) about the terrain point at the screen centre;
 *  - keys: 'n' north up, 'u' look straight down, 'r' reset to a view of the whole body. They
 *    replace VTK's 'u' (user event) and 'r' (reset camera); 'f' (fly to, which can go
 *    underground) is ignored; VTK's other keys (w, s, 3, e, q, p) are kept.
 * After every move the camera is kept MinimumHeightAboveTerrain over the composed terrain at
 * its sub-point (the mapper's vtkGlobeTerrain: the GPU's composition rules on the CPU),
 * moved back along the cursor ray when that keeps the grabbed or zoomed point under the cursor,
 * else up along the local vertical; and it is never rolled: its right vector is horizontal, so
 * its view-up is the projection of the local geodetic up on the view plane (at the nadir, where
 * that projection vanishes, the heading is kept).
 *
 * The actor's matrix must be rigid (rotation and translation). Works for any vtkGlobeEllipsoid:
 * the Earth, the Moon, Mars, triaxial bodies. Inertia is not implemented.
 */
#ifndef vtkGlobeInteractorStyle_h
#define vtkGlobeInteractorStyle_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkInteractorStyle.h"

class vtkActor;
class vtkGlobeMapper;
class vtkGlobePointPicker;

class VTKGLOBERENDERING_EXPORT vtkGlobeInteractorStyle : public vtkInteractorStyle
{
public:
  static vtkGlobeInteractorStyle* New();
  vtkTypeMacro(vtkGlobeInteractorStyle, vtkInteractorStyle);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The globe navigated (default: the first visible vtkGlobeMapper of the poked renderer).
  void SetMapper(vtkGlobeMapper* mapper);
  vtkGetObjectMacro(Mapper, vtkGlobeMapper);
  ///@}

  ///@{
  /// The least height (m) of the camera above the composed terrain at its sub-point (default 10).
  vtkSetClampMacro(MinimumHeightAboveTerrain, double, 0.0, 1e30);
  vtkGetMacro(MinimumHeightAboveTerrain, double);
  ///@}

  ///@{
  /// Fraction of the distance to the point under the cursor that one wheel notch moves
  /// (default 0.2; zooming out by one notch undoes one notch in).
  vtkSetClampMacro(ZoomFactor, double, 0.01, 0.9);
  vtkGetMacro(ZoomFactor, double);
  ///@}

  ///@{
  /// Degrees of tilt or turn per pixel of a tilt drag (default 0.25).
  vtkSetClampMacro(TiltSpeed, double, 0.001, 10.0);
  vtkGetMacro(TiltSpeed, double);
  ///@}

  ///@{
  /// The largest tilt from the nadir (degrees, default 85): the horizon stays in view.
  vtkSetClampMacro(MaximumTilt, double, 0.0, 89.9);
  vtkGetMacro(MaximumTilt, double);
  ///@}

  ///@{
  /// The actions behind the keys, for scripts and buttons: heading north about the screen
  /// centre's terrain point, look straight down from where the camera is, and a whole-body view
  /// over the camera's sub-point. Each renders.
  void NorthUp();
  void LookDown();
  void ResetView();
  ///@}

  /**
   * Keeps the active camera above the terrain plus the margin (up along the local vertical)
   * and unrolled: what the style does after each move, for a camera placed by other code.
   * Returns true when the camera was changed.
   */
  bool EnforceConstraints();

  /// The composed terrain height (m) at (lon, lat) in degrees that the style keeps above.
  double GetTerrainHeight(double lon, double lat);

  ///@{
  /// The state of the current or last drag and zoom, for tests and overlays: the grabbed point
  /// (world; valid while Grabbing), the last zoom's target (world) and whether it was valid, and
  /// whether the last move kept its point exactly under the cursor (false when the drag left
  /// the sphere through the grabbed point, or the terrain clamp had to move the camera up).
  vtkGetMacro(Grabbing, bool);
  vtkGetVector3Macro(GrabbedPoint, double);
  vtkGetVector3Macro(ZoomTarget, double);
  vtkGetMacro(ZoomTargetValid, bool);
  vtkGetMacro(LastMoveExact, bool);
  ///@}

  void OnMouseMove() override;
  void OnLeftButtonDown() override;
  void OnLeftButtonUp() override;
  void OnMiddleButtonDown() override;
  void OnMiddleButtonUp() override;
  void OnRightButtonDown() override;
  void OnRightButtonUp() override;
  void OnMouseWheelForward() override;
  void OnMouseWheelBackward() override;
  void OnChar() override;

protected:
  vtkGlobeInteractorStyle();
  ~vtkGlobeInteractorStyle() override;

  // Finds the renderer, globe and actor for an event at (x, y); false when there is no globe.
  bool Prepare(int x, int y);
  // The surface point under a display position (world): terrain from the depth buffer, else
  // the ellipsoid. False when the ray misses both.
  bool PickSurface(double x, double y, double world[3]);
  void Zoom(double x, double y, const double target[3], bool targetValid, double factor);
  void Finish();
  // A button released: ends `state` (a VTKIS_ gesture) if it is the current one.
  void EndGesture(int state);
  // One wheel notch: zoom toward the terrain under the cursor by `factor` of the distance.
  void WheelZoom(double factor);

  vtkGlobeMapper* Mapper = nullptr;
  // The globe of the current event: Mapper, or the one found in the renderer (not owned).
  vtkGlobeMapper* ActiveMapper = nullptr;
  vtkActor* GlobeActor = nullptr;
  vtkGlobePointPicker* Picker = nullptr;
  double MinimumHeightAboveTerrain = 10.0;
  double ZoomFactor = 0.2;
  double TiltSpeed = 0.25;
  double MaximumTilt = 85.0;

  bool Grabbing = false;
  bool Tilting = false;
  bool Zooming = false;
  double GrabbedPoint[3] = { 0, 0, 0 };
  double ZoomTarget[3] = { 0, 0, 0 };
  bool ZoomTargetValid = false;
  double Pivot[3] = { 0, 0, 0 };
  bool PivotValid = false;
  int PressPosition[2] = { 0, 0 };
  bool LastMoveExact = true;

private:
  vtkGlobeInteractorStyle(const vtkGlobeInteractorStyle&) = delete;
  void operator=(const vtkGlobeInteractorStyle&) = delete;
};

#endif
