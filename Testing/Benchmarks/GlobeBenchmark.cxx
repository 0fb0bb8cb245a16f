// GlobeBenchmark: frame time against on-screen accuracy of the Projective Grid Mapping globe,
// next to the globes plain VTK can draw. A program, not a test: it prints a table and writes
// JSON, and asserts nothing (DESIGN.md §9).
//
//   GlobeBenchmark [--quick] [--frames N] [--json PATH] [--help]
//
// Candidates, all in ONE window and renderer with the same cameras and clipping ranges:
//  - pgm:    vtkGlobeMapper with the demo's Earth layers, grid 256^2, 512^2, 1024^2;
//  - sphere: a vtkTexturedSphereSource (256 x 128) on the WGS84 ellipsoid with the imagery;
//  - mesh:   a global lon/lat mesh warped by the composed heights through
//            vtkGlobeGeodeticTransform (double points), with the imagery, 256 x 128 .. 4096 x 2048.
// Each is timed at two viewpoints (the whole Earth; Mount Rainier from 20 km) and four window
// sizes (256^2, 512^2, 1024^2, 1024 x 768, after Mahsman's Tables 6.2-6.5), and its height error
// is measured at the Rainier view in the 1024 x 768 window.
#include "vtkGlobeRenderingTestHelpers.h" // Scene, LookAt, ReadDepth, UnprojectPixel, ComposedHeight

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGeodeticTransform.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeMapper.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTexturedSphereSource.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h" // glFinish, glGetString

#include <algorithm>
#include <utility>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
const double NaN = std::numeric_limits<double>::quiet_NaN();

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

//------------------------------------------------------------------------------
// What is measured.

struct View
{
  const char* Name;
  double Camera[3]; // geodetic (deg, deg, m)
  double Target[3];
  double ViewAngle; // deg
  double Near, Far; // m; the whole-Earth range is filled in from the globe's bounds at start-up
};

// The demo's viewpoints (Examples/Cxx/GlobeEarth.cxx, TestGlobeWholeEarth, TestGlobeRainier).
View Views[] = {
  { "earth", { -40.0, 25.0, 2.2e7 }, { -40.0, 25.0, 0.0 }, 30.0, 0.0, 0.0 },
  { "rainier", { -121.86, 46.75, 16000.0 }, { -121.7603, 46.8523, 4392.0 }, 40.0, 100.0, 1.0e6 },
};
const int EarthView = 0;
const int RainierView = 1;

struct Size
{
  int X, Y;
  bool operator==(const Size& o) const { return this->X == o.X && this->Y == o.Y; }
  std::string ToString() const { return std::to_string(this->X) + "x" + std::to_string(this->Y); }
};

// Accuracy is measured in this window for every candidate.
const Size AccuracyWindow = { 1024, 768 };

struct Options
{
  bool Quick = false;
  bool EffectsOnly = false;
  int Frames = 30;
  int Warmup = 5;
  std::string Json = "benchmark.json";
  std::vector<int> Grids = { 256, 512, 1024 };
  std::vector<Size> Windows = { { 256, 256 }, { 512, 512 }, { 1024, 1024 }, { 1024, 768 } };
  Size Sphere = { 256, 128 };
  std::vector<Size> Meshes = { { 256, 128 }, { 1024, 512 }, { 2048, 1024 }, { 4096, 2048 } };
  // Configurations slower than this are timed with fewer frames (never fewer than
  // MinimumFrames after 2 warm-up frames), so the huge meshes do not dominate the run.
  double SecondsPerConfiguration = 20.0;
  int MinimumFrames = 10;
  // A mesh whose projected time (from the previous mesh, scaled by its triangles) exceeds this
  // is skipped.
  double SecondsPerMesh = 300.0;
};

/// Order statistics of frame times, in milliseconds.
struct Stats
{
  int Count = 0;
  double Median = NaN, Q1 = NaN, Q3 = NaN, Min = NaN, Max = NaN;
};

/// The q-quantile of sorted values, interpolated between order statistics.
double Quantile(const std::vector<double>& sorted, double q)
{
  if (sorted.empty())
  {
    return NaN;
  }
  const double at = q * (sorted.size() - 1);
  const size_t i = static_cast<size_t>(std::floor(at));
  const size_t j = std::min(i + 1, sorted.size() - 1);
  return sorted[i] + (at - i) * (sorted[j] - sorted[i]);
}

Stats Summarize(std::vector<double> milliseconds)
{
  Stats s;
  std::sort(milliseconds.begin(), milliseconds.end());
  s.Count = static_cast<int>(milliseconds.size());
  if (s.Count > 0)
  {
    s.Median = Quantile(milliseconds, 0.5);
    s.Q1 = Quantile(milliseconds, 0.25);
    s.Q3 = Quantile(milliseconds, 0.75);
    s.Min = milliseconds.front();
    s.Max = milliseconds.back();
  }
  return s;
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return Quantile(values, 0.5);
}

/// |rendered height - data height| over the covered pixels, in metres.
struct Accuracy
{
  bool Measured = false;
  int Pixels = 0;
  int Invalid = 0; // NaN depth or a point without a geodetic position
  double Median = NaN, P95 = NaN, Max = NaN;
};

// The GPU stages vtkGlobeMapper times (DESIGN.md §4).
enum Stage
{
  PGMStage,
  HeightStage,
  RasterStage,
  CompositeStage,
  ReductionStage,
  NumberOfStages
};
const char* const StageNames[NumberOfStages] = { "pgm", "height", "raster", "composite",
  "reduction" };

struct Row
{
  std::string Method; // pgm, sphere, mesh
  int ViewIndex = 0;
  Size Window = { 0, 0 };
  Size Resolution = { 0, 0 }; // grid points per side (pgm) or cells in lon x lat
  double Triangles = 0;
  int Warmup = 0;
  Stats Time;
  double Stages[NumberOfStages] = { NaN, NaN, NaN, NaN, NaN }; // median ms; NaN: none
  Accuracy Error;
};

/// How many warm-up and timed frames a configuration gets.
struct FramePlan
{
  int Warmup, Frames;
};

/**
 * The plan for a configuration whose frames take frameSeconds: the requested counts, or, when
 * capped and they would take longer than SecondsPerConfiguration, 2 warm-up frames (the first
 * pays for the uploads) and as many timed frames as fit, but at least MinimumFrames.
 */
FramePlan PlanFrames(const Options& options, double frameSeconds, bool capped)
{
  FramePlan plan{ options.Warmup, options.Frames };
  if (capped && frameSeconds * (plan.Warmup - 2 + plan.Frames) > options.SecondsPerConfiguration)
  {
    plan.Warmup = std::min(plan.Warmup, 2);
    plan.Frames = std::max(options.MinimumFrames,
      std::min(plan.Frames, static_cast<int>(options.SecondsPerConfiguration / frameSeconds)));
  }
  return plan;
}

//------------------------------------------------------------------------------
// The naive globes.

/// The colour layer's RGBA pixels as a VTK texture. The layer's row 0 is north; VTK's image
/// row 0 is at t = 0, which the sphere and the mesh put at the south pole.
vtkSmartPointer<vtkTexture> ImageryTexture(vtkGlobeLayer* layer)
{
  auto* rgba = vtkUnsignedCharArray::SafeDownCast(layer->GetData());
  const int w = layer->GetWidth(), h = layer->GetHeight();
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(4);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (int row = 0; row < h; ++row)
  {
    std::memcpy(pixels->GetPointer(static_cast<vtkIdType>(row) * w * 4),
      rgba->GetPointer(static_cast<vtkIdType>(h - 1 - row) * w * 4), static_cast<size_t>(w) * 4);
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->GetPointData()->SetScalars(pixels);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  // Mipmapped and filtered like the globe's own colour layer, so the comparison is fair.
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->SetWrap(vtkTexture::ClampToEdge);
  return texture;
}

/**
 * A global lon/lat mesh of columns x rows quads, its vertices at (lon, lat, composed height)
 * mapped onto the body in double precision. The seam column is duplicated so the texture
 * coordinates run 0..1 without wrapping. Indices are 32-bit to halve the memory of the
 * largest meshes (4096 x 2048 is 8.4 million vertices).
 */
vtkSmartPointer<vtkPolyData> WarpedMesh(
  int columns, int rows, const std::vector<vtkGlobeLayer*>& layers, vtkGlobeEllipsoid* body)
{
  const vtkIdType nx = columns + 1, ny = rows + 1;
  vtkNew<vtkPoints> geodetic;
  geodetic->SetDataTypeToDouble();
  geodetic->SetNumberOfPoints(nx * ny);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(nx * ny);
  for (vtkIdType j = 0; j < ny; ++j)
  {
    const double t = static_cast<double>(j) / rows;
    const double lat = -90.0 + 180.0 * t;
    for (vtkIdType i = 0; i < nx; ++i)
    {
      const double s = static_cast<double>(i) / columns;
      const double lon = -180.0 + 360.0 * s;
      const vtkIdType k = j * nx + i;
      geodetic->SetPoint(k, lon, lat, vtkGlobeTest::ComposedHeight(layers, lon, lat));
      tcoords->SetTuple2(k, s, t);
    }
  }
  vtkNew<vtkGlobeGeodeticTransform> transform;
  transform->SetEllipsoid(body);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->Allocate(nx * ny);
  transform->TransformPoints(geodetic, points);

  const vtkIdType cells = static_cast<vtkIdType>(columns) * rows;
  vtkNew<vtkTypeInt32Array> offsets, connectivity;
  offsets->SetNumberOfValues(cells + 1);
  connectivity->SetNumberOfValues(4 * cells);
  vtkIdType c = 0;
  for (vtkIdType j = 0; j < rows; ++j)
  {
    for (vtkIdType i = 0; i < columns; ++i, ++c)
    {
      const vtkTypeInt32 a = static_cast<vtkTypeInt32>(j * nx + i);
      const vtkTypeInt32 quad[4] = { a, a + 1, a + 1 + static_cast<vtkTypeInt32>(nx),
        a + static_cast<vtkTypeInt32>(nx) };
      offsets->SetValue(c, static_cast<vtkTypeInt32>(4 * c));
      for (int q = 0; q < 4; ++q)
      {
        connectivity->SetValue(4 * c + q, quad[q]);
      }
    }
  }
  offsets->SetValue(cells, static_cast<vtkTypeInt32>(4 * cells));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetTCoords(tcoords);
  return mesh;
}

//------------------------------------------------------------------------------
// JSON output (a few numbers and strings; VTK's jsoncpp is not among the project's components).

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (const char ch : s)
  {
    if (ch == '"' || ch == '\\')
    {
      out += '\\';
      out += ch;
    }
    else if (static_cast<unsigned char>(ch) < 0x20)
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", ch);
      out += escaped;
    }
    else
    {
      out += ch;
    }
  }
  return out + "\"";
}

std::string JsonNumber(double value)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

std::string GLString(GLenum name)
{
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "unknown";
}

std::string CpuModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
  {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
    {
      return line.substr(line.find(':') + 2);
    }
  }
  return "unknown";
}

std::string UtcNow()
{
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
}

//------------------------------------------------------------------------------
class Benchmark
{
public:
  explicit Benchmark(const Options& options)
    : Opt(options)
    , Scene(AccuracyWindow.X, AccuracyWindow.Y, 512)
  {
  }

  int Run();

private:
  void Prepare();
  void RunGlobe();
  void RunSphere();
  void RunMeshes();
  void RunEffects();
  void PrintEffects();
  double ProjectMesh(size_t firstRow, double otherSeconds, double previousTriangles,
    double triangles);
  void TimeCandidate(const std::string& method, Size resolution, double triangles, vtkProp* actor,
    bool capped);
  Row TimeConfiguration(const std::string& method, Size resolution, double triangles,
    int viewIndex, Size window, bool capped);
  void PlaceCamera(int viewIndex, Size window, double positions[2][3], double focals[2][3]);
  Accuracy MeasureAccuracy();
  Row* FindRow(const std::string& method, Size resolution, int viewIndex, Size window);
  void PrintTable();
  void Compare();
  bool WriteJson(double totalSeconds);
  void Note(const std::string& note);

  struct Comparison
  {
    std::string Name, Statement, Result;
  };

  Options Opt;
  vtkGlobeTest::Scene Scene; // the one window, renderer and PGM globe every candidate uses
  std::vector<vtkGlobeLayer*> Layers;
  vtkSmartPointer<vtkTexture> Imagery;
  std::vector<Row> Rows;
  std::vector<std::pair<std::string, Row>> EffectRows; // whole Earth, grid 512^2, accuracy window
  std::vector<std::string> Notes; // what was cut short or skipped, and why
  std::vector<Comparison> Comparisons;
  std::string Renderer, Version, Vendor;
  Clock::time_point Start = Clock::now();
};

void Benchmark::Note(const std::string& note)
{
  this->Notes.push_back(note);
  std::fprintf(stderr, "  note: %s\n", note.c_str());
}

/// Loads the layers, fixes the whole-Earth clipping range and reads what the renderer is.
void Benchmark::Prepare()
{
  this->Scene.AddEarthLayers();
  this->Layers = vtkGlobeTest::HeightLayers(this->Scene.Mapper);
  vtkGlobeLayer* color = nullptr;
  for (vtkGlobeLayer* layer : this->Layers)
  {
    layer->Update();
    if (layer->GetRole() == vtkGlobeLayer::Color)
    {
      color = layer;
    }
  }
  this->Imagery = ImageryTexture(color);

  // VTK would reset the whole-Earth clipping range to each actor's bounds; fixing it once from
  // the globe's bounds (the body plus its tallest terrain) gives every candidate the same one.
  View& earth = Views[EarthView];
  vtkGlobeTest::LookAt(
    this->Scene.Renderer, this->Scene.Body, earth.Camera, earth.Target, earth.ViewAngle);
  this->Scene.Renderer->ResetCameraClippingRange();
  this->Scene.Renderer->GetActiveCamera()->GetClippingRange(earth.Near, earth.Far);

  this->Scene.Window->Render();
  this->Scene.Window->MakeCurrent();
  this->Renderer = GLString(GL_RENDERER);
  this->Version = GLString(GL_VERSION);
  this->Vendor = GLString(GL_VENDOR);
}

/**
 * Points the camera at a view and gives the two eye/focal-point pairs the timed frames
 * alternate between: the view itself and the view moved sideways by a quarter of a pixel at the
 * focal distance. The picture (and its cost) stays the same, but every frame has a new camera,
 * so nothing computed from the camera can be reused from the previous frame.
 */
void Benchmark::PlaceCamera(int viewIndex, Size window, double positions[2][3], double focals[2][3])
{
  const View& v = Views[viewIndex];
  vtkGlobeTest::LookAt(this->Scene.Renderer, this->Scene.Body, v.Camera, v.Target, v.ViewAngle);
  vtkCamera* camera = this->Scene.Renderer->GetActiveCamera();
  camera->SetClippingRange(v.Near, v.Far);
  double forward[3], right[3];
  camera->GetDirectionOfProjection(forward);
  vtkMath::Cross(forward, camera->GetViewUp(), right);
  vtkMath::Normalize(right);
  const double pixel = 2.0 * camera->GetDistance() *
    std::tan(vtkMath::RadiansFromDegrees(v.ViewAngle) / 2.0) / window.Y;
  for (int i = 0; i < 3; ++i)
  {
    positions[0][i] = camera->GetPosition()[i];
    focals[0][i] = camera->GetFocalPoint()[i];
    positions[1][i] = positions[0][i] + 0.25 * pixel * right[i];
    focals[1][i] = focals[0][i] + 0.25 * pixel * right[i];
  }
}

/**
 * Times one configuration: warm-up frames (shader builds, uploads, the PGM reduction settling),
 * then timed frames, each a Render() followed by glFinish() so the time is the whole frame and
 * not just its submission. In capped mode a configuration slower than SecondsPerConfiguration
 * gets 2 warm-up frames and fewer timed ones.
 */
Row Benchmark::TimeConfiguration(const std::string& method, Size resolution, double triangles,
  int viewIndex, Size window, bool capped)
{
  Row row;
  row.Method = method;
  row.ViewIndex = viewIndex;
  row.Window = window;
  row.Resolution = resolution;
  row.Triangles = triangles;

  vtkRenderWindow* renWin = this->Scene.Window;
  renWin->SetSize(window.X, window.Y);
  double positions[2][3], focals[2][3];
  this->PlaceCamera(viewIndex, window, positions, focals);
  vtkCamera* camera = this->Scene.Renderer->GetActiveCamera();
  int frame = 0;
  auto renderFrame = [&]() {
    camera->SetPosition(positions[frame % 2]);
    camera->SetFocalPoint(focals[frame % 2]);
    ++frame;
    const Clock::time_point start = Clock::now();
    renWin->Render();
    glFinish();
    return SecondsSince(start);
  };

  FramePlan plan = PlanFrames(this->Opt, 0.0, capped);
  for (int i = 0; i < plan.Warmup; ++i)
  {
    const double seconds = renderFrame();
    // The first frame pays for uploads; the second is a fair estimate of the rest.
    if (i == 1)
    {
      plan = PlanFrames(this->Opt, seconds, capped);
    }
  }
  row.Warmup = plan.Warmup;

  vtkGlobeMapper* globe = method.compare(0, 3, "pgm") == 0 ? this->Scene.Mapper.Get() : nullptr;
  std::vector<double> times;
  std::vector<double> stages[NumberOfStages];
  for (int i = 0; i < plan.Frames; ++i)
  {
    times.push_back(1e3 * renderFrame());
    if (globe)
    {
      // From the most recent frame whose timer queries are done (-1: no timer queries).
      const double s[NumberOfStages] = { globe->GetGridPass()->GetPGMTime(),
        globe->GetGridPass()->GetHeightTime(), globe->GetRasterTime(),
        globe->GetCompositePass()->GetCompositeTime(), globe->GetReductionTime() };
      for (int k = 0; k < NumberOfStages; ++k)
      {
        if (s[k] >= 0.0)
        {
          stages[k].push_back(1e3 * s[k]);
        }
      }
    }
  }
  row.Time = Summarize(times);
  for (int k = 0; k < NumberOfStages; ++k)
  {
    row.Stages[k] = stages[k].empty() ? NaN : Median(stages[k]);
  }
  std::fprintf(stderr, "  [%6.0f s] %-6s %-9s %-7s %-9s %3d frames: median %8.2f ms\n",
    SecondsSince(this->Start), method.c_str(), resolution.ToString().c_str(),
    Views[viewIndex].Name, window.ToString().c_str(), row.Time.Count, row.Time.Median);
  return row;
}

/**
 * The on-screen height error at the Rainier view in the accuracy window: every 2nd pixel in
 * each direction that the terrain covers is reconstructed from the depth buffer (double), and
 * its geodetic height compared with the composed data height at its (lon, lat).
 */
Accuracy Benchmark::MeasureAccuracy()
{
  const View& v = Views[RainierView];
  this->Scene.Window->SetSize(AccuracyWindow.X, AccuracyWindow.Y);
  double positions[2][3], focals[2][3];
  this->PlaceCamera(RainierView, AccuracyWindow, positions, focals);
  // Twice at rest: PGM's second frame uses the first one's reduction, as in every timed frame.
  this->Scene.Render();

  Accuracy result;
  result.Measured = true;
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(this->Scene.Window);
  const int* size = this->Scene.Window->GetSize();
  std::vector<double> errors;
  for (int y = 0; y < size[1]; y += 2)
  {
    for (int x = 0; x < size[0]; x += 2)
    {
      const float d = depth[static_cast<size_t>(y) * size[0] + x];
      if (std::isnan(d))
      {
        ++result.Invalid;
        continue;
      }
      if (d >= 1.0f)
      {
        continue; // background
      }
      double p[3], llh[3];
      vtkGlobeTest::UnprojectPixel(this->Scene.Renderer, x + 0.5, y + 0.5, d, p);
      if (!this->Scene.Body->CartesianToGeodetic(p, llh))
      {
        ++result.Invalid;
        continue;
      }
      errors.push_back(std::abs(llh[2] - vtkGlobeTest::ComposedHeight(this->Layers, llh[0], llh[1])));
    }
  }
  std::sort(errors.begin(), errors.end());
  result.Pixels = static_cast<int>(errors.size());
  if (!errors.empty())
  {
    result.Median = Quantile(errors, 0.5);
    result.P95 = Quantile(errors, 0.95);
    result.Max = errors.back();
  }
  std::fprintf(stderr, "  [%6.0f s] height error at %s %s: %d pixels, median %.1f m, p95 %.1f m\n",
    SecondsSince(this->Start), v.Name, AccuracyWindow.ToString().c_str(), result.Pixels,
    result.Median, result.P95);
  return result;
}

/// Times an actor at every view and window, then measures its accuracy. The actor is alone in
/// the renderer and its graphics resources are released afterwards.
void Benchmark::TimeCandidate(
  const std::string& method, Size resolution, double triangles, vtkProp* actor, bool capped)
{
  vtkRenderer* renderer = this->Scene.Renderer;
  renderer->AddViewProp(actor);
  const size_t first = this->Rows.size();
  for (int view = 0; view < 2; ++view)
  {
    for (const Size& window : this->Opt.Windows)
    {
      this->Rows.push_back(
        this->TimeConfiguration(method, resolution, triangles, view, window, capped));
    }
  }
  const Accuracy error = this->MeasureAccuracy();
  for (size_t i = first; i < this->Rows.size(); ++i)
  {
    if (this->Rows[i].ViewIndex == RainierView && this->Rows[i].Window == AccuracyWindow)
    {
      this->Rows[i].Error = error;
    }
  }
  actor->ReleaseGraphicsResources(this->Scene.Window);
  renderer->RemoveViewProp(actor);
}

void Benchmark::RunGlobe()
{
  // The scene starts with the globe in the renderer; TimeCandidate adds and removes it.
  this->Scene.Renderer->RemoveViewProp(this->Scene.Actor);
  for (const int grid : this->Opt.Grids)
  {
    this->Scene.Mapper->SetGridResolution(grid);
    this->TimeCandidate("pgm", { grid, grid }, 2.0 * (grid - 1) * (grid - 1), this->Scene.Actor,
      false);
  }
}

/**
 * The plainest VTK globe: a textured sphere source. It is scaled into the WGS84 ellipsoid
 * (radius a, polar axis b) so that its surface is at height 0 and its "height error" is the
 * terrain it leaves out (plus its facets); a sphere of radius a would sit ~10 km above the
 * ellipsoid at Rainier's latitude. Its texture follows the parametric latitude, up to 0.19 deg
 * off the geodetic one: imagery misregistration does not affect time or heights.
 */
void Benchmark::RunSphere()
{
  const double* radii = this->Scene.Body->GetRadii();
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetThetaResolution(this->Opt.Sphere.X);
  sphere->SetPhiResolution(this->Opt.Sphere.Y);
  sphere->SetRadius(radii[0]);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(this->Imagery);
  // The source starts longitude at +x with u = 0; the imagery starts at -180 deg.
  actor->RotateZ(180.0);
  actor->SetScale(1.0, 1.0, radii[2] / radii[0]);
  this->TimeCandidate("sphere", this->Opt.Sphere,
    2.0 * this->Opt.Sphere.X * (this->Opt.Sphere.Y - 1), actor, false);
}

/**
 * What the mesh of the given triangles would take, projected from the rows (and the build and
 * accuracy time) of the previous mesh, everything scaled by the ratio of triangles. Frame time
 * grows more slowly than the triangles where the fragments dominate, so this errs long.
 */
double Benchmark::ProjectMesh(size_t firstRow, double otherSeconds, double previousTriangles,
  double triangles)
{
  const double ratio = triangles / previousTriangles;
  double seconds = otherSeconds * ratio;
  for (size_t i = firstRow; i < this->Rows.size(); ++i)
  {
    const double frame = 1e-3 * this->Rows[i].Time.Median * ratio;
    const FramePlan plan = PlanFrames(this->Opt, frame, true);
    seconds += frame * (plan.Warmup + plan.Frames);
  }
  return seconds;
}

void Benchmark::RunMeshes()
{
  size_t previousRows = 0;         // the previous mesh's first row
  double previousTriangles = 0.0;  // 0: no previous mesh
  double previousOtherSeconds = 0; // its time outside the frames
  for (const Size& size : this->Opt.Meshes)
  {
    const double triangles = 2.0 * size.X * size.Y;
    const double projected = previousTriangles > 0
      ? this->ProjectMesh(previousRows, previousOtherSeconds, previousTriangles, triangles)
      : 0.0;
    if (projected > this->Opt.SecondsPerMesh)
    {
      char note[256];
      std::snprintf(note, sizeof(note),
        "mesh %s skipped: projected to take %.0f s (the previous mesh's times scaled by its "
        "triangles), more than the %.0f s allowed per mesh",
        size.ToString().c_str(), projected, this->Opt.SecondsPerMesh);
      this->Note(note);
      continue;
    }
    const Clock::time_point start = Clock::now();
    vtkSmartPointer<vtkPolyData> mesh =
      WarpedMesh(size.X, size.Y, this->Layers, this->Scene.Body);
    std::fprintf(stderr, "  [%6.0f s] built mesh %s (%.1f M triangles) in %.1f s\n",
      SecondsSince(this->Start), size.ToString().c_str(), triangles / 1e6, SecondsSince(start));
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(mesh);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(this->Imagery);
    const size_t first = this->Rows.size();
    this->TimeCandidate("mesh", size, triangles, actor, true);
    for (size_t i = first; i < this->Rows.size(); ++i)
    {
      const Row& row = this->Rows[i];
      if (row.Time.Count < this->Opt.Frames || row.Warmup < this->Opt.Warmup)
      {
        char note[256];
        std::snprintf(note, sizeof(note),
          "mesh %s %s %s: %d warm-up + %d timed frames (%.0f ms per frame; %.0f s allowed per "
          "configuration)",
          size.ToString().c_str(), Views[row.ViewIndex].Name, row.Window.ToString().c_str(),
          row.Warmup, row.Time.Count, row.Time.Median, this->Opt.SecondsPerConfiguration);
        this->Note(note);
      }
    }
    // What the frames do not explain: building, uploading, the accuracy measurement.
    double frameSeconds = 0.0;
    for (size_t i = first; i < this->Rows.size(); ++i)
    {
      const Row& row = this->Rows[i];
      frameSeconds += 1e-3 * row.Time.Median * (row.Warmup + row.Time.Count);
    }
    previousRows = first;
    previousTriangles = triangles;
    previousOtherSeconds = std::max(0.0, SecondsSince(start) - frameSeconds);
  }
}

Row* Benchmark::FindRow(const std::string& method, Size resolution, int viewIndex, Size window)
{
  for (Row& row : this->Rows)
  {
    if (row.Method == method && row.Resolution == resolution && row.ViewIndex == viewIndex &&
      row.Window == window)
    {
      return &row;
    }
  }
  return nullptr;
}

std::string Format(double value, const char* format = "%.2f")
{
  if (!std::isfinite(value))
  {
    return "-";
  }
  char text[32];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

/// One row per configuration, grouped by view and window so the candidates sit together.
void Benchmark::PrintTable()
{
  std::printf("\nGlobeBenchmark: %s (%s), %u CPU threads\n", this->Renderer.c_str(),
    this->Version.c_str(), std::thread::hardware_concurrency());
  std::printf("Frame times in ms (wall clock, Render + glFinish); PGM stages: median GPU times of "
              "the mapper's timer queries (ms).\n"
              "Height error: |rendered - data| in m over every 2nd covered pixel, %s window, "
              "Rainier view.\n\n",
    AccuracyWindow.ToString().c_str());
  const char* header = "%-6s %-7s %-9s %-9s %6s %9s %7s %8s %8s | %7s %7s %7s %7s %7s | %8s "
                       "%8s %8s %7s\n";
  std::printf(header, "method", "view", "size", "window", "frames", "median", "IQR", "min", "max",
    "pgm", "height", "raster", "compos", "reduce", "err med", "err p95", "err max", "pixels");
  std::vector<const Row*> order;
  for (int view = 0; view < 2; ++view)
  {
    for (const Size& window : this->Opt.Windows)
    {
      for (const Row& row : this->Rows)
      {
        if (row.ViewIndex == view && row.Window == window)
        {
          order.push_back(&row);
        }
      }
    }
  }
  int lastView = -1;
  Size lastWindow = { 0, 0 };
  for (const Row* row : order)
  {
    if (row->ViewIndex != lastView || !(row->Window == lastWindow))
    {
      std::printf("\n");
      lastView = row->ViewIndex;
      lastWindow = row->Window;
    }
    const Accuracy& e = row->Error;
    std::printf(header, row->Method.c_str(), Views[row->ViewIndex].Name,
      row->Resolution.ToString().c_str(), row->Window.ToString().c_str(),
      std::to_string(row->Time.Count).c_str(), Format(row->Time.Median).c_str(),
      Format(row->Time.Q3 - row->Time.Q1).c_str(), Format(row->Time.Min).c_str(),
      Format(row->Time.Max).c_str(), Format(row->Stages[PGMStage]).c_str(),
      Format(row->Stages[HeightStage]).c_str(), Format(row->Stages[RasterStage]).c_str(),
      Format(row->Stages[CompositeStage]).c_str(), Format(row->Stages[ReductionStage]).c_str(),
      Format(e.Median, "%.1f").c_str(), Format(e.P95, "%.1f").c_str(),
      Format(e.Max, "%.1f").c_str(), e.Measured ? std::to_string(e.Pixels).c_str() : "-");
  }
  if (!this->Notes.empty())
  {
    std::printf("\nCut short or skipped:\n");
    for (const std::string& note : this->Notes)
    {
      std::printf("  - %s\n", note.c_str());
    }
  }
}

/// The two targets, as statements (a benchmark asserts nothing).
void Benchmark::Compare()
{
  char text[512];
  // (i) PGM 512^2 against the textured sphere, whole Earth, 1024 x 768.
  {
    const Row* pgm = this->FindRow("pgm", { 512, 512 }, EarthView, AccuracyWindow);
    const Row* sphere = this->FindRow("sphere", this->Opt.Sphere, EarthView, AccuracyWindow);
    Comparison c{ "pgm512_vs_sphere", "", "" };
    if (pgm && sphere)
    {
      const double ratio = pgm->Time.Median / sphere->Time.Median;
      c.Result = ratio <= 3.0 ? "PASS" : "MISS";
      std::snprintf(text, sizeof(text),
        "(i) PGM grid 512^2 at 1024x768, whole Earth: %.2f ms = %.2fx the textured sphere's "
        "%.2f ms (target <= 3x): %s",
        pgm->Time.Median, ratio, sphere->Time.Median, c.Result.c_str());
    }
    else
    {
      c.Result = "NOT MEASURED";
      std::snprintf(text, sizeof(text), "(i) PGM 512^2 vs sphere: not measured in this run");
    }
    c.Statement = text;
    this->Comparisons.push_back(c);
  }
  // (ii) PGM 512^2 against the cheapest warped mesh at least as accurate (p95), Rainier.
  {
    const Row* pgm = this->FindRow("pgm", { 512, 512 }, RainierView, AccuracyWindow);
    Comparison c{ "pgm512_vs_equally_accurate_mesh", "", "" };
    if (pgm && pgm->Error.Measured)
    {
      const Row* match = nullptr;
      const Row* best = nullptr; // the most accurate mesh, for the statement when none matches
      for (const Row& row : this->Rows)
      {
        if (row.Method != "mesh" || row.ViewIndex != RainierView || !row.Error.Measured)
        {
          continue;
        }
        if (!best || row.Error.P95 < best->Error.P95)
        {
          best = &row;
        }
        if (row.Error.P95 <= pgm->Error.P95 && (!match || row.Triangles < match->Triangles))
        {
          match = &row;
        }
      }
      if (match)
      {
        c.Result = pgm->Time.Median < match->Time.Median ? "PASS" : "MISS";
        std::snprintf(text, sizeof(text),
          "(ii) Rainier at 1024x768: PGM 512^2 (p95 %.1f m) %.2f ms; the smallest mesh as "
          "accurate, %s (p95 %.1f m), %.2f ms: %s",
          pgm->Error.P95, pgm->Time.Median, match->Resolution.ToString().c_str(), match->Error.P95,
          match->Time.Median, c.Result.c_str());
      }
      else
      {
        c.Result = "PASS";
        std::snprintf(text, sizeof(text),
          "(ii) Rainier at 1024x768: PGM 512^2 (p95 %.1f m, %.2f ms); no warped mesh measured "
          "reaches that p95 (best: %s, p95 %.1f m, %.2f ms): a win for PGM: %s",
          pgm->Error.P95, pgm->Time.Median,
          best ? best->Resolution.ToString().c_str() : "none",
          best ? best->Error.P95 : NaN, best ? best->Time.Median : NaN, c.Result.c_str());
      }
    }
    else
    {
      c.Result = "NOT MEASURED";
      std::snprintf(text, sizeof(text), "(ii) PGM 512^2 vs meshes: not measured in this run");
    }
    c.Statement = text;
    this->Comparisons.push_back(c);
  }
  std::printf("\nTargets:\n");
  for (const Comparison& c : this->Comparisons)
  {
    std::printf("  %s\n", c.Statement.c_str());
  }
}

bool Benchmark::WriteJson(double totalSeconds)
{
  std::ostringstream j;
  j << "{\n  \"benchmark\": \"GlobeBenchmark\",\n";
  j << "  \"date\": " << JsonString(UtcNow()) << ",\n";
  j << "  \"machine\": {\"gl_renderer\": " << JsonString(this->Renderer)
    << ", \"gl_version\": " << JsonString(this->Version)
    << ", \"gl_vendor\": " << JsonString(this->Vendor) << ", \"cpu\": " << JsonString(CpuModel())
    << ", \"cpu_threads\": " << std::thread::hardware_concurrency()
    << ", \"timer_queries\": " << (vtkOpenGLRenderTimer::IsSupported() ? "true" : "false")
    << "},\n";
  j << "  \"settings\": {\"quick\": " << (this->Opt.Quick ? "true" : "false")
    << ", \"frames\": " << this->Opt.Frames << ", \"warmup\": " << this->Opt.Warmup
    << ", \"seconds_per_configuration\": " << JsonNumber(this->Opt.SecondsPerConfiguration)
    << ", \"minimum_frames\": " << this->Opt.MinimumFrames
    << ", \"seconds_per_mesh\": " << JsonNumber(this->Opt.SecondsPerMesh)
    << ", \"accuracy_window\": [" << AccuracyWindow.X << ", " << AccuracyWindow.Y
    << "], \"accuracy_pixel_stride\": 2},\n";
  j << "  \"viewpoints\": [\n";
  for (int v = 0; v < 2; ++v)
  {
    const View& view = Views[v];
    j << "    {\"name\": " << JsonString(view.Name) << ", \"camera_lon_lat_h\": ["
      << JsonNumber(view.Camera[0]) << ", " << JsonNumber(view.Camera[1]) << ", "
      << JsonNumber(view.Camera[2]) << "], \"target_lon_lat_h\": [" << JsonNumber(view.Target[0])
      << ", " << JsonNumber(view.Target[1]) << ", " << JsonNumber(view.Target[2])
      << "], \"view_angle_deg\": " << JsonNumber(view.ViewAngle) << ", \"clipping_range_m\": ["
      << JsonNumber(view.Near) << ", " << JsonNumber(view.Far) << "]}" << (v ? "\n" : ",\n");
  }
  j << "  ],\n  \"total_seconds\": " << JsonNumber(totalSeconds) << ",\n";
  j << "  \"notes\": [";
  for (size_t i = 0; i < this->Notes.size(); ++i)
  {
    j << (i ? ", " : "") << JsonString(this->Notes[i]);
  }
  j << "],\n  \"rows\": [\n";
  for (size_t i = 0; i < this->Rows.size(); ++i)
  {
    const Row& r = this->Rows[i];
    j << "    {\"method\": " << JsonString(r.Method)
      << ", \"viewpoint\": " << JsonString(Views[r.ViewIndex].Name) << ", \"window\": ["
      << r.Window.X << ", " << r.Window.Y << "], \"size\": [" << r.Resolution.X << ", "
      << r.Resolution.Y << "], \"triangles\": " << JsonNumber(r.Triangles)
      << ", \"warmup\": " << r.Warmup << ", \"frames\": " << r.Time.Count
      << ",\n     \"frame_ms\": {\"median\": " << JsonNumber(r.Time.Median)
      << ", \"q1\": " << JsonNumber(r.Time.Q1) << ", \"q3\": " << JsonNumber(r.Time.Q3)
      << ", \"iqr\": " << JsonNumber(r.Time.Q3 - r.Time.Q1) << ", \"min\": " << JsonNumber(r.Time.Min)
      << ", \"max\": " << JsonNumber(r.Time.Max) << "},\n     \"stage_ms\": ";
    if (r.Method == "pgm")
    {
      j << "{";
      for (int k = 0; k < NumberOfStages; ++k)
      {
        j << (k ? ", " : "") << JsonString(StageNames[k]) << ": " << JsonNumber(r.Stages[k]);
      }
      j << "}";
    }
    else
    {
      j << "null";
    }
    j << ",\n     \"height_error_m\": ";
    if (r.Error.Measured)
    {
      j << "{\"pixels\": " << r.Error.Pixels << ", \"invalid\": " << r.Error.Invalid
        << ", \"median\": " << JsonNumber(r.Error.Median) << ", \"p95\": " << JsonNumber(r.Error.P95)
        << ", \"max\": " << JsonNumber(r.Error.Max) << "}";
    }
    else
    {
      j << "null";
    }
    j << "}" << (i + 1 < this->Rows.size() ? ",\n" : "\n");
  }
  j << "  ],\n  \"effects\": [\n";
  for (size_t i = 0; i < this->EffectRows.size(); ++i)
  {
    const Row& r = this->EffectRows[i].second;
    j << "    {\"effects\": " << JsonString(this->EffectRows[i].first)
      << ", \"viewpoint\": \"earth\", \"window\": [" << r.Window.X << ", " << r.Window.Y
      << "], \"grid\": 512, \"frames\": " << r.Time.Count
      << ", \"frame_ms\": {\"median\": " << JsonNumber(r.Time.Median)
      << ", \"q1\": " << JsonNumber(r.Time.Q1) << ", \"q3\": " << JsonNumber(r.Time.Q3)
      << "}, \"composite_ms\": " << JsonNumber(r.Stages[CompositeStage]) << "}"
      << (i + 1 < this->EffectRows.size() ? ",\n" : "\n");
  }
  j << "  ],\n  \"comparisons\": [\n";
  for (size_t i = 0; i < this->Comparisons.size(); ++i)
  {
    const Comparison& c = this->Comparisons[i];
    j << "    {\"name\": " << JsonString(c.Name) << ", \"result\": " << JsonString(c.Result)
      << ", \"statement\": " << JsonString(c.Statement) << "}"
      << (i + 1 < this->Comparisons.size() ? ",\n" : "\n");
  }
  j << "  ]\n}\n";

  std::ofstream file(this->Opt.Json);
  file << j.str();
  file.close();
  if (!file)
  {
    std::fprintf(stderr, "Could not write %s\n", this->Opt.Json.c_str());
    return false;
  }
  std::printf("\nWrote %s\n", this->Opt.Json.c_str());
  return true;
}

int Benchmark::Run()
{
  this->Prepare();
  std::fprintf(stderr, "GlobeBenchmark on %s: %d warm-up + %d timed frames per configuration%s\n",
    this->Renderer.c_str(), this->Opt.Warmup, this->Opt.Frames, this->Opt.Quick ? " (quick)" : "");
  if (!vtkOpenGLRenderTimer::IsSupported())
  {
    this->Note("no GPU timer queries: the per-stage times are not available");
  }
  if (!this->Opt.EffectsOnly)
  {
    this->RunGlobe();
    this->RunSphere();
    this->RunMeshes();
  }
  this->RunEffects();
  const double total = SecondsSince(this->Start);
  this->PrintTable();
  this->PrintEffects();
  this->Compare();
  std::printf("\nTotal run time: %.0f s (%.1f min)\n", total, total / 60.0);
  return this->WriteJson(total) ? 0 : 1;
}

/**
 * The cost of each effect of the screen composition: the whole-Earth view in the accuracy
 * window at grid 512^2, with lighting only (the default), each effect added alone, all of them,
 * and unlit. The water mask and night lights are image layers derived from the relief; they are
 * present in every configuration, but sampled only when their effect is on.
 */
void Benchmark::RunEffects()
{
  vtkGlobeMapper* mapper = this->Scene.Mapper;
  vtkGlobeTest::AddWaterMaskAndNightLights(mapper, this->Layers.front());
  mapper->SetGridResolution(512);
  this->Scene.Renderer->AddActor(this->Scene.Actor);
  struct Effect
  {
    const char* Name;
    bool Lighting, Night, Water, Atmosphere, Graticule, Contours;
  };
  const Effect effects[] = { { "lighting", true, false, false, false, false, false },
    { "+night lights", true, true, false, false, false, false },
    { "+specular water", true, false, true, false, false, false },
    { "+atmosphere", true, false, false, true, false, false },
    { "+graticule", true, false, false, false, true, false },
    { "+contours", true, false, false, false, false, true },
    { "all", true, true, true, true, true, true },
    { "unlit", false, false, false, false, false, false } };
  for (const Effect& e : effects)
  {
    mapper->SetLighting(e.Lighting);
    mapper->SetNightLights(e.Night);
    mapper->SetSpecularWater(e.Water);
    mapper->SetAtmosphere(e.Atmosphere);
    mapper->SetGraticule(e.Graticule);
    mapper->SetContours(e.Contours);
    Row row = this->TimeConfiguration(
      std::string("pgm ") + e.Name, { 512, 512 }, 2.0 * 511 * 511, EarthView, AccuracyWindow, false);
    this->EffectRows.emplace_back(e.Name, row);
  }
  this->Scene.Renderer->RemoveViewProp(this->Scene.Actor);
}

void Benchmark::PrintEffects()
{
  if (this->EffectRows.empty())
  {
    return;
  }
  const Row& base = this->EffectRows.front().second;
  std::printf("\nEffects: whole Earth, PGM 512^2, %s window. Frame: median wall ms; composite: "
              "median GPU ms of the screen pass; extra: against lighting only.\n\n",
    AccuracyWindow.ToString().c_str());
  std::printf("%-16s %6s %9s %7s %10s %12s\n", "effects", "frames", "frame", "IQR", "composite",
    "extra frame");
  for (const auto& [name, row] : this->EffectRows)
  {
    std::printf("%-16s %6d %9s %7s %10s %12s\n", name.c_str(), row.Time.Count,
      Format(row.Time.Median).c_str(), Format(row.Time.Q3 - row.Time.Q1).c_str(),
      Format(row.Stages[CompositeStage]).c_str(),
      Format(row.Time.Median - base.Time.Median, "%+.2f").c_str());
  }
}

void Usage(const char* program)
{
  std::printf(
    "usage: %s [--quick] [--frames N] [--json PATH] [--help]\n"
    "  Times the PGM globe (grids 256^2, 512^2, 1024^2) against a textured sphere and warped\n"
    "  lon/lat meshes (256x128 .. 4096x2048) at the whole-Earth and Rainier views in windows of\n"
    "  256^2, 512^2, 1024^2 and 1024x768, and measures their height error at the Rainier view.\n"
    "  Then times each effect of the composition (whole Earth, 512^2, 1024x768).\n"
    "  --quick      fewer sizes and frames (a smoke run)\n"
    "  --effects-only  only the effects section\n"
    "  --frames N   timed frames per configuration (default 30; the slowest meshes get fewer)\n"
    "  --json PATH  where to write the numbers (default benchmark.json)\n",
    program);
}
} // namespace

int main(int argc, char* argv[])
{
  Options options;
  int frames = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--quick")
    {
      options.Quick = true;
    }
    else if (arg == "--effects-only")
    {
      options.EffectsOnly = true;
    }
    else if (arg == "--frames" && i + 1 < argc && std::atoi(argv[i + 1]) > 0)
    {
      frames = std::atoi(argv[++i]);
    }
    else if (arg == "--json" && i + 1 < argc)
    {
      options.Json = argv[++i];
    }
    else
    {
      Usage(argv[0]);
      return arg == "--help" || arg == "-h" ? 0 : 2;
    }
  }
  if (options.Quick)
  {
    // Enough for both target statements: grid 512^2, the sphere and two meshes at 1024 x 768.
    options.Frames = 10;
    options.Warmup = 2;
    options.Grids = { 256, 512 };
    options.Windows = { { 512, 512 }, { 1024, 768 } };
    options.Meshes = { { 256, 128 }, { 1024, 512 } };
  }
  if (frames > 0)
  {
    options.Frames = frames;
    options.MinimumFrames = std::min(options.MinimumFrames, frames);
  }
  Benchmark benchmark(options);
  return benchmark.Run();
}
