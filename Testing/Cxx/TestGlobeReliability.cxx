// Reliability defects (issue 16): one extreme height must not blank the globe; layers removed
// by observers while they load must not crash; a failing layer is reported once, not every
// frame, and a file rewritten on disk is re-read; cameras that leave nothing to see (inside the
// body, 1e15 m away, focal point at the eye, view-up along the view) are reported once each.
// Every case also checks: no GL error, no NaN in the depth buffer, the rest of the scene draws.
#include "vtkCallbackCommand.h"
#include "vtkConeSource.h"
#include "vtkFloatArray.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeRasterReader.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

namespace
{
vtkGlobeTest::Checklist Checks;
using vtkGlobeTest::Printf;

// Every error and warning message of the objects it observes.
class Messages : public vtkCommand
{
public:
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Texts.emplace_back(data ? static_cast<const char*>(data) : "");
  }
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  int Count(const std::string& needle) const
  {
    int n = 0;
    for (const std::string& t : this->Texts)
    {
      n += t.find(needle) != std::string::npos ? 1 : 0;
    }
    return n;
  }
  void Print() const
  {
    for (const std::string& t : this->Texts)
    {
      const size_t at = t.find("): ");
      std::printf("       | %s\n", (at == std::string::npos ? t : t.substr(at + 3)).substr(0, 150).c_str());
    }
  }
  std::vector<std::string> Texts;
};

// Frame-level health: no GL error, no NaN depth; how many pixels something covers.
struct Frame
{
  bool GLOk = true;
  bool DepthOk = true;
  int Covered = 0;
};

Frame Look(vtkGlobeTest::Scene& scene)
{
  Frame f;
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  f.GLOk = vtkGlobeTest::NoGLError();
  f.DepthOk = vtkGlobeTest::CountNaN(depth) == 0;
  f.Covered = vtkGlobeTest::CoveredPixels(depth);
  return f;
}

// A height layer in memory: 64 x 64 posts of 100 m over (west, south) .. +1 degree, one post
// replaced by `spike`.
vtkSmartPointer<vtkGlobeLayer> SpikeLayer(double west, double south, float spike)
{
  std::vector<float> values(64 * 64, 100.0f);
  values[32 * 64 + 32] = spike;
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetHeightData(64, 64, values.data(), west, west + 1.0, south, south + 1.0);
  layer->SetName("spike");
  return layer;
}

void ExtremeHeights()
{
  std::printf("One extreme height (defect 2):\n");
  for (float spike : { 1e30f, -1e30f })
  {
    vtkGlobeTest::Scene scene(200, 150, 128);
    vtkNew<Messages> messages;
    scene.AddEarthLayers(true, false);
    auto layer = SpikeLayer(10.0, 45.0, spike);
    messages->Watch(layer);
    messages->Watch(scene.Mapper->GetLayerSet());
    scene.Mapper->AddLayer(layer);
    // From the far side of the Earth, over the inset from 60 km, and from 20,000 km over it.
    const double views[3][3] = { { -170.0, -45.0, 2.0e7 }, { 10.5, 45.5, 6.0e4 },
      { 10.5, 45.5, 2.0e7 } };
    for (const auto& v : views)
    {
      const double target[3] = { v[0], v[1], 0.0 };
      scene.Look(v, target, 40.0);
      scene.Render();
      const Frame f = Look(scene);
      double range[2];
      scene.Renderer->GetActiveCamera()->GetClippingRange(range);
      Checks.Expect(scene.Mapper->GetLastFrameDrewGlobe() && f.Covered > 5000 && f.GLOk &&
          f.DepthOk && range[1] < 1e9,
        Printf("spike %g m, camera (%g, %g) at %g km: globe drawn over %d of 30000 pixels, far "
               "plane %.3g m",
          spike, v[0], v[1], v[2] / 1000, f.Covered, range[1]));
    }
    const double top = scene.Mapper->GetLayerSet()->GetMaximumHeight();
    const double bottom = scene.Mapper->GetLayerSet()->GetMinimumHeight();
    Checks.Expect(layer->IsValid() && layer->GetNumberOfImplausibleValues() == 1,
      Printf("the post is a void of a valid layer (%lld implausible)",
        static_cast<long long>(layer->GetNumberOfImplausibleValues())));
    Checks.Expect(top < 9000.0 && bottom > -12000.0,
      Printf("the composed height range is the data's: %.0f .. %.0f m", bottom, top));
    Checks.Expect(messages->Count("spike") == 1 && messages->Count("plausible") == 1,
      Printf("one warning names the layer and the plausible range (%zu messages)",
        messages->Texts.size()));
    messages->Print();
  }

  // A single flipped bit in the 2-degree relief: a post of a few metres becomes ~1e20 m.
  vtkNew<vtkGlobeRasterReader> reader;
  reader->SetFileName(VTKGLOBE_DATA_DIR "/earth/relief_2deg.tif");
  reader->Update();
  vtkNew<vtkImageData> image;
  image->DeepCopy(reader->GetOutput());
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  vtkIdType flipped = -1;
  double before = 0.0, after = 0.0;
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples() && flipped < 0; ++i)
  {
    if (scalars->GetDataType() == VTK_FLOAT)
    {
      float* p = static_cast<vtkFloatArray*>(scalars)->GetPointer(i);
      if (*p >= 2.0f && *p < 4.0f)
      {
        uint32_t bits;
        std::memcpy(&bits, p, 4);
        bits ^= 1u << 29; // the exponent grows by 64
        before = *p;
        std::memcpy(p, &bits, 4);
        after = *p;
        flipped = i;
      }
    }
    else if (scalars->GetDataType() == VTK_SHORT || scalars->GetDataType() == VTK_INT)
    {
      const double v = scalars->GetComponent(i, 0);
      if (v >= 2 && v < 100)
      {
        before = v;
        after = scalars->GetDataType() == VTK_SHORT ? v - 32768 : v + 1073741824.0;
        scalars->SetComponent(i, 0, after);
        flipped = i;
      }
    }
  }
  vtkGlobeTest::Scene scene(200, 150, 128);
  vtkNew<Messages> messages;
  vtkNew<vtkGlobeLayer> relief;
  relief->SetInputData(image);
  messages->Watch(relief);
  scene.Mapper->AddLayer(relief);
  const double camera[3] = { 60.0, 10.0, 2.0e7 }, target[3] = { 60.0, 10.0, 0.0 };
  scene.Look(camera, target, 40.0);
  scene.Render();
  const Frame f = Look(scene);
  Checks.Expect(flipped >= 0 && scene.Mapper->GetLastFrameDrewGlobe() && f.Covered > 5000 &&
      f.GLOk && f.DepthOk,
    Printf("a flipped bit in relief_2deg (post %lld: %g -> %g m): the globe is drawn (%d px)",
      static_cast<long long>(flipped), before, after, f.Covered));
  Checks.Expect(messages->Count("plausible") == 1 && scene.Mapper->GetLayerSet()->GetMaximumHeight() < 9000,
    Printf("reported once; composed maximum %.0f m", scene.Mapper->GetLayerSet()->GetMaximumHeight()));

  // The range is a setting: a user's range wider than the data keeps every post.
  vtkNew<vtkGlobeMapper> mapper;
  double range[2];
  mapper->GetPlausibleHeightRange(range);
  Checks.Expect(std::abs(range[1] - 0.05 * 6356752.314245) < 1.0 && range[0] == -range[1],
    Printf("the default range on WGS84 is +-%.1f km", range[1] / 1000));
  mapper->SetPlausibleHeightRange(-1e31, 1e31);
  auto wide = SpikeLayer(10.0, 45.0, 1e30f);
  mapper->AddLayer(wide);
  mapper->GetBounds();
  Checks.Expect(wide->GetNumberOfImplausibleValues() == 0 && wide->GetMaximumValue() == 1e30f,
    "SetPlausibleHeightRange(-1e31, 1e31) keeps the 1e30 post");
}

void LayersRemovedWhileLoading()
{
  std::printf("Layers removed by observers while they load (defect 3):\n");
  {
    vtkGlobeTest::Scene scene(200, 150, 128);
    auto relief = vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true);
    auto world = vtkGlobeTest::FileLayer("earth/world.tif", false);
    scene.Mapper->AddLayer(relief);
    scene.Mapper->AddLayer(world);
    vtkGlobeMapper* mapper = scene.Mapper;
    vtkNew<vtkCallbackCommand> removeAll;
    removeAll->SetClientData(mapper);
    removeAll->SetCallback([](vtkObject*, unsigned long, void* mapperPointer, void*) {
      static_cast<vtkGlobeMapper*>(mapperPointer)->RemoveAllLayers();
    });
    relief->GetFileReader()->AddObserver(vtkCommand::ProgressEvent, removeAll);
    const double camera[3] = { 0.0, 20.0, 2.0e7 }, target[3] = { 0.0, 20.0, 0.0 };
    scene.Look(camera, target, 40.0);
    relief = nullptr;
    world = nullptr;
    scene.Render();
    const Frame f = Look(scene);
    Checks.Expect(scene.Mapper->GetNumberOfLayers() == 0 && f.Covered > 5000 && f.GLOk,
      Printf("RemoveAllLayers() from a reader's ProgressEvent: no crash, %d layers left, the "
             "bare globe drawn over %d px",
        scene.Mapper->GetNumberOfLayers(), f.Covered));
  }
  {
    // The last reference to a layer dropped by its own reader's observer, through GetBounds.
    vtkGlobeTest::Scene scene(200, 150, 128);
    vtkGlobeLayer* relief = vtkGlobeLayer::New();
    relief->SetFileName(VTKGLOBE_DATA_DIR "/earth/relief_2deg.tif");
    scene.Mapper->AddLayer(relief);
    relief->Delete(); // the mapper holds the only reference
    struct Context
    {
      vtkGlobeMapper* Mapper;
      vtkGlobeLayer* Layer;
    } context{ scene.Mapper, relief };
    vtkNew<vtkCallbackCommand> removeOne;
    removeOne->SetClientData(&context);
    removeOne->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
      auto* c = static_cast<Context*>(data);
      c->Mapper->RemoveLayer(c->Layer);
    });
    relief->GetFileReader()->AddObserver(vtkCommand::ProgressEvent, removeOne);
    const double* bounds = scene.Mapper->GetBounds();
    const double camera[3] = { 0.0, 20.0, 2.0e7 }, target[3] = { 0.0, 20.0, 0.0 };
    scene.Look(camera, target, 40.0);
    scene.Render();
    const Frame f = Look(scene);
    Checks.Expect(scene.Mapper->GetNumberOfLayers() == 0 && bounds[1] >= 6378137.0 &&
        f.Covered > 5000 && f.GLOk,
      Printf("a layer removed and released by its reader's observer during GetBounds(): no "
             "crash, bounds x max %.0f m, %d px drawn",
        bounds[1], f.Covered));
  }
}

void FailuresReportedOnce()
{
  std::printf("A failing layer is reported once; files rewritten on disk are re-read (defect 6):\n");
  const std::string file = std::string(VTKGLOBE_TEMP_DIR) + "/reliability_later.tif";
  std::filesystem::remove(file);
  vtkGlobeTest::Scene scene(200, 150, 128);
  vtkNew<Messages> messages;
  vtkNew<vtkGlobeLayer> later;
  later->SetFileName(file.c_str());
  messages->Watch(later);
  messages->Watch(later->GetFileReader());
  messages->Watch(scene.Mapper->GetLayerSet());
  messages->Watch(scene.Mapper);
  scene.Mapper->AddLayer(later);
  const double camera[3] = { 0.0, 20.0, 2.0e7 }, target[3] = { 0.0, 20.0, 0.0 };
  scene.Look(camera, target, 40.0);
  for (int frame = 0; frame < 10; ++frame)
  {
    scene.Window->Render();
  }
  const Frame f = Look(scene);
  Checks.Expect(messages->Texts.size() >= 1 && messages->Texts.size() <= 3 &&
      later->GetNumberOfLoads() == 1 && f.Covered > 5000,
    Printf("a missing file over 10 frames: %zu messages, %d load attempts, globe drawn (%d px)",
      messages->Texts.size(), later->GetNumberOfLoads(), f.Covered));
  messages->Print();

  // The file appears: the next frame reads it, without Modified().
  std::filesystem::copy_file(VTKGLOBE_DATA_DIR "/earth/relief_2deg.tif", file);
  scene.Window->Render();
  Checks.Expect(later->IsValid() && later->GetNumberOfLoads() == 2,
    Printf("the file appears: read by the next frame (valid %d, %d loads)", later->IsValid(),
      later->GetNumberOfLoads()));
  const double firstMaximum = later->GetMaximumValue();
  for (int frame = 0; frame < 5; ++frame)
  {
    scene.Window->Render();
  }
  Checks.Expect(later->GetNumberOfLoads() == 2, "an unchanged file is not read again");

  // Rewritten on disk (another raster, another size): re-read by the next frame.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::filesystem::copy_file(VTKGLOBE_DATA_DIR "/earth/mt_rainier_90m.tif", file,
    std::filesystem::copy_options::overwrite_existing);
  scene.Window->Render();
  Checks.Expect(later->IsValid() && later->GetNumberOfLoads() == 3 &&
      later->GetMaximumValue() != firstMaximum,
    Printf("rewritten on disk: re-read by the next frame (%d loads, maximum %.0f -> %.0f m)",
      later->GetNumberOfLoads(), firstMaximum, later->GetMaximumValue()));

  // Corrupted on disk: one report, then quiet; Modified() asks for one more try.
  const size_t before = messages->Texts.size();
  std::ofstream(file, std::ios::binary | std::ios::trunc) << "II*\0 not a tiff any more";
  for (int frame = 0; frame < 5; ++frame)
  {
    scene.Window->Render();
  }
  const size_t reports = messages->Texts.size() - before;
  Checks.Expect(!later->IsValid() && reports >= 1 && reports <= 3 && later->GetNumberOfLoads() == 4,
    Printf("corrupted on disk: %zu messages over 5 frames, %d loads", reports,
      later->GetNumberOfLoads()));
  later->Modified();
  scene.Window->Render();
  Checks.Expect(later->GetNumberOfLoads() == 5, "Modified() on a failed layer tries once more");
  std::filesystem::remove(file);
}

/// Places the camera `depth` metres under the composed terrain at (10 E, 20 N), looking north
/// at a cone 50 m ahead.
std::function<void(vtkGlobeTest::Scene&, double[3])> Inside(double depth)
{
  return [depth](vtkGlobeTest::Scene& s, double cone[3]) {
    const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(s.Mapper);
    for (vtkGlobeLayer* layer : layers)
    {
      layer->Update();
    }
    const double ground = vtkGlobeTest::ComposedHeight(layers, 10.0, 20.0);
    double eye[3], east[3], north[3], up[3];
    s.Body->GeodeticToCartesian(10.0, 20.0, ground - depth, eye);
    s.Body->ComputeEastNorthUp(10.0, 20.0, east, north, up);
    vtkGlobeTest::LookAlong(s.Renderer, eye, north, up, 40.0);
    for (int i = 0; i < 3; ++i)
    {
      cone[i] = eye[i] + 50.0 * north[i];
    }
  };
}

void CameraCases()
{
  std::printf("Cameras that leave nothing to see are reported once (defect 7):\n");
  struct Case
  {
    const char* Name;
    const char* Needle; // in the one report
    std::function<void(vtkGlobeTest::Scene&, double cone[3])> Place;
  };
  const std::vector<Case> cases = {
    { "1 m under the terrain", "inside the body", Inside(1.0) },
    { "1,000 km under the terrain", "inside the body", Inside(1.0e6) },
    { "1e15 m away", "smaller than a pixel",
      [](vtkGlobeTest::Scene& s, double cone[3]) {
        const double eye[3] = { 1e15, 0.0, 0.0 }, view[3] = { -1, 0, 0 }, up[3] = { 0, 0, 1 };
        vtkGlobeTest::LookAlong(s.Renderer, eye, view, up, 40.0);
        cone[0] = 1e15 - 50.0;
        cone[1] = cone[2] = 0.0;
      } },
    { "focal point at the eye", "focal point",
      [](vtkGlobeTest::Scene& s, double cone[3]) {
        vtkCamera* c = s.Renderer->GetActiveCamera();
        c->SetPosition(2.0e7, 0.0, 0.0);
        c->SetFocalPoint(2.0e7, 0.0, 0.0);
        c->SetViewUp(0, 0, 1);
        cone[0] = 1.9e7;
        cone[1] = cone[2] = 0.0;
      } },
    { "view-up along the view direction", "view-up",
      [](vtkGlobeTest::Scene& s, double cone[3]) {
        vtkCamera* c = s.Renderer->GetActiveCamera();
        c->SetPosition(2.0e7, 0.0, 0.0);
        c->SetFocalPoint(0.0, 0.0, 0.0);
        c->SetViewUp(1, 0, 0);
        cone[0] = 1.9e7;
        cone[1] = cone[2] = 0.0;
      } },
  };
  for (const Case& k : cases)
  {
    vtkGlobeTest::Scene scene(200, 150, 128);
    vtkNew<Messages> messages;
    messages->Watch(scene.Mapper);
    messages->Watch(scene.Mapper->GetLayerSet());
    scene.AddEarthLayers(true, false);
    double cone[3];
    k.Place(scene, cone);
    vtkNew<vtkConeSource> source;
    source->SetCenter(cone);
    source->SetHeight(10.0);
    source->SetRadius(10.0);
    source->SetResolution(16);
    scene.Renderer->AddActor(vtkGlobeTest::FlatActor(source, 1, 0, 0));
    scene.Renderer->ResetCameraClippingRange();
    bool healthy = true;
    for (int frame = 0; frame < 3; ++frame)
    {
      scene.Window->Render();
      const Frame f = Look(scene);
      healthy = healthy && f.GLOk && f.DepthOk;
    }
    Checks.Expect(healthy && messages->Texts.size() == 1 && messages->Count(k.Needle) == 1,
      Printf("%s: %zu report(s) in 3 frames, naming '%s'; no GL error, no NaN depth", k.Name,
        messages->Texts.size(), k.Needle));
    messages->Print();
  }
}

void ShaderVariantsReleased()
{
  std::printf("Memory per layer/effect combination (defect 5):\n");
  vtkGlobeTest::Scene scene(200, 150, 64);
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
  const double camera[3] = { 0.0, 20.0, 2.0e7 }, target[3] = { 0.0, 20.0, 0.0 };
  scene.Look(camera, target, 40.0);
  std::vector<vtkSmartPointer<vtkGlobeLayer>> extra;
  for (int i = 0; i < 3; ++i)
  {
    extra.push_back(SpikeLayer(10.0 * i, 0.0, 100.0f));
    extra.back()->SetBlendMode(i == 1 ? vtkGlobeLayer::Add : vtkGlobeLayer::Replace);
  }
  // 32 distinct shader variants: effects (8) x extra height layers (0..3). The first 8 warm up
  // the driver; the other 24 are each new to the process.
  double warm = 0.0;
  for (int layers = 0; layers <= 3; ++layers)
  {
    if (layers > 0)
    {
      scene.Mapper->AddLayer(extra[layers - 1]);
    }
    for (int effects = 0; effects < 8; ++effects)
    {
      scene.Mapper->SetAtmosphere(effects & 1);
      scene.Mapper->SetGraticule(effects & 2);
      scene.Mapper->SetContours(effects & 4);
      scene.Window->Render();
    }
    if (layers == 0)
    {
      warm = vtkGlobeTest::ResidentMiB();
    }
  }
  const double grown = vtkGlobeTest::ResidentMiB() - warm;
  const std::string what =
    Printf("24 new combinations after warm-up: resident memory %+.1f MiB (%.2f MiB each; "
           "41 MiB when every variant's program was kept)",
      grown, grown / 24.0);
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer keeps freed blocks in quarantine (256 MiB) and adds shadow memory:
  // resident memory measures it, not the shader cache. Judged in the normal build only.
  std::printf("  (not judged under AddressSanitizer) %s\n", what.c_str());
#else
  Checks.Expect(grown < 24.0, what);
#endif
}
} // namespace

int TestGlobeReliability(int, char*[])
{
  ExtremeHeights();
  LayersRemovedWhileLoading();
  FailuresReportedOnce();
  CameraCases();
  ShaderVariantsReleased();
  return Checks.Result();
}
