#include "vtkGlobeLayerSet.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGeoid.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeMapProjection.h"
#include "vtkGlobePageCache.h"
#include "vtkGlobePageSource.h"
#include "vtkGlobeFootprint.h"
#include "vtkGlobePages.h"
#include "vtkGlobeShaderSources.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <memory>
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include "globe_projection.h"

vtkStandardNewMacro(vtkGlobeLayerSet);

namespace
{
/// A layer as messages name it: its file, else its name (a pipeline's source, say).
std::string LayerLabel(vtkGlobeLayer* layer)
{
  if (layer->GetFileName())
  {
    return layer->GetFileName();
  }
  const char* name = layer->GetName();
  return name && *name ? "'" + std::string(name) + "'" : std::string("(in-memory layer)");
}

// Largest magnitude passed for an unbounded valid range (a float uniform).
constexpr double FloatLimit = 3.0e38;

struct Entry
{
  vtkSmartPointer<vtkGlobeLayer> Layer;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkDataArray* UploadedData = nullptr;
  vtkMTimeType UploadedTime = 0;
  // The heights' ValueScale and ValueOffset when the texture was made: a later rescale of the
  // layer maps the texture with a uniform instead of an upload.
  double UploadedScale = 1.0;
  double UploadedOffset = 0.0;
  int UploadedLevels = 1; // of the whole-raster texture's pyramid
  int Added = 0;          // insertion index: ties in DrawOrder keep it
  bool Active = false;    // loaded, valid, supported and enabled
  bool Reported = false;  // an error about this layer was reported already
  bool Removed = false;   // removed from the set (perhaps while Update() walked it)
  bool Wraps = false;     // a global geographic layer: longitude wraps, no east/west border
  double Map[4] = { 0, 0, 0, 0 };    // geographic: west, east-west span, north, span (rad)
  // Projected layers: the projection, its globe_projection.glsl function and parameters.
  vtkSmartPointer<vtkGlobeMapProjection> Projection;
  std::string Function;
  float Parameters[vtkGlobeMapProjection::NumberOfShaderParameters] = {};
  double Reference[2] = { 0, 0 }; // the parameters' reference point (u, v), in double
  // The loaded data the projection was prepared for: georeferencing changes only with a load.
  vtkDataArray* PreparedData = nullptr;
  vtkMTimeType PreparedTime = 0;
  int PreparedLoads = -1;
  // Streamed (vtkGlobeLayer::IsStreamed): pages in the page cache instead of a texture.
  bool Streamed = false;
  bool Prepared = false;
  double Border[4] = { 0, 0, 0, 0 }; // feather u, v (texture coordinates); 1/log(n); unused
  // Height layers: skirt u, v outside the raster (texture coordinates); a whole turn of
  // longitude in u (geographic layers; 1e30 for projected ones); unused.
  double Skirt[4] = { 0, 0, 1e30, 0 };
  // Heights above a geoid: the index of its texture in vtkInternals::Geoids, else -1.
  int Geoid = -1;
  // Per-frame culling (CullLayers): out of the view this frame. The footprint: (lon, lat) in
  // degrees sampled over the layer's extent, and the spacing of the samples (rad), for the
  // bulge of the surface between them; empty for layers that are never culled.
  bool Culled = false;
  std::vector<std::array<double, 2>> Footprint;
  double FootprintSpacing = 0.0;
  // Colour match (vtkGlobeLayer::ColorMatch): per channel, colour -> colour * gain + offset
  // near the border; Match is false when it is off or nothing below covers the layer. Stamp:
  // what the statistics were computed from (recomputed only when it changes).
  bool Match = false;
  double MatchGain[3] = { 1, 1, 1 };
  double MatchOffset[3] = { 0, 0, 0 };
  std::vector<double> MatchStamp;
};

// A whole colour layer's RGBA at texture coordinates (u, v) (nearest texel), after its gamma,
// in [0, 1]; false where it has no data (outside, or alpha 0).
bool ColorAt(vtkGlobeLayer* layer, double u, double v, double rgb[3])
{
  vtkDataArray* data = layer->GetData();
  const int w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
  if (!data || data->GetNumberOfComponents() != 4 || u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0)
  {
    return false;
  }
  const vtkIdType c = std::min(static_cast<vtkIdType>(u * w), static_cast<vtkIdType>(w - 1));
  const vtkIdType r = std::min(static_cast<vtkIdType>(v * h), static_cast<vtkIdType>(h - 1));
  const vtkIdType t = r * w + c;
  if (data->GetComponent(t, 3) <= 0.0)
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = std::pow(data->GetComponent(t, k) / 255.0, layer->GetGamma());
  }
  return true;
}

// The colour match of entry `e` against the geographic whole colour layers below it (`below`,
// bottom first): each channel's mean and standard deviation over the layer, and over the same
// ground below (33 x 33 points placed through the layer's footprint), give gain and offset.
void ComputeColorMatch(Entry& e, const std::vector<Entry*>& below)
{
  vtkGlobeLayer* layer = e.Layer;
  // What the statistics depend on: the switch, and each layer's data and gamma (opacity,
  // feather or the width of the match are uniforms and recompute nothing).
  auto dataTime = [](vtkGlobeLayer* l) {
    return l->GetData() ? static_cast<double>(l->GetData()->GetMTime()) : 0.0;
  };
  std::vector<double> stamp = { layer->GetColorMatch() ? 1.0 : 0.0, dataTime(layer),
    layer->GetGamma() };
  for (const Entry* b : below)
  {
    stamp.push_back(dataTime(b->Layer));
    stamp.push_back(b->Layer->GetGamma());
  }
  if (stamp == e.MatchStamp)
  {
    return;
  }
  e.MatchStamp = stamp;
  e.Match = false;
  if (!layer->GetColorMatch() || e.Streamed || e.Wraps || e.Footprint.size() != 81 ||
    !layer->GetData())
  {
    return;
  }
  // The layer's own statistics, over at most about 2^20 of its pixels.
  double sum[2][3] = { { 0, 0, 0 }, { 0, 0, 0 } }, sq[2][3] = { { 0, 0, 0 }, { 0, 0, 0 } };
  double count[2] = { 0, 0 };
  const int w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
  const int stride = std::max(1, static_cast<int>(std::sqrt(double(w) * h / 1048576.0)));
  for (int r = 0; r < h; r += stride)
  {
    for (int c = 0; c < w; c += stride)
    {
      double rgb[3];
      if (ColorAt(layer, (c + 0.5) / w, (r + 0.5) / h, rgb))
      {
        count[0] += 1.0;
        for (int k = 0; k < 3; ++k)
        {
          sum[0][k] += rgb[k];
          sq[0][k] += rgb[k] * rgb[k];
        }
      }
    }
  }
  // What lies below, at 33 x 33 points of the layer's footprint (bilinear in its 9 x 9 samples).
  constexpr int n = 33;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double fu = 8.0 * i / (n - 1), fv = 8.0 * j / (n - 1);
      const int i0 = std::min(static_cast<int>(fu), 7), j0 = std::min(static_cast<int>(fv), 7);
      const double a = fu - i0, b = fv - j0;
      auto at = [&](int ii, int jj) { return e.Footprint[static_cast<size_t>(jj) * 9 + ii]; };
      double ll[2];
      for (int k = 0; k < 2; ++k)
      {
        ll[k] = (1 - a) * (1 - b) * at(i0, j0)[k] + a * (1 - b) * at(i0 + 1, j0)[k] +
          (1 - a) * b * at(i0, j0 + 1)[k] + a * b * at(i0 + 1, j0 + 1)[k];
      }
      for (auto it = below.rbegin(); it != below.rend(); ++it)
      {
        vtkGlobeLayer* base = (*it)->Layer;
        double extent[4], rgb[3];
        base->GetGeographicExtent(extent);
        double x = ll[0] - extent[0];
        if ((*it)->Wraps)
        {
          x = std::fmod(std::fmod(x, 360.0) + 360.0, 360.0);
        }
        if (ColorAt(base, x / (extent[1] - extent[0]), (extent[3] - ll[1]) / (extent[3] - extent[2]),
              rgb))
        {
          count[1] += 1.0;
          for (int k = 0; k < 3; ++k)
          {
            sum[1][k] += rgb[k];
            sq[1][k] += rgb[k] * rgb[k];
          }
          break; // the topmost layer below that has data here
        }
      }
    }
  }
  if (count[0] < 16.0 || count[1] < 0.5 * n * n)
  {
    return;
  }
  for (int k = 0; k < 3; ++k)
  {
    double mean[2], sd[2];
    for (int q = 0; q < 2; ++q)
    {
      mean[q] = sum[q][k] / count[q];
      sd[q] = std::sqrt(std::max(0.0, sq[q][k] / count[q] - mean[q] * mean[q]));
    }
    e.MatchGain[k] = sd[0] > 1e-6 ? std::max(0.25, std::min(4.0, sd[1] / sd[0])) : 1.0;
    e.MatchOffset[k] = mean[1] - e.MatchGain[k] * mean[0];
  }
  e.Match = true;
}

// A geoid grid on the GPU (vtkGlobeLayer::VerticalDatum Geoid): its nodes as an R32F texture
// read with texelFetch, interpolated in the shader (hardware filtering weights have 8 bits).
struct GeoidTexture
{
  vtkSmartPointer<vtkGlobeGeoid> Geoid;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkMTimeType UploadedTime = 0;
};

// The footprint CullLayers tests: (lon, lat) at 9 x 9 points (u, v) over the layer's raster
// and its skirt, longitudes unwrapped around the centre's. Left empty, so the layer is never
// culled, for layers that wrap, reach within a degree of a pole, have a point that does not
// map, or are so large (samples over 5 degrees apart) that the bulge margin grows too loose.
void SetFootprint(Entry& e, const std::function<bool(double, double, double[2])>& at)
{
  constexpr int n = 8;
  e.Footprint.clear();
  double centre[2];
  if (e.Wraps || !at(0.5, 0.5, centre))
  {
    return;
  }
  // A height layer's skirt reaches outside its raster.
  double skirt[2];
  e.Layer->GetSkirtBorder(skirt);
  double west = 1e9, east = -1e9, south = 90.0, north = -90.0;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      double ll[2];
      const double u = -skirt[0] + (1.0 + 2.0 * skirt[0]) * i / n;
      const double v = -skirt[1] + (1.0 + 2.0 * skirt[1]) * j / n;
      if (!at(u, v, ll))
      {
        e.Footprint.clear();
        return;
      }
      const double lon = centre[0] + std::remainder(ll[0] - centre[0], 360.0);
      e.Footprint.push_back({ lon, ll[1] });
      west = std::min(west, lon);
      east = std::max(east, lon);
      south = std::min(south, ll[1]);
      north = std::max(north, ll[1]);
    }
  }
  e.FootprintSpacing = std::max(east - west, north - south) / n * vtkMath::Pi() / 180.0;
  if (north > 89.0 || south < -89.0 || e.FootprintSpacing > 5.0 * vtkMath::Pi() / 180.0)
  {
    e.Footprint.clear();
  }
}

const char* RoleFunction(int role)
{
  switch (role)
  {
    case vtkGlobeLayer::Color:
      return "Color";
    case vtkGlobeLayer::NormalMap:
      return "Normal";
    case vtkGlobeLayer::Overlay:
      return "Overlay";
    case vtkGlobeLayer::Mask:
      return "Mask";
    case vtkGlobeLayer::NightLights:
      return "NightLights";
    default:
      return "Height";
  }
}
constexpr int NumberOfRoles = 6;
} // namespace

class vtkGlobeLayerSet::vtkInternals
{
public:
  // Shared: Update() keeps the entries it walks alive while layer observers add or remove
  // layers (a layer's ProgressEvent may call RemoveAllLayers()).
  std::vector<std::shared_ptr<Entry>> Entries;
  // Textures of removed layers, released when a context is at hand.
  std::vector<vtkSmartPointer<vtkTextureObject>> Retired;
  // The GPU side of streamed layers.
  vtkNew<vtkGlobePageCache> Pages;
  // Active layers by role, in composition order; Index[] is the uniform index of each.
  std::array<std::vector<Entry*>, NumberOfRoles> Roles;
  // What the passes compose this frame: Roles without the layers CullLayers culled. The
  // generated code, its key and the bindings follow this, so a culled layer costs nothing.
  std::array<std::vector<Entry*>, NumberOfRoles> Composed;
  // Geoids of height layers, kept with their textures; Entry::Geoid indexes this.
  std::vector<GeoidTexture> Geoids;
  int NextAdded = 0;
  double MinimumHeight = 0.0;
  double MaximumHeight = 0.0;
  // The texture-unit probe (FiltersFloatTexturesExactly): its window and answer.
  vtkOpenGLRenderWindow* ProbedWindow = nullptr;
  int FiltersExactly = -1;

  void Retire(Entry& e)
  {
    e.Removed = true;
    e.Active = false;
    if (e.Texture)
    {
      this->Retired.push_back(e.Texture);
      e.Texture = nullptr;
    }
  }

  void ReleaseRetired(vtkWindow* window)
  {
    for (auto& t : this->Retired)
    {
      t->ReleaseGraphicsResources(window);
    }
    this->Retired.clear();
  }

  void ClearActive()
  {
    for (auto& list : this->Roles)
    {
      list.clear();
    }
    this->UpdateComposed();
  }

  // Composed from Roles and each entry's last culling decision (Update() clears it).
  void UpdateComposed()
  {
    for (int role = 0; role < NumberOfRoles; ++role)
    {
      this->Composed[role].clear();
      for (Entry* e : this->Roles[role])
      {
        if (!e->Culled)
        {
          this->Composed[role].push_back(e);
        }
      }
    }
  }
};

//------------------------------------------------------------------------------
vtkGlobeLayerSet::vtkGlobeLayerSet()
  : Internals(new vtkInternals)
{
}

vtkGlobeLayerSet::~vtkGlobeLayerSet() = default;

void vtkGlobeLayerSet::AddLayer(vtkGlobeLayer* layer)
{
  if (!layer)
  {
    vtkErrorMacro(<< "AddLayer: no layer given");
    return;
  }
  auto entry = std::make_shared<Entry>();
  entry->Layer = layer;
  entry->Added = this->Internals->NextAdded++;
  this->Internals->Entries.push_back(entry);
  this->Modified();
}

void vtkGlobeLayerSet::RemoveLayer(vtkGlobeLayer* layer)
{
  auto& entries = this->Internals->Entries;
  auto it = std::stable_partition(entries.begin(), entries.end(),
    [layer](const std::shared_ptr<Entry>& e) { return e->Layer != layer; });
  if (it != entries.end())
  {
    for (auto r = it; r != entries.end(); ++r)
    {
      this->Internals->Retire(**r);
    }
    entries.erase(it, entries.end());
    this->Internals->ClearActive();
    this->Modified();
  }
}

void vtkGlobeLayerSet::RemoveAllLayers()
{
  for (auto& e : this->Internals->Entries)
  {
    this->Internals->Retire(*e);
  }
  this->Internals->Entries.clear();
  this->Internals->ClearActive();
  this->Modified();
}

int vtkGlobeLayerSet::GetNumberOfLayers()
{
  return static_cast<int>(this->Internals->Entries.size());
}

vtkGlobeLayer* vtkGlobeLayerSet::GetLayer(int index)
{
  if (index < 0 || index >= this->GetNumberOfLayers())
  {
    return nullptr;
  }
  return this->Internals->Entries[index]->Layer;
}

//------------------------------------------------------------------------------
int vtkGlobeLayerSet::Update()
{
  auto& in = *this->Internals;
  in.ClearActive();
  std::vector<Entry*> order;
  // A copy: loading a layer runs its observers, which may add or remove layers.
  const std::vector<std::shared_ptr<Entry>> entries = in.Entries;
  for (const std::shared_ptr<Entry>& held : entries)
  {
    Entry& e = *held;
    if (e.Removed)
    {
      continue;
    }
    vtkSmartPointer<vtkGlobeLayer> layer = e.Layer; // alive through its own observers
    if (layer->GetRole() == vtkGlobeLayer::Height)
    {
      layer->SetPlausibleRange(this->PlausibleHeightRange);
    }
    e.Active = false;
    if (!layer->GetEnabled())
    {
      continue;
    }
    in.Pages->ConfigureSource(layer); // a streamed layer opens its file once, as the cache reads it
    const bool loaded = layer->Update() && layer->IsValid();
    if (e.Removed)
    {
      continue; // an observer removed it while it loaded
    }
    const std::string name = LayerLabel(layer);
    if (!loaded)
    {
      // The layer reported its own error; say once that the globe goes on without it.
      if (!e.Reported)
      {
        vtkWarningMacro(<< "Layer " << name << " is skipped: it could not be loaded");
        e.Reported = true;
      }
      continue;
    }
    const bool projected = layer->GetModelType() == vtkGlobeLayer::Projected;
    vtkDataArray* data = layer->GetData(); // nullptr when streamed
    e.Streamed = layer->IsStreamed();
    if (data != e.PreparedData ||
      (data && data->GetMTime() != e.PreparedTime && !layer->IsRescaledSince(e.PreparedTime)) ||
      layer->GetNumberOfLoads() != e.PreparedLoads)
    {
      e.Function.clear();
      e.Prepared = !projected || this->PrepareProjection(&e);
      e.PreparedData = data;
      e.PreparedTime = data ? data->GetMTime() : 0;
      e.PreparedLoads = layer->GetNumberOfLoads();
    }
    if (projected)
    {
      if (!e.Prepared)
      {
        continue;
      }
    }
    else if (layer->GetModelType() != vtkGlobeLayer::Geographic)
    {
      if (!e.Reported)
      {
        vtkErrorMacro(<< "Layer " << name << " is skipped: its georeferencing is neither geographic "
                      << "nor projected (model type " << layer->GetModelType() << ")");
        e.Reported = true;
      }
      continue;
    }
    e.Geoid = -1;
    if (vtkGlobeGeoid* geoid = layer->GetRole() == vtkGlobeLayer::Height ? layer->GetGeoid() : nullptr)
    {
      if (!geoid->IsValid())
      {
        if (!e.Reported)
        {
          vtkErrorMacro(<< "Layer " << name << " is skipped: its geoid "
                        << (geoid->GetFileName() && *geoid->GetFileName() ? geoid->GetFileName() : "(no file)")
                        << " cannot be read, so its heights cannot be made ellipsoidal");
          e.Reported = true;
        }
        continue;
      }
      auto found = std::find_if(in.Geoids.begin(), in.Geoids.end(),
        [geoid](const GeoidTexture& g) { return g.Geoid == geoid; });
      if (found == in.Geoids.end())
      {
        in.Geoids.push_back(GeoidTexture{ geoid, nullptr, 0 });
        found = in.Geoids.end() - 1;
      }
      e.Geoid = static_cast<int>(found - in.Geoids.begin());
    }
    e.Reported = false;
    e.Active = true;
    double feather[2], skirt[2];
    layer->GetFeatherBorder(feather);
    layer->GetSkirtBorder(skirt);
    e.Border[2] = 1.0 / std::log(layer->GetProjectionQualityLimit());
    if (!e.Function.empty())
    {
      // A cylindrical projection one whole turn wide wraps like a global geographic layer.
      e.Wraps = layer->IsGlobal();
      e.Border[0] = e.Wraps ? 0.0 : feather[0];
      e.Border[1] = feather[1];
      e.Skirt[0] = e.Wraps ? 0.0 : skirt[0];
      e.Skirt[1] = skirt[1];
      e.Skirt[2] = 1e30;
      order.push_back(&e);
      continue;
    }
    double extent[4];
    layer->GetGeographicExtent(extent);
    const double deg = vtkMath::Pi() / 180.0;
    e.Map[0] = extent[0] * deg;
    e.Map[1] = (extent[1] - extent[0]) * deg;
    e.Map[2] = extent[3] * deg;
    e.Map[3] = (extent[3] - extent[2]) * deg;
    e.Wraps = layer->IsGlobal();
    // A global layer wraps in longitude and has no east/west border; one that reaches both
    // poles has no north/south border.
    e.Border[0] = e.Wraps ? 0.0 : feather[0];
    const bool polesCovered = extent[2] <= -90.0 && extent[3] >= 90.0;
    e.Border[1] = polesCovered ? 0.0 : feather[1];
    e.Skirt[0] = e.Wraps ? 0.0 : skirt[0];
    e.Skirt[1] = polesCovered ? 0.0 : skirt[1];
    e.Skirt[2] = 360.0 / (extent[1] - extent[0]);
    SetFootprint(e, [&extent](double u, double v, double lonLat[2]) {
      lonLat[0] = extent[0] + (extent[1] - extent[0]) * u;
      lonLat[1] = std::max(-90.0, std::min(90.0, extent[3] - (extent[3] - extent[2]) * v));
      return true;
    });
    order.push_back(&e);
  }
  // Observers of later layers may have removed earlier ones.
  order.erase(std::remove_if(order.begin(), order.end(), [](const Entry* e) { return e->Removed; }),
    order.end());
  std::stable_sort(order.begin(), order.end(), [](const Entry* a, const Entry* b) {
    return a->Layer->GetDrawOrder() != b->Layer->GetDrawOrder()
      ? a->Layer->GetDrawOrder() < b->Layer->GetDrawOrder()
      : a->Added < b->Added;
  });

  for (Entry* e : order)
  {
    e->Culled = false;
    in.Roles[e->Layer->GetRole()].push_back(e);
  }
  // Colour match: against the geographic whole colour layers below each layer that asks.
  std::vector<Entry*> below;
  for (Entry* e : in.Roles[vtkGlobeLayer::Color])
  {
    ComputeColorMatch(*e, below);
    if (e->Function.empty() && !e->Streamed && e->Layer->GetData())
    {
      below.push_back(e);
    }
  }
  this->ComputeHeightRange();
  return static_cast<int>(order.size());
}

void vtkGlobeLayerSet::ComputeHeightRange()
{
  // Heights: an interval bound of what the composition can give (the PGM spheres need it;
  // a streamed layer's range spans the pages read so far, which grows between frames).
  auto& in = *this->Internals;
  in.MinimumHeight = in.MaximumHeight = 0.0;
  bool first = true;
  for (Entry* e : in.Roles[vtkGlobeLayer::Height])
  {
    vtkGlobeLayer* layer = e->Layer;
    const double range[2] = { layer->GetMinimumValue(), layer->GetMaximumValue() };
    const double* valid = layer->GetValidRange();
    double lo = std::max(range[0], valid[0]);
    double hi = std::min(range[1], valid[1]);
    if (lo > hi)
    {
      continue; // nothing of it is valid
    }
    if (e->Geoid >= 0)
    {
      // Heights above a geoid: N, within the grid's range, is added to each value.
      const double* n = in.Geoids[e->Geoid].Geoid->GetRange();
      lo += n[0];
      hi += n[1];
    }
    if (layer->GetBlendMode() == vtkGlobeLayer::Add)
    {
      in.MinimumHeight += std::min(0.0, lo);
      in.MaximumHeight += std::max(0.0, hi);
    }
    else
    {
      in.MinimumHeight = first ? lo : std::min(in.MinimumHeight, lo);
      in.MaximumHeight = first ? hi : std::max(in.MaximumHeight, hi);
    }
    first = false;
  }
}

bool vtkGlobeLayerSet::PrepareProjection(void* entry)
{
  Entry& e = *static_cast<Entry*>(entry);
  vtkGlobeLayer* layer = e.Layer;
  const std::string name = LayerLabel(layer);
  auto refuse = [&](const std::string& why) {
    if (!e.Reported)
    {
      vtkErrorMacro(<< "Layer " << name << " is skipped: " << why);
      e.Reported = true;
    }
    e.Function.clear();
    return false;
  };
  if (!e.Projection)
  {
    e.Projection = vtkSmartPointer<vtkGlobeMapProjection>::New();
  }
  vtkGlobeMapProjection* projection = e.Projection;
  const int epsg = layer->GetEPSG();
  const std::string definition = layer->GetCRSDefinition();
  if (epsg <= 0 && definition.empty())
  {
    return refuse("it is in projected coordinates without an EPSG code or a CRS definition, so "
                  "its projection is unknown");
  }
  if (!layer->GetMapProjection(projection))
  {
    return refuse("its map projection " + (epsg > 0 ? "EPSG:" + std::to_string(epsg) : "'" + definition + "'") +
      " is not supported (supported: geographic, equirectangular, polar stereographic, Mercator, "
      "Web Mercator, transverse Mercator / UTM, Lambert conformal conic, Albers, polar Lambert "
      "azimuthal and cylindrical equal-area, sinusoidal on a sphere)");
  }
  double origin[2], pixelSize[2];
  layer->GetProjectedGeoTransform(origin, pixelSize);
  const bool warnings = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  double parameters[vtkGlobeMapProjection::NumberOfShaderParameters];
  bool ok = projection->ComputeShaderParametersDouble(
    origin, pixelSize, layer->GetNumberOfColumns(), layer->GetNumberOfRows(), parameters);
  std::copy(parameters, parameters + vtkGlobeMapProjection::NumberOfShaderParameters, e.Parameters);
  e.Reference[0] = parameters[8];
  e.Reference[1] = parameters[9];
  // The raster must lie in the projection's domain: its centre maps to a (lon, lat) there and
  // back to itself (an inverse far outside the domain does not round-trip).
  const double centre[2] = { origin[0] + 0.5 * pixelSize[0] * layer->GetNumberOfColumns(),
    origin[1] - 0.5 * pixelSize[1] * layer->GetNumberOfRows() };
  double lonLat[2], back[2];
  ok = ok && projection->Inverse(centre[0], centre[1], lonLat) &&
    projection->IsInValidDomain(lonLat[0], lonLat[1]) &&
    projection->Forward(lonLat[0], lonLat[1], back) &&
    std::abs(back[0] - centre[0]) < 0.01 * pixelSize[0] &&
    std::abs(back[1] - centre[1]) < 0.01 * pixelSize[1];
  vtkObject::SetGlobalWarningDisplay(warnings);
  if (!ok)
  {
    char text[300];
    std::snprintf(text, sizeof(text),
      "its georeferencing (north-west corner %.6g, %.6g; pixel %.6g x %.6g; %d x %d pixels) does "
      "not fit its projection %s (the extent is empty or outside the projection's domain)",
      origin[0], origin[1], pixelSize[0], pixelSize[1], layer->GetNumberOfColumns(),
      layer->GetNumberOfRows(),
      epsg > 0 ? ("EPSG:" + std::to_string(epsg)).c_str() : projection->GetKindAsString());
    return refuse(text);
  }
  e.Function = projection->GetShaderFunctionName();
  // The footprint for culling: the raster's edges and inside mapped back to (lon, lat).
  e.Wraps = layer->IsGlobal();
  const int w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
  SetFootprint(e, [&](double u, double v, double ll[2]) {
    return projection->InverseInDomain(
      origin[0] + pixelSize[0] * w * u, origin[1] - pixelSize[1] * h * v, ll);
  });
  return true;
}

void vtkGlobeLayerSet::CullLayers(vtkCamera* camera, double aspect, vtkMatrix4x4* bodyToWorld,
  vtkGlobeEllipsoid* body)
{
  auto& in = *this->Internals;
  this->NumberOfCulledLayers = 0;
  double planes[24];
  const bool usable = this->LayerCulling && camera && bodyToWorld && body && aspect > 0.0;
  if (usable)
  {
    camera->GetFrustumPlanes(aspect, planes); // world coordinates, normals inward
  }
  for (int role = 0; role < NumberOfRoles; ++role)
  {
    for (Entry* e : in.Roles[role])
    {
      e->Culled = false;
      if (!usable || e->Footprint.empty())
      {
        continue;
      }
      // Where any layer shows, the surface is the composed terrain (layers below, opacity,
      // feathers and Add layers all move it), within the set's height range.
      const double lo = in.MinimumHeight, hi = in.MaximumHeight;
      if (!std::isfinite(lo) || !std::isfinite(hi))
      {
        continue;
      }
      // The samples at the top, raised by R_top (1 / cos t - 1), enclose the surface of a cell
      // whose centre is t = spacing / sqrt(2) from its corners.
      const double top = body->GetMaximumRadius() + std::max(hi, 0.0);
      const double bulge = top * (1.0 / std::cos(e->FootprintSpacing / std::sqrt(2.0)) - 1.0);
      const double heights[2] = { std::min(lo, 0.0) - 1.0, std::max(hi, 0.0) + bulge + 1.0 };
      bool outsideSome = false;
      std::vector<std::array<double, 3>> points;
      points.reserve(2 * e->Footprint.size());
      for (const auto& ll : e->Footprint)
      {
        for (double h : heights)
        {
          const double llh[3] = { ll[0], ll[1], h };
          double p[4] = { 0, 0, 0, 1 };
          body->GeodeticToCartesianQuiet(llh, p);
          bodyToWorld->MultiplyPoint(p, p);
          points.push_back({ p[0], p[1], p[2] });
        }
      }
      for (int k = 0; k < 6 && !outsideSome; ++k)
      {
        const double* q = planes + 4 * k;
        bool allOutside = true;
        for (const auto& p : points)
        {
          if (q[0] * p[0] + q[1] * p[1] + q[2] * p[2] + q[3] >= 0.0)
          {
            allOutside = false;
            break;
          }
        }
        outsideSome = allOutside;
      }
      e->Culled = outsideSome;
      this->NumberOfCulledLayers += outsideSome ? 1 : 0;
    }
  }
  in.UpdateComposed();
}

double vtkGlobeLayerSet::GetMinimumHeight()
{
  return this->Internals->MinimumHeight;
}

double vtkGlobeLayerSet::GetMaximumHeight()
{
  return this->Internals->MaximumHeight;
}

int vtkGlobeLayerSet::GetNumberOfComposedLayers(int role)
{
  if (role < 0 || role >= NumberOfRoles)
  {
    return 0;
  }
  return static_cast<int>(this->Internals->Composed[role].size());
}

int vtkGlobeLayerSet::GetNumberOfActiveHeightLayers()
{
  return this->GetNumberOfActiveLayers(vtkGlobeLayer::Height);
}

int vtkGlobeLayerSet::GetNumberOfActiveColorLayers()
{
  return this->GetNumberOfActiveLayers(vtkGlobeLayer::Color);
}

int vtkGlobeLayerSet::GetNumberOfActiveLayers(vtkGlobeLayer::Roles role)
{
  if (role < 0 || role >= NumberOfRoles)
  {
    return 0;
  }
  return static_cast<int>(this->Internals->Roles[role].size());
}

//------------------------------------------------------------------------------
namespace
{
// Whether this OpenGL's texture unit filters float textures with float weights: a 2 x 1 R32F
// texture holding 0 and 1, read linearly at 64 fractions f between its texels, must give f to
// float rounding (8-bit weights, NVIDIA's, miss by up to 2e-3). Where the probe cannot run,
// false: the shader filters, which is right everywhere.
bool FiltersFloatTexturesExactly(vtkOpenGLRenderWindow* window)
{
  constexpr int n = 64;
  vtkOpenGLState* state = window->GetState();
  const vtkGlobeShaderSources::ScopedOffscreenPass offscreen(state);
  vtkNew<vtkTextureObject> ramp, target;
  ramp->SetContext(window);
  target->SetContext(window);
  float values[2] = { 0.0f, 1.0f };
  ramp->SetWrapS(vtkTextureObject::ClampToEdge);
  ramp->SetWrapT(vtkTextureObject::ClampToEdge);
  ramp->SetMinificationFilter(vtkTextureObject::Linear);
  ramp->SetMagnificationFilter(vtkTextureObject::Linear);
  bool exact = false;
  if (ramp->Create2DFromRaw(2, 1, 1, VTK_FLOAT, values) && target->Create2D(n, 1, 4, VTK_FLOAT, false))
  {
    vtkNew<vtkOpenGLFramebufferObject> framebuffer;
    framebuffer->SetContext(window);
    framebuffer->Bind();
    framebuffer->AddColorAttachment(0, target);
    framebuffer->ActivateDrawBuffers(1);
    const std::string vs = vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader();
    const std::string columns = std::to_string(n) + ".0";
    const std::string fs = "//VTK::System::Dec\n"
                           "//VTK::Output::Dec\n"
                           "in vec2 texCoord;\n"
                           "uniform sampler2D ramp;\n"
                           "void main()\n"
                           "{\n"
                           "  float f = (floor(texCoord.x * " + columns + ") + 0.371) / " + columns + ";\n"
                           "  gl_FragData[0] = vec4(textureLod(ramp, vec2((0.5 + f) / 2.0, 0.5), 0.0).r, f, 0.0, 1.0);\n"
                           "}\n";
    vtkOpenGLQuadHelper quad(window, vs.c_str(), fs.c_str(), "");
    if (quad.Program && quad.Program->GetCompiled() &&
      framebuffer->CheckFrameBufferStatus(GL_FRAMEBUFFER))
    {
      window->GetShaderCache()->ReadyShaderProgram(quad.Program);
      ramp->Activate();
      quad.Program->SetUniformi("ramp", ramp->GetTextureUnit());
      state->vtkglViewport(0, 0, n, 1);
      quad.Render();
      ramp->Deactivate();
      float read[4 * n];
      framebuffer->ActivateReadBuffer(0);
      glReadPixels(0, 0, n, 1, GL_RGBA, GL_FLOAT, read);
      exact = true;
      for (int i = 0; i < n; ++i)
      {
        exact = exact && std::abs(read[4 * i] - read[4 * i + 1]) <= 1e-6f;
      }
    }
    if (quad.Program)
    {
      quad.Program->ReleaseGraphicsResources(window);
    }
    framebuffer->ReleaseGraphicsResources(window);
  }
  ramp->ReleaseGraphicsResources(window);
  target->ReleaseGraphicsResources(window);
  return exact;
}
} // namespace

int vtkGlobeLayerSet::GetTextureUnitFiltersExactly()
{
  return this->Internals->FiltersExactly;
}

bool vtkGlobeLayerSet::GetFiltersHeightsInShader()
{
  return this->HeightFiltering == HeightFilteringShader ||
    (this->HeightFiltering == HeightFilteringAutomatic && this->Internals->FiltersExactly != 1);
}

void vtkGlobeLayerSet::UploadTextures(vtkOpenGLRenderWindow* window, bool waitForPages)
{
  this->Internals->ReleaseRetired(window);
  if (this->Internals->ProbedWindow != window)
  {
    this->Internals->ProbedWindow = window;
    this->Internals->FiltersExactly = FiltersFloatTexturesExactly(window) ? 1 : 0;
  }
  for (auto& held : this->Internals->Entries)
  {
    Entry& e = *held;
    if (!e.Active)
    {
      continue;
    }
    if (e.Streamed)
    {
      this->Internals->Pages->AddFrameLayer(e.Layer);
      continue;
    }
    vtkGlobeLayer* layer = e.Layer;
    vtkDataArray* data = layer->GetData();
    // Only the data decides: composition settings change the layer's MTime, not its data,
    // and a new ValueScale or ValueOffset only maps it (a uniform, see BindUniforms).
    if (e.Texture && e.Texture->GetContext() == window && e.UploadedData == data &&
      (e.UploadedTime >= data->GetMTime() || layer->IsRescaledSince(e.UploadedTime)))
    {
      continue;
    }
    if (!e.Texture)
    {
      e.Texture = vtkSmartPointer<vtkTextureObject>::New();
    }
    e.Texture->SetContext(window);
    const int w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
    const int maxSize = vtkTextureObject::GetMaximumTextureSize(window);
    if (w > maxSize || h > maxSize)
    {
      vtkErrorMacro(<< "Layer " << (layer->GetFileName() ? layer->GetFileName() : "(in-memory)")
                    << " is " << w << " x " << h << " texels, more than this OpenGL allows ("
                    << maxSize << "); it is skipped");
      e.Active = false;
      for (auto& list : this->Internals->Roles)
      {
        list.erase(std::remove(list.begin(), list.end(), &e), list.end());
      }
      continue;
    }
    const bool height = layer->GetRole() == vtkGlobeLayer::Height;
    e.Texture->SetWrapS(e.Wraps ? vtkTextureObject::Repeat : vtkTextureObject::ClampToEdge);
    e.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    // The whole pyramid, made on the CPU as vtkGlobeTerrain samples it (voids left out of
    // the means, which glGenerateMipmap would spread), so that every level is filtered to the
    // footprint (Documentation/composition.md "Filtering to the footprint").
    const int levels = std::max(1, layer->GetNumberOfLevels());
    e.Texture->SetBaseLevel(0);
    e.Texture->SetMaxLevel(levels - 1);
    e.UploadedLevels = levels;
    const int type = height ? VTK_FLOAT : VTK_UNSIGNED_CHAR, components = height ? 1 : 4;
    e.Texture->Create2DFromRaw(w, h, components, type, data->GetVoidPointer(0));
    e.Texture->Bind();
    const GLenum internal = e.Texture->GetInternalFormat(type, components, false);
    const GLenum format = e.Texture->GetFormat(type, components, false);
    const GLenum glType = e.Texture->GetDataType(type);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int l = 1; l < levels; ++l)
    {
      vtkDataArray* level = layer->GetLevelData(l);
      int size[2];
      layer->GetLevelDimensions(l, size);
      if (!level)
      {
        e.UploadedLevels = l;
        break;
      }
      glTexImage2D(GL_TEXTURE_2D, l, internal, size[0], size[1], 0, format, glType,
        level->GetVoidPointer(0));
    }
    e.Texture->Deactivate();
    e.UploadedData = data;
    e.UploadedTime = data->GetMTime();
    e.UploadedScale = layer->GetValueScale();
    e.UploadedOffset = layer->GetValueOffset();
    ++this->NumberOfUploads;
  }
  // Geoids of the active height layers: the node grid as it is (texelFetch only).
  for (const Entry* e : this->Internals->Roles[vtkGlobeLayer::Height])
  {
    if (e->Geoid < 0)
    {
      continue;
    }
    GeoidTexture& g = this->Internals->Geoids[e->Geoid];
    vtkFloatArray* values = g.Geoid->GetValues();
    if (!values || (g.Texture && g.Texture->GetContext() == window && g.UploadedTime >= values->GetMTime()))
    {
      continue;
    }
    if (!g.Texture)
    {
      g.Texture = vtkSmartPointer<vtkTextureObject>::New();
    }
    g.Texture->SetContext(window);
    g.Texture->SetMinificationFilter(vtkTextureObject::Nearest);
    g.Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    g.Texture->Create2DFromRaw(g.Geoid->GetNumberOfColumns(), g.Geoid->GetNumberOfRows(), 1,
      VTK_FLOAT, values->GetVoidPointer(0));
    g.UploadedTime = values->GetMTime();
    ++this->NumberOfUploads;
  }
  // Streamed layers: the pages the last frames asked for, and the coarsest of new layers.
  this->Internals->Pages->BeginFrame(window, waitForPages);
  for (auto& list : this->Internals->Roles)
  {
    // A layer whose coarsest page could not be read or placed is skipped.
    list.erase(std::remove_if(list.begin(), list.end(),
                 [this](Entry* e) {
                   return e->Streamed && !this->Internals->Pages->GetTable(e->Layer);
                 }),
      list.end());
  }
  // Culling decided earlier in the frame stands (the mapper uploads again while it waits for
  // pages).
  this->Internals->UpdateComposed();
  this->ComputeHeightRange();
}

size_t vtkGlobeLayerSet::GetTextureMemory()
{
  size_t bytes = this->Internals->Pages->GetGPUMemoryUsed();
  for (auto& held : this->Internals->Entries)
  {
    const Entry& e = *held;
    if (e.Texture && e.Texture->GetHandle())
    {
      // Mipmaps add a third.
      bytes += static_cast<size_t>(e.Texture->GetWidth()) * e.Texture->GetHeight() *
        e.Texture->GetComponents() * (e.Layer->GetRole() == vtkGlobeLayer::Height ? 4 : 1) * 4 / 3;
    }
  }
  for (const GeoidTexture& g : this->Internals->Geoids)
  {
    if (g.Texture && g.Texture->GetHandle())
    {
      bytes += static_cast<size_t>(g.Texture->GetWidth()) * g.Texture->GetHeight() * 4;
    }
  }
  return bytes;
}

//------------------------------------------------------------------------------
namespace
{
bool Included(int role, int roles)
{
  return (roles >> role) & 1;
}

// The geoids the active height layers use (indices into vtkInternals::Geoids), each once.
std::vector<int> UsedGeoids(const std::vector<Entry*>& heights)
{
  std::vector<int> used;
  for (const Entry* e : heights)
  {
    if (e->Geoid >= 0 && std::find(used.begin(), used.end(), e->Geoid) == used.end())
    {
      used.push_back(e->Geoid);
    }
  }
  return used;
}

// The uniform name prefix of the i-th layer of a role ("globeHeight0", "globeColor2", ...).
std::string Prefix(int role, size_t i)
{
  return std::string("globe") + RoleFunction(role) + std::to_string(i);
}

// Emits one layer's blend into `target` with weight `w` and value `v`. A run of consecutive
// Average layers accumulates into sumW/sumV and is resolved by ResolveAverage.
void EmitBlend(std::ostream& s, int mode, const char* target, const char* v)
{
  switch (mode)
  {
    case vtkGlobeLayer::Add:
      s << "    " << target << " += w * " << v << ";\n";
      break;
    case vtkGlobeLayer::Average:
      s << "    sumW += w;\n    sumV += w * " << v << ";\n";
      break;
    default:
      s << "    " << target << " = mix(" << target << ", " << v << ", w);\n";
  }
}

// The (lon, lat) a generated function passes to a layer, optionally displaced by small steps
// (GLSL expressions): hi + lo pairs with the steps added to the lo parts; or, without high
// precision, one float each (hi = the sum, lo = the step), as before hi + lo existed.
struct LonLat
{
  std::string LonHi, LonLo, LatHi, LatLo;
};
LonLat At(bool highPrecision, const char* dLon = nullptr, const char* dLat = nullptr)
{
  if (highPrecision)
  {
    return { "lonHi", dLon ? std::string("(lonLo + ") + dLon + ")" : "lonLo", "latHi",
      dLat ? std::string("(latLo + ") + dLat + ")" : "latLo" };
  }
  return { "lon", dLon ? dLon : "0.0", "lat", dLat ? dLat : "0.0" };
}

// The GLSL expression of a layer's texture coordinates at (lon hi + lo, lat hi + lo).
// offsetOnly (projected layers): the projection's offset from its reference point instead,
// unwrapped (the function called with a zero reference, p2.xy = 0).
std::string UV(const Entry* e, const std::string& p, const LonLat& c, bool highPrecision,
  bool offsetOnly = false)
{
  if (e->Function.empty())
  {
    if (highPrecision)
    {
      return "globe_geographicUV(" + c.LonHi + ", " + c.LonLo + ", " + c.LatHi + ", " + c.LatLo +
        ", " + p + "Map, " + p + "MapLo)";
    }
    return "globe_geographicUV(" + c.LonHi + " + " + c.LonLo + ", " + c.LatHi + " + " + c.LatLo +
      ", " + p + "Map)";
  }
  std::string call = e->Function + "(" + c.LonHi + ", " + c.LonLo + ", " + c.LatHi + ", " + c.LatLo;
  for (int k = 0; k < 7; ++k)
  {
    call += offsetOnly && k == 2 ? ", vec4(0.0, 0.0, " + p + "Projection[2].zw)"
                                 : ", " + p + "Projection[" + std::to_string(k) + "]";
  }
  // A wrapping projected layer's u may round just past 0 or 1 at the antimeridian.
  return e->Wraps && !offsetOnly ? "globe_wrapU(" + call + "))" : call + ")";
}

// Declares a streamed layer's texture coordinates uv<i> and its level-0 texel coordinates
// st<i> as hi.xy + lo.zw (Documentation/streaming.md, "Exact addressing"). Geographic layers
// with high precision: from the hi + lo (lon, lat), exact products on the hi grids
// (globe_geographicTexels). Projected layers: the projection's offset from its reference point
// (the function called with a zero reference), added to the reference's texel coordinates in
// hi + lo. Otherwise uv times the size.
void EmitStreamedCoordinates(std::ostream& s, const Entry* e, const std::string& p, size_t i,
  bool hp)
{
  const std::string n = std::to_string(i);
  const LonLat c = At(hp);
  if (e->Function.empty())
  {
    s << "  vec2 uv" << n << " = " << UV(e, p, c, hp) << ";\n";
    if (hp)
    {
      s << "  vec4 st" << n << " = globe_geographicTexels(" << c.LonHi << ", " << c.LonLo << ", "
        << c.LatHi << ", " << c.LatLo << ", " << p << "Map, " << p << "MapLo, " << p
        << "Texels, " << p << "Turn);\n";
    }
    else
    {
      s << "  vec4 st" << n << " = vec4(uv" << n << " * " << p << "Pyramid.xy, 0.0, 0.0);\n";
    }
    return;
  }
  s << "  vec2 d" << n << " = " << UV(e, p, c, hp, true) << ";\n"
    << "  vec2 uv" << n << " = globe_projectionInDomain(" << c.LonHi << " + " << c.LonLo << ", "
    << c.LatHi << " + " << c.LatLo << ", " << p << "Projection[4]) ? " << p
    << "Projection[2].xy + d" << n << " : vec2(-1.0);\n";
  if (e->Wraps)
  {
    s << "  uv" << n << " = globe_wrapU(uv" << n << ");\n";
  }
  s << "  vec4 st" << n << " = vec4(" << p << "Texels.xy, " << p << "Texels.zw + d" << n
    << " * " << p << "Pyramid.xy);\n";
  if (e->Wraps)
  {
    // The reference follows the view, so a point across the seam lies a turn away: move the
    // hi part by a turn (exact: it is on the grid of float's ulp at twice the width).
    s << "  if (st" << n << ".x + st" << n << ".z >= " << p << "Pyramid.x) st" << n << ".x -= "
      << p << "Pyramid.x;\n"
      << "  else if (st" << n << ".x + st" << n << ".z < 0.0) st" << n << ".x += " << p
      << "Pyramid.x;\n";
  }
}

// A layer's filtered value (GLSL), with the screen derivatives dx, dy of its texture
// coordinates: its texture at texture coordinates `uv`, or for a streamed layer its pages
// (globe_pageGrad) at level-0 texel coordinates `uv` as hi + lo (StreamedTexels).
std::string Sample(const Entry* e, const std::string& p, const std::string& uv)
{
  if (!e->Streamed)
  {
    return "textureGrad(" + p + ", " + uv + ", dx, dy)";
  }
  const bool height = e->Layer->GetRole() == vtkGlobeLayer::Height;
  const bool nearest = e->Layer->GetInterpolation() == vtkGlobeLayer::Nearest;
  return std::string("globe_pageGrad(") + (height ? "globePagesHeights" : "globePagesImages") +
    ", " + p + "Table, " + p + "Pyramid, " + uv + ", dx, dy, " + (nearest ? "true" : "false") + ")";
}

// A layer's level-0 size in texels (GLSL vec2).
std::string Size(const Entry* e, const std::string& p)
{
  return e->Streamed ? p + "Pyramid.xy" : "vec2(textureSize(" + p + ", 0))";
}

void EmitResolveAverage(std::ostream& s, const char* target, const char* zero)
{
  s << "  if (sumW > 0.0) " << target << " = mix(" << target
    << ", sumV / sumW, min(sumW, 1.0));\n"
    << "  sumW = 0.0;\n  sumV = " << zero << ";\n";
}
} // namespace

std::string vtkGlobeLayerSet::GetShaderKey(int roles)
{
  const auto& in = *this->Internals;
  std::ostringstream key;
  // The passes' own code differs with the geodetic precision even without layers.
  key << (this->HighPrecisionGeodetic ? "H:" : "F:");
  key << (this->GetFiltersHeightsInShader() ? "S:" : "T:");
  for (int role = 0; role < NumberOfRoles; ++role)
  {
    if (!Included(role, roles) || in.Composed[role].empty())
    {
      continue;
    }
    key << RoleFunction(role)[0] << RoleFunction(role)[1] << "[";
    for (const Entry* e : in.Composed[role])
    {
      key << e->Layer->GetBlendMode()
          << (!e->Function.empty() ? e->Function.substr(13, 2) : "g") << (e->Wraps ? "w" : "")
          << (e->Layer->GetProjectionQualityWeight() ? "q" : "") << (e->Match ? "m" : "")
          << (e->Geoid >= 0 ? "G" + std::to_string(e->Geoid) +
                  (in.Geoids[e->Geoid].Geoid->IsGlobal() ? "w" : "")
                            : std::string())
          << (e->Streamed ? "s" : "")
          << (e->Streamed && e->Layer->GetInterpolation() == vtkGlobeLayer::Nearest ? "n" : "")
          << ",";
    }
    key << "]";
  }
  return key.str();
}

std::string vtkGlobeLayerSet::GetShaderCode(int roles)
{
  const auto& in = *this->Internals;
  std::ostringstream s;
  s << "// Generated by vtkGlobeLayerSet: " << this->GetShaderKey(roles) << "\n";
  bool projected = false;
  for (int role = 0; role < NumberOfRoles; ++role)
  {
    for (const Entry* e : in.Composed[role])
    {
      projected |= Included(role, roles) && !e->Function.empty();
    }
  }
  if (projected)
  {
    s << globe_projection << "\n";
  }
  // Streamed layers: the page atlases of the kinds they use, and the page lookup.
  bool streamed[2] = { false, false };
  for (int role = 0; role < NumberOfRoles; ++role)
  {
    for (const Entry* e : in.Composed[role])
    {
      streamed[role == vtkGlobeLayer::Height ? 0 : 1] |= Included(role, roles) && e->Streamed;
    }
  }
  if (streamed[0])
  {
    s << "uniform sampler2DArray globePagesHeights;\n";
  }
  if (streamed[1])
  {
    s << "uniform sampler2DArray globePagesImages;\n";
  }
  s << vtkGlobeFootprint;
  // Heights' level of detail: OpenGL's (the longer axis) per pixel; on the grid the shorter
  // axis within 16:1 (GLOBE_GRID_FOOTPRINT), since a grid cell seen at a grazing angle is long
  // along the view, and the longer axis there levels distant peaks. The screen pass's terrain
  // refinement places points too: it sets the grid's rule for its steps, then 1 again for the
  // shading (a variable there, not a constant).
  s << "#ifdef GLOBE_GRID_FOOTPRINT\nconst float globe_heightStretch = 1.0 / 16.0;\n#else\n"
       "float globe_heightStretch = 1.0;\n#endif\n";
  if (streamed[0] || streamed[1])
  {
    if (this->GetFiltersHeightsInShader())
    {
      s << "#define GLOBE_HEIGHTS_IN_SHADER\n";
    }
    s << vtkGlobePages;
  }
  // Shared helpers: texture coordinates of a geographic layer, the coverage weight with its
  // feathered border, and Kooima's projection-quality weight.
  const bool hp = this->HighPrecisionGeodetic;
  s << "const float globe_TwoPi = 6.283185307179586;\n";
  if (hp)
  {
    // map: (west hi, longitude span, north hi, latitude span), mapLo: (west lo, north lo). The
    // hi parts of the edges and of (lon, lat) lie on the 2^-12 rad grid of globe_splitOnGrid,
    // so their differences are exact; a negative one takes a whole turn in hi + lo.
    s << "uniform vec3 globeReferenceDirection;\n"
         "uniform vec4 globeGeodeticReference;\n"
         "vec2 globe_geographicUV(float lonHi, float lonLo, float latHi, float latLo, vec4 map,\n"
         "  vec2 mapLo)\n"
         "{\n"
         "  float hd = lonHi - map.x;\n"
         "  float k = hd < 0.0 ? 1.0 : 0.0;\n"
         "  float dLon = (hd + k * GLOBE_TWO_PI_HI) + ((lonLo - mapLo.x) + k * GLOBE_TWO_PI_LO);\n"
         "  float dLat = (map.z - latHi) + (mapLo.y - latLo);\n"
         "  return vec2(mod(dLon, globe_TwoPi) / map.y, dLat / map.w);\n"
         "}\n"
         // A streamed layer's level-0 texel coordinates (x east, y south) as hi.xy + lo.zw.
         // scale: texels per radian east (hi, lo) and south (hi, lo), the hi parts with 9
         // significant bits, so that a difference on the 2^-12 grid (15 bits) times a hi part
         // is exact; turn: texels per 2 pi (hi on the grid of those products, lo).
         "vec4 globe_geographicTexels(float lonHi, float lonLo, float latHi, float latLo,\n"
         "  vec4 map, vec2 mapLo, vec4 scale, vec2 turn)\n"
         "{\n"
         "  float hd = lonHi - map.x;\n"
         "  float k = hd < 0.0 ? 1.0 : 0.0;\n"
         "  float hv = map.z - latHi;\n"
         "  return vec4(hd * scale.x + k * turn.x, hv * scale.z,\n"
         "    hd * scale.y + ((lonLo - mapLo.x) * (scale.x + scale.y) + k * turn.y),\n"
         "    hv * scale.w + (mapLo.y - latLo) * (scale.z + scale.w));\n"
         "}\n";
  }
  else
  {
    s << "vec2 globe_geographicUV(float lon, float lat, vec4 map)\n"
         "{\n"
         "  return vec2(mod(lon - map.x, globe_TwoPi) / map.y, (map.z - lat) / map.w);\n"
         "}\n";
  }
  s << ""
       // u of a projected layer that wraps, into [0, 1); outside the projection's domain
       // (-1, -1) stays outside.
       "vec2 globe_wrapU(vec2 uv)\n"
       "{\n"
       "  return uv.y < -0.5 ? uv : vec2(uv.x - floor(uv.x), uv.y);\n"
       "}\n"
       // A height layer's weight in its skirt outside the raster (Entry::Skirt), and in uv the
       // point of the raster whose heights continue there (vtkGlobeTerrain's Skirt).
       "float globe_skirt(inout vec2 uv, vec4 skirt, out vec2 outside)\n"
       "{\n"
       "  outside = vec2(0.0);\n"
       "  if (uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0) return 1.0;\n"
       "  if (!(skirt.x > 0.0 || skirt.y > 0.0) || (uv.x == -1.0 && uv.y == -1.0)) return 0.0;\n"
       "  float dv = max(0.0, max(-uv.y, uv.y - 1.0));\n"
       "  bool west = uv.x < 0.0;\n"
       "  float du = west ? -uv.x : 0.0;\n"
       "  if (uv.x > 1.0)\n"
       "  {\n"
       "    west = skirt.z - uv.x < uv.x - 1.0;\n"
       "    du = west ? skirt.z - uv.x : uv.x - 1.0;\n"
       "  }\n"
       "  float w = (du > 0.0 ? (skirt.x > 0.0 ? max(0.0, 1.0 - du / skirt.x) : 0.0) : 1.0) *\n"
       "    (dv > 0.0 ? (skirt.y > 0.0 ? max(0.0, 1.0 - dv / skirt.y) : 0.0) : 1.0);\n"
       "  uv = vec2(west ? 0.0 : min(uv.x, 1.0), clamp(uv.y, 0.0, 1.0));\n"
       "  outside = vec2(du, dv);\n"
       "  return w;\n"
       "}\n"
       "float globe_coverage(vec2 uv, vec4 border)\n"
       "{\n"
       "  if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0) return 0.0;\n"
       "  float w = 1.0;\n"
       "  if (border.x > 0.0) w *= clamp(min(uv.x, 1.0 - uv.x) / border.x, 0.0, 1.0);\n"
       "  if (border.y > 0.0) w *= clamp(min(uv.y, 1.0 - uv.y) / border.y, 0.0, 1.0);\n"
       "  return w;\n"
       "}\n"
       // k: the texel aspect of the map at (lon, lat): texels per metre east over texels per
       // metre north, from the texture coordinates of two nearby points.
       "float globe_quality(vec2 uv, vec2 uvEast, vec2 uvNorth, float cosLat, vec2 size,\n"
       "  float invLogN, bool wraps)\n"
       "{\n"
       "  vec2 e = uvEast - uv;\n"
       "  if (wraps) e.x -= floor(e.x + 0.5);\n"
       "  float te = length(e * size) / max(cosLat, 1e-6);\n"
       "  float tn = length((uvNorth - uv) * size);\n"
       "  if (!(te > 0.0) || !(tn > 0.0)) return 1.0;\n"
       "  return clamp(1.0 - abs(log(te / tn)) * invLogN, 0.0, 1.0);\n"
       "}\n"
       // Screen derivatives of texture coordinates; across a wrapping layer's seam they jump
       // by a whole turn, which would select the coarsest mipmap along a line of pixels.
       "void globe_uvDerivatives(vec2 uv, bool wraps, out vec2 dx, out vec2 dy)\n"
       "{\n"
       "  dx = dFdx(uv);\n"
       "  dy = dFdy(uv);\n"
       "  if (wraps) { dx.x -= floor(dx.x + 0.5); dy.x -= floor(dy.x + 0.5); }\n"
       "}\n";
  if (this->GetFiltersHeightsInShader())
  {
    s << ""
         // A height texture's value at uv, filtered as LINEAR_MIPMAP_LINEAR between levels 0 and
         // levels.x (levels.y > 0: nearest, which the hardware does exactly) but with float
         // weights: GPUs filter with 8-bit weights (a 256th of the step between two texels, up
         // to metres on steep terrain), which rays along the ground magnify to pixels
         // (Documentation/composition.md, "Exact height filtering").
         "float globe_bilinear(sampler2D t, vec2 uv, int level, bool wraps)\n"
         "{\n"
         // The pyramid's sizes (vtkGlobeLayer::GetLevelData: floor(w / 2^l)); llvmpipe's
         // textureSize(t, level) gave other ones for levels above 0 (Mesa 22.3).
         "  ivec2 size = max(textureSize(t, 0) >> level, ivec2(1));\n"
         "  vec2 x = uv * vec2(size) - 0.5;\n"
         "  vec2 i = floor(x);\n"
         "  vec2 f = x - i;\n"
         "  ivec2 i0 = ivec2(i);\n"
         "  ivec2 i1 = i0 + 1;\n"
         "  if (wraps)\n"
         "  {\n"
         "    i0.x -= size.x * int(floor(float(i0.x) / float(size.x)));\n"
         "    i1.x = i0.x + 1 == size.x ? 0 : i0.x + 1;\n"
         "  }\n"
         "  i0 = clamp(i0, ivec2(0), size - 1);\n"
         "  i1 = clamp(i1, ivec2(0), size - 1);\n"
         "  float a = texelFetch(t, i0, level).r;\n"
         "  float b = texelFetch(t, ivec2(i1.x, i0.y), level).r;\n"
         "  float c = texelFetch(t, ivec2(i0.x, i1.y), level).r;\n"
         "  float d = texelFetch(t, i1, level).r;\n"
         "  return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);\n"
         "}\n"
         "float globe_heightLod(sampler2D t, vec2 uv, float lod, vec2 levels, bool wraps)\n"
         "{\n"
         "  if (levels.y > 0.0) return textureLod(t, uv, lod).r;\n"
         "  float l = lod > 0.0 ? min(lod, levels.x) : 0.0; // NaN: level 0\n"
         "  int l0 = int(l);\n"
         "  float f = l - float(l0);\n"
         "  float a = globe_bilinear(t, uv, l0, wraps);\n"
         "  return f > 0.0 ? mix(a, globe_bilinear(t, uv, l0 + 1, wraps), f) : a;\n"
         "}\n";
  }

  // Geoids of height layers (vertical datum Geoid): N and its gradient per radian, bilinear
  // between the nodes as vtkGlobeGeoid::GetUndulation (and PROJ) interpolate; w = 0 outside a
  // regional grid or next to a node without value.
  const std::vector<int> geoids = Included(vtkGlobeLayer::Height, roles) ? UsedGeoids(in.Composed[vtkGlobeLayer::Height]) : std::vector<int>();
  if (!geoids.empty())
  {
    s << "vec4 globe_geoid(sampler2D g, vec4 grid, bool wraps, float lon, float lat)\n"
         "{\n"
         "  ivec2 size = textureSize(g, 0);\n"
         "  float x = (lon - grid.x) / grid.z;\n"
         "  float y = (lat - grid.y) / grid.w;\n"
         "  if (wraps) x -= floor(x / float(size.x)) * float(size.x);\n"
         "  else if (x < 0.0 || x > float(size.x - 1)) return vec4(0.0);\n"
         "  if (y < -1e-3 || y > float(size.y - 1) + 1e-3) return vec4(0.0);\n"
         "  ivec2 i0 = ivec2(min(floor(x), float(size.x - 1)), clamp(floor(y), 0.0, float(size.y - 2)));\n"
         "  vec2 f = vec2(x - float(i0.x), clamp(y - float(i0.y), 0.0, 1.0));\n"
         "  int i1 = wraps ? (i0.x + 1) % size.x : min(i0.x + 1, size.x - 1);\n"
         "  float a = texelFetch(g, i0, 0).r;\n"
         "  float b = texelFetch(g, ivec2(i1, i0.y), 0).r;\n"
         "  float c = texelFetch(g, ivec2(i0.x, i0.y + 1), 0).r;\n"
         "  float d = texelFetch(g, ivec2(i1, i0.y + 1), 0).r;\n"
         "  float n = mix(mix(a, b, f.x), mix(c, d, f.x), f.y);\n"
         "  vec2 gradient = vec2(mix(b - a, d - c, f.y) / grid.z, mix(c - a, d - b, f.x) / grid.w);\n"
         "  return isnan(n) || isnan(gradient.x) || isnan(gradient.y) ? vec4(0.0) : vec4(n, gradient, 1.0);\n"
         "}\n";
    for (int k : geoids)
    {
      s << "uniform sampler2D globeGeoid" << k << ";\nuniform vec4 globeGeoid" << k << "Grid;\n";
    }
  }
  for (int role = 0; role < NumberOfRoles; ++role)
  {
    const auto& list = in.Composed[role];
    if (!Included(role, roles) || list.empty())
    {
      continue;
    }
    for (size_t i = 0; i < list.size(); ++i)
    {
      const std::string p = Prefix(role, i);
      if (list[i]->Streamed)
      {
        s << "uniform usampler2D " << p << "Table;\n"
          << "uniform vec4 " << p << "Pyramid;\n";
        if (hp || !list[i]->Function.empty())
        {
          s << "uniform vec4 " << p << "Texels;\n";
        }
        if (hp && list[i]->Function.empty())
        {
          s << "uniform vec2 " << p << "Turn;\n";
        }
      }
      else
      {
        s << "uniform sampler2D " << p << ";\n";
      }
      if (role == vtkGlobeLayer::Height && !list[i]->Streamed && this->GetFiltersHeightsInShader())
      {
        s << "uniform vec2 " << p << "Levels;\n"; // top level, nearest (globe_heightLod)
      }
      s << "uniform vec4 " << p << "Map;\n";
      if (hp && list[i]->Function.empty())
      {
        s << "uniform vec2 " << p << "MapLo;\n";
      }
      if (!list[i]->Function.empty())
      {
        s << "uniform vec4 " << p << "Projection[7];\n";
      }
      if (role == vtkGlobeLayer::Height)
      {
        s << "uniform vec2 " << p << "Value;\n" // texture or pages -> metres: scale, offset
          << "uniform vec4 " << p << "Skirt;\n";
      }
      if (list[i]->Match)
      {
        s << "uniform vec3 " << p << "MatchGain;\n"
          << "uniform vec3 " << p << "MatchOffset;\n"
          << "uniform vec4 " << p << "MatchBorder;\n";
      }
      s << ""
        << "uniform vec4 " << p << "Style;\n" // opacity, gamma, valid min, valid max
        << "uniform vec4 " << p << "Border;\n";
    }
    const bool height = role == vtkGlobeLayer::Height;
    const std::string fn = RoleFunction(role);
    // Signature and accumulator by role.
    const char* type = "vec3";
    const char* zero = "vec3(0.0)";
    const char* target = "c";
    switch (role)
    {
      case vtkGlobeLayer::Height:
        s << "float globe_composeHeight(float lonHi, float lonLo, float latHi, float latLo, out vec2 gradient)\n{\n";
        type = "vec3"; // (h, gradient)
        zero = "vec3(0.0)";
        target = "hg";
        s << "  vec3 hg = vec3(0.0);\n";
        break;
      case vtkGlobeLayer::Color:
        s << "vec3 globe_composeColor(float lonHi, float lonLo, float latHi, float latLo, vec3 base)\n{\n  vec3 c = base;\n";
        break;
      case vtkGlobeLayer::NormalMap:
        // xyz: the tangent-space normal; w: its summed weight.
        s << "vec4 globe_composeNormal(float lonHi, float lonLo, float latHi, float latLo)\n{\n  vec4 c = vec4(0.0, 0.0, 1.0, "
             "0.0);\n";
        type = "vec4";
        zero = "vec4(0.0)";
        break;
      case vtkGlobeLayer::Overlay:
        // Premultiplied: the lit colour becomes lit * (1 - a) + rgb.
        s << "vec4 globe_composeOverlay(float lonHi, float lonLo, float latHi, float latLo)\n{\n  vec4 c = vec4(0.0);\n";
        type = "vec4";
        zero = "vec4(0.0)";
        break;
      case vtkGlobeLayer::Mask:
        s << "float globe_composeMask(float lonHi, float lonLo, float latHi, float latLo)\n{\n  float c = 0.0;\n";
        type = "float";
        zero = "0.0";
        break;
      default:
        s << "vec3 globe_composeNightLights(float lonHi, float lonLo, float latHi, float latLo)\n{\n  vec3 c = vec3(0.0);\n";
    }
    // Without high precision the pairs become one float each (the lo parts are 0.0 there).
    s << (hp ? "" : "  float lon = lonHi + lonLo;\n") << "  float lat = latHi + latLo;\n"
      << "  float cosLat = cos(lat);\n"
         "  float w;\n  float sumW = 0.0;\n  "
      << type << " sumV = " << zero << ";\n"
      << "  vec2 uv, uvs, uvE, uvN, dx, dy, outside;\n  float least;\n";
    if (height)
    {
      for (int k : geoids)
      {
        s << "  vec4 geoid" << k << " = globe_geoid(globeGeoid" << k << ", globeGeoid" << k
          << "Grid, " << (in.Geoids[k].Geoid->IsGlobal() ? "true" : "false")
          << ", lonHi + lonLo, lat);\n";
      }
    }
    // All texture coordinates and their derivatives first, in uniform control flow.
    for (size_t i = 0; i < list.size(); ++i)
    {
      const Entry* e = list[i];
      const std::string p = Prefix(role, i);
      const std::string wraps = e->Wraps ? "true" : "false";
      if (e->Streamed)
      {
        EmitStreamedCoordinates(s, e, p, i, hp);
      }
      else
      {
        s << "  vec2 uv" << i << " = " << UV(e, p, At(hp), hp) << ";\n";
      }
      s << "  vec2 dx" << i << ", dy" << i << ";\n";
      // The layer's Jacobian: texture coordinates per radian of lon (jLon) and lat (jLat). A
      // projected layer's comes from two nearby points, with offsets passed as the low parts
      // of (lon, lat) (exact steps), and serves both the footprint and the heights' gradient.
      if (e->Function.empty())
      {
        s << "  vec2 jLon" << i << " = vec2(1.0 / " << p << "Map.y, 0.0);\n"
          << "  vec2 jLat" << i << " = vec2(0.0, -1.0 / " << p << "Map.w);\n";
      }
      else
      {
        const std::string lon = "jLon" + std::to_string(i), lat = "jLat" + std::to_string(i);
        s << "  vec2 " << lon << " = " << UV(e, p, At(hp, "1e-4"), hp) << " - uv" << i << ";\n"
          << "  vec2 " << lat << " = " << UV(e, p, At(hp, nullptr, "(lat > 0.0 ? -1e-4 : 1e-4)"), hp)
          << " - uv" << i << ";\n";
        if (e->Wraps)
        {
          s << "  " << lon << ".x -= floor(" << lon << ".x + 0.5);\n"
            << "  " << lat << ".x -= floor(" << lat << ".x + 0.5);\n";
        }
        else if (e->Projection && e->Projection->HasMapCut())
        {
          // A map cut opposite the central meridian: a step east of a point next to it lands
          // on the map's other side. The step west then gives the derivative.
          s << "  {\n    vec2 west = uv" << i << " - " << UV(e, p, At(hp, "-1e-4"), hp) << ";\n"
            << "    if (dot(west, west) < dot(" << lon << ", " << lon << ")) " << lon << " = west;\n  }\n";
        }
        s << "  " << lon << " /= 1e-4;\n  " << lat << " /= lat > 0.0 ? -1e-4 : 1e-4;\n";
      }
      // In the grid and screen passes, the footprint is the step towards the nearer neighbour
      // along each axis (globeFootprint, radians of lon and lat) through the Jacobian: a grid
      // point next to the horizon, or a pixel on a ridge's silhouette, keeps the level of its
      // own surface where screen derivatives would take that of the long step across to
      // another one (the horizon's far side, the terrain behind the ridge).
      s << "#ifdef GLOBE_FOOTPRINT\n"
        << "  dx" << i << " = jLon" << i << " * globeFootprint.x + jLat" << i
        << " * globeFootprint.y;\n"
        << "  dy" << i << " = jLon" << i << " * globeFootprint.z + jLat" << i
        << " * globeFootprint.w;\n"
        << "#else\n";
      s << "  globe_uvDerivatives(uv" << i << ", " << wraps << ", dx" << i << ", dy" << i << ");\n"
        << "#endif\n";
    }
    for (size_t i = 0; i < list.size(); ++i)
    {
      const Entry* e = list[i];
      vtkGlobeLayer* layer = e->Layer;
      const std::string p = Prefix(role, i);
      const std::string n = std::to_string(i);
      const int mode = layer->GetBlendMode();
      s << "  // " << layer->GetRoleAsString() << " layer '" << layer->GetName() << "', "
        << layer->GetBlendModeAsString() << "\n";
      s << "  uv = uv" << n << ";\n  dx = dx" << n << ";\n  dy = dy" << n << ";\n";
      if (height)
      {
        // uvs: where the heights are read (the raster's nearest point within its skirt).
        // In the skirt the edge is read coarser with the distance (vtkGlobeLayer::ApplySkirt).
        s << "  uvs = uv;\n  w = globe_skirt(uvs, " << p << "Skirt, outside) * globe_coverage(uvs, "
          << p << "Border) * " << p << "Style.x;\n"
          << "  least = log2(max(1.0, max(outside.x * " << Size(e, p) << ".x, outside.y * "
          << Size(e, p) << ".y)));\n";
      }
      else
      {
        s << "  w = globe_coverage(uv, " << p << "Border) * " << p << "Style.x;\n";
      }
      if (layer->GetProjectionQualityWeight())
      {
        s << "  if (w > 0.0)\n  {\n"
          << "    uvE = " << UV(e, p, At(hp, "1e-3"), hp) << ";\n"
          << "    uvN = " << UV(e, p, At(hp, nullptr, "(lat > 0.0 ? -1e-3 : 1e-3)"), hp) << ";\n"
          << "    w *= globe_quality(uv, uvE, uvN, cosLat, " << Size(e, p) << ", " << p
          << "Border.z, " << (e->Wraps ? "true" : "false") << ");\n"
          << "  }\n";
      }
      s << "  if (w > 0.0)\n  {\n";
      if (height)
      {
        // Value and gradient per radian of lon and lat (central differences one texel apart).
        s << "    vec2 texel = 1.0 / " << Size(e, p) << ";\n";
        if (e->Streamed)
        {
          // In the skirt, the texel coordinates of the raster's edge (exact: 0 or the size).
          s << "    vec4 sts = st" << n << ";\n"
            << "    if (uvs.x != uv.x) sts.xz = vec2(uvs.x * " << p << "Pyramid.x, 0.0);\n"
            << "    if (uvs.y != uv.y) sts.yw = vec2(uvs.y * " << p << "Pyramid.y, 0.0);\n";
          s << "    float v;\n    vec4 ewns;\n"
            << "    globe_pageHeights(globePagesHeights, " << p << "Table, " << p
            << "Pyramid, sts, dx, dy, "
            << (e->Function.empty() ? "min(globe_heightStretch, 10.0 * cosLat)" : "globe_heightStretch") << ", least, "
            << (layer->GetInterpolation() == vtkGlobeLayer::Nearest ? "true" : "false")
            << ", v, ewns);\n"
            << "    float vE = ewns.x, vW = ewns.y, vN = ewns.z, vS = ewns.w;\n";
        }
        else
        {
          // The streamed layers' level (the polar rule included), so both filter alike.
          s << "    float lod = max(globe_footprintLodHeights(vec4(" << Size(e, p) << ", 64.0, 0.0), dx, dy, "
            << (e->Function.empty() ? "min(globe_heightStretch, 10.0 * cosLat)" : "globe_heightStretch") << "), least);\n"
            << "    float v = " << (this->GetFiltersHeightsInShader()
                                ? "globe_heightLod(" + p + ", uvs, lod, " + p + "Levels, " +
                                  (e->Wraps ? "true" : "false") + ")"
                                : "textureLod(" + p + ", uvs, lod).r")
            << ";\n"
            << "    float vE = textureLod(" << p << ", uvs + vec2(texel.x, 0.0), lod).r;\n"
            << "    float vW = textureLod(" << p << ", uvs - vec2(texel.x, 0.0), lod).r;\n"
            << "    float vN = textureLod(" << p << ", uvs - vec2(0.0, texel.y), lod).r;\n"
            << "    float vS = textureLod(" << p << ", uvs + vec2(0.0, texel.y), lod).r;\n";
        }
        if (e->Function.empty())
        {
          s << "    vec2 gi = vec2((vE - vW) / (2.0 * texel.x * " << p << "Map.y),\n"
            << "                   (vN - vS) / (2.0 * texel.y * " << p << "Map.w));\n";
        }
        else
        {
          // Per texture unit (u east, v south), then per radian through the layer's Jacobian.
          s << "    vec2 perUV = vec2((vE - vW) / (2.0 * texel.x), (vS - vN) / (2.0 * texel.y));\n"
            << "    vec2 gi = vec2(dot(perUV, jLon" << n << "), dot(perUV, jLat" << n << "));\n";
        }
        s << "    v = v * " << p << "Value.x + " << p << "Value.y;\n    gi *= " << p
          << "Value.x;\n";
        s
          << "    bool valid = !isnan(v) && !isnan(gi.x) && !isnan(gi.y) && v >= " << p
          << "Style.z && v <= " << p << "Style.w;\n";
        if (e->Geoid >= 0)
        {
          // Heights above the geoid: h = H + N (Documentation/geodesy.md "Vertical datums").
          const std::string g = "geoid" + std::to_string(e->Geoid);
          s << "    valid = valid && " << g << ".w > 0.0;\n"
            << "    v += " << g << ".x;\n    gi += " << g << ".yz;\n";
        }
        s << "    if (!valid) w = 0.0;\n"
          << "    vec3 value = valid ? vec3(v, gi) : vec3(0.0);\n";
        EmitBlend(s, mode, target, "value");
      }
      else
      {
        s << "    vec4 t = " << Sample(e, p, e->Streamed ? "st" + n : "uv") << ";\n"
          << "    w *= t.a;\n"
          << "    vec3 rgb = pow(t.rgb, vec3(" << p << "Style.y));\n";
        if (e->Match)
        {
          // Towards the statistics below: fully at the edge, not at all MatchBorder inside.
          s << "    rgb = mix(clamp(rgb * " << p << "MatchGain + " << p
            << "MatchOffset, 0.0, 1.0), rgb, globe_coverage(uv, " << p << "MatchBorder));\n";
        }
        switch (role)
        {
          case vtkGlobeLayer::NormalMap:
            s << "    vec4 value = vec4(normalize(2.0 * t.rgb - 1.0), 1.0);\n";
            EmitBlend(s, mode, target, "value");
            break;
          case vtkGlobeLayer::Mask:
            EmitBlend(s, mode, target, "rgb.r");
            break;
          case vtkGlobeLayer::Overlay:
            EmitBlend(s, mode, target, "vec4(rgb, 1.0)");
            break;
          default:
            EmitBlend(s, mode, target, "rgb");
        }
      }
      s << "  }\n";
      const bool lastOfRun = i + 1 == list.size() ||
        list[i + 1]->Layer->GetBlendMode() != vtkGlobeLayer::Average;
      if (mode == vtkGlobeLayer::Average && lastOfRun)
      {
        EmitResolveAverage(s, target, zero);
      }
    }
    switch (role)
    {
      case vtkGlobeLayer::Height:
        s << "  gradient = hg.yz;\n  return hg.x;\n}\n";
        break;
      case vtkGlobeLayer::NormalMap:
        s << "  return vec4(normalize(c.xyz), min(c.w, 1.0));\n}\n";
        break;
      case vtkGlobeLayer::Overlay:
        s << "  return vec4(c.rgb, min(c.a, 1.0));\n}\n";
        break;
      default:
        s << "  return c;\n}\n";
    }
  }
  if (in.Composed[vtkGlobeLayer::Height].empty())
  {
    // Always defined: the passes call it.
    s << "float globe_composeHeight(float lonHi, float lonLo, float latHi, float latLo, out vec2 gradient)\n"
         "{\n  gradient = vec2(0.0);\n  return 0.0;\n}\n";
  }
  return s.str();
}

//------------------------------------------------------------------------------
vtkGlobePageCache* vtkGlobeLayerSet::GetPageCache()
{
  return this->Internals->Pages;
}

int vtkGlobeLayerSet::GetNumberOfStreamedLayers()
{
  int n = 0;
  for (const auto& list : this->Internals->Roles)
  {
    n += static_cast<int>(std::count_if(list.begin(), list.end(), [](Entry* e) { return e->Streamed; }));
  }
  return n;
}

void vtkGlobeLayerSet::RequestPages(vtkDoubleArray* footprints, int blockPixels, double gridCellPixels)
{
  auto& in = *this->Internals;
  if (!footprints || footprints->GetNumberOfComponents() != 6)
  {
    return;
  }
  const double pi = vtkMath::Pi(), twoPi = 2.0 * pi;
  const double deg = 180.0 / pi;
  const double gridLod = std::log2(std::max(1.0, gridCellPixels));
  const vtkIdType n = footprints->GetNumberOfTuples();
  for (const auto& list : in.Roles)
  {
    for (Entry* e : list)
    {
      if (!e->Streamed)
      {
        continue;
      }
      vtkGlobeLayer* layer = e->Layer;
      vtkGlobePageSource* pages = layer->GetPageSource();
      // The cache's description of the pyramid (its levels, its page size); the page source
      // gives the level-0 size and the page counts for the same page size.
      const int levels = in.Pages->GetNumberOfLevels(layer);
      const int P = in.Pages->GetPageSize();
      if (levels <= 0 || pages->GetPageSize() != P || pages->GetNumberOfLevels() != levels)
      {
        continue; // a page size change the next BeginFrame applies
      }
      // Per level: texels per unit of uv (level 0's size / 2^l, as vtkGlobePageCache maps
      // them), page columns and rows.
      std::vector<std::array<double, 4>> level(levels);
      int size0[2];
      pages->GetLevelSize(0, size0);
      for (int l = 0; l < levels; ++l)
      {
        int count[2];
        pages->GetNumberOfPages(l, count);
        level[l] = { std::ldexp(static_cast<double>(size0[0]), -l),
          std::ldexp(static_cast<double>(size0[1]), -l), static_cast<double>(count[0]),
          static_cast<double>(count[1]) };
      }
      const bool height = layer->GetRole() == vtkGlobeLayer::Height;
      // The layer's texture coordinates at (lon, lat), in double; false outside its domain.
      double origin[2], pixel[2];
      layer->GetProjectedGeoTransform(origin, pixel);
      const double W = layer->GetNumberOfColumns(), H = layer->GetNumberOfRows();
      auto uvAt = [&](double lon, double lat, double uv[2]) -> bool {
        if (e->Function.empty())
        {
          uv[0] = std::fmod(lon - e->Map[0], twoPi);
          uv[0] = (uv[0] < 0.0 ? uv[0] + twoPi : uv[0]) / e->Map[1];
          uv[1] = (e->Map[2] - lat) / e->Map[3];
          return true;
        }
        // Points outside the projection's domain are expected (the shader shows nothing there).
        double xy[2];
        const bool ok = e->Projection->ForwardInDomain(lon * deg, lat * deg, xy);
        uv[0] = (xy[0] - origin[0]) / (pixel[0] * W);
        uv[1] = (origin[1] - xy[1]) / (pixel[1] * H);
        return ok && std::isfinite(uv[0]) && std::isfinite(uv[1]);
      };
      for (vtkIdType i = 0; i < n; ++i)
      {
        double f[6];
        footprints->GetTuple(i, f);
        double uv[2], ux[2], uy[2];
        if (!uvAt(f[0], f[1], uv) || !uvAt(f[0] + f[2], f[1] + f[3], ux) ||
          !uvAt(f[0] + f[4], f[1] + f[5], uy))
        {
          continue;
        }
        double du[2] = { ux[0] - uv[0], ux[1] - uv[1] };
        double dv[2] = { uy[0] - uv[0], uy[1] - uv[1] };
        if (e->Wraps)
        {
          du[0] -= std::floor(du[0] + 0.5);
          dv[0] -= std::floor(dv[0] + 0.5);
        }
        // A height layer's skirt reads the raster's edge pages, coarser with the distance.
        double blur = 1.0;
        if (height)
        {
          const double skirt[3] = { e->Skirt[0], e->Skirt[1], e->Function.empty() ? e->Skirt[2] : 0.0 };
          double at[2] = { uv[0], uv[1] }, outside[2];
          if ((skirt[0] > 0.0 || skirt[1] > 0.0) && vtkGlobeLayer::ApplySkirt(skirt, at, outside) > 0.0)
          {
            uv[0] = at[0];
            uv[1] = at[1];
            blur = std::max(1.0, std::max(outside[0] * W, outside[1] * H));
          }
        }
        // The block this sample stands for, in texture coordinates (one pixel of margin).
        const double reach = 0.5 * blockPixels + 1.0;
        const double halfU = reach * (std::abs(du[0]) + std::abs(dv[0]));
        const double halfV = reach * (std::abs(du[1]) + std::abs(dv[1]));
        if (!e->Wraps && (uv[0] + halfU < 0.0 || uv[0] - halfU > 1.0))
        {
          continue;
        }
        if (uv[1] + halfV < 0.0 || uv[1] - halfV > 1.0)
        {
          continue;
        }
        // The footprint's level as the shader chooses it: the longer screen axis
        // (globe_footprintLod); for geographic height layers within 6 degrees of a pole, down to
        // the Jacobian's shorter axis (globe_footprintLodHeights).
        const double ax = du[0] * W, ay = du[1] * H, bx = dv[0] * W, by = dv[1] * H;
        double rho = std::max(std::hypot(ax, ay), std::hypot(bx, by));
        const double stretch = std::min(1.0, 10.0 * std::cos(f[1]));
        if (height && e->Function.empty() && stretch < 1.0)
        {
          const double t = ax * ax + ay * ay + bx * bx + by * by;
          const double det = std::abs(ax * by - ay * bx);
          const double major = std::sqrt(0.5 * t + std::sqrt(std::max(0.25 * t * t - det * det, 0.0)));
          rho = std::max(det / std::max(major, 1e-300), rho * stretch);
        }
        const double lod = std::log2(std::max(std::max(rho, blur), 1e-30));
        auto ask = [&](double at) {
          // Linear filtering blends floor(lod) and the level above; nearest takes the
          // nearer of the two. Both are asked for either way: the coarser one is the
          // fallback within one level while the finer one loads.
          const double clamped = std::min(std::max(at, 0.0), levels - 1.0);
          const int first = static_cast<int>(std::floor(clamped));
          const int last = std::min(first + 1, levels - 1);
          for (int l = first; l <= last; ++l)
          {
            const auto& L = level[l];
            const int c0 = static_cast<int>(std::floor((uv[0] - halfU) * L[0] / P));
            const int c1 = static_cast<int>(std::floor((uv[0] + halfU) * L[0] / P));
            const int r0 = std::max(0, static_cast<int>(std::floor((uv[1] - halfV) * L[1] / P)));
            const int r1 =
              std::min(static_cast<int>(L[3]) - 1, static_cast<int>(std::floor((uv[1] + halfV) * L[1] / P)));
            const int columns = static_cast<int>(L[2]);
            if (c1 - c0 > 8 || r1 - r0 > 8)
            {
              continue; // a block this wide is sampled coarser; its neighbours ask too
            }
            for (int r = r0; r <= r1; ++r)
            {
              for (int c = c0; c <= c1; ++c)
              {
                int column = c;
                if (e->Wraps)
                {
                  column = ((c % columns) + columns) % columns;
                }
                else if (c < 0 || c >= columns)
                {
                  continue;
                }
                in.Pages->Request(layer, l, column, r);
              }
            }
          }
        };
        ask(lod);
        if (height)
        {
          ask(lod + gridLod);
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkGlobeLayerSet::SetGeodeticReference(const double direction[3], const double radii[3])
{
  const double largest = std::max(radii[0], std::max(radii[1], radii[2]));
  double q[3];
  for (int i = 0; i < 3; ++i)
  {
    this->ReferenceDirection[i] = direction[i];
    // The geodetic normal of the point in direction d (scaled space) is along d / radii.
    q[i] = direction[i] / (radii[i] / largest);
  }
  this->ReferenceLonLat[0] = std::atan2(q[1], q[0]);
  this->ReferenceLonLat[1] = std::atan2(q[2], std::hypot(q[0], q[1]));

  // A streamed projected layer's float offsets from its projection's reference point are
  // exact to a small fraction of a texel only within some 1e5 texels of it (2^-24 of the
  // distance): the reference follows the view, the camera's sub-point clamped into the raster.
  // Its hi + lo texel coordinates and the parameters are uniforms: nothing is rebuilt.
  const double lon = vtkMath::DegreesFromRadians(this->ReferenceLonLat[0]);
  const double lat = vtkMath::DegreesFromRadians(this->ReferenceLonLat[1]);
  for (const auto& list : this->Internals->Roles)
  {
    for (Entry* e : list)
    {
      double xy[2], origin[2], pixel[2];
      if (!e->Streamed || e->Function.empty() || !e->Projection ||
        !e->Projection->ForwardInDomain(lon, lat, xy))
      {
        continue;
      }
      e->Layer->GetProjectedGeoTransform(origin, pixel);
      double parameters[vtkGlobeMapProjection::NumberOfShaderParameters];
      const bool warnings = vtkObject::GetGlobalWarningDisplay();
      vtkObject::GlobalWarningDisplayOff();
      const bool ok = e->Projection->ComputeShaderParametersAt(origin, pixel,
        e->Layer->GetNumberOfColumns(), e->Layer->GetNumberOfRows(), xy, parameters);
      vtkObject::SetGlobalWarningDisplay(warnings);
      if (ok)
      {
        std::copy(parameters, parameters + vtkGlobeMapProjection::NumberOfShaderParameters,
          e->Parameters);
        e->Reference[0] = parameters[8];
        e->Reference[1] = parameters[9];
      }
    }
  }
}

void vtkGlobeLayerSet::GetReferenceDirection(double direction[3])
{
  std::copy(this->ReferenceDirection, this->ReferenceDirection + 3, direction);
}

void vtkGlobeLayerSet::GetGeodeticReference(double lonLat[2])
{
  lonLat[0] = this->ReferenceLonLat[0];
  lonLat[1] = this->ReferenceLonLat[1];
}

namespace
{
// A double as float hi + lo (hi + lo equals it to ~1e-15 relative).
std::array<float, 2> Split(double v)
{
  const float hi = static_cast<float>(v);
  return { hi, static_cast<float>(v - hi) };
}

// A positive double as hi + lo with hi rounded to 9 significant bits; quantum: hi's last bit
// (hi = m quantum, m < 2^9 + 1). A 15-bit multiple of the 2^-12 grid times hi is exact in float.
std::array<float, 2> SplitShort(double v, double& quantum)
{
  int exponent;
  std::frexp(v, &exponent); // v = f 2^exponent, f in [0.5, 1)
  quantum = std::ldexp(1.0, exponent - 9);
  const double hi = std::floor(v / quantum + 0.5) * quantum;
  return { static_cast<float>(hi), static_cast<float>(v - hi) };
}

// A texel coordinate in [0, span] as hi + lo with hi on the grid of float's ulp at 2 span, so
// that hi +- span (the wrap of a streamed projected layer's coordinates) is exact in float.
std::array<float, 2> SplitForWrap(double v, double span)
{
  const double q = std::ldexp(1.0, std::ilogb(2.0 * std::max(span, 1.0)) - 23);
  const double hi = std::floor(v / q + 0.5) * q;
  return { static_cast<float>(hi), static_cast<float>(v - hi) };
}

// The same with hi on the 2^-12 grid (globe_splitOnGrid in globe_ellipsoid.glsl).
std::array<float, 2> OnGrid(double v)
{
  const double hi = std::floor(v * 4096.0 + 0.5) / 4096.0;
  return { static_cast<float>(hi), static_cast<float>(v - hi) };
}
} // namespace

void vtkGlobeLayerSet::BindTextures(vtkShaderProgram* program, int roles)
{
  const auto& in = *this->Internals;
  const bool hp = this->HighPrecisionGeodetic;
  if (hp)
  {
    const std::array<float, 2> lon = Split(this->ReferenceLonLat[0]);
    const std::array<float, 2> lat = Split(this->ReferenceLonLat[1]);
    const float reference[4] = { lon[0], lon[1], lat[0], lat[1] };
    const float direction[3] = { static_cast<float>(this->ReferenceDirection[0]),
      static_cast<float>(this->ReferenceDirection[1]),
      static_cast<float>(this->ReferenceDirection[2]) };
    program->SetUniform4f("globeGeodeticReference", reference);
    program->SetUniform3f("globeReferenceDirection", direction);
  }
  // The atlases of the streamed layers' kinds (bound once for all their layers).
  bool streamed[2] = { false, false };
  for (int role = 0; role < NumberOfRoles; ++role)
  {
    for (const Entry* e : in.Composed[role])
    {
      streamed[role == vtkGlobeLayer::Height ? 0 : 1] |= Included(role, roles) && e->Streamed;
    }
  }
  for (int kind = 0; kind < 2; ++kind)
  {
    vtkTextureObject* atlas = in.Pages->GetAtlas(kind);
    if (streamed[kind] && atlas)
    {
      atlas->Activate();
      program->SetUniformi(kind == 0 ? "globePagesHeights" : "globePagesImages",
        atlas->GetTextureUnit());
    }
  }
  if (streamed[0] || streamed[1])
  {
    const float geometry[2] = { static_cast<float>(in.Pages->GetPageSize()),
      static_cast<float>(vtkGlobePageCache::Border) };
    program->SetUniform2f("globePageGeometry", geometry);
  }
  if (Included(vtkGlobeLayer::Height, roles))
  {
    const double deg = vtkMath::Pi() / 180.0;
    for (int k : UsedGeoids(in.Composed[vtkGlobeLayer::Height]))
    {
      const GeoidTexture& g = in.Geoids[k];
      g.Texture->Activate();
      const std::string name = "globeGeoid" + std::to_string(k);
      program->SetUniformi(name.c_str(), g.Texture->GetTextureUnit());
      const double* origin = g.Geoid->GetOrigin();
      const double* spacing = g.Geoid->GetSpacing();
      const float grid[4] = { static_cast<float>(origin[0] * deg),
        static_cast<float>(origin[1] * deg), static_cast<float>(spacing[0] * deg),
        static_cast<float>(spacing[1] * deg) };
      program->SetUniform4f((name + "Grid").c_str(), grid);
    }
  }
  for (int role = 0; role < NumberOfRoles; ++role)
  {
    if (!Included(role, roles))
    {
      continue;
    }
    const auto& list = in.Composed[role];
    for (size_t i = 0; i < list.size(); ++i)
    {
      Entry* e = list[i];
      vtkGlobeLayer* layer = e->Layer;
      const std::string p = Prefix(role, i);
      if (e->Streamed)
      {
        vtkTextureObject* table = in.Pages->GetTable(layer);
        table->Activate();
        program->SetUniformi((p + "Table").c_str(), table->GetTextureUnit());
        double pyramid[4];
        in.Pages->GetPyramid(layer, pyramid);
        const float values[4] = { static_cast<float>(pyramid[0]), static_cast<float>(pyramid[1]),
          static_cast<float>(pyramid[2]), static_cast<float>(pyramid[3]) };
        program->SetUniform4f((p + "Pyramid").c_str(), values);
        if (!e->Function.empty())
        {
          // The reference point's level-0 texel coordinates (globe_projection's p2.xy).
          const std::array<float, 2> x = SplitForWrap(e->Reference[0] * pyramid[0], pyramid[0]);
          const std::array<float, 2> y = SplitForWrap(e->Reference[1] * pyramid[1], pyramid[1]);
          const float texels[4] = { x[0], y[0], x[1], y[1] };
          program->SetUniform4f((p + "Texels").c_str(), texels);
        }
        else if (hp)
        {
          const double twoPi = 2.0 * vtkMath::Pi();
          double quantum;
          const std::array<float, 2> x = SplitShort(pyramid[0] / e->Map[1], quantum);
          const std::array<float, 2> y = SplitShort(pyramid[1] / e->Map[3], quantum);
          const float texels[4] = { x[0], x[1], y[0], y[1] };
          program->SetUniform4f((p + "Texels").c_str(), texels);
          // Texels per turn, its hi part a multiple of the 2^-12 grid times x's hi part's ulp.
          const double turn = twoPi * pyramid[0] / e->Map[1];
          const double step = quantum / 4096.0;
          const double turnHi = std::floor(turn / step + 0.5) * step;
          const float turns[2] = { static_cast<float>(turnHi), static_cast<float>(turn - turnHi) };
          program->SetUniform2f((p + "Turn").c_str(), turns);
        }
      }
      else
      {
        const bool nearest = layer->GetInterpolation() == vtkGlobeLayer::Nearest;
        e->Texture->SetMagnificationFilter(
          nearest ? vtkTextureObject::Nearest : vtkTextureObject::Linear);
        e->Texture->SetMinificationFilter(
          nearest ? vtkTextureObject::Nearest : vtkTextureObject::LinearMipmapLinear);
        // A texture parameter, sent when the texture is bound: no upload, no new program.
        const int top = this->FootprintFiltering ? e->UploadedLevels - 1 : 0;
        e->Texture->SetMaxLevel(top);
        e->Texture->Activate();
        program->SetUniformi(p.c_str(), e->Texture->GetTextureUnit());
        if (layer->GetRole() == vtkGlobeLayer::Height && this->GetFiltersHeightsInShader())
        {
          const float levels[2] = { static_cast<float>(top), nearest ? 1.0f : 0.0f };
          program->SetUniform2f((p + "Levels").c_str(), levels);
        }
      }
      auto f4 = [](const double v[4]) {
        return std::array<float, 4>{ static_cast<float>(v[0]), static_cast<float>(v[1]),
          static_cast<float>(v[2]), static_cast<float>(v[3]) };
      };
      const double* valid = layer->GetValidRange();
      const double style[4] = { layer->GetOpacity(), layer->GetGamma(),
        std::max(valid[0], -FloatLimit), std::min(valid[1], FloatLimit) };
      if (hp && e->Function.empty())
      {
        // The edges as hi + lo with hi on globe_splitOnGrid's 2^-12 rad grid (GLSL's
        // GLOBE_HI_GRID), the west edge in [-pi, pi).
        const double twoPi = 2.0 * vtkMath::Pi();
        const double west = e->Map[0] - twoPi * std::floor((e->Map[0] + vtkMath::Pi()) / twoPi);
        const std::array<float, 2> w = OnGrid(west), n = OnGrid(e->Map[2]);
        const float map[4] = { w[0], static_cast<float>(e->Map[1]), n[0],
          static_cast<float>(e->Map[3]) };
        const float lo[2] = { w[1], n[1] };
        program->SetUniform4f((p + "Map").c_str(), map);
        program->SetUniform2f((p + "MapLo").c_str(), lo);
      }
      else
      {
        program->SetUniform4f((p + "Map").c_str(), f4(e->Map).data());
      }
      program->SetUniform4f((p + "Style").c_str(), f4(style).data());
      program->SetUniform4f((p + "Border").c_str(), f4(e->Border).data());
      if (e->Match)
      {
        const float gain[3] = { static_cast<float>(e->MatchGain[0]),
          static_cast<float>(e->MatchGain[1]), static_cast<float>(e->MatchGain[2]) };
        const float offset[3] = { static_cast<float>(e->MatchOffset[0]),
          static_cast<float>(e->MatchOffset[1]), static_cast<float>(e->MatchOffset[2]) };
        const double width = layer->GetColorMatchWidth();
        const float border[4] = { static_cast<float>(width / layer->GetNumberOfColumns()),
          static_cast<float>(width / layer->GetNumberOfRows()), 0.0f, 0.0f };
        program->SetUniform3f((p + "MatchGain").c_str(), gain);
        program->SetUniform3f((p + "MatchOffset").c_str(), offset);
        program->SetUniform4f((p + "MatchBorder").c_str(), border);
      }
      if (layer->GetRole() == vtkGlobeLayer::Height)
      {
        // The texture's heights were made with UploadedScale/Offset (a streamed layer's pages
        // with its stored ones); the layer's values now use ValueScale/Offset
        // (vtkGlobeLayer::IsRescaledSince, ReadStoredPage).
        double map[2];
        vtkGlobeLayer::ValueMap(e->Streamed ? layer->GetStoredValueScale() : e->UploadedScale,
          e->Streamed ? layer->GetStoredValueOffset() : e->UploadedOffset,
          layer->GetValueScale(), layer->GetValueOffset(), map);
        const float value[2] = { static_cast<float>(map[0]), static_cast<float>(map[1]) };
        program->SetUniform2f((p + "Value").c_str(), value);
        program->SetUniform4f((p + "Skirt").c_str(), f4(e->Skirt).data());
      }
      if (!e->Function.empty())
      {
        program->SetUniform4fv((p + "Projection").c_str(), 7,
          reinterpret_cast<const float(*)[4]>(e->Parameters));
      }
    }
  }
}

void vtkGlobeLayerSet::UnbindTextures(int roles)
{
  const auto& in = *this->Internals;
  if (Included(vtkGlobeLayer::Height, roles))
  {
    for (int k : UsedGeoids(in.Composed[vtkGlobeLayer::Height]))
    {
      in.Geoids[k].Texture->Deactivate();
    }
  }
  for (int role = 0; role < NumberOfRoles; ++role)
  {
    if (!Included(role, roles))
    {
      continue;
    }
    for (Entry* e : in.Composed[role])
    {
      if (!e->Streamed)
      {
        e->Texture->Deactivate();
      }
      else if (vtkTextureObject* table = in.Pages->GetTable(e->Layer))
      {
        table->Deactivate();
      }
    }
  }
  for (int kind = 0; kind < 2; ++kind)
  {
    // Deactivate is harmless for an atlas that was not bound.
    if (vtkTextureObject* atlas = in.Pages->GetAtlas(kind))
    {
      atlas->Deactivate();
    }
  }
}

void vtkGlobeLayerSet::ReleaseGraphicsResources(vtkWindow* window)
{
  // A context made later at the same address is probed again.
  if (this->Internals->ProbedWindow == window)
  {
    this->Internals->ProbedWindow = nullptr;
  }
  this->Internals->ReleaseRetired(window);
  this->Internals->Pages->ReleaseGraphicsResources(window);
  for (GeoidTexture& g : this->Internals->Geoids)
  {
    if (g.Texture)
    {
      g.Texture->ReleaseGraphicsResources(window);
      g.Texture = nullptr;
      g.UploadedTime = 0;
    }
  }
  for (auto& held : this->Internals->Entries)
  {
    Entry& e = *held;
    if (e.Texture)
    {
      e.Texture->ReleaseGraphicsResources(window);
      e.Texture = nullptr;
      e.UploadedData = nullptr;
      e.UploadedTime = 0;
    }
  }
}

//------------------------------------------------------------------------------
void vtkGlobeLayerSet::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Layers: " << this->Internals->Entries.size() << "\n";
  for (const auto& e : this->Internals->Entries)
  {
    os << indent.GetNextIndent() << e->Layer->GetRoleAsString() << " "
       << (e->Layer->GetFileName() ? e->Layer->GetFileName() : "(in-memory)")
       << (e->Active ? " (active)" : " (inactive)") << "\n";
  }
  os << indent << "PlausibleHeightRange: " << this->PlausibleHeightRange[0] << " .. "
     << this->PlausibleHeightRange[1] << " m\n";
  os << indent << "NumberOfUploads: " << this->NumberOfUploads << "\n";
  os << indent << "HighPrecisionGeodetic: " << this->HighPrecisionGeodetic << "\n";
  os << indent << "FootprintFiltering: " << this->FootprintFiltering << "\n";
  os << indent << "HeightFiltering: " << this->HeightFiltering << " (texture unit exact: "
     << this->Internals->FiltersExactly << ")\n";
  os << indent << "GeodeticReference: " << vtkMath::DegreesFromRadians(this->ReferenceLonLat[0])
     << ", " << vtkMath::DegreesFromRadians(this->ReferenceLonLat[1]) << " deg\n";
}
