// GlobeSoak: a long run for what single tests miss (the reliability issue's soak program; a
// program, not a timed test). Two phases over the Earth's layers (2-degree relief, the Rainier
// and Everest insets, Blue Marble streamed in pages of 64 through a 2 MiB page cache, so pages
// churn too):
//   cameras  N random cameras (default 1,000): random place, height log-uniform from 2 m to
//            40,000 km above the composed terrain, looking at a random point of the visible
//            globe (every frame should draw the globe);
//   churn    M frames (default 200) that each change the scene at random: a layer enabled or
//            disabled, an opacity, a layer removed and added back, an effect (lighting,
//            atmosphere, graticule, contours, night lights, specular water) on or off, the grid
//            resolution (128 / 256), the page size (64 / 128: the page cache empties).
// Every frame: OpenGL errors; NaN or Inf in the depth buffer, NaN in the G-buffer; whether the
// globe was drawn (the mapper says so and the depth buffer has terrain). RSS (VmRSS) every 10
// frames; after a warm-up (the first 100 frames of a phase, or its first half when shorter)
// the spread of RSS must stay within 5 %, over at least 2 samples. Prints a table and writes
// JSON.
//
//   GlobeSoak [--cameras N] [--churn M] [--window WxH] [--seed S] [--json PATH] [--no-rss]
// --no-rss: report RSS but do not judge it (runs too short for a warm-up, as Soak.Short).
// (GLOBE_SOAK_TRACE=1 prints each churn action, to find the frame a failure follows.)
#include "vtkGlobeRenderingTestHelpers.h"

#include "vtkGlobePageCache.h"
#include "vtkGlobeTestHelpers.h"

#include <chrono>
#include <fstream>
#include <random>

namespace
{
struct Phase
{
  std::string Name;
  int Frames = 0, Planned = 0, GLErrors = 0, NaNFrames = 0, ShouldDraw = 0, Missed = 0;
  std::vector<std::pair<int, double>> RSS; // (frame, MiB)
  double Seconds = 0;
  // The spread of RSS after the warm-up, (max - min) / min; -1 with fewer than 2 samples
  // there (nothing measured: a failure, not a pass).
  double Spread() const
  {
    const int warmup = std::min(100, this->Planned / 2);
    double lo = 1e300, hi = 0;
    int samples = 0;
    for (const auto& r : this->RSS)
    {
      if (r.first > warmup)
      {
        lo = std::min(lo, r.second);
        hi = std::max(hi, r.second);
        ++samples;
      }
    }
    return samples >= 2 ? (hi - lo) / lo : -1.0;
  }
  bool RSSFlat() const { return this->Planned == 0 || (this->Spread() >= 0.0 && this->Spread() <= 0.05); }
};

// Renders a frame and checks it (every frame of the soak looks at the globe from outside).
void Frame(vtkGlobeTest::Scene& scene, Phase& phase)
{
  scene.Window->Render();
  ++phase.Frames;
  phase.GLErrors += vtkGlobeTest::NoGLError() ? 0 : 1;
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  bool bad = vtkGlobeTest::CountNaN(vtkGlobeTest::ReadTexture(vtkGlobeMapperTesting::GetGBufferTexture(scene.Mapper))) > 0;
  for (float d : depth)
  {
    bad |= !std::isfinite(d);
  }
  phase.NaNFrames += bad ? 1 : 0;
  ++phase.ShouldDraw;
  const bool drawn = scene.Mapper->GetLastFrameDrewGlobe() && vtkGlobeTest::CoveredPixels(depth) > 0;
  phase.Missed += drawn ? 0 : 1;
  if (phase.Frames % 10 == 0)
  {
    phase.RSS.emplace_back(phase.Frames, vtkGlobeTest::ResidentMiB());
  }
}

void Print(const Phase& p)
{
  std::printf("%-8s %6d frames in %6.1f s: GL errors %d, frames with NaN/Inf depth or NaN "
              "G-buffer %d, globe missed %d of %d; RSS spread after warm-up %.2f %% (",
    p.Name.c_str(), p.Frames, p.Seconds, p.GLErrors, p.NaNFrames, p.Missed, p.ShouldDraw,
    100.0 * p.Spread());
  for (const auto& r : p.RSS)
  {
    std::printf("%s%.0f", &r == &p.RSS.front() ? "" : " ", r.second);
  }
  std::printf(" MiB, every 10 frames)\n");
}
} // namespace

int main(int argc, char* argv[])
{
  int cameras = 1000, churn = 200, w = 200, h = 150;
  unsigned seed = 12345;
  std::string json;
  bool judgeRSS = true;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (arg == "--cameras")
    {
      cameras = std::max(0, std::atoi(next().c_str()));
    }
    else if (arg == "--churn")
    {
      churn = std::max(0, std::atoi(next().c_str()));
    }
    else if (arg == "--window")
    {
      std::sscanf(next().c_str(), "%dx%d", &w, &h);
    }
    else if (arg == "--seed")
    {
      seed = static_cast<unsigned>(std::atoi(next().c_str()));
    }
    else if (arg == "--json")
    {
      json = next();
    }
    else if (arg == "--no-rss")
    {
      judgeRSS = false;
    }
    else
    {
      std::fprintf(stderr, "usage: GlobeSoak [--cameras N] [--churn M] [--window WxH] [--seed S] [--json PATH] [--no-rss]\n");
      return 2;
    }
  }
  vtkGlobeTest::Scene scene(w, h, 256);
  scene.AddEarthLayers(true, false);
  auto imagery = vtkGlobeTest::FileLayer("earth/world.tif", false);
  imagery->SetStreamingToOn();
  scene.Mapper->AddLayer(imagery);
  vtkGlobePageCache* cache = scene.Mapper->GetPageCache();
  cache->SetPageSize(64);
  cache->SetGPUMemory(2.0);
  std::mt19937 random(seed);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(random); };

  // Phase 1: random cameras.
  Phase one;
  one.Name = "cameras";
  one.Planned = cameras;
  auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < cameras; ++i)
  {
    const double lon = uniform(-180, 180), lat = std::asin(uniform(-1, 1)) * 180 / vtkMath::Pi();
    // Above the composed terrain (a camera under it rightly draws nothing: TestGlobeInsideBody).
    bool exact = false;
    const double ground =
      std::max(0.0, vtkGlobeClippingRange::ComputeTerrainHeight(scene.Mapper, lon, lat, exact));
    const double height = ground + std::exp(uniform(std::log(2.0), std::log(4.0e7)));
    // A target on the visible globe: within the horizon's angular radius of the sub-point.
    const double a = scene.Body->GetMaximumRadius();
    const double reach = std::acos(a / (a + height)) * 180 / vtkMath::Pi();
    const double bearing = uniform(0, 2 * vtkMath::Pi()), distance = uniform(0, 0.9) * reach;
    const double target[3] = { lon + distance * std::sin(bearing) / std::max(0.05, std::cos(lat * vtkMath::Pi() / 180)),
      std::max(-89.9, std::min(89.9, lat + distance * std::cos(bearing))), 0.0 };
    const double camera[3] = { lon, lat, height };
    scene.Look(camera, target, 40.0);
    Frame(scene, one);
  }
  one.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Print(one);

  // Phase 2: churn, from a fixed set of views.
  Phase two;
  two.Name = "churn";
  two.Planned = churn;
  const double views[3][6] = { { 0, 0, 2.0e7, 0, 0, 0 }, { -121.86, 46.75, 16000.0, -121.7603, 46.8523, 4392.0 },
    { 86.6, 27.6, 30000.0, 86.925, 27.99, 8000.0 } };
  std::vector<vtkSmartPointer<vtkGlobeLayer>> layers;
  for (int i = 0; i < scene.Mapper->GetNumberOfLayers(); ++i)
  {
    layers.emplace_back(scene.Mapper->GetLayer(i));
  }
  start = std::chrono::steady_clock::now();
  for (int i = 0; i < churn; ++i)
  {
    const double* v = views[i % 3];
    scene.Look(v, v + 3, 40.0);
    vtkGlobeLayer* layer = layers[random() % layers.size()];
    const unsigned action = random() % 8;
    if (std::getenv("GLOBE_SOAK_TRACE"))
    {
      std::fprintf(stderr, "churn %d: action %u on %s\n", i, action, layer->GetName());
    }
    switch (action)
    {
      case 0:
        layer->SetEnabled(!layer->GetEnabled());
        break;
      case 1:
        layer->SetOpacity(uniform(0, 1));
        break;
      case 2:
        scene.Mapper->RemoveLayer(layer);
        scene.Mapper->AddLayer(layer);
        break;
      case 3:
        scene.Mapper->SetAtmosphere(!scene.Mapper->GetAtmosphere());
        break;
      case 4:
        scene.Mapper->SetGraticule(!scene.Mapper->GetGraticule());
        scene.Mapper->SetContours(random() % 2 == 0);
        break;
      case 5:
        scene.Mapper->SetLighting(!scene.Mapper->GetLighting());
        scene.Mapper->SetNightLights(random() % 2 == 0);
        scene.Mapper->SetSpecularWater(random() % 2 == 0);
        break;
      case 6:
        scene.Mapper->SetGridResolution(random() % 2 ? 128 : 256);
        break;
      default:
        cache->SetPageSize(random() % 2 ? 64 : 128);
    }
    Frame(scene, two);
  }
  two.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Print(two);
  std::printf("page cache: %lld pages loaded, %lld evicted, %lld deferred\n",
    cache->GetNumberOfLoadedPages(), cache->GetNumberOfEvictedPages(), cache->GetNumberOfDeferredPages());

  if (!json.empty())
  {
    std::ofstream out(json);
    out << "{\"benchmark\": \"GlobeSoak\", \"seed\": " << seed << ", \"window\": [" << w << ", " << h
        << "], \"phases\": [";
    for (const Phase* p : { &one, &two })
    {
      out << (p == &one ? "" : ", ") << "{\"name\": \"" << p->Name << "\", \"frames\": " << p->Frames
          << ", \"seconds\": " << p->Seconds << ", \"gl_errors\": " << p->GLErrors
          << ", \"nan_depth_frames\": " << p->NaNFrames << ", \"should_draw\": " << p->ShouldDraw
          << ", \"missed\": " << p->Missed << ", \"rss_spread_after_warmup\": " << p->Spread()
          << ", \"rss_mib\": [";
      for (size_t k = 0; k < p->RSS.size(); ++k)
      {
        out << (k ? ", " : "") << "[" << p->RSS[k].first << ", " << p->RSS[k].second << "]";
      }
      out << "]}";
    }
    out << "]}\n";
  }
  const bool ok = one.GLErrors + two.GLErrors + one.NaNFrames + two.NaNFrames + one.Missed + two.Missed == 0 &&
    (!judgeRSS || (one.RSSFlat() && two.RSSFlat()));
  std::printf("%s\n", !ok ? "soak: FAILURES (see above)"
                           : judgeRSS ? "soak: no failure, RSS flat within 5 %"
                                      : "soak: no failure (RSS not judged)");
  return ok ? 0 : 1;
}
