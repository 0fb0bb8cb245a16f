// GlobeStreamingBenchmark: what streaming costs (after Kooima's thesis, section 5.1). A scripted
// flight from a whole-Earth view down to a close-up of Mount Rainier and back, starting with an
// empty cache, over global height and imagery layers (GlobeMakePlanet's) plus the real 90 m
// Rainier inset; each data set given runs streamed, and those small enough also in-core (after
// the streamed run, so that its whole-file reads warm neither the file cache nor the heap of
// the streamed run), in the same process, with the same camera path. A program, not a test:
// it prints a table and writes JSON; Utilities/plot_streaming.py plots it
// (`bash Utilities/globe.sh bench-streaming`).
//
//   GlobeStreamingBenchmark --data DATA_DIR --planet WIDTH:HEIGHTS.tif:IMAGERY.tif ...
//       [--frames 240] [--window 640x480] [--grid 256] [--gpu 120] [--incore-max 8192]
//       [--interleaved-only] [--json PATH]
//
// Per block of 10 frames: median frame time (Render + glFinish, wall clock); the camera's
// height at the block's last frame; pages loaded and evicted and bytes uploaded in the block;
// CPU memory (VmRSS), GPU layer memory (vtkGlobeLayerSet::GetTextureMemory: textures, or the
// page atlases as allocated and the tables) and the GPU memory of the resident pages, at its
// end; and, for a streamed run whose data also ran in-core, the mean absolute RGB difference
// of the block's last frame from the in-core frame (0..255). Also: the first frame's time,
// and the steady frame time: the median over frames 5/12 to 7/12 of the flight (the close-up,
// cache warm) and its last sixth (far, warm). Frames never wait for pages
// (vtkGlobeMapper::WaitForPages off): the picture refines over the following frames, as in an
// interactive application. Then, for data that ran both ways, the two fly again interleaved
// (frame i streamed, frame i in-core, ...) for a ratio that a changing load on the machine
// does not bias; `--interleaved-only` runs that part alone.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeCompositePass.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobePageCache.h"
#include "vtkGlobeRasterReader.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Planet
{
  int Width = 0;
  std::string Heights, Imagery;
};

struct Block
{
  int Frame = 0;
  double Ms = 0, Altitude = 0;
  long long Loaded = 0, Evicted = 0, Uploaded = 0;
  double RSS = 0, GPU = 0, Resident = 0, Error = -1;
};

// The OpenGL renderer, read while a context is current.
std::string Renderer = "unknown";

struct Run
{
  std::string Label, Mode;
  int Width = 0;
  double FirstMs = 0, SteadyMs = 0, PeakRSS = 0, PeakGPU = 0;
  // Streamed runs with an in-core twin: the interleaved flight (FlyPaired); 0 without.
  double PairedMs = 0, PairedIncoreMs = 0, PairedRatio = 0, PairedCpuRatio = 0;
  std::vector<Block> Blocks;
  std::vector<double> Frames;
};

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0;
  }
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The camera at frame i of n: down from 20,000 km over Rainier to 6 km above its flank, looking
// at the summit (altitude log-linear, tilt growing near the ground), then back up. Gives the
// camera's height above the ellipsoid.
double Place(vtkGlobeTest::Scene& scene, int i, int n)
{
  const double half = 0.5 * (n - 1);
  const double t = i <= half ? i / half : (n - 1 - i) / half; // 0 far .. 1 near
  const double altitude = std::exp(std::log(2.0e7) + t * (std::log(6000.0) - std::log(2.0e7)));
  const double summit[3] = { -121.7603, 46.8523, 4392.0 };
  // Offset south-west with height, so the close-up looks across the mountain.
  const double back = std::min(1.0, altitude / 40000.0);
  const double camera[3] = { summit[0] - 0.25 * (1.0 - back), summit[1] - 0.2 * (1.0 - back),
    altitude + (1.0 - back) * 2000.0 };
  scene.Look(camera, summit, 40.0);
  return camera[2];
}

// The flight's layers: the planet's heights and imagery, and the Rainier inset (whole).
void AddLayers(vtkGlobeMapper* mapper, const std::string& data, const Planet& planet, bool streamed)
{
  auto add = [&](const std::string& file, bool height) {
    auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
    layer->SetFileName(file.c_str());
    if (height)
    {
      layer->SetRoleToHeight();
    }
    else
    {
      layer->SetRoleToColor();
    }
    layer->SetStreaming(streamed ? vtkGlobeLayer::StreamingOn : vtkGlobeLayer::StreamingOff);
    layer->GetFileReader()->SetMaximumMemory(16384);
    mapper->AddLayer(layer);
  };
  add(planet.Heights, true);
  add(data + "/earth/mt_rainier_90m.tif", true);
  add(planet.Imagery, false);
}

// The steady frames of a flight: the middle (the close-up, cache warm) and the last sixth
// (far, warm).
std::vector<double> Steady(const std::vector<double>& ms, int frames)
{
  std::vector<double> steady(ms.begin() + frames * 5 / 12, ms.begin() + frames * 7 / 12);
  steady.insert(steady.end(), ms.end() - frames / 6, ms.end());
  return steady;
}

Run Fly(const std::string& data, const Planet& planet, bool streamed, int frames, int w, int h,
  int grid, double gpu, std::vector<std::vector<unsigned char>>& images)
{
  Run run;
  run.Width = planet.Width;
  run.Mode = streamed ? "streamed" : "in-core";
  run.Label = run.Mode + " " + std::to_string(planet.Width);
  vtkGlobeTest::Scene scene(w, h, grid);
  vtkGlobeMapper* mapper = scene.Mapper;
  mapper->GetPageCache()->SetGPUMemory(gpu);
  AddLayers(mapper, data, planet, streamed);
  vtkRenderWindow* window = scene.Window;
  vtkGlobePageCache* cache = mapper->GetPageCache();
  Block block;
  std::vector<double> times;
  long long loaded = 0, evicted = 0, uploaded = 0;
  for (int i = 0; i < frames; ++i)
  {
    const double altitude = Place(scene, i, frames);
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    run.Frames.push_back(ms);
    if (i == 0)
    {
      run.FirstMs = ms;
      if (const auto* name = glGetString(GL_RENDERER))
      {
        Renderer = reinterpret_cast<const char*>(name);
      }
    }
    times.push_back(ms);
    if (i % 10 == 9 || i + 1 == frames)
    {
      block.Frame = i + 1;
      block.Ms = Median(times);
      block.Altitude = altitude;
      block.Loaded = cache->GetNumberOfLoadedPages() - loaded;
      block.Evicted = cache->GetNumberOfEvictedPages() - evicted;
      block.Uploaded = cache->GetBytesUploaded() - uploaded;
      loaded = cache->GetNumberOfLoadedPages();
      evicted = cache->GetNumberOfEvictedPages();
      uploaded = cache->GetBytesUploaded();
      block.RSS = vtkGlobeTest::ResidentMiB();
      block.GPU = mapper->GetLayerSet()->GetTextureMemory() / 1048576.0;
      const double pageTexels = cache->GetPageSize() + 2.0 * vtkGlobePageCache::Border;
      block.Resident = cache->GetNumberOfResidentPages() * pageTexels * pageTexels * 4.0 / 1048576.0;
      run.PeakRSS = std::max(run.PeakRSS, block.RSS);
      run.PeakGPU = std::max(run.PeakGPU, block.GPU);
      images.push_back(vtkGlobeTest::ReadPixels(window));
      run.Blocks.push_back(block);
      times.clear();
    }
  }
  run.SteadyMs = Median(Steady(run.Frames, frames));
  return run;
}

// Streamed against in-core with the frames interleaved: both scenes fly the same path, frame i
// streamed then frame i in-core, so a load that comes and goes on the machine weighs on both
// alike (the runs above follow each other, and spread by about +-10 % on a quiet machine).
// Gives the steady frame times of both and the median of the per-frame ratios.
// Also the process's CPU time per frame (every thread: llvmpipe's included), which another
// load on the machine inflates much less than wall-clock time.
struct Paired
{
  double StreamedMs = 0, IncoreMs = 0, Ratio = 0;
  double StreamedCpuMs = 0, IncoreCpuMs = 0, CpuRatio = 0;
  // Median steady GPU time per stage (the mapper's timer queries): PGM, height, raster,
  // composite, reduction; [0] streamed, [1] in-core. -1 where the driver gave none.
  double Stages[2][5] = { { -1, -1, -1, -1, -1 }, { -1, -1, -1, -1, -1 } };
};

const char* const StageNames[5] = { "pgm", "height", "raster", "composite", "reduction" };

double CpuMs()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

Paired FlyPaired(const std::string& data, const Planet& planet, int frames, int w, int h, int grid,
  double gpu)
{
  vtkGlobeTest::Scene streamed(w, h, grid), incore(w, h, grid);
  streamed.Mapper->GetPageCache()->SetGPUMemory(gpu);
  AddLayers(streamed.Mapper, data, planet, true);
  AddLayers(incore.Mapper, data, planet, false);
  std::vector<double> a, b, ca, cb;
  std::vector<double> stages[2][5];
  for (int i = 0; i < frames; ++i)
  {
    for (vtkGlobeTest::Scene* scene : { &streamed, &incore })
    {
      const int k = scene == &streamed ? 0 : 1;
      Place(*scene, i, frames);
      const double cpu = CpuMs();
      const auto start = std::chrono::steady_clock::now();
      scene->Window->Render();
      glFinish();
      (scene == &streamed ? a : b)
        .push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      (scene == &streamed ? ca : cb).push_back(CpuMs() - cpu);
      // From the most recent frame whose timer queries are done, hence a frame or two late:
      // steady frames only, where that does not matter.
      vtkGlobeMapper* m = scene->Mapper;
      const double s[5] = { m->GetGridPass()->GetPGMTime(), m->GetGridPass()->GetHeightTime(),
        m->GetRasterTime(), m->GetCompositePass()->GetCompositeTime(), m->GetReductionTime() };
      for (int j = 0; j < 5; ++j)
      {
        stages[k][j].push_back(1e3 * s[j]);
      }
    }
  }
  auto ratio = [frames](const std::vector<double>& x, const std::vector<double>& y) {
    const std::vector<double> sx = Steady(x, frames), sy = Steady(y, frames);
    std::vector<double> r;
    for (size_t k = 0; k < sx.size(); ++k)
    {
      r.push_back(sx[k] / sy[k]);
    }
    return Median(r);
  };
  Paired p;
  p.StreamedMs = Median(Steady(a, frames));
  p.IncoreMs = Median(Steady(b, frames));
  p.Ratio = ratio(a, b);
  p.StreamedCpuMs = Median(Steady(ca, frames));
  p.IncoreCpuMs = Median(Steady(cb, frames));
  p.CpuRatio = ratio(ca, cb);
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 5; ++j)
    {
      std::vector<double> steady = Steady(stages[k][j], frames);
      steady.erase(std::remove_if(steady.begin(), steady.end(), [](double v) { return v < 0; }),
        steady.end());
      p.Stages[k][j] = steady.empty() ? -1.0 : Median(steady);
    }
  }
  return p;
}
} // namespace

int main(int argc, char* argv[])
{
  std::string data, json;
  std::vector<Planet> planets;
  int frames = 240, w = 640, h = 480, grid = 256, incoreMax = 8192;
  bool interleavedOnly = false;
  double gpu = 120.0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (arg == "--data")
    {
      data = next();
    }
    else if (arg == "--planet")
    {
      std::stringstream s(next());
      Planet p;
      std::string width;
      std::getline(s, width, ':');
      std::getline(s, p.Heights, ':');
      std::getline(s, p.Imagery, ':');
      p.Width = std::atoi(width.c_str());
      planets.push_back(p);
    }
    else if (arg == "--frames")
    {
      frames = std::max(20, std::atoi(next().c_str()));
    }
    else if (arg == "--window")
    {
      std::sscanf(next().c_str(), "%dx%d", &w, &h);
    }
    else if (arg == "--grid")
    {
      grid = std::atoi(next().c_str());
    }
    else if (arg == "--gpu")
    {
      gpu = std::atof(next().c_str());
    }
    else if (arg == "--incore-max")
    {
      incoreMax = std::atoi(next().c_str());
    }
    else if (arg == "--interleaved-only")
    {
      interleavedOnly = true;
    }
    else if (arg == "--json")
    {
      json = next();
    }
    else
    {
      std::fprintf(stderr,
        "usage: GlobeStreamingBenchmark --data DIR --planet WIDTH:HEIGHTS:IMAGERY ... [--frames N] "
        "[--window WxH] [--grid N] [--gpu MiB] [--incore-max W] [--interleaved-only] [--json PATH]\n");
      return 2;
    }
  }
  if (data.empty() || planets.empty())
  {
    std::fprintf(stderr, "GlobeStreamingBenchmark: --data and at least one --planet are needed\n");
    return 2;
  }
  std::vector<Run> runs;
  auto print = [](const Run& r) {
    std::printf("%-16s first %7.0f ms, steady %6.1f ms, peak RSS %6.0f MiB, GPU %6.1f MiB\n",
      r.Label.c_str(), r.FirstMs, r.SteadyMs, r.PeakRSS, r.PeakGPU);
  };
  auto printStages = [](const Paired& q) {
    std::printf("  GPU stages, steady medians (ms), streamed / in-core:");
    for (int j = 0; j < 5; ++j)
    {
      std::printf(" %s %.1f / %.1f%s", StageNames[j], q.Stages[0][j], q.Stages[1][j], j < 4 ? "," : "\n");
    }
  };
  for (const Planet& p : planets)
  {
    if (interleavedOnly)
    {
      const Paired q = FlyPaired(data, p, frames, w, h, grid, gpu);
      std::printf("%d wide, interleaved: steady %.1f ms streamed, %.1f ms in-core, median ratio "
                  "%.3f; CPU time %.1f ms / %.1f ms, ratio %.3f\n",
        p.Width, q.StreamedMs, q.IncoreMs, q.Ratio, q.StreamedCpuMs, q.IncoreCpuMs, q.CpuRatio);
      printStages(q);
      continue;
    }
    std::vector<std::vector<unsigned char>> streamedImages, incoreImages;
    runs.push_back(Fly(data, p, true, frames, w, h, grid, gpu, streamedImages));
    const size_t streamedRun = runs.size() - 1;
    if (p.Width <= incoreMax)
    {
      runs.push_back(Fly(data, p, false, frames, w, h, grid, gpu, incoreImages));
      print(runs.back());
      // The streamed run's blocks against the in-core frames.
      for (size_t k = 0; k < runs[streamedRun].Blocks.size() && k < incoreImages.size(); ++k)
      {
        const std::vector<unsigned char>& a = streamedImages[k];
        const std::vector<unsigned char>& b = incoreImages[k];
        double sum = 0;
        for (size_t q = 0; q < a.size() && q < b.size(); ++q)
        {
          sum += std::abs(static_cast<int>(a[q]) - static_cast<int>(b[q]));
        }
        runs[streamedRun].Blocks[k].Error = a.empty() ? -1.0 : sum / a.size();
      }
    }
    const Run& r = runs[streamedRun];
    print(r);
    if (p.Width <= incoreMax)
    {
      const Paired q = FlyPaired(data, p, frames, w, h, grid, gpu);
      runs[streamedRun].PairedMs = q.StreamedMs;
      runs[streamedRun].PairedIncoreMs = q.IncoreMs;
      runs[streamedRun].PairedRatio = q.Ratio;
      runs[streamedRun].PairedCpuRatio = q.CpuRatio;
      std::printf("  interleaved with in-core: steady %.1f ms streamed, %.1f ms in-core, "
                  "median ratio %.3f; CPU time %.1f ms / %.1f ms, ratio %.3f\n",
        q.StreamedMs, q.IncoreMs, q.Ratio, q.StreamedCpuMs, q.IncoreCpuMs, q.CpuRatio);
      printStages(q);
    }
    std::printf("  %6s %10s %8s %7s %7s %9s %8s %8s %9s %6s\n", "frames", "height m", "ms",
      "loaded", "evicted", "uploaded", "RSS", "GPU", "resident", "error");
    for (const Block& b : r.Blocks)
    {
      std::printf("  %6d %10.0f %8.1f %7lld %7lld %8.1fM %7.0fM %7.1fM %8.1fM %6s\n", b.Frame,
        b.Altitude, b.Ms, b.Loaded, b.Evicted, b.Uploaded / 1048576.0, b.RSS, b.GPU, b.Resident,
        b.Error < 0 ? "-" : std::to_string(b.Error).substr(0, 5).c_str());
    }
  }
  if (!json.empty())
  {
    std::ofstream out(json);
    out << "{\"benchmark\": \"GlobeStreamingBenchmark\", \"frames\": " << frames
        << ", \"window\": [" << w << ", " << h << "], \"grid\": " << grid << ", \"gpu_cache_mib\": " << gpu
        << ", \"gl_renderer\": \"" << Renderer << "\", \"runs\": [";
    for (size_t i = 0; i < runs.size(); ++i)
    {
      const Run& r = runs[i];
      out << (i ? ", " : "") << "{\"label\": \"" << r.Label << "\", \"mode\": \"" << r.Mode
          << "\", \"width\": " << r.Width << ", \"first_ms\": " << r.FirstMs
          << ", \"steady_ms\": " << r.SteadyMs << ", \"peak_rss_mib\": " << r.PeakRSS
          << ", \"peak_gpu_mib\": " << r.PeakGPU;
      if (r.PairedRatio > 0)
      {
        out << ", \"interleaved\": {\"streamed_steady_ms\": " << r.PairedMs
            << ", \"incore_steady_ms\": " << r.PairedIncoreMs << ", \"ratio\": " << r.PairedRatio
            << ", \"cpu_time_ratio\": " << r.PairedCpuRatio << "}";
      }
      out << ", \"frame_ms\": [";
      for (size_t k = 0; k < r.Frames.size(); ++k)
      {
        out << (k ? ", " : "") << r.Frames[k];
      }
      out << "], \"blocks\": [";
      for (size_t k = 0; k < r.Blocks.size(); ++k)
      {
        const Block& b = r.Blocks[k];
        out << (k ? ", " : "") << "{\"frame\": " << b.Frame << ", \"altitude_m\": " << b.Altitude
            << ", \"ms\": " << b.Ms << ", \"loaded\": " << b.Loaded << ", \"evicted\": " << b.Evicted
            << ", \"uploaded_bytes\": " << b.Uploaded << ", \"rss_mib\": " << b.RSS
            << ", \"gpu_mib\": " << b.GPU << ", \"resident_gpu_mib\": " << b.Resident
            << ", \"error\": " << (b.Error < 0 ? std::string("null") : std::to_string(b.Error))
            << "}";
      }
      out << "]}";
    }
    out << "]}\n";
    std::printf("wrote %s\n", json.c_str());
  }
  return 0;
}
