#include "vtkGlobeRasterPreparer.h"

#include "vtkCommand.h"
#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeRasterSamples.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <geo_normalize.h>
#include <geotiff.h>
#include <geovalues.h>
#include <tiffio.h>
#include <xtiffio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkGlobeRasterPreparer);

namespace
{
constexpr ttag_t GDALNoDataTag = 42113;

/// Sample layout of the output, from the reader's VTK scalar type.
struct SampleFormat
{
  int Bits = 8;
  int Format = SAMPLEFORMAT_UINT;
};

bool SampleFormatOf(int vtkType, SampleFormat& f)
{
  switch (vtkType)
  {
    case VTK_UNSIGNED_CHAR:
      f = { 8, SAMPLEFORMAT_UINT };
      return true;
    case VTK_SIGNED_CHAR:
    case VTK_CHAR:
      f = { 8, SAMPLEFORMAT_INT };
      return true;
    case VTK_UNSIGNED_SHORT:
      f = { 16, SAMPLEFORMAT_UINT };
      return true;
    case VTK_SHORT:
      f = { 16, SAMPLEFORMAT_INT };
      return true;
    case VTK_UNSIGNED_INT:
      f = { 32, SAMPLEFORMAT_UINT };
      return true;
    case VTK_INT:
      f = { 32, SAMPLEFORMAT_INT };
      return true;
    case VTK_FLOAT:
      f = { 32, SAMPLEFORMAT_IEEEFP };
      return true;
    case VTK_DOUBLE:
      f = { 64, SAMPLEFORMAT_IEEEFP };
      return true;
    default:
      return false;
  }
}

template <typename T>
void PutInteger(unsigned char* p, double v)
{
  const double lo = static_cast<double>(std::numeric_limits<T>::lowest());
  const double hi = static_cast<double>(std::numeric_limits<T>::max());
  const T t = static_cast<T>(std::min(std::max(std::round(v), lo), hi));
  std::memcpy(p, &t, sizeof(T));
}

/// Stores v as VTK type `type` at p: integers rounded to nearest and clamped.
inline void PutSample(unsigned char* p, int type, double v)
{
  switch (type)
  {
    case VTK_UNSIGNED_CHAR:
      PutInteger<uint8_t>(p, v);
      break;
    case VTK_SIGNED_CHAR:
    case VTK_CHAR:
      PutInteger<int8_t>(p, v);
      break;
    case VTK_UNSIGNED_SHORT:
      PutInteger<uint16_t>(p, v);
      break;
    case VTK_SHORT:
      PutInteger<int16_t>(p, v);
      break;
    case VTK_UNSIGNED_INT:
      PutInteger<uint32_t>(p, v);
      break;
    case VTK_INT:
      PutInteger<int32_t>(p, v);
      break;
    case VTK_FLOAT:
    {
      const float f = static_cast<float>(v);
      std::memcpy(p, &f, 4);
      break;
    }
    default:
      std::memcpy(p, &v, 8);
      break;
  }
}

/// The EPSG code of a linear unit name as vtkGlobeRasterReader gives it; 0 if not known.
int LinearUnitCode(const std::string& name)
{
  if (name == "metre" || name == "meter")
  {
    return Linear_Meter;
  }
  if (name == "foot")
  {
    return Linear_Foot;
  }
  if (name == "US survey foot")
  {
    return Linear_Foot_US_Survey;
  }
  return 0;
}

/// A nodata value as GDAL writes it ("nan", "-32768", "-3.4028234663852886e+38").
std::string NoDataText(double v)
{
  if (std::isnan(v))
  {
    return "nan";
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.17g", v);
  return text;
}

// libtiff resets a handle's custom fields at every new directory and then calls the tag
// extenders: GDAL_NODATA (and the GeoTIFF tags, XTIFFInitialize) are registered through one,
// installed once and chained to any previous extender.
TIFFExtendProc PreviousExtender = nullptr;

void NoDataTagExtender(TIFF* tif)
{
  static const TIFFFieldInfo info[] = { { GDALNoDataTag, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0,
    const_cast<char*>("GDAL_NODATA") } };
  if (!TIFFFindField(tif, GDALNoDataTag, TIFF_ANY))
  {
    TIFFMergeFieldInfo(tif, info, 1);
  }
  if (PreviousExtender)
  {
    PreviousExtender(tif);
  }
}

/// Opens a TIFF for writing with the GeoTIFF and GDAL_NODATA tags known to the handle.
TIFF* OpenForWriting(const std::string& path, bool big)
{
  static std::once_flag once;
  std::call_once(once,
    []
    {
      XTIFFInitialize();
      PreviousExtender = TIFFSetTagExtender(NoDataTagExtender);
    });
  return XTIFFOpen(path.c_str(), big ? "w8" : "w");
}

/// What every level's directory has in common.
struct Layout
{
  int Channels = 1;
  int ScalarType = VTK_FLOAT;
  SampleFormat Sample;
  int Tile = 256;
  int Compression = 1;
  bool HasNoData = false;
  double NoData = 0.0;
  // Nodata as a sample of ScalarType holds it (samples are compared after conversion to
  // double); false when no sample can be nodata.
  bool NoDataUsable = false;
  double NoDataSample = 0.0;
  bool Height = true; // 1 channel: nodata-aware averaging
};

/// Sets up a directory for a level of size w x h (the tags, not the pixels).
void SetupDirectory(TIFF* tif, const Layout& layout, int w, int h, bool reduced)
{
  TIFFSetField(tif, TIFFTAG_SUBFILETYPE, reduced ? FILETYPE_REDUCEDIMAGE : 0);
  TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, static_cast<uint32_t>(w));
  TIFFSetField(tif, TIFFTAG_IMAGELENGTH, static_cast<uint32_t>(h));
  TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, layout.Channels);
  TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, layout.Sample.Bits);
  TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, layout.Sample.Format);
  TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(
    tif, TIFFTAG_PHOTOMETRIC, layout.Channels >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
  if (layout.Channels == 2 || layout.Channels == 4)
  {
    const uint16_t extra = EXTRASAMPLE_UNASSALPHA; // straight alpha, as the reader gives it
    TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, 1, &extra);
  }
  TIFFSetField(tif, TIFFTAG_TILEWIDTH, static_cast<uint32_t>(layout.Tile));
  TIFFSetField(tif, TIFFTAG_TILELENGTH, static_cast<uint32_t>(layout.Tile));
  if (layout.Compression == vtkGlobeRasterPreparer::Deflate)
  {
    TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tif, TIFFTAG_PREDICTOR,
      layout.Sample.Format == SAMPLEFORMAT_IEEEFP ? PREDICTOR_FLOATINGPOINT
                                                  : PREDICTOR_HORIZONTAL);
  }
  else
  {
    TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
  }
  if (layout.HasNoData)
  {
    TIFFSetField(tif, GDALNoDataTag, NoDataText(layout.NoData).c_str());
  }
}

/**
 * One level being built: a buffer of one tile row (Tile rows of the padded width), written
 * tile by tile when full, and the even row waiting for its odd partner to make the next level.
 */
struct Level
{
  int Width = 0;
  int Height = 0;
  int TilesAcross = 0;
  TIFF* Tif = nullptr;
  std::string Path; // temporary file (levels >= 1)
  std::vector<unsigned char> TileRow;
  std::vector<double> Pending; // the even row of this level, as double
};

void CloseTIFF(TIFF*& tif)
{
  if (tif)
  {
    XTIFFClose(tif);
    tif = nullptr;
  }
}
} // namespace

//------------------------------------------------------------------------------------------
vtkGlobeRasterPreparer::vtkGlobeRasterPreparer() = default;

vtkGlobeRasterPreparer::~vtkGlobeRasterPreparer()
{
  this->SetInputFileName(nullptr);
  this->SetFileName(nullptr);
}

bool vtkGlobeRasterPreparer::Fail(const std::string& why)
{
  this->LastError = why;
  vtkErrorMacro(<< "Cannot prepare '" << (this->InputFileName ? this->InputFileName : "")
                << "' as '" << (this->FileName ? this->FileName : "") << "': " << why);
  return false;
}

void vtkGlobeRasterPreparer::SetProgressValue(double progress)
{
  this->Progress = progress;
  this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
}

//------------------------------------------------------------------------------------------
bool vtkGlobeRasterPreparer::Write()
{
  this->LastError.clear();
  this->AbortExecute = false;
  this->NumberOfLevels = 0;
  this->Size[0] = this->Size[1] = 0;
  if (!this->InputFileName || !*this->InputFileName)
  {
    return this->Fail("no InputFileName is set");
  }
  if (!this->FileName || !*this->FileName)
  {
    return this->Fail("no FileName is set");
  }
  const std::string output = this->FileName;
  {
    std::error_code ec;
    if (std::filesystem::equivalent(this->InputFileName, output, ec))
    {
      return this->Fail("the output would overwrite the input");
    }
  }

  // The header: size, sample type, channels.
  vtkNew<vtkGlobeRasterReader> reader;
  reader->SetFileName(this->InputFileName);
  // The reader's own messages (and its executive's) are swallowed: this class reports the
  // reason, GetLastError(), once, naming the file.
  vtkNew<vtkCallbackCommand> quiet;
  quiet->SetCallback([](vtkObject*, unsigned long, void*, void*) {});
  reader->AddObserver(vtkCommand::ErrorEvent, quiet);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
  reader->UpdateInformation();
  if (*reader->GetLastError())
  {
    return this->Fail(std::string("the input cannot be read: ") + reader->GetLastError());
  }
  vtkInformation* outInfo = reader->GetOutputInformation(0);
  int whole[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  const int W = whole[1] - whole[0] + 1;
  const int H = whole[3] - whole[2] + 1;
  vtkInformation* scalarInfo = vtkDataObject::GetActiveFieldInformation(
    outInfo, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  if (!scalarInfo || W <= 0 || H <= 0)
  {
    return this->Fail("the input has no scalars");
  }
  Layout layout;
  layout.ScalarType = scalarInfo->Get(vtkDataObject::FIELD_ARRAY_TYPE());
  layout.Channels = scalarInfo->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS());
  layout.Height = layout.Channels == 1;
  layout.Tile = (this->TileSize + 15) / 16 * 16;
  layout.Compression = this->Compression;
  if (!SampleFormatOf(layout.ScalarType, layout.Sample) || layout.Channels < 1 ||
    layout.Channels > 4)
  {
    return this->Fail("its sample type or channel count is not supported");
  }
  const int T = layout.Tile;
  const size_t sampleBytes = static_cast<size_t>(layout.Sample.Bits / 8);
  const size_t pixelBytes = sampleBytes * layout.Channels;

  // The level sizes: OpenImageIO's MIP convention, down to the first level fitting one tile.
  std::vector<Level> levels(1);
  levels[0].Width = W;
  levels[0].Height = H;
  while (levels.back().Width > T || levels.back().Height > T)
  {
    Level next;
    next.Width = std::max(1, levels.back().Width / 2);
    next.Height = std::max(1, levels.back().Height / 2);
    levels.push_back(next);
  }
  const int nLevels = static_cast<int>(levels.size());

  // Clean-up of temporary files (and the output on failure) on every return path.
  struct Cleanup
  {
    std::vector<Level>& Levels;
    std::string Output;
    bool Success = false;
    ~Cleanup()
    {
      std::error_code ec;
      for (Level& level : this->Levels)
      {
        CloseTIFF(level.Tif);
        if (!level.Path.empty())
        {
          std::filesystem::remove(level.Path, ec);
        }
      }
      if (!this->Success)
      {
        std::filesystem::remove(this->Output, ec);
      }
    }
  } cleanup{ levels, output };

  // Level 0 goes to the output, levels >= 1 to temporary TIFFs next to it.
  double uncompressed = 0.0;
  for (const Level& level : levels)
  {
    uncompressed += static_cast<double>(level.Width) * level.Height * pixelBytes;
  }
  const bool big = uncompressed > 3.5e9;
  for (int l = 0; l < nLevels; ++l)
  {
    Level& level = levels[l];
    level.TilesAcross = (level.Width + T - 1) / T;
    level.TileRow.assign(static_cast<size_t>(level.TilesAcross) * T * T * pixelBytes, 0);
    if (l > 0)
    {
      level.Path = output + ".level" + std::to_string(l) + ".tmp";
    }
    level.Tif = OpenForWriting(l == 0 ? output : level.Path, big);
    if (!level.Tif)
    {
      return this->Fail("'" + (l == 0 ? output : level.Path) + "' cannot be created");
    }
  }

  this->SetProgressValue(0.0);
  // The first band gives the georeferencing (field data); keep it for the tags.
  int modelType = 0, epsg = 0;
  double geo[4] = { 0, 0, 0, 0 };
  double semiAxes[2] = { 0, 0 };
  std::string units;
  bool tagsWritten = false;

  std::vector<unsigned char> tile(static_cast<size_t>(T) * T * pixelBytes);
  std::vector<double> rowValues, nextValues;
  std::vector<unsigned char> rowBytes;
  bool writeFailed = false;

  // Writes tile row `ty` of level l from its buffer.
  const auto flush = [&](int l, int ty)
  {
    Level& level = levels[l];
    const size_t bufferRow = static_cast<size_t>(level.TilesAcross) * T * pixelBytes;
    for (int tx = 0; tx < level.TilesAcross; ++tx)
    {
      for (int y = 0; y < T; ++y)
      {
        std::memcpy(tile.data() + y * T * pixelBytes,
          level.TileRow.data() + y * bufferRow + static_cast<size_t>(tx) * T * pixelBytes,
          T * pixelBytes);
      }
      const uint32_t index = TIFFComputeTile(level.Tif, tx * T, ty * T, 0, 0);
      if (TIFFWriteEncodedTile(level.Tif, index, tile.data(), static_cast<tmsize_t>(tile.size())) <
        0)
      {
        writeFailed = true;
      }
    }
    std::fill(level.TileRow.begin(), level.TileRow.end(), 0);
  };

  // Level l receives its row r (native bytes): into the tile-row buffer, then the cascade.
  std::vector<std::vector<double>> scratch(nLevels);
  std::vector<std::vector<unsigned char>> scratchBytes(nLevels);
  std::function<void(int, int, const unsigned char*)> addRow;
  addRow = [&](int l, int r, const unsigned char* bytes)
  {
    Level& level = levels[l];
    const size_t bufferRow = static_cast<size_t>(level.TilesAcross) * T * pixelBytes;
    std::memcpy(level.TileRow.data() + (r % T) * bufferRow, bytes, level.Width * pixelBytes);
    if (r % T == T - 1 || r == level.Height - 1)
    {
      flush(l, r / T);
    }
    if (l + 1 >= nLevels)
    {
      return;
    }
    // The row as double, for averaging.
    const size_t n = static_cast<size_t>(level.Width) * layout.Channels;
    std::vector<double>& values = scratch[l];
    values.resize(n);
    for (size_t i = 0; i < n; ++i)
    {
      values[i] = vtkGlobeRasterSamples::ToDouble(bytes + i * sampleBytes, layout.ScalarType);
    }
    const bool single = level.Height == 1; // a 1-row level pairs its row with itself
    if (!single && r % 2 == 0)
    {
      if (r + 1 < level.Height)
      {
        level.Pending.swap(values);
      }
      return; // an odd height's last row is dropped
    }
    const std::vector<double>& even = single ? values : level.Pending;
    const std::vector<double>& odd = values;
    Level& next = levels[l + 1];
    const int outRow = single ? 0 : r / 2;
    if (outRow >= next.Height)
    {
      return;
    }
    std::vector<unsigned char>& out = scratchBytes[l];
    out.assign(static_cast<size_t>(next.Width) * pixelBytes, 0);
    const int C = layout.Channels;
    for (int i = 0; i < next.Width; ++i)
    {
      const int c0 = std::min(2 * i, level.Width - 1);
      const int c1 = std::min(2 * i + 1, level.Width - 1);
      for (int k = 0; k < C; ++k)
      {
        const double v[4] = { even[c0 * C + k], even[c1 * C + k], odd[c0 * C + k],
          odd[c1 * C + k] };
        double result;
        if (layout.Height)
        {
          double sum = 0.0;
          int count = 0;
          for (double x : v)
          {
            if (!std::isnan(x) && !(layout.NoDataUsable && x == layout.NoDataSample))
            {
              sum += x;
              ++count;
            }
          }
          result = count > 0 ? sum / count
                             : (layout.HasNoData ? layout.NoData
                                                 : std::numeric_limits<double>::quiet_NaN());
        }
        else
        {
          result = (v[0] + v[1] + v[2] + v[3]) / 4.0;
        }
        PutSample(out.data() + (static_cast<size_t>(i) * C + k) * sampleBytes, layout.ScalarType,
          result);
      }
    }
    addRow(l + 1, outRow, out.data());
  };

  // One pass over the input in bands of T rows (file rows, north first).
  for (int r0 = 0; r0 < H; r0 += T)
  {
    const int r1 = std::min(r0 + T, H); // exclusive
    // VTK rows grow north: file row r is VTK row H - 1 - r.
    int extent[6] = { 0, W - 1, H - r1, H - 1 - r0, 0, 0 };
    reader->UpdateExtent(extent);
    if (*reader->GetLastError())
    {
      return this->Fail(std::string("the input cannot be read: ") + reader->GetLastError());
    }
    vtkImageData* image = reader->GetOutput();
    vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
    if (!scalars || scalars->GetNumberOfTuples() != static_cast<vtkIdType>(W) * (r1 - r0))
    {
      return this->Fail("the input's rows " + std::to_string(r0) + ".." + std::to_string(r1 - 1) +
        " were not read");
    }
    if (!tagsWritten)
    {
      vtkFieldData* fd = image->GetFieldData();
      const auto number = [fd](const char* name, int i) -> double
      {
        vtkDataArray* a = vtkArrayDownCast<vtkDataArray>(fd->GetAbstractArray(name));
        return a && i < a->GetNumberOfValues() ? a->GetComponent(i / a->GetNumberOfComponents(),
                                                   i % a->GetNumberOfComponents())
                                               : std::numeric_limits<double>::quiet_NaN();
      };
      modelType = static_cast<int>(number(vtkGlobeRasterReader::GetModelTypeArrayName(), 0));
      epsg = static_cast<int>(number(vtkGlobeRasterReader::GetEPSGArrayName(), 0));
      for (int i = 0; i < 4; ++i)
      {
        geo[i] = number(vtkGlobeRasterReader::GetGeoTransformArrayName(), i);
      }
      if (fd->GetAbstractArray(vtkGlobeRasterReader::GetNoDataValueArrayName()))
      {
        layout.HasNoData = true;
        layout.NoData = number(vtkGlobeRasterReader::GetNoDataValueArrayName(), 0);
        layout.NoDataUsable =
          vtkGlobeRasterSamples::NoDataSample(layout.NoData, layout.ScalarType, layout.NoDataSample);
      }
      if (fd->GetAbstractArray(vtkGlobeRasterReader::GetDatumSemiAxesArrayName()))
      {
        semiAxes[0] = number(vtkGlobeRasterReader::GetDatumSemiAxesArrayName(), 0);
        semiAxes[1] = number(vtkGlobeRasterReader::GetDatumSemiAxesArrayName(), 1);
      }
      if (auto* u = vtkArrayDownCast<vtkStringArray>(
            fd->GetAbstractArray(vtkGlobeRasterReader::GetUnitsArrayName())))
      {
        units = u->GetNumberOfValues() > 0 ? u->GetValue(0) : "";
      }
      if (!std::isfinite(geo[0]) || !std::isfinite(geo[1]) || !(geo[2] > 0) || !(geo[3] > 0))
      {
        return this->Fail("the input has no usable georeferencing");
      }

      // Every level's directory; level 0 also gets the georeferencing and the texture tag.
      for (int l = 0; l < nLevels; ++l)
      {
        SetupDirectory(levels[l].Tif, layout, levels[l].Width, levels[l].Height, l > 0);
      }
      TIFF* tif = levels[0].Tif;
      TIFFSetField(tif, TIFFTAG_PIXAR_TEXTUREFORMAT, "Plain Texture");
      TIFFSetField(tif, TIFFTAG_SOFTWARE, "VTKGlobe vtkGlobeRasterPreparer");
      const double scale[3] = { geo[2], geo[3], 0.0 };
      const double tie[6] = { 0.0, 0.0, 0.0, geo[0], geo[1], 0.0 };
      TIFFSetField(tif, TIFFTAG_GEOPIXELSCALE, 3, scale);
      TIFFSetField(tif, TIFFTAG_GEOTIEPOINTS, 6, tie);
      GTIF* gtif = GTIFNew(tif);
      if (!gtif)
      {
        return this->Fail("the GeoTIFF keys cannot be written");
      }
      const bool geographic = modelType == vtkGlobeRasterReader::Geographic;
      GTIFKeySet(gtif, GTModelTypeGeoKey, TYPE_SHORT, 1,
        geographic ? ModelTypeGeographic : ModelTypeProjected);
      GTIFKeySet(gtif, GTRasterTypeGeoKey, TYPE_SHORT, 1, RasterPixelIsArea);
      GTIFKeySet(gtif, geographic ? GeographicTypeGeoKey : ProjectedCSTypeGeoKey, TYPE_SHORT, 1,
        epsg > 0 && epsg < KvUserDefined ? epsg : KvUserDefined);
      if (geographic)
      {
        // The reader gives geographic coordinates in degrees, whatever the input's unit.
        GTIFKeySet(gtif, GeogAngularUnitsGeoKey, TYPE_SHORT, 1, Angular_Degree);
      }
      else if (const int unit = LinearUnitCode(units))
      {
        GTIFKeySet(gtif, ProjLinearUnitsGeoKey, TYPE_SHORT, 1, unit);
      }
      if (semiAxes[0] > 0.0)
      {
        GTIFKeySet(gtif, GeogSemiMajorAxisGeoKey, TYPE_DOUBLE, 1, semiAxes[0]);
        GTIFKeySet(gtif, GeogSemiMinorAxisGeoKey, TYPE_DOUBLE, 1, semiAxes[1]);
      }
      GTIFWriteKeys(gtif);
      GTIFFree(gtif);
      tagsWritten = true;
    }

    // Feed the band's rows, north first, into level 0 (and the cascade).
    const auto* base = static_cast<const unsigned char*>(scalars->GetVoidPointer(0));
    for (int r = r0; r < r1; ++r)
    {
      const int index = (H - 1 - r) - extent[2]; // the row within the band image
      addRow(0, r, base + static_cast<size_t>(index) * W * pixelBytes);
    }
    if (writeFailed)
    {
      return this->Fail("writing tiles failed (disk full?)");
    }
    this->SetProgressValue(0.9 * r1 / H);
    if (this->AbortExecute)
    {
      return this->Fail("aborted");
    }
  }
  reader->GetOutput()->Initialize(); // the last band's memory

  // Close the temporary levels, then append their compressed tiles as directories.
  TIFF* out = levels[0].Tif;
  if (!TIFFWriteDirectory(out))
  {
    return this->Fail("its first directory cannot be written");
  }
  std::vector<unsigned char> raw;
  for (int l = 1; l < nLevels; ++l)
  {
    Level& level = levels[l];
    CloseTIFF(level.Tif);
    TIFF* in = TIFFOpen(level.Path.c_str(), "r");
    if (!in)
    {
      return this->Fail("the temporary file '" + level.Path + "' cannot be read back");
    }
    SetupDirectory(out, layout, level.Width, level.Height, true);
    uint64_t* counts = nullptr;
    TIFFGetField(in, TIFFTAG_TILEBYTECOUNTS, &counts);
    const uint32_t nTiles = TIFFNumberOfTiles(in);
    bool ok = counts != nullptr;
    for (uint32_t t = 0; ok && t < nTiles; ++t)
    {
      raw.resize(static_cast<size_t>(counts[t]));
      const tmsize_t n =
        TIFFReadRawTile(in, t, raw.data(), static_cast<tmsize_t>(raw.size()));
      ok = n >= 0 && TIFFWriteRawTile(out, t, raw.data(), n) == n;
    }
    TIFFClose(in);
    if (!ok || !TIFFWriteDirectory(out))
    {
      return this->Fail("level " + std::to_string(l) + " cannot be appended (disk full?)");
    }
    std::error_code ec;
    std::filesystem::remove(level.Path, ec);
    level.Path.clear();
    this->SetProgressValue(0.9 + 0.1 * l / nLevels);
    if (this->AbortExecute)
    {
      return this->Fail("aborted");
    }
  }
  CloseTIFF(levels[0].Tif);
  cleanup.Success = true;
  this->NumberOfLevels = nLevels;
  this->Size[0] = W;
  this->Size[1] = H;
  this->SetProgressValue(1.0);
  return true;
}

//------------------------------------------------------------------------------------------
void vtkGlobeRasterPreparer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputFileName: " << (this->InputFileName ? this->InputFileName : "(none)")
     << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "TileSize: " << this->TileSize << "\n";
  os << indent << "Compression: " << (this->Compression == Deflate ? "deflate" : "none") << "\n";
  os << indent << "AbortExecute: " << this->AbortExecute << "\n";
  os << indent << "Progress: " << this->Progress << "\n";
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError) << "\n";
}
