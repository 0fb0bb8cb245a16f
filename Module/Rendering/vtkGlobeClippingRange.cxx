#include "vtkGlobeClippingRange.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGeoid.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobeTerrain.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkGlobeClippingRange);
vtkInformationKeyMacro(vtkGlobeClippingRange, POLICY, ObjectBase);

vtkGlobeClippingRange::vtkGlobeClippingRange() = default;
vtkGlobeClippingRange::~vtkGlobeClippingRange() = default;

namespace
{
void OnReset(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* policy = static_cast<vtkGlobeClippingRange*>(clientData);
  if (auto* renderer = vtkRenderer::SafeDownCast(caller))
  {
    policy->Apply(renderer);
  }
}

/// The composed terrain around a point, as far as the CPU can bound it.
struct LocalTerrain
{
  double Top = 0.0;    // tallest composed height in the window (m)
  double Nadir = 0.0;  // composed height at the point (valid when Exact)
  double Slope = 0.0;  // steepest slope in the window (valid when Exact)
  bool Exact = false;  // one layer replaces all below over the whole window
};

/**
 * Bounds the composed terrain within `radius` metres of (lon, lat). Layers compose in
 * vtkGlobeLayerSet's order (DrawOrder, then as added), each by its blend mode and weight
 * (coverage: extent, voids, an 8-texel feathered border; times opacity):
 * - Replace mixes towards the layer: one that covers the whole window with full weight decides
 *   the terrain there (its bilinear height at the point, its posts' maximum and slope); with
 *   less weight somewhere the result is at most the larger of the two maxima;
 * - Add adds weight * value: the maximum grows by the layer's maximum (by its positive part
 *   where the weight may be below 1); with full weight the point and slope add exactly;
 * - Average (a run of layers replaced by their weighted mean) is at most the larger maximum.
 * Layers that cannot be sampled in longitude/latitude (projected ones, missing data) enter with
 * their data maximum by the same rules, so the near plane stays in front of them.
 */
LocalTerrain ComputeLocalTerrain(vtkGlobeMapper* mapper, double lon, double lat, double radius,
  double metresPerDegree)
{
  LocalTerrain result;
  result.Exact = true; // composition starts from 0 everywhere
  std::vector<vtkGlobeLayer*> order;
  for (int l = 0; l < mapper->GetNumberOfLayers(); ++l)
  {
    vtkGlobeLayer* layer = mapper->GetLayer(l);
    if (layer && layer->GetRole() == vtkGlobeLayer::Height && layer->GetEnabled() &&
      layer->IsValid())
    {
      order.push_back(layer);
    }
  }
  std::stable_sort(order.begin(), order.end(),
    [](vtkGlobeLayer* a, vtkGlobeLayer* b) { return a->GetDrawOrder() < b->GetDrawOrder(); });
  // A layer's window maximum (and, with full weight, its point height and slope) into the
  // result by its blend mode.
  auto compose = [&result](vtkGlobeLayer* layer, bool fullWeight, double top, bool exact,
                   double nadir, double slope) {
    const bool full = fullWeight && layer->GetOpacity() >= 1.0;
    switch (layer->GetBlendMode())
    {
      case vtkGlobeLayer::Add:
        result.Top += full ? top : std::max(0.0, top);
        result.Exact = result.Exact && full && exact;
        result.Nadir += nadir;
        result.Slope += slope;
        break;
      case vtkGlobeLayer::Average:
        result.Top = std::max(result.Top, top);
        result.Exact = false;
        break;
      default:
        if (full)
        {
          result.Top = top;
          result.Exact = exact;
          result.Nadir = nadir;
          result.Slope = slope;
        }
        else
        {
          result.Top = std::max(result.Top, top);
          result.Exact = false;
        }
    }
  };
  for (vtkGlobeLayer* layer : order)
  {
    // Heights above a geoid: N at the point, and at most its steepest slope further over the
    // window (the geoid is smooth: EGM96's slopes stay below 1e-3).
    // A layer whose geoid cannot be read is not drawn (vtkGlobeLayerSet skips it); where a
    // regional geoid has no N the layer has no weight, so it replaces nothing there.
    double geoidTop = 0.0, geoidAt = 0.0, geoidSlope = 0.0;
    bool geoidCovers = true;
    if (vtkGlobeGeoid* geoid = layer->GetGeoid())
    {
      if (!geoid->IsValid())
      {
        continue;
      }
      geoidAt = geoid->GetUndulation(lon, lat);
      geoidSlope = geoid->GetMaximumSlope();
      geoidCovers = std::isfinite(geoidAt);
      geoidTop = geoidCovers ? geoidAt + geoidSlope * radius : geoid->GetRange()[1];
      geoidAt = geoidCovers ? geoidAt : 0.0;
    }
    double e[4];
    layer->GetGeographicExtent(e);
    vtkDataArray* data = layer->GetData();
    const int w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
    if (layer->GetModelType() != vtkGlobeLayer::Geographic || !data || w <= 0 || h <= 0 ||
      !std::isfinite(e[0]) || !std::isfinite(e[3]))
    {
      const double top = layer->GetMaximumValue() +
        (layer->GetGeoid() ? layer->GetGeoid()->GetRange()[1] : 0.0);
      compose(layer, false, top, false, 0.0, 0.0);
      continue;
    }
    const double cosLat = std::max(std::cos(vtkMath::RadiansFromDegrees(lat)), 1e-3);
    const double dLat = radius / metresPerDegree;
    const double dLon = dLat / cosLat;
    const double texelX = (e[1] - e[0]) / w, texelY = (e[3] - e[2]) / h;
    const bool global = layer->IsGlobal();
    double x = lon - e[0];
    if (global)
    {
      x = std::fmod(x + 720.0, 360.0);
    }
    const double y = e[3] - lat; // degrees south of the north edge
    if ((!global && (x + dLon < 0.0 || x - dLon > e[1] - e[0])) || y + dLat < 0.0 ||
      y - dLat > e[3] - e[2])
    {
      continue; // the window misses the layer
    }
    // Full weight: inside the extent by more than the feathered border, and no voids left
    // (unfilled voids would let the layer below through).
    const double borderX = 9.0 * texelX, borderY = 9.0 * texelY;
    const bool fullLon = global || (x - dLon >= borderX && x + dLon <= e[1] - e[0] - borderX);
    const bool fullLat = (e[2] <= -90.0 && e[3] >= 90.0) ||
      (y - dLat >= borderY && y + dLat <= e[3] - e[2] - borderY);
    // A reprojected layer has no value outside its source's footprint (unfilled NaN).
    const bool replaces = fullLon && fullLat && geoidCovers &&
      !layer->IsReprojected() &&
      (layer->GetNumberOfVoids() == 0 || layer->GetFillVoids());
    // More than 64 texels each way: the layer's maximum is a good enough bound.
    if (dLon > 64.0 * texelX || dLat > 64.0 * texelY)
    {
      compose(layer, replaces, layer->GetMaximumValue() + geoidTop, false, 0.0, 0.0);
      continue;
    }
    auto at = [&](int i, int j) {
      i = global ? ((i % w) + w) % w : std::max(0, std::min(i, w - 1));
      j = std::max(0, std::min(j, h - 1));
      const double v = data->GetComponent(static_cast<vtkIdType>(j) * w + i, 0);
      return std::isfinite(v) ? v : 0.0;
    };
    // Posts sit at texel centres; bilinear terrain between them.
    const int i0 = static_cast<int>(std::floor((x - dLon) / texelX - 0.5));
    const int i1 = static_cast<int>(std::floor((x + dLon) / texelX - 0.5)) + 1;
    const int j0 = static_cast<int>(std::floor((y - dLat) / texelY - 0.5));
    const int j1 = static_cast<int>(std::floor((y + dLat) / texelY - 0.5)) + 1;
    const double mx = texelX * metresPerDegree * cosLat, my = texelY * metresPerDegree;
    double top = -VTK_DOUBLE_MAX, slope = 0.0;
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const double v = at(i, j);
        top = std::max(top, v);
        const double sx = i < i1 ? (at(i + 1, j) - v) / mx : 0.0;
        const double sy = j < j1 ? (at(i, j + 1) - v) / my : 0.0;
        slope = std::max(slope, std::sqrt(sx * sx + sy * sy));
      }
    }
    double nadir = 0.0;
    if (replaces)
    {
      const double u = x / texelX - 0.5, v = y / texelY - 0.5;
      const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
      const double fx = u - i, fy = v - j;
      nadir = (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) +
        fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
    }
    // Both axes' differences of a cell can combine: sqrt(2) covers the diagonal.
    compose(layer, replaces, top + geoidTop, replaces, nadir + geoidAt,
      std::sqrt(2.0) * slope + geoidSlope);
  }
  return result;
}
} // namespace

//------------------------------------------------------------------------------
double vtkGlobeClippingRange::ComputeTerrainHeight(
  vtkGlobeMapper* mapper, double lon, double lat, bool& exact)
{
  // The composition itself (vtkGlobeTerrain); where it cannot be had (a streamed page that
  // cannot be read), the tallest data there.
  const double h = mapper->GetTerrain()->GetHeight(lon, lat);
  if (std::isfinite(h))
  {
    exact = true;
    return h;
  }
  const double metresPerDegree = mapper->GetEllipsoid()->GetMinimumRadius() * vtkMath::Pi() / 180.0;
  const LocalTerrain t = ComputeLocalTerrain(mapper, lon, lat, 1.0, metresPerDegree);
  exact = t.Exact;
  return t.Exact ? t.Nadir : t.Top;
}

//------------------------------------------------------------------------------
vtkGlobeClippingRange* vtkGlobeClippingRange::Install(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkGenericWarningMacro(<< "vtkGlobeClippingRange::Install: no renderer");
    return nullptr;
  }
  if (vtkGlobeClippingRange* installed = GetInstalled(renderer))
  {
    return installed;
  }
  vtkInformation* info = renderer->GetInformation();
  if (!info)
  {
    vtkNew<vtkInformation> fresh;
    renderer->SetInformation(fresh);
    info = renderer->GetInformation();
  }
  vtkNew<vtkGlobeClippingRange> policy;
  info->Set(POLICY(), policy);
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(OnReset);
  command->SetClientData(policy.Get());
  // Both events fire after VTK computed its own range, so the policy has the last word.
  renderer->AddObserver(vtkCommand::ResetCameraClippingRangeEvent, command);
  renderer->AddObserver(vtkCommand::ResetCameraEvent, command);
  return policy;
}

vtkGlobeClippingRange* vtkGlobeClippingRange::GetInstalled(vtkRenderer* renderer)
{
  vtkInformation* info = renderer ? renderer->GetInformation() : nullptr;
  return info ? vtkGlobeClippingRange::SafeDownCast(info->Get(POLICY())) : nullptr;
}

bool vtkGlobeClippingRange::Apply(vtkRenderer* renderer)
{
  double range[2];
  if (!this->ComputeRange(renderer, range))
  {
    return false;
  }
  renderer->GetActiveCamera()->SetClippingRange(range);
  ++this->NumberOfApplications;
  return true;
}

//------------------------------------------------------------------------------
bool vtkGlobeClippingRange::ComputeGlobeRange(
  vtkRenderer* renderer, vtkActor* actor, vtkGlobeMapper* mapper, double range[2])
{
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkGlobeEllipsoid* body = mapper->GetEllipsoid();
  vtkGlobeLayerSet* layers = mapper->GetLayerSet();
  layers->Update();
  const double minHeight = std::min(0.0, layers->GetMinimumHeight());
  const double maxHeight = std::max(0.0, layers->GetMaximumHeight());

  // Eye and view axis in the body frame (the actor's matrix places the body in the world).
  vtkNew<vtkMatrix4x4> worldToBody;
  vtkMatrix4x4::Invert(actor->GetMatrix(), worldToBody);
  double eye[4] = { 0, 0, 0, 1 }, view[4] = { 0, 0, 0, 0 };
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(view);
  worldToBody->MultiplyPoint(eye, eye);
  worldToBody->MultiplyPoint(view, view);
  if (vtkMath::Normalize(view) == 0.0 || !std::isfinite(eye[0] + eye[1] + eye[2]))
  {
    return false;
  }
  const double* radii = body->GetRadii();
  const double rMin = body->GetMinimumRadius(), rMax = body->GetMaximumRadius();
  const double rOut = rMax + maxHeight;
  // Eye distance of the body's centre along the view: every point of the bounding sphere lies
  // within rOut of it.
  const double centreZ = -vtkMath::Dot(eye, view);
  if (centreZ + rOut <= 0.0)
  {
    return false; // behind the camera
  }

  // Far: the horizon of the lowest terrain, plus where the tallest can rise above it. In the
  // body's scaled space (x/a, y/b, z/c) the ellipsoid is the unit sphere, terrain lies between
  // the spheres 1 + minHeight/rMin and 1 + maxHeight/rMin, and metres are at most rMax times
  // scaled lengths.
  double farZ = centreZ + rOut;
  const double scaled[3] = { eye[0] / radii[0], eye[1] / radii[1], eye[2] / radii[2] };
  const double ds = vtkMath::Norm(scaled);
  const double inner = 1.0 + minHeight / rMin, outer = 1.0 + maxHeight / rMin;
  if (ds > inner)
  {
    farZ = std::min(farZ,
      rMax * (std::sqrt(ds * ds - inner * inner) + std::sqrt(outer * outer - inner * inner)));
  }

  // Near: a lower bound of the distance to any terrain, turned into z along the view.
  double llh[3];
  double nearest = 0.0;
  if (body->CartesianToGeodeticQuiet(eye, llh))
  {
    // Over the tallest data anywhere (distance to the parallel surface at that height) ...
    nearest = llh[2] - maxHeight;
    // ... or over the tallest data in a window around the nadir, beyond which any terrain is
    // at least the window's radius away.
    const double metresPerDegree = body->GetMinimumRadius() * vtkMath::Pi() / 180.0;
    const LocalTerrain nadir = ComputeLocalTerrain(mapper, llh[0], llh[1], 1.0, metresPerDegree);
    const double below = llh[2] - (nadir.Exact ? nadir.Nadir : nadir.Top);
    const double window = std::max(100.0, 10.0 * below);
    const LocalTerrain local = ComputeLocalTerrain(mapper, llh[0], llh[1], window, metresPerDegree);
    nearest = std::max(nearest, std::min(llh[2] - local.Top, window));
    if (local.Exact)
    {
      // Terrain rising at most at `Slope` from its height under the eye is at least
      // (height over it) / sqrt(1 + slope^2) away.
      nearest = std::max(nearest,
        std::min((llh[2] - local.Nadir) / std::sqrt(1.0 + local.Slope * local.Slope), window));
    }
  }
  const double angle = vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0;
  const double aspect = std::max(renderer->GetTiledAspectRatio(), 1e-6);
  const double diagonal = std::tan(angle) * std::sqrt(1.0 + aspect * aspect);
  const double cosHalfDiagonal = 1.0 / std::sqrt(1.0 + diagonal * diagonal);
  double nearZ = this->NearSafety * nearest * cosHalfDiagonal;
  nearZ = std::max(nearZ, centreZ - rOut);
  range[0] = nearZ;
  range[1] = farZ;
  return true;
}

bool vtkGlobeClippingRange::ComputeRange(vtkRenderer* renderer, double range[2])
{
  if (!renderer || !renderer->GetActiveCamera() ||
    renderer->GetActiveCamera()->GetParallelProjection())
  {
    return false;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  double eye[3], view[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(view);
  double nearZ = VTK_DOUBLE_MAX, farZ = 0.0;
  bool globe = false;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility() || !prop->GetUseBounds())
    {
      continue;
    }
    auto* actor = vtkActor::SafeDownCast(prop);
    auto* mapper = actor ? vtkGlobeMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (mapper)
    {
      double r[2];
      if (this->ComputeGlobeRange(renderer, actor, mapper, r))
      {
        nearZ = std::min(nearZ, r[0]);
        farZ = std::max(farZ, r[1]);
        globe = true;
      }
      continue;
    }
    const double* b = prop->GetBounds();
    if (!b || !vtkMath::AreBoundsInitialized(b))
    {
      continue;
    }
    // z along the view is linear: its extremes over a box are at corners.
    double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
    for (int k = 0; k < 8; ++k)
    {
      const double p[3] = { b[k & 1], b[2 + ((k >> 1) & 1)], b[4 + ((k >> 2) & 1)] };
      const double z = (p[0] - eye[0]) * view[0] + (p[1] - eye[1]) * view[1] + (p[2] - eye[2]) * view[2];
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    // What the bounds leave out: an impostor sphere's radius (vtkOpenGLSphereMapper's Radius;
    // not a scale array's), and points or lines drawn as spheres or tubes, whose size is in
    // pixels: half of it at a pixel's size per metre of eye distance.
    if (actor)
    {
      double radius = 0.0, pixels = 0.0;
      if (auto* spheres = vtkOpenGLSphereMapper::SafeDownCast(actor->GetMapper()))
      {
        radius = spheres->GetRadius();
      }
      vtkProperty* property = actor->GetProperty();
      if (property->GetRenderPointsAsSpheres())
      {
        pixels = property->GetPointSize();
      }
      if (property->GetRenderLinesAsTubes())
      {
        pixels = std::max(pixels, static_cast<double>(property->GetLineWidth()));
      }
      const int* size = renderer->GetSize();
      const double across = camera->GetUseHorizontalViewAngle() ? size[0] : size[1];
      // A pixel spans 2 tan(angle / 2) / across metres per metre of eye distance.
      const double perMetre = pixels *
        std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle())) / std::max(across, 1.0);
      lo -= radius + perMetre * std::abs(lo);
      hi += radius + perMetre * std::abs(hi);
    }
    if (hi > 0.0)
    {
      nearZ = std::min(nearZ, 0.99 * lo);
      farZ = std::max(farZ, hi);
    }
  }
  if (!globe)
  {
    return false; // VTK's own range is right for scenes without a globe
  }
  range[0] = std::max(nearZ, this->MinimumNear);
  range[1] = std::max(1.01 * farZ, 1.01 * range[0] + 1e-3);
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeClippingRange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumNear: " << this->MinimumNear << "\n";
  os << indent << "NearSafety: " << this->NearSafety << "\n";
  os << indent << "NumberOfApplications: " << this->NumberOfApplications << "\n";
}
