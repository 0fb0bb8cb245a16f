// Bad input to vtkGlobeLayer: a missing file, a directory, garbage bytes, truncated copies
// of real GeoTIFFs, a TIFF and a PNG without georeferencing, channel counts that do not fit
// the role, rejected in-memory rasters, a role that does not match in-memory data, a
// non-finite scale, all-void heights. Each must return false, report an error that names
// the file (or the in-memory data) and the reason, keep no stale data, and never hang or
// crash. A Projected layer is not an error.
#include "vtkGlobeTestHelpers.h"
#include "vtkDataArray.h"
#include "vtkGlobeErrorTestHelpers.h"
#include "vtkGlobeLayer.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
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
const std::string Temp = VTKGLOBE_TEMP_DIR;

/// The shared check, printing from the layer's name on.
bool ErrorSaid(vtkTest::ErrorObserver* observer, const std::vector<std::string>& words)
{
  return vtkGlobeTest::ErrorSaid(observer, words, "vtkGlobeLayer");
}

/// No data is kept: what a failed layer must look like.
bool Cleared(vtkGlobeLayer* layer)
{
  double e[4];
  layer->GetGeographicExtent(e);
  return !layer->IsValid() && !layer->GetData() && layer->GetNumberOfColumns() == 0 &&
    layer->GetNumberOfRows() == 0 && layer->GetNumberOfComponents() == 0 && layer->GetModelType() == 0 &&
    layer->GetEPSG() == 0 && std::isnan(e[0]) && layer->GetMinimumValue() == 0 &&
    layer->GetMaximumValue() == 0 && !layer->IsGlobal();
}

void WriteBytes(const std::string& path, const std::vector<char>& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::vector<char> ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// A plain image (no GeoTIFF tags) written with OpenImageIO.
bool WritePlainImage(const std::string& path, int channels, OIIO::TypeDesc type)
{
  auto out = OIIO::ImageOutput::create(path);
  if (!out)
  {
    return false;
  }
  OIIO::ImageSpec spec(16, 8, channels, type);
  std::vector<float> pixels(16 * 8 * channels, 0.25f);
  return out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) &&
    out->close();
}

/// Loads `file` into `layer` with `role` and expects a failure that says all `words`.
void ExpectFileError(vtkGlobeLayer* layer, vtkTest::ErrorObserver* observer,
  const std::string& file, int role, const std::vector<std::string>& words, const std::string& what)
{
  layer->SetFileName(file.c_str());
  layer->SetRole(role);
  std::vector<std::string> all = words;
  all.push_back(file);
  const bool failed = !layer->Update();
  Expect(failed && ErrorSaid(observer, all) && Cleared(layer), what);
}
} // namespace

int TestGlobeLayerBadInput(int, char*[])
{
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkGlobeLayer> layer;
  layer->AddObserver(vtkCommand::ErrorEvent, observer);

  std::printf("Nothing to load:\n");
  Expect(!layer->Update() && ErrorSaid(observer, { "no FileName" }) && Cleared(layer),
    "no FileName and no in-memory data: false, an error");

  std::printf("Missing and unreadable files:\n");
  // A valid load first, so the failures below must also throw the old data away.
  layer->SetFileName((Data + "/earth/relief_2deg.tif").c_str());
  Expect(layer->Update() && layer->GetData(), "relief_2deg.tif loads (the stale data to drop)");
  ExpectFileError(layer, observer, Temp + "/no_such_file.tif", vtkGlobeLayer::Height,
    { "does not exist" }, "a missing file: false, 'does not exist', the old data dropped");
  // A failure is reported once: Update() does not try (or report) again until something it
  // depended on changed; the layer's own Modified() asks for another try.
  const int loads = layer->GetNumberOfLoads();
  observer->Clear();
  Expect(!layer->Update() && !observer->GetError() && layer->GetNumberOfLoads() == loads,
    "Update() after a failure, nothing changed: false, no new attempt and no new report");
  layer->Modified();
  Expect(!layer->Update() && observer->GetError() && layer->GetNumberOfLoads() == loads + 1,
    "after Modified(): tried (and reported) again");
  // The same for a streamed layer (its failure once compared a setting decided later).
  {
    vtkNew<vtkGlobeLayer> streamed;
    vtkNew<vtkTest::ErrorObserver> streamedErrors;
    streamed->AddObserver(vtkCommand::ErrorEvent, streamedErrors);
    streamed->SetStreamingToOn();
    streamed->SetFileName((Temp + "/no_such_file.tif").c_str());
    int reports = 0;
    for (int i = 0; i < 3; ++i)
    {
      streamedErrors->Clear();
      streamed->Update();
      reports += streamedErrors->GetError() ? 1 : 0;
    }
    Expect(reports == 1 && !streamed->IsValid(),
      "a missing streamed file: reported once over three Update() calls (" +
        std::to_string(reports) + ")");
  }
  observer->Clear();
  ExpectFileError(layer, observer, Temp, vtkGlobeLayer::Height, { "not a regular file" },
    "a directory: 'not a regular file'");

  std::mt19937 rng(42);
  std::vector<char> garbage(4096);
  for (char& c : garbage)
  {
    c = static_cast<char>(rng() & 0xff);
  }
  WriteBytes(Temp + "/garbage.tif", garbage);
  ExpectFileError(layer, observer, Temp + "/garbage.tif", vtkGlobeLayer::Height,
    { "cannot be opened as an image" }, "4 KiB of random bytes: 'cannot be opened as an image'");
  WriteBytes(Temp + "/empty.tif", {});
  ExpectFileError(layer, observer, Temp + "/empty.tif", vtkGlobeLayer::Height,
    { "cannot be opened as an image" }, "an empty file: 'cannot be opened as an image'");

  // Truncated copies of real GeoTIFFs.
  const std::vector<char> everest = ReadBytes(Data + "/earth/mt_everest_90m.tif");
  WriteBytes(Temp + "/everest_half.tif",
    std::vector<char>(everest.begin(), everest.begin() + everest.size() / 2));
  // GDAL wrote this file's directory after the pixels: cut in half, it has no directory.
  ExpectFileError(layer, observer, Temp + "/everest_half.tif", vtkGlobeLayer::Height,
    { "cannot be opened as an image", "corrupt or truncated" },
    "mt_everest_90m.tif cut in half: 'cannot be opened as an image ... corrupt or truncated'");
  const std::vector<char> world = ReadBytes(Data + "/earth/world.tif");
  WriteBytes(
    Temp + "/world_half.tif", std::vector<char>(world.begin(), world.begin() + world.size() / 2));
  // This one keeps its directory; half of its JPEG tiles are gone.
  ExpectFileError(layer, observer, Temp + "/world_half.tif", vtkGlobeLayer::Color,
    { "pixels cannot be decoded", "corrupt or truncated" },
    "world.tif (JPEG tiles) cut in half: 'pixels cannot be decoded ... corrupt or truncated'");
  // Cut inside the header: not even an image.
  WriteBytes(Temp + "/everest_head.tif", std::vector<char>(everest.begin(), everest.begin() + 12));
  ExpectFileError(layer, observer, Temp + "/everest_head.tif", vtkGlobeLayer::Height,
    { "cannot be opened as an image" }, "its first 12 bytes only: 'cannot be opened as an image'");

  std::printf("Images without georeferencing:\n");
  const bool wroteTiff = WritePlainImage(Temp + "/plain.tif", 1, OIIO::TypeDesc::FLOAT);
  Expect(wroteTiff, "wrote a plain 16 x 8 float TIFF with OpenImageIO");
  ExpectFileError(layer, observer, Temp + "/plain.tif", vtkGlobeLayer::Height,
    { "no GeoTIFF georeferencing" }, "a TIFF without GeoTIFF tags: 'no GeoTIFF georeferencing'");
  const bool wrotePng = WritePlainImage(Temp + "/plain.png", 3, OIIO::TypeDesc::UINT8);
  Expect(wrotePng, "wrote a plain 16 x 8 RGB PNG with OpenImageIO");
  ExpectFileError(layer, observer, Temp + "/plain.png", vtkGlobeLayer::Color,
    { "not a TIFF file", "no GeoTIFF georeferencing" },
    "a PNG: 'not a TIFF file, so it has no GeoTIFF georeferencing'");

  std::printf("Channel counts that do not fit the role:\n");
  ExpectFileError(layer, observer, Data + "/earth/relief_2deg.tif", vtkGlobeLayer::Color,
    { "Color layer needs a 3-channel", "has 1 channel" },
    "a Color layer from the 1-channel relief_2deg.tif");
  ExpectFileError(layer, observer, Data + "/earth/world.tif", vtkGlobeLayer::Height,
    { "Height layer needs a 1-channel", "has 3 channels" },
    "a Height layer from the 3-channel world.tif");

  std::printf("A Projected layer is read, not refused:\n");
  layer->SetFileName((Data + "/earth/world_north_polar_3413.tif").c_str());
  layer->SetRoleToColor();
  Expect(layer->Update() && !observer->GetError() &&
      layer->GetModelType() == vtkGlobeLayer::Projected && layer->GetEPSG() == 3413,
    "world_north_polar_3413.tif: valid, Projected, EPSG 3413, no error");

  std::printf("Non-finite ValueScale:\n");
  layer->SetFileName((Data + "/earth/relief_2deg.tif").c_str());
  layer->SetRoleToHeight();
  layer->SetValueScale(std::numeric_limits<double>::quiet_NaN());
  Expect(!layer->Update() && ErrorSaid(observer, { "relief_2deg.tif", "must be finite" }) &&
      Cleared(layer),
    "ValueScale NaN: 'must be finite'");
  layer->SetValueScale(1.0);
  Expect(layer->Update() && !observer->GetError(), "ValueScale 1 again: loads");

  std::printf("In-memory rasters:\n");
  const float heights[12] = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 };
  const unsigned char rgb[12 * 3] = { 0 };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct BadCall
  {
    int W, H;
    double West, East, South, North;
    const char* Words;
    const char* What;
  };
  const BadCall calls[] = {
    { 0, 3, 0, 1, 0, 1, "must be positive", "width 0" },
    { 4, -3, 0, 1, 0, 1, "must be positive", "height -3" },
    { -4, -3, 0, 1, 0, 1, "must be positive", "width -4, height -3" },
    { 4, 3, 10, 10, 0, 1, "needs west < east", "west == east" },
    { 4, 3, 20, 10, 0, 1, "needs west < east", "west > east" },
    { 4, 3, 0, 1, 5, 5, "needs south < north", "south == north" },
    { 4, 3, 0, 1, 6, 5, "needs south < north", "south > north" },
    { 4, 3, 0, 1, 80, 90.5, "latitude beyond", "north 90.5" },
    { 4, 3, 0, 1, -91, 0, "latitude beyond", "south -91" },
    { 4, 3, -180, 181, 0, 1, "more than 360", "361 degrees of longitude" },
    { 4, 3, nan, 1, 0, 1, "not finite", "west NaN" },
  };
  for (const BadCall& c : calls)
  {
    layer->SetHeightData(c.W, c.H, heights, c.West, c.East, c.South, c.North);
    Expect(ErrorSaid(observer, { "SetHeightData", "in-memory height data", c.Words }) &&
        Cleared(layer) && !layer->GetFileName(),
      std::string("SetHeightData, ") + c.What + ": error '" + c.Words + "', invalid");
    layer->SetColorData(c.W, c.H, 3, rgb, c.West, c.East, c.South, c.North);
    Expect(
      ErrorSaid(observer, { "SetColorData", "in-memory color data", c.Words }) && Cleared(layer),
      std::string("SetColorData, ") + c.What + ": error '" + c.Words + "', invalid");
  }
  layer->SetHeightData(4, 3, nullptr, 0, 1, 0, 1);
  Expect(
    ErrorSaid(observer, { "no values" }) && Cleared(layer), "SetHeightData(nullptr): 'no values'");
  layer->SetColorData(4, 3, 2, rgb, 0, 1, 0, 1);
  Expect(ErrorSaid(observer, { "2 components", "3 (RGB) or 4 (RGBA)" }) && Cleared(layer),
    "SetColorData with 2 components: '3 (RGB) or 4 (RGBA)'");
  Expect(!layer->Update() && ErrorSaid(observer, { "Nothing to load" }),
    "Update() after a rejected SetColorData: nothing to load");

  layer->SetHeightData(4, 3, heights, 0, 1, 0, 1);
  Expect(layer->IsValid() && !observer->GetError() && layer->GetMaximumValue() == 12,
    "a good 4 x 3 SetHeightData is valid at once, max 12");
  layer->SetRoleToColor();
  Expect(!layer->Update() &&
      ErrorSaid(observer, { "in-memory height data", "role does not match" }) && Cleared(layer),
    "the same data as a Color layer: 'role does not match'");
  layer->SetRoleToHeight();
  Expect(layer->Update() && !observer->GetError(), "back to Height: valid again");

  std::vector<float> allVoid(12, std::numeric_limits<float>::quiet_NaN());
  layer->SetHeightData(4, 3, allVoid.data(), 0, 1, 0, 1);
  Expect(ErrorSaid(observer, { "in-memory height data", "no valid height", "all 12 posts" }) &&
      Cleared(layer),
    "all-NaN heights: 'no valid height: all 12 posts are nodata or NaN'");
  std::vector<float> someVoid(heights, heights + 12);
  someVoid[5] = std::numeric_limits<float>::quiet_NaN();
  someVoid[6] = std::numeric_limits<float>::infinity();
  layer->SetFillVoids(false);
  layer->SetHeightData(4, 3, someVoid.data(), 0, 1, 0, 1);
  Expect(layer->IsValid() && layer->GetNumberOfVoids() == 2 &&
      std::isnan(layer->GetData()->GetComponent(5, 0)) &&
      std::isnan(layer->GetData()->GetComponent(6, 0)) && layer->GetMaximumValue() == 12,
    "NaN and +Inf heights are voids (2), left NaN with FillVoids off");
  layer->SetNoDataValue(12.0);
  Expect(layer->Update() && layer->GetNumberOfVoids() == 3 && layer->GetMaximumValue() == 11,
    "SetNoDataValue(12) on in-memory heights: 3 voids, max 11");

  return Checks.Result();
}
