#include "vtkGlobeProjectiveGrid.h"

#include "vtkCamera.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeShaderMath.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkGlobeProjectiveGrid);

namespace
{
using Vec = std::array<double, 3>;

Vec Make(const double v[3])
{
  return { v[0], v[1], v[2] };
}
Vec Add(const Vec& a, const Vec& b, double s = 1.0)
{
  return { a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2] };
}
Vec Scale(const Vec& a, double s)
{
  return { a[0] * s, a[1] * s, a[2] * s };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}
Vec Normalized(const Vec& a)
{
  const double n = Norm(a);
  return n > 0.0 ? Scale(a, 1.0 / n) : a;
}
void Copy(const Vec& a, double out[3])
{
  out[0] = a[0];
  out[1] = a[1];
  out[2] = a[2];
}
bool Finite(const Vec& a)
{
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}
/// Any unit vector perpendicular to the unit vector n.
Vec Perpendicular(const Vec& n)
{
  const Vec axis = std::abs(n[0]) < 0.6 ? Vec{ 1, 0, 0 } : Vec{ 0, 1, 0 };
  return Normalized(Add(axis, n, -Dot(axis, n)));
}
/// Angle between unit vectors, accurate everywhere (atan2 of sine and cosine).
double Angle(const Vec& a, const Vec& b)
{
  return std::atan2(Norm(Cross(a, b)), Dot(a, b));
}
} // namespace

//------------------------------------------------------------------------------
vtkGlobeProjectiveGrid::vtkGlobeProjectiveGrid()
{
  this->Ellipsoid = vtkSmartPointer<vtkGlobeEllipsoid>::New();
}

vtkGlobeProjectiveGrid::~vtkGlobeProjectiveGrid() = default;

void vtkGlobeProjectiveGrid::SetEllipsoid(vtkGlobeEllipsoid* ellipsoid)
{
  if (ellipsoid != this->Ellipsoid)
  {
    this->Ellipsoid = ellipsoid ? ellipsoid : vtkSmartPointer<vtkGlobeEllipsoid>::New().Get();
    this->Modified();
  }
}

vtkGlobeEllipsoid* vtkGlobeProjectiveGrid::GetEllipsoid()
{
  return this->Ellipsoid;
}

bool vtkGlobeProjectiveGrid::Fail(const char* status)
{
  this->Status = status;
  this->Visible = false;
  return false;
}

//------------------------------------------------------------------------------
bool vtkGlobeProjectiveGrid::Update(vtkCamera* camera, vtkMatrix4x4* bodyToWorld, double aspect,
  double minimumHeight, double maximumHeight)
{
  if (!camera)
  {
    return this->Fail("no camera");
  }
  if (camera->GetParallelProjection())
  {
    return this->Fail("parallel projection is not supported by projective grid mapping");
  }
  if (!(aspect > 0.0) || !std::isfinite(aspect))
  {
    return this->Fail("the viewport has no area");
  }
  // World -> body: the inverse of the actor's matrix.
  vtkNew<vtkMatrix4x4> worldToBody;
  if (bodyToWorld)
  {
    vtkMatrix4x4::Invert(bodyToWorld, worldToBody);
  }
  // Corner rays from the inverse of the camera's composite projection, in double.
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1), inverse);
  const double ndc[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
  double corners[12];
  const double* position = camera->GetPosition();
  double eyeWorld[4] = { position[0], position[1], position[2], 1.0 };
  for (int i = 0; i < 4; ++i)
  {
    double nearPoint[4] = { ndc[i][0], ndc[i][1], -1.0, 1.0 };
    double farPoint[4] = { ndc[i][0], ndc[i][1], 1.0, 1.0 };
    inverse->MultiplyPoint(nearPoint, nearPoint);
    inverse->MultiplyPoint(farPoint, farPoint);
    double dirWorld[4];
    for (int j = 0; j < 3; ++j)
    {
      dirWorld[j] = farPoint[j] / farPoint[3] - nearPoint[j] / nearPoint[3];
    }
    dirWorld[3] = 0.0;
    double dirBody[4];
    worldToBody->MultiplyPoint(dirWorld, dirBody);
    for (int j = 0; j < 3; ++j)
    {
      corners[3 * i + j] = dirBody[j];
    }
  }
  double eyeBody[4];
  worldToBody->MultiplyPoint(eyeWorld, eyeBody);
  double up[4] = { 0, 0, 0, 0 }, upBody[4];
  camera->GetViewUp(up);
  worldToBody->MultiplyPoint(up, upBody);
  return this->Update(eyeBody, corners, upBody, minimumHeight, maximumHeight);
}

//------------------------------------------------------------------------------
bool vtkGlobeProjectiveGrid::Update(const double eye[3], const double cornerRays[12],
  const double viewUp[3], double minimumHeight, double maximumHeight)
{
  const double* radii = this->Ellipsoid->GetRadii();
  const double minRadius = this->Ellipsoid->GetMinimumRadius();
  const Vec eyeScaled = { eye[0] / radii[0], eye[1] / radii[1], eye[2] / radii[2] };
  if (!Finite(eyeScaled))
  {
    return this->Fail("the camera position is not finite");
  }
  const double d = Norm(eyeScaled);
  if (!(d > 1e-9))
  {
    return this->Fail("the camera is at the centre of the body");
  }
  if (!std::isfinite(minimumHeight) || !std::isfinite(maximumHeight))
  {
    return this->Fail("the terrain height range is not finite");
  }
  Copy(eyeScaled, this->EyeScaled);
  this->Distance = d;
  const Vec nadir = Scale(eyeScaled, -1.0 / d);
  Copy(nadir, this->Nadir);
  Copy(Perpendicular(nadir), this->NadirPerpendicular);

  // Reference spheres in scaled units. A height h moves a point by at most |h| / minRadius.
  this->MaximumRadius = 1.0 + std::max(maximumHeight, 0.0) / minRadius;
  double rp = 1.0 + std::min(minimumHeight, maximumHeight) / minRadius;
  rp = std::max(rp, 1e-3);
  // The eye must be outside the primary sphere for front-facing hits to exist; a camera below
  // the lowest terrain (or inside the body) samples a sphere just beneath it.
  if (!(d > rp * (1.0 + 1e-12)))
  {
    rp = d / (1.0 + 1e-7);
  }
  this->PrimaryRadius = rp;
  this->Altitude = d - rp;
  this->PrimaryCMinusOne = this->Altitude / rp;
  this->PrimaryTangentAngle = std::asin(std::min(1.0, rp / d));
  this->BlendStart = this->BlendThreshold * this->PrimaryTangentAngle;

  // Secondary sphere (Mahsman §3.4.2): tangent where the primary's tangent ray leaves the
  // maximum sphere, gamma_0 = acos(r_p / d) + acos(r_p / r_max).
  const double rmax = std::max(this->MaximumRadius, rp);
  this->MaximumNormalAngle = std::acos(std::min(1.0, rp / d)) + std::acos(std::min(1.0, rp / rmax));
  const double rs = d * std::cos(this->MaximumNormalAngle);
  if (this->UseSecondarySphere && rs > 0.0 && rs < rp && this->MaximumNormalAngle < vtkMath::Pi() / 2)
  {
    this->SecondaryRadius = rs;
    this->SecondaryCMinusOne = (d - rs) / rs;
    this->SecondaryTangentAngle = std::asin(rs / d);
    // E4: start the secondary ray where its normal angle continues the primary's.
    const double gammaB = vtkGlobeShaderMath::d::globe_frontNormalAngle(
      d / rp, this->PrimaryCMinusOne, this->BlendStart);
    this->SecondaryBlendStart = std::min(this->SecondaryTangentAngle,
      vtkGlobeShaderMath::d::globe_rayAngleForNormalAngle(d / rs, gammaB));
  }
  else
  {
    this->SecondaryRadius = -1.0;
    this->SecondaryCMinusOne = 0.0;
    this->SecondaryTangentAngle = 0.0;
    this->SecondaryBlendStart = 0.0;
  }

  // The view frustum in scaled space: a linear map keeps planes planes.
  double corners[4][3];
  for (int i = 0; i < 4; ++i)
  {
    const Vec c = { cornerRays[3 * i] / radii[0], cornerRays[3 * i + 1] / radii[1],
      cornerRays[3 * i + 2] / radii[2] };
    if (!Finite(c) || Norm(c) == 0.0)
    {
      return this->Fail("the view frustum is degenerate");
    }
    Copy(Normalized(c), corners[i]);
  }
  const double up[3] = { viewUp[0] / radii[0], viewUp[1] / radii[1], viewUp[2] / radii[2] };
  this->FitSamplingCamera(corners, up);
  this->Status = this->Visible ? "ok" : "the body is not in view";
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeProjectiveGrid::FitSamplingCamera(const double cornerArray[4][3], const double viewUp[3])
{
  const Vec nadir = Make(this->Nadir);
  const double tau0 = this->PrimaryTangentAngle;
  Vec corners[4];
  for (int i = 0; i < 4; ++i)
  {
    corners[i] = Make(cornerArray[i]);
  }
  // Inward normals of the frustum's side planes, oriented with the frustum's centre ray.
  const Vec centre = Normalized(Add(Add(corners[0], corners[1]), Add(corners[2], corners[3])));
  Vec planes[4];
  for (int i = 0; i < 4; ++i)
  {
    planes[i] = Normalized(Cross(corners[(i + 1) % 4], corners[i]));
    if (Dot(planes[i], centre) < 0.0)
    {
      planes[i] = Scale(planes[i], -1.0);
    }
  }
  auto inFrustum = [&](const Vec& r) {
    for (const Vec& p : planes)
    {
      if (Dot(p, r) < -1e-12)
      {
        return false;
      }
    }
    return true;
  };
  auto inCone = [&](const Vec& r) { return Angle(r, nadir) <= tau0 * (1.0 + 1e-12); };

  // The intersection of the view frustum and the primary tangent cone (E3: the cone's corners
  // lie at -n, not +n): frustum edges inside the cone, cone boundary inside the frustum.
  std::vector<Vec> rays;
  const int samples = 32;
  for (int i = 0; i < 4; ++i)
  {
    for (int s = 0; s < samples; ++s)
    {
      const double t = static_cast<double>(s) / samples;
      const Vec r = Normalized(Add(Scale(corners[i], 1.0 - t), corners[(i + 1) % 4], t));
      if (inCone(r))
      {
        rays.push_back(r);
      }
    }
  }
  const Vec e1 = Make(this->NadirPerpendicular);
  const Vec e2 = Cross(nadir, e1);
  for (int s = 0; s < 4 * samples; ++s)
  {
    const double theta = 2.0 * vtkMath::Pi() * s / (4 * samples);
    const Vec r = Add(Scale(nadir, std::cos(tau0)),
      Add(Scale(e1, std::sin(tau0) * std::cos(theta)), e2, std::sin(tau0) * std::sin(theta)));
    if (inFrustum(r))
    {
      rays.push_back(r);
    }
  }
  if (inFrustum(nadir))
  {
    rays.push_back(nadir);
  }
  this->Visible = !rays.empty();
  if (!this->Visible)
  {
    return;
  }

  // Terrain below the frustum's lower edge can rise into view by at most the angle of the
  // height range seen from above the maximum sphere: tilt every ray that far towards the nadir.
  const double heightRange = this->MaximumRadius - this->PrimaryRadius;
  const double aboveMax = this->Distance - this->MaximumRadius;
  const double tilt = aboveMax > 0.0 ? std::atan2(heightRange, aboveMax) : vtkMath::Pi() / 2;
  if (tilt > 0.0)
  {
    const size_t count = rays.size();
    for (size_t i = 0; i < count; ++i)
    {
      const double omega = Angle(rays[i], nadir);
      if (omega <= 0.0)
      {
        continue;
      }
      const Vec k = Normalized(Add(rays[i], nadir, -Dot(rays[i], nadir)));
      const double w = omega - std::min(tilt, omega);
      rays.push_back(Add(Scale(nadir, std::cos(w)), k, std::sin(w)));
    }
  }

  // Forward: the mean ray. Roll: the anti-nadir projected on the image plane, so the horizon
  // stays level; looking along the nadir, the view-up instead.
  Vec forward = { 0, 0, 0 };
  for (const Vec& r : rays)
  {
    forward = Add(forward, r);
  }
  forward = Normalized(forward);
  if (!(Norm(forward) > 0.5))
  {
    forward = centre;
  }
  Vec up = Add(Scale(nadir, -1.0), forward, Dot(nadir, forward));
  if (Norm(up) < 1e-6)
  {
    const Vec vu = Make(viewUp);
    up = Add(vu, forward, -Dot(vu, forward));
    if (Norm(up) < 1e-9)
    {
      up = Perpendicular(forward);
    }
  }
  up = Normalized(up);
  const Vec right = Normalized(Cross(forward, up));
  up = Cross(right, forward);

  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Vec& r : rays)
  {
    // Rays more than ~87 degrees off the axis are clamped: a wider frustum has no tangent.
    const double z = std::max(Dot(r, forward), 0.05);
    const double x = Dot(r, right) / z;
    const double y = Dot(r, up) / z;
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
  // A margin of 1 % keeps the outermost rays inside the grid.
  const double mx = 0.01 * (x1 - x0) + 1e-9, my = 0.01 * (y1 - y0) + 1e-9;
  Copy(forward, this->SamplingForward);
  Copy(right, this->SamplingRight);
  Copy(up, this->SamplingUp);
  this->SamplingExtent[0] = x0 - mx;
  this->SamplingExtent[1] = x1 + mx;
  this->SamplingExtent[2] = y0 - my;
  this->SamplingExtent[3] = y1 + my;
}

//------------------------------------------------------------------------------
void vtkGlobeProjectiveGrid::ComputeGridRay(double u, double v, double ray[3])
{
  const double x = this->SamplingExtent[0] + u * (this->SamplingExtent[1] - this->SamplingExtent[0]);
  const double y = this->SamplingExtent[2] + v * (this->SamplingExtent[3] - this->SamplingExtent[2]);
  const Vec r = Normalized(Add(Add(Make(this->SamplingForward), Make(this->SamplingRight), x),
    Make(this->SamplingUp), y));
  Copy(r, ray);
}

double vtkGlobeProjectiveGrid::ComputeSamplingSpan(
  vtkMatrix4x4* worldToClip, vtkMatrix4x4* bodyToWorld, int width, int height)
{
  const double inf = std::numeric_limits<double>::infinity();
  if (!worldToClip || !this->Visible || width <= 0 || height <= 0)
  {
    return inf;
  }
  const double* radii = this->Ellipsoid->GetRadii();
  const double* e = this->SamplingExtent;
  const double corners[4][2] = { { e[0], e[2] }, { e[1], e[2] }, { e[1], e[3] }, { e[0], e[3] } };
  double screen[4][2];
  for (int i = 0; i < 4; ++i)
  {
    // A direction (w = 0): the eye's translation drops out, and the corner's point on screen is
    // its vanishing point.
    double d[4] = { 0, 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      d[k] = (this->SamplingForward[k] + corners[i][0] * this->SamplingRight[k] +
               corners[i][1] * this->SamplingUp[k]) *
        radii[k];
    }
    if (bodyToWorld)
    {
      bodyToWorld->MultiplyPoint(d, d);
    }
    double c[4];
    worldToClip->MultiplyPoint(d, c);
    if (!(c[3] > 1e-9 * (std::abs(c[0]) + std::abs(c[1]))))
    {
      return inf;
    }
    screen[i][0] = 0.5 * width * c[0] / c[3];
    screen[i][1] = 0.5 * height * c[1] / c[3];
  }
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    const int j = (i + 1) % 4;
    longest = std::max(longest,
      std::hypot(screen[j][0] - screen[i][0], screen[j][1] - screen[i][1]));
  }
  return std::isfinite(longest) ? longest : inf;
}

bool vtkGlobeProjectiveGrid::ComputeGridPoint(
  double u, double v, double direction[3], double eyeRelative[3])
{
  namespace D = vtkGlobeShaderMath::d;
  double r[3];
  this->ComputeGridRay(u, v, r);
  D::vec3 s, p;
  const double hit = D::globe_pgmGridPoint(D::vec3(r[0], r[1], r[2]),
    D::vec3(this->Nadir[0], this->Nadir[1], this->Nadir[2]),
    D::vec3(this->NadirPerpendicular[0], this->NadirPerpendicular[1], this->NadirPerpendicular[2]),
    this->Distance, this->PrimaryRadius, this->Altitude, this->PrimaryTangentAngle,
    this->BlendStart, this->SecondaryRadius, this->Distance - this->SecondaryRadius,
    this->SecondaryBlendStart, this->SecondaryTangentAngle, s, p);
  direction[0] = s.x, direction[1] = s.y, direction[2] = s.z;
  eyeRelative[0] = p.x, eyeRelative[1] = p.y, eyeRelative[2] = p.z;
  return hit > 0.5;
}

//------------------------------------------------------------------------------
void vtkGlobeProjectiveGrid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BlendThreshold: " << this->BlendThreshold << "\n";
  os << indent << "UseSecondarySphere: " << this->UseSecondarySphere << "\n";
  os << indent << "Status: " << this->Status << "\n";
  os << indent << "Visible: " << this->Visible << "\n";
  os << indent << "Distance (scaled): " << this->Distance << "\n";
  os << indent << "PrimaryRadius: " << this->PrimaryRadius << "\n";
  os << indent << "SecondaryRadius: " << this->SecondaryRadius << "\n";
  os << indent << "MaximumRadius: " << this->MaximumRadius << "\n";
  os << indent << "PrimaryTangentAngle: " << this->PrimaryTangentAngle << "\n";
  os << indent << "SamplingExtent: " << this->SamplingExtent[0] << ", " << this->SamplingExtent[1]
     << ", " << this->SamplingExtent[2] << ", " << this->SamplingExtent[3] << "\n";
}
