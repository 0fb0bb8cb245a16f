/**
 * @class   vtkGlobeCamera
 * @brief   Camera helpers for a globe: look at a geodetic point from a range, heading and
 *          tilt, and the views of a smooth fly-to between two such views.
 *
 * A view is six numbers: the target's longitude and latitude (degrees) and ellipsoidal height
 * (m), the heading (degrees clockwise from north, the direction the camera looks along the
 * ground), the tilt (degrees from looking straight down: 0 = nadir, 90 = at the horizon) and
 * the range (m from the camera to the target).
 * @code
 *   double view[6] = { -121.7603, 46.8523, 4392.0, 30.0, 60.0, 15000.0 };
 *   vtkGlobeCamera::LookAt(renderer->GetActiveCamera(), mapper->GetEllipsoid(), view);
 * @endcode
 * LookAt places the camera in the body frame (a globe actor with an identity matrix), with the
 * local vertical as view-up (never rolled; north when looking straight down). It does not
 * reset the clipping range: call renderer->ResetCameraClippingRange() (vtkGlobeClippingRange).
 *
 * FrameExtent gives the nadir view that frames a geographic extent (a layer's, say).
 *
 * InterpolateView gives the view at fraction t of a fly-to: longitude and latitude along the
 * shorter way, heading the shorter turn, height and tilt linearly, the range geometrically and
 * raised in the middle by the distance covered (sin(pi t) times half the chord between the two
 * targets), so a long flight climbs out and descends as in Google Earth and Cesium. t is eased
 * (smoothstep). An application renders the views for t = k / n, k = 0..n, one per frame.
 */
#ifndef vtkGlobeCamera_h
#define vtkGlobeCamera_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkObject.h"

class vtkCamera;
class vtkGlobeEllipsoid;

class VTKGLOBERENDERING_EXPORT vtkGlobeCamera : public vtkObject
{
public:
  static vtkGlobeCamera* New();
  vtkTypeMacro(vtkGlobeCamera, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Places the camera for the view (lon, lat, height, heading, tilt, range); false (with an
  /// error) for a missing camera or body or a non-finite view, a range <= 0 or a tilt outside
  /// [0, 90).
  static bool LookAt(vtkCamera* camera, vtkGlobeEllipsoid* body, const double view[6]);
  static bool LookAt(vtkCamera* camera, vtkGlobeEllipsoid* body, double lon, double lat,
    double height, double heading, double tilt, double range);

  /**
   * The view straight down (heading 0, tilt 0) on the centre of a geographic extent (west,
   * east, south, north in degrees; west > east crosses 180 degrees) at `height`, from the
   * shortest range at which the extent, sampled 17 x 17 at that height, fits a perspective
   * camera of vertical view angle `viewAngle` (degrees) and aspect width / height, with 5 %
   * to spare. The centre is the direction of the samples' mean (a polar cap's is its pole).
   * Points near or past the body's horizon cannot be framed: an extent reaching more than 60
   * degrees around the body from its centre gets the whole body's disc instead. False (with an error) for a missing body or a
   * bad extent, angle or aspect. E.g. a layer's extent (vtkGlobeLayer::GetGeographicExtent).
   */
  static bool FrameExtent(vtkGlobeEllipsoid* body, const double extent[4], double height,
    double viewAngle, double aspect, double view[6]);

  /// The view at fraction t in [0, 1] of a fly-to from `from` to `to` (see above).
  static void InterpolateView(vtkGlobeEllipsoid* body, const double from[6], const double to[6],
    double t, double view[6]);

protected:
  vtkGlobeCamera() = default;
  ~vtkGlobeCamera() override = default;

private:
  vtkGlobeCamera(const vtkGlobeCamera&) = delete;
  void operator=(const vtkGlobeCamera&) = delete;
};

#endif
