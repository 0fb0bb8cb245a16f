#include "vtkGlobeInteractorStyle.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkGlobeClippingRange.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobePointPicker.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkGlobeInteractorStyle);

namespace
{
// The camera in the body-fixed frame: eye, unit view direction, unit view-up (orthogonal).
struct BodyCamera
{
  double Eye[3];
  double Direction[3];
  double Up[3];
};

void Rotate(const double axis[3], double angle, const double v[3], double out[3])
{
  // Rodrigues' formula; axis is unit.
  const double c = std::cos(angle), s = std::sin(angle);
  double cross[3];
  vtkMath::Cross(axis, v, cross);
  const double d = vtkMath::Dot(axis, v);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = v[i] * c + cross[i] * s + axis[i] * d * (1 - c);
  }
}

// Rotates the camera rigidly about the line through `centre` along the unit `axis`.
void RotateAbout(BodyCamera& cam, const double centre[3], const double axis[3], double angle)
{
  double rel[3] = { cam.Eye[0] - centre[0], cam.Eye[1] - centre[1], cam.Eye[2] - centre[2] };
  Rotate(axis, angle, rel, rel);
  for (int i = 0; i < 3; ++i)
  {
    cam.Eye[i] = centre[i] + rel[i];
  }
  Rotate(axis, angle, cam.Direction, cam.Direction);
  Rotate(axis, angle, cam.Up, cam.Up);
}

// The smallest rotation (about the body centre) that takes direction a to direction b.
void RotateFromTo(BodyCamera& cam, const double a[3], const double b[3])
{
  double axis[3];
  vtkMath::Cross(a, b, axis);
  const double s = vtkMath::Normalize(axis);
  const double c = vtkMath::Dot(a, b) / (vtkMath::Norm(a) * vtkMath::Norm(b));
  if (s == 0.0)
  {
    return;
  }
  const double angle = std::atan2(s / (vtkMath::Norm(a) * vtkMath::Norm(b)), c);
  const double origin[3] = { 0, 0, 0 };
  RotateAbout(cam, origin, axis, angle);
}

// Nearest non-negative ray parameter where origin + t * dir (unit) meets the sphere of the
// given radius about the body centre: the entry point from outside, the exit from inside.
bool RaySphere(const double origin[3], const double dir[3], double radius, double& t)
{
  const double b = vtkMath::Dot(origin, dir);
  const double c = vtkMath::Dot(origin, origin) - radius * radius;
  const double disc = b * b - c;
  if (disc < 0)
  {
    return false;
  }
  const double root = std::sqrt(disc);
  t = c > 0 ? -b - root : -b + root;
  return t >= 0;
}
} // namespace

//------------------------------------------------------------------------------
// The geometry of one event: the camera in the body frame, and the way back to the world.
class vtkGlobeStyleFrame
{
public:
  vtkGlobeStyleFrame(vtkRenderer* renderer, vtkActor* actor, vtkGlobeMapper* mapper)
    : Renderer(renderer)
    , Mapper(mapper)
    , Body(mapper->GetEllipsoid())
  {
    if (actor)
    {
      this->BodyToWorld->DeepCopy(actor->GetMatrix());
    }
    vtkMatrix4x4::Invert(this->BodyToWorld, this->WorldToBody);
  }

  void ToBody(const double world[3], double body[3], double w) const
  {
    double in[4] = { world[0], world[1], world[2], w }, out[4];
    this->WorldToBody->MultiplyPoint(in, out);
    body[0] = out[0];
    body[1] = out[1];
    body[2] = out[2];
  }
  void ToWorld(const double body[3], double world[3], double w) const
  {
    double in[4] = { body[0], body[1], body[2], w }, out[4];
    this->BodyToWorld->MultiplyPoint(in, out);
    world[0] = out[0];
    world[1] = out[1];
    world[2] = out[2];
  }

  BodyCamera Get() const
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    BodyCamera c;
    double p[3], f[3], u[3];
    camera->GetPosition(p);
    camera->GetFocalPoint(f);
    camera->GetViewUp(u);
    this->ToBody(p, c.Eye, 1.0);
    double fb[3];
    this->ToBody(f, fb, 1.0);
    for (int i = 0; i < 3; ++i)
    {
      c.Direction[i] = fb[i] - c.Eye[i];
    }
    vtkMath::Normalize(c.Direction);
    this->ToBody(u, c.Up, 0.0);
    // Orthonormal up: the camera's own orthogonalization, in the body frame.
    double right[3];
    vtkMath::Cross(c.Direction, c.Up, right);
    vtkMath::Normalize(right);
    vtkMath::Cross(right, c.Direction, c.Up);
    vtkMath::Normalize(c.Up);
    return c;
  }

  void Set(const BodyCamera& c, double focalDistance) const
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    // The focal point only names the view direction: at least 100 m away, so that the
    // direction read back from the world's large coordinates keeps ~1e-11 rad.
    const double d = std::max(focalDistance, 100.0);
    double f[3] = { c.Eye[0] + d * c.Direction[0], c.Eye[1] + d * c.Direction[1],
      c.Eye[2] + d * c.Direction[2] };
    double p[3], fw[3], u[3];
    this->ToWorld(c.Eye, p, 1.0);
    this->ToWorld(f, fw, 1.0);
    this->ToWorld(c.Up, u, 0.0);
    camera->SetPosition(p);
    camera->SetFocalPoint(fw);
    camera->SetViewUp(u);
  }

  // The unit ray (body frame) from the eye through a display position, for a camera `c`
  // (set on the renderer's camera first: the display transform is the camera's).
  void Ray(double x, double y, const BodyCamera& c, double dir[3]) const
  {
    this->Set(c, this->Focal);
    double nearW[4], farW[4];
    this->Renderer->SetDisplayPoint(x, y, 0.0);
    this->Renderer->DisplayToWorld();
    this->Renderer->GetWorldPoint(nearW);
    this->Renderer->SetDisplayPoint(x, y, 1.0);
    this->Renderer->DisplayToWorld();
    this->Renderer->GetWorldPoint(farW);
    double n[3], f[3];
    for (int i = 0; i < 3; ++i)
    {
      n[i] = nearW[i] / nearW[3];
      f[i] = farW[i] / farW[3];
    }
    double nb[3], fb[3];
    this->ToBody(n, nb, 1.0);
    this->ToBody(f, fb, 1.0);
    for (int i = 0; i < 3; ++i)
    {
      dir[i] = fb[i] - nb[i];
    }
    vtkMath::Normalize(dir);
  }

  // The geodetic up at the eye.
  void LocalUp(const double p[3], double up[3], double east[3] = nullptr,
    double north[3] = nullptr) const
  {
    double llh[3], e[3], n[3];
    this->Body->CartesianToGeodeticQuiet(p, llh);
    this->Body->ComputeEastNorthUp(llh[0], llh[1], e, n, up);
    if (east)
    {
      std::copy(e, e + 3, east);
    }
    if (north)
    {
      std::copy(n, n + 3, north);
    }
  }

  // No roll: the right vector made horizontal by the smallest turn of the view direction, so
  // the view-up is the projection of the local up (stable at the nadir, where it keeps the
  // heading).
  void Level(BodyCamera& c) const
  {
    double up[3], right[3];
    this->LocalUp(c.Eye, up);
    vtkMath::Cross(c.Direction, c.Up, right);
    const double along = vtkMath::Dot(right, up);
    for (int i = 0; i < 3; ++i)
    {
      right[i] -= along * up[i];
    }
    if (vtkMath::Normalize(right) < 1e-6)
    {
      // Rolled by 90 degrees: the only horizontal right is across the view.
      vtkMath::Cross(c.Direction, up, right);
      if (vtkMath::Normalize(right) == 0.0)
      {
        return;
      }
    }
    const double d = vtkMath::Dot(c.Direction, right);
    for (int i = 0; i < 3; ++i)
    {
      c.Direction[i] -= d * right[i];
    }
    vtkMath::Normalize(c.Direction);
    vtkMath::Cross(right, c.Direction, c.Up);
    vtkMath::Normalize(c.Up);
    if (vtkMath::Dot(c.Up, up) < 0 && std::abs(vtkMath::Dot(c.Direction, up)) < 0.999)
    {
      // Upside down (looking above the horizon from a flipped camera): turn right over.
      for (int i = 0; i < 3; ++i)
      {
        c.Up[i] = -c.Up[i];
      }
      vtkMath::Cross(c.Direction, c.Up, right);
    }
  }

  double Terrain(double lon, double lat) const
  {
    bool exact = false;
    const double h = vtkGlobeClippingRange::ComputeTerrainHeight(this->Mapper, lon, lat, exact);
    return std::isfinite(h) ? h : 0.0;
  }

  // Height of p over terrain plus margin (negative: too low).
  double Clearance(const double p[3], double margin) const
  {
    double llh[3];
    if (!this->Body->CartesianToGeodeticQuiet(p, llh))
    {
      return 0.0;
    }
    return llh[2] - this->Terrain(llh[0], llh[1]) - margin;
  }

  // Moves the eye away from `anchor` along the line through both until it clears the
  // terrain plus margin: the anchor keeps its place on the screen. False when the line is
  // too flat to climb (the caller then lifts along the vertical).
  bool SlideClear(BodyCamera& c, const double anchor[3], double margin) const
  {
    double w[3] = { c.Eye[0] - anchor[0], c.Eye[1] - anchor[1], c.Eye[2] - anchor[2] };
    if (vtkMath::Normalize(w) == 0.0)
    {
      return false;
    }
    double p[3] = { c.Eye[0], c.Eye[1], c.Eye[2] };
    for (int k = 0; k < 20; ++k)
    {
      const double need = -this->Clearance(p, margin);
      if (need <= 0.0)
      {
        std::copy(p, p + 3, c.Eye);
        return true;
      }
      double up[3];
      this->LocalUp(p, up);
      const double climb = vtkMath::Dot(w, up);
      if (climb < 0.05)
      {
        return false;
      }
      // A millimetre beyond: the terrain may rise along the way.
      const double s = need / climb + 1e-3;
      for (int i = 0; i < 3; ++i)
      {
        p[i] += s * w[i];
      }
    }
    return false;
  }

  // Lifts the eye along its geodetic vertical to the terrain plus margin: the local up (and
  // so the roll) does not change. True when it moved.
  bool Lift(BodyCamera& c, double margin) const
  {
    double llh[3];
    if (!this->Body->CartesianToGeodeticQuiet(c.Eye, llh))
    {
      return false;
    }
    const double floor = this->Terrain(llh[0], llh[1]) + margin;
    if (llh[2] >= floor)
    {
      return false;
    }
    llh[2] = floor;
    this->Body->GeodeticToCartesianQuiet(llh, c.Eye);
    return true;
  }

  // Turns the camera about the body centre (and levels it) until the ray through (x, y)
  // meets `target` (body), climbing back along the ray when below the terrain. False when
  // the ray misses the sphere through the target (the camera is then unchanged).
  bool Regrab(BodyCamera& c, double x, double y, const double target[3], double margin) const
  {
    const double radius = vtkMath::Norm(target);
    BodyCamera work = c;
    for (int k = 0; k < 30; ++k)
    {
      double dir[3], t;
      this->Ray(x, y, work, dir);
      if (!RaySphere(work.Eye, dir, radius, t))
      {
        return false;
      }
      double q[3] = { work.Eye[0] + t * dir[0], work.Eye[1] + t * dir[1],
        work.Eye[2] + t * dir[2] };
      double miss[3] = { q[0] - target[0], q[1] - target[1], q[2] - target[2] };
      const double error = vtkMath::Norm(miss) / std::max(t, 1e-3);
      if (error < 1e-11)
      {
        c = work;
        return true;
      }
      RotateFromTo(work, q, target);
      this->Level(work);
      if (this->Clearance(work.Eye, margin) < 0.0)
      {
        this->SlideClear(work, target, margin);
        this->Level(work);
      }
    }
    // Not converged to 1e-11 rad; close enough to be used (the tests measure it).
    c = work;
    return true;
  }

  vtkRenderer* Renderer;
  vtkGlobeMapper* Mapper;
  vtkGlobeEllipsoid* Body;
  vtkNew<vtkMatrix4x4> BodyToWorld;
  vtkNew<vtkMatrix4x4> WorldToBody;
  double Focal = 1000.0;
};

//------------------------------------------------------------------------------
vtkGlobeInteractorStyle::vtkGlobeInteractorStyle()
{
  this->Picker = vtkGlobePointPicker::New();
}

vtkGlobeInteractorStyle::~vtkGlobeInteractorStyle()
{
  this->SetMapper(nullptr);
  this->Picker->Delete();
}

void vtkGlobeInteractorStyle::SetMapper(vtkGlobeMapper* mapper)
{
  if (this->Mapper == mapper)
  {
    return;
  }
  if (this->Mapper)
  {
    this->Mapper->UnRegister(this);
  }
  this->Mapper = mapper;
  if (this->Mapper)
  {
    this->Mapper->Register(this);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkGlobeInteractorStyle::Prepare(int x, int y)
{
  if (!this->Interactor)
  {
    return false;
  }
  this->FindPokedRenderer(x, y);
  vtkRenderer* renderer = this->CurrentRenderer;
  if (!renderer || !renderer->GetActiveCamera())
  {
    return false;
  }
  this->GlobeActor = vtkGlobeMapper::FindGlobeActor(renderer, this->Mapper);
  this->ActiveMapper = this->GlobeActor
    ? vtkGlobeMapper::SafeDownCast(this->GlobeActor->GetMapper())
    : this->Mapper;
  if (!this->ActiveMapper)
  {
    return false;
  }
  // The clipping policy from the first move on, not only from the globe's first frame.
  vtkGlobeClippingRange::Install(renderer);
  return true;
}

double vtkGlobeInteractorStyle::GetTerrainHeight(double lon, double lat)
{
  vtkGlobeMapper* mapper = this->Mapper ? this->Mapper : this->ActiveMapper;
  if (!mapper)
  {
    vtkErrorMacro(<< "GetTerrainHeight: no globe (SetMapper, or use the style on a renderer "
                     "with a vtkGlobeMapper)");
    return 0.0;
  }
  bool exact = false;
  return vtkGlobeClippingRange::ComputeTerrainHeight(mapper, lon, lat, exact);
}

bool vtkGlobeInteractorStyle::PickSurface(double x, double y, double world[3])
{
  vtkGlobeStyleFrame frame(this->CurrentRenderer, this->GlobeActor, this->ActiveMapper);
  if (this->Picker->Pick(x, y, 0.0, this->CurrentRenderer) && this->Picker->GetHit())
  {
    this->Picker->GetPickPosition(world);
    return true;
  }
  // Nothing drawn under the cursor (a frame not rendered yet, or beyond the terrain's
  // silhouette): the ellipsoid.
  BodyCamera c = frame.Get();
  double dir[3], t[2];
  frame.Ray(x, y, c, dir);
  if (frame.Body->IntersectRay(c.Eye, dir, t) == 0)
  {
    return false;
  }
  double p[3] = { c.Eye[0] + t[0] * dir[0], c.Eye[1] + t[0] * dir[1], c.Eye[2] + t[0] * dir[2] };
  frame.ToWorld(p, world, 1.0);
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeInteractorStyle::OnLeftButtonDown()
{
  const int* pos = this->Interactor->GetEventPosition();
  if (!this->Prepare(pos[0], pos[1]))
  {
    return;
  }
  this->GrabFocus(this->EventCallbackCommand);
  this->PressPosition[0] = pos[0];
  this->PressPosition[1] = pos[1];
  if (this->Interactor->GetControlKey() || this->Interactor->GetShiftKey())
  {
    this->OnMiddleButtonDown();
    return;
  }
  this->Grabbing = this->PickSurface(pos[0], pos[1], this->GrabbedPoint);
  this->StartRotate();
}

void vtkGlobeInteractorStyle::OnLeftButtonUp()
{
  if (this->Tilting)
  {
    this->OnMiddleButtonUp();
    return;
  }
  this->Grabbing = false;
  this->EndGesture(VTKIS_ROTATE);
}

void vtkGlobeInteractorStyle::EndGesture(int state)
{
  if (this->State == state)
  {
    this->StopState();
  }
  if (this->Interactor)
  {
    this->ReleaseFocus();
  }
}

void vtkGlobeInteractorStyle::OnMiddleButtonDown()
{
  const int* pos = this->Interactor->GetEventPosition();
  if (!this->Prepare(pos[0], pos[1]))
  {
    return;
  }
  this->GrabFocus(this->EventCallbackCommand);
  // The pivot: the terrain at the viewport's centre, moved onto the view axis so that turning
  // about it keeps the centre still.
  const int* size = this->CurrentRenderer->GetSize();
  const int* origin = this->CurrentRenderer->GetOrigin();
  double centre[2] = { origin[0] + 0.5 * size[0], origin[1] + 0.5 * size[1] };
  double world[3];
  this->PivotValid = this->PickSurface(centre[0], centre[1], world);
  if (this->PivotValid)
  {
    vtkGlobeStyleFrame frame(this->CurrentRenderer, this->GlobeActor, this->ActiveMapper);
    BodyCamera c = frame.Get();
    double p[3];
    frame.ToBody(world, p, 1.0);
    double rel[3] = { p[0] - c.Eye[0], p[1] - c.Eye[1], p[2] - c.Eye[2] };
    const double along = vtkMath::Dot(rel, c.Direction);
    for (int i = 0; i < 3; ++i)
    {
      this->Pivot[i] = c.Eye[i] + along * c.Direction[i];
    }
  }
  this->Tilting = true;
  this->StartSpin();
}

void vtkGlobeInteractorStyle::OnMiddleButtonUp()
{
  this->Tilting = false;
  this->EndGesture(VTKIS_SPIN);
}

void vtkGlobeInteractorStyle::OnRightButtonDown()
{
  const int* pos = this->Interactor->GetEventPosition();
  if (!this->Prepare(pos[0], pos[1]))
  {
    return;
  }
  this->GrabFocus(this->EventCallbackCommand);
  this->PressPosition[0] = pos[0];
  this->PressPosition[1] = pos[1];
  this->ZoomTargetValid = this->PickSurface(pos[0], pos[1], this->ZoomTarget);
  this->Zooming = true;
  this->StartDolly();
}

void vtkGlobeInteractorStyle::OnRightButtonUp()
{
  this->Zooming = false;
  this->EndGesture(VTKIS_DOLLY);
}

void vtkGlobeInteractorStyle::OnMouseWheelForward()
{
  this->WheelZoom(this->ZoomFactor);
}

void vtkGlobeInteractorStyle::OnMouseWheelBackward()
{
  // The exact inverse of one notch in: 1 / (1 - f) - 1 of the distance, outward.
  this->WheelZoom(-this->ZoomFactor / (1.0 - this->ZoomFactor));
}

void vtkGlobeInteractorStyle::WheelZoom(double factor)
{
  const int* pos = this->Interactor->GetEventPosition();
  if (!this->Prepare(pos[0], pos[1]))
  {
    return;
  }
  this->ZoomTargetValid = this->PickSurface(pos[0], pos[1], this->ZoomTarget);
  this->StartDolly();
  this->Zoom(pos[0], pos[1], this->ZoomTarget, this->ZoomTargetValid, factor);
  this->EndDolly();
}

//------------------------------------------------------------------------------
void vtkGlobeInteractorStyle::Zoom(
  double x, double y, const double target[3], bool targetValid, double factor)
{
  vtkGlobeStyleFrame frame(this->CurrentRenderer, this->GlobeActor, this->ActiveMapper);
  BodyCamera c = frame.Get();
  const double margin = this->MinimumHeightAboveTerrain;
  double llh[3];
  frame.Body->CartesianToGeodeticQuiet(c.Eye, llh);
  const double height = std::max(llh[2] - frame.Terrain(llh[0], llh[1]), margin);
  double p[3], dir[3], distance;
  if (targetValid)
  {
    frame.ToBody(target, p, 1.0);
    for (int i = 0; i < 3; ++i)
    {
      dir[i] = p[i] - c.Eye[i];
    }
    distance = vtkMath::Normalize(dir);
  }
  else
  {
    // Over the sky: along the cursor's ray, by the height.
    frame.Ray(x, y, c, dir);
    distance = height;
  }
  // The step: a fraction of the distance to the point, at most that of 10 heights above the
  // terrain (a point near the horizon is far; the step still shrinks with the height).
  double step = factor * std::min(distance, 10.0 * height);
  // Out: no farther than 100 body radii from the centre.
  const double limit = 100.0 * frame.Body->GetMaximumRadius();
  for (int i = 0; i < 3; ++i)
  {
    c.Eye[i] += step * dir[i];
  }
  if (vtkMath::Norm(c.Eye) > limit)
  {
    return;
  }
  this->LastMoveExact = true;
  if (targetValid)
  {
    // Level, then turn the target back under the cursor; back along the ray when too low.
    frame.Level(c);
    if (frame.Clearance(c.Eye, margin) < 0.0)
    {
      frame.SlideClear(c, p, margin);
    }
    if (!frame.Regrab(c, x, y, p, margin))
    {
      this->LastMoveExact = false;
      frame.Level(c);
    }
  }
  else
  {
    frame.Level(c);
  }
  if (frame.Lift(c, margin))
  {
    this->LastMoveExact = false;
  }
  frame.Set(c, targetValid ? distance - step : height);
  this->Finish();
}

void vtkGlobeInteractorStyle::OnMouseMove()
{
  // Between drags the globe found at the last press may be gone: touch it only while dragging.
  if (this->State == VTKIS_NONE || !this->CurrentRenderer || !this->ActiveMapper)
  {
    return;
  }
  const int* pos = this->Interactor->GetEventPosition();
  const int* last = this->Interactor->GetLastEventPosition();
  vtkGlobeStyleFrame frame(this->CurrentRenderer, this->GlobeActor, this->ActiveMapper);
  const double margin = this->MinimumHeightAboveTerrain;
  if (this->State == VTKIS_ROTATE && this->Grabbing)
  {
    BodyCamera c = frame.Get();
    const BodyCamera before = c;
    double g[3];
    frame.ToBody(this->GrabbedPoint, g, 1.0);
    this->LastMoveExact = frame.Regrab(c, pos[0], pos[1], g, margin);
    if (!this->LastMoveExact)
    {
      c = before; // beyond the sphere through the grabbed point: wait for the cursor
    }
    if (frame.Lift(c, margin))
    {
      this->LastMoveExact = false;
    }
    frame.Set(c, vtkMath::Distance2BetweenPoints(c.Eye, g) > 0
        ? std::sqrt(vtkMath::Distance2BetweenPoints(c.Eye, g))
        : 1000.0);
    this->Finish();
  }
  else if (this->State == VTKIS_SPIN && this->Tilting)
  {
    BodyCamera c = frame.Get();
    double pivot[3];
    if (this->PivotValid)
    {
      std::copy(this->Pivot, this->Pivot + 3, pivot);
    }
    else
    {
      // Over the sky: turn and tilt about the eye.
      std::copy(c.Eye, c.Eye + 3, pivot);
    }
    double up[3];
    frame.LocalUp(this->PivotValid ? pivot : c.Eye, up);
    // Turn: about the vertical through the pivot.
    const double turn = -(pos[0] - last[0]) * vtkMath::RadiansFromDegrees(this->TiltSpeed);
    RotateAbout(c, pivot, up, turn);
    // Tilt: about the horizontal right axis through the pivot, within 0..MaximumTilt. The tilt
    // is signed, positive toward the screen's top (the horizontal part of the view-up, defined
    // at the nadir too): at the nadir both senses give the same angle, and only one of them
    // keeps the view-up pointing up.
    auto tiltOf = [&](const BodyCamera& cam) {
      double h[3];
      const double along = vtkMath::Dot(cam.Up, up);
      for (int i = 0; i < 3; ++i)
      {
        h[i] = cam.Up[i] - along * up[i];
      }
      vtkMath::Normalize(h);
      return std::atan2(vtkMath::Dot(cam.Direction, h), -vtkMath::Dot(cam.Direction, up));
    };
    const double tilt = tiltOf(c);
    const double wanted = std::max(0.0,
      std::min(vtkMath::RadiansFromDegrees(this->MaximumTilt),
        tilt + (pos[1] - last[1]) * vtkMath::RadiansFromDegrees(this->TiltSpeed)));
    double right[3];
    vtkMath::Cross(c.Direction, c.Up, right);
    vtkMath::Normalize(right);
    BodyCamera plus = c, minus = c;
    RotateAbout(plus, pivot, right, wanted - tilt);
    RotateAbout(minus, pivot, right, tilt - wanted);
    c = std::abs(tiltOf(plus) - wanted) <= std::abs(tiltOf(minus) - wanted) ? plus : minus;
    frame.Level(c);
    frame.Lift(c, margin);
    double rel[3] = { pivot[0] - c.Eye[0], pivot[1] - c.Eye[1], pivot[2] - c.Eye[2] };
    frame.Set(c, this->PivotValid ? vtkMath::Norm(rel) : 1000.0);
    this->Finish();
  }
  else if (this->State == VTKIS_DOLLY && this->Zooming)
  {
    const double dy = pos[1] - last[1];
    if (dy == 0)
    {
      return;
    }
    // Up: in; 1 % of the distance per pixel, inverse moves undo each other.
    const double in = 1.0 - std::exp(-0.01 * dy);
    this->Zoom(this->PressPosition[0], this->PressPosition[1], this->ZoomTarget,
      this->ZoomTargetValid, std::max(-10.0, std::min(0.9, in)));
  }
}

//------------------------------------------------------------------------------
bool vtkGlobeInteractorStyle::EnforceConstraints()
{
  if (!this->CurrentRenderer && this->Interactor)
  {
    const int* pos = this->Interactor->GetEventPosition();
    this->FindPokedRenderer(pos[0], pos[1]);
  }
  if (!this->CurrentRenderer || !this->Prepare(0, 0))
  {
    vtkErrorMacro(<< "EnforceConstraints: no renderer with a globe");
    return false;
  }
  vtkGlobeStyleFrame frame(this->CurrentRenderer, this->GlobeActor, this->ActiveMapper);
  BodyCamera c = frame.Get();
  const BodyCamera before = c;
  frame.Level(c);
  frame.Lift(c, this->MinimumHeightAboveTerrain);
  double change = 0;
  for (int i = 0; i < 3; ++i)
  {
    change += std::abs(c.Eye[i] - before.Eye[i]) + std::abs(c.Up[i] - before.Up[i]) +
      std::abs(c.Direction[i] - before.Direction[i]);
  }
  if (change == 0)
  {
    return false;
  }
  frame.Set(c, this->CurrentRenderer->GetActiveCamera()->GetDistance());
  this->CurrentRenderer->ResetCameraClippingRange();
  return true;
}

void vtkGlobeInteractorStyle::Finish()
{
  // Always: the near plane must follow a camera that may now be metres over the ground.
  this->CurrentRenderer->ResetCameraClippingRange();
  if (this->Interactor->GetLightFollowCamera())
  {
    this->CurrentRenderer->UpdateLightsGeometryToFollowCamera();
  }
  this->Interactor->Render();
  // As VTK's styles do after each move: observers (and tests) see every step.
  this->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
}

//------------------------------------------------------------------------------
void vtkGlobeInteractorStyle::NorthUp()
{
  if (!this->Interactor || !this->Prepare(this->Interactor->GetEventPosition()[0],
                             this->Interactor->GetEventPosition()[1]))
  {
    vtkErrorMacro(<< "NorthUp: no renderer with a globe");
    return;
  }
  const int* size = this->CurrentRenderer->GetSize();
  const int* origin = this->CurrentRenderer->GetOrigin();
  double world[3];
  const bool onGround =
    this->PickSurface(origin[0] + 0.5 * size[0], origin[1] + 0.5 * size[1], world);
  vtkGlobeStyleFrame frame(this->CurrentRenderer, this->GlobeActor, this->ActiveMapper);
  BodyCamera c = frame.Get();
  double pivot[3];
  if (onGround)
  {
    double p[3];
    frame.ToBody(world, p, 1.0);
    double rel[3] = { p[0] - c.Eye[0], p[1] - c.Eye[1], p[2] - c.Eye[2] };
    const double along = vtkMath::Dot(rel, c.Direction);
    for (int i = 0; i < 3; ++i)
    {
      pivot[i] = c.Eye[i] + along * c.Direction[i];
    }
  }
  else
  {
    std::copy(c.Eye, c.Eye + 3, pivot);
  }
  double east[3], north[3], up[3];
  frame.LocalUp(pivot, up, east, north);
  // The heading: where the horizontal part of the view-up points (the view's heading when
  // tilted, the screen's up at the nadir).
  const double heading = std::atan2(vtkMath::Dot(c.Up, east), vtkMath::Dot(c.Up, north));
  BodyCamera a = c, b = c;
  RotateAbout(a, pivot, up, heading);
  RotateAbout(b, pivot, up, -heading);
  auto headingOf = [&](const BodyCamera& cam) {
    return std::abs(std::atan2(vtkMath::Dot(cam.Up, east), vtkMath::Dot(cam.Up, north)));
  };
  c = headingOf(a) <= headingOf(b) ? a : b;
  frame.Level(c);
  frame.Lift(c, this->MinimumHeightAboveTerrain);
  frame.Set(c, this->CurrentRenderer->GetActiveCamera()->GetDistance());
  this->Finish();
}

void vtkGlobeInteractorStyle::LookDown()
{
  if (!this->Interactor || !this->Prepare(this->Interactor->GetEventPosition()[0],
                             this->Interactor->GetEventPosition()[1]))
  {
    vtkErrorMacro(<< "LookDown: no renderer with a globe");
    return;
  }
  vtkGlobeStyleFrame frame(this->CurrentRenderer, this->GlobeActor, this->ActiveMapper);
  BodyCamera c = frame.Get();
  double east[3], north[3], up[3];
  frame.LocalUp(c.Eye, up, east, north);
  // Keep the heading: the horizontal part of the view-up (or of the view, looking up).
  double h[3];
  const double* from = std::abs(vtkMath::Dot(c.Up, up)) < 0.999 ? c.Up : c.Direction;
  const double along = vtkMath::Dot(from, up);
  for (int i = 0; i < 3; ++i)
  {
    h[i] = from[i] - along * up[i];
  }
  if (vtkMath::Normalize(h) < 1e-9)
  {
    std::copy(north, north + 3, h);
  }
  for (int i = 0; i < 3; ++i)
  {
    c.Direction[i] = -up[i];
    c.Up[i] = h[i];
  }
  frame.Lift(c, this->MinimumHeightAboveTerrain);
  double llh[3];
  frame.Body->CartesianToGeodeticQuiet(c.Eye, llh);
  frame.Set(c, llh[2] - frame.Terrain(llh[0], llh[1]));
  this->Finish();
}

void vtkGlobeInteractorStyle::ResetView()
{
  if (!this->Interactor || !this->Prepare(this->Interactor->GetEventPosition()[0],
                             this->Interactor->GetEventPosition()[1]))
  {
    vtkErrorMacro(<< "ResetView: no renderer with a globe");
    return;
  }
  vtkGlobeStyleFrame frame(this->CurrentRenderer, this->GlobeActor, this->ActiveMapper);
  BodyCamera c = frame.Get();
  double llh[3];
  if (!frame.Body->CartesianToGeodeticQuiet(c.Eye, llh))
  {
    llh[0] = llh[1] = 0.0;
  }
  // The body's bounding sphere in 80 % of the smaller field of view.
  vtkCamera* camera = this->CurrentRenderer->GetActiveCamera();
  double aspect[2];
  this->CurrentRenderer->GetAspect(aspect);
  double half = 0.5 * vtkMath::RadiansFromDegrees(camera->GetViewAngle());
  if (!camera->GetUseHorizontalViewAngle() && aspect[0] < 1.0)
  {
    half = std::atan(std::tan(half) * aspect[0]);
  }
  const double radius = frame.Body->GetMaximumRadius();
  const double distance = radius / std::sin(0.8 * half);
  double east[3], north[3], up[3];
  frame.Body->ComputeEastNorthUp(llh[0], llh[1], east, north, up);
  double surface[3];
  frame.Body->GeodeticToCartesian(llh[0], llh[1], 0.0, surface);
  for (int i = 0; i < 3; ++i)
  {
    c.Eye[i] = surface[i] + (distance - vtkMath::Norm(surface)) * up[i];
    c.Direction[i] = -up[i];
    c.Up[i] = north[i];
  }
  frame.Lift(c, this->MinimumHeightAboveTerrain);
  frame.Set(c, vtkMath::Norm(c.Eye));
  this->Finish();
}

void vtkGlobeInteractorStyle::OnChar()
{
  switch (this->Interactor->GetKeyCode())
  {
    case 'n':
    case 'N':
      this->NorthUp();
      break;
    case 'u':
    case 'U':
      this->LookDown();
      break;
    case 'r':
    case 'R':
      this->ResetView();
      break;
    case 'f':
    case 'F':
      break; // VTK's fly-to ignores the terrain
    default:
      this->Superclass::OnChar();
  }
}

//------------------------------------------------------------------------------
void vtkGlobeInteractorStyle::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper << "\n";
  os << indent << "MinimumHeightAboveTerrain: " << this->MinimumHeightAboveTerrain << "\n";
  os << indent << "ZoomFactor: " << this->ZoomFactor << "\n";
  os << indent << "TiltSpeed: " << this->TiltSpeed << "\n";
  os << indent << "MaximumTilt: " << this->MaximumTilt << "\n";
  os << indent << "Grabbing: " << this->Grabbing << "\n";
  os << indent << "LastMoveExact: " << this->LastMoveExact << "\n";
}
