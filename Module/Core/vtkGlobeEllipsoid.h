/**
 * @class   vtkGlobeEllipsoid
 * @brief   The shape of a planetary body: geodetic <-> body-fixed Cartesian conversions.
 *
 * A body is an ellipsoid with semi-axes a (along x), b (along y) and c (along z, the polar
 * axis), centred at the origin of its body-fixed frame. Presets give WGS84, GRS80, Mars
 * (IAU 2000) and the Moon; any positive, finite a, b, c is accepted, including prolate
 * (c > a) and triaxial (a != b) bodies.
 *
 * Geodetic coordinates are longitude and latitude in degrees and height in metres along the
 * geodetic surface normal (the normal of the ellipsoid at the foot point). For a point with
 * several foot points (inside the evolute, near the centre) the nearest one is used, so the
 * height is minus the distance to the surface.
 *
 * Biaxial bodies (a == b) use GeographicLib::Geocentric. Triaxial bodies use a bracketed
 * Newton iteration for the nearest surface point (Eberly's formulation) that always
 * terminates: a capped iteration count, and closed forms for the degenerate planes and the
 * centre, where the plain Newton method of Cozzi & Ring never returns.
 *
 * Conversions taking non-finite input write NaN and return false after a vtkErrorMacro.
 */
#ifndef vtkGlobeEllipsoid_h
#define vtkGlobeEllipsoid_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // for VTK_SIZEHINT

#include <memory> // for std::unique_ptr

class vtkMatrix4x4;

class VTKGLOBECORE_EXPORT vtkGlobeEllipsoid : public vtkObject
{
public:
  /// A new ellipsoid is WGS84.
  static vtkGlobeEllipsoid* New();
  vtkTypeMacro(vtkGlobeEllipsoid, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Presets. WGS84 and GRS80: a = 6,378,137 m with the flattening of each datum. Mars:
   * IAU 2000, 3,396,190 m x 3,376,200 m. Moon: a 1,737,400 m sphere.
   */
  void SetToWGS84();
  void SetToGRS80();
  void SetToMars();
  void SetToMoon();
  ///@}

  /**
   * Set the semi-axes in metres. Each must be finite and positive; otherwise the ellipsoid
   * is left unchanged, an error is reported and false is returned. The name is cleared.
   */
  bool SetRadii(double a, double b, double c);
  bool SetRadii(const double radii[3]) { return this->SetRadii(radii[0], radii[1], radii[2]); }
  vtkGetVector3Macro(Radii, double);

  /// A display name ("WGS84", "Mars", ...); empty for custom radii.
  vtkSetStringMacro(Name);
  vtkGetStringMacro(Name);

  ///@{
  /// Shape queries.
  bool IsSphere() const;
  bool IsBiaxial() const;  // a == b (spheres included)
  bool IsTriaxial() const; // a != b
  bool IsProlate() const;  // c larger than both a and b
  double GetMinimumRadius() const;
  double GetMaximumRadius() const;
  /// (a - c) / a; negative for a prolate body. Meaningful for biaxial bodies.
  double GetFlattening() const;
  ///@}

  ///@{
  /**
   * Use GeographicLib for biaxial bodies (default on). Off forces the general solver used
   * for triaxial bodies; the tests use this to check that solver against GeographicLib.
   */
  vtkSetMacro(UseGeographicLib, bool);
  vtkGetMacro(UseGeographicLib, bool);
  vtkBooleanMacro(UseGeographicLib, bool);
  ///@}

  ///@{
  /// (longitude deg, latitude deg, height m) -> body-fixed (x, y, z) m.
  bool GeodeticToCartesian(const double lonLatHeight[3], double xyz[3]);
  bool GeodeticToCartesian(double lon, double lat, double height, double xyz[3]);
  ///@}

  /// Body-fixed (x, y, z) m -> (longitude deg in [-180, 180], latitude deg, height m).
  bool CartesianToGeodetic(const double xyz[3], double lonLatHeight[3]);

  ///@{
  /**
   * The same conversions as return values (Python: `xyz = body.GeodeticToCartesian(lon, lat,
   * h)`, a tuple): the result lives in this object until its next call (VTK's idiom, not
   * thread-safe); NaN where the out-parameter form returns false. The out-parameter forms stay
   * for C++ and for threads.
   */
  double* GeodeticToCartesian(double lon, double lat, double height) VTK_SIZEHINT(3);
  double* CartesianToGeodetic(double x, double y, double z) VTK_SIZEHINT(3);
  ///@}

  /// Unit geodetic surface normal at (longitude, latitude) in degrees.
  void GeodeticSurfaceNormal(double lon, double lat, double normal[3]);

  /// Unit normal of the ellipsoid at its surface point nearest to xyz.
  bool GeodeticSurfaceNormalAt(const double xyz[3], double normal[3]);

  /// The surface point whose geodetic normal passes through xyz (the nearest one).
  bool ScaleToGeodeticSurface(const double xyz[3], double surface[3]);

  /// The surface point on the line from the centre through xyz. Fails at the centre.
  bool ScaleToGeocentricSurface(const double xyz[3], double surface[3]);

  /**
   * Local east-north-up unit vectors at (longitude, latitude) in degrees. At the poles east
   * is taken as the direction of increasing longitude at the given longitude.
   */
  void ComputeEastNorthUp(double lon, double lat, double east[3], double north[3], double up[3]);

  /**
   * The 4x4 transform from the local east-north-up frame at (lon, lat, height) to the
   * body-fixed frame: columns are east, north, up and the origin.
   */
  bool ComputeLocalFrame(double lon, double lat, double height, vtkMatrix4x4* enuToBody);

  /**
   * Intersections of the ray origin + t * direction (direction need not be unit) with the
   * ellipsoid surface: returns how many (0, 1 or 2) with t >= 0, nearest first in t.
   */
  int IntersectRay(const double origin[3], const double direction[3], double t[2]);

  ///@{
  /**
   * The quiet conversions that the methods above and vtkGlobeGeodeticTransform use: no
   * error reporting, NaN output and false for non-finite input. Thread-safe.
   */
  bool GeodeticToCartesianQuiet(const double lonLatHeight[3], double xyz[3]) const;
  bool CartesianToGeodeticQuiet(const double xyz[3], double lonLatHeight[3]) const;
  ///@}

  /**
   * The point of the surface nearest to xyz (the foot of the surface normal through it), for
   * any radii, triaxial included: writes it and returns the number of root-finder iterations,
   * or -1 for non-finite input or radii. Public on purpose: it is the direct answer to "where
   * is the ground below this point", cheaper than CartesianToGeodetic followed by
   * GeodeticToCartesian, and the iteration count lets a caller see how hard the point was.
   */
  static int NearestSurfacePoint(const double radii[3], const double xyz[3], double surface[3]);

protected:
  vtkGlobeEllipsoid();
  ~vtkGlobeEllipsoid() override;

  void ApplyRadii(double a, double b, double c, const char* name);

  double Radii[3];
  double Result[3] = { 0, 0, 0 }; // the return-value forms' result
  char* Name = nullptr;
  bool UseGeographicLib = true;

private:
  vtkGlobeEllipsoid(const vtkGlobeEllipsoid&) = delete;
  void operator=(const vtkGlobeEllipsoid&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
