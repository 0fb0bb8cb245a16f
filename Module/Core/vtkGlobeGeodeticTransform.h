/**
 * @class   vtkGlobeGeodeticTransform
 * @brief   Maps (longitude deg, latitude deg, height m) point coordinates onto a body.
 *
 * The forward transform takes points whose coordinates are geodetic longitude and latitude
 * in degrees and height in metres, and returns body-fixed Cartesian coordinates in metres on
 * the transform's vtkGlobeEllipsoid (WGS84 unless set). Inverse() gives the reverse mapping,
 * computed exactly (not by the generic Newton iteration of vtkWarpTransform). Use it with
 * vtkTransformFilter to put lon/lat/height data (tracks, cities, grids) on the globe;
 * request double-precision output points there, since float resolves only ~0.5 m at the
 * radius of the Earth.
 *
 * Non-finite input points map to NaN; TransformPoints() reports how many there were.
 */
#ifndef vtkGlobeGeodeticTransform_h
#define vtkGlobeGeodeticTransform_h

#include "vtkGlobeCoreModule.h" // for export macro
#include "vtkSmartPointer.h"    // for vtkSmartPointer
#include "vtkWarpTransform.h"

class vtkGlobeEllipsoid;

class VTKGLOBECORE_EXPORT vtkGlobeGeodeticTransform : public vtkWarpTransform
{
public:
  static vtkGlobeGeodeticTransform* New();
  vtkTypeMacro(vtkGlobeGeodeticTransform, vtkWarpTransform);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The body. Setting nullptr restores a WGS84 ellipsoid.
  void SetEllipsoid(vtkGlobeEllipsoid* ellipsoid);
  vtkGlobeEllipsoid* GetEllipsoid();
  ///@}

  vtkAbstractTransform* MakeTransform() override;
  vtkMTimeType GetMTime() override;

  /// Transforms the points and reports (once) how many inputs were not finite.
  void TransformPoints(vtkPoints* in, vtkPoints* out) override;

protected:
  vtkGlobeGeodeticTransform();
  ~vtkGlobeGeodeticTransform() override;

  void InternalDeepCopy(vtkAbstractTransform* transform) override;

  void ForwardTransformPoint(const float in[3], float out[3]) override;
  void ForwardTransformPoint(const double in[3], double out[3]) override;
  void ForwardTransformDerivative(const float in[3], float out[3], float derivative[3][3]) override;
  void ForwardTransformDerivative(
    const double in[3], double out[3], double derivative[3][3]) override;
  void InverseTransformPoint(const float in[3], float out[3]) override;
  void InverseTransformPoint(const double in[3], double out[3]) override;
  void InverseTransformDerivative(const float in[3], float out[3], float derivative[3][3]) override;
  void InverseTransformDerivative(
    const double in[3], double out[3], double derivative[3][3]) override;

  vtkSmartPointer<vtkGlobeEllipsoid> Ellipsoid;

private:
  vtkGlobeGeodeticTransform(const vtkGlobeGeodeticTransform&) = delete;
  void operator=(const vtkGlobeGeodeticTransform&) = delete;
};

#endif
