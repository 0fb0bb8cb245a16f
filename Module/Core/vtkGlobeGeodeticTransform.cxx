#include "vtkGlobeGeodeticTransform.h"

#include "vtkGlobeEllipsoid.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"

#include <cmath>

vtkStandardNewMacro(vtkGlobeGeodeticTransform);

//------------------------------------------------------------------------------
vtkGlobeGeodeticTransform::vtkGlobeGeodeticTransform()
{
  this->Ellipsoid = vtkSmartPointer<vtkGlobeEllipsoid>::New();
}

vtkGlobeGeodeticTransform::~vtkGlobeGeodeticTransform() = default;

//------------------------------------------------------------------------------
void vtkGlobeGeodeticTransform::SetEllipsoid(vtkGlobeEllipsoid* ellipsoid)
{
  if (ellipsoid == this->Ellipsoid && ellipsoid)
  {
    return;
  }
  this->Ellipsoid = ellipsoid ? ellipsoid : vtkSmartPointer<vtkGlobeEllipsoid>::New().Get();
  this->Modified();
}

vtkGlobeEllipsoid* vtkGlobeGeodeticTransform::GetEllipsoid()
{
  return this->Ellipsoid;
}

vtkMTimeType vtkGlobeGeodeticTransform::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Ellipsoid->GetMTime());
}

vtkAbstractTransform* vtkGlobeGeodeticTransform::MakeTransform()
{
  return vtkGlobeGeodeticTransform::New();
}

void vtkGlobeGeodeticTransform::InternalDeepCopy(vtkAbstractTransform* transform)
{
  auto* other = vtkGlobeGeodeticTransform::SafeDownCast(transform);
  if (!other)
  {
    vtkErrorMacro(<< "InternalDeepCopy: " << transform->GetClassName()
                  << " is not a vtkGlobeGeodeticTransform");
    return;
  }
  // Transforms share their body, as vtkGeoTransform shares its projections.
  this->SetEllipsoid(other->Ellipsoid);
  if (this->InverseFlag != other->InverseFlag)
  {
    this->Inverse();
  }
}

//------------------------------------------------------------------------------
void vtkGlobeGeodeticTransform::TransformPoints(vtkPoints* in, vtkPoints* out)
{
  vtkIdType bad = 0;
  const vtkIdType n = in->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    in->GetPoint(i, p);
    bad += !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
  }
  if (bad)
  {
    vtkErrorMacro(<< bad << " of " << n
                  << " input points have non-finite coordinates; they map to NaN");
  }
  this->Superclass::TransformPoints(in, out);
}

//------------------------------------------------------------------------------
namespace
{
/// d(xyz)/d(lon deg, lat deg, h): derivative[i][j] = d out_i / d in_j.
void GeodeticJacobian(const double radii[3], const double llh[3], double derivative[3][3])
{
  const double deg = vtkMath::Pi() / 180.0;
  const double lon = llh[0] * deg;
  const double lat = llh[1] * deg;
  const double n[3] = { std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
    std::sin(lat) };
  const double dn[2][3] = {
    { -std::cos(lat) * std::sin(lon), std::cos(lat) * std::cos(lon), 0.0 },
    { -std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat) }
  };
  double k[3];
  for (int i = 0; i < 3; ++i)
  {
    k[i] = radii[i] * radii[i] * n[i];
  }
  const double g = std::sqrt(vtkMath::Dot(k, n));
  // surface = k / g with k = R^2 n and g = sqrt(n . R^2 n):
  // d(surface) = R^2 dn / g - k (k . dn) / g^3.
  for (int j = 0; j < 2; ++j)
  {
    const double kdn = vtkMath::Dot(k, dn[j]);
    for (int i = 0; i < 3; ++i)
    {
      const double dSurface = radii[i] * radii[i] * dn[j][i] / g - k[i] * kdn / (g * g * g);
      derivative[i][j] = (dSurface + llh[2] * dn[j][i]) * deg;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    derivative[i][2] = n[i];
  }
}

template <typename T>
void ToDouble(const T in[3], double out[3])
{
  out[0] = in[0];
  out[1] = in[1];
  out[2] = in[2];
}

template <typename T>
void FromDouble(const double in[3], T out[3])
{
  out[0] = static_cast<T>(in[0]);
  out[1] = static_cast<T>(in[1]);
  out[2] = static_cast<T>(in[2]);
}
} // namespace

//------------------------------------------------------------------------------
void vtkGlobeGeodeticTransform::ForwardTransformPoint(const double in[3], double out[3])
{
  this->Ellipsoid->GeodeticToCartesianQuiet(in, out);
}

void vtkGlobeGeodeticTransform::ForwardTransformPoint(const float in[3], float out[3])
{
  double din[3], dout[3];
  ToDouble(in, din);
  this->ForwardTransformPoint(din, dout);
  FromDouble(dout, out);
}

void vtkGlobeGeodeticTransform::ForwardTransformDerivative(
  const double in[3], double out[3], double derivative[3][3])
{
  this->ForwardTransformPoint(in, out);
  GeodeticJacobian(this->Ellipsoid->GetRadii(), in, derivative);
}

void vtkGlobeGeodeticTransform::ForwardTransformDerivative(
  const float in[3], float out[3], float derivative[3][3])
{
  double din[3], dout[3], dd[3][3];
  ToDouble(in, din);
  this->ForwardTransformDerivative(din, dout, dd);
  FromDouble(dout, out);
  for (int i = 0; i < 3; ++i)
  {
    FromDouble(dd[i], derivative[i]);
  }
}

//------------------------------------------------------------------------------
void vtkGlobeGeodeticTransform::InverseTransformPoint(const double in[3], double out[3])
{
  this->Ellipsoid->CartesianToGeodeticQuiet(in, out);
}

void vtkGlobeGeodeticTransform::InverseTransformPoint(const float in[3], float out[3])
{
  double din[3], dout[3];
  ToDouble(in, din);
  this->InverseTransformPoint(din, dout);
  FromDouble(dout, out);
}

void vtkGlobeGeodeticTransform::InverseTransformDerivative(
  const double in[3], double out[3], double derivative[3][3])
{
  // vtkWarpTransform's contract: the forward Jacobian at the inverse point, which the base
  // class inverts. It is singular on the polar axis, where longitude is undefined.
  this->InverseTransformPoint(in, out);
  GeodeticJacobian(this->Ellipsoid->GetRadii(), out, derivative);
}

void vtkGlobeGeodeticTransform::InverseTransformDerivative(
  const float in[3], float out[3], float derivative[3][3])
{
  double din[3], dout[3], dd[3][3];
  ToDouble(in, din);
  this->InverseTransformDerivative(din, dout, dd);
  FromDouble(dout, out);
  for (int i = 0; i < 3; ++i)
  {
    FromDouble(dd[i], derivative[i]);
  }
}

//------------------------------------------------------------------------------
void vtkGlobeGeodeticTransform::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Ellipsoid:\n";
  this->Ellipsoid->PrintSelf(os, indent.GetNextIndent());
}
