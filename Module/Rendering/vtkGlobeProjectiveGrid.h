/**
 * @class   vtkGlobeProjectiveGrid
 * @brief   The CPU half of spherical Projective Grid Mapping for one frame, in double.
 *
 * From the camera, the body (a vtkGlobeEllipsoid placed by the actor's matrix) and the range
 * of terrain heights, computes what the grid pass needs (Documentation/rendering.md, "One frame",
 * "PGM as implemented" and "Errata and degenerate cases"):
 *  - the eye in the body's scaled space (x/a, y/b, z/c), where the ellipsoid is the unit
 *    sphere, its distance d, the nadir;
 *  - the primary reference sphere r_p (below all visible terrain), the maximum sphere r_max
 *    (above all terrain) and the secondary sphere r_s = d cos(gamma_0) that lets the grid
 *    sample terrain rising from behind the primary horizon (none when r_s <= 0);
 *  - the blend of the two (errata E2, E4) and the sampling camera: a frustum with the eye as
 *    apex that covers the intersection of the view frustum with the primary tangent cone
 *    (erratum E3), extended towards the nadir by the angle under which the tallest terrain
 *    below the frustum could rise into view, with the horizon kept level.
 *
 * All large values stay here in double; the shader receives small, eye-relative ones.
 * ComputeGridPoint() is the double-precision reference of what the grid shader computes.
 */
#ifndef vtkGlobeProjectiveGrid_h
#define vtkGlobeProjectiveGrid_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkCamera;
class vtkGlobeEllipsoid;
class vtkMatrix4x4;

class VTKGLOBERENDERING_EXPORT vtkGlobeProjectiveGrid : public vtkObject
{
public:
  static vtkGlobeProjectiveGrid* New();
  vtkTypeMacro(vtkGlobeProjectiveGrid, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The body (WGS84 unless set).
  void SetEllipsoid(vtkGlobeEllipsoid* ellipsoid);
  vtkGlobeEllipsoid* GetEllipsoid();
  ///@}

  ///@{
  /// zeta: the fraction of the primary tangent angle after which the secondary sphere blends in.
  vtkSetClampMacro(BlendThreshold, double, 0.05, 0.999);
  vtkGetMacro(BlendThreshold, double);
  ///@}

  ///@{
  /// Use the secondary sphere for terrain rising from behind the horizon (default on; off
  /// shows what it is for: peaks behind the horizon go missing).
  vtkSetMacro(UseSecondarySphere, bool);
  vtkGetMacro(UseSecondarySphere, bool);
  vtkBooleanMacro(UseSecondarySphere, bool);
  ///@}

  /**
   * Sets up the frame from a VTK camera. bodyToWorld is the actor's matrix (nullptr: identity),
   * aspect the viewport's aspect ratio, and the terrain heights (m) bound all visible terrain
   * from below (minimumHeight, the primary sphere) and all terrain from above (maximumHeight).
   * Returns false, with the reason in GetStatus(), when no globe can be drawn: a camera at the
   * centre, not finite, or with a parallel projection.
   */
  bool Update(vtkCamera* camera, vtkMatrix4x4* bodyToWorld, double aspect, double minimumHeight,
    double maximumHeight);

  /**
   * The same from explicit body-frame quantities: the eye (m), the four corner rays of the view
   * frustum (any length, in the order bottom-left, bottom-right, top-right, top-left) and the
   * view-up vector.
   */
  bool Update(const double eye[3], const double corners[12], const double viewUp[3],
    double minimumHeight, double maximumHeight);

  /// Why the last Update() failed, or "ok".
  const char* GetStatus() { return this->Status; }

  /// False when the body cannot be in view (looking away, or a failed Update()).
  vtkGetMacro(Visible, bool);

  ///@{
  /// Frame geometry, in the scaled space (unit-sphere units).
  vtkGetVector3Macro(EyeScaled, double);
  vtkGetMacro(Distance, double);
  vtkGetVector3Macro(Nadir, double);
  vtkGetMacro(PrimaryRadius, double);
  vtkGetMacro(SecondaryRadius, double); // <= 0: none
  vtkGetMacro(MaximumRadius, double);
  vtkGetMacro(Altitude, double);        // Distance - PrimaryRadius, computed exactly
  vtkGetMacro(PrimaryTangentAngle, double);
  vtkGetMacro(SecondaryTangentAngle, double);
  vtkGetMacro(BlendStart, double);          // b = zeta * tau_0
  vtkGetMacro(SecondaryBlendStart, double); // where the secondary sphere takes over (E4)
  vtkGetMacro(MaximumNormalAngle, double);  // gamma_0: no terrain is visible beyond it
  /// c - 1 = d / r - 1 for the primary and the secondary spheres, without cancellation.
  vtkGetMacro(PrimaryCMinusOne, double);
  vtkGetMacro(SecondaryCMinusOne, double);
  ///@}

  ///@{
  /// The sampling camera: forward, right and up unit vectors (scaled space) and the tangents
  /// of its asymmetric frustum, (x0, x1, y0, y1).
  vtkGetVector3Macro(SamplingForward, double);
  vtkGetVector3Macro(SamplingRight, double);
  vtkGetVector3Macro(SamplingUp, double);
  vtkGetVector4Macro(SamplingExtent, double);
  /// A unit vector perpendicular to the nadir, for rays parallel to it.
  vtkGetVector3Macro(NadirPerpendicular, double);
  ///@}

  /// The unit ray (scaled space) of the grid point at (u, v) in [0, 1]^2.
  void ComputeGridRay(double u, double v, double ray[3]);

  /**
   * How long the grid is on screen: the longest edge of the sampling camera's frustum seen
   * through the view, in pixels of a width x height viewport. `worldToClip` is the camera's
   * composite projection (world -> clip) and `bodyToWorld` the actor's matrix (nullptr: the
   * identity). +inf where a corner's direction points behind the eye, or before Update. The
   * mapper's automatic grid spaces its points over this span when it is shorter than the
   * viewport (a whole planet in part of the window).
   */
  double ComputeSamplingSpan(
    vtkMatrix4x4* worldToClip, vtkMatrix4x4* bodyToWorld, int width, int height);

  /**
   * The double-precision reference of the grid shader: for the grid point (u, v), the unit
   * direction from the body's centre (scaled space) of its reference point and the
   * reference point relative to the eye (scaled space, on the primary sphere). Returns false
   * for a miss, whose point is then the horizon point the grid shader gives it
   * (globe_pgmGridPoint: its triangles reach the limb).
   */
  bool ComputeGridPoint(double u, double v, double direction[3], double eyeRelative[3]);

protected:
  vtkGlobeProjectiveGrid();
  ~vtkGlobeProjectiveGrid() override;

  bool Fail(const char* status);
  void FitSamplingCamera(const double corners[4][3], const double viewUp[3]);

  vtkSmartPointer<vtkGlobeEllipsoid> Ellipsoid;
  double BlendThreshold = 0.9;
  bool UseSecondarySphere = true;
  const char* Status = "not updated";
  bool Visible = false;

  double EyeScaled[3] = { 0, 0, 0 };
  double Distance = 0;
  double Nadir[3] = { 0, 0, -1 };
  double NadirPerpendicular[3] = { 1, 0, 0 };
  double PrimaryRadius = 1;
  double SecondaryRadius = -1;
  double MaximumRadius = 1;
  double Altitude = 0;
  double PrimaryTangentAngle = 0;
  double SecondaryTangentAngle = 0;
  double BlendStart = 0;
  double SecondaryBlendStart = 0;
  double MaximumNormalAngle = 0;
  double PrimaryCMinusOne = 0;
  double SecondaryCMinusOne = 0;
  double SamplingForward[3] = { 0, 0, -1 };
  double SamplingRight[3] = { 1, 0, 0 };
  double SamplingUp[3] = { 0, 1, 0 };
  double SamplingExtent[4] = { -1, 1, -1, 1 };

private:
  vtkGlobeProjectiveGrid(const vtkGlobeProjectiveGrid&) = delete;
  void operator=(const vtkGlobeProjectiveGrid&) = delete;
};

#endif
