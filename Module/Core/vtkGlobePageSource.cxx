#include "vtkGlobePageSource.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkGlobeMapProjection.h"
#include "vtkFloatArray.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeRasterSamples.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <OpenImageIO/imagecache.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkGlobePageSource);

namespace
{
constexpr float NaNf = std::numeric_limits<float>::quiet_NaN();

// The largest coarsest file level that synthesised levels are averaged from (texels).
constexpr double MaxSynthesisTexels = 4096.0 * 4096.0;

/// Everything an opened source knows. Immutable once built, shared with running reads.
struct State
{
  std::string File;
  std::shared_ptr<OIIO::ImageCache> Cache;
  OIIO::ustring Name;
  int Width = 0;
  int Height = 0;
  int FileChannels = 1;
  bool Heights = true;
  int ScalarType = VTK_UNSIGNED_CHAR; // of the samples read (heights: the file's own)
  OIIO::TypeDesc ReadType;
  int ModelType = 0;
  int EPSG = 0;
  double Geo[4] = { 0, 0, 0, 0 };
  bool HasNoData = false;
  double NoData = 0.0;
  // Nodata as a sample of the file's type holds it (compared with converted samples); false
  // when no sample can be nodata.
  bool NoDataUsable = false;
  double NoDataSample = 0.0;
  bool Global = false;
  bool FlipRows = false;
  bool FlipColumns = false;
  int PageSize = 256;
  int Border = 1;
  std::vector<std::array<int, 4>> Levels; // width, height, data-window x, y
  int FileLevels = 0;
  // Levels >= FileLevels, averaged here (north-up): floats or RGBA bytes.
  std::vector<std::vector<float>> MemoryHeights;
  std::vector<std::vector<unsigned char>> MemoryColors;

  int Components() const { return this->Heights ? 1 : 4; }

  /// Converts n texels of the file's read type at `in` (FileChannels each) into page values.
  void Convert(const unsigned char* in, size_t n, float* heights, unsigned char* rgba) const
  {
    const size_t bytes = this->ReadType.size() * this->FileChannels;
    for (size_t i = 0; i < n; ++i, in += bytes)
    {
      if (this->Heights)
      {
        const double v = vtkGlobeRasterSamples::ToDouble(in, this->ScalarType);
        heights[i] = (std::isnan(v) || (this->NoDataUsable && v == this->NoDataSample))
          ? NaNf
          : static_cast<float>(v);
        continue;
      }
      unsigned char* o = rgba + 4 * i;
      const int colours = this->FileChannels >= 3 ? 3 : 1;
      if (colours == 3)
      {
        o[0] = in[0];
        o[1] = in[1];
        o[2] = in[2];
      }
      else
      {
        o[0] = o[1] = o[2] = in[0];
      }
      const bool hasAlpha = this->FileChannels == 2 || this->FileChannels >= 4;
      o[3] = hasAlpha ? in[colours] : 255;
      if (this->NoDataUsable)
      {
        bool all = true;
        for (int k = 0; k < colours; ++k)
        {
          all = all && static_cast<double>(in[k]) == this->NoDataSample;
        }
        if (all)
        {
          o[3] = 0;
        }
      }
    }
  }
};

/// Level L+1 from level L (north-up page values): 2 x 2 averages, nodata-aware for heights.
void Reduce(const State& s, int w, int h, const std::vector<float>& heights,
  const std::vector<unsigned char>& rgba, int nw, int nh, std::vector<float>& outHeights,
  std::vector<unsigned char>& outRGBA)
{
  if (s.Heights)
  {
    outHeights.assign(static_cast<size_t>(nw) * nh, NaNf);
  }
  else
  {
    outRGBA.assign(static_cast<size_t>(nw) * nh * 4, 0);
  }
  for (int j = 0; j < nh; ++j)
  {
    const int r0 = std::min(2 * j, h - 1), r1 = std::min(2 * j + 1, h - 1);
    for (int i = 0; i < nw; ++i)
    {
      const int c0 = std::min(2 * i, w - 1), c1 = std::min(2 * i + 1, w - 1);
      const size_t idx[4] = { static_cast<size_t>(r0) * w + c0, static_cast<size_t>(r0) * w + c1,
        static_cast<size_t>(r1) * w + c0, static_cast<size_t>(r1) * w + c1 };
      const size_t o = static_cast<size_t>(j) * nw + i;
      if (s.Heights)
      {
        double sum = 0.0;
        int count = 0;
        for (size_t k : idx)
        {
          if (!std::isnan(heights[k]))
          {
            sum += heights[k];
            ++count;
          }
        }
        outHeights[o] = count ? static_cast<float>(sum / count) : NaNf;
      }
      else
      {
        for (int c = 0; c < 4; ++c)
        {
          const int sum =
            rgba[4 * idx[0] + c] + rgba[4 * idx[1] + c] + rgba[4 * idx[2] + c] + rgba[4 * idx[3] + c];
          outRGBA[4 * o + c] = static_cast<unsigned char>((sum + 2) / 4);
        }
      }
    }
  }
}
} // namespace

//------------------------------------------------------------------------------------------
namespace
{
/// Builds the state for `file`; "" on success, else the reason.
std::string Build(const std::string& file, int pageSize, int border, double cacheMB, State& s)
{
  s.File = file;
  s.PageSize = pageSize;
  s.Border = border;

  // Georeferencing, nodata, size and type: vtkGlobeRasterReader's header and one row.
  vtkNew<vtkGlobeRasterReader> reader;
  reader->SetFileName(file.c_str());
  // The reader's own messages (and its executive's) are swallowed: this class reports the
  // reason, GetLastError(), once, naming the file.
  vtkNew<vtkCallbackCommand> quiet;
  quiet->SetCallback([](vtkObject*, unsigned long, void*, void*) {});
  reader->AddObserver(vtkCommand::ErrorEvent, quiet);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
  reader->UpdateInformation();
  if (*reader->GetLastError())
  {
    return reader->GetLastError();
  }
  vtkInformation* info = reader->GetOutputInformation(0);
  int whole[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  s.Width = whole[1] - whole[0] + 1;
  s.Height = whole[3] - whole[2] + 1;
  // The north row, first column: the reader reads only the rows asked for.
  int extent[6] = { 0, 0, s.Height - 1, s.Height - 1, 0, 0 };
  reader->UpdateExtent(extent);
  vtkImageData* image = reader->GetOutput();
  if (*reader->GetLastError() || !image)
  {
    return *reader->GetLastError() ? reader->GetLastError() : "its first row cannot be read";
  }
  vtkFieldData* fd = image->GetFieldData();
  const auto number = [fd](const char* name, int i) -> double
  {
    vtkDataArray* a = vtkArrayDownCast<vtkDataArray>(fd->GetAbstractArray(name));
    return a && i < a->GetNumberOfValues()
      ? a->GetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents())
      : std::numeric_limits<double>::quiet_NaN();
  };
  s.ModelType = static_cast<int>(number(vtkGlobeRasterReader::GetModelTypeArrayName(), 0));
  s.EPSG = static_cast<int>(number(vtkGlobeRasterReader::GetEPSGArrayName(), 0));
  for (int i = 0; i < 4; ++i)
  {
    s.Geo[i] = number(vtkGlobeRasterReader::GetGeoTransformArrayName(), i);
  }
  if (!std::isfinite(s.Geo[0]) || !std::isfinite(s.Geo[1]) || !(s.Geo[2] > 0) || !(s.Geo[3] > 0))
  {
    return "it has no usable georeferencing";
  }
  s.HasNoData = fd->GetAbstractArray(vtkGlobeRasterReader::GetNoDataValueArrayName()) != nullptr;
  s.NoData = s.HasNoData ? number(vtkGlobeRasterReader::GetNoDataValueArrayName(), 0) : 0.0;
  s.Global = vtkGlobeMapProjection::IsGlobalRaster(
    s.ModelType == vtkGlobeRasterReader::Geographic, s.EPSG, s.Geo[2], s.Width);
  s.FlipColumns = number(vtkGlobeRasterReader::GetStorageOrientationArrayName(), 0) == 1;
  s.FlipRows = number(vtkGlobeRasterReader::GetStorageOrientationArrayName(), 1) == 1;

  // A private ImageCache: its own memory limit and statistics.
  s.Cache = std::shared_ptr<OIIO::ImageCache>(
    OIIO::ImageCache::create(false), [](OIIO::ImageCache* c) { OIIO::ImageCache::destroy(c); });
  if (!s.Cache)
  {
    return "an OpenImageIO ImageCache cannot be created";
  }
  OIIO::ImageCache& cache = *s.Cache;
  cache.attribute("max_memory_MB", static_cast<float>(cacheMB));
  cache.attribute("autotile", 256);       // untiled files are cached in 256 x 256 tiles ...
  cache.attribute("automip", 1);          // ... with MIP levels made on demand
  cache.attribute("unassociatedalpha", 1); // straight alpha, as vtkGlobeRasterReader reads it
  cache.attribute("max_open_files", 16);
  s.Name = OIIO::ustring(file);
  OIIO::ImageSpec spec;
  if (!cache.get_imagespec(s.Name, spec, 0, 0))
  {
    return "OpenImageIO's ImageCache cannot open it (" + cache.geterror() + ")";
  }
  if (spec.width != s.Width || spec.height != s.Height)
  {
    return "OpenImageIO and vtkGlobeRasterReader disagree on its size";
  }
  s.FileChannels = spec.nchannels;
  s.Heights = spec.nchannels == 1;
  if (s.Heights)
  {
    // Native samples, as vtkGlobeRasterReader reads them.
    s.ScalarType = vtkGlobeRasterSamples::ScalarTypeOf(spec.format);
    if (s.ScalarType == 0)
    {
      return std::string("its sample type (") + spec.format.c_str() + ") is not supported";
    }
    s.ReadType = vtkGlobeRasterSamples::ReadTypeOf(s.ScalarType);
  }
  else
  {
    s.FileChannels = std::min(spec.nchannels, 4);
    s.ReadType = OIIO::TypeDesc::UINT8;
  }
  s.NoDataUsable = s.HasNoData &&
    vtkGlobeRasterSamples::NoDataSample(
      s.NoData, s.Heights ? s.ScalarType : VTK_UNSIGNED_CHAR, s.NoDataSample);

  // The levels the file (or automip) provides, up to the first that fits in one page.
  int mipLevels = 1;
  cache.get_image_info(s.Name, 0, 0, OIIO::ustring("miplevels"), OIIO::TypeInt, &mipLevels);
  for (int level = 0; level < std::max(mipLevels, 1); ++level)
  {
    OIIO::ImageSpec ls;
    if (!cache.get_imagespec(s.Name, ls, 0, level))
    {
      return "its level " + std::to_string(level) + " cannot be read (" + cache.geterror() + ")";
    }
    s.Levels.push_back({ ls.width, ls.height, ls.x, ls.y });
    if (ls.width <= pageSize && ls.height <= pageSize)
    {
      break;
    }
    // A file without levels of its own (no "Plain Texture" tag: OpenImageIO's automip would
    // make them, blind to nodata, so voids of -32768 turn into deep pits): when its full
    // resolution fits in memory, the levels are averaged here, nodata-aware, instead.
    if (level == 0 && spec.get_string_attribute("textureformat").empty() &&
      static_cast<double>(ls.width) * ls.height <= MaxSynthesisTexels)
    {
      break;
    }
  }
  s.FileLevels = static_cast<int>(s.Levels.size());

  // A chain that stops before one page: average the rest here from the coarsest file level.
  const std::array<int, 4> last = s.Levels.back();
  if (last[0] > pageSize || last[1] > pageSize)
  {
    if (static_cast<double>(last[0]) * last[1] > MaxSynthesisTexels)
    {
      return "its coarsest level (" + std::to_string(last[0]) + " x " + std::to_string(last[1]) +
        ") does not fit in one page of " + std::to_string(pageSize) +
        " and is too large to reduce in memory; prepare the file with GlobePrepare "
        "(vtkGlobeRasterPreparer)";
    }
    const int w = last[0], h = last[1];
    const size_t n = static_cast<size_t>(w) * h;
    std::vector<unsigned char> raw(n * s.ReadType.size() * s.FileChannels);
    if (!cache.get_pixels(s.Name, 0, s.FileLevels - 1, last[2], last[2] + w, last[3],
          last[3] + h, 0, 1, 0, s.FileChannels, s.ReadType, raw.data()))
    {
      return "its level " + std::to_string(s.FileLevels - 1) + " cannot be read (" +
        cache.geterror() + ")";
    }
    std::vector<float> heights(s.Heights ? n : 0), flippedHeights;
    std::vector<unsigned char> rgba(s.Heights ? 0 : 4 * n), flippedRGBA;
    s.Convert(raw.data(), n, heights.data(), rgba.data());
    raw.clear();
    raw.shrink_to_fit();
    // North-up, west-to-east.
    if (s.FlipRows || s.FlipColumns)
    {
      flippedHeights = heights;
      flippedRGBA = rgba;
      for (int j = 0; j < h; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          const size_t from = static_cast<size_t>(s.FlipRows ? h - 1 - j : j) * w +
            (s.FlipColumns ? w - 1 - i : i);
          const size_t to = static_cast<size_t>(j) * w + i;
          if (s.Heights)
          {
            flippedHeights[to] = heights[from];
          }
          else
          {
            std::memcpy(&flippedRGBA[4 * to], &rgba[4 * from], 4);
          }
        }
      }
      heights.swap(flippedHeights);
      rgba.swap(flippedRGBA);
    }
    int cw = w, ch = h;
    while (cw > pageSize || ch > pageSize)
    {
      const int nw = std::max(1, cw / 2), nh = std::max(1, ch / 2);
      std::vector<float> nextHeights;
      std::vector<unsigned char> nextRGBA;
      Reduce(s, cw, ch, heights, rgba, nw, nh, nextHeights, nextRGBA);
      s.Levels.push_back({ nw, nh, 0, 0 });
      s.MemoryHeights.push_back(nextHeights);
      s.MemoryColors.push_back(nextRGBA);
      heights.swap(nextHeights);
      rgba.swap(nextRGBA);
      cw = nw;
      ch = nh;
    }
  }
  return std::string();
}
} // namespace

//------------------------------------------------------------------------------------------
class vtkGlobePageSource::vtkInternals
{
public:
  std::mutex Mutex;
  std::shared_ptr<const State> Current;
  vtkMTimeType BuiltAt = 0;
  vtkMTimeType FailedAt = 0;
  std::string FailReason;
  std::atomic<vtkTypeInt64> PagesRead{ 0 };

  /// The current state, (re)built when FileName or a setting changed since it was built;
  /// nullptr (reported once per failure) when the file cannot be opened.
  std::shared_ptr<const State> Acquire(vtkGlobePageSource* self)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    const vtkMTimeType now = self->GetMTime();
    if (this->Current && this->BuiltAt >= now)
    {
      return this->Current;
    }
    if (!this->Current && this->FailedAt >= now && this->FailedAt != 0)
    {
      return nullptr;
    }
    this->Current.reset();
    this->FailReason.clear();
    auto state = std::make_shared<State>();
    const std::string file = self->FileName ? self->FileName : "";
    std::string why;
    if (file.empty())
    {
      why = "no FileName is set";
    }
    else
    {
      try
      {
        why = Build(file, self->PageSize, self->Border, self->CacheMemory, *state);
      }
      catch (const std::exception& e)
      {
        why = dynamic_cast<const std::bad_alloc*>(&e) ? "not enough memory" : e.what();
      }
    }
    if (!why.empty())
    {
      this->FailedAt = now;
      this->FailReason = why;
      vtkErrorWithObjectMacro(self, << "Cannot open '" << file << "' as pages: " << why);
      return nullptr;
    }
    this->Current = state;
    this->BuiltAt = now;
    return this->Current;
  }
};

//------------------------------------------------------------------------------------------
vtkGlobePageSource::vtkGlobePageSource()
  : Internals(new vtkInternals)
{
}

vtkGlobePageSource::~vtkGlobePageSource()
{
  this->SetFileName(nullptr);
}

bool vtkGlobePageSource::Open()
{
  return this->Internals->Acquire(this) != nullptr;
}

int vtkGlobePageSource::GetNumberOfColumns()
{
  auto s = this->Internals->Acquire(this);
  return s ? s->Width : 0;
}

int vtkGlobePageSource::GetNumberOfRows()
{
  auto s = this->Internals->Acquire(this);
  return s ? s->Height : 0;
}

int vtkGlobePageSource::GetNumberOfComponents()
{
  auto s = this->Internals->Acquire(this);
  return s ? s->Components() : 0;
}

int vtkGlobePageSource::GetPageDataType()
{
  auto s = this->Internals->Acquire(this);
  return s ? (s->Heights ? VTK_FLOAT : VTK_UNSIGNED_CHAR) : 0;
}

int vtkGlobePageSource::GetModelType()
{
  auto s = this->Internals->Acquire(this);
  return s ? s->ModelType : 0;
}

int vtkGlobePageSource::GetEPSG()
{
  auto s = this->Internals->Acquire(this);
  return s ? s->EPSG : 0;
}

bool vtkGlobePageSource::GetHasNoDataValue()
{
  auto s = this->Internals->Acquire(this);
  return s && s->HasNoData;
}

double vtkGlobePageSource::GetNoDataValue()
{
  auto s = this->Internals->Acquire(this);
  return s ? s->NoData : 0.0;
}

bool vtkGlobePageSource::IsGlobal()
{
  auto s = this->Internals->Acquire(this);
  return s && s->Global;
}

bool vtkGlobePageSource::GetGeoTransform(double transform[4])
{
  auto s = this->Internals->Acquire(this);
  for (int i = 0; i < 4; ++i)
  {
    transform[i] = s ? s->Geo[i] : std::numeric_limits<double>::quiet_NaN();
  }
  return s != nullptr;
}

int vtkGlobePageSource::GetNumberOfLevels()
{
  auto s = this->Internals->Acquire(this);
  return s ? static_cast<int>(s->Levels.size()) : 0;
}

int vtkGlobePageSource::GetNumberOfFileLevels()
{
  auto s = this->Internals->Acquire(this);
  return s ? s->FileLevels : 0;
}

namespace
{
bool LevelInRange(vtkObject* self, const State& s, int level)
{
  if (level < 0 || level >= static_cast<int>(s.Levels.size()))
  {
    vtkErrorWithObjectMacro(self, << "'" << s.File << "': level " << level
                                  << " is out of range (the levels are 0.."
                                  << s.Levels.size() - 1 << ")");
    return false;
  }
  return true;
}

bool PageInRange(vtkObject* self, const State& s, int level, int column, int row)
{
  if (!LevelInRange(self, s, level))
  {
    return false;
  }
  const int across = (s.Levels[level][0] + s.PageSize - 1) / s.PageSize;
  const int down = (s.Levels[level][1] + s.PageSize - 1) / s.PageSize;
  if (column < 0 || column >= across || row < 0 || row >= down)
  {
    vtkErrorWithObjectMacro(self, << "'" << s.File << "': page (" << column << ", " << row
                                  << ") of level " << level << " is out of range (" << across
                                  << " x " << down << " pages)");
    return false;
  }
  return true;
}
} // namespace

bool vtkGlobePageSource::GetLevelSize(int level, int size[2])
{
  size[0] = size[1] = 0;
  auto s = this->Internals->Acquire(this);
  if (!s || !LevelInRange(this, *s, level))
  {
    return false;
  }
  size[0] = s->Levels[level][0];
  size[1] = s->Levels[level][1];
  return true;
}

bool vtkGlobePageSource::GetNumberOfPages(int level, int count[2])
{
  count[0] = count[1] = 0;
  auto s = this->Internals->Acquire(this);
  if (!s || !LevelInRange(this, *s, level))
  {
    return false;
  }
  count[0] = (s->Levels[level][0] + s->PageSize - 1) / s->PageSize;
  count[1] = (s->Levels[level][1] + s->PageSize - 1) / s->PageSize;
  return true;
}

bool vtkGlobePageSource::GetPageBounds(int level, int column, int row, double bounds[4])
{
  std::fill(bounds, bounds + 4, std::numeric_limits<double>::quiet_NaN());
  auto s = this->Internals->Acquire(this);
  if (!s || !PageInRange(this, *s, level, column, row))
  {
    return false;
  }
  // Each level spans the whole raster: its texel is the extent over its size.
  const double dx = s->Width * s->Geo[2] / s->Levels[level][0];
  const double dy = s->Height * s->Geo[3] / s->Levels[level][1];
  const int P = s->PageSize;
  bounds[0] = s->Geo[0] + static_cast<double>(column) * P * dx;
  bounds[1] = s->Geo[0] + static_cast<double>(column + 1) * P * dx;
  bounds[3] = s->Geo[1] - static_cast<double>(row) * P * dy;
  bounds[2] = s->Geo[1] - static_cast<double>(row + 1) * P * dy;
  return true;
}

//------------------------------------------------------------------------------------------
bool vtkGlobePageSource::ReadPage(int level, int column, int row, vtkDataArray* out)
{
  auto state = this->Internals->Acquire(this);
  if (!state)
  {
    return false;
  }
  const State& s = *state;
  if (!PageInRange(this, s, level, column, row))
  {
    return false;
  }
  float* heights = nullptr;
  unsigned char* rgba = nullptr;
  vtkFloatArray* floats = vtkArrayDownCast<vtkFloatArray>(out);
  vtkUnsignedCharArray* bytes = vtkArrayDownCast<vtkUnsignedCharArray>(out);
  if (s.Heights ? !floats : !bytes)
  {
    vtkErrorMacro(<< "'" << s.File << "': ReadPage needs a "
                  << (s.Heights ? "vtkFloatArray" : "vtkUnsignedCharArray") << ", not "
                  << (out ? out->GetClassName() : "nullptr"));
    return false;
  }
  const int P = s.PageSize, B = s.Border, N = P + 2 * B;
  const int w = s.Levels[level][0], h = s.Levels[level][1];
  const int comps = s.Components();
  // Source texel of each output column and row (level coordinates, north-up): clamped at the
  // edges, wrapped east-west for global rasters.
  std::vector<int> cols(N), rows(N);
  for (int i = 0; i < N; ++i)
  {
    const int x = column * P - B + i;
    cols[i] = s.Global ? ((x % w) + w) % w : std::min(std::max(x, 0), w - 1);
    const int y = row * P - B + i;
    rows[i] = std::min(std::max(y, 0), h - 1);
  }
  try
  {
    out->SetNumberOfComponents(comps);
    out->SetNumberOfTuples(static_cast<vtkIdType>(N) * N);
    if (s.Heights)
    {
      heights = floats->GetPointer(0);
    }
    else
    {
      rgba = bytes->GetPointer(0);
    }

    if (level >= s.FileLevels)
    {
      // A level averaged in memory (north-up).
      const size_t m = static_cast<size_t>(level - s.FileLevels);
      for (int j = 0; j < N; ++j)
      {
        for (int i = 0; i < N; ++i)
        {
          const size_t from = static_cast<size_t>(rows[j]) * w + cols[i];
          const size_t to = static_cast<size_t>(j) * N + i;
          if (s.Heights)
          {
            heights[to] = s.MemoryHeights[m][from];
          }
          else
          {
            std::memcpy(rgba + 4 * to, &s.MemoryColors[m][4 * from], 4);
          }
        }
      }
    }
    else
    {
      // File coordinates of the needed texels: the rows are one contiguous range; the
      // columns are contiguous runs (more than one where a global raster wraps).
      std::vector<int> fileCols(N), fileRows(N);
      for (int i = 0; i < N; ++i)
      {
        fileCols[i] = s.FlipColumns ? w - 1 - cols[i] : cols[i];
        fileRows[i] = s.FlipRows ? h - 1 - rows[i] : rows[i];
      }
      const auto [rowMin, rowMax] = std::minmax_element(fileRows.begin(), fileRows.end());
      const int y0 = *rowMin, R = *rowMax - *rowMin + 1;
      std::vector<int> unique(fileCols);
      std::sort(unique.begin(), unique.end());
      unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
      const int U = static_cast<int>(unique.size());
      const size_t texelBytes = s.ReadType.size() * s.FileChannels;
      std::vector<unsigned char> raw(static_cast<size_t>(U) * R * texelBytes);
      for (int a = 0; a < U;)
      {
        int b = a;
        while (b + 1 < U && unique[b + 1] == unique[b] + 1)
        {
          ++b;
        }
        const int x0 = s.Levels[level][2], yOrigin = s.Levels[level][3];
        if (!s.Cache->get_pixels(s.Name, 0, level, x0 + unique[a], x0 + unique[b] + 1,
              yOrigin + y0, yOrigin + y0 + R, 0, 1, 0, s.FileChannels, s.ReadType,
              raw.data() + static_cast<size_t>(a) * texelBytes,
              static_cast<OIIO::stride_t>(texelBytes),
              static_cast<OIIO::stride_t>(texelBytes * U), OIIO::AutoStride))
        {
          vtkErrorMacro(<< "'" << s.File << "': page (" << column << ", " << row
                        << ") of level " << level
                        << " cannot be read (OpenImageIO: " << s.Cache->geterror() << ")");
          return false;
        }
        a = b + 1;
      }
      // Convert the block once, then place each output texel.
      const size_t n = static_cast<size_t>(U) * R;
      std::vector<float> blockHeights(s.Heights ? n : 0);
      std::vector<unsigned char> blockRGBA(s.Heights ? 0 : 4 * n);
      s.Convert(raw.data(), n, blockHeights.data(), blockRGBA.data());
      std::vector<int> colIndex(N);
      for (int i = 0; i < N; ++i)
      {
        colIndex[i] = static_cast<int>(
          std::lower_bound(unique.begin(), unique.end(), fileCols[i]) - unique.begin());
      }
      for (int j = 0; j < N; ++j)
      {
        const size_t base = static_cast<size_t>(fileRows[j] - y0) * U;
        for (int i = 0; i < N; ++i)
        {
          const size_t from = base + colIndex[i];
          const size_t to = static_cast<size_t>(j) * N + i;
          if (s.Heights)
          {
            heights[to] = blockHeights[from];
          }
          else
          {
            std::memcpy(rgba + 4 * to, &blockRGBA[4 * from], 4);
          }
        }
      }
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "'" << s.File << "': page (" << column << ", " << row << ") of level "
                  << level << " cannot be read: "
                  << (dynamic_cast<const std::bad_alloc*>(&e) ? "not enough memory" : e.what()));
    return false;
  }
  ++this->Internals->PagesRead;
  return true;
}

//------------------------------------------------------------------------------------------
vtkTypeInt64 vtkGlobePageSource::GetNumberOfPagesRead()
{
  return this->Internals->PagesRead.load();
}

namespace
{
vtkTypeInt64 CacheStat(const std::shared_ptr<const State>& s, const char* name)
{
  long long value = 0;
  if (s && s->Cache)
  {
    s->Cache->getattribute(name, OIIO::TypeDesc::INT64, &value);
  }
  return static_cast<vtkTypeInt64>(value);
}
} // namespace

vtkTypeInt64 vtkGlobePageSource::GetCacheMemoryUsed()
{
  return CacheStat(this->Internals->Acquire(this), "stat:cache_memory_used");
}

vtkTypeInt64 vtkGlobePageSource::GetFileBytesRead()
{
  return CacheStat(this->Internals->Acquire(this), "stat:bytes_read");
}

void vtkGlobePageSource::ResetStatistics()
{
  this->Internals->PagesRead = 0;
  auto s = this->Internals->Acquire(this);
  if (s && s->Cache)
  {
    s->Cache->reset_stats();
  }
}

//------------------------------------------------------------------------------------------
void vtkGlobePageSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "PageSize: " << this->PageSize << "\n";
  os << indent << "Border: " << this->Border << "\n";
  os << indent << "CacheMemory: " << this->CacheMemory << " MiB\n";
  std::shared_ptr<const State> s;
  {
    std::lock_guard<std::mutex> lock(this->Internals->Mutex);
    s = this->Internals->Current;
    if (!s && !this->Internals->FailReason.empty())
    {
      os << indent << "LastError: " << this->Internals->FailReason << "\n";
    }
  }
  if (!s)
  {
    os << indent << "(not open)\n";
    return;
  }
  os << indent << "Raster: " << s->Width << " x " << s->Height << ", "
     << (s->Heights ? "heights (float)" : "RGBA") << (s->Global ? ", global" : "") << "\n";
  os << indent << "Levels: " << s->Levels.size() << " (" << s->FileLevels << " from the file)";
  for (const auto& l : s->Levels)
  {
    os << " " << l[0] << "x" << l[1];
  }
  os << "\n";
  os << indent << "PagesRead: " << this->Internals->PagesRead.load() << "\n";
  os << indent << "CacheMemoryUsed: " << CacheStat(s, "stat:cache_memory_used") << "\n";
  os << indent << "FileBytesRead: " << CacheStat(s, "stat:bytes_read") << "\n";
}
