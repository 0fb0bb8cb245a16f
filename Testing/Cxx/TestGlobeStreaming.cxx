// Streamed layers (issue "Planetary-scale data", Documentation/streaming.md): a self-encoding
// raster (each texel's colour is its own index) streamed through a GPU page cache of 8 pages
// of 64^2. Every frame, from the first, shows only texels of the raster (no undefined texel);
// once refinement settles, every pixel shows the texel at its (lon, lat) of a level within
// one of its ideal footprint level (0 wrong), across page borders and the antimeridian (the
// (lon, lat) of its mesh point, or with terrain refinement on also of its ray's exact hit); a
// camera move that needs no new page loads none; the GPU memory stays within the cache; and a
// raster many times larger than the caches streams with bounded RSS.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkCallbackCommand.h"
#include "vtkFloatArray.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobePageCache.h"
#include "vtkGlobePageSource.h"
#include "vtkGlobeRasterPreparer.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkTIFFWriter.h"

#include <chrono>
#include <cstring>
#include <fstream>
#include <thread>

namespace
{
vtkGlobeTest::Checklist Checks;
const std::string Temp = VTKGLOBE_TEMP_DIR;

// Texel (x, y), y from the north, encodes itself: R = x mod 256, G = y mod 256, B = the rest.
std::array<int, 3> Code(int x, int y)
{
  return { x & 255, y & 255, (x >> 8) | ((y >> 8) << 4) };
}

std::string WriteSelfEncoding(int w, int h)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      // VTK images are stored south first.
      const std::array<int, 3> c = Code(x, h - 1 - y);
      for (int k = 0; k < 3; ++k)
      {
        p[3 * (static_cast<size_t>(y) * w + x) + k] = static_cast<unsigned char>(c[k]);
      }
    }
  }
  const std::string path = Temp + "/streaming_self_encoding.png";
  std::remove(path.c_str());
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  vtkGlobeTest::WriteGlobalWorldFile(Temp + "/streaming_self_encoding.pgw", w, h);
  return path;
}

// Every level of a page source, north-up RGBA, assembled from its pages.
struct Levels
{
  std::vector<int> W, H;
  std::vector<std::vector<unsigned char>> RGBA;
};

Levels ReadLevels(const std::string& path, int pageSize)
{
  vtkNew<vtkGlobePageSource> source;
  source->SetFileName(path.c_str());
  source->SetPageSize(pageSize);
  source->SetBorder(0);
  Levels levels;
  for (int l = 0; l < source->GetNumberOfLevels(); ++l)
  {
    int size[2], count[2];
    source->GetLevelSize(l, size);
    source->GetNumberOfPages(l, count);
    levels.W.push_back(size[0]);
    levels.H.push_back(size[1]);
    std::vector<unsigned char> rgba(static_cast<size_t>(size[0]) * size[1] * 4);
    for (int r = 0; r < count[1]; ++r)
    {
      for (int c = 0; c < count[0]; ++c)
      {
        vtkNew<vtkUnsignedCharArray> page;
        source->ReadPage(l, c, r, page);
        for (int j = 0; j < pageSize && r * pageSize + j < size[1]; ++j)
        {
          for (int i = 0; i < pageSize && c * pageSize + i < size[0]; ++i)
          {
            const size_t to = 4 * (static_cast<size_t>(r * pageSize + j) * size[0] + c * pageSize + i);
            std::copy_n(page->GetPointer(4 * (j * pageSize + i)), 4, &rgba[to]);
          }
        }
      }
    }
    levels.RGBA.push_back(std::move(rgba));
  }
  return levels;
}

struct FrameCheck
{
  int Covered = 0;
  int Undefined = 0; // matches no texel of any level near its position
  int WrongLevel = 0; // matches none of the levels within one of the ideal
  int IdealLow = 99, IdealHigh = -1; // the ideal levels the frame asks for
};

// Each covered pixel against the texels at its (lon, lat): any level (undefined otherwise),
// and the levels within one of its ideal level, from its footprint to its neighbours.
// The self-encoding layer's (u, v) at the exact ground point of pixel (x, y): its centre ray
// against the ellipsoid. False when the ray misses.
bool ExactUV(vtkGlobeTest::Scene& scene, int x, int y, std::array<double, 2>& uv)
{
  double eye[3], ray[3], t[2], p[3], llh[3];
  scene.Renderer->GetActiveCamera()->GetPosition(eye);
  vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
  if (scene.Body->IntersectRay(eye, ray, t) == 0)
  {
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    p[c] = eye[c] + t[0] * ray[c];
  }
  scene.Body->CartesianToGeodetic(p, llh);
  uv = { (llh[0] + 180.0) / 360.0, (90.0 - llh[1]) / 180.0 };
  uv[0] -= std::floor(uv[0]);
  return true;
}

FrameCheck CheckFrame(vtkGlobeTest::Scene& scene, const Levels& levels)
{
  FrameCheck result;
  const int* size = scene.Window->GetSize();
  const std::vector<unsigned char> rgb = vtkGlobeTest::ReadPixels(scene.Window);
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const std::vector<float> g = vtkGlobeTest::ReadTexture(vtkGlobeMapperTesting::GetGBufferTexture(scene.Mapper));
  const int W = size[0], H = size[1];
  std::vector<std::array<double, 2>> uv(static_cast<size_t>(W) * H, { NAN, NAN });
  for (size_t i = 0; i < uv.size(); ++i)
  {
    if (depth[i] < 1.0f)
    {
      double p[3], llh[3];
      vtkGlobeTest::GBufferPoint(scene, &g[4 * i], false, p);
      scene.Body->CartesianToGeodetic(p, llh);
      uv[i] = { (llh[0] + 180.0) / 360.0, (90.0 - llh[1]) / 180.0 };
      uv[i][0] -= std::floor(uv[i][0]);
    }
  }
  const int n = static_cast<int>(levels.W.size());
  for (int y = 1; y + 1 < H; ++y)
  {
    for (int x = 1; x + 1 < W; ++x)
    {
      const size_t i = static_cast<size_t>(y) * W + x;
      if (!(depth[i] < 1.0f))
      {
        continue;
      }
      // The ideal footprint from the exact ground points of the pixel's four neighbours
      // (their rays against the ellipsoid, in double: the scene has no heights), in level-0
      // texels, as OpenGL measures it (the larger axis, central differences). Not from the
      // G-buffer: next to the limb the mesh's points are what a grid cell across the limb
      // allows (Documentation/rendering.md "The limb"), not the ground under each pixel.
      std::array<double, 2> around[4];
      bool onGround = true;
      const int offsets[4][2] = { { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } };
      for (int k = 0; k < 4 && onGround; ++k)
      {
        onGround = ExactUV(scene, x + offsets[k][0], y + offsets[k][1], around[k]);
      }
      if (!onGround)
      {
        continue;
      }
      ++result.Covered;
      auto d = [&](int a, int b, int k) {
        double v = around[b][k] - around[a][k];
        return 0.5 * (k == 0 ? v - std::floor(v + 0.5) : v);
      };
      const double rho = std::max(std::hypot(d(0, 1, 0) * levels.W[0], d(0, 1, 1) * levels.H[0]),
        std::hypot(d(2, 3, 0) * levels.W[0], d(2, 3, 1) * levels.H[0]));
      const int ideal = std::clamp(static_cast<int>(std::floor(std::log2(std::max(rho, 1e-9)) + 0.5)), 0, n - 1);
      result.IdealLow = std::min(result.IdealLow, ideal);
      result.IdealHigh = std::max(result.IdealHigh, ideal);
      // Whether the pixel shows the texel of level l at its centre, or a neighbour when the
      // centre is within 2 % of a texel of its edge (float G-buffer against the GPU's own
      // coordinates). A coarse texel's colour can equal a finer one's (the mean of codes is a
      // code), so a pixel passes when any level within one of the ideal matches.
      // With terrain refinement the pixel is drawn at its refined point, which on this level
      // ground is the ray's exact hit (the mesh point where the refinement stands aside), so
      // either reference passes.
      std::array<double, 2> exact = uv[i];
      const bool refined = scene.Mapper->GetTerrainRefinement() > 0 &&
        scene.Mapper->GetHighPrecisionGeodetic() && ExactUV(scene, x, y, exact);
      auto showsAt = [&](int l, const std::array<double, 2>& at) {
        const double tx = at[0] * levels.W[l], ty = at[1] * levels.H[l];
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dx = -1; dx <= 1; ++dx)
          {
            const int cx = (static_cast<int>(std::floor(tx + 0.02 * dx)) % levels.W[l] + levels.W[l]) % levels.W[l];
            const int cy = std::clamp(static_cast<int>(std::floor(ty + 0.02 * dy)), 0, levels.H[l] - 1);
            const unsigned char* t = &levels.RGBA[l][4 * (static_cast<size_t>(cy) * levels.W[l] + cx)];
            if (t[0] == rgb[3 * i] && t[1] == rgb[3 * i + 1] && t[2] == rgb[3 * i + 2])
            {
              return true;
            }
          }
        }
        return false;
      };
      auto shows = [&](int l) { return showsAt(l, uv[i]) || (refined && showsAt(l, exact)); };
      bool near = false, any = false;
      for (int l = 0; l < n; ++l)
      {
        const bool match = shows(l);
        any |= match;
        near |= match && std::abs(l - ideal) <= 1;
      }
      result.Undefined += any ? 0 : 1;
      result.WrongLevel += any && !near ? 1 : 0;
    }
  }
  return result;
}

// A 8192 x 4096 float raster (128 MiB) with a world file, streamed through caches of 4 MiB
// (GPU) and 16 MiB (CPU) over a flight: RSS stays bounded.
void MemoryBound()
{
  const int w = 8192, h = 4096;
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* v = static_cast<float*>(image->GetScalarPointer());
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      v[static_cast<size_t>(y) * w + x] = static_cast<float>(
        2000.0 * std::sin(x * 0.013) * std::cos(y * 0.021) + 100.0 * ((x * 7 + y * 13) % 17));
    }
  }
  const std::string path = Temp + "/streaming_large.tif";
  vtkNew<vtkTIFFWriter> writer;
  writer->SetInputData(image);
  writer->SetCompressionToNoCompression();
  writer->SetFileName(path.c_str());
  writer->Write();
  vtkGlobeTest::WriteGlobalWorldFile(Temp + "/streaming_large.tfw", w, h);
  image->Initialize(); // the 128 MiB source leaves memory before the flight
  // Prepared, as large rasters are meant to be: a plain file this size gets OpenImageIO's
  // automip, which reads the whole full-resolution image to make level 1 (measured: +181 MiB).
  const std::string prepared = Temp + "/streaming_large_prepared.tif";
  vtkNew<vtkGlobeRasterPreparer> preparer;
  preparer->SetInputFileName(path.c_str());
  preparer->SetFileName(prepared.c_str());
  Checks.Expect(preparer->Write(), "the 128 MiB raster prepared");

  vtkGlobeTest::Scene scene(200, 150, 128);
  vtkGlobePageCache* cache = scene.Mapper->GetPageCache();
  cache->SetPageSize(128);
  cache->SetGPUMemory(4.0);
  cache->SetCPUMemory(16.0);
  scene.Mapper->WaitForPagesOn();
  auto look = [&](int i) {
    const double lon = -170.0 + 15.0 * i, lat = -60.0 + 5.0 * i;
    const double camera[3] = { lon, lat, 300000.0 }, target[3] = { lon + 1.0, lat + 1.0, 0.0 };
    scene.Look(camera, target, 40.0, 1000.0, 3.0e6);
  };
  // The baseline: the same view rendered without the layer (the window, the passes, their
  // shaders), so loading the raster whole on the first frame would count.
  look(0);
  scene.Window->Render();
  const double before = vtkGlobeTest::ResidentMiB();
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetFileName(prepared.c_str());
  layer->SetRoleToHeight();
  layer->SetStreamingToOn();
  scene.Mapper->AddLayer(layer);
  double peak = before;
  for (int i = 0; i < 24; ++i)
  {
    look(i);
    scene.Window->Render();
    peak = std::max(peak, vtkGlobeTest::ResidentMiB());
  }
  const double growth = peak - before;
  const double gpu = static_cast<double>(cache->GetGPUMemoryUsed());
  std::printf("  128 MiB raster, 4 MiB GPU + 16 MiB CPU cache: %lld pages loaded, %lld evicted, "
              "RSS %.0f MiB without the layer, peak %.0f MiB with it (+%.1f MiB); GPU %.2f MiB\n",
    cache->GetNumberOfLoadedPages(), cache->GetNumberOfEvictedPages(), before, peak, growth,
    gpu / 1048576.0);
  scene.Mapper->RemoveAllLayers();
  cache->SetPageSize(64); // lets go of the file's readers before the files go
  for (const std::string& file : { path, prepared, Temp + "/streaming_large.tfw" })
  {
    std::remove(file.c_str()); // ~270 MB the build folder need not keep
  }
  Checks.Expect(layer->IsStreamed() && cache->GetNumberOfLoadedPages() > 100,
    "the 128 MiB raster streams (over 100 pages loaded)");
  Checks.Expect(cache->GetNumberOfEvictedPages() > 0, "the flight needed more pages than the GPU cache holds");
  // The caches (24 MiB) and OpenImageIO's tiles in flight; nothing proportional to the raster.
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer keeps freed blocks in quarantine (256 MiB) and adds shadow memory: RSS
  // measures it, not the caches. Judged in the normal build only.
  std::printf("  (not judged under AddressSanitizer) RSS grew by %.1f MiB\n", growth);
#else
  Checks.Expect(growth < 64.0, "RSS grows by less than 64 MiB while streaming 128 MiB");
#endif
  Checks.Expect(gpu <= 4.0 * 1048576.0 + 256.0 * 1024.0,
    "GPU memory within the 4 MiB cache (and the page tables)");
}
// One streamed layer that cannot be registered (here: its coarsest page finds no free slot)
// is skipped with one error, and the others go on streaming. Before, the cache restarted its
// reading threads every frame for want of that layer, dropping every read: no page beyond the
// pinned coarsest ones ever loaded, for any layer.
void OneLayerRefused(const std::string& image)
{
  vtkGlobeTest::Scene scene(64, 64, 64);
  scene.Mapper->LightingOff();
  vtkGlobePageCache* cache = scene.Mapper->GetPageCache();
  cache->SetPageSize(64);
  const double texels = 64.0 + 2.0 * vtkGlobePageCache::Border;
  cache->SetGPUMemory(4.5 * texels * texels * 4.0 / 1048576.0); // 4 slots per kind
  int errors = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&errors);
  count->SetCallback([](vtkObject*, unsigned long, void* n, void*) { ++*static_cast<int*>(n); });
  cache->AddObserver(vtkCommand::ErrorEvent, count);
  // Five height layers for four slots: the fifth coarsest page has no room.
  for (int i = 0; i < 5; ++i)
  {
    vtkNew<vtkGlobeLayer> relief;
    relief->SetFileName((std::string(VTKGLOBE_DATA_DIR) + "/earth/relief_2deg.tif").c_str());
    relief->SetRoleToHeight();
    relief->SetStreamingToOn();
    relief->SetName(("relief " + std::to_string(i)).c_str());
    scene.Mapper->AddLayer(relief);
  }
  vtkNew<vtkGlobeLayer> layer;
  layer->SetFileName(image.c_str());
  layer->SetRoleToColor();
  layer->SetStreamingToOn();
  scene.Mapper->AddLayer(layer);
  const double camera[3] = { -157.5, 67.5, 120000.0 }, target[3] = { -157.5, 67.5, 0.0 };
  scene.Look(camera, target, 30.0);
  int frames = 0;
  for (; frames < 300 && !(frames > 1 && scene.Mapper->IsStreamingIdle()); ++frames)
  {
    scene.Window->Render();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const long long loaded = cache->GetNumberOfLoadedPages();
  std::printf("  5 height layers and 1 image for 4 slots per kind: %d streamed layers composed, "
              "%d error(s), %lld pages loaded (5 pinned coarsest pages), idle after %d frames\n",
    scene.Mapper->GetLayerSet()->GetNumberOfStreamedLayers(), errors, loaded, frames);
  Checks.Expect(scene.Mapper->GetLayerSet()->GetNumberOfStreamedLayers() == 5,
    "the layer without room is skipped, the other five are composed");
  Checks.Expect(errors == 1, vtkGlobeTest::Printf("reported once (%d errors)", errors));
  Checks.Expect(loaded > 5 && frames < 300,
    "the other layers go on streaming (pages beyond the pinned ones load, the cache settles)");
  Checks.Expect(vtkGlobeTest::NoGLError(), "no OpenGL error with a refused layer");
}

// A raster with more pages along an axis than a page-table entry holds (65,535 columns at
// level 0: 1,048,577 texels wide in pages of 16): refused once, with an error that names the
// layer and the remedy; a streamed layer beside it goes on, and nothing else breaks.
void TooManyPages()
{
  const int w = 65536 * 16 + 1, h = 2;
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::memset(image->GetScalarPointer(), 128, static_cast<size_t>(w) * h * 3);
  const std::string path = Temp + "/streaming_too_wide.tif";
  vtkNew<vtkTIFFWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  vtkGlobeTest::WriteGlobalWorldFile(Temp + "/streaming_too_wide.tfw", w, h);

  vtkGlobeTest::Scene scene(64, 48, 32);
  vtkGlobePageCache* cache = scene.Mapper->GetPageCache();
  cache->SetPageSize(16);
  std::string said;
  int errors = 0;
  vtkNew<vtkCallbackCommand> record;
  std::pair<int*, std::string*> sink(&errors, &said);
  record->SetClientData(&sink);
  record->SetCallback([](vtkObject*, unsigned long, void* client, void* message) {
    auto* s = static_cast<std::pair<int*, std::string*>*>(client);
    ++*s->first;
    *s->second = message ? static_cast<const char*>(message) : "";
  });
  cache->AddObserver(vtkCommand::ErrorEvent, record);
  vtkNew<vtkGlobeLayer> relief;
  relief->SetFileName((std::string(VTKGLOBE_DATA_DIR) + "/earth/relief_2deg.tif").c_str());
  relief->SetRoleToHeight();
  relief->SetStreamingToOn();
  scene.Mapper->AddLayer(relief);
  vtkNew<vtkGlobeLayer> wide;
  wide->SetFileName(path.c_str());
  wide->SetName("too wide");
  wide->SetRoleToColor();
  wide->SetStreamingToOn();
  scene.Mapper->AddLayer(wide);
  const double camera[3] = { 10.0, 20.0, 2.0e7 }, target[3] = { 10.0, 20.0, 0.0 };
  scene.Look(camera, target, 40.0);
  for (int i = 0; i < 3; ++i)
  {
    scene.Window->Render();
  }
  const int covered = vtkGlobeTest::CoveredPixels(vtkGlobeTest::ReadDepth(scene.Window));
  std::printf("  a layer of %d x %d texels in pages of 16: %d error(s): %s; %d streamed layers "
              "composed, %d pixels covered\n",
    w, h, errors, said.c_str(), scene.Mapper->GetLayerSet()->GetNumberOfStreamedLayers(), covered);
  Checks.Expect(errors == 1 && said.find("too wide") != std::string::npos &&
      said.find("65537 x 1 pages") != std::string::npos &&
      said.find("raise PageSize") != std::string::npos,
    "a layer with more than 65,535 pages along an axis is refused once, naming it and the remedy");
  Checks.Expect(scene.Mapper->GetLayerSet()->GetNumberOfStreamedLayers() == 1 && covered > 500 &&
      vtkGlobeTest::NoGLError(),
    "the streamed layer beside it is composed, the globe renders, no OpenGL error");
}
} // namespace

int TestGlobeStreaming(int, char*[])
{
  const int pageSize = 64;
  const std::string path = WriteSelfEncoding(1024, 512);
  const Levels levels = ReadLevels(path, pageSize);
  std::printf("  self-encoding 1024 x 512, %zu levels of pages of %d^2\n", levels.W.size(), pageSize);
  // The reference levels come from the page source, as the GPU's pages do: its level 0 must be
  // the file's own texels, so a misregistered page source cannot pass as its own reference.
  int misread = 0;
  for (int y = 0; y < levels.H[0]; ++y)
  {
    for (int x = 0; x < levels.W[0]; ++x)
    {
      const std::array<int, 3> c = Code(x, y);
      const unsigned char* t = &levels.RGBA[0][4 * (static_cast<size_t>(y) * levels.W[0] + x)];
      misread += (t[0] != c[0] || t[1] != c[1] || t[2] != c[2]) ? 1 : 0;
    }
  }
  Checks.Expect(levels.W[0] == 1024 && levels.H[0] == 512 && misread == 0,
    "the page source's level 0 is the self-encoding texel for texel (" + std::to_string(misread) +
      " of 524,288 differ)");

  vtkGlobeTest::Scene scene(64, 64, 64);
  scene.Mapper->LightingOff();
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetFileName(path.c_str());
  layer->SetRoleToColor();
  layer->SetInterpolationToNearest();
  layer->SetStreamingToOn();
  scene.Mapper->AddLayer(layer);
  vtkGlobePageCache* cache = scene.Mapper->GetPageCache();
  cache->SetPageSize(pageSize);
  // 8 pages of (64 + 2 * 2)^2 RGBA texels.
  const double pageBytes = (pageSize + 2.0 * vtkGlobePageCache::Border) * (pageSize + 2.0 * vtkGlobePageCache::Border) * 4.0;
  cache->SetGPUMemory(8.5 * pageBytes / 1048576.0);

  struct View
  {
    const char* Name;
    double Lon, Lat, Height, TargetLat; // looking at (Lon, TargetLat) on the ground
    int Coarsest;                       // the coarsest ideal level the view must reach
  };
  // Magnified level 0 on a page corner, at the antimeridian, an oblique view (levels 0 to 3
  // towards the horizon) and the whole Earth (levels 2 to 4).
  const View views[] = { { "level 0, page corner", -180.0 + 22.5, 90.0 - 22.5, 120000.0, 67.5, 0 },
    { "antimeridian", 180.0, 10.0, 200000.0, 10.0, 0 },
    { "oblique", 40.0, -30.0, 600000.0, -18.0, 3 },
    { "whole Earth", -100.0, 45.0, 30000000.0, 45.0, 3 } };
  for (const View& v : views)
  {
    const double camera[3] = { v.Lon, v.Lat, v.Height }, target[3] = { v.Lon, v.TargetLat, 0.0 };
    scene.Look(camera, target, 30.0);
    int frames = 0, undefined = 0;
    FrameCheck settled;
    // Frames never wait for the readers: give them time, up to 10 s.
    for (; frames < 500; ++frames)
    {
      scene.Window->Render();
      const FrameCheck f = CheckFrame(scene, levels);
      undefined += f.Undefined;
      if (scene.Mapper->IsStreamingIdle() && frames > 1)
      {
        settled = f;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    std::printf("  %-22s settled after %2d frames: %d px, ideal levels %d-%d, %d undefined over "
                "all frames, %d at a level more than one from the ideal; %d slots, %d resident\n",
      v.Name, frames + 1, settled.Covered, settled.IdealLow, settled.IdealHigh, undefined,
      settled.WrongLevel, cache->GetNumberOfSlots(vtkGlobePageCache::Images),
      cache->GetNumberOfResidentPages());
    Checks.Expect(settled.Covered > 1000, std::string(v.Name) + ": the globe covers the view");
    Checks.Expect(settled.IdealHigh >= v.Coarsest,
      vtkGlobeTest::Printf("%s: the view reaches level %d", v.Name, v.Coarsest));
    Checks.Expect(undefined == 0, std::string(v.Name) + ": no frame shows an undefined texel");
    Checks.Expect(settled.Undefined == 0 && settled.WrongLevel == 0,
      std::string(v.Name) + ": settled, every pixel shows its texel within one level");

    // Settled means stable: no request or load over two more frames (a busy machine can still
    // be trading deferred pages for slots the view stopped using).
    long long requested = -1, loaded = -1;
    for (int i = 0; i < 100; ++i)
    {
      const long long r = cache->GetNumberOfRequestedPages(), l = cache->GetNumberOfLoadedPages();
      scene.Window->Render();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      scene.Window->Render();
      if (r == cache->GetNumberOfRequestedPages() && l == cache->GetNumberOfLoadedPages())
      {
        requested = r;
        loaded = l;
        break;
      }
    }
    // Then a move that needs no new page (1e-6 degrees, 0.1 m, far below a pixel) loads none.
    Checks.Expect(requested >= 0, std::string(v.Name) + ": the cache settles (no loads over two frames)");
    const double moved[3] = { v.Lon + 1e-6, v.Lat, v.Height };
    scene.Look(moved, target, 30.0);
    for (int i = 0; i < 3; ++i)
    {
      scene.Window->Render();
    }
    Checks.Expect(cache->GetNumberOfRequestedPages() == requested &&
        cache->GetNumberOfLoadedPages() == loaded,
      std::string(v.Name) + ": a move that needs no new page loads none");
  }
  Checks.Expect(cache->GetNumberOfSlots(vtkGlobePageCache::Images) == 8, "the cache has 8 slots");
  Checks.Expect(cache->GetNumberOfEvictedPages() > 0, "pages were evicted");
  const size_t atlasBytes = static_cast<size_t>(8 * pageBytes);
  Checks.Expect(cache->GetGPUMemoryUsed() <= atlasBytes + 64 * 1024,
    "GPU memory within the cache (8 pages and the page table)");
  Checks.Expect(vtkGlobeTest::NoGLError(), "no OpenGL error");

  OneLayerRefused(path);
  TooManyPages();
  MemoryBound();
  return Checks.Result();
}
