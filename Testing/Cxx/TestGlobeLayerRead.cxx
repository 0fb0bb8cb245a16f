// Reading the real data sets of Data/ into vtkGlobeLayer: sizes, georeferencing (geographic,
// projected, the Moon's own datum), values against OpenImageIO's direct read, the SRTM voids
// of Everest and Rainier before and after the fill, value scale/offset, and lazy Update().
// The expected numbers are those of Data/README.md (gdalinfo/listgeo).
#include "vtkGlobeTestHelpers.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGlobeLayer.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <sstream>
#include <string>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

const std::string Data = VTKGLOBE_DATA_DIR;

bool Near(double a, double b, double tolerance)
{
  return std::abs(a - b) <= tolerance;
}

/// Checks the geographic pixel-edge box and the pixel size of a layer.
void ExpectExtent(vtkGlobeLayer* layer, double west, double east, double south, double north,
  double degreesPerPixel, double tolerance)
{
  double e[4];
  layer->GetGeographicExtent(e);
  Expect(Near(e[0], west, tolerance) && Near(e[1], east, tolerance) &&
      Near(e[2], south, tolerance) && Near(e[3], north, tolerance),
    vtkGlobeTest::Printf("extent W %.9f E %.9f S %.9f N %.9f (expected %.9f %.9f %.9f %.9f, +-%g)", e[0], e[1],
      e[2], e[3], west, east, south, north, tolerance));
  const double dx = layer->GetDegreesPerPixel(0);
  const double dy = layer->GetDegreesPerPixel(1);
  Expect(Near(dx, degreesPerPixel, 1e-12) && Near(dy, degreesPerPixel, 1e-12),
    vtkGlobeTest::Printf("degrees per pixel %.12g x %.12g (expected %.12g)", dx, dy, degreesPerPixel));
}

/// Range of the values of a float array, counting NaN and a sentinel.
struct Stats
{
  double Min = 1e300, Max = -1e300;
  long NaNs = 0, Sentinels = 0;
};

Stats Measure(vtkDataArray* data, float sentinel)
{
  Stats s;
  const float* v = vtkFloatArray::SafeDownCast(data)->GetPointer(0);
  for (vtkIdType i = 0; i < data->GetNumberOfTuples(); ++i)
  {
    if (std::isnan(v[i]))
    {
      ++s.NaNs;
      continue;
    }
    s.Sentinels += v[i] == sentinel;
    s.Min = std::min(s.Min, static_cast<double>(v[i]));
    s.Max = std::max(s.Max, static_cast<double>(v[i]));
  }
  return s;
}

/// The SRTM tiles: voids, fill, the summit.
void CheckSRTM(const char* name, vtkIdType expectedVoids, double expectedMin, double expectedMax,
  double west, double north, double summitLon, double summitLat, double plausibleMax)
{
  std::printf("%s:\n", name);
  vtkNew<vtkGlobeLayer> layer;
  layer->SetFileName((Data + "/earth/" + name).c_str());
  layer->SetFillVoids(false);
  Expect(layer->Update() && layer->IsValid(), "Update() succeeds (FillVoids off)");
  const int w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
  Expect(w == 1201 && h == 1201 && layer->GetNumberOfComponents() == 1,
    vtkGlobeTest::Printf("1201 x 1201 x 1: %d x %d x %d", w, h, layer->GetNumberOfComponents()));
  Expect(layer->GetModelType() == vtkGlobeLayer::Geographic && layer->GetEPSG() == 4326,
    vtkGlobeTest::Printf("Geographic, EPSG %d", layer->GetEPSG()));
  // RasterPixelIsArea: the tie point is the outer corner of the first pixel.
  const double step = 1.0 / 1200.0;
  ExpectExtent(layer, west, west + 1201 * step, north - 1201 * step, north, step, 1e-9);
  Expect(layer->GetHasNoDataValue() && layer->GetNoDataValue() == -32768.0 &&
      !layer->GetNoDataValueOverridden(),
    vtkGlobeTest::Printf("nodata %g from the GDAL_NODATA tag", layer->GetNoDataValue()));
  Expect(layer->GetNumberOfVoids() == expectedVoids,
    vtkGlobeTest::Printf("%lld voids (expected %lld)", static_cast<long long>(layer->GetNumberOfVoids()),
      static_cast<long long>(expectedVoids)));
  Stats raw = Measure(layer->GetData(), -32768.0f);
  Expect(raw.NaNs == expectedVoids && raw.Sentinels == 0,
    vtkGlobeTest::Printf("FillVoids off: the voids are NaN (%ld NaN, %ld -32768 left)", raw.NaNs, raw.Sentinels));
  Expect(raw.Min == expectedMin && raw.Max == expectedMax &&
      layer->GetMinimumValue() == expectedMin && layer->GetMaximumValue() == expectedMax,
    vtkGlobeTest::Printf("valid range %g .. %g m (expected %g .. %g), GetMinimum/MaximumValue agree", raw.Min,
      raw.Max, expectedMin, expectedMax));
  // Keep the raw posts for the checks after the fill.
  std::vector<float> before(vtkFloatArray::SafeDownCast(layer->GetData())->GetPointer(0),
    vtkFloatArray::SafeDownCast(layer->GetData())->GetPointer(0) + static_cast<size_t>(w) * h);
  // Independently: OpenImageIO's int16 read, -32768 = void, every other post in metres.
  auto in = OIIO::ImageInput::open(Data + "/earth/" + name);
  std::vector<short> direct(static_cast<size_t>(w) * h);
  const bool read = in && in->read_image(0, 0, 0, 1, OIIO::TypeDesc::INT16, direct.data());
  long agree = 0;
  for (size_t i = 0; read && i < direct.size(); ++i)
  {
    agree += direct[i] == -32768 ? std::isnan(before[i]) : before[i] == direct[i];
  }
  Expect(read && agree == static_cast<long>(direct.size()),
    vtkGlobeTest::Printf(
      "all %ld posts agree with OpenImageIO's native int16 read (metres, not rescaled)", agree));

  layer->SetFillVoids(true);
  Expect(layer->Update(), "Update() with FillVoids on re-loads");
  const float* filled = vtkFloatArray::SafeDownCast(layer->GetData())->GetPointer(0);
  Stats after = Measure(layer->GetData(), -32768.0f);
  Expect(after.NaNs == 0 && after.Sentinels == 0 && layer->GetNumberOfVoids() == expectedVoids,
    vtkGlobeTest::Printf("filled: no NaN (%ld), no -32768 (%ld), still %lld voids counted", after.NaNs,
      after.Sentinels, static_cast<long long>(layer->GetNumberOfVoids())));
  Expect(after.Max >= expectedMax && after.Max <= plausibleMax && after.Min >= expectedMin,
    vtkGlobeTest::Printf("filled range %g .. %g m: max within [%g, %g], never below the lowest valid post",
      after.Min, after.Max, expectedMax, plausibleMax));
  bool validKept = true;
  for (size_t i = 0; i < before.size(); ++i)
  {
    validKept = validKept && (std::isnan(before[i]) || before[i] == filled[i]);
  }
  Expect(validKept, "every valid post is unchanged by the fill");

  // The void at the summit: its 8-connected component and the ring of valid posts around it.
  const int row = static_cast<int>((north - summitLat) / step);
  const int col = static_cast<int>((summitLon - west) / step);
  const auto at = [w](int r, int c) { return static_cast<size_t>(r) * w + c; };
  if (!std::isnan(before[at(row, col)]))
  {
    std::printf(
      "  the summit post (row %d, col %d) is valid: %g m\n", row, col, before[at(row, col)]);
    return;
  }
  std::vector<char> seen(before.size(), 0);
  std::deque<std::pair<int, int>> queue{ { row, col } };
  seen[at(row, col)] = 1;
  long componentSize = 0;
  double ringMin = 1e300, ringMax = -1e300, fillMin = 1e300, fillMax = -1e300;
  int rowMin = row, rowMax = row, colMin = col, colMax = col;
  while (!queue.empty())
  {
    const auto [r, c] = queue.front();
    queue.pop_front();
    ++componentSize;
    fillMin = std::min(fillMin, static_cast<double>(filled[at(r, c)]));
    fillMax = std::max(fillMax, static_cast<double>(filled[at(r, c)]));
    rowMin = std::min(rowMin, r);
    rowMax = std::max(rowMax, r);
    colMin = std::min(colMin, c);
    colMax = std::max(colMax, c);
    for (int dr = -1; dr <= 1; ++dr)
    {
      for (int dc = -1; dc <= 1; ++dc)
      {
        const int rr = r + dr, cc = c + dc;
        if (rr < 0 || rr >= h || cc < 0 || cc >= w || seen[at(rr, cc)] == 1)
        {
          continue;
        }
        if (std::isnan(before[at(rr, cc)]))
        {
          seen[at(rr, cc)] = 1;
          queue.emplace_back(rr, cc);
        }
        else
        {
          ringMin = std::min(ringMin, static_cast<double>(before[at(rr, cc)]));
          ringMax = std::max(ringMax, static_cast<double>(before[at(rr, cc)]));
        }
      }
    }
  }
  const double summit = filled[at(row, col)];
  std::printf("  summit void: post (row %d, col %d) in a %ld-post void spanning rows %d-%d, "
              "cols %d-%d\n",
    row, col, componentSize, rowMin, rowMax, colMin, colMax);
  Expect(summit >= ringMin && summit <= ringMax,
    vtkGlobeTest::Printf(
      "filled summit %.1f m lies within its valid ring %.1f .. %.1f m", summit, ringMin, ringMax));
  Expect(fillMin >= ringMin - 1e-3 && fillMax <= ringMax + 1e-3,
    vtkGlobeTest::Printf("the whole summit void is filled within the ring: %.1f .. %.1f m", fillMin, fillMax));
}
} // namespace

int TestGlobeLayerRead(int, char*[])
{
  vtkNew<vtkTest::ErrorObserver> observer;

  std::printf("relief_2deg.tif (float32 heights, global):\n");
  {
    vtkNew<vtkGlobeLayer> layer;
    layer->AddObserver(vtkCommand::ErrorEvent, observer);
    layer->SetFileName((Data + "/earth/relief_2deg.tif").c_str());
    Expect(!layer->IsValid() && !layer->GetData() && layer->GetNumberOfLoads() == 0,
      "not loaded before Update()");
    Expect(layer->Update() && layer->IsValid() && !observer->GetError(), "Update() succeeds");
    Expect(std::string(layer->GetName()) == "relief_2deg",
      vtkGlobeTest::Printf("default name is the file's base name: '%s'", layer->GetName()));
    Expect(layer->GetRole() == vtkGlobeLayer::Height &&
        std::string(layer->GetRoleAsString()) == "Height",
      "role Height (the default)");
    Expect(layer->GetNumberOfColumns() == 180 && layer->GetNumberOfRows() == 90 &&
        layer->GetNumberOfComponents() == 1 && layer->GetData()->GetNumberOfTuples() == 16200 &&
        vtkFloatArray::SafeDownCast(layer->GetData()),
      vtkGlobeTest::Printf("180 x 90 x 1, a vtkFloatArray of %lld values",
        static_cast<long long>(layer->GetData()->GetNumberOfTuples())));
    Expect(layer->GetModelType() == vtkGlobeLayer::Geographic && layer->GetEPSG() == 4326,
      vtkGlobeTest::Printf("Geographic (%d), EPSG %d", layer->GetModelType(), layer->GetEPSG()));
    ExpectExtent(layer, -180, 180, -90, 90, 2.0, 0.0);
    Expect(layer->IsGlobal(), "IsGlobal()");
    Expect(layer->GetDatumSemiMajorAxis() == 6378137.0 &&
        Near(layer->GetDatumSemiMinorAxis(), 6356752.314245, 1e-6),
      vtkGlobeTest::Printf("datum from the SemiMajor + InvFlattening keys: %.6f, %.6f m",
        layer->GetDatumSemiMajorAxis(), layer->GetDatumSemiMinorAxis()));
    Expect(Near(layer->GetMinimumValue(), -6526.538, 5e-4) &&
        Near(layer->GetMaximumValue(), 5211.506, 5e-4),
      vtkGlobeTest::Printf("range %.4f .. %.4f m (README: -6526.5 .. 5211.5)", layer->GetMinimumValue(),
        layer->GetMaximumValue()));
    Expect(!layer->GetHasNoDataValue() && layer->GetNumberOfVoids() == 0, "no nodata, no voids");
    std::ostringstream printed;
    layer->Print(printed);
    Expect(printed.str().find("ModelType: Geographic") != std::string::npos &&
        printed.str().find("EPSG: 4326") != std::string::npos &&
        printed.str().find("(global)") != std::string::npos,
      "PrintSelf reports the model type, the EPSG code and a global extent");

    // Row 0 is north: the Arctic Ocean row is deep, the Antarctic row is high ice.
    const float* v = vtkFloatArray::SafeDownCast(layer->GetData())->GetPointer(0);
    double north = 0, south = 0;
    for (int c = 0; c < 180; ++c)
    {
      north += v[c] / 180.0;
      south += v[89 * 180 + c] / 180.0;
    }
    Expect(north < -1000 && south > 1000,
      vtkGlobeTest::Printf(
        "row 0 is north: mean of row 0 (88-90N) %.0f m, of row 89 (88-90S) %.0f m", north, south));
    // Every value equals OpenImageIO's direct float read (float32 data is not rescaled).
    auto in = OIIO::ImageInput::open(Data + "/earth/relief_2deg.tif");
    std::vector<float> direct(180 * 90);
    const bool read = in && in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, direct.data());
    Expect(read && std::equal(direct.begin(), direct.end(), v),
      "all 16,200 values equal OpenImageIO's direct read");
  }

  std::printf("world.tif (RGB JPEG, tiled, global):\n");
  {
    vtkNew<vtkGlobeLayer> layer;
    layer->AddObserver(vtkCommand::ErrorEvent, observer);
    layer->SetFileName((Data + "/earth/world.tif").c_str());
    layer->SetRoleToColor();
    Expect(layer->Update() && !observer->GetError(), "Update() as a Color layer succeeds");
    auto* rgba = vtkUnsignedCharArray::SafeDownCast(layer->GetData());
    Expect(rgba && layer->GetNumberOfColumns() == 2048 && layer->GetNumberOfRows() == 1024 &&
        layer->GetNumberOfComponents() == 4 && rgba->GetNumberOfComponents() == 4,
      vtkGlobeTest::Printf("2048 x 1024, a 4-component (RGBA) vtkUnsignedCharArray: %d x %d x %d",
        layer->GetNumberOfColumns(), layer->GetNumberOfRows(), layer->GetNumberOfComponents()));
    ExpectExtent(layer, -180, 180, -90, 90, 0.17578125, 0.0);
    Expect(layer->IsGlobal() && layer->GetEPSG() == 4326, "global, EPSG 4326");
    auto in = OIIO::ImageInput::open(Data + "/earth/world.tif");
    std::vector<unsigned char> direct(2048 * 1024 * 3);
    const bool read = in && in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, direct.data());
    const unsigned char* p = rgba ? rgba->GetPointer(0) : nullptr;
    long mismatches = 0, opaque = 0;
    for (size_t i = 0; p && i < 2048 * 1024; ++i)
    {
      mismatches += p[4 * i] != direct[3 * i] || p[4 * i + 1] != direct[3 * i + 1] ||
        p[4 * i + 2] != direct[3 * i + 2];
      opaque += p[4 * i + 3] == 255;
    }
    Expect(read && p && mismatches == 0 && opaque == 2048 * 1024,
      vtkGlobeTest::Printf("all 2,097,152 pixels equal OpenImageIO's direct read (%ld differ), alpha 255 (%ld)",
        mismatches, opaque));
    // The pixel that contains (lon 0, lat 0): column 1024, row 512 (row 0 is 90N).
    const size_t k = 512 * 2048 + 1024;
    if (p && read)
    {
      Expect(p[4 * k] == direct[3 * k] && p[4 * k + 1] == direct[3 * k + 1] &&
          p[4 * k + 2] == direct[3 * k + 2],
        vtkGlobeTest::Printf("spot check at (0E, 0N), column 1024, row 512: RGBA (%d, %d, %d, %d)", p[4 * k],
          p[4 * k + 1], p[4 * k + 2], p[4 * k + 3]));
    }
  }

  // SRTM: README's counts; the summits (Everest 27.98806N 86.92528E, Rainier 46.85278N
  // 121.76028W). The fill's maximum principle keeps the max at the highest valid post.
  CheckSRTM("mt_everest_90m.tif", 130953, 192, 8642, 85.0 + 1199.5 / 1200.0, 28.0 + 0.5 / 1200.0,
    86.92528, 27.98806, 8900);
  CheckSRTM("mt_rainier_90m.tif", 9033, 263, 4371, -122.0 - 0.5 / 1200.0, 47.0 + 0.5 / 1200.0,
    -121.76028, 46.85278, 4400);

  std::printf("Projected layers (read; whether to render them is the mapper's decision):\n");
  {
    vtkNew<vtkGlobeLayer> layer;
    layer->AddObserver(vtkCommand::ErrorEvent, observer);
    layer->SetFileName((Data + "/earth/mt_rainier_utm10n.tif").c_str());
    Expect(layer->Update() && !observer->GetError(), "mt_rainier_utm10n.tif: Update() succeeds");
    double origin[2], size[2], e[4];
    layer->GetProjectedGeoTransform(origin, size);
    layer->GetGeographicExtent(e);
    Expect(layer->GetModelType() == vtkGlobeLayer::Projected && layer->GetEPSG() == 32610 &&
        layer->GetNumberOfColumns() == 876 && layer->GetNumberOfRows() == 1252,
      vtkGlobeTest::Printf(
        "Projected, EPSG %d, %d x %d", layer->GetEPSG(), layer->GetNumberOfColumns(), layer->GetNumberOfRows()));
    Expect(Near(origin[0], 575993.04, 0.005) && Near(origin[1], 5207152.44, 0.005) &&
        size[0] == 90.0 && size[1] == 90.0,
      vtkGlobeTest::Printf("origin (%.4f, %.4f) m, pixel %g x %g m", origin[0], origin[1], size[0], size[1]));
    Expect(std::isnan(e[0]) && !layer->IsGlobal() && std::isnan(layer->GetDegreesPerPixel(0)),
      "no geographic extent, not global, no degrees per pixel");
    Expect(layer->GetHasNoDataValue() && layer->GetNoDataValue() == -32768.0 &&
        layer->GetMaximumValue() == 4370.0,
      vtkGlobeTest::Printf("nodata -32768; %lld voids (re-projection border + SRTM voids), max %g m",
        static_cast<long long>(layer->GetNumberOfVoids()), layer->GetMaximumValue()));

    layer->SetFileName((Data + "/earth/world_north_polar_3413.tif").c_str());
    layer->SetRoleToColor();
    Expect(
      layer->Update() && !observer->GetError(), "world_north_polar_3413.tif: Update() succeeds");
    layer->GetProjectedGeoTransform(origin, size);
    Expect(layer->GetModelType() == vtkGlobeLayer::Projected && layer->GetEPSG() == 3413 &&
        layer->GetNumberOfColumns() == 1024 && layer->GetNumberOfRows() == 1024,
      vtkGlobeTest::Printf(
        "Projected, EPSG %d, %d x %d", layer->GetEPSG(), layer->GetNumberOfColumns(), layer->GetNumberOfRows()));
    Expect(origin[0] == -4.0e6 && origin[1] == 4.0e6 && size[0] == 7812.5 && size[1] == 7812.5 &&
        origin[0] + 1024 * size[0] == 4.0e6,
      vtkGlobeTest::Printf(
        "origin (%.1f, %.1f) m, pixel %g m: extent +-4,000,000 m", origin[0], origin[1], size[0]));
  }

  std::printf("moon_1024x512.tif (Moon 2000 sphere, user-defined datum):\n");
  {
    vtkNew<vtkGlobeLayer> layer;
    layer->AddObserver(vtkCommand::ErrorEvent, observer);
    layer->SetFileName((Data + "/moon/moon_1024x512.tif").c_str());
    layer->SetRoleToColor();
    Expect(layer->Update() && !observer->GetError(), "Update() succeeds");
    Expect(layer->GetModelType() == vtkGlobeLayer::Geographic && layer->GetEPSG() == 0,
      vtkGlobeTest::Printf("Geographic, EPSG %d (user-defined)", layer->GetEPSG()));
    Expect(
      layer->GetDatumSemiMajorAxis() == 1737400.0 && layer->GetDatumSemiMinorAxis() == 1737400.0,
      vtkGlobeTest::Printf("datum semi-axes %.1f, %.1f m", layer->GetDatumSemiMajorAxis(),
        layer->GetDatumSemiMinorAxis()));
    ExpectExtent(layer, -180, 180, -90, 90, 0.3515625, 0.0);
    Expect(layer->IsGlobal() && layer->GetNumberOfColumns() == 1024 && layer->GetNumberOfRows() == 512,
      "global, 1024 x 512");
  }

  std::printf("ValueScale / ValueOffset:\n");
  {
    vtkNew<vtkGlobeLayer> layer;
    layer->SetFileName((Data + "/earth/relief_2deg.tif").c_str());
    layer->Update();
    const double min = layer->GetMinimumValue(), max = layer->GetMaximumValue();
    std::vector<float> plain(vtkFloatArray::SafeDownCast(layer->GetData())->GetPointer(0),
      vtkFloatArray::SafeDownCast(layer->GetData())->GetPointer(0) + 16200);
    layer->SetValueScale(2.0);
    layer->SetValueOffset(10.0);
    Expect(layer->Update(), "Update() after SetValueScale(2), SetValueOffset(10)");
    const float* v = vtkFloatArray::SafeDownCast(layer->GetData())->GetPointer(0);
    bool all = true;
    for (int i = 0; i < 16200; ++i)
    {
      all = all && v[i] == static_cast<float>(2.0 * plain[i] + 10.0);
    }
    Expect(layer->GetMinimumValue() == 2 * min + 10 && layer->GetMaximumValue() == 2 * max + 10,
      vtkGlobeTest::Printf("range %.4f .. %.4f m = 2 x (%.4f .. %.4f) + 10", layer->GetMinimumValue(),
        layer->GetMaximumValue(), min, max));
    Expect(all, "every value is 2 raw + 10");

    // SRTM with a scale: nodata is recognised on the raw value, before the scale.
    layer->SetFileName((Data + "/earth/mt_everest_90m.tif").c_str());
    layer->SetValueScale(0.001); // kilometres
    layer->SetValueOffset(0.0);
    const bool km = layer->Update();
    Expect(km && layer->GetNumberOfVoids() == 130953 && Near(layer->GetMaximumValue(), 8.642, 1e-6),
      vtkGlobeTest::Printf("Everest in km: %lld voids, max %.6f km",
        static_cast<long long>(layer->GetNumberOfVoids()), layer->GetMaximumValue()));
  }

  std::printf("Lazy Update():\n");
  {
    vtkNew<vtkGlobeLayer> layer;
    const std::string relief = Data + "/earth/relief_2deg.tif";
    layer->SetFileName(relief.c_str());
    layer->Update();
    layer->Update();
    Expect(layer->GetNumberOfLoads() == 1,
      vtkGlobeTest::Printf("two Update() calls, one load (%d)", layer->GetNumberOfLoads()));
    layer->SetName("Relief");
    layer->Modified();
    layer->Update();
    Expect(layer->GetNumberOfLoads() == 1 && std::string(layer->GetName()) == "Relief",
      vtkGlobeTest::Printf(
        "SetName() and Modified() alone do not re-read (%d loads)", layer->GetNumberOfLoads()));
    const double highest = layer->GetMaximumValue();
    const float first = static_cast<float>(layer->GetData()->GetComponent(1000, 0));
    layer->SetValueScale(3.0);
    layer->Update();
    Expect(layer->GetNumberOfLoads() == 1 && layer->GetMaximumValue() == static_cast<float>(3.0 * highest) &&
        layer->GetData()->GetComponent(1000, 0) == static_cast<float>(3.0 * first),
      vtkGlobeTest::Printf("SetValueScale(3) maps the heights in place, reads nothing (%d loads, "
                           "maximum %g m)", layer->GetNumberOfLoads(), layer->GetMaximumValue()));
    layer->SetValueScale(0.0);
    layer->Update();
    layer->SetValueScale(3.0);
    layer->Update();
    Expect(layer->GetNumberOfLoads() == 2 && layer->GetMaximumValue() == static_cast<float>(3.0 * highest),
      vtkGlobeTest::Printf("to a scale of 0 in place, from it (no inverse) it reads again (%d loads)",
        layer->GetNumberOfLoads()));
    layer->SetValueScale(3.0);
    layer->SetFileName(relief.c_str());
    layer->Update();
    Expect(layer->GetNumberOfLoads() == 2,
      vtkGlobeTest::Printf("setting the same scale and file name again does not (%d loads)",
        layer->GetNumberOfLoads()));
    layer->SetFileName((Data + "/earth/mt_rainier_90m.tif").c_str());
    layer->Update();
    Expect(layer->GetNumberOfLoads() == 3 && layer->GetNumberOfColumns() == 1201,
      vtkGlobeTest::Printf("a new FileName re-reads (%d loads)", layer->GetNumberOfLoads()));
    layer->SetFillVoids(false);
    layer->Update();
    layer->SetNoDataValue(-32768.0); // the file's own value, but now the user's: a new setting
    layer->Update();
    Expect(layer->GetNumberOfLoads() == 5 && layer->GetNoDataValueOverridden(),
      vtkGlobeTest::Printf("FillVoids and SetNoDataValue re-read (%d loads)", layer->GetNumberOfLoads()));
    Expect(layer->GetData()->GetNumberOfTuples() == 1201 * 1201 && layer->IsValid(),
      "the data is there after each Update()");
  }

  return Checks.Result();
}
