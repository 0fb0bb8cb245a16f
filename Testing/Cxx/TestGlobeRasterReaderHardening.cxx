// vtkGlobeRasterReader against small hostile files (issue 16, defects 1 and 4), each written
// here with libtiff, the GeoKey directory raw so that keys can have the wrong type:
// - GeoKeys stored with the wrong type (a DOUBLE or ASCII where a SHORT belongs, a SHORT where
//   a DOUBLE belongs): libgeotiff's GTIFKeyGet copies the stored size, 8 bytes into a 2-byte
//   short, a stack overflow that let a corrupt file load; now an error naming the key and type;
// - a 290-byte header declaring 30000 x 30000 floats: refused before anything is allocated
//   (MaximumMemory), quickly, by the reader and by vtkGlobeLayer;
// - a strip shorter than its pixels (libtiff "repairs" a single short strip by reading past it,
//   into the file's own directory): refused as truncated;
// - GeographicTypeGeoKey 60000 (no EPSG code), a 1e-300 pixel size (an empty extent): refused;
// - a 4e9 x 1 header: refused with its real size (not an int that wrapped around).
// The good files of Data/ still load with the default MaximumMemory, and a uint32 raster
// (heights of 4e9) is read exactly.
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTestErrorObserver.h"

#include <geotiff.h>
#include <geovalues.h>
#include <tiffio.h>
#include <xtiffio.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

using vtkGlobeTest::Printf;

const std::string Data = VTKGLOBE_DATA_DIR;
const std::string Temp = VTKGLOBE_TEMP_DIR;

// GeoKey locations (TIFFTagLocation): the value itself, or an index into a params tag.
constexpr uint16_t Inline = 0;
constexpr uint16_t InDoubles = 34736; // GeoDoubleParamsTag
constexpr uint16_t InAscii = 34737;   // GeoAsciiParamsTag

struct GeoKey
{
  uint16_t Id, Location, Count, Value;
};

/// What to write: a one-channel, uncompressed GeoTIFF with a raw GeoKey directory.
struct File
{
  uint32_t Width = 4;
  uint32_t Height = 3;
  int Bits = 32;
  int Format = SAMPLEFORMAT_IEEEFP;
  double Value = 1.0;        // every sample
  uint32_t RowsPerStrip = 0; // 0: one strip
  size_t ShortBy = 0;        // bytes left out of the last strip
  // Values given to tags of the written directory afterwards (as LONG): a header can then
  // declare any size without the pixels being written.
  std::vector<std::pair<uint16_t, uint32_t>> Patch;
  double Tie[6] = { 0, 0, 0, 10, 50, 0 };
  double Scale[3] = { 0.25, 0.25, 0 };
  std::vector<GeoKey> Keys = { { GTModelTypeGeoKey, Inline, 1, ModelTypeGeographic },
    { GTRasterTypeGeoKey, Inline, 1, RasterPixelIsArea },
    { GeographicTypeGeoKey, Inline, 1, 4326 } };
  std::vector<double> Doubles;
  std::string Ascii;
};

/// Gives single-valued tags of the first directory of a little-endian classic TIFF (as
/// libtiff writes here) new LONG values.
bool PatchTags(const std::string& path, const std::vector<std::pair<uint16_t, uint32_t>>& patch)
{
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> b(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const auto u16 = [&b](size_t at) { return static_cast<uint32_t>(b[at] | b[at + 1] << 8); };
  const auto u32 = [&](size_t at) { return u16(at) | u16(at + 2) << 16; };
  if (b.size() < 8 || b[0] != 'I' || u16(2) != 42 || u32(4) + 2 > b.size())
  {
    return false;
  }
  const size_t ifd = u32(4);
  size_t patched = 0;
  for (uint32_t e = 0; e < u16(ifd) && ifd + 2 + 12 * (e + 1) <= b.size(); ++e)
  {
    unsigned char* entry = b.data() + ifd + 2 + 12 * e;
    for (const auto& p : patch)
    {
      if (u16(ifd + 2 + 12 * e) == p.first && u32(ifd + 2 + 12 * e + 4) == 1)
      {
        const uint32_t v = p.second;
        const unsigned char bytes[12] = { entry[0], entry[1], 4, 0, 1, 0, 0, 0,
          static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
          static_cast<unsigned char>(v >> 16), static_cast<unsigned char>(v >> 24) };
        std::memcpy(entry, bytes, 12);
        ++patched;
      }
    }
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  return patched == patch.size() && static_cast<bool>(out);
}

/// Writes `f`: libtiff's own tags, the GeoKey directory (34735) and params raw.
bool Write(const std::string& path, const File& f)
{
  TIFF* tif = XTIFFOpen(path.c_str(), "w");
  if (!tif)
  {
    return false;
  }
  const uint32_t rowsPerStrip = f.RowsPerStrip ? f.RowsPerStrip : f.Height;
  TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, f.Width);
  TIFFSetField(tif, TIFFTAG_IMAGELENGTH, f.Height);
  TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
  TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, f.Bits);
  TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, f.Format);
  TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
  TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, rowsPerStrip);
  TIFFSetField(tif, TIFFTAG_GEOTIEPOINTS, 6, f.Tie);
  TIFFSetField(tif, TIFFTAG_GEOPIXELSCALE, 3, f.Scale);
  std::vector<uint16_t> directory = { 1, 1, 0, static_cast<uint16_t>(f.Keys.size()) };
  for (const GeoKey& k : f.Keys)
  {
    directory.insert(directory.end(), { k.Id, k.Location, k.Count, k.Value });
  }
  TIFFSetField(tif, TIFFTAG_GEOKEYDIRECTORY, static_cast<int>(directory.size()), directory.data());
  if (!f.Doubles.empty())
  {
    TIFFSetField(
      tif, TIFFTAG_GEODOUBLEPARAMS, static_cast<int>(f.Doubles.size()), f.Doubles.data());
  }
  if (!f.Ascii.empty())
  {
    TIFFSetField(tif, TIFFTAG_GEOASCIIPARAMS, f.Ascii.c_str());
  }
  bool ok = true;
  {
    const size_t sampleBytes = f.Bits / 8;
    const uint32_t strips = (f.Height + rowsPerStrip - 1) / rowsPerStrip;
    std::vector<unsigned char> strip(sampleBytes * f.Width * rowsPerStrip);
    for (size_t i = 0; i < strip.size(); i += sampleBytes)
    {
      const float asFloat = static_cast<float>(f.Value);
      const uint32_t asUInt32 = static_cast<uint32_t>(f.Value);
      const int16_t asInt16 = static_cast<int16_t>(f.Value);
      std::memcpy(strip.data() + i,
        f.Format == SAMPLEFORMAT_IEEEFP ? static_cast<const void*>(&asFloat)
          : f.Bits == 32                ? static_cast<const void*>(&asUInt32)
                                        : static_cast<const void*>(&asInt16),
        sampleBytes);
    }
    for (uint32_t s = 0; s < strips && ok; ++s)
    {
      const uint32_t rows = std::min(rowsPerStrip, f.Height - s * rowsPerStrip);
      size_t bytes = sampleBytes * f.Width * rows;
      bytes -= s + 1 == strips ? f.ShortBy : 0;
      ok = TIFFWriteEncodedStrip(tif, s, strip.data(), static_cast<tmsize_t>(bytes)) ==
        static_cast<tmsize_t>(bytes);
    }
  }
  XTIFFClose(tif);
  return ok && (f.Patch.empty() || PatchTags(path, f.Patch));
}

/// Whether the last failure of Read went through the executive, named the file and left no
/// points.
bool LastFailureReported = false;

/// Reads `path` with a new reader: true when it loads without error; the reason of a failure
/// and the time taken are returned.
bool Read(
  const std::string& path, std::string& error, double& seconds, vtkImageData* copy = nullptr)
{
  vtkNew<vtkGlobeRasterReader> reader;
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkTest::ErrorObserver> executiveErrors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  reader->SetFileName(path.c_str());
  const auto start = std::chrono::steady_clock::now();
  const bool updated = reader->GetExecutive()->Update() != 0;
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  error = reader->GetLastError();
  const std::string message = errors->GetErrorMessage();
  if (copy && updated)
  {
    copy->DeepCopy(reader->GetOutput());
  }
  LastFailureReported = errors->GetError() && executiveErrors->GetError() &&
    message.find(path) != std::string::npos && !error.empty() &&
    reader->GetOutput()->GetNumberOfPoints() == 0;
  return updated && !errors->GetError();
}

bool Says(const std::string& text, const std::vector<std::string>& words)
{
  for (const std::string& w : words)
  {
    if (text.find(w) == std::string::npos)
    {
      return false;
    }
  }
  return true;
}

/// Writes `f` as `name`, reads it and expects a quick failure whose reason says `words`.
void ExpectRefused(const std::string& name, const File& f, const std::vector<std::string>& words,
  const std::string& what)
{
  const std::string path = Temp + "/" + name;
  if (!Write(path, f))
  {
    Expect(false, what + ": the test file could not be written");
    return;
  }
  std::string error;
  double seconds = 0.0;
  const bool loaded = Read(path, error, seconds);
  std::printf("       error: %s\n", error.c_str());
  // Quick: nothing the size of the declared raster is allocated or read.
  Expect(!loaded && LastFailureReported && Says(error, words) && seconds < 5.0,
    Printf(
      "%s: refused in %.3f s through the executive, the reason names it", what.c_str(), seconds));
}

File Projected()
{
  File f;
  f.Keys = { { GTModelTypeGeoKey, Inline, 1, ModelTypeProjected },
    { GTRasterTypeGeoKey, Inline, 1, RasterPixelIsArea },
    { ProjectedCSTypeGeoKey, Inline, 1, 32610 } };
  f.Tie[3] = 500000;
  f.Tie[4] = 5200000;
  f.Scale[0] = f.Scale[1] = 30;
  return f;
}
} // namespace

int TestGlobeRasterReaderHardening(int, char*[])
{
  std::printf("The test files, written correctly, load (the writer is sound):\n");
  {
    std::string error;
    double seconds = 0.0;
    Write(Temp + "/hardening_good.tif", File());
    Expect(Read(Temp + "/hardening_good.tif", error, seconds),
      "4 x 3 float, geographic EPSG:4326 keys as SHORT: loads " + error);
    Write(Temp + "/hardening_good_utm.tif", Projected());
    Expect(Read(Temp + "/hardening_good_utm.tif", error, seconds),
      "4 x 3 float, projected EPSG:32610 keys as SHORT: loads " + error);
    File axes;
    axes.Keys.push_back({ GeogSemiMajorAxisGeoKey, InDoubles, 1, 0 });
    axes.Keys.push_back({ GeogInvFlatteningGeoKey, InDoubles, 1, 1 });
    axes.Doubles = { 6378137.0, 298.257223563 };
    Write(Temp + "/hardening_good_axes.tif", axes);
    Expect(Read(Temp + "/hardening_good_axes.tif", error, seconds),
      "with GeogSemiMajorAxis and GeogInvFlattening as DOUBLE: loads " + error);
    File strips;
    strips.Width = 500;
    strips.Height = 400;
    strips.Bits = 16;
    strips.Format = SAMPLEFORMAT_INT;
    strips.Value = 1234;
    Write(Temp + "/hardening_good_strip.tif", strips);
    vtkNew<vtkImageData> image;
    const bool read = Read(Temp + "/hardening_good_strip.tif", error, seconds, image);
    vtkDataArray* values = image->GetPointData()->GetScalars();
    double low = 0.0, high = 0.0;
    if (values)
    {
      low = values->GetRange()[0];
      high = values->GetRange()[1];
    }
    Expect(read && low == 1234 && high == 1234,
      Printf(
        "500 x 400 int16 in one whole strip: loads, every post 1234 (range %g..%g)", low, high));
    strips.RowsPerStrip = 7;
    Write(Temp + "/hardening_good_strips.tif", strips);
    Expect(Read(Temp + "/hardening_good_strips.tif", error, seconds),
      "the same in 7-row strips: loads " + error);
  }

  std::printf("GeoKeys of the wrong type (defect 1):\n");
  {
    // A key stored in a tag that is not a GeoKey params tag (found by Testing/Fuzz): libgeotiff
    // refuses the directory, and its reason is in the error (it went to stderr before, and the
    // error only said the keys cannot be read).
    File f;
    f.Keys[1] = { GTRasterTypeGeoKey, 12345, 1, 0 };
    ExpectRefused("hardening_key_location.tif", f,
      { "GeoTIFF keys cannot be read", "libgeotiff: Key 1025 of unknown type" },
      "a GeoKey in an unknown TIFF tag");
  }
  {
    File f;
    f.Keys[0] = { GTModelTypeGeoKey, InDoubles, 1, 0 };
    f.Doubles = { 2.0 };
    ExpectRefused("hardening_model_double.tif", f,
      { "GTModelTypeGeoKey", "stored as DOUBLE, not SHORT", "corrupt" },
      "GTModelTypeGeoKey stored as DOUBLE");
  }
  {
    File f = Projected();
    f.Keys[2] = { ProjectedCSTypeGeoKey, InDoubles, 1, 0 };
    f.Doubles = { 32610.0 };
    ExpectRefused("hardening_pcs_double.tif", f,
      { "ProjectedCSTypeGeoKey", "stored as DOUBLE, not SHORT", "corrupt" },
      "ProjectedCSTypeGeoKey stored as DOUBLE (a projected file)");
  }
  {
    File f;
    f.Keys[1] = { GTRasterTypeGeoKey, InDoubles, 1, 0 };
    f.Doubles = { 1.0 };
    ExpectRefused("hardening_raster_double.tif", f,
      { "GTRasterTypeGeoKey", "stored as DOUBLE, not SHORT" },
      "GTRasterTypeGeoKey stored as DOUBLE");
  }
  {
    File f;
    f.Keys[2] = { GeographicTypeGeoKey, InAscii, 5, 0 };
    f.Ascii = "4326|";
    ExpectRefused("hardening_gcs_ascii.tif", f,
      { "GeographicTypeGeoKey", "stored as ASCII, not SHORT" },
      "GeographicTypeGeoKey stored as ASCII");
  }
  {
    File f;
    f.Keys.push_back({ GeogAngularUnitsGeoKey, InDoubles, 1, 0 });
    f.Doubles = { 9102.0 };
    ExpectRefused("hardening_angular_double.tif", f,
      { "GeogAngularUnitsGeoKey", "stored as DOUBLE, not SHORT" },
      "GeogAngularUnitsGeoKey stored as DOUBLE");
  }
  {
    File f;
    f.Keys.push_back({ GeogSemiMajorAxisGeoKey, Inline, 1, 6378 });
    ExpectRefused("hardening_axis_short.tif", f,
      { "GeogSemiMajorAxisGeoKey", "stored as SHORT, not DOUBLE" },
      "GeogSemiMajorAxisGeoKey stored as SHORT");
  }
  {
    File f;
    f.Keys.push_back({ GeogSemiMajorAxisGeoKey, InDoubles, 1, 0 });
    f.Keys.push_back({ GeogInvFlatteningGeoKey, InAscii, 4, 0 });
    f.Doubles = { 6378137.0 };
    f.Ascii = "298|";
    ExpectRefused("hardening_flattening_ascii.tif", f,
      { "GeogInvFlatteningGeoKey", "stored as ASCII, not DOUBLE" },
      "GeogInvFlatteningGeoKey stored as ASCII");
  }
  {
    File f;
    f.Keys[2] = { GeographicTypeGeoKey, InDoubles, 2, 0 };
    f.Doubles = { 4326.0, 4326.0 };
    ExpectRefused("hardening_gcs_double2.tif", f,
      { "GeographicTypeGeoKey", "stored as DOUBLE, not SHORT" },
      "GeographicTypeGeoKey stored as 2 DOUBLEs (16 bytes into a 2-byte short before)");
  }

  std::printf("Declared sizes beyond the memory budget (defect 4a):\n");
  {
    vtkNew<vtkGlobeRasterReader> reader;
    Expect(reader->GetMaximumMemory() == 2048,
      Printf("MaximumMemory defaults to %d MiB", reader->GetMaximumMemory()));
    // A 4 x 3 file whose header then says 30000 x 30000 in one sparse strip (offset and
    // byte count 0, which libtiff reads as zeros): a few hundred bytes.
    File f;
    f.Scale[0] = f.Scale[1] = 1e-5;
    f.Patch = { { TIFFTAG_IMAGEWIDTH, 30000 }, { TIFFTAG_IMAGELENGTH, 30000 },
      { TIFFTAG_ROWSPERSTRIP, 30000 }, { TIFFTAG_STRIPOFFSETS, 0 },
      { TIFFTAG_STRIPBYTECOUNTS, 0 } };
    ExpectRefused("hardening_30000.tif", f,
      { "30000 x 30000 x 1 float", "3433 MiB", "MaximumMemory (2048 MiB)", "SetMaximumMemory" },
      "a header of 30000 x 30000 floats (3433 MiB), no pixels");

    // Through vtkGlobeLayer read whole: the same refusal, as quick. (Streamed, its default
    // for a raster this size, the header's missing pixels are refused: below.)
    vtkNew<vtkGlobeLayer> layer;
    vtkNew<vtkTest::ErrorObserver> errors;
    layer->AddObserver(vtkCommand::ErrorEvent, errors);
    layer->SetStreamingToOff();
    layer->SetFileName((Temp + "/hardening_30000.tif").c_str());
    const auto start = std::chrono::steady_clock::now();
    const bool loaded = layer->Update();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Expect(!loaded && Says(errors->GetErrorMessage(), { "hardening_30000.tif", "MaximumMemory" }) &&
        seconds < 5.0,
      Printf("vtkGlobeLayer: refused in %.3f s, 'MaximumMemory'", seconds));
    vtkNew<vtkGlobeLayer> streamed;
    vtkNew<vtkTest::ErrorObserver> streamedErrors;
    streamed->AddObserver(vtkCommand::ErrorEvent, streamedErrors);
    streamed->SetFileName((Temp + "/hardening_30000.tif").c_str());
    const auto streamedStart = std::chrono::steady_clock::now();
    const bool streamedLoaded = streamed->Update();
    const double streamedSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - streamedStart).count();
    Expect(!streamedLoaded && Says(streamedErrors->GetErrorMessage(), { "hardening_30000.tif" }) &&
        streamedSeconds < 5.0,
      Printf("vtkGlobeLayer streamed (Auto): refused in %.3f s, naming the file: %s",
        streamedSeconds, streamedErrors->GetErrorMessage().c_str()));

    // The information pass still describes the file.
    reader->SetFileName((Temp + "/hardening_30000.tif").c_str());
    reader->UpdateInformation();
    int extent[6] = { 0, 0, 0, 0, 0, 0 };
    reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
    Expect(extent[1] == 29999 && extent[3] == 29999,
      Printf("its information pass succeeds: WHOLE_EXTENT 0..%d x 0..%d", extent[1], extent[3]));

    // The budget is a setting: world.tif (2048 x 1024 RGB, 6 MiB) against 1 MiB, then 8 MiB.
    vtkNew<vtkTest::ErrorObserver> readerErrors;
    reader->AddObserver(vtkCommand::ErrorEvent, readerErrors);
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, readerErrors);
    reader->SetFileName((Data + "/earth/world.tif").c_str());
    reader->SetMaximumMemory(1);
    reader->Update();
    const std::string small = reader->GetLastError();
    std::printf("       error: %s\n", small.c_str());
    Expect(Says(small, { "2048 x 1024 x 3 unsigned char", "MaximumMemory (1 MiB)" }) &&
        reader->GetOutput()->GetNumberOfPoints() == 0,
      "world.tif with MaximumMemory 1 MiB: refused");
    reader->SetMaximumMemory(8);
    reader->Update();
    Expect(*reader->GetLastError() == 0 && reader->GetOutput()->GetNumberOfPoints() == 2048 * 1024,
      "... with 8 MiB: the whole raster loads");
    reader->SetMaximumMemory(-5);
    Expect(reader->GetMaximumMemory() == 1, "SetMaximumMemory(-5) is clamped to 1 MiB");

    // In-memory heights: the layer's own float copy is held to the same budget.
    vtkNew<vtkGlobeLayer> memory;
    vtkNew<vtkTest::ErrorObserver> memoryErrors;
    memory->AddObserver(vtkCommand::ErrorEvent, memoryErrors);
    memory->GetFileReader()->SetMaximumMemory(1);
    std::vector<float> heights(600 * 600, 5.0f);
    memory->SetHeightData(600, 600, heights.data(), 0, 1, 0, 1);
    std::printf("       error: %s", memoryErrors->GetErrorMessage().c_str());
    Expect(!memory->IsValid() && Says(memoryErrors->GetErrorMessage(), { "MaximumMemory (1 MiB)" }),
      "in-memory 600 x 600 heights (1.4 MiB as float) with MaximumMemory 1 MiB: refused");
    memory->GetFileReader()->SetMaximumMemory(2048);
    memory->SetHeightData(600, 600, heights.data(), 0, 1, 0, 1);
    Expect(memory->IsValid(), "... with 2048 MiB: valid");
  }

  std::printf("Strips shorter than their pixels (defect 4b):\n");
  {
    File f;
    f.Width = 500;
    f.Height = 400;
    f.Bits = 16;
    f.Format = SAMPLEFORMAT_INT;
    f.Value = 1234;
    f.ShortBy = 228; // the directory that libtiff writes after it would be read as pixels
    ExpectRefused("hardening_short_strip.tif", f, { "truncated", "strip 0", "399772", "400000" },
      "500 x 400 int16, its one strip 228 bytes short");
    f.RowsPerStrip = 7;
    ExpectRefused("hardening_short_strips.tif", f, { "truncated", "strip 57" },
      "the same in 7-row strips, the last one 228 bytes short");
  }

  std::printf("Georeferencing that is not usable (defect 4c):\n");
  {
    File f;
    f.Keys[2].Value = 60000;
    ExpectRefused("hardening_epsg60000.tif", f,
      { "EPSG:60000", "GeographicTypeGeoKey", "PROJ's database" },
      "GeographicTypeGeoKey 60000 (not an EPSG code)");
    // A code below 32767 that PROJ's database lacks: libgeotiff's lookups printed
    // "proj_create_from_database: crs not found" to stderr (found by Testing/Fuzz); the
    // reader's error is the only message now.
    f.Keys[2].Value = 1234;
    const std::string captured = Temp + "/hardening_epsg1234.stderr";
    std::fflush(stderr);
    const int saved = dup(2);
    FILE* sink = std::fopen(captured.c_str(), "w");
    if (saved >= 0 && sink)
    {
      dup2(fileno(sink), 2);
    }
    ExpectRefused("hardening_epsg1234.tif", f, { "EPSG:1234", "GeographicTypeGeoKey" },
      "GeographicTypeGeoKey 1234 (no such EPSG code)");
    std::fflush(stderr);
    if (saved >= 0)
    {
      dup2(saved, 2);
      close(saved);
    }
    if (sink)
    {
      std::fclose(sink);
    }
    std::ifstream in(captured);
    const std::string printed(
      (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Expect(saved >= 0 && sink && printed.find("proj_") == std::string::npos,
      "nothing from PROJ on stderr while it is read: '" + printed + "'");
    f = File();
    f.Scale[0] = f.Scale[1] = 1e-300;
    ExpectRefused("hardening_tiny_pixel.tif", f, { "pixel size", "1e-300" },
      "a 1e-300-degree pixel at (10, 50)");
    f.Tie[3] = f.Tie[4] = 0.0;
    ExpectRefused("hardening_tiny_pixel0.tif", f, { "pixel size", "1e-300" },
      "a 1e-300-degree pixel at (0, 0)");
    f = File();
    f.Scale[0] = 1e-14;
    ExpectRefused("hardening_ulp_pixel.tif", f, { "pixel size" },
      "a 1e-14-degree pixel at 10 E (below the coordinate's precision)");

    // uint32 heights of 4e9 m are read exactly (whether they are plausible is the layer's).
    f = File();
    f.Format = SAMPLEFORMAT_UINT;
    f.Value = 4e9;
    Write(Temp + "/hardening_uint32.tif", f);
    std::string error;
    double seconds = 0.0;
    vtkNew<vtkImageData> image;
    const bool read = Read(Temp + "/hardening_uint32.tif", error, seconds, image);
    vtkDataArray* values = image->GetPointData()->GetScalars();
    Expect(read && values && values->GetDataType() == VTK_UNSIGNED_INT &&
        values->GetRange()[0] == 4e9 && values->GetRange()[1] == 4e9,
      "4 x 3 uint32 of 4e9: read as unsigned int, every value 4000000000");
    vtkNew<vtkGlobeLayer> layer;
    vtkNew<vtkTest::ErrorObserver> errors;
    layer->AddObserver(vtkCommand::ErrorEvent, errors);
    layer->SetFileName((Temp + "/hardening_uint32.tif").c_str());
    const bool loaded = layer->Update();
    std::printf("       (not asserted) vtkGlobeLayer on it: %s, heights %.10g..%.10g%s%s",
      loaded ? "valid" : "refused", layer->GetMinimumValue(), layer->GetMaximumValue(),
      errors->GetError() ? ", error: " : "\n", errors->GetErrorMessage().c_str());
  }

  std::printf("Sizes beyond int (defect 4d):\n");
  {
    File f;
    f.Format = SAMPLEFORMAT_UINT;
    f.Patch = { { TIFFTAG_IMAGEWIDTH, 4000000000u }, { TIFFTAG_IMAGELENGTH, 1 },
      { TIFFTAG_ROWSPERSTRIP, 1 }, { TIFFTAG_STRIPOFFSETS, 0 }, { TIFFTAG_STRIPBYTECOUNTS, 0 } };
    ExpectRefused("hardening_4e9.tif", f, { "4000000000 x 1 x 1" },
      "a 4e9 x 1 uint32 header: its real size in the message");
    std::string error;
    double seconds = 0.0;
    Read(Temp + "/hardening_4e9.tif", error, seconds);
    Expect(error.find("-294967296") == std::string::npos, "... not -294967296");
  }

  std::printf("Data/ loads with the default MaximumMemory:\n");
  for (const char* name :
    { "earth/world.tif", "earth/relief_2deg.tif", "earth/mt_rainier_90m.tif",
      "earth/mt_everest_90m.tif", "earth/mt_rainier_utm10n.tif", "earth/world_north_polar_3413.tif",
      "earth/nyc-inset-wgs84.tif", "earth/boston-inset-wgs84.tif", "moon/moon_1024x512.tif" })
  {
    std::string error;
    double seconds = 0.0;
    Expect(Read(Data + "/" + name, error, seconds), std::string(name) + ": loads " + error);
  }

  return Checks.Result();
}
