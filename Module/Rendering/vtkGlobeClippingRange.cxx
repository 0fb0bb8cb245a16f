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
#include <functional>
#include <queue>
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
  double Bottom = 0.0; // lowest composed height in the window (m)
  double Nadir = 0.0;  // composed height at the point (valid when Exact)
  double Slope = 0.0;  // steepest slope in the window (valid when Exact)
  bool Exact = false;  // one layer replaces all below over the whole window
};

/**
 * Bounds the composed terrain within `radius` metres of (lon, lat). Layers compose in
 * vtkGlobeLayerSet's order (DrawOrder, then as added), each by its blend mode and weight
 * (coverage: extent, voids, an 8-texel feathered border; times opacity):
 * - Replace mixes towards the layer: one that covers the whole window with full weight decides
 *   the terrain there (its bilinear height at the point, its extremes over the window and its
 *   posts' slope); with less weight somewhere the result is at most the larger of the two
 *   maxima (at least the smaller minimum);
 * - Add adds weight * value: the maximum grows by the layer's maximum (by its positive part
 *   where the weight may be below 1), the minimum likewise; with full weight the point and
 *   slope add exactly;
 * - Average (a run of layers replaced by their weighted mean) is at most the larger maximum.
 * Layers that cannot be sampled in longitude/latitude (projected ones, missing data) enter with
 * their data's range by the same rules, so the near plane stays in front of them. `slopes`
 * false leaves Slope 0 (it reads every post of the window twice more); windows wider than
 * `texels` texels each way take the layer's range.
 */
LocalTerrain ComputeLocalTerrain(vtkGlobeMapper* mapper, double lon, double lat, double radius,
  double metresPerDegree, bool slopes = true, double texels = 64.0)
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
  // A layer's window extremes (and, with full weight, its point height and slope) into the
  // result by its blend mode; the lowest mirrors the tallest.
  auto compose = [&result](vtkGlobeLayer* layer, bool fullWeight, double top, double bottom,
                   bool exact, double nadir, double slope) {
    const bool full = fullWeight && layer->GetOpacity() >= 1.0;
    switch (layer->GetBlendMode())
    {
      case vtkGlobeLayer::Add:
        result.Top += full ? top : std::max(0.0, top);
        result.Bottom += full ? bottom : std::min(0.0, bottom);
        result.Exact = result.Exact && full && exact;
        result.Nadir += nadir;
        result.Slope += slope;
        break;
      case vtkGlobeLayer::Average:
        result.Top = std::max(result.Top, top);
        result.Bottom = std::min(result.Bottom, bottom);
        result.Exact = false;
        break;
      default:
        if (full)
        {
          result.Top = top;
          result.Bottom = bottom;
          result.Exact = exact;
          result.Nadir = nadir;
          result.Slope = slope;
        }
        else
        {
          result.Top = std::max(result.Top, top);
          result.Bottom = std::min(result.Bottom, bottom);
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
    double geoidTop = 0.0, geoidBottom = 0.0, geoidAt = 0.0, geoidSlope = 0.0;
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
      geoidBottom = geoidCovers ? geoidAt - geoidSlope * radius : geoid->GetRange()[0];
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
      const double bottom = layer->GetMinimumValue() +
        (layer->GetGeoid() ? layer->GetGeoid()->GetRange()[0] : 0.0);
      compose(layer, false, top, bottom, false, 0.0, 0.0);
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
    // More than `texels` texels each way: the layer's range is a good enough bound.
    if (dLon > texels * texelX || dLat > texels * texelY)
    {
      compose(layer, replaces, layer->GetMaximumValue() + geoidTop,
        layer->GetMinimumValue() + geoidBottom, false, 0.0, 0.0);
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
    double slope = 0.0, top = -VTK_DOUBLE_MAX, bottom = VTK_DOUBLE_MAX;
    // Windows of a few texels: the extremes of the bilinear terrain over the window itself. It
    // is linear along each axis, so they lie where the window's edges and the posts' rows and
    // columns cross (window corners, posts inside, edges across rows and columns). Wider ones:
    // the posts around the window.
    const double u0 = (x - dLon) / texelX - 0.5, u1 = (x + dLon) / texelX - 0.5;
    const double v0 = (y - dLat) / texelY - 0.5, v1 = (y + dLat) / texelY - 0.5;
    auto bilinear = [&at](double u, double v) {
      const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
      const double fx = u - i, fy = v - j;
      return (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) +
        fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
    };
    const bool wide = u1 - u0 > 4.0 || v1 - v0 > 4.0;
    if (!wide)
    {
      // (A span of at most 4 texels crosses at most 4 rows or columns: 6 values each way.)
      auto crossings = [](double lo, double hi, double* c) {
        int n = 0;
        c[n++] = lo;
        for (double k = std::floor(lo) + 1.0; k < hi && n < 5; k += 1.0)
        {
          c[n++] = k;
        }
        c[n++] = hi;
        return n;
      };
      double us[6], vs[6];
      const int nu = crossings(u0, u1, us), nv = crossings(v0, v1, vs);
      for (int b = 0; b < nv; ++b)
      {
        for (int a = 0; a < nu; ++a)
        {
          const double value = bilinear(us[a], vs[b]);
          top = std::max(top, value);
          bottom = std::min(bottom, value);
        }
      }
    }
    for (int j = j0; j <= j1 && (wide || slopes); ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const double v = at(i, j);
        if (wide)
        {
          top = std::max(top, v);
          bottom = std::min(bottom, v);
        }
        if (slopes)
        {
          const double sx = i < i1 ? (at(i + 1, j) - v) / mx : 0.0;
          const double sy = j < j1 ? (at(i, j + 1) - v) / my : 0.0;
          slope = std::max(slope, std::sqrt(sx * sx + sy * sy));
        }
      }
    }
    const double nadir = replaces ? bilinear(x / texelX - 0.5, y / texelY - 0.5) : 0.0;
    // Both axes' differences of a cell can combine: sqrt(2) covers the diagonal.
    compose(layer, replaces, top + geoidTop, bottom + geoidBottom, replaces, nadir + geoidAt,
      std::sqrt(2.0) * slope + geoidSlope);
  }
  return result;
}

/// A block of terrain: a longitude/latitude box and what bounds its terrain's eye z.
struct Block
{
  double Lon[2], Lat[2];
  double ZMin;   // lower bound of the eye z of its terrain inside the frustum
  double Extent; // its diagonal (m)
  bool operator>(const Block& other) const { return this->ZMin > other.ZMin; }
};

/**
 * A lower bound of the eye z (along `view`) of any terrain inside the frustum (`planes`:
 * inward unit normals of its four sides through the eye, body frame) whose foot lies in the
 * longitude/latitude box `root`; +inf when none can be. Best-first subdivision: each block is
 * the hull of its footprint's corners between its lowest and tallest composed terrain
 * (ComputeLocalTerrain), grown by the sagitta of its curved edges; blocks wholly outside a side
 * plane are dropped, the block with the smallest z is split until it is small (10 %) against
 * its z or against `enough` (a bound already known), or `budget` blocks were bounded.
 */
double NearestTerrainInFrustum(vtkGlobeMapper* mapper, vtkGlobeEllipsoid* body,
  const double eye[3], const double view[3], const double planes[4][3], const Block& root,
  double lowest, double enough, int budget, double metresPerDegree)
{
  // The smallest radius of curvature of the body's surface (b^2 / a for the Earth).
  const double curvature = std::max(body->GetMinimumRadius() * body->GetMinimumRadius() /
      body->GetMaximumRadius() + std::min(0.0, lowest), 1.0);
  // The sides are widened by 1 degree: the GPU samples distant heights from coarser levels,
  // whose averages may stand a fraction of a pixel above the posts' bilinear terrain.
  const double margin = std::sin(vtkMath::RadiansFromDegrees(1.0));
  auto bound = [&](Block& b) {
    const double lon = 0.5 * (b.Lon[0] + b.Lon[1]), lat = 0.5 * (b.Lat[0] + b.Lat[1]);
    const double cosLat = std::max(std::cos(vtkMath::RadiansFromDegrees(lat)), 1e-3);
    const double radius = 1.0001 * metresPerDegree *
      std::max(0.5 * (b.Lat[1] - b.Lat[0]), 0.5 * (b.Lon[1] - b.Lon[0]) * cosLat);
    const LocalTerrain terrain =
      ComputeLocalTerrain(mapper, lon, lat, radius, metresPerDegree, false, 8.0);
    double p[8][3];
    for (int k = 0; k < 8; ++k)
    {
      const double llh[3] = { b.Lon[k & 1], b.Lat[(k >> 1) & 1],
        (k & 4) ? terrain.Top : terrain.Bottom };
      body->GeodeticToCartesianQuiet(llh, p[k]);
    }
    // Curved edges bulge out of the corners' hull: a chord of length L of a surface with
    // radius of curvature R sags L^2 / (8 R); a parallel's radius is R cos(latitude).
    const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(p[4], p[7]));
    const double parallel = std::max(std::sqrt(vtkMath::Distance2BetweenPoints(p[4], p[5])),
      std::sqrt(vtkMath::Distance2BetweenPoints(p[6], p[7])));
    const double cosPole = std::max(
      std::cos(vtkMath::RadiansFromDegrees(std::max(std::abs(b.Lat[0]), std::abs(b.Lat[1])))),
      1e-3);
    const double sag = diagonal * diagonal / (8.0 * curvature) +
      parallel * parallel / (8.0 * curvature * cosPole) + 1e-3;
    b.Extent = diagonal;
    for (int f = 0; f < 4; ++f)
    {
      bool outside = true;
      for (int k = 0; k < 8 && outside; ++k)
      {
        const double d[3] = { p[k][0] - eye[0], p[k][1] - eye[1], p[k][2] - eye[2] };
        outside = vtkMath::Dot(d, planes[f]) < -sag - margin * vtkMath::Norm(d);
      }
      if (outside)
      {
        return false;
      }
    }
    b.ZMin = VTK_DOUBLE_MAX;
    for (int k = 0; k < 8; ++k)
    {
      const double d[3] = { p[k][0] - eye[0], p[k][1] - eye[1], p[k][2] - eye[2] };
      b.ZMin = std::min(b.ZMin, vtkMath::Dot(d, view) - sag);
    }
    return true;
  };
  std::priority_queue<Block, std::vector<Block>, std::greater<Block>> queue;
  Block first = root;
  if (bound(first))
  {
    queue.push(first);
  }
  int bounded = 1;
  while (!queue.empty())
  {
    const Block b = queue.top();
    queue.pop();
    if (b.Extent <= 0.1 * std::max(b.ZMin, enough) || bounded + 4 > budget)
    {
      return b.ZMin;
    }
    const double lonMid = 0.5 * (b.Lon[0] + b.Lon[1]), latMid = 0.5 * (b.Lat[0] + b.Lat[1]);
    for (int k = 0; k < 4; ++k)
    {
      Block child = b;
      child.Lon[(k & 1) ? 0 : 1] = lonMid;
      child.Lat[(k & 2) ? 0 : 1] = latMid;
      ++bounded;
      if (bound(child))
      {
        queue.push(child);
      }
    }
  }
  return VTK_DOUBLE_MAX;
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

  // Near: a lower bound of the distance to any terrain, turned into z along the view (points
  // in the frustum lie within its half diagonal of the view axis).
  const double angle = vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0;
  const double aspect = std::max(renderer->GetTiledAspectRatio(), 1e-6);
  const double diagonal = std::tan(angle) * std::sqrt(1.0 + aspect * aspect);
  const double cosHalfDiagonal = 1.0 / std::sqrt(1.0 + diagonal * diagonal);
  double llh[3];
  double nearest = 0.0, frustumZ = 0.0;
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
    // ... or, better where the camera looks away from the ground under it (a summit, an
    // aircraft looking at the horizon): the nearest terrain the frustum itself can hold, within
    // 100 km (beyond, at least that far).
    const double reach = std::max(window, 1e5);
    const double dLat = reach / metresPerDegree;
    const double cosLat = std::cos(vtkMath::RadiansFromDegrees(llh[1]));
    // (Not across a pole or the antimeridian, where the layers' windows would split.)
    if (std::abs(llh[1]) + dLat < 89.0 && std::abs(llh[0]) + dLat / cosLat < 180.0)
    {
      // The frustum's sides (VTK's planes, left, right, bottom, top first: inward normals,
      // through the eye) into the body frame, where normals go by the transposed matrix.
      double world[24], planes[4][3];
      camera->GetFrustumPlanes(aspect, world);
      vtkMatrix4x4* bodyToWorld = actor->GetMatrix();
      bool valid = true;
      for (int k = 0; k < 4; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          planes[k][c] = bodyToWorld->GetElement(0, c) * world[4 * k] +
            bodyToWorld->GetElement(1, c) * world[4 * k + 1] +
            bodyToWorld->GetElement(2, c) * world[4 * k + 2];
        }
        valid = valid && vtkMath::Normalize(planes[k]) > 0.0 &&
          std::isfinite(planes[k][0] + planes[k][1] + planes[k][2]);
      }
      const Block root = { { llh[0] - dLat / cosLat, llh[0] + dLat / cosLat },
        { llh[1] - dLat, llh[1] + dLat }, 0.0, 0.0 };
      const double enough = nearest * cosHalfDiagonal;
      if (valid)
      {
        frustumZ = std::min(0.99 * reach * cosHalfDiagonal,
          NearestTerrainInFrustum(mapper, body, eye, view, planes, root, minHeight, enough, 4000,
            metresPerDegree));
      }
    }
  }
  double nearZ = this->NearSafety * std::max(nearest * cosHalfDiagonal, frustumZ);
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
