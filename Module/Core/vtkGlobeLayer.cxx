#include "vtkGlobeLayer.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <OpenImageIO/imageio.h>

#include <geotiff.h>
#include <geovalues.h>
#include <tiffio.h>
#include <xtiffio.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <mutex>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkGlobeLayer);

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr float NaNf = std::numeric_limits<float>::quiet_NaN();

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

/// Parses GDAL's nodata text ("-32768", "nan", "-3.4028234663852886e+38"), locale-free.
bool ParseNoData(const char* text, double& value)
{
  std::string s(text);
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
      return 180.0 / 3.14159265358979323846;
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

/// What libgeotiff tells about a file.
struct GeoInfo
{
  int ModelType = 0; // vtkGlobeLayer::ModelTypes
  int EPSG = 0;
  bool PixelIsPoint = false;
  // GDAL-style affine transform: x = t0 + col t1 + row t2, y = t3 + col t4 + row t5, in the
  // model's units (degrees after conversion for Geographic), for the outer pixel corner.
  double T[6] = { 0, 0, 0, 0, 0, 0 };
  double SemiMajor = 0.0;
  double SemiMinor = 0.0;
  bool HasNoData = false;
  double NoData = 0.0;
  bool NoDataUnparsed = false;
  int Width = 0;
  int Height = 0;
};

/// Reads the georeferencing and the nodata tag. False with the reason in `why`.
bool ReadGeoTIFF(const std::string& fileName, GeoInfo& info, std::string& why)
{
  RegisterTIFFTags();
  std::string tiffError;
  TIFF* tif = OpenTIFF(fileName, &tiffError);
  if (!tif)
  {
    why = "it is not a TIFF file, so it has no GeoTIFF georeferencing";
    if (!tiffError.empty())
    {
      why += " (libtiff: " + tiffError + ")";
    }
    return false;
  }
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
  info.Width = static_cast<int>(std::min<uint32_t>(w, std::numeric_limits<int>::max()));
  info.Height = static_cast<int>(std::min<uint32_t>(h, std::numeric_limits<int>::max()));

  char* noDataText = nullptr;
  if (TIFFGetField(tif, GDALNoDataTag, &noDataText) && noDataText)
  {
    info.HasNoData = ParseNoData(noDataText, info.NoData);
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
  double* t = info.T;
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
    why = "it has no GeoTIFF georeferencing (no ModelTiepoint + ModelPixelScale or "
          "ModelTransformation tag)";
    return false;
  }

  closer.Gtif = GTIFNew(tif);
  GTIF* gtif = closer.Gtif;
  if (!gtif)
  {
    why = "its GeoTIFF keys cannot be read";
    return false;
  }
  unsigned short code = 0;
  if (GTIFKeyGet(gtif, GTModelTypeGeoKey, &code, 0, 1) != 1)
  {
    why = "it has no GTModelTypeGeoKey, so it is not known whether it is geographic or "
          "projected";
    return false;
  }
  if (code == ModelTypeGeographic)
  {
    info.ModelType = vtkGlobeLayer::Geographic;
  }
  else if (code == ModelTypeProjected)
  {
    info.ModelType = vtkGlobeLayer::Projected;
  }
  else
  {
    why = "its model type (GTModelTypeGeoKey = " + std::to_string(code) +
      ") is neither geographic nor projected";
    return false;
  }
  if (GTIFKeyGet(gtif, GTRasterTypeGeoKey, &code, 0, 1) == 1)
  {
    info.PixelIsPoint = (code == RasterPixelIsPoint);
  }
  const geokey_t epsgKey =
    info.ModelType == vtkGlobeLayer::Geographic ? GeographicTypeGeoKey : ProjectedCSTypeGeoKey;
  if (GTIFKeyGet(gtif, epsgKey, &code, 0, 1) == 1 && code != KvUserDefined)
  {
    info.EPSG = code;
  }

  // The datum's ellipsoid, only when the file spells it out (a user-defined body).
  double a = 0.0, b = 0.0, inverseFlattening = 0.0;
  if (GTIFKeyGet(gtif, GeogSemiMajorAxisGeoKey, &a, 0, 1) == 1 && a > 0.0)
  {
    info.SemiMajor = a;
    if (GTIFKeyGet(gtif, GeogSemiMinorAxisGeoKey, &b, 0, 1) == 1 && b > 0.0)
    {
      info.SemiMinor = b;
    }
    else if (GTIFKeyGet(gtif, GeogInvFlatteningGeoKey, &inverseFlattening, 0, 1) == 1)
    {
      // An inverse flattening of 0 denotes a sphere.
      info.SemiMinor = inverseFlattening != 0.0 ? a * (1.0 - 1.0 / inverseFlattening) : a;
    }
  }

  if (info.ModelType == vtkGlobeLayer::Geographic)
  {
    // Geographic coordinates are in GeogAngularUnits (degrees unless said otherwise).
    double degrees = 1.0;
    double unitSize = 0.0; // radians per unit
    const bool hasSize = GTIFKeyGet(gtif, GeogAngularUnitSizeGeoKey, &unitSize, 0, 1) == 1;
    if (GTIFKeyGet(gtif, GeogAngularUnitsGeoKey, &code, 0, 1) == 1 && code != KvUserDefined)
    {
      degrees = DegreesPerAngularUnit(code);
      if (degrees == 0.0)
      {
        why = "its angular unit (GeogAngularUnitsGeoKey = " + std::to_string(code) +
          ") is not supported";
        return false;
      }
    }
    else if (hasSize && unitSize > 0.0)
    {
      degrees = unitSize * 180.0 / 3.14159265358979323846;
    }
    for (double& v : info.T)
    {
      v *= degrees;
    }
  }
  if (info.PixelIsPoint)
  {
    // The transform is for pixel centres: move it to the outer pixel corner.
    t[0] -= 0.5 * (t[1] + t[2]);
    t[3] -= 0.5 * (t[4] + t[5]);
  }
  for (double v : info.T)
  {
    if (!std::isfinite(v))
    {
      why = "its GeoTIFF transform is not finite";
      return false;
    }
  }
  if (t[2] != 0.0 || t[4] != 0.0)
  {
    why = "it is rotated or sheared (ModelTransformation with off-diagonal terms), which is "
          "not supported";
    return false;
  }
  if (t[1] == 0.0 || t[5] == 0.0)
  {
    why = "its pixel size is zero";
    return false;
  }
  return true;
}

/// Reverses the row order (south-up -> north-up) of a row-major raster.
template <typename T>
void FlipRows(std::vector<T>& v, int width, int height, int components)
{
  const size_t row = static_cast<size_t>(width) * components;
  for (int r = 0; r < height / 2; ++r)
  {
    std::swap_ranges(
      v.begin() + r * row, v.begin() + (r + 1) * row, v.begin() + (height - 1 - r) * row);
  }
}

/// Reverses the column order (east-to-west storage) of a row-major raster.
template <typename T>
void FlipColumns(std::vector<T>& v, int width, int height, int components)
{
  for (int r = 0; r < height; ++r)
  {
    for (int c = 0; c < width / 2; ++c)
    {
      const size_t a = (static_cast<size_t>(r) * width + c) * components;
      const size_t b = (static_cast<size_t>(r) * width + (width - 1 - c)) * components;
      std::swap_ranges(v.begin() + a, v.begin() + a + components, v.begin() + b);
    }
  }
}

/// The nodata value in a raster's sample type, when it is one of its values.
template <typename T>
bool NoDataAs(double noData, T& value)
{
  if constexpr (std::is_integral_v<T>)
  {
    // Out-of-range or fractional values cannot occur in the raster (and the cast would be
    // undefined).
    if (!(noData == std::floor(noData)) ||
      noData < static_cast<double>(std::numeric_limits<T>::lowest()) ||
      noData > static_cast<double>(std::numeric_limits<T>::max()))
    {
      return false;
    }
    value = static_cast<T>(noData);
    return true;
  }
  else
  {
    if (std::isnan(noData))
    {
      return false; // NaN samples are voids anyway
    }
    const double max = static_cast<double>(std::numeric_limits<T>::max());
    if (std::isfinite(noData) && std::abs(noData) > max)
    {
      // Text that rounds just past the largest float (e.g. "3.40282347e+38") means it.
      if (std::abs(noData) > max * (1.0 + 1e-7))
      {
        return false;
      }
      noData = std::copysign(max, noData);
    }
    value = static_cast<T>(noData);
    return true;
  }
}

/// Converts native samples to float, turning nodata samples into NaN (the void marker).
template <typename T>
void SamplesToFloat(const std::vector<unsigned char>& bytes, size_t n, bool hasNoData,
  double noData, std::vector<float>& out)
{
  const T* raw = reinterpret_cast<const T*>(bytes.data());
  // Compare in the raster's own type: the nodata text may round (e.g. float -3.4e38).
  T nd{};
  const bool useNoData = hasNoData && NoDataAs(noData, nd);
  out.resize(n);
  for (size_t i = 0; i < n; ++i)
  {
    out[i] = (useNoData && raw[i] == nd) ? NaNf : static_cast<float>(raw[i]);
  }
}

/**
 * Push-pull void fill (Gortler et al., "The Lumigraph", 1996): NaN entries of a row-major
 * width x height raster are replaced; valid entries are not touched.
 *
 * Pull: each coarser level halves the raster; a coarse cell is known when any of its (up
 * to) 2 x 2 children is known, and takes their mean. Levels are added until one is fully
 * known. Push: from the coarsest level down, every unknown cell takes the bilinear
 * interpolation of the (now complete) next-coarser level at its centre. Each filled value is
 * thus a convex combination of valid values: no overshoot, no pit, and a constant field is
 * reproduced exactly. Requires at least one valid entry.
 */
void PushPullFill(std::vector<float>& values, int width, int height)
{
  struct Level
  {
    int W, H;
    std::vector<float> V;
    std::vector<unsigned char> Known;
  };
  std::vector<Level> levels(1);
  levels[0].W = width;
  levels[0].H = height;
  levels[0].V.swap(values);
  levels[0].Known.resize(levels[0].V.size());
  bool complete = true;
  for (size_t i = 0; i < levels[0].V.size(); ++i)
  {
    levels[0].Known[i] = !std::isnan(levels[0].V[i]);
    complete = complete && levels[0].Known[i];
  }

  // Pull.
  while (!complete && (levels.back().W > 1 || levels.back().H > 1))
  {
    const Level& fine = levels.back();
    Level coarse;
    coarse.W = (fine.W + 1) / 2;
    coarse.H = (fine.H + 1) / 2;
    coarse.V.assign(static_cast<size_t>(coarse.W) * coarse.H, 0.0f);
    coarse.Known.assign(coarse.V.size(), 0);
    complete = true;
    for (int j = 0; j < coarse.H; ++j)
    {
      for (int i = 0; i < coarse.W; ++i)
      {
        double sum = 0.0;
        int n = 0;
        for (int y = 2 * j; y < std::min(2 * j + 2, fine.H); ++y)
        {
          for (int x = 2 * i; x < std::min(2 * i + 2, fine.W); ++x)
          {
            const size_t k = static_cast<size_t>(y) * fine.W + x;
            if (fine.Known[k])
            {
              sum += fine.V[k];
              ++n;
            }
          }
        }
        const size_t c = static_cast<size_t>(j) * coarse.W + i;
        if (n > 0)
        {
          coarse.V[c] = static_cast<float>(sum / n);
          coarse.Known[c] = 1;
        }
        else
        {
          complete = false;
        }
      }
    }
    levels.push_back(std::move(coarse));
  }

  // Push: fine cell centre x maps to coarse coordinate (x - 0.5) / 2.
  for (int k = static_cast<int>(levels.size()) - 2; k >= 0; --k)
  {
    Level& fine = levels[k];
    const Level& coarse = levels[k + 1];
    for (int j = 0; j < fine.H; ++j)
    {
      const double v = std::clamp(0.5 * j - 0.25, 0.0, coarse.H - 1.0);
      const int j0 = std::min(static_cast<int>(v), std::max(coarse.H - 2, 0));
      const int j1 = std::min(j0 + 1, coarse.H - 1);
      const double fv = v - j0;
      for (int i = 0; i < fine.W; ++i)
      {
        const size_t f = static_cast<size_t>(j) * fine.W + i;
        if (fine.Known[f])
        {
          continue;
        }
        const double u = std::clamp(0.5 * i - 0.25, 0.0, coarse.W - 1.0);
        const int i0 = std::min(static_cast<int>(u), std::max(coarse.W - 2, 0));
        const int i1 = std::min(i0 + 1, coarse.W - 1);
        const double fu = u - i0;
        const auto at = [&coarse](int x, int y)
        { return static_cast<double>(coarse.V[static_cast<size_t>(y) * coarse.W + x]); };
        fine.V[f] = static_cast<float>((1.0 - fv) * ((1.0 - fu) * at(i0, j0) + fu * at(i1, j0)) +
          fv * ((1.0 - fu) * at(i0, j1) + fu * at(i1, j1)));
      }
    }
  }
  values.swap(levels[0].V);
}

/// Checks an in-memory geographic pixel-edge box.
bool CheckExtent(double west, double east, double south, double north, std::string& why)
{
  char text[256];
  std::snprintf(text, sizeof(text), "the extent (west %g, east %g, south %g, north %g) ", west,
    east, south, north);
  why = text;
  if (!std::isfinite(west) || !std::isfinite(east) || !std::isfinite(south) ||
    !std::isfinite(north))
  {
    why += "is not finite";
    return false;
  }
  if (!(west < east))
  {
    why += "needs west < east";
    return false;
  }
  if (!(south < north))
  {
    why += "needs south < north";
    return false;
  }
  if (south < -90.0 || north > 90.0)
  {
    why += "has a latitude beyond +-90 degrees";
    return false;
  }
  if (east - west > 360.0 * (1.0 + 1e-12))
  {
    why += "spans more than 360 degrees of longitude";
    return false;
  }
  why.clear();
  return true;
}

bool SameDouble(double a, double b)
{
  return a == b || (std::isnan(a) && std::isnan(b));
}
} // namespace

//------------------------------------------------------------------------------------------
class vtkGlobeLayer::vtkInternals
{
public:
  /// Everything a load depends on; Update() re-loads only when this changed.
  struct Settings
  {
    bool Loaded = false;
    std::string FileName;
    // The file's size and modification time: a file rewritten in place is re-read by the
    // next Update() after a Modified().
    std::uintmax_t FileSize = 0;
    long long FileTime = 0;
    unsigned long MemoryGeneration = 0;
    int Role = 0;
    double ValueScale = 1.0;
    double ValueOffset = 0.0;
    bool NoDataOverridden = false;
    bool HasNoData = false;
    double NoData = 0.0;
    bool FillVoids = true;

    bool operator==(const Settings& o) const
    {
      return this->Loaded == o.Loaded && this->FileName == o.FileName &&
        this->FileSize == o.FileSize && this->FileTime == o.FileTime &&
        this->MemoryGeneration == o.MemoryGeneration && this->Role == o.Role &&
        this->ValueScale == o.ValueScale && this->ValueOffset == o.ValueOffset &&
        this->NoDataOverridden == o.NoDataOverridden && this->HasNoData == o.HasNoData &&
        SameDouble(this->NoData, o.NoData) && this->FillVoids == o.FillVoids;
    }
  };

  Settings LastLoad;
  vtkTimeStamp LoadTime;

  // In-memory source (SetHeightData / SetColorData).
  bool HasMemoryData = false;
  unsigned long MemoryGeneration = 0;
  int MemoryRole = Height;
  int MemoryWidth = 0;
  int MemoryHeight = 0;
  int MemoryComponents = 0;
  std::vector<float> MemoryHeights;
  std::vector<unsigned char> MemoryColors;
  double MemoryExtent[4] = { 0, 0, 0, 0 };

  // Results.
  vtkSmartPointer<vtkDataArray> Data;
  double Extent[4] = { NaN, NaN, NaN, NaN };
  double Origin[2] = { NaN, NaN };
  double PixelSize[2] = { NaN, NaN };
  std::string DefaultName;

  void ClearMemory()
  {
    this->HasMemoryData = false;
    std::vector<float>().swap(this->MemoryHeights);
    std::vector<unsigned char>().swap(this->MemoryColors);
  }
};

//------------------------------------------------------------------------------------------
vtkGlobeLayer::vtkGlobeLayer()
  : Internals(new vtkInternals)
{
}

vtkGlobeLayer::~vtkGlobeLayer()
{
  this->SetFileName(nullptr);
  this->SetName(nullptr);
}

//------------------------------------------------------------------------------------------
const char* vtkGlobeLayer::GetRoleAsString()
{
  switch (this->Role)
  {
    case Color:
      return "Color";
    case NormalMap:
      return "NormalMap";
    case Overlay:
      return "Overlay";
    case Mask:
      return "Mask";
    case NightLights:
      return "NightLights";
    default:
      return "Height";
  }
}

const char* vtkGlobeLayer::GetBlendModeAsString()
{
  switch (this->BlendMode)
  {
    case Add:
      return "Add";
    case Average:
      return "Average";
    default:
      return "Replace";
  }
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::SetFileName(const char* fileName)
{
  if ((!fileName && !this->FileName) ||
    (fileName && this->FileName && std::strcmp(fileName, this->FileName) == 0))
  {
    return;
  }
  delete[] this->FileName;
  this->FileName = nullptr;
  this->Internals->DefaultName.clear();
  if (fileName)
  {
    const size_t n = std::strlen(fileName) + 1;
    this->FileName = new char[n];
    std::memcpy(this->FileName, fileName, n);
    this->Internals->DefaultName = std::filesystem::path(fileName).stem().string();
    // A file replaces in-memory data.
    this->Internals->ClearMemory();
  }
  this->Modified();
}

//------------------------------------------------------------------------------------------
const char* vtkGlobeLayer::GetName()
{
  return this->Name ? this->Name : this->Internals->DefaultName.c_str();
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::SetNoDataValue(double value)
{
  if (this->NoDataValueOverridden && this->HasNoDataValue && SameDouble(value, this->NoDataValue))
  {
    return;
  }
  this->NoDataValue = value;
  this->HasNoDataValue = true;
  this->NoDataValueOverridden = true;
  this->Modified();
}

void vtkGlobeLayer::SetHasNoDataValue(bool has)
{
  if (this->NoDataValueOverridden && this->HasNoDataValue == has)
  {
    return;
  }
  this->HasNoDataValue = has;
  this->NoDataValueOverridden = true;
  this->Modified();
}

void vtkGlobeLayer::UseFileNoDataValue()
{
  if (this->NoDataValueOverridden)
  {
    this->NoDataValueOverridden = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------------------
vtkDataArray* vtkGlobeLayer::GetData()
{
  return this->Valid ? this->Internals->Data.Get() : nullptr;
}

void vtkGlobeLayer::GetGeographicExtent(double extent[4])
{
  const bool geographic = this->Valid && this->ModelType == Geographic;
  for (int i = 0; i < 4; ++i)
  {
    extent[i] = geographic ? this->Internals->Extent[i] : NaN;
  }
}

void vtkGlobeLayer::GetProjectedGeoTransform(double origin[2], double pixelSize[2])
{
  for (int i = 0; i < 2; ++i)
  {
    origin[i] = this->Valid ? this->Internals->Origin[i] : NaN;
    pixelSize[i] = this->Valid ? this->Internals->PixelSize[i] : NaN;
  }
}

bool vtkGlobeLayer::IsGlobal()
{
  const double* e = this->Internals->Extent;
  // Tolerate rounding in the pixel size (e.g. 360 / 2048 written with 15 digits).
  return this->Valid && this->ModelType == Geographic && e[1] - e[0] >= 360.0 - 1e-7;
}

double vtkGlobeLayer::GetDegreesPerPixel(int axis)
{
  if (!this->Valid || this->ModelType != Geographic || axis < 0 || axis > 1)
  {
    return NaN;
  }
  return this->Internals->PixelSize[axis];
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::Invalidate()
{
  vtkInternals& in = *this->Internals;
  this->Valid = false;
  in.Data = nullptr;
  this->RasterWidth = this->RasterHeight = this->NumberOfComponents = 0;
  this->NumberOfVoids = 0;
  this->ModelType = this->EPSG = 0;
  this->DatumSemiMajorAxis = this->DatumSemiMinorAxis = 0.0;
  this->MinimumValue = this->MaximumValue = 0.0;
  std::fill(in.Extent, in.Extent + 4, NaN);
  std::fill(in.Origin, in.Origin + 2, NaN);
  std::fill(in.PixelSize, in.PixelSize + 2, NaN);
  in.LastLoad = vtkInternals::Settings();
  if (!this->NoDataValueOverridden)
  {
    this->HasNoDataValue = false;
    this->NoDataValue = 0.0;
  }
}

//------------------------------------------------------------------------------------------
bool vtkGlobeLayer::Update()
{
  vtkInternals& in = *this->Internals;
  if (this->Valid && this->GetMTime() <= in.LoadTime.GetMTime())
  {
    return true; // nothing modified since the last load
  }
  vtkInternals::Settings now;
  now.Loaded = true;
  now.FileName = this->FileName ? this->FileName : "";
  now.MemoryGeneration = in.HasMemoryData ? in.MemoryGeneration : 0;
  if (!in.HasMemoryData && !now.FileName.empty())
  {
    std::error_code ec;
    now.FileSize = std::filesystem::file_size(now.FileName, ec);
    const auto time = std::filesystem::last_write_time(now.FileName, ec);
    now.FileTime = ec ? 0 : static_cast<long long>(time.time_since_epoch().count());
  }
  now.Role = this->IsImageRole() ? Color : Height; // images load alike whatever their role
  now.ValueScale = this->ValueScale;
  now.ValueOffset = this->ValueOffset;
  now.NoDataOverridden = this->NoDataValueOverridden;
  now.HasNoData = this->NoDataValueOverridden && this->HasNoDataValue;
  now.NoData = now.HasNoData ? this->NoDataValue : 0.0;
  now.FillVoids = this->FillVoids;
  if (this->Valid && now == in.LastLoad)
  {
    in.LoadTime.Modified(); // only e.g. the Name changed: nothing to re-read
    return true;
  }

  ++this->NumberOfLoads;
  this->Invalidate();
  bool ok = false;
  try
  {
    ok = this->Load();
  }
  catch (const std::exception& e)
  {
    // E.g. std::bad_alloc for a corrupt header that claims a gigantic raster.
    const std::string what = now.FileName.empty() ? "in-memory data" : "'" + now.FileName + "'";
    const bool memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
    vtkErrorMacro(<< "Cannot load " << what << ": "
                  << (memory ? std::string("not enough memory") : std::string(e.what())));
    ok = false;
  }
  if (!ok)
  {
    this->Invalidate();
    return false;
  }
  this->Valid = true;
  in.LastLoad = now;
  in.LoadTime.Modified();
  return true;
}

bool vtkGlobeLayer::Load()
{
  if (this->Role == Height &&
    (!std::isfinite(this->ValueScale) || !std::isfinite(this->ValueOffset)))
  {
    vtkErrorMacro(<< "Cannot load '" << (this->FileName ? this->FileName : "in-memory data")
                  << "': ValueScale and ValueOffset must be finite (" << this->ValueScale << ", "
                  << this->ValueOffset << ")");
    return false;
  }
  if (this->Internals->HasMemoryData)
  {
    return this->LoadMemory();
  }
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "Nothing to load: no FileName is set and no in-memory data was given");
    return false;
  }
  return this->LoadFile();
}

//------------------------------------------------------------------------------------------
namespace
{
/// The common end of loading heights: scale/offset, voids, range, fill. `values` holds raw
/// values with NaN for voids. Returns false (with `why`) when no post is valid.
bool FinishHeights(std::vector<float>& values, int width, int height, double scale, double offset,
  bool fill, vtkIdType& voids, double& minimum, double& maximum, std::string& why,
  vtkSmartPointer<vtkDataArray>& data)
{
  voids = 0;
  minimum = std::numeric_limits<double>::infinity();
  maximum = -minimum;
  for (float& v : values)
  {
    if (!std::isfinite(v))
    {
      v = NaNf; // +-Inf are voids too
      ++voids;
      continue;
    }
    v = static_cast<float>(v * scale + offset);
    minimum = std::min(minimum, static_cast<double>(v));
    maximum = std::max(maximum, static_cast<double>(v));
  }
  if (voids == static_cast<vtkIdType>(values.size()))
  {
    why = "it has no valid height: all " + std::to_string(voids) + " posts are nodata or NaN";
    return false;
  }
  if (fill && voids > 0)
  {
    PushPullFill(values, width, height);
  }
  vtkNew<vtkFloatArray> array;
  array->SetName("Height");
  array->SetNumberOfComponents(1);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  data = array;
  return true;
}

/// The common end of loading colour: RGB(A) -> RGBA, nodata pixels transparent.
void FinishColors(const std::vector<unsigned char>& pixels, size_t n, int components,
  bool hasNoData, double noData, vtkIdType& voids, vtkSmartPointer<vtkDataArray>& data)
{
  vtkNew<vtkUnsignedCharArray> array;
  array->SetName("Color");
  array->SetNumberOfComponents(4);
  array->SetNumberOfTuples(static_cast<vtkIdType>(n));
  unsigned char* out = array->GetPointer(0);
  // Nodata applies only when it is a possible 8-bit value.
  const bool useNoData =
    hasNoData && noData >= 0.0 && noData <= 255.0 && noData == std::floor(noData);
  const unsigned char nd = useNoData ? static_cast<unsigned char>(noData) : 0;
  voids = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const unsigned char* p = pixels.data() + i * components;
    out[4 * i + 0] = p[0];
    out[4 * i + 1] = p[1];
    out[4 * i + 2] = p[2];
    out[4 * i + 3] = components == 4 ? p[3] : 255;
    // As GDAL's per-dataset nodata mask: a pixel is missing when all its bands are nodata.
    if (useNoData && p[0] == nd && p[1] == nd && p[2] == nd)
    {
      out[4 * i + 3] = 0;
      ++voids;
    }
  }
  data = array;
}
} // namespace

//------------------------------------------------------------------------------------------
bool vtkGlobeLayer::LoadFile()
{
  vtkInternals& in = *this->Internals;
  const std::string file = this->FileName;
  const auto fail = [this, &file](const std::string& why)
  {
    vtkErrorMacro(<< "Cannot load '" << file << "': " << why);
    return false;
  };

  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
  {
    return fail("the file does not exist");
  }
  if (!std::filesystem::is_regular_file(file, ec))
  {
    return fail("it is not a regular file");
  }

  // Pixels: OpenImageIO.
  // Keep colour with an alpha channel as stored (straight alpha, as GeoTIFF writers mean
  // it): by default OpenImageIO premultiplies unassociated alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(file, &config);
  if (!input)
  {
    return fail("it cannot be opened as an image: not an image file, or corrupt or truncated "
                "(OpenImageIO: " +
      OIIO::geterror() + ")");
  }
  const OIIO::ImageSpec spec = input->spec();
  const int width = spec.width;
  const int height = spec.height;
  const int channels = spec.nchannels;
  if (width <= 0 || height <= 0 || spec.depth > 1 || spec.deep)
  {
    return fail("its raster size (" + std::to_string(width) + " x " + std::to_string(height) +
      ") is not a plain 2D image");
  }
  if (this->Role == Height && channels != 1)
  {
    return fail("a Height layer needs a 1-channel raster, and it has " + std::to_string(channels) +
      " channels");
  }
  if (this->Role != Height && channels != 3 && channels != 4)
  {
    return fail(std::string("a ") + this->GetRoleAsString() + " layer needs a 3-channel (RGB) or 4-channel (RGBA) raster, and it has " +
      std::to_string(channels) + " channel" + (channels == 1 ? "" : "s"));
  }

  // Georeferencing and nodata: libgeotiff (before decoding, which may be long).
  GeoInfo geo;
  std::string why;
  if (!ReadGeoTIFF(file, geo, why))
  {
    return fail(why);
  }
  if (geo.Width != width || geo.Height != height)
  {
    return fail("libtiff and OpenImageIO disagree on its size");
  }
  if (geo.NoDataUnparsed)
  {
    vtkWarningMacro(<< "'" << file << "': the GDAL_NODATA tag is not a number; ignored");
  }

  // Decode. Integer heights in their native type: OpenImageIO's float conversion would
  // normalise them to [-1, 1].
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  std::vector<float> heights;
  std::vector<unsigned char> pixels;
  if (!this->NoDataValueOverridden)
  {
    this->HasNoDataValue = geo.HasNoData;
    this->NoDataValue = geo.HasNoData ? geo.NoData : 0.0;
  }
  const bool hasNoData = this->HasNoDataValue;
  const double noData = this->NoDataValue;
  bool read = false;
  if (this->Role == Height)
  {
    OIIO::TypeDesc type = spec.format;
    switch (type.basetype)
    {
      case OIIO::TypeDesc::UINT8:
      case OIIO::TypeDesc::INT8:
      case OIIO::TypeDesc::UINT16:
      case OIIO::TypeDesc::INT16:
      case OIIO::TypeDesc::UINT32:
      case OIIO::TypeDesc::INT32:
      case OIIO::TypeDesc::FLOAT:
      case OIIO::TypeDesc::DOUBLE:
        break;
      case OIIO::TypeDesc::HALF:
        type = OIIO::TypeDesc::FLOAT; // exact widening, no rescaling
        break;
      default:
        return fail("its sample type (" + std::string(spec.format.c_str()) +
          ") is not supported for heights");
    }
    std::vector<unsigned char> bytes(n * type.size());
    read = input->read_image(0, 0, 0, 1, type, bytes.data());
    if (read)
    {
      switch (type.basetype)
      {
        case OIIO::TypeDesc::UINT8:
          SamplesToFloat<uint8_t>(bytes, n, hasNoData, noData, heights);
          break;
        case OIIO::TypeDesc::INT8:
          SamplesToFloat<int8_t>(bytes, n, hasNoData, noData, heights);
          break;
        case OIIO::TypeDesc::UINT16:
          SamplesToFloat<uint16_t>(bytes, n, hasNoData, noData, heights);
          break;
        case OIIO::TypeDesc::INT16:
          SamplesToFloat<int16_t>(bytes, n, hasNoData, noData, heights);
          break;
        case OIIO::TypeDesc::UINT32:
          SamplesToFloat<uint32_t>(bytes, n, hasNoData, noData, heights);
          break;
        case OIIO::TypeDesc::INT32:
          SamplesToFloat<int32_t>(bytes, n, hasNoData, noData, heights);
          break;
        case OIIO::TypeDesc::FLOAT:
          SamplesToFloat<float>(bytes, n, hasNoData, noData, heights);
          break;
        default:
          SamplesToFloat<double>(bytes, n, hasNoData, noData, heights);
          break;
      }
    }
  }
  else
  {
    pixels.resize(n * channels);
    read = input->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data());
  }
  if (!read)
  {
    std::string error = input->geterror();
    if (error.empty())
    {
      error = OIIO::geterror();
    }
    return fail("its pixels cannot be decoded; the file is corrupt or truncated (OpenImageIO: " +
      error + ")");
  }
  input->close();

  // Store north-up and west-to-east, so row 0 is the north row.
  double* t = geo.T;
  if (t[5] > 0.0)
  {
    t[3] += height * t[5];
    t[5] = -t[5];
    if (this->Role == Height)
    {
      FlipRows(heights, width, height, 1);
    }
    else
    {
      FlipRows(pixels, width, height, channels);
    }
  }
  if (t[1] < 0.0)
  {
    t[0] += width * t[1];
    t[1] = -t[1];
    if (this->Role == Height)
    {
      FlipColumns(heights, width, height, 1);
    }
    else
    {
      FlipColumns(pixels, width, height, channels);
    }
  }
  in.Origin[0] = t[0];
  in.Origin[1] = t[3];
  in.PixelSize[0] = t[1];
  in.PixelSize[1] = -t[5];
  if (geo.ModelType == Geographic)
  {
    const double west = t[0], east = t[0] + width * t[1];
    const double north = t[3], south = t[3] + height * t[5];
    // Points-registered global grids reach half a pixel beyond the poles and the date line;
    // more than a pixel means the coordinates are not degrees.
    if (south < -90.0 - in.PixelSize[1] || north > 90.0 + in.PixelSize[1] ||
      east - west > 360.0 + in.PixelSize[0])
    {
      char text[200];
      std::snprintf(text, sizeof(text),
        "its geographic extent (west %g, east %g, south %g, north %g) is not a box in degrees",
        west, east, south, north);
      return fail(text);
    }
    in.Extent[0] = west;
    in.Extent[1] = east;
    in.Extent[2] = south;
    in.Extent[3] = north;
  }

  if (this->Role == Height)
  {
    if (!FinishHeights(heights, width, height, this->ValueScale, this->ValueOffset, this->FillVoids,
          this->NumberOfVoids, this->MinimumValue, this->MaximumValue, why, in.Data))
    {
      return fail(why);
    }
    this->NumberOfComponents = 1;
  }
  else
  {
    FinishColors(pixels, n, channels, hasNoData, noData, this->NumberOfVoids, in.Data);
    this->NumberOfComponents = 4;
  }
  this->RasterWidth = width;
  this->RasterHeight = height;
  this->ModelType = geo.ModelType;
  this->EPSG = geo.EPSG;
  this->DatumSemiMajorAxis = geo.SemiMajor;
  this->DatumSemiMinorAxis = geo.SemiMinor;
  return true;
}

//------------------------------------------------------------------------------------------
bool vtkGlobeLayer::LoadMemory()
{
  vtkInternals& in = *this->Internals;
  const char* what = in.MemoryRole == Height ? "in-memory height data" : "in-memory color data";
  if ((in.MemoryRole == Height) != (this->Role == Height))
  {
    vtkErrorMacro(<< "Cannot load " << what << " as a " << this->GetRoleAsString()
                  << " layer: the role does not match the data");
    return false;
  }
  const int width = in.MemoryWidth;
  const int height = in.MemoryHeight;
  const size_t n = static_cast<size_t>(width) * height;
  const bool hasNoData = this->NoDataValueOverridden && this->HasNoDataValue;
  if (!this->NoDataValueOverridden)
  {
    this->HasNoDataValue = false;
    this->NoDataValue = 0.0;
  }
  if (this->Role == Height)
  {
    std::vector<float> heights(in.MemoryHeights);
    float nd = 0.0f;
    if (hasNoData && NoDataAs(this->NoDataValue, nd))
    {
      std::replace(heights.begin(), heights.end(), nd, NaNf);
    }
    std::string why;
    if (!FinishHeights(heights, width, height, this->ValueScale, this->ValueOffset, this->FillVoids,
          this->NumberOfVoids, this->MinimumValue, this->MaximumValue, why, in.Data))
    {
      vtkErrorMacro(<< "Cannot load " << what << ": " << why);
      return false;
    }
    this->NumberOfComponents = 1;
  }
  else
  {
    FinishColors(in.MemoryColors, n, in.MemoryComponents, hasNoData, this->NoDataValue,
      this->NumberOfVoids, in.Data);
    this->NumberOfComponents = 4;
  }
  this->RasterWidth = width;
  this->RasterHeight = height;
  this->ModelType = Geographic;
  this->EPSG = 0;
  std::copy(in.MemoryExtent, in.MemoryExtent + 4, in.Extent);
  in.Origin[0] = in.Extent[0];
  in.Origin[1] = in.Extent[3];
  in.PixelSize[0] = (in.Extent[1] - in.Extent[0]) / width;
  in.PixelSize[1] = (in.Extent[3] - in.Extent[2]) / height;
  return true;
}

//------------------------------------------------------------------------------------------
namespace
{
bool CheckMemoryInput(int width, int height, const void* values, std::string& why)
{
  if (width <= 0 || height <= 0)
  {
    why =
      "the size (" + std::to_string(width) + " x " + std::to_string(height) + ") must be positive";
    return false;
  }
  if (!values)
  {
    why = "no values were given";
    return false;
  }
  return true;
}
} // namespace

void vtkGlobeLayer::SetHeightData(
  int width, int height, const float* values, double west, double east, double south, double north)
{
  vtkInternals& in = *this->Internals;
  // In-memory data replaces the file.
  this->SetFileName(nullptr);
  in.ClearMemory();
  ++in.MemoryGeneration;
  this->Invalidate();
  this->Modified();
  std::string why;
  if (!CheckMemoryInput(width, height, values, why) || !CheckExtent(west, east, south, north, why))
  {
    vtkErrorMacro(<< "SetHeightData: rejected in-memory height data: " << why);
    return;
  }
  in.MemoryRole = Height;
  in.MemoryWidth = width;
  in.MemoryHeight = height;
  in.MemoryComponents = 1;
  in.MemoryHeights.assign(values, values + static_cast<size_t>(width) * height);
  const double extent[4] = { west, east, south, north };
  std::copy(extent, extent + 4, in.MemoryExtent);
  in.HasMemoryData = true;
  this->SetRole(Height);
  this->Update();
}

void vtkGlobeLayer::SetColorData(int width, int height, int components, const unsigned char* values,
  double west, double east, double south, double north)
{
  vtkInternals& in = *this->Internals;
  this->SetFileName(nullptr);
  in.ClearMemory();
  ++in.MemoryGeneration;
  this->Invalidate();
  this->Modified();
  std::string why;
  if (!CheckMemoryInput(width, height, values, why) || !CheckExtent(west, east, south, north, why))
  {
    vtkErrorMacro(<< "SetColorData: rejected in-memory color data: " << why);
    return;
  }
  if (components != 3 && components != 4)
  {
    vtkErrorMacro(<< "SetColorData: rejected in-memory color data: " << components
                  << " components per pixel; 3 (RGB) or 4 (RGBA) are needed");
    return;
  }
  in.MemoryRole = Color;
  in.MemoryWidth = width;
  in.MemoryHeight = height;
  in.MemoryComponents = components;
  in.MemoryColors.assign(values, values + static_cast<size_t>(width) * height * components);
  const double extent[4] = { west, east, south, north };
  std::copy(extent, extent + 4, in.MemoryExtent);
  in.HasMemoryData = true;
  this->SetRole(Color);
  this->Update();
}

//------------------------------------------------------------------------------------------
void vtkGlobeLayer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const vtkInternals& in = *this->Internals;
  os << indent << "Name: " << this->GetName() << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent
     << "Source: " << (in.HasMemoryData ? "in-memory data" : (this->FileName ? "file" : "(none)"))
     << "\n";
  os << indent << "Role: " << this->GetRoleAsString() << "\n";
  os << indent << "ValueScale: " << this->ValueScale << "\n";
  os << indent << "ValueOffset: " << this->ValueOffset << "\n";
  os << indent << "NoDataValue: ";
  if (this->HasNoDataValue)
  {
    os << this->NoDataValue;
  }
  else
  {
    os << "(none)";
  }
  os << (this->NoDataValueOverridden ? " (set by the user)" : " (from the file)") << "\n";
  os << indent << "FillVoids: " << (this->FillVoids ? "On" : "Off") << "\n";
  os << indent << "Enabled: " << (this->Enabled ? "On" : "Off") << "\n";
  os << indent << "DrawOrder: " << this->DrawOrder << "\n";
  os << indent << "Opacity: " << this->Opacity << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "ValidRange: " << this->ValidRange[0] << " .. " << this->ValidRange[1] << "\n";
  os << indent << "BlendMode: " << this->GetBlendModeAsString() << "\n";
  os << indent << "FeatherWidth: " << this->FeatherWidth << "\n";
  os << indent << "ProjectionQualityWeight: " << (this->ProjectionQualityWeight ? "On" : "Off")
     << " (limit " << this->ProjectionQualityLimit << ")\n";
  os << indent << "Interpolation: " << (this->Interpolation == Nearest ? "Nearest" : "Linear")
     << "\n";
  os << indent << "Valid: " << (this->Valid ? "yes" : "no") << "\n";
  os << indent << "NumberOfLoads: " << this->NumberOfLoads << "\n";
  if (!this->Valid)
  {
    return;
  }
  const std::streamsize precision = os.precision(12);
  os << indent << "Size: " << this->RasterWidth << " x " << this->RasterHeight << " x "
     << this->NumberOfComponents << "\n";
  os << indent << "ModelType: "
     << (this->ModelType == Geographic ? "Geographic"
                                       : (this->ModelType == Projected ? "Projected" : "unknown"))
     << "\n";
  os << indent << "EPSG: " << this->EPSG << "\n";
  if (this->ModelType == Geographic)
  {
    os << indent << "GeographicExtent: " << in.Extent[0] << ", " << in.Extent[1] << ", "
       << in.Extent[2] << ", " << in.Extent[3] << (this->IsGlobal() ? " (global)" : "") << "\n";
  }
  os << indent << "Origin: " << in.Origin[0] << ", " << in.Origin[1] << "\n";
  os << indent << "PixelSize: " << in.PixelSize[0] << ", " << in.PixelSize[1] << "\n";
  os << indent << "DatumSemiAxes: " << this->DatumSemiMajorAxis << ", " << this->DatumSemiMinorAxis
     << "\n";
  os << indent << "NumberOfVoids: " << this->NumberOfVoids << "\n";
  if (this->Role == Height)
  {
    os << indent << "Range: " << this->MinimumValue << " .. " << this->MaximumValue << "\n";
  }
  os.precision(precision);
}
