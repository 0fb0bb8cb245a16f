// vtkGlobeRasterPreparer + vtkGlobePageSource: self-encoding rasters (value = row * width +
// column) prepared with 64-texel tiles and read in 64-texel pages with a 1-texel border, so
// every payload and border texel of level 0 is checked exactly (clamped edges, the wrap of a
// global raster at the antimeridian), and every texel of every level >= 1 against the
// nodata-aware 2 x 2 average of the level above computed here in double. Also: voids,
// georeferencing and nodata kept by the preparer, OpenImageIO's view of the prepared file
// (its IFDs as MIP levels of subimage 0), a plain untiled GeoTIFF (automip) against
// vtkGlobeLayer, colour rasters against vtkGlobeRasterReader (and levels averaged in memory
// for a tiled file without levels), the cache memory bound, concurrent reads, and bad input.
#include "vtkGlobeTestHelpers.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobePageSource.h"
#include "vtkGlobeRasterPreparer.h"
#include "vtkGlobeRasterReader.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include <OpenImageIO/imagecache.h>

#include <geotiff.h>
#include <geovalues.h>
#include <tiffio.h>
#include <xtiffio.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

void Expect(bool condition, const std::string& what)
{
  Checks.Expect(condition, what);
}

const std::string Temp = VTKGLOBE_TEMP_DIR;
const std::string Data = VTKGLOBE_DATA_DIR;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// A float height GeoTIFF (strips, uncompressed), geographic EPSG:4326, north-up.
/// A 1-channel float GeoTIFF; value(r, c) is stored at file row r, column c. Stored north-up
/// and west-to-east unless southUp / eastToWest (the tie point then names the south / east
/// edge and the pixel scale is negative).
bool WriteFloatGeoTIFF(const std::string& path, int w, int h, double west, double north,
  double pixel, const char* noData, const std::function<float(int, int)>& value,
  bool southUp = false, bool eastToWest = false)
{
  TIFF* tif = XTIFFOpen(path.c_str(), "w");
  if (!tif)
  {
    return false;
  }
  static const TIFFFieldInfo noDataInfo[] = { { 42113, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0,
    const_cast<char*>("GDAL_NODATA") } };
  if (!TIFFFindField(tif, 42113, TIFF_ANY))
  {
    TIFFMergeFieldInfo(tif, noDataInfo, 1);
  }
  TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, w);
  TIFFSetField(tif, TIFFTAG_IMAGELENGTH, h);
  TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
  TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 32);
  TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
  TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, 16);
  if (pixel > 0)
  {
    const double tie[6] = { 0, 0, 0, eastToWest ? west + w * pixel : west,
      southUp ? north - h * pixel : north, 0 };
    const double scale[3] = { eastToWest ? -pixel : pixel, southUp ? -pixel : pixel, 0 };
    TIFFSetField(tif, TIFFTAG_GEOTIEPOINTS, 6, tie);
    TIFFSetField(tif, TIFFTAG_GEOPIXELSCALE, 3, scale);
    GTIF* gtif = GTIFNew(tif);
    GTIFKeySet(gtif, GTModelTypeGeoKey, TYPE_SHORT, 1, ModelTypeGeographic);
    GTIFKeySet(gtif, GTRasterTypeGeoKey, TYPE_SHORT, 1, RasterPixelIsArea);
    GTIFKeySet(gtif, GeographicTypeGeoKey, TYPE_SHORT, 1, 4326);
    GTIFWriteKeys(gtif);
    GTIFFree(gtif);
  }
  if (noData)
  {
    TIFFSetField(tif, 42113, noData);
  }
  std::vector<float> row(static_cast<size_t>(w));
  bool ok = true;
  for (int r = 0; r < h && ok; ++r)
  {
    for (int c = 0; c < w; ++c)
    {
      row[c] = value(r, c);
    }
    ok = TIFFWriteScanline(tif, row.data(), r, 0) == 1;
  }
  XTIFFClose(tif);
  return ok;
}

bool Prepare(const std::string& in, const std::string& out, int tile)
{
  vtkNew<vtkGlobeRasterPreparer> preparer;
  preparer->SetInputFileName(in.c_str());
  preparer->SetFileName(out.c_str());
  preparer->SetTileSize(tile);
  return preparer->Write();
}

/// A level of heights, north-up, row-major, NaN = void.
struct Grid
{
  int W = 0, H = 0;
  std::vector<double> V;
  double At(int r, int c) const { return V[static_cast<size_t>(r) * W + c]; }
};

/// A w x h grid, row 0 north, of value(r, c).
Grid MakeGrid(int w, int h, const std::function<double(int, int)>& value)
{
  Grid g;
  g.W = w;
  g.H = h;
  for (int r = 0; r < h; ++r)
  {
    for (int c = 0; c < w; ++c)
    {
      g.V.push_back(value(r, c));
    }
  }
  return g;
}

/// The nodata-aware 2 x 2 average (OpenImageIO's MIP sizes), each result rounded to float as
/// the file stores it.
Grid Reduce(const Grid& g)
{
  Grid n;
  n.W = std::max(1, g.W / 2);
  n.H = std::max(1, g.H / 2);
  n.V.resize(static_cast<size_t>(n.W) * n.H);
  for (int j = 0; j < n.H; ++j)
  {
    for (int i = 0; i < n.W; ++i)
    {
      double sum = 0;
      int count = 0;
      for (int r : { std::min(2 * j, g.H - 1), std::min(2 * j + 1, g.H - 1) })
      {
        for (int c : { std::min(2 * i, g.W - 1), std::min(2 * i + 1, g.W - 1) })
        {
          if (!std::isnan(g.At(r, c)))
          {
            sum += g.At(r, c);
            ++count;
          }
        }
      }
      n.V[static_cast<size_t>(j) * n.W + i] = count ? static_cast<float>(sum / count) : NaN;
    }
  }
  return n;
}

bool Same(double expected, float got)
{
  if (std::isnan(expected) || std::isnan(got))
  {
    return std::isnan(expected) && std::isnan(got);
  }
  return std::abs(got - expected) <=
    4.0 * std::numeric_limits<float>::epsilon() * std::max(1.0, std::abs(expected));
}

/**
 * Reads every page of every level and compares each texel (payload and border) with the
 * reference pyramid (clamped rows; wrapped or clamped columns). Returns the wrong texels.
 */
long CheckPyramid(vtkGlobePageSource* source, std::vector<Grid> reference, bool wrap,
  long* texels, std::string& where)
{
  long wrong = 0;
  *texels = 0;
  const int P = source->GetPageSize(), B = source->GetBorder(), N = source->GetPageTexels();
  vtkNew<vtkFloatArray> page;
  for (int level = 0; level < source->GetNumberOfLevels(); ++level)
  {
    while (static_cast<int>(reference.size()) <= level)
    {
      reference.push_back(Reduce(reference.back()));
    }
    const Grid& g = reference[level];
    int size[2], pages[2];
    source->GetLevelSize(level, size);
    source->GetNumberOfPages(level, pages);
    if (size[0] != g.W || size[1] != g.H)
    {
      where = "level " + std::to_string(level) + " size " + std::to_string(size[0]) + "x" +
        std::to_string(size[1]) + ", expected " + std::to_string(g.W) + "x" + std::to_string(g.H);
      return -1;
    }
    for (int pr = 0; pr < pages[1]; ++pr)
    {
      for (int pc = 0; pc < pages[0]; ++pc)
      {
        if (!source->ReadPage(level, pc, pr, page))
        {
          where = "ReadPage failed";
          return -1;
        }
        for (int j = 0; j < N; ++j)
        {
          const int r = std::min(std::max(pr * P - B + j, 0), g.H - 1);
          for (int i = 0; i < N; ++i)
          {
            const int x = pc * P - B + i;
            const int c = wrap ? ((x % g.W) + g.W) % g.W : std::min(std::max(x, 0), g.W - 1);
            const float got = page->GetValue(static_cast<vtkIdType>(j) * N + i);
            ++*texels;
            if (!Same(g.At(r, c), got))
            {
              if (wrong == 0)
              {
                char text[200];
                std::snprintf(text, sizeof(text),
                  "level %d page (%d,%d) texel (%d,%d): %.9g, expected %.9g", level, pc, pr, i, j,
                  got, g.At(r, c));
                where = text;
              }
              ++wrong;
            }
          }
        }
      }
    }
  }
  return wrong;
}

/// A whole RGBA level assembled from the payload of its pages (north-up).
std::vector<unsigned char> Assemble(vtkGlobePageSource* source, int level)
{
  int size[2], pages[2];
  source->GetLevelSize(level, size);
  source->GetNumberOfPages(level, pages);
  std::vector<unsigned char> out(static_cast<size_t>(size[0]) * size[1] * 4);
  const int P = source->GetPageSize(), B = source->GetBorder(), N = source->GetPageTexels();
  vtkNew<vtkUnsignedCharArray> page;
  for (int pr = 0; pr < pages[1]; ++pr)
  {
    for (int pc = 0; pc < pages[0]; ++pc)
    {
      source->ReadPage(level, pc, pr, page);
      for (int j = 0; j < P && pr * P + j < size[1]; ++j)
      {
        for (int i = 0; i < P && pc * P + i < size[0]; ++i)
        {
          std::memcpy(&out[4 * (static_cast<size_t>(pr * P + j) * size[0] + pc * P + i)],
            page->GetPointer(4 * ((j + B) * N + i + B)), 4);
        }
      }
    }
  }
  return out;
}

/// Channel values of `level` that differ from the rounded 2 x 2 means of `above` (w x h).
long WrongMeans(vtkGlobePageSource* source, int level, const std::vector<unsigned char>& above,
  int w, int h)
{
  const std::vector<unsigned char> got = Assemble(source, level);
  const int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
  long wrong = got.size() == static_cast<size_t>(nw) * nh * 4 ? 0 : 1;
  for (int j = 0; wrong == 0 && j < nh; ++j)
  {
    for (int i = 0; i < nw; ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        int sum = 0;
        for (int dr = 0; dr < 2; ++dr)
        {
          for (int dc = 0; dc < 2; ++dc)
          {
            sum += above[4 * (static_cast<size_t>(2 * j + dr) * w + 2 * i + dc) + k];
          }
        }
        wrong += got[4 * (static_cast<size_t>(j) * nw + i) + k] == (sum + 2) / 4 ? 0 : 1;
      }
    }
  }
  return wrong;
}

/// What OpenImageIO's ImageCache sees in a file: the MIP levels of subimage 0.
std::vector<std::pair<int, int>> CacheLevels(const std::string& file, int* subimages)
{
  std::vector<std::pair<int, int>> levels;
  OIIO::ImageCache* cache = OIIO::ImageCache::create(false);
  const OIIO::ustring name(file);
  int mips = 0;
  *subimages = 0;
  cache->get_image_info(name, 0, 0, OIIO::ustring("subimages"), OIIO::TypeInt, subimages);
  cache->get_image_info(name, 0, 0, OIIO::ustring("miplevels"), OIIO::TypeInt, &mips);
  for (int m = 0; m < mips; ++m)
  {
    OIIO::ImageSpec spec;
    if (cache->get_imagespec(name, spec, 0, m))
    {
      levels.emplace_back(spec.width, spec.height);
    }
  }
  OIIO::ImageCache::destroy(cache);
  return levels;
}

/// The reader's field data of a file (1-row read).
vtkSmartPointer<vtkImageData> ReadHeader(const std::string& file)
{
  vtkNew<vtkGlobeRasterReader> reader;
  reader->SetFileName(file.c_str());
  reader->UpdateInformation();
  int whole[6];
  reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  int extent[6] = { 0, 0, whole[3], whole[3], 0, 0 };
  reader->UpdateExtent(extent);
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  return image;
}

double Field(vtkImageData* image, const char* name, int i = 0)
{
  vtkDataArray* a = vtkArrayDownCast<vtkDataArray>(image->GetFieldData()->GetAbstractArray(name));
  return a && i < a->GetNumberOfValues() ? a->GetComponent(0, i) : NaN;
}

bool ErrorSaid(vtkTest::ErrorObserver* observer, const std::string& words)
{
  const std::string message = observer->GetErrorMessage();
  const bool said = observer->GetError() && message.find(words) != std::string::npos;
  const size_t start = message.find("Cannot");
  std::string shown = message.substr(start == std::string::npos ? 0 : start);
  while (!shown.empty() && (shown.back() == '\n' || shown.back() == ' '))
  {
    shown.pop_back();
  }
  std::printf("       error: %s\n", shown.substr(0, 240).c_str());
  observer->Clear();
  return said;
}
} // namespace

int TestGlobePageSource(int, char*[])
{
  const auto start = std::chrono::steady_clock::now();

  // 1. A regional 1000 x 600 ramp: level 0 exact, levels >= 1 the 2 x 2 averages.
  {
    std::printf("regional ramp 1000 x 600, value = row * 1000 + column\n");
    const std::string in = Temp + "/pages_ramp.tif", out = Temp + "/pages_ramp_prepared.tif";
    Expect(WriteFloatGeoTIFF(in, 1000, 600, 10.0, 50.0, 0.01, nullptr,
             [](int r, int c) { return static_cast<float>(r * 1000 + c); }),
      "input written");
    vtkNew<vtkGlobeRasterPreparer> preparer;
    preparer->SetInputFileName(in.c_str());
    preparer->SetFileName(out.c_str());
    preparer->SetTileSize(64);
    std::vector<double> progress;
    vtkNew<vtkCallbackCommand> observer;
    observer->SetClientData(&progress);
    observer->SetCallback([](vtkObject*, unsigned long, void* cd, void* call)
      { static_cast<std::vector<double>*>(cd)->push_back(*static_cast<double*>(call)); });
    preparer->AddObserver(vtkCommand::ProgressEvent, observer);
    Expect(preparer->Write(), "prepared with 64-texel tiles");
    Expect(preparer->GetNumberOfLevels() == 5, "5 levels: 1000x600 .. 62x37 (got " +
        std::to_string(preparer->GetNumberOfLevels()) + ")");
    Expect(progress.size() >= 10 && progress.front() == 0.0 && progress.back() == 1.0 &&
        std::is_sorted(progress.begin(), progress.end()),
      "ProgressEvent from 0 to 1, increasing (" + std::to_string(progress.size()) + " events)");

    int subimages = 0;
    const auto levels = CacheLevels(out, &subimages);
    std::string sizes;
    bool halves = levels.size() == 5;
    for (size_t l = 0; l < levels.size(); ++l)
    {
      sizes += std::to_string(levels[l].first) + "x" + std::to_string(levels[l].second) + " ";
      if (l > 0)
      {
        halves = halves && levels[l].first == std::max(1, levels[l - 1].first / 2) &&
          levels[l].second == std::max(1, levels[l - 1].second / 2);
      }
    }
    Expect(subimages == 1 && halves,
      "OpenImageIO's ImageCache sees 1 subimage with 5 MIP levels, each max(1, n/2) of the "
      "previous: " + sizes);

    TIFF* tif = TIFFOpen(out.c_str(), "r");
    int directories = 0, reduced = 0, tiled = 0;
    if (tif)
    {
      do
      {
        ++directories;
        uint32_t type = 0;
        if (TIFFGetField(tif, TIFFTAG_SUBFILETYPE, &type) && (type & FILETYPE_REDUCEDIMAGE))
        {
          ++reduced;
        }
        tiled += TIFFIsTiled(tif) ? 1 : 0;
      } while (TIFFReadDirectory(tif));
      TIFFClose(tif);
    }
    Expect(directories == 5 && reduced == 4 && tiled == 5,
      "libtiff: 5 tiled IFDs, 4 of them FILETYPE_REDUCEDIMAGE");

    vtkNew<vtkGlobePageSource> source;
    source->SetFileName(out.c_str());
    source->SetPageSize(64);
    source->SetBorder(1);
    const Grid g0 = MakeGrid(1000, 600, [](int r, int c) { return r * 1000 + c; });
    long texels = 0;
    std::string where;
    const long wrong = CheckPyramid(source, { g0 }, false, &texels, where);
    Expect(wrong == 0 && source->GetNumberOfLevels() == 5 && source->GetNumberOfFileLevels() == 5,
      "every texel of every page (payload + clamped border) of 5 levels right: " +
        std::to_string(texels) + " texels, " + std::to_string(wrong) + " wrong " + where);
    Expect(!source->IsGlobal(), "regional: not global");
    vtkIdType pages = 0;
    for (int l = 0; l < 5; ++l)
    {
      int count[2];
      source->GetNumberOfPages(l, count);
      pages += count[0] * count[1];
    }
    Expect(source->GetNumberOfPagesRead() == pages,
      "pages read counted: " + std::to_string(source->GetNumberOfPagesRead()));
    Expect(source->GetFileBytesRead() >= 1000 * 600 * 4,
      "bytes read: " + std::to_string(source->GetFileBytesRead()));

    // The same with 64-texel pages over 256-texel tiles: the file's chain stops at 250x150,
    // the last two levels are averaged in memory.
    const std::string out256 = Temp + "/pages_ramp_tile256.tif";
    Expect(Prepare(in, out256, 256), "prepared with 256-texel tiles (3 levels)");
    vtkNew<vtkGlobePageSource> source256;
    source256->SetFileName(out256.c_str());
    source256->SetPageSize(64);
    const long wrong256 = CheckPyramid(source256, { g0 }, false, &texels, where);
    Expect(wrong256 == 0 && source256->GetNumberOfFileLevels() == 3 &&
        source256->GetNumberOfLevels() == 5,
      "tiles larger than pages: 3 file levels + 2 averaged in memory, all texels right (" +
        std::to_string(wrong256) + " wrong) " + where);

    // Georeferencing: page bounds agree with the reader's transform.
    double t[4], b[4], b3[4];
    source->GetGeoTransform(t);
    source->GetPageBounds(0, 1, 2, b);
    source->GetPageBounds(3, 1, 1, b3);
    const double dx3 = 10.0 / 125, dy3 = 6.0 / 75; // level 3: 125 x 75 over 10 x 6 degrees
    Expect(std::abs(t[0] - 10) < 1e-12 && std::abs(t[1] - 50) < 1e-12 &&
        std::abs(t[2] - 0.01) < 1e-15 && std::abs(b[0] - 10.64) < 1e-9 &&
        std::abs(b[1] - 11.28) < 1e-9 && std::abs(b[3] - 48.72) < 1e-9 &&
        std::abs(b[2] - 48.08) < 1e-9 && std::abs(b3[0] - (10 + 64 * dx3)) < 1e-9 &&
        std::abs(b3[3] - (50 - 64 * dy3)) < 1e-9,
      "GetPageBounds: level 0 page (1,2) = west 10.64 east 11.28 south 48.08 north 48.72; "
      "level 3 scaled by extent / level size");
  }

  // 2. A global 720 x 360 ramp: wraps at the antimeridian.
  {
    std::printf("global ramp 720 x 360\n");
    const std::string in = Temp + "/pages_global.tif", out = Temp + "/pages_global_prepared.tif";
    Expect(WriteFloatGeoTIFF(in, 720, 360, -180.0, 90.0, 0.5, nullptr,
             [](int r, int c) { return static_cast<float>(r * 720 + c); }),
      "input written");
    Expect(Prepare(in, out, 64), "prepared");
    vtkNew<vtkGlobePageSource> source;
    source->SetFileName(out.c_str());
    source->SetPageSize(64);
    const Grid g0 = MakeGrid(720, 360, [](int r, int c) { return r * 720 + c; });
    long texels = 0;
    std::string where;
    const long wrong = CheckPyramid(source, { g0 }, true, &texels, where);
    Expect(source->IsGlobal() && wrong == 0,
      "global: every texel right with east-west wrap (" + std::to_string(texels) + " texels, " +
        std::to_string(wrong) + " wrong) " + where);
    vtkNew<vtkFloatArray> page;
    source->ReadPage(0, 0, 1, page);
    const int N = source->GetPageTexels();
    Expect(page->GetValue(5 * N + 0) == 68 * 720 + 719 && page->GetValue(5 * N + 1) == 68 * 720,
      "page (0,1) west border = the raster's east column (antimeridian)");

    // Concurrent reads agree with sequential ones.
    int pages[2];
    source->GetNumberOfPages(0, pages);
    std::vector<std::vector<float>> sequential(pages[0] * pages[1]), parallel(sequential.size());
    for (int p = 0; p < pages[0] * pages[1]; ++p)
    {
      vtkNew<vtkFloatArray> a;
      source->ReadPage(0, p % pages[0], p / pages[0], a);
      sequential[p].assign(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfValues());
    }
    vtkNew<vtkGlobePageSource> fresh;
    fresh->SetFileName(out.c_str());
    fresh->SetPageSize(64);
    fresh->Open();
    std::vector<std::thread> threads;
    for (int k = 0; k < 4; ++k)
    {
      threads.emplace_back(
        [&, k]
        {
          for (int p = k; p < pages[0] * pages[1]; p += 4)
          {
            vtkNew<vtkFloatArray> a;
            fresh->ReadPage(0, p % pages[0], p / pages[0], a);
            parallel[p].assign(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfValues());
          }
        });
    }
    for (auto& thread : threads)
    {
      thread.join();
    }
    Expect(parallel == sequential, "4 threads reading pages at once give the same pages");
  }

  // 3. Voids: all-void 2 x 2 blocks average to NaN, partly void ones average the valid posts.
  {
    std::printf("voids (nodata -9999)\n");
    const std::string in = Temp + "/pages_voids.tif", out = Temp + "/pages_voids_prepared.tif";
    const auto value = [](int r, int c) -> float
    {
      if ((r / 2 + c / 2) % 3 == 0)
      {
        return -9999.0f; // whole 2 x 2 blocks void
      }
      if ((r / 2 + c / 2) % 3 == 1 && r % 2 == 0 && c % 2 == 0)
      {
        return -9999.0f; // one void post in the block
      }
      return static_cast<float>(r * 256 + c);
    };
    Expect(WriteFloatGeoTIFF(in, 256, 200, 5.0, 45.0, 0.001, "-9999", value), "input written");
    Expect(Prepare(in, out, 64), "prepared");
    vtkNew<vtkGlobePageSource> source;
    source->SetFileName(out.c_str());
    source->SetPageSize(64);
    Grid g0;
    g0.W = 256;
    g0.H = 200;
    for (int r = 0; r < 200; ++r)
    {
      for (int c = 0; c < 256; ++c)
      {
        const float v = value(r, c);
        g0.V.push_back(v == -9999.0f ? NaN : v);
      }
    }
    long texels = 0;
    std::string where;
    const long wrong = CheckPyramid(source, { g0 }, false, &texels, where);
    Expect(wrong == 0, "every texel right, voids NaN (" + std::to_string(wrong) + " wrong) " + where);
    vtkNew<vtkFloatArray> page;
    source->ReadPage(1, 0, 0, page);
    const int N = source->GetPageTexels();
    // Level-1 texel (0, 0) is over block (0, 0): all void. Texel (1, 0) is over block (0, 1),
    // whose post (0, 2) is void: the average of 3, 258, 259.
    Expect(std::isnan(page->GetValue(1 * N + 1)) &&
        page->GetValue(1 * N + 2) == static_cast<float>((3.0 + 258.0 + 259.0) / 3.0),
      "level 1: all-void block -> NaN; partly void block -> mean of its 3 valid posts");

    // Nodata text a float cannot hold exactly (-9999.9 is stored as -9999.900390625): the
    // voids are compared as the file's samples hold them, in the plain file (its levels
    // averaged here) and in the prepared one.
    const std::string in9 = Temp + "/pages_voids_9.tif", out9 = Temp + "/pages_voids_9_prepared.tif";
    Expect(WriteFloatGeoTIFF(in9, 256, 200, 5.0, 45.0, 0.001, "-9999.9",
             [&](int r, int c) { return value(r, c) == -9999.0f ? -9999.9f : value(r, c); }) &&
        Prepare(in9, out9, 64),
      "nodata -9999.9 written and prepared");
    for (const std::string& file : { in9, out9 })
    {
      vtkNew<vtkGlobePageSource> nines;
      nines->SetFileName(file.c_str());
      nines->SetPageSize(64);
      long checked = 0;
      std::string at;
      const long bad = CheckPyramid(nines, { g0 }, false, &checked, at);
      Expect(bad == 0 && checked > 0,
        "nodata -9999.9, " + std::string(file == in9 ? "plain" : "prepared") +
          ": every level nodata-aware, voids NaN (" + std::to_string(bad) + " of " +
          std::to_string(checked) + " wrong) " + at);
    }

    // The preparer keeps georeferencing and nodata.
    auto before = ReadHeader(in), after = ReadHeader(out);
    bool same = true;
    for (int i = 0; i < 4; ++i)
    {
      same = same &&
        Field(before, vtkGlobeRasterReader::GetGeoTransformArrayName(), i) ==
          Field(after, vtkGlobeRasterReader::GetGeoTransformArrayName(), i);
    }
    Expect(same &&
        Field(after, vtkGlobeRasterReader::GetEPSGArrayName()) == 4326 &&
        Field(after, vtkGlobeRasterReader::GetModelTypeArrayName()) == 1 &&
        Field(after, vtkGlobeRasterReader::GetNoDataValueArrayName()) == -9999.0,
      "prepared file: same GlobeGeoTransform, EPSG:4326, geographic, nodata -9999 (reader)");
    double t[4], b[4];
    source->GetGeoTransform(t);
    source->GetPageBounds(0, 0, 0, b);
    Expect(t[0] == Field(before, vtkGlobeRasterReader::GetGeoTransformArrayName(), 0) &&
        b[0] == t[0] && b[3] == t[1] && std::abs(b[1] - (t[0] + 64 * t[2])) < 1e-12 &&
        source->GetHasNoDataValue() && source->GetNoDataValue() == -9999.0,
      "GetPageBounds of page (0,0) starts at the north-west corner; nodata -9999");
  }

  // 4. A plain, untiled GeoTIFF (no levels: automip) against vtkGlobeLayer.
  {
    std::printf("Data/earth/relief_2deg.tif (untiled, no levels)\n");
    const std::string file = Data + "/earth/relief_2deg.tif";
    vtkNew<vtkGlobeLayer> layer;
    layer->SetFileName(file.c_str());
    layer->FillVoidsOff();
    layer->Update();
    vtkNew<vtkGlobePageSource> source;
    source->SetFileName(file.c_str());
    source->SetPageSize(64);
    Grid g0;
    g0.W = layer->GetNumberOfColumns();
    g0.H = layer->GetNumberOfRows();
    vtkDataArray* data = layer->GetData();
    for (vtkIdType i = 0; data && i < data->GetNumberOfTuples(); ++i)
    {
      g0.V.push_back(data->GetComponent(i, 0));
    }
    int pages[2];
    source->GetNumberOfPages(0, pages);
    long wrong = 0, texels = 0;
    vtkNew<vtkFloatArray> page;
    const int N = source->GetPageTexels();
    for (int pr = 0; pr < pages[1]; ++pr)
    {
      for (int pc = 0; pc < pages[0]; ++pc)
      {
        source->ReadPage(0, pc, pr, page);
        for (int j = 0; j < N; ++j)
        {
          for (int i = 0; i < N; ++i)
          {
            const int r = std::min(std::max(pr * 64 - 1 + j, 0), g0.H - 1);
            const int x = pc * 64 - 1 + i;
            const int c = ((x % g0.W) + g0.W) % g0.W; // global
            wrong += Same(g0.At(r, c), page->GetValue(j * N + i)) ? 0 : 1;
            ++texels;
          }
        }
      }
    }
    int size1[2], size2[2];
    source->GetLevelSize(1, size1);
    source->GetLevelSize(2, size2);
    Expect(g0.W == 180 && g0.H == 90 && wrong == 0,
      "level 0 equals vtkGlobeLayer's values, row 0 north (" + std::to_string(texels) +
        " texels, " + std::to_string(wrong) + " wrong)");
    // A plain file that fits in memory gets nodata-aware levels averaged here, not
    // OpenImageIO's automip (blind to nodata).
    Expect(source->GetNumberOfLevels() == 3 && source->GetNumberOfFileLevels() == 1 &&
        size1[0] == 90 && size1[1] == 45 && size2[0] == 45 && size2[1] == 22,
      "levels averaged here: 180x90, 90x45, 45x22 (max(1, n/2)), 1 from the file");
  }

  // 4b. Files stored south-up and east-to-west, read without preparing: pages come north-up,
  // west-to-east (the orientation from the reader's GlobeStorageOrientation).
  for (int flips = 1; flips < 4; ++flips)
  {
    const bool southUp = flips & 1, eastToWest = flips & 2;
    std::printf("plain 256 x 128 ramp stored%s%s\n", southUp ? " south-up" : "",
      eastToWest ? " east-to-west" : "");
    const std::string in = Temp + "/pages_flipped_" + std::to_string(flips) + ".tif";
    Expect(WriteFloatGeoTIFF(in, 256, 128, 20.0, 10.0, 0.01, nullptr,
             [](int r, int c) { return static_cast<float>(r * 256 + c); }, southUp, eastToWest),
      "input written");
    vtkNew<vtkGlobePageSource> source;
    source->SetFileName(in.c_str());
    source->SetPageSize(64);
    // North row j, west column i is the file's row (127 - j) / column (255 - i) where flipped.
    const Grid g0 = MakeGrid(256, 128, [southUp, eastToWest](int r, int c) {
      return (southUp ? 127 - r : r) * 256 + (eastToWest ? 255 - c : c);
    });
    long texels = 0;
    std::string where;
    const long wrong = CheckPyramid(source, { g0 }, false, &texels, where);
    Expect(wrong == 0 && source->GetNumberOfLevels() == 3,
      "every texel of 3 levels north-up and west-to-east (" + std::to_string(texels) +
        " texels, " + std::to_string(wrong) + " wrong) " + where);
  }

  // 5. Colour: a tiled RGB file without levels (levels averaged in memory), and prepared.
  {
    std::printf("Data/earth/world.tif (RGB, 256-texel JPEG tiles, no levels)\n");
    const std::string file = Data + "/earth/world.tif";
    vtkNew<vtkGlobeRasterReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    auto* pixels = vtkArrayDownCast<vtkUnsignedCharArray>(image->GetPointData()->GetScalars());
    const auto check = [&](const std::string& name, int pageSize, long* texels) -> long
    {
      vtkNew<vtkGlobePageSource> source;
      source->SetFileName(name.c_str());
      source->SetPageSize(pageSize);
      int pages[2];
      source->GetNumberOfPages(0, pages);
      vtkNew<vtkUnsignedCharArray> page;
      const int N = source->GetPageTexels();
      long wrong = 0;
      *texels = 0;
      for (int pr = 0; pr < pages[1]; ++pr)
      {
        for (int pc = 0; pc < pages[0]; ++pc)
        {
          if (!source->ReadPage(0, pc, pr, page) || page->GetNumberOfComponents() != 4)
          {
            return -1;
          }
          for (int j = 1; j < N - 1; ++j)
          {
            for (int i = 1; i < N - 1; ++i)
            {
              const int r = std::min(pr * pageSize + j - 1, dims[1] - 1);
              const int c = std::min(pc * pageSize + i - 1, dims[0] - 1);
              const vtkIdType vtkRow = dims[1] - 1 - r; // the reader's row 0 is south
              const unsigned char* want = pixels->GetPointer(3 * (vtkRow * dims[0] + c));
              const unsigned char* got = page->GetPointer(4 * (j * N + i));
              wrong += (got[0] == want[0] && got[1] == want[1] && got[2] == want[2] &&
                         got[3] == 255)
                ? 0
                : 1;
              ++*texels;
            }
          }
        }
      }
      return wrong;
    };
    long texels = 0;
    const long wrong = check(file, 256, &texels);
    Expect(dims[0] == 2048 && wrong == 0,
      "level-0 payload equals the reader's RGB, alpha 255 (" + std::to_string(texels) +
        " texels, " + std::to_string(wrong) + " wrong)");
    // A tiled file without levels that fits in memory: its levels are averaged here
    // (OpenImageIO 2.4's automip would make them, blind to nodata).
    vtkNew<vtkGlobePageSource> source;
    source->SetFileName(file.c_str());
    source->SetPageSize(256);
    Expect(source->GetNumberOfFileLevels() == 1 && source->GetNumberOfLevels() == 4,
      "tiled file without levels: 1 file level + 3 averaged here (2048 -> 256); got " +
        std::to_string(source->GetNumberOfFileLevels()) + " + " +
        std::to_string(source->GetNumberOfLevels() - source->GetNumberOfFileLevels()));
    std::vector<unsigned char> level0(static_cast<size_t>(dims[0]) * dims[1] * 4);
    for (int r = 0; r < dims[1]; ++r)
    {
      for (int c = 0; c < dims[0]; ++c)
      {
        const unsigned char* p = pixels->GetPointer(3 * ((dims[1] - 1 - r) * dims[0] + c));
        unsigned char* q = &level0[4 * (static_cast<size_t>(r) * dims[0] + c)];
        q[0] = p[0];
        q[1] = p[1];
        q[2] = p[2];
        q[3] = 255;
      }
    }
    const long wrongAuto = WrongMeans(source, 1, level0, dims[0], dims[1]);
    Expect(wrongAuto == 0,
      "level 1 = rounded 2 x 2 means of level 0 (" + std::to_string(wrongAuto) +
        " wrong channel values)");
    const std::string prepared = Temp + "/pages_world_prepared.tif";
    Expect(Prepare(file, prepared, 128), "world.tif prepared (RGB, 128-texel tiles)");
    const long wrongPrepared = check(prepared, 64, &texels);
    Expect(wrongPrepared == 0,
      "prepared RGB level 0 equals the reader's pixels (" + std::to_string(wrongPrepared) +
        " wrong)");
    // Prepared with 128-texel tiles: 5 file levels (2048 .. 128); 64-texel pages need one more,
    // averaged in memory.
    vtkNew<vtkGlobePageSource> preparedSource;
    preparedSource->SetFileName(prepared.c_str());
    preparedSource->SetPageSize(64);
    const long wrong1 = WrongMeans(preparedSource, 1, level0, dims[0], dims[1]);
    const std::vector<unsigned char> level4 = Assemble(preparedSource, 4);
    const long wrong5 = WrongMeans(preparedSource, 5, level4, 128, 64);
    Expect(preparedSource->GetNumberOfFileLevels() == 5 &&
        preparedSource->GetNumberOfLevels() == 6 && wrong1 == 0 && wrong5 == 0,
      "prepared RGB: level 1 (file) and level 5 (in memory) = rounded 2 x 2 means (" +
        std::to_string(wrong1) + ", " + std::to_string(wrong5) + " wrong)");
    // The Moon: a user-defined sphere (datum axes) survives preparation.
    const std::string moon = Data + "/moon/moon_1024x512.tif", moonOut = Temp + "/pages_moon.tif";
    Expect(Prepare(moon, moonOut, 256), "moon prepared");
    auto before = ReadHeader(moon), after = ReadHeader(moonOut);
    Expect(Field(before, vtkGlobeRasterReader::GetDatumSemiAxesArrayName(), 0) == 1737400.0 &&
        Field(after, vtkGlobeRasterReader::GetDatumSemiAxesArrayName(), 0) == 1737400.0 &&
        Field(after, vtkGlobeRasterReader::GetDatumSemiAxesArrayName(), 1) ==
          Field(before, vtkGlobeRasterReader::GetDatumSemiAxesArrayName(), 1) &&
        Field(after, vtkGlobeRasterReader::GetEPSGArrayName()) ==
          Field(before, vtkGlobeRasterReader::GetEPSGArrayName()) &&
        Field(after, vtkGlobeRasterReader::GetGeoTransformArrayName(), 2) ==
          Field(before, vtkGlobeRasterReader::GetGeoTransformArrayName(), 2),
      "moon: datum semi-axes (1737400 m), EPSG and pixel size kept");
  }

  // 6. The cache memory bound: a 64 MiB raster through a 4 MiB cache.
  {
    std::printf("4096 x 4096 float (64 MiB) through a 4 MiB cache\n");
    const std::string in = Temp + "/pages_big.tif", out = Temp + "/pages_big_prepared.tif";
    Expect(WriteFloatGeoTIFF(in, 4096, 4096, 0.0, 40.0, 0.001, nullptr,
             [](int r, int c) { return static_cast<float>(r * 4096 + c); }),
      "input written");
    Expect(Prepare(in, out, 64), "prepared");
    vtkNew<vtkGlobePageSource> source;
    source->SetFileName(out.c_str());
    source->SetPageSize(256);
    source->SetCacheMemory(4);
    int pages[2];
    source->GetNumberOfPages(0, pages);
    vtkNew<vtkFloatArray> page;
    const int N = source->GetPageTexels();
    vtkTypeInt64 peak = 0;
    long wrong = 0;
    for (int pr = 0; pr < pages[1]; ++pr)
    {
      for (int pc = 0; pc < pages[0]; ++pc)
      {
        source->ReadPage(0, pc, pr, page);
        peak = std::max(peak, source->GetCacheMemoryUsed());
        for (int j = 0; j < N; ++j)
        {
          const int r = std::min(std::max(pr * 256 - 1 + j, 0), 4095);
          for (int i = 0; i < N; ++i)
          {
            const int c = std::min(std::max(pc * 256 - 1 + i, 0), 4095);
            wrong += page->GetValue(j * N + i) == static_cast<float>(r * 4096 + c) ? 0 : 1;
          }
        }
      }
    }
    // Slack: the tiles one page needs at once (a 258 x 258 page spans 6 x 6 tiles of 16 KiB).
    const vtkTypeInt64 limit = 4 * 1048576 + 36 * 64 * 64 * 4;
    Expect(wrong == 0 && source->GetNumberOfPagesRead() == 256,
      "all 256 level-0 pages read, every texel right (" + std::to_string(wrong) + " wrong)");
    Expect(peak > 0 && peak <= limit && source->GetFileBytesRead() >= 4096LL * 4096 * 4,
      "cache memory peak " + std::to_string(peak) + " bytes <= 4 MiB + one page's tiles (" +
        std::to_string(limit) + "); " + std::to_string(source->GetFileBytesRead()) +
        " pixel bytes read");
    source->ResetStatistics();
    Expect(source->GetNumberOfPagesRead() == 0 && source->GetFileBytesRead() == 0,
      "ResetStatistics zeroes pages and bytes read");
  }

  // 7. Bad input: clear errors, no crash.
  {
    std::printf("bad input\n");
    vtkNew<vtkTest::ErrorObserver> errors;
    vtkNew<vtkGlobePageSource> source;
    source->AddObserver(vtkCommand::ErrorEvent, errors);
    const std::string missing = Temp + "/pages_no_such_file.tif";
    source->SetFileName(missing.c_str());
    vtkNew<vtkFloatArray> page;
    Expect(!source->ReadPage(0, 0, 0, page) && ErrorSaid(errors, missing) &&
        source->GetNumberOfLevels() == 0,
      "missing file: error naming it");
    const std::string plain = Temp + "/pages_not_georeferenced.tif";
    WriteFloatGeoTIFF(plain, 32, 16, 0, 0, 0.0, nullptr, [](int, int) { return 1.0f; });
    source->SetFileName(plain.c_str());
    Expect(!source->Open() && ErrorSaid(errors, "georeferencing"),
      "a TIFF without georeferencing: error");
    source->SetFileName((Temp + "/pages_voids_prepared.tif").c_str());
    source->SetPageSize(64);
    Expect(source->Open(), "a good file opens again after a failure");
    Expect(!source->ReadPage(9, 0, 0, page) && ErrorSaid(errors, "level 9 is out of range"),
      "level out of range: error");
    Expect(!source->ReadPage(0, 4, 0, page) && ErrorSaid(errors, "out of range"),
      "page column out of range: error");
    Expect(!source->ReadPage(0, 0, -1, page) && ErrorSaid(errors, "out of range"),
      "page row out of range: error");
    vtkNew<vtkUnsignedCharArray> wrongType;
    Expect(!source->ReadPage(0, 0, 0, wrongType) && ErrorSaid(errors, "vtkFloatArray"),
      "heights into an unsigned char array: error");
    Expect(!source->ReadPage(0, 0, 0, nullptr) && ErrorSaid(errors, "nullptr"),
      "no array: error");
    double bounds[4];
    Expect(!source->GetPageBounds(0, 0, 99, bounds) && std::isnan(bounds[0]) &&
        ErrorSaid(errors, "out of range"),
      "GetPageBounds out of range: error, NaN");

    vtkNew<vtkGlobeRasterPreparer> preparer;
    preparer->AddObserver(vtkCommand::ErrorEvent, errors);
    preparer->SetInputFileName(missing.c_str());
    preparer->SetFileName((Temp + "/pages_never.tif").c_str());
    Expect(!preparer->Write() && ErrorSaid(errors, "does not exist"),
      "preparer, missing input: error");
    preparer->SetInputFileName(plain.c_str());
    Expect(!preparer->Write() && ErrorSaid(errors, "georeferencing"),
      "preparer, input without georeferencing: error");
    preparer->SetInputFileName((Temp + "/pages_ramp.tif").c_str());
    preparer->SetFileName((Temp + "/no_such_directory/out.tif").c_str());
    Expect(!preparer->Write() && ErrorSaid(errors, "cannot be created"),
      "preparer, unwritable output: error");
    // Abort from a progress observer: fails, leaves no output.
    const std::string aborted = Temp + "/pages_aborted.tif";
    preparer->SetFileName(aborted.c_str());
    vtkNew<vtkCallbackCommand> abort;
    abort->SetCallback([](vtkObject* caller, unsigned long, void*, void* call)
      {
        if (*static_cast<double*>(call) > 0.2)
        {
          static_cast<vtkGlobeRasterPreparer*>(caller)->AbortExecuteOn();
        }
      });
    preparer->AddObserver(vtkCommand::ProgressEvent, abort);
    std::FILE* leftover = nullptr;
    Expect(!preparer->Write() && ErrorSaid(errors, "aborted") &&
        !(leftover = std::fopen(aborted.c_str(), "rb")),
      "AbortExecute from a progress observer: fails, no output left");
    if (leftover)
    {
      std::fclose(leftover);
    }
  }

  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%.1f s\n", seconds);
  return Checks.Result();
}
