#include "vtkGlobeTerrain.h"

#include "vtkFloatArray.h"
#include "vtkGlobeGeoid.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeMapProjection.h"
#include "vtkGlobePageSource.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

vtkStandardNewMacro(vtkGlobeTerrain);
vtkCxxSetObjectMacro(vtkGlobeTerrain, Geoid, vtkGlobeGeoid);

namespace
{
/// One height layer as the composition sees it, taken when the layer last changed.
struct Composed
{
  vtkGlobeLayer* Layer = nullptr;
  vtkGlobeGeoid* Geoid = nullptr; // valid geoid of a Geoid datum, else nullptr
  vtkSmartPointer<vtkGlobeMapProjection> Projection; // projected layers
  double Extent[4] = { 0, 0, 0, 0 };                // geographic layers
  double Origin[2] = { 0, 0 }, Pixel[2] = { 0, 0 }; // projected layers
  int Width = 0, Height = 0;
  bool Wraps = false;
  double Border[2] = { 0, 0 }; // feather / size per axis (0: no border)
  double Skirt[2] = { 0, 0 };  // skirt / size per axis, outside the raster (0: none)
  double Turn = 0.0;           // a whole turn of longitude in u (geographic layers)
  const float* Values = nullptr; // whole layers
  bool Streamed = false;
  int PageSize = 0, PageBorder = 0;
  int Levels = 1; // of the layer's pyramid (vtkGlobeLayer::GetLevelData or its pages)
};

constexpr double Degree = 3.14159265358979323846 / 180.0;
} // namespace

struct vtkGlobeTerrain::vtkInternals
{
  std::vector<vtkSmartPointer<vtkGlobeLayer>> Layers;
  // The composition order and each layer's state when it was taken.
  std::vector<Composed> Order;
  std::vector<std::tuple<vtkGlobeLayer*, vtkMTimeType, int>> Stamp;
  vtkMTimeType Built = 0;
  // Pages of streamed layers read so far: (layer, level, column, row) -> values.
  std::map<std::tuple<vtkGlobeLayer*, int, int, int>, vtkSmartPointer<vtkFloatArray>> Pages;

  bool Stale(vtkGlobeTerrain* self)
  {
    if (self->GetMTime() > this->Built || this->Stamp.size() != this->Layers.size())
    {
      return true;
    }
    for (size_t i = 0; i < this->Layers.size(); ++i)
    {
      vtkGlobeLayer* layer = this->Layers[i];
      if (std::get<0>(this->Stamp[i]) != layer || std::get<1>(this->Stamp[i]) != layer->GetMTime() ||
        std::get<2>(this->Stamp[i]) != layer->GetNumberOfLoads())
      {
        return true;
      }
    }
    return false;
  }

  void Build(vtkGlobeTerrain* self)
  {
    this->Order.clear();
    this->Pages.clear();
    std::vector<std::pair<vtkGlobeLayer*, size_t>> order;
    for (size_t i = 0; i < this->Layers.size(); ++i)
    {
      vtkGlobeLayer* layer = this->Layers[i];
      if (layer->GetRole() != vtkGlobeLayer::Height || !layer->GetEnabled())
      {
        continue;
      }
      if (layer->GetNumberOfLoads() == 0 && !layer->IsValid())
      {
        layer->Update(); // never loaded: the first query loads it
      }
      if (layer->IsValid())
      {
        order.emplace_back(layer, i);
      }
    }
    std::stable_sort(order.begin(), order.end(),
      [](const std::pair<vtkGlobeLayer*, size_t>& a, const std::pair<vtkGlobeLayer*, size_t>& b) {
        return a.first->GetDrawOrder() < b.first->GetDrawOrder();
      });
    for (const auto& entry : order)
    {
      vtkGlobeLayer* layer = entry.first;
      Composed c;
      c.Layer = layer;
      c.Width = layer->GetNumberOfColumns();
      c.Height = layer->GetNumberOfRows();
      if (c.Width <= 0 || c.Height <= 0)
      {
        continue;
      }
      if (vtkGlobeGeoid* geoid = layer->GetGeoid())
      {
        if (!geoid->IsValid())
        {
          continue; // the renderer skips a layer whose heights cannot be made ellipsoidal
        }
        c.Geoid = geoid;
      }
      c.Wraps = layer->IsGlobal();
      double feather[2], skirt[2];
      layer->GetFeatherBorder(feather);
      layer->GetSkirtBorder(skirt);
      if (layer->GetModelType() == vtkGlobeLayer::Projected)
      {
        c.Projection = vtkSmartPointer<vtkGlobeMapProjection>::New();
        if (!layer->GetMapProjection(c.Projection))
        {
          continue; // the renderer cannot draw it either
        }
        layer->GetProjectedGeoTransform(c.Origin, c.Pixel);
        c.Border[0] = c.Wraps ? 0.0 : feather[0];
        c.Border[1] = feather[1];
        c.Skirt[0] = c.Wraps ? 0.0 : skirt[0];
        c.Skirt[1] = skirt[1];
      }
      else if (layer->GetModelType() == vtkGlobeLayer::Geographic)
      {
        layer->GetGeographicExtent(c.Extent);
        const bool poles = c.Extent[2] <= -90.0 && c.Extent[3] >= 90.0;
        c.Border[0] = c.Wraps ? 0.0 : feather[0];
        c.Border[1] = poles ? 0.0 : feather[1];
        c.Skirt[0] = c.Wraps ? 0.0 : skirt[0];
        c.Skirt[1] = poles ? 0.0 : skirt[1];
        c.Turn = 360.0 / (c.Extent[1] - c.Extent[0]);
      }
      else
      {
        continue;
      }
      c.Streamed = layer->IsStreamed();
      if (c.Streamed)
      {
        vtkGlobePageSource* source = layer->GetPageSource();
        if (!source)
        {
          continue;
        }
        c.PageSize = source->GetPageSize();
        c.PageBorder = source->GetBorder();
        c.Levels = std::max(1, source->GetNumberOfLevels());
      }
      else
      {
        auto* values = vtkFloatArray::SafeDownCast(layer->GetData());
        if (!values)
        {
          continue;
        }
        c.Values = values->GetPointer(0);
        c.Levels = std::max(1, layer->GetNumberOfLevels());
      }
      this->Order.push_back(c);
    }
    this->Stamp.clear();
    for (vtkGlobeLayer* layer : this->Layers)
    {
      this->Stamp.emplace_back(layer, layer->GetMTime(), layer->GetNumberOfLoads());
    }
    this->Built = self->GetMTime();
  }

  /// A layer's size in texels at a level: whole layers as OpenGL sizes mipmaps, streamed ones
  /// as their page source.
  static void LevelSize(const Composed& c, int level, int& w, int& h)
  {
    w = c.Width;
    h = c.Height;
    if (level > 0)
    {
      if (c.Streamed)
      {
        int size[2] = { 1, 1 };
        c.Layer->GetPageSource()->GetLevelSize(level, size);
        w = size[0];
        h = size[1];
      }
      else
      {
        w = std::max(1, c.Width >> level);
        h = std::max(1, c.Height >> level);
      }
    }
  }

  /// A post of a layer's level (column i east, row j south of the north edge), clamped or
  /// wrapped.
  double Post(const Composed& c, int level, int i, int j)
  {
    int w, h;
    LevelSize(c, level, w, h);
    i = c.Wraps ? ((i % w) + w) % w : std::max(0, std::min(i, w - 1));
    j = std::max(0, std::min(j, h - 1));
    if (!c.Streamed)
    {
      const float* values = level == 0 ? c.Values
        : static_cast<vtkFloatArray*>(c.Layer->GetLevelData(level))->GetPointer(0);
      return values[static_cast<size_t>(j) * w + i];
    }
    const int column = i / c.PageSize, row = j / c.PageSize;
    auto key = std::make_tuple(c.Layer, level, column, row);
    auto found = this->Pages.find(key);
    if (found == this->Pages.end())
    {
      if (this->Pages.size() >= 64)
      {
        this->Pages.clear(); // bounded memory: start over
      }
      auto page = vtkSmartPointer<vtkFloatArray>::New();
      if (!c.Layer->ReadPage(level, column, row, page))
      {
        page = nullptr;
      }
      found = this->Pages.emplace(key, page).first;
    }
    if (!found->second)
    {
      return std::nan("");
    }
    const int side = c.PageSize + 2 * c.PageBorder;
    const int x = c.PageBorder + i % c.PageSize, y = c.PageBorder + j % c.PageSize;
    return found->second->GetValue(static_cast<vtkIdType>(y) * side + x);
  }

  /// Texture coordinates (u east, v south, [0, 1] over the outer pixel edges); false where
  /// the projection is undefined.
  static bool UV(const Composed& c, double lon, double lat, double& u, double& v)
  {
    if (c.Projection)
    {
      double xy[2];
      if (!c.Projection->ForwardInDomain(lon, lat, xy))
      {
        return false;
      }
      u = (xy[0] - c.Origin[0]) / (c.Pixel[0] * c.Width);
      v = (c.Origin[1] - xy[1]) / (c.Pixel[1] * c.Height);
      if (c.Wraps)
      {
        u -= std::floor(u);
      }
      return std::isfinite(u) && std::isfinite(v);
    }
    u = std::fmod(std::fmod(lon - c.Extent[0], 360.0) + 360.0, 360.0) / (c.Extent[1] - c.Extent[0]);
    v = (c.Extent[3] - lat) / (c.Extent[3] - c.Extent[2]);
    return std::isfinite(u) && std::isfinite(v);
  }

  /// The bilinear value of a level at (u, v) (the texel itself for Nearest). Whole layers'
  /// levels span [0, 1] as OpenGL's mipmaps; a streamed level's texel is 2^level of level 0's.
  double SampleLevel(const Composed& c, int level, double u, double v, bool nearest)
  {
    double x, y;
    if (c.Streamed)
    {
      x = std::ldexp(u * c.Width, -level);
      y = std::ldexp(v * c.Height, -level);
    }
    else
    {
      int w, h;
      LevelSize(c, level, w, h);
      x = u * w;
      y = v * h;
    }
    if (nearest)
    {
      return this->Post(c, level, static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
    }
    const double fx0 = x - 0.5, fy0 = y - 0.5;
    const int i = static_cast<int>(std::floor(fx0)), j = static_cast<int>(std::floor(fy0));
    const double fx = fx0 - i, fy = fy0 - j;
    return (1 - fy) * ((1 - fx) * this->Post(c, level, i, j) + fx * this->Post(c, level, i + 1, j)) +
      fy * ((1 - fx) * this->Post(c, level, i, j + 1) + fx * this->Post(c, level, i + 1, j + 1));
  }

  /// The filtered value at (u, v) at level of detail `lod`, as the GPU samples it: between the
  /// two levels around it (LINEAR_MIPMAP_LINEAR); Nearest: level 0's texel for whole layers
  /// (their texture has no mipmap filter), the nearest level's for streamed ones.
  double Sample(const Composed& c, double u, double v, bool nearest, double lod)
  {
    if (nearest)
    {
      return this->SampleLevel(c, c.Streamed ? static_cast<int>(std::floor(lod + 0.5)) : 0, u, v, true);
    }
    const int l = static_cast<int>(std::floor(lod));
    const double f = lod - l;
    const double a = this->SampleLevel(c, l, u, v, false);
    return f > 0.0 ? a + (this->SampleLevel(c, l + 1, u, v, false) - a) * f : a;
  }

  /**
   * The level of detail the GPU takes for a height layer where one step along each of two axes
   * moves (lon, lat) by footprint (dlon, dlat per axis, degrees): globe_footprintLodHeights
   * (vtkGlobeFootprint.glsl) from the texture coordinates' Jacobian, the polar rule included.
   */
  static double Lod(const Composed& c, double lon, double lat, double u, double v,
    const double footprint[4], bool grid, double blur)
  {
    double jLon[2], jLat[2]; // texture coordinates per degree of lon and lat
    if (c.Projection)
    {
      const double e = 1e-4 / Degree, eLat = lat > 0.0 ? -e : e;
      double uE, vE, uN, vN;
      if (!UV(c, lon + e, lat, uE, vE) || !UV(c, lon, lat + eLat, uN, vN))
      {
        return 0.0;
      }
      double du = uE - u, duN = uN - u;
      if (c.Wraps)
      {
        du -= std::floor(du + 0.5);
        duN -= std::floor(duN + 0.5);
      }
      jLon[0] = du / e;
      jLon[1] = (vE - v) / e;
      jLat[0] = duN / eLat;
      jLat[1] = (vN - v) / eLat;
    }
    else
    {
      jLon[0] = 1.0 / (c.Extent[1] - c.Extent[0]);
      jLon[1] = 0.0;
      jLat[0] = 0.0;
      jLat[1] = -1.0 / (c.Extent[3] - c.Extent[2]);
    }
    const double a[2] = { (jLon[0] * footprint[0] + jLat[0] * footprint[1]) * c.Width,
      (jLon[1] * footprint[0] + jLat[1] * footprint[1]) * c.Height };
    const double b[2] = { (jLon[0] * footprint[2] + jLat[0] * footprint[3]) * c.Width,
      (jLon[1] * footprint[2] + jLat[1] * footprint[3]) * c.Height };
    const double longer = std::max(std::hypot(a[0], a[1]), std::hypot(b[0], b[1]));
    const double most = grid ? 1.0 / 16.0 : 1.0; // the grid pass's anisotropy (vtkGlobeLayerSet)
    const double stretch = c.Projection ? most : std::min(most, 10.0 * std::cos(lat * Degree));
    double rho = longer;
    if (stretch < 1.0)
    {
      const double t = a[0] * a[0] + a[1] * a[1] + b[0] * b[0] + b[1] * b[1];
      const double det = std::abs(a[0] * b[1] - a[1] * b[0]);
      const double major = std::sqrt(0.5 * t + std::sqrt(std::max(0.25 * t * t - det * det, 0.0)));
      rho = std::max(det / std::max(major, 1e-300), longer * stretch);
    }
    rho = std::max(rho, blur);
    return std::min(std::max(std::log2(std::max(rho, 1e-300)), 0.0), c.Levels - 1.0);
  }

  /// One layer's value (ellipsoidal, m) and weight at (lon, lat).
  void Evaluate(const Composed& c, double lon, double lat, const double* footprint, bool grid,
    double& value, double& weight)
  {
    value = 0.0;
    weight = 0.0;
    double u, v;
    if (!UV(c, lon, lat, u, v))
    {
      return;
    }
    // (su, sv): where the heights are read (the raster's nearest point within its skirt).
    const double skirt[3] = { c.Skirt[0], c.Skirt[1], c.Turn };
    double at[2] = { u, v }, outside[2];
    double w = vtkGlobeLayer::ApplySkirt(skirt, at, outside);
    if (!(w > 0.0))
    {
      return;
    }
    const double su = at[0], sv = at[1];
    vtkGlobeLayer* layer = c.Layer;
    if (c.Border[0] > 0.0)
    {
      w *= std::min(1.0, std::max(0.0, std::min(u, 1.0 - u) / c.Border[0]));
    }
    if (c.Border[1] > 0.0)
    {
      w *= std::min(1.0, std::max(0.0, std::min(v, 1.0 - v) / c.Border[1]));
    }
    w *= layer->GetOpacity();
    if (w > 0.0 && layer->GetProjectionQualityWeight())
    {
      // Kooima's weight from the texel aspect of the map here (vtkGlobeLayerSet's
      // globe_quality): two points 1e-3 rad east and towards the equator.
      const double step = 1e-3 / Degree;
      double uE, vE, uN, vN;
      if (UV(c, lon + step, lat, uE, vE) && UV(c, lon, lat > 0.0 ? lat - step : lat + step, uN, vN))
      {
        double eu = uE - u;
        if (c.Wraps)
        {
          eu -= std::floor(eu + 0.5);
        }
        const double cosLat = std::max(std::cos(lat * Degree), 1e-6);
        const double te = std::hypot(eu * c.Width, (vE - v) * c.Height) / cosLat;
        const double tn = std::hypot((uN - u) * c.Width, (vN - v) * c.Height);
        if (te > 0.0 && tn > 0.0)
        {
          w *= std::min(1.0, std::max(0.0, 1.0 - std::abs(std::log(te / tn)) /
            std::log(layer->GetProjectionQualityLimit())));
        }
      }
    }
    if (!(w > 0.0))
    {
      return;
    }
    const bool nearest = layer->GetInterpolation() == vtkGlobeLayer::Nearest;
    // In the skirt, the edge is read coarser with the distance (vtkGlobeLayer::ApplySkirt).
    const double blur = std::max(1.0, std::max(outside[0] * c.Width, outside[1] * c.Height));
    const double lod = footprint
      ? Lod(c, lon, lat, u, v, footprint, grid, blur)
      : std::min(std::log2(blur), c.Levels - 1.0);
    const double h = this->Sample(c, su, sv, nearest, lod);
    // The GPU's gradient samples one texel away each way: a NaN there voids the sample too.
    const double du = 1.0 / c.Width, dv = 1.0 / c.Height;
    const double neighbours = this->Sample(c, su + du, sv, nearest, lod) +
      this->Sample(c, su - du, sv, nearest, lod) + this->Sample(c, su, sv - dv, nearest, lod) +
      this->Sample(c, su, sv + dv, nearest, lod);
    const double* valid = layer->GetValidRange();
    if (std::isnan(h) || std::isnan(neighbours) || !(h >= valid[0] && h <= valid[1]))
    {
      return;
    }
    double n = 0.0;
    if (c.Geoid)
    {
      n = c.Geoid->GetUndulation(lon, lat);
      if (!std::isfinite(n))
      {
        return;
      }
    }
    value = h + n;
    weight = w;
  }
};

//------------------------------------------------------------------------------
vtkGlobeTerrain::vtkGlobeTerrain()
  : Internals(new vtkInternals)
{
}

vtkGlobeTerrain::~vtkGlobeTerrain()
{
  this->SetGeoid(nullptr);
}

void vtkGlobeTerrain::AddLayer(vtkGlobeLayer* layer)
{
  if (!layer)
  {
    vtkErrorMacro(<< "AddLayer: no layer");
    return;
  }
  this->Internals->Layers.emplace_back(layer);
  this->Modified();
}

void vtkGlobeTerrain::RemoveLayer(vtkGlobeLayer* layer)
{
  auto& layers = this->Internals->Layers;
  const auto end = std::remove(layers.begin(), layers.end(), layer);
  if (end != layers.end())
  {
    layers.erase(end, layers.end());
    this->Modified();
  }
}

void vtkGlobeTerrain::RemoveAllLayers()
{
  if (!this->Internals->Layers.empty())
  {
    this->Internals->Layers.clear();
    this->Modified();
  }
}

int vtkGlobeTerrain::GetNumberOfLayers()
{
  return static_cast<int>(this->Internals->Layers.size());
}

vtkGlobeLayer* vtkGlobeTerrain::GetLayer(int index)
{
  if (index < 0 || index >= this->GetNumberOfLayers())
  {
    vtkErrorMacro(<< "GetLayer: index " << index << " out of range [0, "
                  << this->GetNumberOfLayers() << ")");
    return nullptr;
  }
  return this->Internals->Layers[index];
}

void vtkGlobeTerrain::Update()
{
  for (vtkGlobeLayer* layer : this->Internals->Layers)
  {
    if (layer->GetRole() == vtkGlobeLayer::Height && layer->GetEnabled())
    {
      layer->Update();
    }
  }
  this->Internals->Build(this);
}

//------------------------------------------------------------------------------
double vtkGlobeTerrain::GetHeight(double lon, double lat)
{
  return this->GetFilteredHeight(lon, lat, nullptr);
}

double vtkGlobeTerrain::GetFilteredHeight(
  double lon, double lat, const double footprint[4], int rule)
{
  vtkInternals& in = *this->Internals;
  if (in.Stale(this))
  {
    in.Build(this);
  }
  if (!std::isfinite(lon) || !std::isfinite(lat))
  {
    return std::nan("");
  }
  // A latitude beyond +-90 degrees lies outside every layer (as the GPU's texture coordinates
  // put it): the composition's 0 there, not the pole's height.
  double h = 0.0, sumW = 0.0, sumV = 0.0;
  for (size_t i = 0; i < in.Order.size(); ++i)
  {
    const Composed& c = in.Order[i];
    double value, w;
    in.Evaluate(c, lon, lat, footprint, rule != PixelFootprint, value, w);
    const int mode = c.Layer->GetBlendMode();
    switch (mode)
    {
      case vtkGlobeLayer::Add:
        h += w * value;
        break;
      case vtkGlobeLayer::Average:
        sumW += w;
        sumV += w * value;
        break;
      default:
        h += (value - h) * w;
    }
    const bool lastOfRun =
      i + 1 == in.Order.size() || in.Order[i + 1].Layer->GetBlendMode() != vtkGlobeLayer::Average;
    if (mode == vtkGlobeLayer::Average && lastOfRun)
    {
      if (sumW > 0.0)
      {
        h += (sumV / sumW - h) * std::min(sumW, 1.0);
      }
      sumW = sumV = 0.0;
    }
  }
  return h;
}

double vtkGlobeTerrain::GetGeoidUndulation(double lon, double lat)
{
  if (this->Geoid)
  {
    this->Geoid->Update();
    return this->Geoid->GetUndulation(lon, lat);
  }
  vtkInternals& in = *this->Internals;
  if (in.Stale(this))
  {
    in.Build(this);
  }
  for (auto c = in.Order.rbegin(); c != in.Order.rend(); ++c)
  {
    if (c->Geoid)
    {
      return c->Geoid->GetUndulation(lon, lat);
    }
  }
  return std::nan("");
}

double vtkGlobeTerrain::GetOrthometricHeight(double lon, double lat)
{
  return this->GetHeight(lon, lat) - this->GetGeoidUndulation(lon, lat);
}

//------------------------------------------------------------------------------
void vtkGlobeTerrain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLayers: " << this->GetNumberOfLayers() << "\n";
  for (vtkGlobeLayer* layer : this->Internals->Layers)
  {
    os << indent.GetNextIndent() << layer->GetName() << " (" << layer->GetRoleAsString() << ")\n";
  }
  os << indent << "Geoid: " << this->Geoid << "\n";
}
