#include "vtkGlobeReprojection.h"

#include "vtkFloatArray.h"
#include "vtkUnsignedCharArray.h"

#include <proj.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace
{
constexpr double Deg = 3.14159265358979323846 / 180.0;
constexpr int MaximumSide = 8192; // what every GPU's textures hold

// A PROJ context and the source -> (lon, lat) transformation, released together.
struct Transformation
{
  PJ_CONTEXT* Context = proj_context_create();
  PJ* P = nullptr;
  explicit Transformation(const std::string& source)
  {
    if (!this->Context)
    {
      return;
    }
    proj_log_level(this->Context, PJ_LOG_NONE);
    PJ* raw = proj_create_crs_to_crs(this->Context, source.c_str(), "EPSG:4326", nullptr);
    if (raw)
    {
      this->P = proj_normalize_for_visualization(this->Context, raw);
      proj_destroy(raw);
    }
  }
  ~Transformation()
  {
    proj_destroy(this->P);
    if (this->Context)
    {
      proj_context_destroy(this->Context);
    }
  }
  // In place: x, y arrays of n points; direction PJ_FWD (source -> lon, lat) or PJ_INV.
  void Apply(PJ_DIRECTION direction, std::vector<double>& x, std::vector<double>& y)
  {
    proj_trans_generic(this->P, direction, x.data(), sizeof(double), x.size(), y.data(),
      sizeof(double), y.size(), nullptr, 0, 0, nullptr, 0, 0);
  }
};

bool Finite(double v)
{
  return std::isfinite(v) && std::abs(v) < 1e300;
}
} // namespace

bool vtkGlobeReprojection::ToGeographic(const std::string& crs, const double origin[2], const double pixel[2],
  int width, int height, vtkDataArray* data, bool nearest, double maxBytes,
  vtkSmartPointer<vtkDataArray>& out, Grid& grid, std::string& why)
{
  Transformation t(crs);
  if (!t.P)
  {
    why = "PROJ has no transformation from " + crs + " to EPSG:4326";
    return false;
  }
  auto* heights = vtkFloatArray::SafeDownCast(data);
  auto* rgba = vtkUnsignedCharArray::SafeDownCast(data);
  if (!(heights && data->GetNumberOfComponents() == 1) &&
    !(rgba && data->GetNumberOfComponents() == 4))
  {
    why = "only float heights and RGBA pixels can be reprojected";
    return false;
  }
  // The source's footprint in (lon, lat): its border densely, its inside on a coarse grid.
  std::vector<double> x, y;
  const int edge = 256, inside = 32;
  for (int k = 0; k <= edge; ++k)
  {
    const double f = static_cast<double>(k) / edge;
    for (const auto& p : { std::make_pair(f, 0.0), std::make_pair(f, 1.0),
           std::make_pair(0.0, f), std::make_pair(1.0, f) })
    {
      x.push_back(origin[0] + p.first * width * pixel[0]);
      y.push_back(origin[1] - p.second * height * pixel[1]);
    }
  }
  for (int j = 0; j <= inside; ++j)
  {
    for (int i = 0; i <= inside; ++i)
    {
      x.push_back(origin[0] + (static_cast<double>(i) / inside) * width * pixel[0]);
      y.push_back(origin[1] - (static_cast<double>(j) / inside) * height * pixel[1]);
    }
  }
  t.Apply(PJ_FWD, x, y);
  double south = 90.0, north = -90.0, west = 1e9, east = -1e9, west360 = 1e9, east360 = -1e9;
  int mapped = 0;
  for (size_t k = 0; k < x.size(); ++k)
  {
    if (!Finite(x[k]) || !Finite(y[k]))
    {
      continue;
    }
    ++mapped;
    const double lon = std::remainder(x[k], 360.0), lon360 = lon < 0.0 ? lon + 360.0 : lon;
    west = std::min(west, lon);
    east = std::max(east, lon);
    west360 = std::min(west360, lon360);
    east360 = std::max(east360, lon360);
    south = std::min(south, y[k]);
    north = std::max(north, y[k]);
  }
  if (mapped < 4)
  {
    why = "its extent does not map to longitudes and latitudes through " + crs;
    return false;
  }
  if (east360 - west360 < east - west)
  {
    west = west360; // it straddles the antimeridian: longitudes 0..360
    east = east360;
  }
  // A pole inside the raster: all longitudes, up to the pole.
  for (double pole : { 90.0, -90.0 })
  {
    std::vector<double> px = { 0.0 }, py = { pole };
    t.Apply(PJ_INV, px, py);
    const double fx = (px[0] - origin[0]) / pixel[0], fy = (origin[1] - py[0]) / pixel[1];
    if (Finite(px[0]) && Finite(py[0]) && fx >= 0.0 && fx <= width && fy >= 0.0 && fy <= height)
    {
      west = -180.0;
      east = 180.0;
      (pole > 0.0 ? north : south) = pole;
    }
  }
  // Texels about as large on the ground as the source's at its centre.
  const double cx = origin[0] + 0.5 * width * pixel[0], cy = origin[1] - 0.5 * height * pixel[1];
  std::vector<double> nx = { cx, cx + pixel[0], cx }, ny = { cy, cy, cy - pixel[1] };
  t.Apply(PJ_FWD, nx, ny);
  const double cosLat = std::max(std::cos(ny[0] * Deg), 0.05);
  double ground = 1e9; // degrees of latitude
  for (int k = 1; k < 3; ++k)
  {
    const double dLon = std::remainder(nx[k] - nx[0], 360.0) * cosLat, dLat = ny[k] - ny[0];
    const double d = std::hypot(dLon, dLat);
    if (Finite(d) && d > 0.0)
    {
      ground = std::min(ground, d);
    }
  }
  if (!(ground < 1e9))
  {
    why = "its pixel size does not map to a distance on the ground";
    return false;
  }
  const double lonSpan = std::max(east - west, ground), latSpan = std::max(north - south, ground);
  double w = std::ceil(lonSpan / (ground / cosLat)), h = std::ceil(latSpan / ground);
  const double bytesPerTexel = 4.0; // a float height or 4 bytes of RGBA
  const double shrink = std::max({ 1.0, w / MaximumSide, h / MaximumSide,
    std::sqrt(w * h * bytesPerTexel / std::max(maxBytes, 1.0)) });
  w = std::max(1.0, std::ceil(w / shrink));
  h = std::max(1.0, std::ceil(h / shrink));
  grid.Width = static_cast<int>(w);
  grid.Height = static_cast<int>(h);
  grid.West = west;
  grid.North = north;
  grid.DLon = lonSpan / w;
  grid.DLat = latSpan / h;

  // Each output texel centre, sampled in the source.
  const int components = data->GetNumberOfComponents();
  vtkSmartPointer<vtkDataArray> result;
  if (heights)
  {
    result = vtkSmartPointer<vtkFloatArray>::New();
  }
  else
  {
    result = vtkSmartPointer<vtkUnsignedCharArray>::New();
  }
  result->SetNumberOfComponents(components);
  result->SetNumberOfTuples(static_cast<vtkIdType>(grid.Width) * grid.Height);
  const float* hv = heights ? heights->GetPointer(0) : nullptr;
  const unsigned char* cv = rgba ? rgba->GetPointer(0) : nullptr;
  float* hOut = heights ? vtkFloatArray::SafeDownCast(result)->GetPointer(0) : nullptr;
  unsigned char* cOut = rgba ? vtkUnsignedCharArray::SafeDownCast(result)->GetPointer(0) : nullptr;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<double> lon(grid.Width), lat(grid.Width);
  for (int j = 0; j < grid.Height; ++j)
  {
    for (int i = 0; i < grid.Width; ++i)
    {
      lon[i] = std::remainder(grid.West + (i + 0.5) * grid.DLon, 360.0);
      lat[i] = grid.North - (j + 0.5) * grid.DLat;
    }
    t.Apply(PJ_INV, lon, lat);
    for (int i = 0; i < grid.Width; ++i)
    {
      const size_t o = static_cast<size_t>(j) * grid.Width + i;
      // Source texel coordinates, texel centres at integers, row 0 north.
      const double fx = (lon[i] - origin[0]) / pixel[0] - 0.5;
      const double fy = (origin[1] - lat[i]) / pixel[1] - 0.5;
      const bool in = Finite(lon[i]) && Finite(lat[i]) && fx >= -0.5 && fx <= width - 0.5 &&
        fy >= -0.5 && fy <= height - 0.5;
      if (!in)
      {
        if (hOut)
        {
          hOut[o] = nan;
        }
        else
        {
          std::fill(cOut + 4 * o, cOut + 4 * o + 4, 0);
        }
        continue;
      }
      if (nearest)
      {
        const int sx = std::min(std::max(static_cast<int>(std::lround(fx)), 0), width - 1);
        const int sy = std::min(std::max(static_cast<int>(std::lround(fy)), 0), height - 1);
        const size_t s = static_cast<size_t>(sy) * width + sx;
        if (hOut)
        {
          hOut[o] = hv[s];
        }
        else
        {
          std::copy(cv + 4 * s, cv + 4 * s + 4, cOut + 4 * o);
        }
        continue;
      }
      const double cxs = std::min(std::max(fx, 0.0), width - 1.0);
      const double cys = std::min(std::max(fy, 0.0), height - 1.0);
      const int x0 = std::min(static_cast<int>(cxs), std::max(width - 2, 0));
      const int y0 = std::min(static_cast<int>(cys), std::max(height - 2, 0));
      const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
      const double ax = cxs - x0, ay = cys - y0;
      const size_t s[4] = { static_cast<size_t>(y0) * width + x0,
        static_cast<size_t>(y0) * width + x1, static_cast<size_t>(y1) * width + x0,
        static_cast<size_t>(y1) * width + x1 };
      const double wt[4] = { (1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay };
      if (hOut)
      {
        double sum = 0.0, weight = 0.0;
        for (int k = 0; k < 4; ++k)
        {
          if (std::isfinite(hv[s[k]]) && wt[k] > 0.0)
          {
            sum += wt[k] * hv[s[k]];
            weight += wt[k];
          }
        }
        hOut[o] = weight > 0.0 ? static_cast<float>(sum / weight) : nan;
      }
      else
      {
        for (int c = 0; c < 4; ++c)
        {
          double v = 0.0;
          for (int k = 0; k < 4; ++k)
          {
            v += wt[k] * cv[4 * s[k] + c];
          }
          cOut[4 * o + c] = static_cast<unsigned char>(std::min(std::max(std::lround(v), 0L), 255L));
        }
      }
    }
  }
  out = result;
  return true;
}
