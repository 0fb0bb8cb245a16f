#include "vtkGlobeRasterReader.h"
#include "vtkGlobeRasterSamples.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <OpenImageIO/imageio.h>

#include <geo_normalize.h>
#include <geotiff.h>
#include <geovalues.h>
#include <proj.h>
#include <tiffio.h>
#include <xtiffio.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <mutex>
#include <new>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkGlobeRasterReader);

namespace
{
constexpr double Pi = 3.14159265358979323846;

// GDAL writes the nodata value as ASCII in this private tag; libtiff does not know it.
constexpr ttag_t GDALNoDataTag = 42113;

//------------------------------------------------------------------------------------------
// libtiff set-up: the GeoTIFF tags (XTIFFInitialize) and GDAL_NODATA are registered through
// tag extenders, which libtiff keeps globally; install them once, chained to any previous one.
TIFFExtendProc PreviousExtender = nullptr;

void GDALTagExtender(TIFF* tif)
{
  static const TIFFFieldInfo info[] = { { GDALNoDataTag, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0,
    const_cast<char*>("GDAL_NODATA") } };
  TIFFMergeFieldInfo(tif, info, 1);
  if (PreviousExtender)
  {
    PreviousExtender(tif);
  }
}

void RegisterTIFFTags()
{
  static std::once_flag once;
  std::call_once(once,
    []
    {
      XTIFFInitialize();
      PreviousExtender = TIFFSetTagExtender(GDALTagExtender);
    });
}

#if defined(TIFFLIB_VERSION) && TIFFLIB_VERSION >= 20221213
// libtiff >= 4.5: per-handle handlers, so messages reach our error text instead of stderr.
int CollectTIFFError(TIFF*, void* userData, const char*, const char* format, va_list args)
{
  char buffer[512];
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  auto* text = static_cast<std::string*>(userData);
  if (text->empty())
  {
    *text = buffer; // the first error is the cause; later ones are consequences
  }
  return 1;
}

int IgnoreTIFFWarning(TIFF*, void*, const char*, const char*, va_list)
{
  return 1; // e.g. GDAL_METADATA (42112), unknown to libtiff and of no use here
}

TIFF* OpenTIFF(const std::string& fileName, std::string* errorText)
{
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  TIFFOpenOptionsSetErrorHandlerExtR(options, CollectTIFFError, errorText);
  TIFFOpenOptionsSetWarningHandlerExtR(options, IgnoreTIFFWarning, nullptr);
  TIFF* tif = TIFFOpenExt(fileName.c_str(), "r", options);
  TIFFOpenOptionsFree(options);
  return tif;
}
#else
TIFF* OpenTIFF(const std::string& fileName, std::string*)
{
  return TIFFOpen(fileName.c_str(), "r");
}
#endif

/// A PROJ context that logs nothing, for libgeotiff's lookups in PROJ's database: with their
/// default context, every miss on a corrupt file's codes went to stderr
/// ("proj_create_from_database: crs not found", found by the fuzzer), out of an application's
/// reach; the reader's own error says what failed.
class QuietPROJContext
{
public:
  QuietPROJContext()
    : Context(proj_context_create())
  {
    if (this->Context)
    {
      proj_log_level(this->Context, PJ_LOG_NONE);
    }
  }
  ~QuietPROJContext()
  {
    if (this->Context)
    {
      proj_context_destroy(this->Context);
    }
  }
  QuietPROJContext(const QuietPROJContext&) = delete;
  QuietPROJContext& operator=(const QuietPROJContext&) = delete;
  PJ_CONTEXT* Get() const { return this->Context; }

private:
  PJ_CONTEXT* Context;
};

/// libgeotiff's errors (e.g. "Key 2054 of unknown type." for a corrupt key directory): kept, the
/// first one, for the reason of a failure (GTIFNew printed them to stderr, where an application
/// cannot see them, and said nothing else).
void CollectGeoTIFFError(GTIF* gtif, int level, const char* format, ...)
{
  auto* text = static_cast<std::string*>(GTIFGetUserData(gtif));
  if (level != LIBGEOTIFF_ERROR || !text || !text->empty())
  {
    return;
  }
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  *text = buffer;
  while (!text->empty() && (text->back() == '.' || text->back() == '\n'))
  {
    text->pop_back();
  }
}

//------------------------------------------------------------------------------------------
// GeoKeys. GTIFKeyGet copies as many bytes as the key's STORED type has: a SHORT key stored as
// DOUBLE writes 8 bytes into a 2-byte unsigned short (a stack overflow that let a corrupt
// file load), a DOUBLE key stored as SHORT leaves 6 bytes of a double unset. Every key is
// checked for its type and count first.

enum class KeyState
{
  Absent,
  Read,
  Corrupt // present with another type or count: `why` says which
};

const char* GeoKeyTypeName(tagtype_t type)
{
  switch (type)
  {
    case TYPE_SHORT:
      return "SHORT";
    case TYPE_DOUBLE:
      return "DOUBLE";
    case TYPE_ASCII:
      return "ASCII";
    default:
      return "an unknown type";
  }
}

/// Reads a single-valued GeoKey of type `wanted` (TYPE_SHORT or TYPE_DOUBLE) into `value`.
KeyState GetGeoKey(GTIF* gtif, geokey_t key, tagtype_t wanted, void* value, std::string& why)
{
  int size = 0;
  tagtype_t type = TYPE_UNKNOWN;
  const int count = GTIFKeyInfo(gtif, key, &size, &type);
  if (count == 0)
  {
    return KeyState::Absent;
  }
  const char* name = GTIFKeyName(key);
  const std::string keyName = name ? name : "GeoKey " + std::to_string(static_cast<int>(key));
  const int wantedSize = wanted == TYPE_SHORT ? 2 : 8;
  if (type != wanted || size != wantedSize)
  {
    why = "its GeoKey " + keyName + " is stored as " + GeoKeyTypeName(type) + ", not " +
      GeoKeyTypeName(wanted) + ": the file is corrupt";
    return KeyState::Corrupt;
  }
  if (count != 1)
  {
    why = "its GeoKey " + keyName + " holds " + std::to_string(count) +
      " values, not 1: the file is corrupt";
    return KeyState::Corrupt;
  }
  if (GTIFKeyGet(gtif, key, value, 0, 1) != 1)
  {
    why = "its GeoKey " + keyName + " cannot be read: the file is corrupt";
    return KeyState::Corrupt;
  }
  return KeyState::Read;
}

KeyState GetShortKey(GTIF* gtif, geokey_t key, unsigned short& value, std::string& why)
{
  return GetGeoKey(gtif, key, TYPE_SHORT, &value, why);
}

KeyState GetDoubleKey(GTIF* gtif, geokey_t key, double& value, std::string& why)
{
  return GetGeoKey(gtif, key, TYPE_DOUBLE, &value, why);
}

//------------------------------------------------------------------------------------------
// CRSs given without an EPSG code (user-defined GeoKeys, a WKT or PROJ string): PROJ
// identifies the equivalent EPSG CRS, so the rest of the project needs only the code.

/// The EPSG code PROJ finds equivalent to a CRS definition (WKT or PROJ string), with PROJ's
/// confidence (70: equivalent up to names, 90 or 100: also by name) and whether it is a
/// projected CRS; 0 when none is at least 70 % or the definition is not a CRS.
int IdentifyEPSG(
  const std::string& definition, int& confidence, std::string& name, bool* projected = nullptr)
{
  confidence = 0;
  int code = 0;
  PJ_CONTEXT* context = proj_context_create();
  if (!context)
  {
    return 0;
  }
  proj_log_level(context, PJ_LOG_NONE);
  if (PJ* crs = proj_create(context, definition.c_str()))
  {
    int* confidences = nullptr;
    if (PJ_OBJ_LIST* list = proj_identify(context, crs, "EPSG", nullptr, &confidences))
    {
      const int n = proj_list_get_count(list);
      for (int i = 0; i < n && code == 0; ++i)
      {
        PJ* candidate = proj_list_get(context, list, i);
        const char* id = candidate ? proj_get_id_code(candidate, 0) : nullptr;
        if (id && confidences[i] >= 70)
        {
          code = std::atoi(id);
          confidence = confidences[i];
          const char* found = proj_get_name(candidate);
          name = found ? found : "";
          if (projected)
          {
            *projected = proj_get_type(candidate) == PJ_TYPE_PROJECTED_CRS;
          }
        }
        proj_destroy(candidate);
      }
      proj_int_list_destroy(confidences);
      proj_list_destroy(list);
    }
    proj_destroy(crs);
  }
  proj_context_destroy(context);
  return code;
}

/// Whether PROJ reads `definition` as a projected CRS.
bool IsProjectedCRS(const std::string& definition)
{
  bool projected = false;
  if (definition.empty())
  {
    return false;
  }
  if (PJ_CONTEXT* context = proj_context_create())
  {
    proj_log_level(context, PJ_LOG_NONE);
    if (PJ* crs = proj_create(context, definition.c_str()))
    {
      projected = proj_get_type(crs) == PJ_TYPE_PROJECTED_CRS;
      proj_destroy(crs);
    }
    proj_context_destroy(context);
  }
  return projected;
}

/// The user-defined projection of a GeoTIFF (ProjectedCSTypeGeoKey absent or user-defined) as
/// libgeotiff normalises it, identified by PROJ. Every GeoKey libgeotiff's normalisation reads
/// is first checked for its type (a corrupt key is refused before libgeotiff reads it).
int IdentifyUserDefinedProjection(GTIF* gtif, int& confidence, std::string& name,
  std::string& definition, std::string& why)
{
  confidence = 0;
  definition.clear();
  // GeogGeodeticDatum .. GeogAzimuthUnits and ProjectedCSType .. ProjRectifiedGridAngle, by type.
  const geokey_t shorts[] = { GeographicTypeGeoKey, GeogGeodeticDatumGeoKey,
    GeogPrimeMeridianGeoKey, GeogLinearUnitsGeoKey, GeogAngularUnitsGeoKey, GeogEllipsoidGeoKey,
    GeogAzimuthUnitsGeoKey, ProjectedCSTypeGeoKey, ProjectionGeoKey, ProjCoordTransGeoKey,
    ProjLinearUnitsGeoKey };
  unsigned short value = 0;
  for (geokey_t key : shorts)
  {
    if (GetShortKey(gtif, key, value, why) == KeyState::Corrupt)
    {
      return -1;
    }
  }
  double number = 0.0;
  for (int key = GeogLinearUnitSizeGeoKey; key <= GeogPrimeMeridianLongGeoKey; ++key)
  {
    const geokey_t k = static_cast<geokey_t>(key);
    if (k != GeogAngularUnitsGeoKey && k != GeogEllipsoidGeoKey && k != GeogAzimuthUnitsGeoKey &&
      GetDoubleKey(gtif, k, number, why) == KeyState::Corrupt)
    {
      return -1;
    }
  }
  for (int key = ProjLinearUnitSizeGeoKey; key <= ProjRectifiedGridAngleGeoKey; ++key)
  {
    if (GetDoubleKey(gtif, static_cast<geokey_t>(key), number, why) == KeyState::Corrupt)
    {
      return -1;
    }
  }
  if (GetShortKey(gtif, ProjCoordTransGeoKey, value, why) != KeyState::Read &&
    GetShortKey(gtif, ProjectionGeoKey, value, why) != KeyState::Read)
  {
    return 0; // no projection defined at all
  }
  int code = 0;
  // A quiet PROJ context for libgeotiff's lookups (QuietPROJContext), detached afterwards.
  QuietPROJContext quiet;
  GTIFAttachPROJContext(gtif, quiet.Get());
  struct Detach
  {
    GTIF* Gtif;
    ~Detach() { GTIFAttachPROJContext(this->Gtif, nullptr); }
  } detach{ gtif };
  GTIFDefn* defn = GTIFAllocDefn();
  if (defn && GTIFGetDefn(gtif, defn) && defn->Model == ModelTypeProjected)
  {
    if (char* proj4 = GTIFGetProj4Defn(defn))
    {
      definition = std::string(proj4) + " +type=crs";
      code = IdentifyEPSG(definition, confidence, name);
      GTIFFreeMemory(proj4);
    }
  }
  GTIFFreeDefn(defn);
  return code;
}

//------------------------------------------------------------------------------------------
// Strips and tiles as stored. libtiff replaces the byte count of a single uncompressed strip
// that is too short by the full size (a warning only) and then reads past the strip's end,
// e.g. into the file's own directory: a truncated file loads with garbage. The counts are
// therefore read from the first directory itself.

uint64_t Unpack(const unsigned char* p, int size, bool bigEndian)
{
  uint64_t v = 0;
  for (int i = 0; i < size; ++i)
  {
    v |= static_cast<uint64_t>(p[bigEndian ? size - 1 - i : i]) << (8 * i);
  }
  return v;
}

/// The values of a SHORT, LONG or LONG8 tag of the first directory; false when absent or odd.
bool ReadStoredTag(std::ifstream& in, uint64_t fileSize, bool bigEndian, bool bigTIFF,
  const std::vector<unsigned char>& entries, uint16_t tag, std::vector<uint64_t>& values)
{
  const size_t entrySize = bigTIFF ? 20 : 12;
  for (size_t e = 0; e + entrySize <= entries.size(); e += entrySize)
  {
    const unsigned char* p = entries.data() + e;
    if (Unpack(p, 2, bigEndian) != tag)
    {
      continue;
    }
    const uint64_t type = Unpack(p + 2, 2, bigEndian);
    const int size = type == TIFF_SHORT ? 2 : type == TIFF_LONG ? 4 : type == TIFF_LONG8 ? 8 : 0;
    const uint64_t count = Unpack(p + 4, bigTIFF ? 8 : 4, bigEndian);
    const unsigned char* field = p + (bigTIFF ? 12 : 8);
    const uint64_t fieldSize = bigTIFF ? 8 : 4;
    if (size == 0 || count == 0 || count > fileSize / size)
    {
      return false;
    }
    std::vector<unsigned char> bytes(count * size);
    if (bytes.size() <= fieldSize)
    {
      std::memcpy(bytes.data(), field, bytes.size());
    }
    else
    {
      const uint64_t offset = Unpack(field, static_cast<int>(fieldSize), bigEndian);
      if (offset > fileSize || bytes.size() > fileSize - offset ||
        !in.seekg(static_cast<std::streamoff>(offset)) ||
        !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
      {
        return false;
      }
    }
    values.resize(count);
    for (uint64_t i = 0; i < count; ++i)
    {
      values[i] = Unpack(bytes.data() + i * size, size, bigEndian);
    }
    return true;
  }
  return false;
}

/**
 * Checks that every strip or tile of the first directory lies within the file and, when
 * uncompressed, holds all its pixels. "" when it does (or when the directory cannot be
 * parsed here: libtiff and OpenImageIO still have their say), else the reason.
 */
std::string CheckStoredStrips(TIFF* tif, const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::error_code ec;
  const uint64_t fileSize = std::filesystem::file_size(fileName, ec);
  unsigned char header[16] = {};
  if (!in || ec || !in.read(reinterpret_cast<char*>(header), 8))
  {
    return std::string();
  }
  const bool bigEndian = header[0] == 'M';
  const uint64_t magic = Unpack(header + 2, 2, bigEndian);
  const bool bigTIFF = magic == 43;
  if ((header[0] != 'I' && header[0] != 'M') || (magic != 42 && !bigTIFF) ||
    (bigTIFF && !in.read(reinterpret_cast<char*>(header + 8), 8)))
  {
    return std::string();
  }
  const uint64_t directory =
    bigTIFF ? Unpack(header + 8, 8, bigEndian) : Unpack(header + 4, 4, bigEndian);
  unsigned char countBytes[8] = {};
  const int countSize = bigTIFF ? 8 : 2;
  if (directory >= fileSize || !in.seekg(static_cast<std::streamoff>(directory)) ||
    !in.read(reinterpret_cast<char*>(countBytes), countSize))
  {
    return std::string();
  }
  const uint64_t entryCount = Unpack(countBytes, countSize, bigEndian);
  const uint64_t entrySize = bigTIFF ? 20 : 12;
  if (entryCount == 0 || entryCount > 65535 || entryCount * entrySize > fileSize)
  {
    return std::string();
  }
  std::vector<unsigned char> entries(entryCount * entrySize);
  if (!in.read(
        reinterpret_cast<char*>(entries.data()), static_cast<std::streamsize>(entries.size())))
  {
    return std::string();
  }
  const bool tiled = TIFFIsTiled(tif) != 0;
  std::vector<uint64_t> offsets, counts, rowsPerStrip;
  if (!ReadStoredTag(in, fileSize, bigEndian, bigTIFF, entries,
        tiled ? TIFFTAG_TILEOFFSETS : TIFFTAG_STRIPOFFSETS, offsets) ||
    !ReadStoredTag(in, fileSize, bigEndian, bigTIFF, entries,
      tiled ? TIFFTAG_TILEBYTECOUNTS : TIFFTAG_STRIPBYTECOUNTS, counts) ||
    offsets.size() != counts.size())
  {
    return std::string();
  }
  uint16_t compression = COMPRESSION_NONE, planar = PLANARCONFIG_CONTIG, samples = 1;
  uint32_t height = 0;
  TIFFGetFieldDefaulted(tif, TIFFTAG_COMPRESSION, &compression);
  TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &planar);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &samples);
  TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height);
  // Rows per strip as stored (libtiff may have cut a single strip into smaller ones).
  uint64_t rows = height;
  if (!tiled &&
    ReadStoredTag(in, fileSize, bigEndian, bigTIFF, entries, TIFFTAG_ROWSPERSTRIP, rowsPerStrip))
  {
    rows = std::max<uint64_t>(std::min<uint64_t>(rowsPerStrip[0], height), 1);
  }
  const uint64_t planes = planar == PLANARCONFIG_SEPARATE ? samples : 1;
  const uint64_t stripsPerPlane = height == 0 ? 0 : (height + rows - 1) / rows;
  const bool checkSize =
    compression == COMPRESSION_NONE && (tiled || counts.size() == stripsPerPlane * planes);
  const char* what = tiled ? "tile" : "strip";
  for (size_t i = 0; i < counts.size(); ++i)
  {
    if (offsets[i] == 0 && counts[i] == 0)
    {
      continue; // sparse: a missing block, read as zeros
    }
    if (offsets[i] > fileSize || counts[i] > fileSize - offsets[i])
    {
      return "its " + std::string(what) + " " + std::to_string(i) + " (bytes " +
        std::to_string(offsets[i]) + " to " + std::to_string(offsets[i] + counts[i]) +
        ") ends beyond the end of the file (" + std::to_string(fileSize) + " bytes)";
    }
    if (checkSize)
    {
      const uint64_t first = (i % std::max<uint64_t>(stripsPerPlane, 1)) * rows;
      const uint64_t need = tiled ? TIFFTileSize64(tif)
                                  : TIFFVStripSize64(tif,
                                      static_cast<uint32_t>(std::min<uint64_t>(
                                        rows, height - std::min<uint64_t>(first, height))));
      if (counts[i] < need)
      {
        return "its " + std::string(what) + " " + std::to_string(i) + " holds " +
          std::to_string(counts[i]) + " bytes (" + (tiled ? "TileByteCounts" : "StripByteCounts") +
          ") but its uncompressed pixels need " + std::to_string(need) + " (a short " + what + ")";
      }
    }
  }
  return std::string();
}

/// CheckStoredStrips for a file; "" also for a file that is not a TIFF.
std::string CheckStoredStrips(const std::string& fileName)
{
  RegisterTIFFTags();
  std::string ignored;
  TIFF* tif = OpenTIFF(fileName, &ignored);
  if (!tif)
  {
    return std::string();
  }
  const std::string why = CheckStoredStrips(tif, fileName);
  XTIFFClose(tif);
  return why;
}

/// The size a TIFF declares, as libtiff reads it (OpenImageIO keeps sizes in int).
bool DeclaredTIFFSize(const std::string& fileName, uint64_t& width, uint64_t& height)
{
  RegisterTIFFTags();
  std::string ignored;
  TIFF* tif = OpenTIFF(fileName, &ignored);
  if (!tif)
  {
    return false;
  }
  uint32_t w = 0, h = 0;
  const bool ok =
    TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w) && TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h);
  XTIFFClose(tif);
  width = w;
  height = h;
  return ok;
}

/// Parses a number as C does in the "C" locale ("-32768", "nan", "1e+38"), whole text only.
bool ParseNumber(std::string s, double& value)
{
  const auto notSpace = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
  s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
  if (!s.empty() && s[0] == '+')
  {
    s.erase(0, 1);
  }
  const auto result = std::from_chars(s.data(), s.data() + s.size(), value);
  return !s.empty() && result.ec == std::errc() && result.ptr == s.data() + s.size();
}

/// Degrees per unit of a GeogAngularUnitsGeoKey code; 0 when unsupported.
double DegreesPerAngularUnit(int code)
{
  switch (code)
  {
    case Angular_Radian:
      return 180.0 / Pi;
    case Angular_Degree:
      return 1.0;
    case Angular_Arc_Minute:
      return 1.0 / 60.0;
    case Angular_Arc_Second:
      return 1.0 / 3600.0;
    case Angular_Grad:
    case Angular_Gon:
      return 0.9;
    default:
      return 0.0;
  }
}

/// The name of an EPSG length unit ("metre", "foot", ...) from PROJ's database; "" if unknown.
std::string LengthUnitName(const QuietPROJContext& context, int code)
{
  char* name = nullptr;
  double metres = 0.0;
  std::string result;
  if (code > 0 && GTIFGetUOMLengthInfoEx(context.Get(), code, &name, &metres) && name)
  {
    result = name;
  }
  if (name)
  {
    GTIFFreeMemory(name);
  }
  return result;
}

/// What an EPSG code is according to PROJ's database (through libgeotiff).
struct EPSGClass
{
  int ModelType = 0; // 0: unknown to the database
  std::string Name;
  std::string Units;
};

/// Looks `code` up, trying `expected` first.
EPSGClass ClassifyEPSG(int code, int expected)
{
  EPSGClass result;
  const QuietPROJContext context;
  const auto geographic = [&]()
  {
    char* name = nullptr;
    short datum = 0, meridian = 0, angular = 0;
    if (GTIFGetGCSInfoEx(context.Get(), code, &name, &datum, &meridian, &angular))
    {
      result.ModelType = vtkGlobeRasterReader::Geographic;
      result.Name = name ? name : "";
      result.Units = "degree";
    }
    if (name)
    {
      GTIFFreeMemory(name);
    }
    return result.ModelType != 0;
  };
  const auto projected = [&]()
  {
    char* name = nullptr;
    short operation = 0, length = 0, gcs = 0;
    if (GTIFGetPCSInfoEx(context.Get(), code, &name, &operation, &length, &gcs))
    {
      result.ModelType = vtkGlobeRasterReader::Projected;
      result.Name = name ? name : "";
      result.Units = LengthUnitName(context, length);
    }
    if (name)
    {
      GTIFFreeMemory(name);
    }
    return result.ModelType != 0;
  };
  if (code <= 0 || code >= KvUserDefined)
  {
    return result;
  }
  if (expected == vtkGlobeRasterReader::Projected)
  {
    projected() || geographic();
  }
  else
  {
    geographic() || projected();
  }
  return result;
}

const char* ModelTypeName(int type)
{
  return type == vtkGlobeRasterReader::Geographic
    ? "geographic"
    : (type == vtkGlobeRasterReader::Projected ? "projected" : "unknown");
}

/// The georeferencing of a raster, from whichever source.
struct Georeference
{
  int ModelType = 0;
  int EPSG = 0;
  // GDAL-style affine transform: x = t0 + col t1 + row t2, y = t3 + col t4 + row t5, in the
  // model's units (degrees for Geographic), for the outer corner of pixel (0, 0) of the file.
  double T[6] = { 0, 0, 0, 0, 0, 0 };
  double SemiMajor = 0.0;
  double SemiMinor = 0.0;
  std::string Units;
  std::string Source;
  std::string EPSGFrom; // where the EPSG code was read (a GeoKey's name, the .prj file)
  // A projected CRS PROJ reads but matches with no EPSG code (EPSG 0): its definition.
  std::string CRS;
};

/// What libtiff and libgeotiff tell about a file.
struct TIFFInfo
{
  bool IsTIFF = false;
  std::string NotTIFFReason;
  bool HasGeoreference = false;
  Georeference Geo;
  bool HasNoData = false;
  double NoData = 0.0;
  bool NoDataUnparsed = false;
  uint64_t Width = 0; // as declared (uint32): OpenImageIO's int may have wrapped around
  uint64_t Height = 0;
};

/// Checks a transform: finite, not rotated or sheared, non-zero pixel size.
bool CheckTransform(const double t[6], const std::string& what, std::string& why)
{
  for (int i = 0; i < 6; ++i)
  {
    if (!std::isfinite(t[i]))
    {
      why = "its " + what + " is not finite";
      return false;
    }
  }
  if (t[2] != 0.0 || t[4] != 0.0)
  {
    why = "it is rotated or sheared (" + what + " with off-diagonal terms), which is not supported";
    return false;
  }
  if (t[1] == 0.0 || t[5] == 0.0)
  {
    why = "its pixel size is zero (" + what + ")";
    return false;
  }
  // Pixels below 1e-12 of the coordinates' magnitude (and of one map unit) cannot be told
  // apart: the extent is empty (corner + width x pixel == corner) or underflows (1e-300).
  const double px = std::abs(t[1]), py = std::abs(t[5]);
  if (px < 1e-12 * std::max(1.0, std::abs(t[0])) || py < 1e-12 * std::max(1.0, std::abs(t[3])))
  {
    char text[300];
    std::snprintf(text, sizeof(text),
      "its pixel size (%.6g x %.6g) is too small for its coordinates (corner %.10g, %.10g): "
      "below 1e-12 of their magnitude, its extent is empty or not representable (",
      px, py, t[0], t[3]);
    why = text + what + ")";
    return false;
  }
  return true;
}

/**
 * Reads the GeoTIFF georeferencing and the nodata tag. A file that is not a TIFF, or a TIFF
 * without georeferencing tags, is not an error here (a world file may georeference it); false
 * with the reason in `why` for georeferencing that is present but unusable or contradictory.
 */
bool ReadGeoTIFF(const std::string& fileName, TIFFInfo& info, std::string& why)
{
  RegisterTIFFTags();
  std::string tiffError;
  TIFF* tif = OpenTIFF(fileName, &tiffError);
  if (!tif)
  {
    info.NotTIFFReason = "it is not a TIFF file, so it has no GeoTIFF georeferencing";
    if (!tiffError.empty())
    {
      info.NotTIFFReason += " (libtiff: " + tiffError + ")";
    }
    return true;
  }
  info.IsTIFF = true;
  // Closes the handles on every return path.
  struct Closer
  {
    TIFF* Tif;
    GTIF* Gtif = nullptr;
    ~Closer()
    {
      if (this->Gtif)
      {
        GTIFFree(this->Gtif);
      }
      XTIFFClose(this->Tif);
    }
  } closer{ tif };

  uint32_t w = 0, h = 0;
  TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w);
  TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h);
  info.Width = w;
  info.Height = h;

  char* noDataText = nullptr;
  if (TIFFGetField(tif, GDALNoDataTag, &noDataText) && noDataText)
  {
    info.HasNoData = ParseNumber(noDataText, info.NoData);
    info.NoDataUnparsed = !info.HasNoData;
  }

  // The raster -> model transform, from the tie point and pixel scale or from the matrix.
  uint16_t count = 0;
  double* values = nullptr;
  double* tie = nullptr;
  uint16_t tieCount = 0;
  if (TIFFGetField(tif, TIFFTAG_GEOTIEPOINTS, &tieCount, &values) && tieCount >= 6)
  {
    tie = values;
  }
  double* scale = nullptr;
  if (TIFFGetField(tif, TIFFTAG_GEOPIXELSCALE, &count, &values) && count >= 2)
  {
    scale = values;
  }
  double* matrix = nullptr;
  if (TIFFGetField(tif, TIFFTAG_GEOTRANSMATRIX, &count, &values) && count >= 16)
  {
    matrix = values;
  }
  Georeference& geo = info.Geo;
  double* t = geo.T;
  if (tie && scale)
  {
    t[0] = tie[3] - tie[0] * scale[0];
    t[1] = scale[0];
    t[2] = 0.0;
    t[3] = tie[4] + tie[1] * scale[1];
    t[4] = 0.0;
    t[5] = -scale[1];
  }
  else if (matrix)
  {
    t[0] = matrix[3];
    t[1] = matrix[0];
    t[2] = matrix[1];
    t[3] = matrix[7];
    t[4] = matrix[4];
    t[5] = matrix[5];
  }
  else if (tie)
  {
    why = "its GeoTIFF georeferencing is ground control points only (no ModelPixelScale or "
          "ModelTransformation tag), which is not supported";
    return false;
  }
  else
  {
    return true; // no GeoTIFF georeferencing: perhaps a world file
  }

  std::string geotiffError;
  closer.Gtif = GTIFNewEx(tif, CollectGeoTIFFError, &geotiffError);
  GTIF* gtif = closer.Gtif;
  if (!gtif)
  {
    why = "its GeoTIFF keys cannot be read" +
      (geotiffError.empty() ? std::string() : " (libgeotiff: " + geotiffError + ")");
    return false;
  }
  // Every key through GetShortKey/GetDoubleKey: a key of the wrong type is an error.
  unsigned short code = 0;
  KeyState state = GetShortKey(gtif, GTModelTypeGeoKey, code, why);
  if (state == KeyState::Corrupt)
  {
    return false;
  }
  if (state == KeyState::Absent)
  {
    why = "it has no GTModelTypeGeoKey, so it is not known whether it is geographic or "
          "projected";
    return false;
  }
  if (code == ModelTypeGeographic)
  {
    geo.ModelType = vtkGlobeRasterReader::Geographic;
  }
  else if (code == ModelTypeProjected)
  {
    geo.ModelType = vtkGlobeRasterReader::Projected;
  }
  else
  {
    why = "its model type (GTModelTypeGeoKey = " + std::to_string(code) +
      ") is neither geographic nor projected";
    return false;
  }
  bool pixelIsPoint = false;
  state = GetShortKey(gtif, GTRasterTypeGeoKey, code, why);
  if (state == KeyState::Corrupt)
  {
    return false;
  }
  if (state == KeyState::Read)
  {
    pixelIsPoint = (code == RasterPixelIsPoint);
  }
  const bool geographic = geo.ModelType == vtkGlobeRasterReader::Geographic;
  const geokey_t crsKey = geographic ? GeographicTypeGeoKey : ProjectedCSTypeGeoKey;
  state = GetShortKey(gtif, crsKey, code, why);
  if (state == KeyState::Corrupt)
  {
    return false;
  }
  if (state == KeyState::Read && code != KvUserDefined)
  {
    geo.EPSG = code;
    geo.EPSGFrom = geographic ? "GeographicTypeGeoKey" : "ProjectedCSTypeGeoKey";
  }
  else if (!geographic)
  {
    int confidence = 0;
    std::string name, definition;
    const int identified = IdentifyUserDefinedProjection(gtif, confidence, name, definition, why);
    if (identified < 0)
    {
      return false;
    }
    if (identified > 0)
    {
      geo.EPSG = identified;
      geo.EPSGFrom = "its user-defined projection GeoKeys, which PROJ identifies as EPSG:" +
        std::to_string(identified) + " (" + name + ", " + std::to_string(confidence) + " %)";
    }
    else if (IsProjectedCRS(definition))
    {
      geo.CRS = definition;
      geo.EPSGFrom = "its user-defined projection GeoKeys ('" + definition +
        "', which match no EPSG CRS)";
    }
  }
  // A projected CRS key in a geographic file contradicts its model type.
  if (geographic)
  {
    state = GetShortKey(gtif, ProjectedCSTypeGeoKey, code, why);
    if (state == KeyState::Corrupt)
    {
      return false;
    }
    if (state == KeyState::Read && code != KvUserDefined)
    {
      why = "its georeferencing is contradictory: GTModelTypeGeoKey says geographic, but it has "
            "a projected CRS (ProjectedCSTypeGeoKey = EPSG:" +
        std::to_string(code) + ")";
      return false;
    }
  }
  else
  {
    state = GetShortKey(gtif, ProjLinearUnitsGeoKey, code, why);
    if (state == KeyState::Corrupt)
    {
      return false;
    }
    if (state == KeyState::Read)
    {
      geo.Units = LengthUnitName(QuietPROJContext(), code);
    }
  }

  // The datum's ellipsoid, only when the file spells it out (a user-defined body).
  double a = 0.0, b = 0.0, inverseFlattening = 0.0;
  const KeyState hasA = GetDoubleKey(gtif, GeogSemiMajorAxisGeoKey, a, why);
  const KeyState hasB =
    hasA == KeyState::Corrupt ? hasA : GetDoubleKey(gtif, GeogSemiMinorAxisGeoKey, b, why);
  const KeyState hasF = hasB == KeyState::Corrupt
    ? hasB
    : GetDoubleKey(gtif, GeogInvFlatteningGeoKey, inverseFlattening, why);
  if (hasF == KeyState::Corrupt)
  {
    return false;
  }
  if (hasA == KeyState::Read && a > 0.0)
  {
    geo.SemiMajor = a;
    if (hasB == KeyState::Read && b > 0.0)
    {
      geo.SemiMinor = b;
    }
    else if (hasF == KeyState::Read)
    {
      // An inverse flattening of 0 denotes a sphere.
      geo.SemiMinor = inverseFlattening != 0.0 ? a * (1.0 - 1.0 / inverseFlattening) : a;
    }
  }

  if (geographic)
  {
    // Geographic coordinates are in GeogAngularUnits (degrees unless said otherwise).
    double degrees = 1.0;
    double unitSize = 0.0; // radians per unit
    const KeyState hasSize = GetDoubleKey(gtif, GeogAngularUnitSizeGeoKey, unitSize, why);
    const KeyState hasUnits =
      hasSize == KeyState::Corrupt ? hasSize : GetShortKey(gtif, GeogAngularUnitsGeoKey, code, why);
    if (hasUnits == KeyState::Corrupt)
    {
      return false;
    }
    if (hasUnits == KeyState::Read && code != KvUserDefined)
    {
      degrees = DegreesPerAngularUnit(code);
      if (degrees == 0.0)
      {
        why = "its angular unit (GeogAngularUnitsGeoKey = " + std::to_string(code) +
          ") is not supported";
        return false;
      }
    }
    else if (hasSize == KeyState::Read && unitSize > 0.0)
    {
      degrees = unitSize * 180.0 / Pi;
    }
    for (double& v : geo.T)
    {
      v *= degrees;
    }
  }
  if (pixelIsPoint)
  {
    // The transform is for pixel centres: move it to the outer pixel corner.
    t[0] -= 0.5 * (t[1] + t[2]);
    t[3] -= 0.5 * (t[4] + t[5]);
  }
  if (!CheckTransform(t, "ModelTransformation", why))
  {
    return false;
  }
  geo.Source = "GeoTIFF";
  info.HasGeoreference = true;
  return true;
}

//------------------------------------------------------------------------------------------
// World files and .prj files.

/// An existing file next to `image` with one of the extensions, tried as given, in lower and
/// in upper case; "" if none.
std::string FindSidecar(const std::filesystem::path& image, const std::vector<std::string>& exts)
{
  for (const std::string& ext : exts)
  {
    std::string lower = ext, upper = ext;
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
    for (const std::string& e : { ext, lower, upper })
    {
      std::filesystem::path candidate = image;
      candidate.replace_extension(e);
      std::error_code ec;
      if (std::filesystem::is_regular_file(candidate, ec))
      {
        return candidate.string();
      }
    }
  }
  return std::string();
}

/// The world-file names of an image: .tfw and .tifw for .tif, .pgw and .pngw for .png, ...
std::vector<std::string> WorldFileExtensions(const std::filesystem::path& image)
{
  std::string ext = image.extension().string();
  std::vector<std::string> exts;
  if (ext.size() >= 3) // ".ab" at least
  {
    exts.push_back(std::string(".") + ext[1] + ext.back() + "w");
    exts.push_back(ext + "w");
  }
  exts.push_back(".wld");
  return exts;
}

bool ReadText(const std::string& path, std::string& text)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return false;
  }
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return true;
}

/// Six numbers A D B E C F: x = A col + B row + C, y = D col + E row + F at pixel centres.
bool ReadWorldFile(const std::string& path, double t[6], std::string& why)
{
  std::string text;
  if (!ReadText(path, text))
  {
    why = "its world file '" + path + "' cannot be read";
    return false;
  }
  std::istringstream in(text);
  std::string token;
  double v[6];
  int n = 0;
  while (n < 6 && in >> token)
  {
    if (!ParseNumber(token, v[n]))
    {
      break;
    }
    ++n;
  }
  if (n < 6)
  {
    why = "its world file '" + path + "' does not hold six numbers";
    return false;
  }
  // To the GDAL order, at the outer corner of pixel (0, 0).
  t[1] = v[0];
  t[4] = v[1];
  t[2] = v[2];
  t[5] = v[3];
  t[0] = v[4] - 0.5 * (v[0] + v[2]);
  t[3] = v[5] - 0.5 * (v[1] + v[3]);
  return CheckTransform(t, "world file '" + path + "'", why);
}

/// What a .prj file's WKT says: its top-level keyword, EPSG authority, unit and ellipsoid.
struct WKTInfo
{
  std::string Keyword;
  int EPSG = 0;
  std::string UnitName;
  double UnitFactor = 0.0;
  double SemiMajor = 0.0;
  double InverseFlattening = -1.0;
};

/// A small WKT (1 or 2) scanner: nodes KEYWORD[arg, arg, ...] with quoted strings; '(' and ')'
/// are accepted as brackets. Only the nodes the reader needs are looked at.
WKTInfo ParseWKT(const std::string& text)
{
  WKTInfo info;
  struct Node
  {
    std::string Keyword;
    std::vector<std::string> Args;
  };
  std::vector<Node> stack;
  std::string token;
  bool quoted = false;
  const auto flush = [&]()
  {
    if (!stack.empty())
    {
      stack.back().Args.push_back(token);
    }
    token.clear();
  };
  const auto close = [&](const Node& node, size_t depth)
  {
    std::string key = node.Keyword;
    std::transform(key.begin(), key.end(), key.begin(), ::toupper);
    const auto arg = [&node](size_t i) { return i < node.Args.size() ? node.Args[i] : ""; };
    double number = 0.0;
    if (depth == 1 && (key == "AUTHORITY" || key == "ID"))
    {
      std::string authority = arg(0);
      std::transform(authority.begin(), authority.end(), authority.begin(), ::toupper);
      if (authority == "EPSG" && ParseNumber(arg(1), number) && number > 0)
      {
        info.EPSG = static_cast<int>(number);
      }
    }
    else if (depth == 1 &&
      (key == "UNIT" || key == "ANGLEUNIT" || key == "LENGTHUNIT") && info.UnitName.empty())
    {
      info.UnitName = arg(0);
      ParseNumber(arg(1), info.UnitFactor);
    }
    else if ((key == "SPHEROID" || key == "ELLIPSOID") && ParseNumber(arg(1), number))
    {
      info.SemiMajor = number;
      if (!ParseNumber(arg(2), info.InverseFlattening))
      {
        info.InverseFlattening = -1.0;
      }
    }
  };
  for (char c : text)
  {
    if (quoted)
    {
      if (c == '"')
      {
        quoted = false;
      }
      else
      {
        token += c;
      }
      continue;
    }
    if (c == '"')
    {
      quoted = true;
    }
    else if (c == '[' || c == '(')
    {
      const auto notSpace = [](unsigned char ch) { return !std::isspace(ch); };
      token.erase(token.begin(), std::find_if(token.begin(), token.end(), notSpace));
      token.erase(std::find_if(token.rbegin(), token.rend(), notSpace).base(), token.end());
      if (stack.empty() && info.Keyword.empty())
      {
        info.Keyword = token;
        std::transform(
          info.Keyword.begin(), info.Keyword.end(), info.Keyword.begin(), ::toupper);
      }
      stack.push_back(Node{ token, {} });
      token.clear();
    }
    else if (c == ',' && !stack.empty())
    {
      flush();
    }
    else if ((c == ']' || c == ')') && !stack.empty())
    {
      flush();
      const Node node = stack.back();
      stack.pop_back();
      // A child node leaves an empty argument in its parent: drop it.
      if (!stack.empty() && !stack.back().Args.empty() && stack.back().Args.back().empty())
      {
        stack.back().Args.pop_back();
      }
      close(node, stack.size());
    }
    else if (!std::isspace(static_cast<unsigned char>(c)) || !token.empty())
    {
      token += c;
    }
  }
  return info;
}

/// Model type of a WKT top-level keyword; 0 for anything else (geocentric, compound...).
int WKTModelType(const std::string& keyword)
{
  if (keyword == "GEOGCS" || keyword == "GEOGCRS" || keyword == "GEOGRAPHICCRS" ||
    (keyword == "GEODCRS"))
  {
    return vtkGlobeRasterReader::Geographic;
  }
  if (keyword == "PROJCS" || keyword == "PROJCRS" || keyword == "PROJECTEDCRS")
  {
    return vtkGlobeRasterReader::Projected;
  }
  return 0;
}

std::string FormatTransform(const double t[6])
{
  char text[160];
  std::snprintf(text, sizeof(text), "corner (%.10g, %.10g), pixel %.10g x %.10g", t[0], t[3],
    t[1], t[5]);
  return text;
}

/// True when two outer-corner transforms describe the same grid (world files are written with
/// ~10 significant digits: allow 1e-6 of a pixel on the corner, 1e-9 relative on the size).
bool SameGrid(const double a[6], const double b[6])
{
  const double px = std::abs(a[1]), py = std::abs(a[5]);
  return std::abs(a[1] - b[1]) <= 1e-9 * px && std::abs(a[5] - b[5]) <= 1e-9 * py &&
    std::abs(a[0] - b[0]) <= 1e-6 * px && std::abs(a[3] - b[3]) <= 1e-6 * py;
}

/// The pixel-edge box of a north-up transform: west, east, south, north.
void BoxOf(const double t[6], int width, int height, double box[4])
{
  box[0] = t[0];
  box[1] = t[0] + width * t[1];
  box[2] = t[3] + height * t[5];
  box[3] = t[3];
}

/// Points-registered global grids reach half a pixel beyond the poles and the date line; more
/// than a pixel means the coordinates are not degrees.
bool FitsDegrees(const double box[4], double dx, double dy)
{
  return box[2] >= -90.0 - dy && box[3] <= 90.0 + dy && box[1] - box[0] <= 360.0 + dx &&
    box[0] >= -360.0 - dx && box[1] <= 360.0 + dx;
}

std::string BoxText(const double box[4])
{
  char text[200];
  std::snprintf(text, sizeof(text), "(west %g, east %g, south %g, north %g)", box[0], box[1],
    box[2], box[3]);
  return text;
}

/// Opens an image for reading pixels; straight alpha is kept as stored (OpenImageIO would
/// premultiply unassociated alpha by default).
std::unique_ptr<OIIO::ImageInput> OpenImage(const std::string& file)
{
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return OIIO::ImageInput::open(file, &config);
}
} // namespace

namespace
{
/**
 * The date a file's name holds (YYYY-MM-DD, YYYYMMDD, YYYY_MM_DD, or YYYY-MM for the month's
 * first day; years 1900..2099) as a decimal year: 2026-04-01 is 2026 + 90 / 365. False when
 * the name holds none, or not a valid day.
 */
bool DecimalYearInName(const std::string& file, double& year)
{
  static const std::regex day(R"(((?:19|20)\d\d)[-_]?(0[1-9]|1[0-2])[-_]?(0[1-9]|[12]\d|3[01]))");
  static const std::regex month(R"(((?:19|20)\d\d)[-_](0[1-9]|1[0-2]))");
  const std::string name = std::filesystem::path(file).stem().string();
  std::smatch m;
  int y = 0, mo = 0, d = 1;
  if (std::regex_search(name, m, day))
  {
    y = std::stoi(m[1]);
    mo = std::stoi(m[2]);
    d = std::stoi(m[3]);
  }
  else if (std::regex_search(name, m, month))
  {
    y = std::stoi(m[1]);
    mo = std::stoi(m[2]);
  }
  else
  {
    return false;
  }
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  const int lengths[12] = { 31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
  if (d > lengths[mo - 1])
  {
    return false;
  }
  int dayOfYear = d - 1;
  for (int k = 0; k < mo - 1; ++k)
  {
    dayOfYear += lengths[k];
  }
  year = y + dayOfYear / (leap ? 366.0 : 365.0);
  return true;
}
} // namespace

//------------------------------------------------------------------------------------------
class vtkGlobeRasterReader::vtkInternals
{
public:
  // What RequestInformation found (for File); RequestData reads pixels with it.
  std::string File;
  int Width = 0;
  int Height = 0;
  int Channels = 0;
  int ScalarType = 0;
  int TileHeight = 0; // 0: scanline file
  int FirstX = 0;     // OpenImageIO's data window origin
  int FirstY = 0;
  bool FlipRows = false; // file row 0 is the north row (the usual case): VTK row 0 is south
  bool FlipColumns = false;
  Georeference Geo; // T normalised: north-west corner, t1 > 0, t5 < 0
  bool HasNoData = false;
  double NoData = 0.0;
  bool StripsChecked = false; // CheckStoredStrips passed since RequestInformation
  std::string LastError;
  std::string Reading;            // the file the last header or pixel read was about
  bool InformationFailed = false; // the last RequestInformation failed

  /// A time series (AddFileName): the files as given, and as time steps.
  struct Step
  {
    std::string File;
    double Time = 0.0;
    bool Timed = false; // given with a time
  };
  std::vector<Step> Series;
  std::vector<Step> Steps; // Series in time order, each with its time (RequestInformation)
  // A series' last read (sharing the output's arrays), given again for another time within
  // the same step while the file, the extent and the reader's settings are the same.
  vtkSmartPointer<vtkImageData> Kept;
  std::string KeptFile;
  int KeptExtent[6] = { 0, -1, 0, -1, 0, -1 };
  vtkMTimeType KeptTime = 0;

  /// Sets Steps from Series; the reason when the times cannot be time steps, else "".
  std::string OrderSteps(bool datesFromNames)
  {
    this->Steps = this->Series;
    auto timed = std::count_if(
      this->Steps.begin(), this->Steps.end(), [](const Step& step) { return step.Timed; });
    if (timed == 0)
    {
      // Dated files (every name holds a date) are at their dates, in decimal years; others at
      // their positions.
      bool dated = datesFromNames;
      for (size_t i = 0; dated && i < this->Steps.size(); ++i)
      {
        dated = DecimalYearInName(this->Steps[i].File, this->Steps[i].Time);
        this->Steps[i].Timed = dated;
      }
      if (!dated)
      {
        for (size_t i = 0; i < this->Steps.size(); ++i)
        {
          this->Steps[i].Time = static_cast<double>(i);
          this->Steps[i].Timed = false;
        }
        return "";
      }
      timed = static_cast<decltype(timed)>(this->Steps.size());
    }
    if (static_cast<size_t>(timed) != this->Steps.size())
    {
      return "the series gives times for " + std::to_string(timed) + " of its " +
        std::to_string(this->Steps.size()) + " files: give every file a time, or none";
    }
    for (const Step& step : this->Steps)
    {
      if (!std::isfinite(step.Time))
      {
        return "the time of '" + step.File + "' is not a finite number";
      }
    }
    std::stable_sort(this->Steps.begin(), this->Steps.end(),
      [](const Step& a, const Step& b) { return a.Time < b.Time; });
    for (size_t i = 1; i < this->Steps.size(); ++i)
    {
      if (this->Steps[i].Time == this->Steps[i - 1].Time)
      {
        std::ostringstream why;
        why.precision(17);
        why << "two files have the time " << this->Steps[i].Time << ": '"
            << this->Steps[i - 1].File << "' and '" << this->Steps[i].File << "'";
        return why.str();
      }
    }
    return "";
  }

  /// What every file of a series must share: size, samples and georeferencing.
  struct Grid
  {
    int Width = 0, Height = 0, Channels = 0, ScalarType = 0;
    Georeference Geo;

    /// How `other` differs from this grid, "" when it does not.
    std::string Mismatch(const Grid& other) const
    {
      std::ostringstream why;
      why.precision(17);
      if (other.Width != this->Width || other.Height != this->Height ||
        other.Channels != this->Channels || other.ScalarType != this->ScalarType)
      {
        why << other.Width << " x " << other.Height << " pixels of " << other.Channels << " "
            << vtkImageScalarTypeNameMacro(other.ScalarType) << " sample(s), not " << this->Width
            << " x " << this->Height << " of " << this->Channels << " "
            << vtkImageScalarTypeNameMacro(this->ScalarType);
      }
      else if (other.Geo.ModelType != this->Geo.ModelType || other.Geo.EPSG != this->Geo.EPSG ||
        other.Geo.CRS != this->Geo.CRS)
      {
        why << "its coordinate system is " << ModelTypeName(other.Geo.ModelType) << " EPSG:"
            << other.Geo.EPSG << ", not " << ModelTypeName(this->Geo.ModelType) << " EPSG:"
            << this->Geo.EPSG;
      }
      else if (!std::equal(other.Geo.T, other.Geo.T + 6, this->Geo.T))
      {
        why << "its north-west corner and pixel size are (" << other.Geo.T[0] << ", "
            << other.Geo.T[3] << "), " << other.Geo.T[1] << " x " << -other.Geo.T[5] << ", not ("
            << this->Geo.T[0] << ", " << this->Geo.T[3] << "), " << this->Geo.T[1] << " x "
            << -this->Geo.T[5];
      }
      return why.str();
    }
  };
  Grid SeriesGrid; // the first step's (RequestInformation)
  Grid CurrentGrid() const
  {
    Grid grid;
    grid.Width = this->Width;
    grid.Height = this->Height;
    grid.Channels = this->Channels;
    grid.ScalarType = this->ScalarType;
    grid.Geo = this->Geo;
    return grid;
  }
};

//------------------------------------------------------------------------------------------
vtkGlobeRasterReader::vtkGlobeRasterReader()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkGlobeRasterReader::~vtkGlobeRasterReader()
{
  this->SetFileName(nullptr);
}

void vtkGlobeRasterReader::AddFileName(const char* fileName)
{
  this->Internals->Series.push_back({ fileName ? fileName : "", 0.0, false });
  this->Modified();
}

void vtkGlobeRasterReader::AddFileName(const char* fileName, double time)
{
  this->Internals->Series.push_back({ fileName ? fileName : "", time, true });
  this->Modified();
}

void vtkGlobeRasterReader::RemoveAllFileNames()
{
  if (!this->Internals->Series.empty())
  {
    this->Internals->Series.clear();
    this->Modified();
  }
}

int vtkGlobeRasterReader::GetNumberOfFileNames()
{
  return static_cast<int>(this->Internals->Series.size());
}

const char* vtkGlobeRasterReader::GetSeriesFileName(int i)
{
  const auto& series = this->Internals->Series;
  return i >= 0 && i < static_cast<int>(series.size()) ? series[i].File.c_str() : nullptr;
}

const char* vtkGlobeRasterReader::GetLastError()
{
  return this->Internals->LastError.c_str();
}

int vtkGlobeRasterReader::Fail(unsigned long errorCode, const std::string& why)
{
  this->Internals->LastError = why;
  this->Internals->File.clear(); // the header information is not valid
  this->SetErrorCode(errorCode);
  vtkErrorMacro(<< "Cannot read '" << this->Internals->Reading << "': " << why);
  return 0;
}

//------------------------------------------------------------------------------------------
int vtkGlobeRasterReader::ReadHeader(const std::string& file)
{
  vtkInternals& in = *this->Internals;
  in.File.clear();
  in.Reading = file;
  try
  {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
    {
      return this->Fail(vtkErrorCode::FileNotFoundError, "the file does not exist");
    }
    if (!std::filesystem::is_regular_file(file, ec))
    {
      return this->Fail(vtkErrorCode::CannotOpenFileError, "it is not a regular file");
    }

    // The image header (no pixels).
    auto input = OpenImage(file);
    if (!input)
    {
      return this->Fail(vtkErrorCode::UnrecognizedFileTypeError,
        "it cannot be opened as an image: not an image file, or corrupt or truncated "
        "(OpenImageIO: " +
          OIIO::geterror() + ")");
    }
    const OIIO::ImageSpec& spec = input->spec();
    const int width = spec.width, height = spec.height, channels = spec.nchannels;
    if (width <= 0 || height <= 0 || spec.depth > 1 || spec.deep || channels <= 0)
    {
      // OpenImageIO keeps sizes in int: a TIFF's uint32 size beyond 2^31 - 1 wraps around to
      // a negative number. Say the size the file declares.
      int64_t declaredWidth = width, declaredHeight = height;
      uint64_t w = 0, h = 0;
      if ((width <= 0 || height <= 0) && DeclaredTIFFSize(file, w, h))
      {
        declaredWidth = static_cast<int64_t>(w);
        declaredHeight = static_cast<int64_t>(h);
      }
      const std::string size = std::to_string(declaredWidth) + " x " +
        std::to_string(declaredHeight) + " x " + std::to_string(channels);
      const int64_t intMax = std::numeric_limits<int>::max();
      return this->Fail(vtkErrorCode::FileFormatError,
        declaredWidth > intMax || declaredHeight > intMax
          ? "its declared raster size (" + size + ") is beyond the " + std::to_string(intMax) +
            " pixels a side that VTK images (and OpenImageIO) can address"
          : "its raster size (" + size + ") is not a plain 2D image");
    }
    int scalarType = VTK_UNSIGNED_CHAR;
    if (channels == 1)
    {
      // Integer rasters in their native type: OpenImageIO's float conversion would
      // normalise them to [-1, 1].
      scalarType = vtkGlobeRasterSamples::ScalarTypeOf(spec.format);
      if (scalarType == 0)
      {
        return this->Fail(vtkErrorCode::FileFormatError,
          "its sample type (" + std::string(spec.format.c_str()) + ") is not supported");
      }
    }
    in.TileHeight = spec.tile_width > 0 ? std::max(spec.tile_height, 1) : 0;
    in.FirstX = spec.x;
    in.FirstY = spec.y;
    input->close();

    // Georeferencing: GeoTIFF tags, a world file, a .prj file, SetEPSG.
    TIFFInfo tiff;
    std::string why;
    if (!ReadGeoTIFF(file, tiff, why))
    {
      return this->Fail(vtkErrorCode::FileFormatError, why);
    }
    if (tiff.IsTIFF &&
      (tiff.Width != static_cast<uint64_t>(width) || tiff.Height != static_cast<uint64_t>(height)))
    {
      return this->Fail(vtkErrorCode::FileFormatError, "libtiff and OpenImageIO disagree on its size");
    }
    if (tiff.NoDataUnparsed)
    {
      vtkWarningMacro(<< "'" << file << "': the GDAL_NODATA tag is not a number; ignored");
    }
    const std::filesystem::path path(file);
    const std::vector<std::string> worldExts = WorldFileExtensions(path);
    const std::string world = FindSidecar(path, worldExts);
    Georeference geo;
    if (!world.empty())
    {
      if (!ReadWorldFile(world, geo.T, why))
      {
        return this->Fail(vtkErrorCode::FileFormatError, why);
      }
      if (tiff.HasGeoreference && !SameGrid(geo.T, tiff.Geo.T))
      {
        return this->Fail(vtkErrorCode::FileFormatError,
          "its georeferencing is contradictory: the world file '" + world + "' gives " +
            FormatTransform(geo.T) + ", its GeoTIFF tags give " + FormatTransform(tiff.Geo.T));
      }
    }
    if (tiff.HasGeoreference)
    {
      geo = tiff.Geo; // the tags are exact; an agreeing world file adds nothing
    }
    else if (world.empty())
    {
      std::string list;
      for (const std::string& e : worldExts)
      {
        list += (list.empty() ? "" : ", ") + e;
      }
      return this->Fail(vtkErrorCode::FileFormatError,
        (tiff.IsTIFF ? std::string("it has no GeoTIFF georeferencing (no ModelTiepoint + "
                                   "ModelPixelScale or ModelTransformation tag)")
                     : tiff.NotTIFFReason) +
          ", and no world file (" + list + ") next to it");
    }

    // The projection of a world file: .prj, SetEPSG, or WGS 84 if the numbers are degrees.
    const std::string prj = FindSidecar(path, { ".prj" });
    if (tiff.HasGeoreference && !prj.empty() && geo.EPSG != 0)
    {
      std::string text;
      const WKTInfo wkt = ReadText(prj, text) ? ParseWKT(text) : WKTInfo();
      if (wkt.EPSG != 0 && wkt.EPSG != geo.EPSG)
      {
        return this->Fail(vtkErrorCode::FileFormatError,
          "its georeferencing is contradictory: its projection file '" + prj + "' says EPSG:" +
            std::to_string(wkt.EPSG) + ", its GeoTIFF tags say EPSG:" + std::to_string(geo.EPSG));
      }
    }
    if (!tiff.HasGeoreference)
    {
      if (!prj.empty())
      {
        std::string text;
        if (!ReadText(prj, text))
        {
          return this->Fail(vtkErrorCode::CannotOpenFileError,
            "its projection file '" + prj + "' cannot be read");
        }
        const WKTInfo wkt = ParseWKT(text);
        geo.ModelType = WKTModelType(wkt.Keyword);
        if (geo.ModelType == 0)
        {
          // Not WKT: a PROJ string ("+proj=merc ...") that PROJ identifies will do.
          std::string definition = text;
          while (!definition.empty() && std::isspace(static_cast<unsigned char>(definition.back())))
          {
            definition.pop_back();
          }
          if (definition.rfind('+', 0) == 0 && definition.find("+type=crs") == std::string::npos)
          {
            definition += " +type=crs";
          }
          int confidence = 0;
          std::string name;
          bool projected = false;
          const int code = definition.rfind('+', 0) == 0
            ? IdentifyEPSG(definition, confidence, name, &projected)
            : 0;
          if (code == 0 && definition.rfind('+', 0) == 0 && IsProjectedCRS(definition))
          {
            // A projected CRS without an EPSG code (MODIS's sinusoidal grid): by definition.
            geo.ModelType = Projected;
            geo.CRS = definition;
            geo.EPSGFrom = "its projection file '" + prj + "' (a PROJ string matching no EPSG CRS)";
          }
          else if (code == 0)
          {
            return this->Fail(vtkErrorCode::FileFormatError,
              "its projection file '" + prj + "' is not a geographic or projected WKT CRS (" +
                (wkt.Keyword.empty() ? std::string("no WKT keyword") : wkt.Keyword) +
                "), nor a PROJ string PROJ identifies with an EPSG CRS");
          }
          else
          {
            geo.ModelType = projected ? Projected : Geographic;
            geo.EPSG = code;
            geo.EPSGFrom = "its projection file '" + prj +
              "' (a PROJ string PROJ identifies as EPSG:" + std::to_string(code) + ", " + name +
              ", " + std::to_string(confidence) + " %)";
          }
        }
        else
        {
          geo.EPSG = wkt.EPSG;
          geo.EPSGFrom = "its projection file '" + prj + "'";
        }
        if (geo.EPSG == 0 && geo.CRS.empty() && this->EPSG == 0 && geo.ModelType == Projected)
        {
          // A WKT without an authority (e.g. written from a PROJ string): PROJ may know it.
          int confidence = 0;
          std::string name;
          geo.EPSG = IdentifyEPSG(text, confidence, name);
          if (geo.EPSG == 0 && IsProjectedCRS(text))
          {
            geo.CRS = text;
            geo.EPSGFrom += " (a projected CRS matching no EPSG CRS)";
          }
          else if (geo.EPSG == 0)
          {
            return this->Fail(vtkErrorCode::FileFormatError,
              "its projection file '" + prj +
                "' names no EPSG authority for its projected CRS, and PROJ finds no EPSG CRS "
                "equivalent to it; give the code with SetEPSG");
          }
          else
          {
            geo.EPSGFrom += ", which PROJ identifies as EPSG:" + std::to_string(geo.EPSG) +
              " (" + name + ", " + std::to_string(confidence) + " %)";
          }
        }
        if (geo.ModelType == Geographic && wkt.UnitFactor > 0.0)
        {
          // Angular unit in radians per unit.
          const double degrees = wkt.UnitFactor * 180.0 / Pi;
          if (std::abs(degrees - 1.0) > 1e-9)
          {
            for (double& v : geo.T)
            {
              v *= degrees;
            }
          }
        }
        geo.Units = geo.ModelType == Geographic ? "degree" : wkt.UnitName;
        if (wkt.SemiMajor > 0.0)
        {
          geo.SemiMajor = wkt.SemiMajor;
          geo.SemiMinor = wkt.InverseFlattening > 0.0
            ? wkt.SemiMajor * (1.0 - 1.0 / wkt.InverseFlattening)
            : wkt.SemiMajor;
        }
        geo.Source = "world file + .prj";
      }
      else if (this->EPSG != 0)
      {
        geo.Source = "world file + SetEPSG";
      }
      else
      {
        double box[4], t[6];
        std::copy(geo.T, geo.T + 6, t);
        if (t[5] > 0.0)
        {
          t[3] += height * t[5];
          t[5] = -t[5];
        }
        BoxOf(t, width, height, box);
        if (t[1] < 0.0)
        {
          std::swap(box[0], box[1]);
        }
        if (!FitsDegrees(box, std::abs(t[1]), -t[5]))
        {
          return this->Fail(vtkErrorCode::FileFormatError,
            "its world file '" + world + "' has no projection (no .prj file, no SetEPSG) and its "
                                         "coordinates " +
              BoxText(box) + " are not degrees, so they cannot be taken as WGS 84");
        }
        geo.ModelType = Geographic;
        geo.EPSG = 4326;
        geo.Source = "world file, assumed WGS 84";
      }
    }

    // EPSG codes: the caller's must agree with the file's, and the model type with the code.
    if (this->EPSG != 0)
    {
      if (this->EPSG < 0)
      {
        return this->Fail(vtkErrorCode::UserError,
          "SetEPSG(" + std::to_string(this->EPSG) + ") is not an EPSG code");
      }
      if (geo.EPSG != 0 && geo.EPSG != this->EPSG)
      {
        return this->Fail(vtkErrorCode::FileFormatError,
          "its georeferencing is contradictory: the file says EPSG:" + std::to_string(geo.EPSG) +
            " (" + geo.Source + "), SetEPSG says EPSG:" + std::to_string(this->EPSG));
      }
      geo.EPSG = this->EPSG;
      geo.EPSGFrom = "SetEPSG";
    }
    if (geo.EPSG != 0)
    {
      const EPSGClass crs = ClassifyEPSG(geo.EPSG, geo.ModelType);
      if (crs.ModelType == 0 && geo.ModelType == 0)
      {
        return this->Fail(vtkErrorCode::UserError,
          "EPSG:" + std::to_string(geo.EPSG) +
            " is neither a geographic nor a projected CRS in PROJ's database");
      }
      if (crs.ModelType == 0)
      {
        // E.g. GeographicTypeGeoKey = 60000: not a code at all (32768 and up are private).
        return this->Fail(this->EPSG != 0 ? vtkErrorCode::UserError : vtkErrorCode::FileFormatError,
          "EPSG:" + std::to_string(geo.EPSG) + " (from " +
            (geo.EPSGFrom.empty() ? geo.Source : geo.EPSGFrom) +
            ") is neither a geographic nor a projected CRS in PROJ's database");
      }
      if (crs.ModelType != 0 && geo.ModelType != 0 && crs.ModelType != geo.ModelType)
      {
        return this->Fail(vtkErrorCode::FileFormatError,
          std::string("its georeferencing is contradictory: the model type is ") +
            ModelTypeName(geo.ModelType) + " (" + geo.Source + "), but EPSG:" +
            std::to_string(geo.EPSG) + " (" + crs.Name + ") is a " +
            ModelTypeName(crs.ModelType) + " CRS");
      }
      if (geo.ModelType == 0)
      {
        geo.ModelType = crs.ModelType;
      }
      if (geo.Units.empty())
      {
        geo.Units = crs.Units;
      }
    }
    if (geo.ModelType == Geographic)
    {
      geo.Units = "degree";
    }
    if (geo.Units.empty())
    {
      geo.Units = "unknown";
    }

    // North-up, west-to-east.
    double* t = geo.T;
    in.FlipRows = t[5] < 0.0;
    if (t[5] > 0.0)
    {
      t[3] += height * t[5];
      t[5] = -t[5];
    }
    in.FlipColumns = t[1] < 0.0;
    if (t[1] < 0.0)
    {
      t[0] += width * t[1];
      t[1] = -t[1];
    }
    // The far corner must be finite and apart from the near one (no zero-area extent).
    const double east = t[0] + width * t[1], south = t[3] + height * t[5];
    if (!std::isfinite(east) || !std::isfinite(south) || !(east > t[0]) || !(south < t[3]))
    {
      char text[300];
      std::snprintf(text, sizeof(text),
        "its extent is empty or not finite: %d x %d pixels of %.6g x %.6g from the corner "
        "(%.10g, %.10g) reach (%.10g, %.10g)",
        width, height, t[1], -t[5], t[0], t[3], east, south);
      return this->Fail(vtkErrorCode::FileFormatError, text);
    }
    if (geo.ModelType == Geographic)
    {
      double box[4];
      BoxOf(t, width, height, box);
      if (!FitsDegrees(box, t[1], -t[5]))
      {
        return this->Fail(vtkErrorCode::FileFormatError,
          "its geographic extent " + BoxText(box) + " is not a box in degrees");
      }
    }

    in.Width = width;
    in.Height = height;
    in.Channels = channels;
    in.ScalarType = scalarType;
    in.Geo = geo;
    in.HasNoData = tiff.HasNoData;
    in.NoData = tiff.NoData;
    in.StripsChecked = false;
    in.File = file;
  }
  catch (const std::exception& e)
  {
    // E.g. std::bad_alloc for a corrupt header, a filesystem error.
    const bool memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
    return this->Fail(vtkErrorCode::UnknownError, memory ? "not enough memory" : e.what());
  }
  return 1;
}

//------------------------------------------------------------------------------------------
int vtkGlobeRasterReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInternals& in = *this->Internals;
  in.LastError.clear();
  in.File.clear();
  in.InformationFailed = true;
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  const bool series = !in.Series.empty();
  if (!series && (!this->FileName || !*this->FileName))
  {
    in.LastError = "no FileName is set";
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    vtkErrorMacro(<< "Cannot read: no FileName is set");
    return 0;
  }
  // On failure, no stale output from an earlier success stays downstream.
  struct ClearOnFailure
  {
    vtkInternals& In;
    vtkImageData* Output;
    ~ClearOnFailure()
    {
      if (this->In.File.empty() && this->Output)
      {
        this->Output->Initialize();
      }
    }
  } clear{ in, vtkImageData::GetData(outputVector) };
  if (series)
  {
    // The time values: the files' own, or their positions in the series.
    const std::string why = in.OrderSteps(this->TimeFromFileNames);
    if (!why.empty())
    {
      in.Reading = in.Series.front().File;
      return this->Fail(vtkErrorCode::UserError, why);
    }
  }
  // A series' grid is its first step's; every other file must match it (RequestData).
  if (!this->ReadHeader(series ? in.Steps.front().File : std::string(this->FileName)))
  {
    return 0;
  }
  in.SeriesGrid = in.CurrentGrid();
  in.InformationFailed = false;
  if (in.Steps.size() > 1)
  {
    std::vector<double> times;
    for (const auto& step : in.Steps)
    {
      times.push_back(step.Time);
    }
    const double range[2] = { times.front(), times.back() };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(),
      static_cast<int>(times.size()));
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  // VTK orientation: the origin is the centre of the south-west pixel, y grows north.
  const double* t = in.Geo.T;
  const int extent[6] = { 0, in.Width - 1, 0, in.Height - 1, 0, 0 };
  const double spacing[3] = { t[1], -t[5], 1.0 };
  const double origin[3] = { t[0] + 0.5 * t[1], t[3] + in.Height * t[5] - 0.5 * t[5], 0.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  // RequestData reads any UPDATE_EXTENT (rows of the file only): the executive may split the
  // raster into pieces, one per MPI rank in pvbatch (Documentation/pipelines.md).
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, in.ScalarType, in.Channels);
  return 1;
}

//------------------------------------------------------------------------------------------
int vtkGlobeRasterReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInternals& in = *this->Internals;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (output)
  {
    output->Initialize();
  }
  if (in.InformationFailed)
  {
    return 0; // the executive asks for data after a failed RequestInformation: said already
  }
  in.LastError.clear();
  this->SetErrorCode(vtkErrorCode::NoError);
  // The file of the requested time: the last step at or before it (the first before them all).
  std::string wanted = this->FileName ? this->FileName : "";
  double dataTime = 0.0;
  const bool timed = in.Steps.size() > 1;
  if (!in.Series.empty())
  {
    size_t step = 0;
    if (timed && outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      const double time = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
      while (step + 1 < in.Steps.size() && in.Steps[step + 1].Time <= time)
      {
        ++step;
      }
    }
    wanted = in.Steps[step].File;
    dataTime = in.Steps[step].Time;
  }
  if (!output || wanted.empty())
  {
    in.Reading = wanted;
    return this->Fail(vtkErrorCode::UnknownError, "its header was not read (RequestInformation)");
  }
  if (in.File != wanted)
  {
    // Another file of the series: its header, which must describe the series' grid.
    if (!this->ReadHeader(wanted))
    {
      return 0;
    }
    const std::string mismatch = in.SeriesGrid.Mismatch(in.CurrentGrid());
    if (!mismatch.empty())
    {
      return this->Fail(vtkErrorCode::FileFormatError,
        "it does not match the first step of its series ('" + in.Steps.front().File +
          "'): " + mismatch);
    }
  }
  const std::string file = in.File;
  int ue[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), ue);
  ue[0] = std::max(ue[0], 0);
  ue[1] = std::min(ue[1], in.Width - 1);
  ue[2] = std::max(ue[2], 0);
  ue[3] = std::min(ue[3], in.Height - 1);
  ue[4] = ue[5] = 0;
  const double* t = in.Geo.T;
  output->Initialize();
  if (timed)
  {
    // The step's own time, so that a request for it again finds the data up to date.
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), dataTime);
  }
  if (ue[0] > ue[1] || ue[2] > ue[3])
  {
    return 1; // an empty request
  }
  if (timed && in.Kept && in.KeptFile == file && std::equal(ue, ue + 6, in.KeptExtent) &&
    in.KeptTime == this->GetMTime())
  {
    // Another time within the step last read (VTK's executive asks again for any new time):
    // the same arrays, nothing decoded.
    output->ShallowCopy(in.Kept);
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), dataTime);
    return 1;
  }
  in.Kept = nullptr;
  try
  {
    // File rows [r0, r1) hold VTK rows ue[2]..ue[3].
    const int r0 = in.FlipRows ? in.Height - 1 - ue[3] : ue[2];
    const int r1 = (in.FlipRows ? in.Height - 1 - ue[2] : ue[3]) + 1;
    // Chunks of about a twentieth of the request, whole tile rows for tiled files.
    const int align = in.TileHeight > 0 ? in.TileHeight : 1;
    int chunk = std::max((r1 - r0 + 19) / 20, 1);
    chunk = (chunk + align - 1) / align * align;
    const OIIO::TypeDesc type =
      in.Channels == 1 ? vtkGlobeRasterSamples::ReadTypeOf(in.ScalarType) : OIIO::TypeDesc(OIIO::TypeDesc::UINT8);
    const size_t pixelBytes = type.size() * static_cast<size_t>(in.Channels);
    const size_t rowBytes = pixelBytes * static_cast<size_t>(in.Width);
    const int outWidth = ue[1] - ue[0] + 1;
    const int outHeight = ue[3] - ue[2] + 1;

    // Strips and tiles shorter than their pixels, or beyond the end of the file (libtiff would
    // read past them silently for a single uncompressed strip).
    const std::string truncated = in.StripsChecked ? std::string() : CheckStoredStrips(file);
    if (!truncated.empty())
    {
      return this->Fail(vtkErrorCode::PrematureEndOfFileError,
        "its pixels cannot be decoded; the file is corrupt or truncated: " + truncated);
    }
    in.StripsChecked = true;

    // The memory budget, before anything is allocated: a header of a few hundred bytes can
    // declare 30000 x 30000 floats. In double: no overflow.
    const double MiB = 1024.0 * 1024.0;
    const double outBytes = static_cast<double>(pixelBytes) * outWidth * outHeight;
    const double bufferBytes = static_cast<double>(rowBytes) * std::min(chunk, in.Height);
    if (outBytes + bufferBytes > this->MaximumMemory * MiB)
    {
      const bool whole = outWidth == in.Width && outHeight == in.Height;
      char text[700];
      std::snprintf(text, sizeof(text),
        "%s %d x %d x %d %s%s needs %.0f MiB (%.0f MiB of pixels, %.0f bytes, and a %.0f MiB "
        "read buffer), more than the reader's MaximumMemory (%d MiB) allows; raise it with "
        "SetMaximumMemory (for a vtkGlobeLayer: GetFileReader()->SetMaximumMemory) where the "
        "machine has the memory; rasters this large are better tiled or downsampled (see "
        "\"Preparing large rasters\" in the user guide)",
        whole ? "its declared size," : "its update extent,", outWidth, outHeight, in.Channels,
        vtkImageScalarTypeNameMacro(in.ScalarType),
        whole
          ? ","
          : (" (of " + std::to_string(in.Width) + " x " + std::to_string(in.Height) + "),").c_str(),
        std::ceil((outBytes + bufferBytes) / MiB), std::round(outBytes / MiB), outBytes,
        std::ceil(bufferBytes / MiB), this->MaximumMemory);
      return this->Fail(vtkErrorCode::UserError, text);
    }

    output->SetExtent(ue);
    output->SetSpacing(t[1], -t[5], 1.0);
    output->SetOrigin(t[0] + 0.5 * t[1], t[3] + in.Height * t[5] - 0.5 * t[5], 0.0);
    output->AllocateScalars(in.ScalarType, in.Channels);
    vtkDataArray* scalars = output->GetPointData()->GetScalars();
    scalars->SetName(in.Channels == 1 ? "Values" : "Colors");

    auto input = OpenImage(file);
    if (!input)
    {
      return this->Fail(vtkErrorCode::CannotOpenFileError,
        "it cannot be opened as an image any more (OpenImageIO: " + OIIO::geterror() + ")");
    }
    unsigned char* out = static_cast<unsigned char*>(scalars->GetVoidPointer(0));
    // Strips already in the wanted type are read as stored: OpenImageIO's converting
    // read_scanlines allocates a buffer of 64 MiB on every call, whatever the rows asked for
    // (20 calls for a 16-row raster; seconds under AddressSanitizer, found by the fuzzer).
    const OIIO::ImageSpec& stored = input->spec();
    const bool native = in.TileHeight <= 0 && stored.format == type &&
      stored.channelformats.empty() && stored.nchannels == in.Channels;
    std::vector<unsigned char> buffer;
    this->UpdateProgress(0.0);
    for (int start = r0 / align * align; start < r1; start += chunk)
    {
      const int end = std::min(start + chunk, in.Height);
      buffer.resize(rowBytes * static_cast<size_t>(end - start));
      const bool read = in.TileHeight > 0
        ? input->read_tiles(0, 0, in.FirstX, in.FirstX + in.Width, in.FirstY + start,
            in.FirstY + end, 0, 1, 0, in.Channels, type, buffer.data())
        : native
        ? input->read_native_scanlines(0, 0, in.FirstY + start, in.FirstY + end, 0, buffer.data())
        : input->read_scanlines(
            0, 0, in.FirstY + start, in.FirstY + end, 0, 0, in.Channels, type, buffer.data());
      if (!read)
      {
        std::string error = input->geterror();
        if (error.empty())
        {
          error = OIIO::geterror();
        }
        output->Initialize();
        return this->Fail(vtkErrorCode::PrematureEndOfFileError,
          "its pixels cannot be decoded; the file is corrupt or truncated (OpenImageIO: " + error +
            ")");
      }
      for (int r = std::max(start, r0); r < std::min(end, r1); ++r)
      {
        const int row = (in.FlipRows ? in.Height - 1 - r : r) - ue[2];
        const unsigned char* src = buffer.data() + rowBytes * static_cast<size_t>(r - start);
        unsigned char* dst = out + pixelBytes * static_cast<size_t>(outWidth) * row;
        if (!in.FlipColumns)
        {
          std::memcpy(dst, src + pixelBytes * ue[0], pixelBytes * outWidth);
        }
        else
        {
          for (int c = 0; c < outWidth; ++c)
          {
            std::memcpy(
              dst + pixelBytes * c, src + pixelBytes * (in.Width - 1 - (ue[0] + c)), pixelBytes);
          }
        }
      }
      this->UpdateProgress(static_cast<double>(std::min(end, r1) - r0) / (r1 - r0));
      if (this->GetAbortExecute())
      {
        output->Initialize();
        return this->Fail(vtkErrorCode::UserError, "reading was aborted (AbortExecute)");
      }
    }
    input->close();
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    const bool memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
    return this->Fail(vtkErrorCode::UnknownError, memory ? "not enough memory" : e.what());
  }

  // The georeferencing.
  const Georeference& geo = in.Geo;
  vtkFieldData* fd = output->GetFieldData();
  const auto addInt = [fd](const char* name, int value)
  {
    vtkNew<vtkIntArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  const auto addDoubles = [fd](const char* name, std::initializer_list<double> values)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    for (double v : values)
    {
      a->InsertNextValue(v);
    }
    fd->AddArray(a);
  };
  const auto addString = [fd](const char* name, const std::string& value)
  {
    vtkNew<vtkStringArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  addInt(GetModelTypeArrayName(), geo.ModelType);
  addInt(GetEPSGArrayName(), geo.EPSG);
  if (geo.EPSG == 0 && !geo.CRS.empty())
  {
    addString(GetCRSDefinitionArrayName(), geo.CRS);
  }
  addDoubles(GetGeoTransformArrayName(), { t[0], t[3], t[1], -t[5] });
  if (geo.ModelType == Geographic)
  {
    double box[4];
    BoxOf(t, in.Width, in.Height, box);
    addDoubles(GetGeographicExtentArrayName(), { box[0], box[1], box[2], box[3] });
  }
  if (in.HasNoData)
  {
    addDoubles(GetNoDataValueArrayName(), { in.NoData });
  }
  addString(GetUnitsArrayName(), geo.Units);
  if (geo.SemiMajor > 0.0)
  {
    addDoubles(GetDatumSemiAxesArrayName(), { geo.SemiMajor, geo.SemiMinor });
  }
  addString(GetFileNameArrayName(), file);
  addString(GetGeoreferenceSourceArrayName(), geo.Source);
  {
    // For readers of the file's own pixels (vtkGlobePageSource reads it through a cache).
    vtkNew<vtkIntArray> a;
    a->SetName(GetStorageOrientationArrayName());
    a->InsertNextValue(in.FlipColumns ? 1 : 0);
    a->InsertNextValue(in.FlipRows ? 0 : 1);
    fd->AddArray(a);
  }
  if (timed)
  {
    in.Kept = vtkSmartPointer<vtkImageData>::New();
    in.Kept->ShallowCopy(output);
    in.KeptFile = file;
    std::copy(ue, ue + 6, in.KeptExtent);
    in.KeptTime = this->GetMTime();
  }
  return 1;
}

//------------------------------------------------------------------------------------------
void vtkGlobeRasterReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const vtkInternals& in = *this->Internals;
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "TimeFromFileNames: " << (this->TimeFromFileNames ? "On" : "Off") << "\n";
  os << indent << "FileNames: " << in.Series.size() << (in.Series.empty() ? "\n" : ":\n");
  for (const auto& step : in.Series)
  {
    os << indent.GetNextIndent() << step.File;
    if (step.Timed)
    {
      os << " (time " << step.Time << ")";
    }
    os << "\n";
  }
  os << indent << "EPSG: " << this->EPSG << "\n";
  os << indent << "MaximumMemory: " << this->MaximumMemory << " MiB\n";
  os << indent << "LastError: " << (in.LastError.empty() ? "(none)" : in.LastError) << "\n";
  if (!in.File.empty())
  {
    const std::streamsize precision = os.precision(12);
    os << indent << "Raster: " << in.Width << " x " << in.Height << " x " << in.Channels << " "
       << vtkImageScalarTypeNameMacro(in.ScalarType) << "\n";
    os << indent << "ModelType: " << ModelTypeName(in.Geo.ModelType) << ", EPSG:" << in.Geo.EPSG
       << " (" << in.Geo.Source << ")\n";
    os << indent << "NorthWestCorner: " << in.Geo.T[0] << ", " << in.Geo.T[3] << "\n";
    os << indent << "PixelSize: " << in.Geo.T[1] << ", " << -in.Geo.T[5] << " " << in.Geo.Units
       << "\n";
    os.precision(precision);
  }
}
