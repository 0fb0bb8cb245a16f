/**
 * @class   vtkGlobeClippingRange
 * @brief   The camera clipping range for scenes with a globe: near from the height over the
 *          terrain, far from the horizon.
 *
 * VTK's ResetCameraClippingRange fits the near and far planes to the bounding boxes of the
 * props and keeps near >= 0.001 far (24-bit depth): with a planet's bounds the near plane is
 * thousands of metres away and terrain under a low camera is clipped. This policy replaces the
 * range whenever the renderer resets it (it observes vtkCommand::ResetCameraClippingRangeEvent
 * and ResetCameraEvent, fired at the end of VTK's own computation):
 *  - near: for each globe, the camera's distance to the nearest terrain it could see, bounded
 *    below by its geodetic height over the tallest data within a window around the nadir
 *    (sampled from the height layers) and over the tallest data anywhere, times the cosine of
 *    the frustum's half diagonal (z along the view, not distance); or, where larger, a lower
 *    bound of the z of the terrain inside the frustum within 100 km (a best-first quadtree of
 *    the layers' height bounds); times NearSafety; for other props the nearest corner of their
 *    bounds along the view; at least MinimumNear;
 *  - far: for each globe, the distance to the horizon of the lowest terrain plus the distance
 *    from there to where the tallest data can rise into view (sqrt(d^2 - r_min^2) +
 *    sqrt(r_max^2 - r_min^2)), and never beyond the far side of the body's bounding sphere;
 *    for other props the farthest corner of their bounds; times 1.01.
 *
 * A vtkGlobeMapper installs the policy on its renderer when it first renders, so interaction
 * (interactor styles reset the range on every move) needs no user code. Before the first
 * render, install it with the one call
 * @code
 *   vtkGlobeClippingRange::Install(renderer);
 * @endcode
 * Explicit camera->SetClippingRange() calls are left alone.
 */
#ifndef vtkGlobeClippingRange_h
#define vtkGlobeClippingRange_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkObject.h"

class vtkActor;
class vtkGlobeMapper;
class vtkInformationObjectBaseKey;
class vtkRenderer;

class VTKGLOBERENDERING_EXPORT vtkGlobeClippingRange : public vtkObject
{
public:
  static vtkGlobeClippingRange* New();
  vtkTypeMacro(vtkGlobeClippingRange, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Makes the renderer's ResetCameraClippingRange()/ResetCamera() use the policy (once per
   * renderer; later calls return the installed policy). Returns the policy (owned by the
   * renderer).
   */
  static vtkGlobeClippingRange* Install(vtkRenderer* renderer);

  /// The policy installed on a renderer, or nullptr.
  static vtkGlobeClippingRange* GetInstalled(vtkRenderer* renderer);

  /**
   * The range for the renderer's active camera: true and range set when a visible globe is in
   * the scene and the camera is a perspective one; false otherwise (range untouched).
   */
  bool ComputeRange(vtkRenderer* renderer, double range[2]);

  /// ComputeRange() and, when it succeeds, set it on the active camera.
  bool Apply(vtkRenderer* renderer);

  /**
   * The nearest and farthest eye distances (m, along the view axis) one globe actor can have
   * for this camera: the globe's part of ComputeRange(). False if the globe cannot be in view.
   */
  bool ComputeGlobeRange(vtkRenderer* renderer, vtkActor* actor, vtkGlobeMapper* mapper,
    double range[2]);

  /**
   * The composed terrain height (m) at (lon, lat) in degrees: the mapper's vtkGlobeTerrain
   * (the GPU's composition rules on the CPU), `exact` true; where it has no answer (a
   * streamed page that cannot be read), an upper bound, the tallest data there, `exact` false.
   */
  static double ComputeTerrainHeight(vtkGlobeMapper* mapper, double lon, double lat, bool& exact);

  ///@{
  /// The smallest near plane (m, default 0.01).
  vtkSetClampMacro(MinimumNear, double, 1e-6, 1e30);
  vtkGetMacro(MinimumNear, double);
  ///@}

  ///@{
  /// Fraction of the computed nearest distance used as the near plane (default 0.9): room for
  /// the mesh's chords and heights between data posts.
  vtkSetClampMacro(NearSafety, double, 1e-3, 1.0);
  vtkGetMacro(NearSafety, double);
  ///@}

  /// Number of times the policy set a range: public so that an application can confirm the
  /// policy is attached and runs (a renderer may reset its range in ResetCameraClippingRange).
  vtkGetMacro(NumberOfApplications, int);

  static vtkInformationObjectBaseKey* POLICY();

protected:
  vtkGlobeClippingRange();
  ~vtkGlobeClippingRange() override;

  double MinimumNear = 0.01;
  double NearSafety = 0.9;
  int NumberOfApplications = 0;

private:
  vtkGlobeClippingRange(const vtkGlobeClippingRange&) = delete;
  void operator=(const vtkGlobeClippingRange&) = delete;
};

#endif
