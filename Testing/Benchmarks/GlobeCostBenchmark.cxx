// What the frame costs against what it shows (issue "Cost proportional to what the frame
// shows"): three measurements, each comparing configurations within one run, in rounds that
// alternate them so that they share the machine's conditions. It prints tables and writes JSON.
//
//  layers   16 height insets, or 16 colour insets, all out of the view, added to the whole-Earth
//           and the Mount Rainier views: the frame with them against the frame without (the
//           layer set culls them; the column says how many it culled).
//  raster   the whole Earth with a global height and colour layer of 1024 x 512 against the same
//           function sampled at 16384 x 8192 (footprint-matched MIP levels make the frame
//           independent of the data's size).
//  filtering  footprint filtering against level 0 whatever the footprint (FootprintFiltering
//           off, the renderer before the filtering): the whole Earth at 1024 and 16384, and the
//           Data/earth layers in the whole-Earth and the Rainier views.
//  grid     the automatic grid (GridPixelsPerCell 1.6) at 400 x 300, 800 x 600 and 1600 x 1200
//           at Rainier, with a fixed 512^2 grid in the same windows.
//  interactive  the frames an interactor draws while the camera moves (AutoAdjustDetail: the
//           window's rate set to 1e6/s, so that no frame meets it) against still frames, at
//           Rainier in the same three windows.
//
// usage: GlobeCostBenchmark [--frames N] [--rounds R] [--json PATH] [--only NAME]
// Run it with GLIBC_TUNABLES=glibc.malloc.mmap_threshold=268435456:glibc.malloc.trim_threshold=536870912
// (llvmpipe frame times are bimodal under glibc's default malloc).
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeCompositePass.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeMapper.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace
{
int Frames = 12;
int Rounds = 3;

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// One configuration: a scene, made once, and what its row says.
struct Config
{
  std::string Section, Scene, Label;
  std::function<void(vtkGlobeTest::Scene&)> Setup;
  int Width = 800, Height = 600;
  std::unique_ptr<vtkGlobeTest::Scene> S;
  std::vector<double> RoundMedians; // ms
  int Culled = 0, Grid = 0, Layers = 0;
  double RasterMs = 0, CompositeMs = 0; // GPU stage times of the last frame (-1: no timers)
};

// Median frame time (ms) of `Frames` frames, each finished on the GPU.
double Time(vtkGlobeTest::Scene& scene)
{
  std::vector<double> ms;
  for (int i = 0; i < Frames; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    scene.Window->Render();
    glFinish();
    ms.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return Median(ms);
}

const double EarthCamera[3] = { -100.0, 40.0, 2.0e7 }, EarthTarget[3] = { -100.0, 40.0, 0.0 };
const double RainierCamera[3] = { -121.86, 46.75, 16000.0 };
const double RainierTarget[3] = { -121.7603, 46.8523, 4392.0 };

void Look(vtkGlobeTest::Scene& scene, const std::string& where)
{
  if (where == "earth")
  {
    scene.Look(EarthCamera, EarthTarget, 30.0);
  }
  else
  {
    scene.Look(RainierCamera, RainierTarget, 40.0, 20.0, 4.0e5);
  }
}

// 16 insets of 1 x 1 degree over central Asia (60..100 E, 30..50 N): on the far side of the
// whole-Earth view over North America and far outside the Rainier view.
void AddInsets(vtkGlobeTest::Scene& scene, bool height)
{
  const int n = 512;
  for (int k = 0; k < 16; ++k)
  {
    const double west = 60.0 + 10.0 * (k % 4), south = 30.0 + 5.0 * (k / 4);
    auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
    if (height)
    {
      std::vector<float> v(static_cast<size_t>(n) * n);
      for (int r = 0; r < n; ++r)
      {
        for (int c = 0; c < n; ++c)
        {
          v[static_cast<size_t>(r) * n + c] = 2000.0f + 500.0f * std::sin(0.05f * (r + c + k));
        }
      }
      layer->SetHeightData(n, n, v.data(), west, west + 1.0, south, south + 1.0);
    }
    else
    {
      std::vector<unsigned char> v(static_cast<size_t>(n) * n * 4);
      for (size_t i = 0; i < v.size(); ++i)
      {
        v[i] = (i % 4 == 3) ? 255 : static_cast<unsigned char>((i * 7 + k) % 256);
      }
      layer->SetColorData(n, n, 4, v.data(), west, west + 1.0, south, south + 1.0);
    }
    scene.Mapper->AddLayer(layer);
  }
}

// A global layer of w x h samples of one smooth function (heights in m, or an RGB pattern).
vtkSmartPointer<vtkGlobeLayer> GlobalLayer(int w, int h, bool height)
{
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  auto f = [](double lon, double lat) {
    return 3000.0 * std::sin(3.0 * lon) * std::cos(2.0 * lat) + 800.0 * std::sin(11.0 * lon + 7.0 * lat);
  };
  if (height)
  {
    std::vector<float> v(static_cast<size_t>(w) * h);
    for (int r = 0; r < h; ++r)
    {
      const double lat = vtkMath::RadiansFromDegrees(90.0 - (r + 0.5) * 180.0 / h);
      for (int c = 0; c < w; ++c)
      {
        const double lon = vtkMath::RadiansFromDegrees(-180.0 + (c + 0.5) * 360.0 / w);
        v[static_cast<size_t>(r) * w + c] = static_cast<float>(f(lon, lat));
      }
    }
    layer->SetHeightData(w, h, v.data(), -180.0, 180.0, -90.0, 90.0);
  }
  else
  {
    std::vector<unsigned char> v(static_cast<size_t>(w) * h * 4);
    for (int r = 0; r < h; ++r)
    {
      const double lat = vtkMath::RadiansFromDegrees(90.0 - (r + 0.5) * 180.0 / h);
      for (int c = 0; c < w; ++c)
      {
        const double lon = vtkMath::RadiansFromDegrees(-180.0 + (c + 0.5) * 360.0 / w);
        const double x = 0.5 + 0.5 * f(lon, lat) / 3800.0;
        unsigned char* p = v.data() + 4 * (static_cast<size_t>(r) * w + c);
        p[0] = static_cast<unsigned char>(255 * x);
        p[1] = static_cast<unsigned char>(255 * (1.0 - x));
        p[2] = static_cast<unsigned char>(128 + 127 * std::sin(20.0 * lon));
        p[3] = 255;
      }
    }
    layer->SetColorData(w, h, 4, v.data(), -180.0, 180.0, -90.0, 90.0);
  }
  return layer;
}

std::vector<Config> MakeConfigs(const std::string& only)
{
  std::vector<Config> configs;
  auto add = [&](const std::string& section, const std::string& scene, const std::string& label,
               std::function<void(vtkGlobeTest::Scene&)> setup, int w = 800, int h = 600) {
    if (!only.empty() && only != section)
    {
      return;
    }
    Config c;
    c.Section = section;
    c.Scene = scene;
    c.Label = label;
    c.Setup = std::move(setup);
    c.Width = w;
    c.Height = h;
    configs.push_back(std::move(c));
  };
  for (const std::string where : { "earth", "rainier" })
  {
    add("layers", where, "base layers", [](vtkGlobeTest::Scene& s) { s.AddEarthLayers(); });
    add("layers", where, "+16 height insets out of view", [](vtkGlobeTest::Scene& s) {
      s.AddEarthLayers();
      AddInsets(s, true);
    });
    add("layers", where, "+16 colour insets out of view", [](vtkGlobeTest::Scene& s) {
      s.AddEarthLayers();
      AddInsets(s, false);
    });
  }
  // Both small, both large, then one of each large: which of the two stages the size reaches.
  // 4096 x 2048 is the first size finer than the whole-Earth view's pixels (a pixel is about
  // 0.23 degrees at 800 x 600): from there on the frame reads the same MIP level sizes.
  for (const auto& size : std::vector<std::pair<int, int>>{ { 1024, 1024 }, { 4096, 4096 },
         { 16384, 16384 }, { 16384, 1024 }, { 1024, 16384 } })
  {
    const int hw = size.first, cw = size.second;
    add("raster", "earth",
      hw == cw ? std::to_string(hw) + " x " + std::to_string(hw / 2) + " heights + colour"
               : std::to_string(hw) + " heights, " + std::to_string(cw) + " colour",
      [hw, cw](vtkGlobeTest::Scene& s) {
        s.Mapper->AddLayer(GlobalLayer(hw, hw / 2, true));
        s.Mapper->AddLayer(GlobalLayer(cw, cw / 2, false));
      });
  }
  // Footprint filtering (Documentation/composition.md "Filtering to the footprint") against
  // level 0 whatever the footprint (the renderer before it): what the filtering costs, and
  // how much of the data's size reached the frame without it.
  for (const int size : { 1024, 16384 })
  {
    add("filtering", "earth", std::to_string(size) + " heights + colour, filtered",
      [size](vtkGlobeTest::Scene& s) {
        s.Mapper->AddLayer(GlobalLayer(size, size / 2, true));
        s.Mapper->AddLayer(GlobalLayer(size, size / 2, false));
      });
    add("filtering", "earth", std::to_string(size) + " heights + colour, level 0",
      [size](vtkGlobeTest::Scene& s) {
        s.Mapper->AddLayer(GlobalLayer(size, size / 2, true));
        s.Mapper->AddLayer(GlobalLayer(size, size / 2, false));
        s.Mapper->FootprintFilteringOff();
      });
  }
  for (const std::string where : { "earth", "rainier" })
  {
    add("filtering", where, "Data/earth layers, filtered", [](vtkGlobeTest::Scene& s) { s.AddEarthLayers(); });
    add("filtering", where, "Data/earth layers, level 0", [](vtkGlobeTest::Scene& s) {
      s.AddEarthLayers();
      s.Mapper->FootprintFilteringOff();
    });
  }
  for (const int w : { 400, 800, 1600 })
  {
    add("grid", "rainier", "automatic (1.6 px per cell)", [](vtkGlobeTest::Scene& s) {
      s.AddEarthLayers();
      s.Mapper->SetGridPixelsPerCell(1.6);
    }, w, w * 3 / 4);
    add("grid", "rainier", "fixed 512^2", [](vtkGlobeTest::Scene& s) { s.AddEarthLayers(); }, w,
      w * 3 / 4);
  }
  for (const int w : { 400, 800, 1600 })
  {
    add("interactive", "rainier", "still (full detail)", [](vtkGlobeTest::Scene& s) {
      s.AddEarthLayers();
      s.Mapper->SetGridPixelsPerCell(1.6);
    }, w, w * 3 / 4);
    // The first frames, before the full-detail frame is measured, are full detail: the
    // rounds' medians leave them out.
    add("interactive", "rainier", "moving (interactive detail)", [](vtkGlobeTest::Scene& s) {
      s.AddEarthLayers();
      s.Mapper->SetGridPixelsPerCell(1.6);
      s.Window->SetDesiredUpdateRate(1e6);
    }, w, w * 3 / 4);
  }
  return configs;
}
} // namespace

int main(int argc, char* argv[])
{
  std::string json = "cost.json", only;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--frames" && i + 1 < argc)
    {
      Frames = std::max(3, std::atoi(argv[++i]));
    }
    else if (a == "--rounds" && i + 1 < argc)
    {
      Rounds = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--json" && i + 1 < argc)
    {
      json = argv[++i];
    }
    else if (a == "--only" && i + 1 < argc)
    {
      only = argv[++i];
    }
    else
    {
      std::printf("usage: %s [--frames N] [--rounds R] [--json PATH] [--only layers|raster|filtering|grid|interactive]\n"
                  "  What the frame costs against what it shows: out-of-view insets, the data's\n"
                  "  size, the automatic grid (see the comment at the top of the source).\n",
        argv[0]);
      return a == "--help" ? 0 : 1;
    }
  }
  std::vector<Config> configs = MakeConfigs(only);
  for (Config& c : configs)
  {
    c.S.reset(new vtkGlobeTest::Scene(c.Width, c.Height, 512));
    c.Setup(*c.S);
    Look(*c.S, c.Scene);
    c.S->Render(); // loads and uploads
    c.S->Render();
  }
  for (int round = 0; round < Rounds; ++round)
  {
    for (Config& c : configs)
    {
      Look(*c.S, c.Scene);
      c.S->Window->Render();
      c.RoundMedians.push_back(Time(*c.S));
      c.Culled = c.S->Mapper->GetLayerSet()->GetNumberOfCulledLayers();
      c.Grid = c.S->Mapper->GetGridResolution();
      c.Layers = c.S->Mapper->GetNumberOfLayers();
      c.RasterMs = 1e3 * c.S->Mapper->GetRasterTime();
      c.CompositeMs = 1e3 * c.S->Mapper->GetCompositePass()->GetCompositeTime();
    }
    std::printf("round %d of %d done\n", round + 1, Rounds);
    std::fflush(stdout);
  }
  std::printf("\n%d frames per round, %d rounds, alternating; median of the round medians "
              "[range], ms\n\n| section | scene | window | configuration | layers (culled) | grid | "
              "frame ms | vs first of its group | G-buffer / composite GPU ms |\n"
              "|---|---|---|---|---|---|---|---|---|\n",
    Frames, Rounds);
  std::ofstream out(json);
  out << "{\n  \"frames\": " << Frames << ",\n  \"rounds\": " << Rounds << ",\n  \"rows\": [\n";
  const Config* first = nullptr;
  for (size_t i = 0; i < configs.size(); ++i)
  {
    const Config& c = configs[i];
    const bool newGroup = !first || first->Section != c.Section || first->Scene != c.Scene ||
      ((c.Section == "grid" || c.Section == "interactive") && first->Width != c.Width) ||
      (c.Section == "filtering" &&
        c.Label.substr(0, c.Label.find(',')) != first->Label.substr(0, first->Label.find(',')));
    if (newGroup)
    {
      first = &c;
    }
    const double ms = Median(c.RoundMedians);
    const auto range = std::minmax_element(c.RoundMedians.begin(), c.RoundMedians.end());
    const double ratio = ms / Median(first->RoundMedians);
    std::printf("| %s | %s | %dx%d | %s | %d (%d) | %d^2 | %.1f [%.1f-%.1f] | %s | %.1f / %.1f |\n",
      c.Section.c_str(), c.Scene.c_str(), c.Width, c.Height, c.Label.c_str(), c.Layers, c.Culled,
      c.Grid, ms, *range.first, *range.second,
      newGroup ? "" : vtkGlobeTest::Printf("%+.1f %%", 100.0 * (ratio - 1.0)).c_str(), c.RasterMs,
      c.CompositeMs);
    out << "    {\"section\": \"" << c.Section << "\", \"scene\": \"" << c.Scene
        << "\", \"window\": [" << c.Width << ", " << c.Height << "], \"configuration\": \""
        << c.Label << "\", \"layers\": " << c.Layers << ", \"culled\": " << c.Culled
        << ", \"grid\": " << c.Grid << ", \"raster_gpu_ms\": " << c.RasterMs
        << ", \"composite_gpu_ms\": " << c.CompositeMs << ", \"ms\": " << ms << ", \"round_ms\": [";
    for (size_t r = 0; r < c.RoundMedians.size(); ++r)
    {
      out << (r ? ", " : "") << c.RoundMedians[r];
    }
    out << "], \"ratio_to_group_first\": " << ratio << "}" << (i + 1 < configs.size() ? "," : "")
        << "\n";
  }
  out << "  ]\n}\n";
  std::printf("\nJSON: %s\n", json.c_str());
  return 0;
}
