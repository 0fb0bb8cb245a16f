// Vertical datums (issue "Geodetic correctness"): heights above the EGM96 geoid made
// ellipsoidal on the GPU, against PROJ's own transformation (EPSG:4979 -> EPSG:4326+5773 with
// Debian proj-data's egm96_15.gtx), which is independent of this project's code.
//  A. vtkGlobeGeoid::GetUndulation (double) against PROJ at the two summits and 2,000 random
//     points (poles and antimeridian included): within 1 mm.
//  B. The GPU: a flat layer 1,000 m above EGM96, seen from 300 km at six places (the poles,
//     the antimeridian, the geoid's low and high): at every grid point (the terrain's
//     vertices, where the grid pass composes the heights) the height is 1,000 m + N of PROJ at
//     that point's (lon, lat), within 1 cm.
//  C. Everest and Rainier (SRTM, orthometric) with nearest posts: at the grid points in the
//     summit post the ellipsoidal height is the post + N of PROJ within 1 cm; without a datum
//     the post itself, -N (28.8 m, 18.8 m) too high.
//  D. Bad input: a missing and a truncated geoid file are errors naming the file; a layer
//     with such a geoid is skipped once, with an error naming the geoid, and the rest of the
//     globe still draws.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeGeoid.h"
#include "vtkGlobeLayerSet.h"
#include "vtkTestErrorObserver.h"

#include <proj.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

namespace
{
vtkGlobeTest::Checklist Check;

// PROJ's geoid undulation N = h - H at (lon, lat) in degrees.
struct ProjGeoid
{
  PJ_CONTEXT* Context = proj_context_create();
  PJ* Transform = nullptr;
  ProjGeoid()
  {
    PJ* raw = proj_create_crs_to_crs(Context, "EPSG:4979", "EPSG:4326+5773", nullptr);
    Transform = raw ? proj_normalize_for_visualization(Context, raw) : nullptr;
    proj_destroy(raw);
  }
  ~ProjGeoid()
  {
    proj_destroy(Transform);
    proj_context_destroy(Context);
  }
  double Undulation(double lon, double lat)
  {
    if (!Transform)
    {
      return NAN;
    }
    PJ_COORD in = proj_coord(lon, lat, 0.0, 0.0);
    PJ_COORD out = proj_trans(Transform, PJ_FWD, in);
    return std::isfinite(out.xyz.z) && out.xyz.z != HUGE_VAL ? -out.xyz.z : NAN;
  }
};

void PartCPU(ProjGeoid& proj, vtkGlobeGeoid* geoid)
{
  std::printf("A. vtkGlobeGeoid against PROJ:\n");
  std::mt19937 random(18);
  std::uniform_real_distribution<double> lon(-180.0, 180.0), z(-1.0, 1.0);
  double worst = 0.0;
  int n = 0;
  std::vector<std::array<double, 2>> points = { { 86.925278, 27.988056 },
    { -121.760374, 46.852886 }, { 180.0, 0.0 }, { -180.0, 12.3 }, { 0.0, 90.0 }, { 33.0, -90.0 },
    { 179.99, -45.0 } };
  for (int i = 0; i < 2000; ++i)
  {
    points.push_back({ lon(random), std::asin(z(random)) * 180.0 / vtkMath::Pi() });
  }
  for (const auto& p : points)
  {
    const double a = geoid->GetUndulation(p[0], p[1]), b = proj.Undulation(p[0], p[1]);
    worst = std::max(worst, std::isfinite(a) && std::isfinite(b) ? std::abs(a - b) : 1e9);
    ++n;
  }
  char text[200];
  std::snprintf(text, sizeof(text),
    "%d points: worst |N - N(PROJ)| %.2g m; Everest N %.3f m (PROJ %.3f), Rainier N %.3f m "
    "(PROJ %.3f)",
    n, worst, geoid->GetUndulation(86.925278, 27.988056), proj.Undulation(86.925278, 27.988056),
    geoid->GetUndulation(-121.760374, 46.852886), proj.Undulation(-121.760374, 46.852886));
  Check.Expect(worst <= 1e-3 && std::abs(proj.Undulation(86.925278, 27.988056)) > 10.0, text);
}

// The grid points of the last frame (the terrain's vertices, where the grid pass composes the
// height layers): (lon, lat) of each point's direction and its composed height; NaN where the
// point's ray missed the body.
std::vector<std::array<double, 3>> ComposedHeights(vtkGlobeTest::Scene& scene)
{
  vtkGlobeGridPass* pass = scene.Mapper->GetGridPass();
  const std::vector<float> d = vtkGlobeTest::ReadTexture(pass->GetDirectionTexture());
  const std::vector<float> h = vtkGlobeTest::ReadTexture(pass->GetHeightTexture());
  const double* radii = scene.Body->GetRadii();
  const size_t n = std::min(d.size() / 4, h.size() / 4);
  std::vector<std::array<double, 3>> out(n, { NAN, NAN, NAN });
  for (size_t i = 0; i < n; ++i)
  {
    if (!(d[4 * i + 3] > 0.5f) || !std::isfinite(h[4 * i]))
    {
      continue;
    }
    const double length = std::sqrt(double(d[4 * i]) * d[4 * i] +
      double(d[4 * i + 1]) * d[4 * i + 1] + double(d[4 * i + 2]) * d[4 * i + 2]);
    double p[3], llh[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = d[4 * i + k] / length * radii[k];
    }
    scene.Body->CartesianToGeodeticQuiet(p, llh);
    out[i] = { llh[0], llh[1], h[4 * i] };
  }
  return out;
}

void PartGPU(ProjGeoid& proj)
{
  std::printf("B. A flat layer 1,000 m above EGM96 on the GPU:\n");
  vtkGlobeTest::Scene scene;
  auto flat = vtkSmartPointer<vtkGlobeLayer>::New();
  std::vector<float> posts(36 * 18, 1000.0f);
  flat->SetHeightData(36, 18, posts.data(), -180, 180, -90, 90);
  flat->SetVerticalDatumToEGM96();
  scene.Mapper->AddLayer(flat);
  // The poles, the antimeridian, the geoid's low (Indian Ocean) and high (New Guinea), Everest.
  const double places[][2] = { { 0.0, 89.9 }, { 30.0, -89.9 }, { 180.0, 10.0 }, { 78.0, 5.0 },
    { 147.0, -5.0 }, { 86.9, 28.0 } };
  double worst = 0.0;
  int pixels = 0;
  for (const auto& at : places)
  {
    const double camera[3] = { at[0], at[1] > 0 ? at[1] - 0.5 : at[1] + 0.5, 3.0e5 };
    const double target[3] = { at[0], at[1], 1000.0 };
    scene.Look(camera, target, 40.0);
    scene.Render();
    for (const auto& p : ComposedHeights(scene))
    {
      if (std::isnan(p[0]))
      {
        continue;
      }
      const double n = proj.Undulation(p[0], p[1]);
      worst = std::max(worst, std::isfinite(n) ? std::abs(p[2] - (1000.0 + n)) : 1e9);
      ++pixels;
    }
  }
  const bool noGLError = vtkGlobeTest::NoGLError();
  char text[200];
  std::snprintf(text, sizeof(text),
    "%d grid points at 6 places: worst |height - (1000 m + N(PROJ))| %.4f m; %s",
    pixels, worst, noGLError ? "without GL error" : "with a GL error");
  Check.Expect(pixels > 6 * 20000 && worst <= 0.01 && noGLError, text);
}

void PartSummits(ProjGeoid& proj)
{
  std::printf("C. Summits above EGM96, nearest posts:\n");
  struct Summit
  {
    const char* Name;
    const char* File;
    double Lon, Lat;
  } summits[] = { { "Everest", "earth/mt_everest_90m.tif", 86.925278, 27.988056 },
    { "Rainier", "earth/mt_rainier_90m.tif", -121.760374, 46.852886 } };
  for (const Summit& s : summits)
  {
    for (bool geoid : { false, true })
    {
      vtkGlobeTest::Scene scene;
      auto base = vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true);
      auto inset = vtkGlobeTest::FileLayer(s.File, true);
      inset->SetInterpolationToNearest();
      if (geoid)
      {
        base->SetVerticalDatumToEGM96();
        inset->SetVerticalDatumToEGM96();
      }
      scene.Mapper->AddLayer(base);
      scene.Mapper->AddLayer(inset);
      inset->Update();
      // The highest post near the summit, and its texel's extent.
      double e[4];
      inset->GetGeographicExtent(e);
      const int w = inset->GetNumberOfColumns(), h = inset->GetNumberOfRows();
      const double dx = (e[1] - e[0]) / w, dy = (e[3] - e[2]) / h;
      vtkDataArray* data = vtkGlobeTest::WholeData(inset);
      int bi = 0, bj = 0;
      double top = -1e9;
      const int ci = static_cast<int>((s.Lon - e[0]) / dx), cj = static_cast<int>((e[3] - s.Lat) / dy);
      for (int j = std::max(0, cj - 20); j <= std::min(h - 1, cj + 20); ++j)
      {
        for (int i = std::max(0, ci - 20); i <= std::min(w - 1, ci + 20); ++i)
        {
          const double v = data->GetComponent(static_cast<vtkIdType>(j) * w + i, 0);
          if (v > top)
          {
            top = v;
            bi = i;
            bj = j;
          }
        }
      }
      const double postLon = e[0] + (bi + 0.5) * dx, postLat = e[3] - (bj + 0.5) * dy;
      const double camera[3] = { postLon, postLat - 0.03, top + 2500.0 };
      const double target[3] = { postLon, postLat, top };
      scene.Look(camera, target, 4.0, 10.0, 1.0e5);
      scene.Render();
      double worst = 0.0, drawn = NAN;
      int inPost = 0;
      for (const auto& p : ComposedHeights(scene))
      {
        if (std::isnan(p[0]) || std::abs(p[0] - postLon) > 0.4 * dx ||
          std::abs(p[1] - postLat) > 0.4 * dy)
        {
          continue;
        }
        const double n = geoid ? proj.Undulation(p[0], p[1]) : 0.0;
        worst = std::max(worst, std::abs(p[2] - (top + n)));
        drawn = p[2];
        ++inPost;
      }
      // Without a datum the orthometric post is drawn as if ellipsoidal: -N too high.
      const double n = proj.Undulation(postLon, postLat);
      char text[300];
      std::snprintf(text, sizeof(text),
        "%s, %s: %d grid points in the summit post (%.1f m above EGM96 at %.5f, %.5f) drawn at "
        "%.3f m above the ellipsoid, %.3f m from the post + N(PROJ) (N %.3f m); worst |drawn "
        "- expected| %.4f m",
        s.Name, geoid ? "EGM96 datum" : "no datum", inPost, top, postLon, postLat, drawn,
        drawn - (top + n), n, worst);
      Check.Expect(inPost > 10 && worst <= 0.01, text);
    }
  }
}

void PartBadInput()
{
  std::printf("D. Bad input:\n");
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkGlobeGeoid> missing;
  missing->AddObserver(vtkCommand::ErrorEvent, observer);
  missing->SetFileName("/nonexistent/geoid.gtx");
  Check.Expect(!missing->Update() && std::isnan(missing->GetUndulation(0, 0)) &&
      observer->GetError() &&
      observer->GetErrorMessage().find("/nonexistent/geoid.gtx") != std::string::npos,
    "a missing geoid file: not valid, NaN, an error naming it");
  const std::string truncated = std::string(VTKGLOBE_TEMP_DIR) + "/truncated.gtx";
  {
    std::ifstream in(vtkGlobeGeoid::GetEGM96FileName(), std::ios::binary);
    std::vector<char> bytes(1000);
    in.read(bytes.data(), bytes.size());
    std::ofstream(truncated, std::ios::binary).write(bytes.data(), bytes.size());
  }
  observer->Clear();
  vtkNew<vtkGlobeGeoid> cut;
  cut->AddObserver(vtkCommand::ErrorEvent, observer);
  cut->SetFileName(truncated.c_str());
  const bool refused = !cut->Update();
  const std::string message = observer->GetErrorMessage();
  Check.Expect(refused && message.find("truncated") != std::string::npos,
    "a truncated geoid file: an error that says so (" +
      message.substr(std::min(message.find("Geoid file"), message.size())) + ")");

  // A layer above a missing geoid is skipped (once), the layer below still draws.
  vtkGlobeTest::Scene scene;
  vtkNew<vtkTest::ErrorObserver> layerErrors;
  scene.Mapper->GetLayerSet()->AddObserver(vtkCommand::ErrorEvent, layerErrors);
  auto base = vtkSmartPointer<vtkGlobeLayer>::New();
  std::vector<float> low(8 * 4, 100.0f), high(8 * 4, 5000.0f);
  base->SetHeightData(8, 4, low.data(), -180, 180, -90, 90);
  auto bad = vtkSmartPointer<vtkGlobeLayer>::New();
  bad->SetHeightData(8, 4, high.data(), -180, 180, -90, 90);
  bad->SetVerticalDatum(vtkGlobeLayer::Geoid);
  bad->SetGeoidFileName("/nonexistent/geoid.gtx");
  scene.Mapper->AddLayer(base);
  scene.Mapper->AddLayer(bad);
  const double camera[3] = { 10.0, 10.0, 3.0e5 }, target[3] = { 10.0, 12.0, 0.0 };
  scene.Look(camera, target, 40.0);
  int errors = 0;
  double worst = 0.0;
  int pixels = 0;
  for (int frame = 0; frame < 3; ++frame)
  {
    scene.Render();
  }
  const std::string all = layerErrors->GetErrorMessage();
  for (size_t at = all.find("its geoid"); at != std::string::npos; at = all.find("its geoid", at + 1))
  {
    ++errors;
  }
  for (const auto& p : ComposedHeights(scene))
  {
    if (!std::isnan(p[0]))
    {
      worst = std::max(worst, std::abs(p[2] - 100.0));
      ++pixels;
    }
  }
  char text[300];
  std::snprintf(text, sizeof(text),
    "a layer above a missing geoid: %d error(s) over 6 frames (\"%.80s\"); %d grid points of "
    "the layer below at 100 m (worst %.3g m)",
    errors, layerErrors->GetErrorMessage().c_str(), pixels, worst);
  Check.Expect(errors == 1 &&
      layerErrors->GetErrorMessage().find("/nonexistent/geoid.gtx") != std::string::npos &&
      pixels > 30000 && worst < 0.01,
    text);
}
} // namespace

int TestGlobeVerticalDatum(int, char*[])
{
  ProjGeoid proj;
  vtkNew<vtkGlobeGeoid> geoid;
  geoid->SetFileName(vtkGlobeGeoid::GetEGM96FileName());
  if (!geoid->Update() || !proj.Transform)
  {
    std::printf("FAIL EGM96 (%s) or PROJ's EPSG:4979 -> 4326+5773 is not available\n",
      vtkGlobeGeoid::GetEGM96FileName());
    return 1;
  }
  PartCPU(proj, geoid);
  PartGPU(proj);
  PartSummits(proj);
  PartBadInput();
  return Check.Result();
}
