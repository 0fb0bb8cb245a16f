// GlobeBenchmark: what accuracy costs in time. On fixed scenes it sweeps the settings that trade
// accuracy for time and puts every error next to its milliseconds; VTK's naive globes run on the
// same scenes, in the same window, in the same run. A program, not a test: it prints tables and
// writes JSON, and asserts nothing (Documentation/accuracy-vs-time.md, "How to run";
// architecture.md, "How it is tested"). Utilities/plot_benchmark.py turns the JSON
// into Documentation/images/accuracy-vs-time-<scene>.png and the Pareto fronts;
// `bash Utilities/globe.sh bench` runs both.
//
//   GlobeBenchmark [--quick] [--frames N] [--json PATH] [--scene NAME]... [--window WxH]
//                  [--effects-only] [--grid-only] [--refinement-only] [--no-matrix]
//                  [--still] [--conditions TEXT] [--help]
//
// Scenes (window 800 x 600 unless --window; one window, renderer and globe for everything):
//   earth      the whole Earth from 22,000 km;
//   rainier    Mount Rainier from ~20 km (the demo's view);
//   everest    1.5 m above the summit of the composed data, looking 4 degrees down to the
//              horizon ~330 km away (ESE, over Makalu);
//   satellite  2 m above the ground west of Rainier looking east, a sphere mesh (100 km radius)
//              400 km up rising over the limb, its lower part behind the Earth.
// Settings, in families (each a list of setters applied to the defaults; see Settings()):
//   baseline     the mapper's defaults, read from a new vtkGlobeMapper: the automatic grid
//                (1.6 px per cell: 500^2 at 800 x 600) with 1 terrain refinement step, Default
//                depth with the vtkGlobeClippingRange policy, lighting only, layers as loaded
//                (linear, feather 8, no projection weight);
//   grid         grid 128^2 .. 1024^2, and the automatic grid at 3.2 px per cell (refined);
//   grid-window  grid = 1/2, 1, 2 x the window's larger side;
//   depth        Default / Logarithmic (vtkGlobeDepthPass) x VTK's plain clipping / the policy;
//   precision    float geodetic coordinates (vtkGlobeMapper::HighPrecisionGeodeticOff) against
//                the default hi/lo ones;
//   composition  colour layers nearest, feather 0 / 32 texels (all layers), Kooima's projection
//                weight (colour layers); the composition over the whole viewport, sky included
//                (vtkGlobeCompositePass::BlockCullingOff, as before 2026-11-28);
//   effects      unlit, each effect alone on top of lighting, all;
//   refinement   per-pixel terrain refinement: none (the defaults until 2026-11-28), 2 and 3
//                steps at the default grid; 512^2 unrefined (the benchmark's baseline until
//                then); 2 steps and none at 128^2 (--refinement-only adds 1 and 2 steps at
//                4.8 and 6.4 px per cell);
//   naive        vtkTexturedSphereSource (256 x 128) and global lon/lat meshes warped by the
//                composed heights (double points), VTK's perspective depth, with the clipping
//                range the policy gives the globe there (VTK's own range, fitted to the body,
//                clips the terrain of every close view: the depth family shows that on PGM).
// Measured per setting, in the same run:
//   time: warm-up frames, then >= 30 timed frames (Render + glFinish, wall clock) alternating
//     between the view and the view turned by a quarter pixel (no frame can reuse the last;
//     --still: the view alone, so no frame waits for a new view's reduction):
//     median, quartiles; per-stage GPU medians from the mapper's timer queries. Configurations
//     slower than 20 s get 2 warm-up and >= 10 timed frames ("frames_reduced": true).
//   terrain: at every sample pixel (a regular grid of ~20,000), the exact ray/terrain hit E
//     (double; the composed data, vtkGlobeTest::ComposedHeight, marched and bisected) against the
//     point P the depth buffer reconstructs (read in the depth mode): error_m = |P - E| (along
//     the ray); error_px = the screen distance between the pixel and where the data's surface
//     point under P (its lon, lat at the data's height) projects; height_error_m = |h(P) -
//     data(lon, lat)|. "missing": E exists but nothing (or another surface) is drawn;
//     "extra": terrain drawn where the exact ray meets none. p95_all_px counts missing and extra
//     samples as infinitely wrong (null when they exceed 5 %).
//   registration_px: a 256^2 marker colour layer (nearest, so read at level 0) whose red and
//     green are its own texel column and row is placed (top, unlit, effects off) on a patch
//     around the view centre with texels a third of a pixel; the colour drawn decodes the (lon, lat) the composition sampled, and
//     its surface point is projected against the exact hit's pixel. Quantization floor ~0.17 px.
//   jitter_px: the same samples rendered again with the camera turned by 0.25 px (exact hits
//     cast again): how much the on-screen error vector of each sample (error_px, as a vector)
//     changes between the two frames. A static error moves with the surface and gives ~0; a
//     grid that swims with the camera does not. jitter_m: the same for the along-ray error.
//   wrong_surface (satellite scene): every pixel whose exact ray meets the satellite, away from
//     its silhouette and from terrain crossings within 1 m + 2 % of the distance: is the colour
//     drawn the satellite's exactly when the satellite is nearer than the terrain?
//   memory: GPU bytes of the layers' textures (vtkGlobeLayerSet::GetTextureMemory), the G-buffer
//     and grid textures (from their sizes and formats); naive: vertex/index buffers and the
//     mipmapped texture (estimated); CPU VmRSS / VmHWM from /proc/self/status.
//
// JSON schema (schema 2):
// {
//   "benchmark": "GlobeBenchmark", "schema": 2, "date": UTC, "conditions": free text,
//   "machine": {"gl_renderer", "gl_version", "gl_vendor", "depth_buffer", "cpu", "cpu_threads",
//               "timer_queries", "loadavg_start", "loadavg_end"},
//   "settings": {"quick", "frames", "warmup", "window": [w, h], "seconds_per_configuration",
//                "minimum_frames", "samples_target"},
//   "total_seconds": s, "notes": [text],
//   "scenes": [{"name", "description", "window": [w, h], "view_angle_deg", "eye_lon_lat_h",
//               "samples", "sample_stride", "reference_seconds", "clipping_policy_m": [n, f],
//               "clipping_vtk_m": [n, f], "marker": {"west", "east", "south", "north",
//               "texel_px", "samples"}}],
//   "rows": [{"scene", "family", "setting", "method": "pgm"|"sphere"|"mesh", "grid": n|null,
//             "size": [x, y]|null, "triangles", "warmup", "frames", "frames_reduced",
//             "frame_ms": {"median", "q1", "q3", "iqr", "min", "max"},
//             "stage_ms": {"pgm", "height", "raster", "composite", "reduction"}|null,
//             "terrain": {"samples", "missing", "extra", "error_m": Q, "error_px": Q,
//                         "height_error_m": Q, "p95_all_px": x|null},
//             "registration_px": Q + {"samples"} | null, "registration_note": text,
//             "jitter_px": Q + {"samples"}, "jitter_m": Q, "wrong_surface": {"checked", "wrong", "hidden",
//             "grazing"}|null,
//             "memory": {"gpu_layers", "gpu_gbuffer", "gpu_grid", "gpu_mesh", "gpu_total",
//                        "cpu_rss", "cpu_hwm"} (bytes)}],   Q = {"median", "p95", "max"}
//   "matrix": [{"grid", "window": [w, h], "frames", "frame_ms", "stage_ms"}]  (whole Earth,
//             Mahsman's Tables 6.2-6.4 layout: grid x window),
//   "comparisons": [{"name", "result", "statement"}],
//   "pareto": {scene: [{"family", "setting", "method", "frame_ms", "error"}]}  (added by
//             Utilities/plot_benchmark.py)
// }
#include "vtkGlobeRenderingTestHelpers.h" // Scene, LookAt, ReadDepth, UnprojectPixel, ComposedHeight

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkGlobeClippingRange.h"
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeDepthPass.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGeodeticTransform.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobeMapperTesting.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkTexturedSphereSource.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h" // glFinish, glGetString

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
const double NaN = std::numeric_limits<double>::quiet_NaN();

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Size
{
  int X, Y;
  bool operator==(const Size& o) const { return this->X == o.X && this->Y == o.Y; }
  std::string ToString() const { return std::to_string(this->X) + "x" + std::to_string(this->Y); }
};

struct Options
{
  bool Quick = false;
  bool EffectsOnly = false;
  bool GridOnly = false;
  bool RefinementOnly = false;
  bool Matrix = true;
  bool Still = false; // time every frame at view A: no frame pays a new view's reduction wait
  int Frames = 30;
  int Warmup = 5;
  std::string Json = "benchmark.json";
  std::string Conditions;
  Size Window = { 800, 600 };
  std::vector<std::string> Scenes = { "earth", "rainier", "everest", "satellite" };
  std::vector<int> Grids = { 128, 256, 512, 1024 };
  std::vector<double> GridFactors = { 0.5, 1.0, 2.0 };
  std::vector<std::string> Effects = { "unlit", "+night lights", "+specular water",
    "+atmosphere", "+graticule", "+contours", "+height colours", "all" };
  std::vector<std::string> Depth = { "default, VTK clipping", "logarithmic, policy",
    "logarithmic, VTK clipping" };
  std::vector<std::string> Compositions = { "colour nearest", "feather 0", "feather 32",
    "colour projection weight", "whole viewport" };
  Size Sphere = { 256, 128 };
  std::vector<Size> Meshes = { { 256, 128 }, { 1024, 512 }, { 2048, 1024 }, { 4096, 2048 } };
  std::vector<int> MatrixGrids = { 256, 512, 1024 };
  std::vector<Size> MatrixWindows = { { 256, 256 }, { 512, 512 }, { 1024, 1024 }, { 1024, 768 } };
  int Samples = 20000; // target number of sample pixels per scene
  // Configurations slower than this are timed with 2 warm-up frames and fewer timed ones (at
  // least MinimumFrames), so the largest meshes and grids do not dominate the run.
  double SecondsPerConfiguration = 20.0;
  int MinimumFrames = 10;
};

/// Order statistics, interpolated between order statistics.
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

struct Stats
{
  int Count = 0;
  double Median = NaN, Q1 = NaN, Q3 = NaN, Min = NaN, Max = NaN, P95 = NaN;
};

Stats Summarize(std::vector<double> values)
{
  Stats s;
  std::sort(values.begin(), values.end());
  s.Count = static_cast<int>(values.size());
  if (s.Count > 0)
  {
    s.Median = Quantile(values, 0.5);
    s.Q1 = Quantile(values, 0.25);
    s.Q3 = Quantile(values, 0.75);
    s.P95 = Quantile(values, 0.95);
    s.Min = values.front();
    s.Max = values.back();
  }
  return s;
}

// The GPU stages vtkGlobeMapper times (Documentation/architecture.md, "One frame").
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

struct Timing
{
  int Warmup = 0;
  bool Reduced = false;
  Stats Time;
  double Stages[NumberOfStages] = { NaN, NaN, NaN, NaN, NaN }; // median ms; NaN: none
};

struct Memory
{
  double GpuLayers = NaN, GpuGBuffer = NaN, GpuGrid = NaN, GpuMesh = NaN, CpuRss = NaN,
         CpuHwm = NaN;
};

struct Accuracy
{
  bool Measured = false;
  int Samples = 0, Missing = 0, Extra = 0;
  Stats ErrorM, ErrorPx, HeightM;
  double P95AllPx = NaN;
  bool RegistrationMeasured = false;
  std::string RegistrationNote;
  Stats RegistrationPx;
  Stats JitterPx, JitterM;
  bool SurfaceMeasured = false;
  int Checked = 0, Wrong = 0, Hidden = 0, Grazing = 0;
};

struct Row
{
  std::string Scene, Family, Setting, Method;
  int Grid = 0;               // pgm
  Size Resolution = { 0, 0 }; // naive: cells in lon x lat
  double Triangles = 0;
  Timing Time;
  Accuracy Error;
  Memory Mem;
};

struct MatrixRow
{
  int Grid;
  Size Window;
  Timing Time;
};

/// VmRSS and VmHWM of this process (bytes).
void ProcessMemory(double& rss, double& hwm)
{
  rss = hwm = NaN;
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    const bool isRss = line.rfind("VmRSS:", 0) == 0, isHwm = line.rfind("VmHWM:", 0) == 0;
    if (isRss || isHwm)
    {
      (isRss ? rss : hwm) = 1024.0 * std::atof(line.c_str() + 6);
    }
  }
}

double TextureBytes(vtkTextureObject* t)
{
  if (!t || !t->GetHandle())
  {
    return 0.0;
  }
  const int type = t->GetVTKDataType();
  const int bytes = type == VTK_FLOAT ? 4 : (type == VTK_UNSIGNED_CHAR || type == VTK_CHAR ? 1 : 4);
  return static_cast<double>(t->GetWidth()) * t->GetHeight() * t->GetComponents() * bytes;
}

//------------------------------------------------------------------------------
// The naive globes.

/// The colour layer's RGBA pixels as a VTK texture. The layer's row 0 is north; VTK's image
/// row 0 is at t = 0, which the sphere and the mesh put at the south pole.
vtkSmartPointer<vtkTexture> ImageryTexture(vtkGlobeLayer* layer)
{
  auto* rgba = vtkUnsignedCharArray::SafeDownCast(layer->GetData());
  const int w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
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
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

std::string JsonQ(const Stats& s, bool withCount = false)
{
  if (s.Count == 0)
  {
    return "null";
  }
  std::string out = "{\"median\": " + JsonNumber(s.Median) + ", \"p95\": " + JsonNumber(s.P95) +
    ", \"max\": " + JsonNumber(s.Max);
  if (withCount)
  {
    out += ", \"samples\": " + std::to_string(s.Count);
  }
  return out + "}";
}

std::string JsonTime(const Stats& s)
{
  return "{\"median\": " + JsonNumber(s.Median) + ", \"q1\": " + JsonNumber(s.Q1) +
    ", \"q3\": " + JsonNumber(s.Q3) + ", \"iqr\": " + JsonNumber(s.Q3 - s.Q1) +
    ", \"min\": " + JsonNumber(s.Min) + ", \"max\": " + JsonNumber(s.Max) + "}";
}

std::string JsonStages(const Timing& t)
{
  std::string out = "{";
  for (int k = 0; k < NumberOfStages; ++k)
  {
    out += std::string(k ? ", " : "") + JsonString(StageNames[k]) + ": " + JsonNumber(t.Stages[k]);
  }
  return out + "}";
}

std::string GLString(GLenum name)
{
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "unknown";
}

/// The depth buffer the scene is drawn into (VTK's render framebuffer, where the window has
/// one; VTK 9.1 asks the same 32 bits for the framebuffers it blits to): bits and type.
/// Renderers differ here (an unsigned normalized 32-bit request may be served with 24 bits).
std::string DepthBufferFormat(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    return "unknown";
  }
  gl->MakeCurrent();
  GLint previous = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
  vtkOpenGLFramebufferObject* fbo = gl->GetRenderFramebuffer();
  GLint bits = 0, type = 0;
  if (fbo && fbo->GetFBOIndex() != 0)
  {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo->GetFBOIndex());
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
  }
  else
  {
    bits = gl->GetDepthBufferSize();
  }
  const char* kind = type == GL_FLOAT ? " float"
    : type == GL_UNSIGNED_NORMALIZED ? " unorm"
                                     : "";
  return std::to_string(bits) + "-bit" + kind;
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

std::string LoadAverage()
{
  std::ifstream file("/proc/loadavg");
  std::string a, b, c;
  file >> a >> b >> c;
  return a + " " + b + " " + c;
}

std::string UtcNow()
{
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
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

//------------------------------------------------------------------------------
// Scenes and their exact reference.

/// A camera: eye, focal point and view-up in the world (the body frame), vertical view angle.
struct Pose
{
  double Eye[3], Focal[3], Up[3];
  double ViewAngle;
};

/// One sample pixel's exact answer (double): the nearest terrain and object along its ray.
struct Sample
{
  double X, Y;        // pixel centre
  double Ray[3];
  double Terrain = -1; // eye distance of the terrain hit, -1: none
  double Object = -1;  // eye distance of the satellite hit, -1: none
  double Hit[3] = { 0, 0, 0 };
  bool TerrainFirst() const { return this->Terrain > 0 && (this->Object < 0 || this->Terrain < this->Object); }
};

struct Reference
{
  std::vector<Sample> A, B; // the view and the view turned by a quarter pixel
  double Seconds = 0;
};

struct SceneDef
{
  std::string Name, Description;
  Pose A, B;
  bool Satellite = false;
  double SatelliteCentre[3] = { 0, 0, 0 };
  double SatelliteRadius = 0;
  int Stride = 8;
  // Marker patch (registration): geographic box and texel size in pixels.
  double Marker[4] = { 0, 0, 0, 0 };
  double MarkerTexelPx = 0;
  int MarkerSamples = 0;
  double ClipPolicy[2] = { NaN, NaN }, ClipVtk[2] = { NaN, NaN };
  std::map<std::string, Reference> References; // by the height layers' composition settings
  double ReferenceSeconds = 0;
  // Wrong-surface classification of the satellite's pixels (pose A): 1 object in front,
  // 0 terrain in front, -1 not checked (silhouette, grazing, elsewhere).
  std::vector<signed char> Expect;
  int Grazing = 0;
};

/// The exact ray/terrain hit (double): sphere tracing on the height over the composed data
/// from where the ray enters the shell of the highest data, bisected at the crossing. Steps are
/// a third of the clearance (slopes up to 3:1 cannot be jumped), at least 1 cm + 0.02 % of the
/// distance. -1: no hit.
double ExactTerrainHit(vtkGlobeEllipsoid* body, const std::vector<vtkGlobeLayer*>& layers,
  const double eye[3], const double ray[3], double maxHeight)
{
  const double* radii = body->GetRadii();
  const double outer = std::max(radii[0], std::max(radii[1], radii[2])) + maxHeight;
  const double b = vtkMath::Dot(eye, ray);
  const double c = vtkMath::Dot(eye, eye) - outer * outer;
  const double disc = b * b - c;
  if (disc < 0)
  {
    return -1;
  }
  const double tMax = -b + std::sqrt(disc);
  if (tMax <= 0)
  {
    return -1;
  }
  double s = std::max(0.0, -b - std::sqrt(disc));
  double previous = s;
  while (s <= tMax)
  {
    const double over = vtkGlobeTest::RayHeightOverTerrain(body, layers, eye, ray, s);
    if (over < 0.0)
    {
      double lo = previous, hi = s;
      for (int i = 0; i < 50; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (vtkGlobeTest::RayHeightOverTerrain(body, layers, eye, ray, mid) < 0.0 ? hi : lo) = mid;
      }
      return 0.5 * (lo + hi);
    }
    previous = s;
    s += std::max(0.01 + 2e-4 * s, over / 3.0);
  }
  return -1;
}

/// Camera turned (yaw) by a fraction of a pixel of a window of the given height.
Pose Turned(const Pose& a, int windowHeight, double pixels)
{
  Pose b = a;
  double forward[3], right[3];
  for (int i = 0; i < 3; ++i)
  {
    forward[i] = a.Focal[i] - a.Eye[i];
  }
  const double distance = vtkMath::Norm(forward);
  vtkMath::Cross(forward, a.Up, right);
  vtkMath::Normalize(right);
  const double angle = pixels * vtkMath::RadiansFromDegrees(a.ViewAngle) / windowHeight;
  for (int i = 0; i < 3; ++i)
  {
    b.Focal[i] = a.Focal[i] + std::tan(angle) * distance * right[i];
  }
  return b;
}

//------------------------------------------------------------------------------
class Benchmark;

/// One setting of a family: what to call it and how to apply it on top of the defaults.
struct Setting
{
  std::string Family, Name;
  std::function<void()> Apply;
  bool Registration = true; // false: cannot change the registration (copied from the baseline)
};

class Benchmark
{
public:
  explicit Benchmark(const Options& options)
    : Opt(options)
    , Scene(options.Window.X, options.Window.Y, 512)
  {
  }

  int Run();

private:
  void Prepare();
  SceneDef MakeScene(const std::string& name);
  std::vector<Setting> Settings();
  void ResetDefaults();
  std::string HeightSignature();
  Reference& GetReference(SceneDef& scene);
  void ClassifySatellite(SceneDef& scene);
  void SetPose(const Pose& pose, bool policy);
  void RenderAt(const Pose& pose);
  Timing Time(const std::string& label, const Pose& a, const Pose& b, vtkGlobeMapper* globe,
    bool capped);
  Accuracy Measure(SceneDef& scene, bool registration);
  void MeasureRegistration(SceneDef& scene, const Reference& ref, Accuracy& result);
  void MeasureMemory(Row& row, bool globe);
  void RunScene(SceneDef& scene);
  void RunNaive(SceneDef& scene);
  void RunMatrix();
  void Project(const double world[3], double display[2]);
  void PrintTables();
  void Compare();
  bool WriteJson(double totalSeconds);
  void Note(const std::string& note);

  struct Comparison
  {
    std::string Name, Statement, Result;
  };
  struct Naive
  {
    std::string Method;
    Size Resolution;
    double Triangles;
    vtkSmartPointer<vtkActor> Actor;
    double GpuBytes;
  };

  Options Opt;
  vtkGlobeTest::Scene Scene; // the one window, renderer and PGM globe every candidate uses
  vtkNew<vtkGlobeMapper> Defaults; // a mapper as constructed, never rendered: the defaults
  vtkNew<vtkGlobeDepthPass> DepthPass;
  vtkNew<vtkRenderer> PlainRenderer; // shares the camera: VTK's own clipping range
  bool Policy = true;                // the clipping policy (else VTK's plain range)
  double FixedRange[2] = { 0, 0 };     // when > 0: this explicit range (the naive globes)
  std::vector<vtkGlobeLayer*> Layers;
  vtkGlobeLayer* Color = nullptr;
  std::map<vtkGlobeLayer*, double> DefaultFeather;
  vtkNew<vtkColorTransferFunction> Tint; // "+height colours": a hypsometric tint
  vtkSmartPointer<vtkTexture> Imagery;
  vtkSmartPointer<vtkActor> SatelliteActor;
  vtkNew<vtkGlobeLayer> MarkerLayer;
  double MaximumHeight = 9000.0;
  std::vector<SceneDef> Scenes;
  std::vector<Naive> NaiveGlobes;
  std::vector<Row> Rows;
  std::vector<MatrixRow> MatrixRows;
  std::vector<std::string> Notes;
  std::vector<Comparison> Comparisons;
  std::string Renderer, Version, Vendor;
  std::string DepthBuffer; // the render framebuffer's depth: bits and type
  std::string LoadStart = LoadAverage();
  Clock::time_point Start = Clock::now();
};

void Benchmark::Note(const std::string& note)
{
  this->Notes.push_back(note);
  std::fprintf(stderr, "  note: %s\n", note.c_str());
}

/// Loads the layers (the demo's Earth, plus the water mask and night lights the effects use:
/// sampled only when their effect is on), installs the depth pass and reads the renderer.
void Benchmark::Prepare()
{
  this->Scene.AddEarthLayers();
  vtkGlobeMapper* mapper = this->Scene.Mapper;
  for (vtkGlobeLayer* layer : vtkGlobeTest::HeightLayers(mapper))
  {
    layer->Update();
    if (layer->GetRole() == vtkGlobeLayer::Color)
    {
      this->Color = layer;
    }
  }
  vtkGlobeTest::AddWaterMaskAndNightLights(mapper, mapper->GetLayer(0));
  this->Layers = vtkGlobeTest::HeightLayers(mapper);
  // The demo's atlas tint (Examples/Cxx/GlobeEarth.cxx, snow line 3,300 m).
  const double stops[][4] = { { -6000, 0.05, 0.15, 0.45 }, { -150, 0.45, 0.70, 0.90 },
    { 0, 0.12, 0.42, 0.20 }, { 500, 0.45, 0.62, 0.30 }, { 1500, 0.85, 0.78, 0.45 },
    { 2100, 0.62, 0.42, 0.25 }, { 3000, 0.58, 0.52, 0.48 }, { 3300, 0.95, 0.95, 0.95 },
    { 9000, 1.0, 1.0, 1.0 } };
  for (const auto& stop : stops)
  {
    this->Tint->AddRGBPoint(stop[0], stop[1], stop[2], stop[3]);
  }
  for (vtkGlobeLayer* layer : this->Layers)
  {
    this->DefaultFeather[layer] = layer->GetFeatherWidth();
  }
  this->Imagery = ImageryTexture(this->Color);
  this->Scene.Renderer->SetPass(this->DepthPass);
  vtkGlobeClippingRange::Install(this->Scene.Renderer);
  this->PlainRenderer->SetActiveCamera(this->Scene.Renderer->GetActiveCamera());

  // The tallest composed data bounds the exact ray casts.
  double highest = 0;
  for (vtkGlobeLayer* layer : this->Layers)
  {
    if (layer->GetRole() == vtkGlobeLayer::Height)
    {
      double range[2];
      layer->GetData()->GetRange(range, 0);
      highest = std::max(highest, range[1]);
    }
  }
  this->MaximumHeight = highest + 100.0;

  this->Scene.Window->Render();
  this->Scene.Window->MakeCurrent();
  this->Renderer = GLString(GL_RENDERER);
  this->Version = GLString(GL_VERSION);
  this->Vendor = GLString(GL_VENDOR);
  this->DepthBuffer = DepthBufferFormat(this->Scene.Window);
}

/// The mapper's defaults and the layers as loaded; the depth pass in Default mode, the policy.
void Benchmark::ResetDefaults()
{
  vtkGlobeMapper* m = this->Scene.Mapper;
  m->SetGridPixelsPerCell(this->Defaults->GetGridPixelsPerCell());
  this->DepthPass->SetModeToDefault();
  this->Policy = true;
  m->SetLighting(true);
  m->SetNightLights(false);
  m->SetSpecularWater(false);
  m->SetAtmosphere(false);
  m->SetGraticule(false);
  m->SetContours(false);
  m->GetCompositePass()->SetHeightColors(nullptr);
  m->GetCompositePass()->SetBlockCulling(true);
  for (vtkGlobeLayer* layer : this->Layers)
  {
    layer->SetFeatherWidth(this->DefaultFeather[layer]);
    layer->SetSkirtDistanceToAutomatic();
    layer->SetProjectionQualityWeight(false);
    if (layer->GetRole() == vtkGlobeLayer::Color)
    {
      layer->SetInterpolationToLinear();
    }
  }
  this->Scene.Mapper->SetHighPrecisionGeodetic(this->Defaults->GetHighPrecisionGeodetic());
  this->Scene.Mapper->SetTerrainRefinement(this->Defaults->GetTerrainRefinement());
  // No row changes it today; a row that does must not leak into the next scene's rows.
  this->Scene.Mapper->SetFootprintFiltering(this->Defaults->GetFootprintFiltering());
  this->Scene.Window->SetDesiredUpdateRate(0.0001); // VTK's default: still, full detail
}

/**
 * The families of settings. Each is a list of (family, name, setter) applied on top of
 * ResetDefaults(); the baseline row stands for the default value of every family.
 */
std::vector<Setting> Benchmark::Settings()
{
  vtkGlobeMapper* m = this->Scene.Mapper;
  std::vector<Setting> list;
  {
    const int steps = this->Defaults->GetTerrainRefinement();
    char name[96];
    std::snprintf(name, sizeof(name), "defaults (%.1f px per cell, %d refinement step%s)",
      this->Defaults->GetGridPixelsPerCell(), steps, steps == 1 ? "" : "s");
    list.push_back({ "baseline", name, [] {} });
  }
  if (this->Opt.EffectsOnly)
  {
    this->Opt.Grids.clear();
    this->Opt.GridFactors.clear();
  }
  for (int grid : this->Opt.Grids)
  {
    list.push_back({ "grid", std::to_string(grid) + "^2", [m, grid] { m->SetGridResolution(grid); } });
  }
  // The automatic grid at half the default density: the refinement's faster candidate.
  if (!this->Opt.EffectsOnly && !this->Opt.GridOnly)
  {
    list.push_back({ "grid", "automatic (3.2 px per cell)", [m] { m->SetGridPixelsPerCell(3.2); } });
  }
  // Interactive detail (vtkGlobeMapper::AutoAdjustDetail): the frames drawn while the camera
  // moves, at a rate no frame meets (an interactor style asks for 15 frames/s).
  if (!this->Opt.EffectsOnly)
  {
    list.push_back({ "interactive", "while moving (grid 2x coarser, unrefined)",
      [this] { this->Scene.Window->SetDesiredUpdateRate(1e6); } });
  }
  const int side = std::max(this->Opt.Window.X, this->Opt.Window.Y);
  for (double f : this->Opt.GridFactors)
  {
    const int grid = static_cast<int>(std::lround(f * side));
    char name[64];
    std::snprintf(name, sizeof(name), "%gx window (%d^2)", f, grid);
    list.push_back({ "grid-window", name, [m, grid] { m->SetGridResolution(grid); } });
  }
  std::vector<Setting> depth;
  depth.push_back({ "depth", "default, VTK clipping", [this] { this->Policy = false; } });
  depth.push_back({ "depth", "logarithmic, policy", [this] { this->DepthPass->SetModeToLogarithmic(); } });
  depth.push_back({ "depth", "logarithmic, VTK clipping", [this] {
                     this->DepthPass->SetModeToLogarithmic();
                     this->Policy = false;
                   } });
  for (const Setting& d : depth)
  {
    if (!this->Opt.EffectsOnly &&
      std::count(this->Opt.Depth.begin(), this->Opt.Depth.end(), d.Name))
    {
      list.push_back(d);
    }
  }
  // Per-pixel terrain refinement (vtkGlobeMapper::SetTerrainRefinement): what each Newton step
  // buys and costs at the default grid, the defaults it replaced, and a coarse grid (the
  // error no longer follows the grid's cells).
  if (!this->Opt.EffectsOnly && !this->Opt.GridOnly)
  {
    for (int steps : { 0, 2, 3 })
    {
      if (this->Opt.Quick && steps != 0)
      {
        continue;
      }
      list.push_back({ "refinement",
        steps == 0 ? "none (the defaults until 2026-11-28)" : std::to_string(steps) + " steps",
        [m, steps] { m->SetTerrainRefinement(steps); } });
    }
    if (!this->Opt.Quick)
    {
      list.push_back({ "refinement", "none, grid 512^2 (the baseline until 2026-11-28)", [m] {
                        m->SetGridResolution(512);
                        m->SetTerrainRefinement(0);
                      } });
      list.push_back({ "refinement", "2 steps, grid 128^2", [m] {
                        m->SetGridResolution(128);
                        m->SetTerrainRefinement(2);
                      } });
      list.push_back({ "refinement", "none, grid 128^2", [m] {
                        m->SetGridResolution(128);
                        m->SetTerrainRefinement(0);
                      } });
    }
    if (this->Opt.RefinementOnly)
    {
      // Coarser automatic grids (the cells scale with the window), refined: what lies beyond
      // the grid family's 3.2 px per cell.
      for (double pixels : { 4.8, 6.4 })
      {
        for (int steps : { 1, 2 })
        {
          char name[64];
          std::snprintf(name, sizeof(name), "%d step%s, automatic grid %.1f px per cell", steps,
            steps > 1 ? "s" : "", pixels);
          list.push_back({ "refinement", name, [m, pixels, steps] {
                            m->SetGridPixelsPerCell(pixels);
                            m->SetTerrainRefinement(steps);
                          } });
        }
      }
    }
  }
  if (this->Opt.RefinementOnly)
  {
    list.erase(std::remove_if(list.begin(), list.end(),
                 [](const Setting& s) {
                   return s.Family != "baseline" && s.Family != "refinement";
                 }),
      list.end());
    return list;
  }
  // The float path the hi/lo geodetic coordinates replaced (Documentation/rendering.md
  // "Geodetic precision"): what the precision costs and buys.
  if (!this->Opt.EffectsOnly && !this->Opt.GridOnly)
  {
    list.push_back({ "precision", "float geodetic", [m] { m->SetHighPrecisionGeodetic(false); } });
  }
  if (!this->Opt.EffectsOnly)
  {
    std::vector<Setting> composition;
    auto each = [this](const std::function<void(vtkGlobeLayer*)>& f) {
      for (vtkGlobeLayer* layer : this->Layers)
      {
        f(layer);
      }
    };
    composition.push_back({ "composition", "colour nearest", [each] {
                      each([](vtkGlobeLayer* l) {
                        if (l->GetRole() == vtkGlobeLayer::Color)
                        {
                          l->SetInterpolationToNearest();
                        }
                      });
                    } });
    // Texel feathers inside every border, height insets included (their default is a skirt).
    composition.push_back({ "composition", "feather 0", [each] {
                      each([](vtkGlobeLayer* l) {
                        l->SetSkirtDistance(0.0);
                        l->SetFeatherWidth(0.0);
                      });
                    } });
    composition.push_back({ "composition", "feather 32", [each] {
                      each([](vtkGlobeLayer* l) {
                        l->SetSkirtDistance(0.0);
                        l->SetFeatherWidth(32.0);
                      });
                    } });
    // Kooima's weight on the colour layers only: on height layers it makes the surface depend
    // on the view (an inset's weight drops below 1 where its texels are stretched).
    composition.push_back({ "composition", "colour projection weight", [each] {
                      each([](vtkGlobeLayer* l) {
                        if (l->GetRole() == vtkGlobeLayer::Color)
                        {
                          l->SetProjectionQualityWeight(true);
                        }
                      });
                    } });
    // The composition over the whole viewport, sky included, as before 2026-11-28
    // (Documentation/rendering.md "What the composition shades").
    composition.push_back({ "composition", "whole viewport",
      [m] { m->GetCompositePass()->SetBlockCulling(false); } });
    for (const Setting& c : composition)
    {
      if (std::count(this->Opt.Compositions.begin(), this->Opt.Compositions.end(), c.Name))
      {
        list.push_back(c);
      }
    }
  }
  for (const std::string& e : this->Opt.Effects)
  {
    const bool all = e == "all";
    std::function<void()> apply;
    if (e == "unlit")
    {
      apply = [m] { m->SetLighting(false); };
    }
    else
    {
      vtkColorTransferFunction* tint = this->Tint;
      apply = [m, e, all, tint] {
        m->GetCompositePass()->SetHeightColors(all || e == "+height colours" ? tint : nullptr);
        m->GetCompositePass()->SetHeightColorOpacity(0.55);
        m->SetNightLights(all || e == "+night lights");
        m->SetSpecularWater(all || e == "+specular water");
        m->SetAtmosphere(all || e == "+atmosphere");
        m->SetGraticule(all || e == "+graticule");
        m->SetContours(all || e == "+contours");
      };
    }
    list.push_back({ "effects", e, apply, false });
  }
  // The defaults again at the end: how far the machine drifted during the scene.
  list.push_back({ "baseline", "defaults, repeated last", [] {} });
  return list;
}

/// The height layers' settings the exact reference depends on (feathered borders).
std::string Benchmark::HeightSignature()
{
  std::string key;
  for (vtkGlobeLayer* layer : this->Layers)
  {
    if (layer->GetRole() == vtkGlobeLayer::Height)
    {
      key += Format(layer->GetFeatherWidth(), "%g") + "," + Format(layer->GetFeatherDistance(), "%g") +
        "," + Format(layer->GetSkirtDistance(), "%g") + ";";
    }
  }
  return key;
}

void Benchmark::SetPose(const Pose& pose, bool policy)
{
  vtkCamera* c = this->Scene.Renderer->GetActiveCamera();
  c->SetPosition(pose.Eye);
  c->SetFocalPoint(pose.Focal);
  c->SetViewUp(pose.Up);
  c->SetViewAngle(pose.ViewAngle);
  if (this->FixedRange[0] > 0)
  {
    c->SetClippingRange(this->FixedRange);
  }
  else if (policy)
  {
    this->Scene.Renderer->ResetCameraClippingRange();
  }
  else
  {
    // VTK's own range: a renderer without the policy, with the same props and camera.
    this->PlainRenderer->RemoveAllViewProps();
    vtkPropCollection* props = this->Scene.Renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* p = props->GetNextProp())
    {
      this->PlainRenderer->AddViewProp(p);
    }
    // VTK picks its near tolerance from the window's depth bits; this renderer has no window.
    this->PlainRenderer->SetNearClippingPlaneTolerance(
      this->Scene.Window->GetDepthBufferSize() > 16 ? 0.001 : 0.01);
    this->PlainRenderer->ResetCameraClippingRange();
    this->PlainRenderer->RemoveAllViewProps();
  }
}

/// Renders twice at a pose: PGM's second frame uses the first one's reduction, as in every
/// timed frame. The clipping range is the one set by SetPose for the view.
void Benchmark::RenderAt(const Pose& pose)
{
  vtkCamera* c = this->Scene.Renderer->GetActiveCamera();
  c->SetPosition(pose.Eye);
  c->SetFocalPoint(pose.Focal);
  c->SetViewUp(pose.Up);
  this->Scene.Window->Render();
  this->Scene.Window->Render();
}

void Benchmark::Project(const double world[3], double display[2])
{
  vtkRenderer* r = this->Scene.Renderer;
  r->SetWorldPoint(world[0], world[1], world[2], 1.0);
  r->WorldToDisplay();
  const double* d = r->GetDisplayPoint();
  display[0] = d[0];
  display[1] = d[1];
}

/**
 * A scene's camera and objects. The cameras are built from the data (the summit of the composed
 * heights, the skyline) so they are the same in every run.
 */
SceneDef Benchmark::MakeScene(const std::string& name)
{
  SceneDef s;
  s.Name = name;
  vtkGlobeEllipsoid* body = this->Scene.Body;
  auto fromLookAt = [&](const double camera[3], const double target[3], double angle) {
    vtkGlobeTest::LookAt(this->Scene.Renderer, body, camera, target, angle);
    vtkCamera* c = this->Scene.Renderer->GetActiveCamera();
    c->GetPosition(s.A.Eye);
    c->GetFocalPoint(s.A.Focal);
    c->GetViewUp(s.A.Up);
    s.A.ViewAngle = angle;
  };
  auto along = [&](const double eye[3], const double view[3], const double up[3], double angle) {
    for (int i = 0; i < 3; ++i)
    {
      s.A.Eye[i] = eye[i];
      s.A.Focal[i] = eye[i] + 1000.0 * view[i];
    }
    double right[3], trueUp[3];
    vtkMath::Cross(view, up, right);
    vtkMath::Cross(right, view, trueUp);
    vtkMath::Normalize(trueUp);
    std::copy(trueUp, trueUp + 3, s.A.Up);
    s.A.ViewAngle = angle;
  };
  if (name == "earth")
  {
    s.Description = "the whole Earth from 22,000 km";
    const double camera[3] = { -40.0, 25.0, 2.2e7 }, target[3] = { -40.0, 25.0, 0.0 };
    fromLookAt(camera, target, 30.0);
  }
  else if (name == "rainier")
  {
    s.Description = "Mount Rainier from 16 km up, 20 km from the summit";
    const double camera[3] = { -121.86, 46.75, 16000.0 },
                 target[3] = { -121.7603, 46.8523, 4392.0 };
    fromLookAt(camera, target, 40.0);
  }
  else if (name == "everest")
  {
    // The summit of the composed data (bilinear 90 m posts), as TestGlobeEverestSummit finds it.
    double lon = 86.925, lat = 27.9881, ground = -1e300;
    for (double step : { 1e-3, 1e-4, 1e-5 })
    {
      const double lon0 = lon, lat0 = lat;
      for (int i = -10; i <= 10; ++i)
      {
        for (int j = -10; j <= 10; ++j)
        {
          const double g =
            vtkGlobeTest::ComposedHeight(this->Layers, lon0 + i * step, lat0 + j * step);
          if (g > ground)
          {
            ground = g;
            lon = lon0 + i * step;
            lat = lat0 + j * step;
          }
        }
      }
    }
    char text[160];
    std::snprintf(text, sizeof(text),
      "1.5 m above the data's summit (%.1f m at %.4f E, %.4f N), looking ESE 4 deg down to the "
      "horizon",
      ground, lon, lat);
    s.Description = text;
    double eye[3], east[3], north[3], up[3], view[3];
    body->GeodeticToCartesian(lon, lat, ground + 1.5, eye);
    body->ComputeEastNorthUp(lon, lat, east, north, up);
    const double az = vtkMath::RadiansFromDegrees(110.0), tilt = vtkMath::RadiansFromDegrees(-4.0);
    for (int i = 0; i < 3; ++i)
    {
      view[i] = std::cos(tilt) * (std::sin(az) * east[i] + std::cos(az) * north[i]) +
        std::sin(tilt) * up[i];
    }
    along(eye, view, up, 40.0);
  }
  else if (name == "satellite")
  {
    // TestGlobeDepthModes' scene: 2 m over the ground looking east at Rainier; the satellite on
    // the view's vertical plane 1 degree above the skyline, where that ray is 400 km up.
    const double lon = -121.95, lat = 46.85;
    const double ground = vtkGlobeTest::ComposedHeight(this->Layers, lon, lat);
    double eye[3], east[3], north[3], up[3];
    body->GeodeticToCartesian(lon, lat, ground + 2.0, eye);
    body->ComputeEastNorthUp(lon, lat, east, north, up);
    along(eye, east, up, 50.0);
    auto elevated = [&](double degrees, double ray[3]) {
      const double a = vtkMath::RadiansFromDegrees(degrees);
      for (int i = 0; i < 3; ++i)
      {
        ray[i] = std::cos(a) * east[i] + std::sin(a) * s.A.Up[i];
      }
    };
    double skyline = 10.0, ray[3];
    for (; skyline > -20.0; skyline -= 0.1)
    {
      elevated(skyline, ray);
      const double t = ExactTerrainHit(body, this->Layers, eye, ray, this->MaximumHeight);
      if (t > 0 && t < 3.0e5)
      {
        break;
      }
    }
    elevated(skyline + 1.0, ray);
    double lo = 1e4, hi = 1e7;
    for (int i = 0; i < 80; ++i)
    {
      const double mid = 0.5 * (lo + hi);
      const double p[3] = { eye[0] + mid * ray[0], eye[1] + mid * ray[1], eye[2] + mid * ray[2] };
      double llh[3];
      body->CartesianToGeodeticQuiet(p, llh);
      (llh[2] < 4.0e5 ? lo : hi) = mid;
    }
    s.Satellite = true;
    s.SatelliteRadius = 1.0e5;
    for (int i = 0; i < 3; ++i)
    {
      s.SatelliteCentre[i] = eye[i] + lo * ray[i];
    }
    char text[200];
    std::snprintf(text, sizeof(text),
      "2 m above the ground west of Rainier looking east; a satellite (sphere mesh, 100 km "
      "radius) 400 km up, %.0f km away, 1 deg above the skyline",
      lo / 1000.0);
    s.Description = text;
  }
  s.B = Turned(s.A, this->Opt.Window.Y, 0.25);
  const int w = this->Opt.Window.X, h = this->Opt.Window.Y;
  s.Stride = std::max(1, static_cast<int>(std::lround(std::sqrt(double(w) * h / this->Opt.Samples))));
  return s;
}

/// The exact answers at the sample pixels for the current height composition (cached).
Reference& Benchmark::GetReference(SceneDef& scene)
{
  const std::string key = this->HeightSignature();
  auto found = scene.References.find(key);
  if (found != scene.References.end())
  {
    return found->second;
  }
  const Clock::time_point start = Clock::now();
  Reference& ref = scene.References[key];
  const int w = this->Opt.Window.X, h = this->Opt.Window.Y;
  this->Scene.Window->SetSize(w, h);
  for (int pass = 0; pass < 2; ++pass)
  {
    const Pose& pose = pass ? scene.B : scene.A;
    this->SetPose(pose, true);
    std::vector<Sample>& samples = pass ? ref.B : ref.A;
    for (int y = scene.Stride / 2; y < h; y += scene.Stride)
    {
      for (int x = scene.Stride / 2; x < w; x += scene.Stride)
      {
        Sample s;
        s.X = x + 0.5;
        s.Y = y + 0.5;
        vtkGlobeTest::PixelRay(this->Scene.Renderer, s.X, s.Y, s.Ray);
        s.Terrain =
          ExactTerrainHit(this->Scene.Body, this->Layers, pose.Eye, s.Ray, this->MaximumHeight);
        if (scene.Satellite)
        {
          s.Object = vtkGlobeTest::RaySphereHit(scene.SatelliteCentre, scene.SatelliteRadius, pose.Eye, s.Ray);
        }
        if (s.Terrain > 0)
        {
          for (int i = 0; i < 3; ++i)
          {
            s.Hit[i] = pose.Eye[i] + s.Terrain * s.Ray[i];
          }
        }
        samples.push_back(s);
      }
    }
  }
  ref.Seconds = SecondsSince(start);
  scene.ReferenceSeconds += ref.Seconds;
  std::fprintf(stderr, "  [%6.0f s] %s: exact reference (%zu samples x 2 views, feather %s) in %.1f s\n",
    SecondsSince(this->Start), scene.Name.c_str(), ref.A.size(), key.c_str(), ref.Seconds);
  return ref;
}

/**
 * Which surface each pixel of the satellite must show (pose A), once per scene: pixels whose
 * exact ray meets the satellite and whose 3x3 neighbours do too; terrain crossing the ray
 * before it (the composed data marched at 0.2 % of the distance) within 1 m + 2 % of the
 * distance is too close to call (the margin TestGlobeDepthModes uses).
 */
void Benchmark::ClassifySatellite(SceneDef& scene)
{
  const int w = this->Opt.Window.X, h = this->Opt.Window.Y;
  this->SetPose(scene.A, true);
  std::vector<double> distance(static_cast<size_t>(w) * h, -1.0);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double ray[3];
      vtkGlobeTest::PixelRay(this->Scene.Renderer, x + 0.5, y + 0.5, ray);
      distance[static_cast<size_t>(y) * w + x] =
        vtkGlobeTest::RaySphereHit(scene.SatelliteCentre, scene.SatelliteRadius, scene.A.Eye, ray);
    }
  }
  scene.Expect.assign(distance.size(), -1);
  for (int y = 1; y + 1 < h; ++y)
  {
    for (int x = 1; x + 1 < w; ++x)
    {
      const size_t at = static_cast<size_t>(y) * w + x;
      bool inside = distance[at] > 0;
      for (int j = -1; j <= 1 && inside; ++j)
      {
        for (int i = -1; i <= 1 && inside; ++i)
        {
          inside = distance[at + j * w + i] > 0;
        }
      }
      if (!inside)
      {
        continue;
      }
      double ray[3];
      vtkGlobeTest::PixelRay(this->Scene.Renderer, x + 0.5, y + 0.5, ray);
      const double t = distance[at];
      double lowest = 1e300;
      for (double s = 1.0;; s = std::min(t, s + std::max(1.0, 0.002 * s)))
      {
        const double over =
          vtkGlobeTest::RayHeightOverTerrain(this->Scene.Body, this->Layers, scene.A.Eye, ray, s);
        lowest = std::min(lowest, over / (1.0 + 0.02 * s));
        if (s >= t || lowest < -1.0)
        {
          break;
        }
      }
      if (std::abs(lowest) < 1.0)
      {
        ++scene.Grazing;
        continue;
      }
      scene.Expect[at] = lowest > 0 ? 1 : 0;
    }
  }
}

/**
 * Times one configuration at the view A (clipping set there) alternating with B: warm-up
 * frames (shader builds, uploads, the reduction settling), then timed frames, each Render() +
 * glFinish(). Capped: a configuration slower than SecondsPerConfiguration gets 2 warm-up frames
 * and as many timed ones as fit, at least MinimumFrames.
 */
Timing Benchmark::Time(
  const std::string& label, const Pose& a, const Pose& b, vtkGlobeMapper* globe, bool capped)
{
  Timing result;
  vtkRenderWindow* renWin = this->Scene.Window;
  this->SetPose(a, this->Policy);
  vtkCamera* camera = this->Scene.Renderer->GetActiveCamera();
  int frame = 0;
  auto renderFrame = [&]() {
    const Pose& p = frame % 2 && !this->Opt.Still ? b : a;
    camera->SetPosition(p.Eye);
    camera->SetFocalPoint(p.Focal);
    camera->SetViewUp(p.Up);
    ++frame;
    const Clock::time_point start = Clock::now();
    renWin->Render();
    glFinish();
    return SecondsSince(start);
  };
  int warmup = this->Opt.Warmup, frames = this->Opt.Frames;
  for (int i = 0; i < warmup; ++i)
  {
    const double seconds = renderFrame();
    // The first frame pays for uploads and shader builds; the second is a fair estimate.
    if (i == 1 && capped && seconds * (warmup - 2 + frames) > this->Opt.SecondsPerConfiguration)
    {
      warmup = 2;
      frames = std::max(this->Opt.MinimumFrames,
        std::min(frames, static_cast<int>(this->Opt.SecondsPerConfiguration / seconds)));
      result.Reduced = frames < this->Opt.Frames;
    }
  }
  result.Warmup = warmup;
  std::vector<double> times, stages[NumberOfStages];
  for (int i = 0; i < frames; ++i)
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
  result.Time = Summarize(times);
  for (int k = 0; k < NumberOfStages; ++k)
  {
    result.Stages[k] = stages[k].empty() ? NaN : Summarize(stages[k]).Median;
  }
  std::fprintf(stderr, "  [%6.0f s] %-44s %3d frames: median %8.2f ms\n", SecondsSince(this->Start),
    label.c_str(), result.Time.Count, result.Time.Median);
  return result;
}

/**
 * The accuracy of what the renderer draws now at the scene's view: terrain and jitter from
 * depth (read in the depth pass's mode), wrong-surface pixels, and (when asked) registration.
 */
Accuracy Benchmark::Measure(SceneDef& scene, bool registration)
{
  Accuracy result;
  result.Measured = true;
  const Reference& ref = this->GetReference(scene);
  vtkRenderer* renderer = this->Scene.Renderer;
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkGlobeEllipsoid* body = this->Scene.Body;
  const int w = this->Opt.Window.X;

  // The rendered point at each sample of a view (NaN: nothing drawn).
  auto rendered = [&](const Pose& pose, const std::vector<Sample>& samples) {
    this->RenderAt(pose);
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(this->Scene.Window);
    std::vector<std::array<double, 3>> points(samples.size(), { NaN, NaN, NaN });
    for (size_t i = 0; i < samples.size(); ++i)
    {
      const Sample& s = samples[i];
      const float d = depth[static_cast<size_t>(s.Y) * w + static_cast<size_t>(s.X)];
      if (d < 1.0f)
      {
        vtkGlobeTest::UnprojectPixel(
          renderer, s.X, s.Y, this->DepthPass->GetPerspectiveDepth(d, camera), points[i].data());
      }
    }
    return points;
  };

  this->SetPose(scene.A, this->Policy);
  const std::vector<std::array<double, 3>> pa = rendered(scene.A, ref.A);
  if (scene.Satellite)
  {
    const std::vector<unsigned char> rgb = vtkGlobeTest::ReadPixels(this->Scene.Window);
    result.SurfaceMeasured = true;
    result.Grazing = scene.Grazing;
    for (size_t at = 0; at < scene.Expect.size(); ++at)
    {
      if (scene.Expect[at] < 0)
      {
        continue;
      }
      const unsigned char* c = &rgb[3 * at];
      const bool drawn = c[0] > 200 && c[1] < 60 && c[2] < 60;
      const bool inFront = scene.Expect[at] == 1;
      ++result.Checked;
      result.Hidden += inFront ? 0 : 1;
      result.Wrong += inFront != drawn ? 1 : 0;
    }
  }
  // At each sample terrain is exactly first on: the on-screen error vector (where the data's
  // surface point under the rendered point projects, minus the pixel) and the signed error
  // along the ray (rendered minus exact distance). NaN where not measurable.
  struct Local
  {
    double Screen[2] = { NaN, NaN };
    double Along = NaN;
  };
  auto local = [&](const Pose& pose, const Sample& s, const std::array<double, 3>& p, double llh[3]) {
    Local l;
    const double data = vtkGlobeTest::ComposedHeight(this->Layers, llh[0], llh[1]);
    double q[3], qd[2];
    body->GeodeticToCartesian(llh[0], llh[1], data, q);
    this->Project(q, qd);
    l.Screen[0] = qd[0] - s.X;
    l.Screen[1] = qd[1] - s.Y;
    l.Along = std::sqrt(vtkMath::Distance2BetweenPoints(p.data(), pose.Eye)) - s.Terrain;
    return l;
  };
  std::vector<Local> la(ref.A.size());
  std::vector<double> errorM, errorPx, heightM, all;
  for (size_t i = 0; i < ref.A.size(); ++i)
  {
    const Sample& s = ref.A[i];
    const bool drawn = std::isfinite(pa[i][0]);
    if (!s.TerrainFirst())
    {
      if (s.Object < 0 && drawn)
      {
        ++result.Extra; // terrain (or anything) drawn where the ray meets nothing
        all.push_back(std::numeric_limits<double>::infinity());
      }
      continue;
    }
    ++result.Samples;
    double llh[3];
    if (!drawn || !body->CartesianToGeodeticQuiet(pa[i].data(), llh))
    {
      ++result.Missing;
      all.push_back(std::numeric_limits<double>::infinity());
      continue;
    }
    la[i] = local(scene.A, s, pa[i], llh);
    const double px = std::hypot(la[i].Screen[0], la[i].Screen[1]);
    errorM.push_back(std::abs(la[i].Along));
    errorPx.push_back(px);
    heightM.push_back(std::abs(llh[2] - vtkGlobeTest::ComposedHeight(this->Layers, llh[0], llh[1])));
    all.push_back(px);
  }
  result.ErrorM = Summarize(errorM);
  result.ErrorPx = Summarize(errorPx);
  result.HeightM = Summarize(heightM);
  std::sort(all.begin(), all.end());
  const double bad = static_cast<double>(result.Missing + result.Extra);
  result.P95AllPx = all.empty() || bad > 0.05 * all.size() ? NaN : Quantile(all, 0.95);

  // Jitter: the view turned by a quarter pixel. A static error field moves with the surface
  // and leaves these unchanged (up to its variation over a quarter pixel); a grid that swims
  // with the camera changes them.
  const std::vector<std::array<double, 3>> pb = rendered(scene.B, ref.B);
  std::vector<double> jitter, jitterM;
  for (size_t i = 0; i < ref.A.size() && i < ref.B.size(); ++i)
  {
    const Sample& sb = ref.B[i];
    double llh[3];
    if (!std::isfinite(la[i].Along) || !sb.TerrainFirst() || !std::isfinite(pb[i][0]) ||
      !body->CartesianToGeodeticQuiet(pb[i].data(), llh))
    {
      continue;
    }
    const Local lb = local(scene.B, sb, pb[i], llh);
    jitter.push_back(std::hypot(lb.Screen[0] - la[i].Screen[0], lb.Screen[1] - la[i].Screen[1]));
    jitterM.push_back(std::abs(lb.Along - la[i].Along));
  }
  result.JitterPx = Summarize(jitter);
  result.JitterM = Summarize(jitterM);

  if (registration)
  {
    this->MeasureRegistration(scene, ref, result);
  }
  else
  {
    result.RegistrationNote = "not measured: the setting changes neither geometry nor texture coordinates";
  }
  return result;
}

/**
 * Registration: the marker layer on top, unlit, effects off, at view A. Its texel column and
 * row come back as red and green; the (lon, lat) they decode, at the data's height, is
 * projected against the pixel of the exact hit.
 */
void Benchmark::MeasureRegistration(SceneDef& scene, const Reference& ref, Accuracy& result)
{
  vtkGlobeMapper* m = this->Scene.Mapper;
  const bool effects[6] = { m->GetLighting(), m->GetNightLights(), m->GetSpecularWater(),
    m->GetAtmosphere(), m->GetGraticule(), m->GetContours() };
  m->SetLighting(false);
  m->SetNightLights(false);
  m->SetSpecularWater(false);
  m->SetAtmosphere(false);
  m->SetGraticule(false);
  m->SetContours(false);
  vtkSmartPointer<vtkScalarsToColors> tint = m->GetCompositePass()->GetHeightColors();
  m->GetCompositePass()->SetHeightColors(nullptr);
  m->AddLayer(this->MarkerLayer);
  this->SetPose(scene.A, this->Policy);
  this->RenderAt(scene.A);
  const std::vector<unsigned char> rgb = vtkGlobeTest::ReadPixels(this->Scene.Window);
  m->RemoveLayer(this->MarkerLayer);
  m->GetCompositePass()->SetHeightColors(tint);
  m->SetLighting(effects[0]);
  m->SetNightLights(effects[1]);
  m->SetSpecularWater(effects[2]);
  m->SetAtmosphere(effects[3]);
  m->SetGraticule(effects[4]);
  m->SetContours(effects[5]);

  const double* e = scene.Marker;
  const double texLon = (e[1] - e[0]) / 256.0, texLat = (e[3] - e[2]) / 256.0;
  const int w = this->Opt.Window.X;
  std::vector<double> px;
  for (const Sample& s : ref.A)
  {
    if (!s.TerrainFirst())
    {
      continue;
    }
    double llh[3];
    this->Scene.Body->CartesianToGeodeticQuiet(s.Hit, llh);
    // Inside the patch, 3 texels clear of its border.
    if (llh[0] < e[0] + 3 * texLon || llh[0] > e[1] - 3 * texLon || llh[1] < e[2] + 3 * texLat ||
      llh[1] > e[3] - 3 * texLat)
    {
      continue;
    }
    const unsigned char* c = &rgb[3 * (static_cast<size_t>(s.Y) * w + static_cast<size_t>(s.X))];
    const double lon = e[0] + (c[0] + 0.5) * texLon, lat = e[3] - (c[1] + 0.5) * texLat;
    double p[3], d[2], exact[2];
    this->Scene.Body->GeodeticToCartesian(
      lon, lat, vtkGlobeTest::ComposedHeight(this->Layers, lon, lat), p);
    this->Project(p, d);
    this->Project(s.Hit, exact);
    px.push_back(std::hypot(d[0] - exact[0], d[1] - exact[1]));
  }
  result.RegistrationMeasured = !px.empty();
  result.RegistrationPx = Summarize(px);
  if (px.empty())
  {
    result.RegistrationNote = "no sample inside the marker patch";
  }
}

void Benchmark::MeasureMemory(Row& row, bool globe)
{
  vtkGlobeMapper* m = this->Scene.Mapper;
  if (globe)
  {
    row.Mem.GpuLayers = static_cast<double>(m->GetLayerSet()->GetTextureMemory());
    row.Mem.GpuGBuffer = TextureBytes(vtkGlobeMapperTesting::GetGBufferTexture(m)) + TextureBytes(vtkGlobeMapperTesting::GetGBufferDepthTexture(m));
    vtkGlobeGridPass* g = m->GetGridPass();
    row.Mem.GpuGrid = TextureBytes(g->GetDirectionTexture()) + TextureBytes(g->GetPositionTexture()) +
      TextureBytes(g->GetHeightTexture());
  }
  ProcessMemory(row.Mem.CpuRss, row.Mem.CpuHwm);
}

/// The marker layer for a scene: a 256^2 patch around the exact hit nearest the view centre,
/// texels a third of a pixel there.
void MakeMarker(SceneDef& scene, const Reference& ref, vtkGlobeEllipsoid* body, int w, int h,
  vtkGlobeLayer* marker)
{
  const Sample* centre = nullptr;
  double best = 1e300;
  for (const Sample& s : ref.A)
  {
    const double d = std::hypot(s.X - 0.5 * w, s.Y - 0.5 * h);
    if (s.TerrainFirst() && d < best)
    {
      best = d;
      centre = &s;
    }
  }
  if (!centre)
  {
    return;
  }
  double llh[3];
  body->CartesianToGeodeticQuiet(centre->Hit, llh);
  const double pixel = centre->Terrain * vtkMath::RadiansFromDegrees(scene.A.ViewAngle) / h;
  const double texel = pixel / 3.0;
  const double dLat = vtkMath::DegreesFromRadians(texel / body->GetMinimumRadius());
  const double dLon = dLat / std::max(std::cos(vtkMath::RadiansFromDegrees(llh[1])), 0.05);
  scene.Marker[0] = llh[0] - 128 * dLon;
  scene.Marker[1] = llh[0] + 128 * dLon;
  scene.Marker[2] = std::max(-89.9, llh[1] - 128 * dLat);
  scene.Marker[3] = std::min(89.9, llh[1] + 128 * dLat);
  scene.MarkerTexelPx = 1.0 / 3.0;
  std::vector<unsigned char> rgba(256 * 256 * 4);
  for (int j = 0; j < 256; ++j)
  {
    for (int i = 0; i < 256; ++i)
    {
      unsigned char* p = &rgba[4 * (j * 256 + i)];
      p[0] = static_cast<unsigned char>(i);
      p[1] = static_cast<unsigned char>(j);
      p[2] = 0;
      p[3] = 255;
    }
  }
  marker->SetColorData(256, 256, 4, rgba.data(), scene.Marker[0], scene.Marker[1],
    scene.Marker[2], scene.Marker[3]);
  marker->SetFeatherWidth(0.0);
  // Its colours are codes, read at level 0: filtered to a grazing footprint (the default for
  // linear layers since 2026-11) they would average texels along the footprint's long axis
  // (Everest: 3.7 px p95) and measure the filter instead of where the composition samples.
  marker->SetInterpolationToNearest();
  marker->SetDrawOrder(1000);
  marker->SetName("registration marker");
}

/// Every setting of every family on one scene, then the naive globes.
void Benchmark::RunScene(SceneDef& scene)
{
  std::fprintf(stderr, "scene %s: %s\n", scene.Name.c_str(), scene.Description.c_str());
  vtkRenderer* renderer = this->Scene.Renderer;
  this->Scene.Window->SetSize(this->Opt.Window.X, this->Opt.Window.Y);
  renderer->AddActor(this->Scene.Actor);
  if (scene.Satellite)
  {
    vtkNew<vtkSphereSource> source;
    source->SetRadius(scene.SatelliteRadius);
    source->SetThetaResolution(64);
    source->SetPhiResolution(64);
    this->SatelliteActor = vtkGlobeTest::FlatActor(source, 1, 0, 0);
    this->SatelliteActor->SetPosition(scene.SatelliteCentre);
    renderer->AddActor(this->SatelliteActor);
    this->ClassifySatellite(scene);
  }
  this->ResetDefaults();
  this->Scene.Window->Render();
  const Reference& base = this->GetReference(scene);
  MakeMarker(scene, base, this->Scene.Body, this->Opt.Window.X, this->Opt.Window.Y, this->MarkerLayer);
  this->SetPose(scene.A, true);
  this->Scene.Renderer->GetActiveCamera()->GetClippingRange(scene.ClipPolicy);
  this->SetPose(scene.A, false);
  this->Scene.Renderer->GetActiveCamera()->GetClippingRange(scene.ClipVtk);

  const Accuracy* baseline = nullptr;
  size_t baselineRow = 0;
  for (const Setting& setting : this->Settings())
  {
    this->ResetDefaults();
    setting.Apply();
    Row row;
    row.Scene = scene.Name;
    row.Family = setting.Family;
    row.Setting = setting.Name;
    row.Method = "pgm";
    row.Time = this->Time(scene.Name + " " + setting.Family + " " + setting.Name, scene.A, scene.B,
      this->Scene.Mapper, true);
    // After the frames: an automatic grid's size is the last frame's.
    row.Grid = this->Scene.Mapper->GetGridResolution();
    row.Triangles = 2.0 * (row.Grid - 1) * (row.Grid - 1);
    this->MeasureMemory(row, true);
    row.Error = this->Measure(scene, setting.Registration);
    if (!setting.Registration && baseline)
    {
      row.Error.RegistrationMeasured = baseline->RegistrationMeasured;
      row.Error.RegistrationPx = baseline->RegistrationPx;
      row.Error.RegistrationNote = "the baseline's: effects change neither geometry nor texture coordinates";
    }
    if (row.Time.Reduced)
    {
      this->Note(scene.Name + " " + setting.Name + ": " + std::to_string(row.Time.Warmup) +
        " warm-up + " + std::to_string(row.Time.Time.Count) + " timed frames (" +
        Format(row.Time.Time.Median, "%.0f") + " ms per frame)");
    }
    this->Rows.push_back(row);
    if (setting.Family == "baseline" && baseline == nullptr)
    {
      baselineRow = this->Rows.size() - 1;
    }
    baseline = &this->Rows[baselineRow].Error;
    std::fprintf(stderr,
      "             terrain p95 %s px / %s m (missing %d, extra %d), registration p95 %s px, "
      "jitter p95 %s px%s\n",
      Format(row.Error.ErrorPx.P95).c_str(), Format(row.Error.ErrorM.P95, "%.1f").c_str(),
      row.Error.Missing, row.Error.Extra, Format(row.Error.RegistrationPx.P95).c_str(),
      Format(row.Error.JitterPx.P95).c_str(),
      scene.Satellite ? (", wrong surface " + std::to_string(row.Error.Wrong) + "/" +
                          std::to_string(row.Error.Checked))
                          .c_str()
                      : "");
  }
  this->ResetDefaults();
  renderer->RemoveViewProp(this->Scene.Actor);
  if (!this->Opt.EffectsOnly)
  {
    this->RunNaive(scene);
  }
  if (this->SatelliteActor)
  {
    renderer->RemoveViewProp(this->SatelliteActor);
    this->SatelliteActor->ReleaseGraphicsResources(this->Scene.Window);
    this->SatelliteActor = nullptr;
  }
}

/// VTK's naive globes on the scene: plain VTK clipping and depth, the same measurements except
/// registration (their texture follows their own vertices).
void Benchmark::RunNaive(SceneDef& scene)
{
  vtkRenderer* renderer = this->Scene.Renderer;
  this->DepthPass->SetModeToDefault();
  // VTK's own range fits the whole body: from 20 km or 2 m its near plane (~1/1000 of the
  // far) clips the terrain in view and the far side shows. The naive globes get the range
  // the policy computes for the globe here, so they are judged on their geometry.
  this->FixedRange[0] = scene.ClipPolicy[0];
  this->FixedRange[1] = scene.ClipPolicy[1];
  for (Naive& n : this->NaiveGlobes)
  {
    renderer->AddViewProp(n.Actor);
    Row row;
    row.Scene = scene.Name;
    row.Family = "naive";
    row.Method = n.Method;
    row.Setting = n.Method + " " + n.Resolution.ToString();
    row.Resolution = n.Resolution;
    row.Triangles = n.Triangles;
    row.Time = this->Time(scene.Name + " " + row.Setting, scene.A, scene.B, nullptr, true);
    this->MeasureMemory(row, false);
    row.Mem.GpuMesh = n.GpuBytes;
    row.Error = this->Measure(scene, false);
    row.Error.RegistrationNote = "not measured: a naive globe's texture follows its own vertices";
    if (row.Time.Reduced)
    {
      this->Note(scene.Name + " " + row.Setting + ": " + std::to_string(row.Time.Warmup) +
        " warm-up + " + std::to_string(row.Time.Time.Count) + " timed frames (" +
        Format(row.Time.Time.Median, "%.0f") + " ms per frame)");
    }
    std::fprintf(stderr, "             terrain p95 %s px / %s m (missing %d, extra %d)\n",
      Format(row.Error.ErrorPx.P95).c_str(), Format(row.Error.ErrorM.P95, "%.1f").c_str(),
      row.Error.Missing, row.Error.Extra);
    this->Rows.push_back(row);
    renderer->RemoveViewProp(n.Actor);
  }
  this->FixedRange[0] = this->FixedRange[1] = 0;
}

/// Grid x window at the whole Earth (Mahsman's Tables 6.2-6.4 layout), time only.
void Benchmark::RunMatrix()
{
  SceneDef earth = this->MakeScene("earth");
  this->ResetDefaults();
  this->Scene.Mapper->SetTerrainRefinement(0); // Mahsman's tables are of the grid alone
  this->Scene.Renderer->AddActor(this->Scene.Actor);
  for (int grid : this->Opt.MatrixGrids)
  {
    this->Scene.Mapper->SetGridResolution(grid);
    for (const Size& window : this->Opt.MatrixWindows)
    {
      this->Scene.Window->SetSize(window.X, window.Y);
      const Pose b = Turned(earth.A, window.Y, 0.25);
      MatrixRow row{ grid, window, {} };
      row.Time = this->Time("matrix grid " + std::to_string(grid) + "^2 window " + window.ToString(),
        earth.A, b, this->Scene.Mapper, true);
      this->MatrixRows.push_back(row);
    }
  }
  this->ResetDefaults();
  this->Scene.Renderer->RemoveViewProp(this->Scene.Actor);
  this->Scene.Window->SetSize(this->Opt.Window.X, this->Opt.Window.Y);
}

void Benchmark::PrintTables()
{
  std::printf("\nGlobeBenchmark: %s (%s), depth buffer %s, %s, %u CPU threads\n",
    this->Renderer.c_str(), this->Version.c_str(), this->DepthBuffer.c_str(), CpuModel().c_str(),
    std::thread::hardware_concurrency());
  std::printf("Frame: median wall ms (Render + glFinish), IQR; stages: median GPU ms. Terrain: "
              "p95 over the samples (px on screen, m along the ray); reg/jit: p95 px.\n");
  const char* header =
    "%-12s %-30s %5s %8s %6s | %6s %6s %6s %6s | %7s %9s %7s %5s | %6s %6s %9s %7s\n";
  for (const SceneDef& scene : this->Scenes)
  {
    std::printf("\n== %s: %s (%s, %zu samples)\n", scene.Name.c_str(), scene.Description.c_str(),
      this->Opt.Window.ToString().c_str(), scene.References.empty() ? size_t(0) : scene.References.begin()->second.A.size());
    std::printf(header, "family", "setting", "frms", "median", "IQR", "pgm", "raster", "compos",
      "reduce", "err px", "err m", "p95all", "miss", "reg px", "jit px", "wrong", "GPU MB");
    for (const Row& r : this->Rows)
    {
      if (r.Scene != scene.Name)
      {
        continue;
      }
      const Accuracy& e = r.Error;
      const double gpu = (std::isfinite(r.Mem.GpuLayers) ? r.Mem.GpuLayers : 0) +
        (std::isfinite(r.Mem.GpuGBuffer) ? r.Mem.GpuGBuffer : 0) +
        (std::isfinite(r.Mem.GpuGrid) ? r.Mem.GpuGrid : 0) +
        (std::isfinite(r.Mem.GpuMesh) ? r.Mem.GpuMesh : 0);
      std::printf(header, r.Family.c_str(), r.Setting.c_str(), std::to_string(r.Time.Time.Count).c_str(),
        Format(r.Time.Time.Median).c_str(), Format(r.Time.Time.Q3 - r.Time.Time.Q1).c_str(),
        Format(r.Time.Stages[PGMStage]).c_str(), Format(r.Time.Stages[RasterStage]).c_str(),
        Format(r.Time.Stages[CompositeStage]).c_str(), Format(r.Time.Stages[ReductionStage]).c_str(),
        Format(e.ErrorPx.P95, "%.3f").c_str(), Format(e.ErrorM.P95, "%.1f").c_str(),
        Format(e.P95AllPx, "%.3f").c_str(), std::to_string(e.Missing + e.Extra).c_str(),
        Format(e.RegistrationPx.P95).c_str(), Format(e.JitterPx.P95, "%.3f").c_str(),
        e.SurfaceMeasured ? (std::to_string(e.Wrong) + "/" + std::to_string(e.Checked)).c_str() : "-",
        Format(gpu / 1048576.0, "%.1f").c_str());
    }
  }
  if (!this->MatrixRows.empty())
  {
    std::printf("\n== matrix: whole Earth, PGM, grid x window (median frame ms; stages pgm / "
                "reduction GPU ms)\n");
    for (const MatrixRow& r : this->MatrixRows)
    {
      std::printf("  grid %4d^2 window %-9s %8s ms  (pgm %s, raster %s, composite %s, reduction %s)\n",
        r.Grid, r.Window.ToString().c_str(), Format(r.Time.Time.Median).c_str(),
        Format(r.Time.Stages[PGMStage]).c_str(), Format(r.Time.Stages[RasterStage]).c_str(),
        Format(r.Time.Stages[CompositeStage]).c_str(), Format(r.Time.Stages[ReductionStage]).c_str());
    }
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

/// The two targets of the mapper issue, as statements (a benchmark asserts nothing).
void Benchmark::Compare()
{
  auto find = [this](const std::string& scene, const std::string& family, const std::string& method,
                Size size) -> const Row* {
    for (const Row& r : this->Rows)
    {
      if (r.Scene == scene && r.Family == family && r.Method == method &&
        (method == "pgm" || r.Resolution == size))
      {
        return &r;
      }
    }
    return nullptr;
  };
  char text[512];
  {
    const Row* pgm = find("earth", "baseline", "pgm", { 0, 0 });
    const Row* sphere = find("earth", "naive", "sphere", this->Opt.Sphere);
    Comparison c{ "pgm_defaults_vs_sphere", "NOT MEASURED", "" };
    std::snprintf(text, sizeof(text), "(i) PGM at the defaults vs the textured sphere: not measured in this run");
    if (pgm && sphere)
    {
      const double ratio = pgm->Time.Time.Median / sphere->Time.Time.Median;
      c.Result = ratio <= 3.0 ? "PASS" : "MISS";
      std::snprintf(text, sizeof(text),
        "(i) whole Earth at %s: PGM at the defaults %.2f ms = %.2fx the textured sphere's %.2f ms (target "
        "<= 3x): %s",
        this->Opt.Window.ToString().c_str(), pgm->Time.Time.Median, ratio, sphere->Time.Time.Median,
        c.Result.c_str());
    }
    c.Statement = text;
    this->Comparisons.push_back(c);
  }
  {
    const Row* pgm = find("rainier", "baseline", "pgm", { 0, 0 });
    Comparison c{ "pgm_defaults_vs_equally_accurate_mesh", "NOT MEASURED", "" };
    std::snprintf(text, sizeof(text), "(ii) PGM at the defaults vs meshes at Rainier: not measured in this run");
    if (pgm && pgm->Error.ErrorM.Count > 0)
    {
      const Row *match = nullptr, *best = nullptr;
      for (const Row& r : this->Rows)
      {
        if (r.Scene != "rainier" || r.Method != "mesh" || r.Error.ErrorM.Count == 0)
        {
          continue;
        }
        if (!best || r.Error.HeightM.P95 < best->Error.HeightM.P95)
        {
          best = &r;
        }
        if (r.Error.HeightM.P95 <= pgm->Error.HeightM.P95 && (!match || r.Triangles < match->Triangles))
        {
          match = &r;
        }
      }
      if (match)
      {
        c.Result = pgm->Time.Time.Median < match->Time.Time.Median ? "PASS" : "MISS";
        std::snprintf(text, sizeof(text),
          "(ii) Rainier: PGM at the defaults (height p95 %.1f m) %.2f ms; the smallest mesh as accurate, %s "
          "(p95 %.1f m), %.2f ms: %s",
          pgm->Error.HeightM.P95, pgm->Time.Time.Median, match->Resolution.ToString().c_str(),
          match->Error.HeightM.P95, match->Time.Time.Median, c.Result.c_str());
      }
      else
      {
        c.Result = "PASS";
        std::snprintf(text, sizeof(text),
          "(ii) Rainier: PGM at the defaults (height p95 %.1f m, %.2f ms); no warped mesh measured reaches "
          "that p95 (best: %s, p95 %.1f m, %.2f ms): %s",
          pgm->Error.HeightM.P95, pgm->Time.Time.Median,
          best ? best->Resolution.ToString().c_str() : "none", best ? best->Error.HeightM.P95 : NaN,
          best ? best->Time.Time.Median : NaN, c.Result.c_str());
      }
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
  j << "{\n  \"benchmark\": \"GlobeBenchmark\",\n  \"schema\": 2,\n";
  j << "  \"date\": " << JsonString(UtcNow()) << ",\n";
  j << "  \"conditions\": " << JsonString(this->Opt.Conditions) << ",\n";
  j << "  \"machine\": {\"gl_renderer\": " << JsonString(this->Renderer)
    << ", \"gl_version\": " << JsonString(this->Version)
    << ", \"gl_vendor\": " << JsonString(this->Vendor)
    << ", \"depth_buffer\": " << JsonString(this->DepthBuffer)
    << ", \"cpu\": " << JsonString(CpuModel())
    << ", \"cpu_threads\": " << std::thread::hardware_concurrency()
    << ", \"timer_queries\": " << (vtkOpenGLRenderTimer::IsSupported() ? "true" : "false")
    << ", \"loadavg_start\": " << JsonString(this->LoadStart)
    << ", \"loadavg_end\": " << JsonString(LoadAverage()) << "},\n";
  j << "  \"settings\": {\"still\": " << (this->Opt.Still ? "true" : "false")
    << ", \"quick\": " << (this->Opt.Quick ? "true" : "false")
    << ", \"frames\": " << this->Opt.Frames << ", \"warmup\": " << this->Opt.Warmup
    << ", \"window\": [" << this->Opt.Window.X << ", " << this->Opt.Window.Y << "]"
    << ", \"seconds_per_configuration\": " << JsonNumber(this->Opt.SecondsPerConfiguration)
    << ", \"minimum_frames\": " << this->Opt.MinimumFrames
    << ", \"samples_target\": " << this->Opt.Samples << "},\n";
  j << "  \"total_seconds\": " << JsonNumber(totalSeconds) << ",\n  \"notes\": [";
  for (size_t i = 0; i < this->Notes.size(); ++i)
  {
    j << (i ? ", " : "") << JsonString(this->Notes[i]);
  }
  j << "],\n  \"scenes\": [\n";
  for (size_t i = 0; i < this->Scenes.size(); ++i)
  {
    const SceneDef& s = this->Scenes[i];
    double llh[3];
    this->Scene.Body->CartesianToGeodeticQuiet(s.A.Eye, llh);
    j << "    {\"name\": " << JsonString(s.Name) << ", \"description\": " << JsonString(s.Description)
      << ", \"window\": [" << this->Opt.Window.X << ", " << this->Opt.Window.Y << "]"
      << ", \"view_angle_deg\": " << JsonNumber(s.A.ViewAngle) << ", \"eye_lon_lat_h\": ["
      << JsonNumber(llh[0]) << ", " << JsonNumber(llh[1]) << ", " << JsonNumber(llh[2]) << "]"
      << ", \"samples\": " << (s.References.empty() ? 0 : s.References.begin()->second.A.size())
      << ", \"sample_stride\": " << s.Stride
      << ", \"reference_seconds\": " << JsonNumber(s.ReferenceSeconds)
      << ", \"clipping_policy_m\": [" << JsonNumber(s.ClipPolicy[0]) << ", " << JsonNumber(s.ClipPolicy[1])
      << "], \"clipping_vtk_m\": [" << JsonNumber(s.ClipVtk[0]) << ", " << JsonNumber(s.ClipVtk[1])
      << "], \"marker\": {\"west\": " << JsonNumber(s.Marker[0]) << ", \"east\": " << JsonNumber(s.Marker[1])
      << ", \"south\": " << JsonNumber(s.Marker[2]) << ", \"north\": " << JsonNumber(s.Marker[3])
      << ", \"texel_px\": " << JsonNumber(s.MarkerTexelPx) << "}}"
      << (i + 1 < this->Scenes.size() ? ",\n" : "\n");
  }
  j << "  ],\n  \"rows\": [\n";
  for (size_t i = 0; i < this->Rows.size(); ++i)
  {
    const Row& r = this->Rows[i];
    const Accuracy& e = r.Error;
    j << "    {\"scene\": " << JsonString(r.Scene) << ", \"family\": " << JsonString(r.Family)
      << ", \"setting\": " << JsonString(r.Setting) << ", \"method\": " << JsonString(r.Method)
      << ", \"grid\": " << (r.Method == "pgm" ? std::to_string(r.Grid) : "null") << ", \"size\": "
      << (r.Method == "pgm" ? "null"
                            : "[" + std::to_string(r.Resolution.X) + ", " +
            std::to_string(r.Resolution.Y) + "]")
      << ", \"triangles\": " << JsonNumber(r.Triangles) << ", \"warmup\": " << r.Time.Warmup
      << ", \"frames\": " << r.Time.Time.Count
      << ", \"frames_reduced\": " << (r.Time.Reduced ? "true" : "false")
      << ",\n     \"frame_ms\": " << JsonTime(r.Time.Time)
      << ", \"stage_ms\": " << (r.Method == "pgm" ? JsonStages(r.Time) : "null")
      << ",\n     \"terrain\": {\"samples\": " << e.Samples << ", \"missing\": " << e.Missing
      << ", \"extra\": " << e.Extra << ", \"error_m\": " << JsonQ(e.ErrorM)
      << ", \"error_px\": " << JsonQ(e.ErrorPx) << ", \"height_error_m\": " << JsonQ(e.HeightM)
      << ", \"p95_all_px\": " << JsonNumber(e.P95AllPx) << "}"
      << ",\n     \"registration_px\": "
      << (e.RegistrationMeasured ? JsonQ(e.RegistrationPx, true) : "null")
      << ", \"registration_note\": " << JsonString(e.RegistrationNote)
      << ", \"jitter_px\": " << JsonQ(e.JitterPx, true) << ", \"jitter_m\": " << JsonQ(e.JitterM)
      << ", \"wrong_surface\": ";
    if (e.SurfaceMeasured)
    {
      j << "{\"checked\": " << e.Checked << ", \"wrong\": " << e.Wrong << ", \"hidden\": " << e.Hidden
        << ", \"grazing\": " << e.Grazing << "}";
    }
    else
    {
      j << "null";
    }
    const Memory& m = r.Mem;
    double total = 0;
    for (double v : { m.GpuLayers, m.GpuGBuffer, m.GpuGrid, m.GpuMesh })
    {
      total += std::isfinite(v) ? v : 0;
    }
    j << ",\n     \"memory\": {\"gpu_layers\": " << JsonNumber(m.GpuLayers)
      << ", \"gpu_gbuffer\": " << JsonNumber(m.GpuGBuffer) << ", \"gpu_grid\": " << JsonNumber(m.GpuGrid)
      << ", \"gpu_mesh\": " << JsonNumber(m.GpuMesh) << ", \"gpu_total\": " << JsonNumber(total)
      << ", \"cpu_rss\": " << JsonNumber(m.CpuRss) << ", \"cpu_hwm\": " << JsonNumber(m.CpuHwm)
      << "}}" << (i + 1 < this->Rows.size() ? ",\n" : "\n");
  }
  j << "  ],\n  \"matrix\": [\n";
  for (size_t i = 0; i < this->MatrixRows.size(); ++i)
  {
    const MatrixRow& r = this->MatrixRows[i];
    j << "    {\"grid\": " << r.Grid << ", \"window\": [" << r.Window.X << ", " << r.Window.Y
      << "], \"frames\": " << r.Time.Time.Count << ", \"frame_ms\": " << JsonTime(r.Time.Time)
      << ", \"stage_ms\": " << JsonStages(r.Time) << "}"
      << (i + 1 < this->MatrixRows.size() ? ",\n" : "\n");
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
  // The naive globes are built once and run on every scene.
  if (!this->Opt.EffectsOnly)
  {
    const double* radii = this->Scene.Body->GetRadii();
    const double textureBytes = 4.0 * this->Color->GetNumberOfColumns() * this->Color->GetNumberOfRows() * 4 / 3;
    {
      vtkNew<vtkTexturedSphereSource> sphere;
      sphere->SetThetaResolution(this->Opt.Sphere.X);
      sphere->SetPhiResolution(this->Opt.Sphere.Y);
      sphere->SetRadius(radii[0]);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(sphere->GetOutputPort());
      auto actor = vtkSmartPointer<vtkActor>::New();
      actor->SetMapper(mapper);
      actor->SetTexture(this->Imagery);
      // The source starts longitude at +x with u = 0; the imagery starts at -180 deg. Scaled
      // into the ellipsoid so its surface is at height 0 (its error is the terrain it lacks).
      actor->RotateZ(180.0);
      actor->SetScale(1.0, 1.0, radii[2] / radii[0]);
      const double vertices = (this->Opt.Sphere.X + 1.0) * this->Opt.Sphere.Y;
      const double triangles = 2.0 * this->Opt.Sphere.X * (this->Opt.Sphere.Y - 1);
      this->NaiveGlobes.push_back({ "sphere", this->Opt.Sphere, triangles, actor,
        vertices * 32.0 + triangles * 12.0 + textureBytes });
    }
    for (const Size& size : this->Opt.Meshes)
    {
      const Clock::time_point start = Clock::now();
      vtkSmartPointer<vtkPolyData> mesh = WarpedMesh(size.X, size.Y, this->Layers, this->Scene.Body);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(mesh);
      auto actor = vtkSmartPointer<vtkActor>::New();
      actor->SetMapper(mapper);
      actor->SetTexture(this->Imagery);
      const double triangles = 2.0 * size.X * size.Y;
      const double vertices = (size.X + 1.0) * (size.Y + 1.0);
      // Positions and normals (float) and texture coordinates per vertex; 32-bit indices.
      this->NaiveGlobes.push_back(
        { "mesh", size, triangles, actor, vertices * 32.0 + triangles * 12.0 + textureBytes });
      std::fprintf(stderr, "  [%6.0f s] built mesh %s (%.1f M triangles) in %.1f s\n",
        SecondsSince(this->Start), size.ToString().c_str(), triangles / 1e6, SecondsSince(start));
    }
  }
  for (const std::string& name : this->Opt.Scenes)
  {
    this->Scenes.push_back(this->MakeScene(name));
  }
  for (SceneDef& scene : this->Scenes)
  {
    this->RunScene(scene);
  }
  if (this->Opt.Matrix && !this->Opt.EffectsOnly)
  {
    this->RunMatrix();
  }
  const double total = SecondsSince(this->Start);
  this->PrintTables();
  this->Compare();
  std::printf("\nTotal run time: %.0f s (%.1f min)\n", total, total / 60.0);
  return this->WriteJson(total) ? 0 : 1;
}

void Usage(const char* program)
{
  std::printf(
    "usage: %s [--quick] [--frames N] [--json PATH] [--scene NAME]... [--window WxH]\n"
    "          [--effects-only] [--grid-only] [--refinement-only] [--no-matrix]\n"
    "          [--still] [--conditions TEXT] [--help]\n"
    "  Sweeps the PGM globe's settings (grid, grid relative to the window, depth mode and\n"
    "  clipping, composition, effects) on the scenes earth, rainier, everest and satellite, with\n"
    "  VTK's naive globes (a textured sphere, warped lon/lat meshes) on the same scenes; frame\n"
    "  time and its stages next to terrain, registration, jitter and wrong-surface errors and\n"
    "  memory. Then the whole-Earth grid x window matrix (Mahsman's Tables 6.2-6.4 layout).\n"
    "  --quick         fewer settings, frames and samples, a smaller window (a smoke run)\n"
    "  --effects-only  only the baseline and the effects, at the whole Earth, 1024x768\n"
    "  --grid-only     only the baseline (the automatic grid), a fixed 512^2, the composition\n"
    "                  over the whole viewport and the textured sphere, without the matrix\n"
    "                  (with --window: the automatic grid's rows)\n"
    "  --refinement-only  only the baseline and the terrain refinement rows (with coarser\n"
    "                  automatic grids, 4.8 and 6.4 px per cell), without naive globes or\n"
    "                  the matrix\n"
    "  --scene NAME    only this scene (repeatable)\n"
    "  --window WxH    the scenes' window (default 800x600)\n"
    "  --no-matrix     skip the grid x window matrix\n"
    "  --still         time every frame at the scene's view instead of alternating it with\n"
    "                  the view turned by 1/4 px: no timed frame is a new view, so none waits\n"
    "                  for its reduction (vtkGlobeMapper's first-frame-after-a-move readback)\n"
    "  --frames N      timed frames per configuration (default 30; slow ones get fewer)\n"
    "  --conditions T  free text stored in the JSON (machine load during the run)\n"
    "  --json PATH     where to write the numbers (default benchmark.json)\n",
    program);
}
} // namespace

int main(int argc, char* argv[])
{
  Options options;
  int frames = 0;
  std::vector<std::string> scenes;
  bool window = false;
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
    else if (arg == "--grid-only")
    {
      options.GridOnly = true;
    }
    else if (arg == "--refinement-only")
    {
      options.RefinementOnly = true;
      options.Matrix = false;
      options.Meshes.clear();
    }
    else if (arg == "--still")
    {
      options.Still = true;
    }
    else if (arg == "--no-matrix")
    {
      options.Matrix = false;
    }
    else if (arg == "--frames" && i + 1 < argc && std::atoi(argv[i + 1]) > 0)
    {
      frames = std::atoi(argv[++i]);
    }
    else if (arg == "--json" && i + 1 < argc)
    {
      options.Json = argv[++i];
    }
    else if (arg == "--conditions" && i + 1 < argc)
    {
      options.Conditions = argv[++i];
    }
    else if (arg == "--scene" && i + 1 < argc)
    {
      scenes.push_back(argv[++i]);
    }
    else if (arg == "--window" && i + 1 < argc &&
      std::sscanf(argv[i + 1], "%dx%d", &options.Window.X, &options.Window.Y) == 2 &&
      options.Window.X > 16 && options.Window.Y > 16)
    {
      ++i;
      window = true;
    }
    else
    {
      Usage(argv[0]);
      return arg == "--help" || arg == "-h" ? 0 : 2;
    }
  }
  if (options.Quick)
  {
    options.Frames = 8;
    options.Warmup = 2;
    if (!window)
    {
      options.Window = { 400, 300 };
    }
    options.Samples = 3000;
    options.Grids = { 256 };
    options.GridFactors = { 1.0 };
    options.Effects = { "all" };
    options.Depth = { "default, VTK clipping", "logarithmic, policy" };
    options.Compositions = { "feather 0" };
    options.Meshes = { { 256, 128 } };
    options.MatrixGrids = { 256 };
    options.MatrixWindows = { { 256, 256 } };
  }
  if (options.GridOnly)
  {
    options.Grids = { 512 }; // the fixed grid the automatic one is compared with
    options.GridFactors.clear();
    options.Effects.clear();
    options.Depth.clear();
    options.Compositions = { "whole viewport" }; // what shading only the terrain's blocks saves
    options.Meshes.clear();
    options.Matrix = false;
  }
  if (options.EffectsOnly)
  {
    options.Scenes = { "earth" };
    if (!window)
    {
      options.Window = { 1024, 768 };
    }
  }
  if (!scenes.empty())
  {
    for (const std::string& s : scenes)
    {
      if (s != "earth" && s != "rainier" && s != "everest" && s != "satellite")
      {
        std::fprintf(stderr, "unknown scene '%s' (earth, rainier, everest, satellite)\n", s.c_str());
        return 2;
      }
    }
    options.Scenes = scenes;
  }
  if (frames > 0)
  {
    options.Frames = frames;
    options.MinimumFrames = std::min(options.MinimumFrames, frames);
  }
  Benchmark benchmark(options);
  return benchmark.Run();
}
