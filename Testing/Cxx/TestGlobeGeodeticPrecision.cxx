// Geodetic precision (issue 5, Documentation/rendering.md "Geodetic precision"): 0.5 m data must
// be placed as precisely at lon = +-179.99 degrees (and across 180) and lat = +-80 degrees as at
// (0, 0).
//  A. CPU mirror: globe_geodeticFromOffset (the shader text, in float) against GeographicLib
//     for points 0.1 m .. 100 km from a local origin at each place; the float path
//     (globe_lonLatFromNormal of a float unit direction) for comparison.
//  B. Rendering, with HighPrecisionGeodetic on and off: a colour inset of 0.5 m checker cells
//     (nearest filtering, cells coloured by (column mod 4, row mod 4)) seen from 20 m above at
//     each place. Per pixel, the exact cell is the one the pixel's ray (double) hits on the
//     ellipsoid (GeographicLib); a pixel is wrong when it shows another cell. Counted away from
//     cell edges (1 cm margin; a pixel is 5 cm); the G-buffer's own position is checked against
//     the ray hit too.
//  C. Height: a 2 m ramp (slope 2, 0.25 m posts) rising to the north-east at each place; the
//     depth-reconstructed surface in the middle of the ramp lies where the data puts it
//     (horizontal misplacement = height error / slope).
//  D. Far from the local origin (a hemisphere, the date line, a polar stereographic layer) the
//     picture is the same with the option on and off.
// The far places must be as good as (0, 0) with the option on, and measurably worse off (so the
// option demonstrably matters); switching it rebuilds the shaders once, not every frame.
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeShaderMath.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkMath.h"

#include <GeographicLib/Geodesic.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace
{
struct Place
{
  const char* Name;
  double Lon, Lat; // degrees
};
// The last straddles the date line: its insets reach from 179.99998 to 180.00002 degrees.
const Place Places[] = { { "(0, 0)", 0.001, 0.001 }, { "(+179.99, +80)", 179.99, 80.0 },
  { "(-179.99, -80)", -179.99, -80.0 }, { "(+179.99, 0)", 179.99, 0.001 },
  { "(180, 30)", 180.0, 30.0 } };

// Degrees of latitude and longitude per metre at a place.
void DegreesPerMetre(vtkGlobeEllipsoid* body, double lon, double lat, double& perLon, double& perLat)
{
  double a[3], b[3];
  const double step = 1e-4;
  body->GeodeticToCartesian(lon - step, lat, 0.0, a);
  body->GeodeticToCartesian(lon + step, lat, 0.0, b);
  perLon = 2.0 * step / vtkGlobeTest::Distance(a, b);
  body->GeodeticToCartesian(lon, lat - step, 0.0, a);
  body->GeodeticToCartesian(lon, lat + step, 0.0, b);
  perLat = 2.0 * step / vtkGlobeTest::Distance(a, b);
}

// The first hit of a ray with the ellipsoid (double; eye outside), or false.
bool RayEllipsoid(vtkGlobeEllipsoid* body, const double eye[3], const double ray[3], double hit[3])
{
  const double* r = body->GetRadii();
  double a = 0, b = 0, c = 0;
  for (int i = 0; i < 3; ++i)
  {
    const double o = eye[i] / r[i], d = ray[i] / r[i];
    a += d * d;
    b += o * d;
    c += o * o;
  }
  c -= 1.0;
  const double disc = b * b - a * c;
  if (!(disc >= 0.0))
  {
    return false;
  }
  const double q = -(b - std::sqrt(disc)); // b < 0 looking at the body: no cancellation
  const double t = c / q;
  for (int i = 0; i < 3; ++i)
  {
    hit[i] = eye[i] + t * ray[i];
  }
  return t > 0.0;
}

// A: the shader's conversion in float against GeographicLib, for points up to 100 km from the
// origin: within 0.1 mm + 3e-7 of the distance (a few float ulps of the offset).
void CheckMirror(vtkGlobeTest::Checklist& check, vtkGlobeEllipsoid* body)
{
  namespace F = vtkGlobeShaderMath::f;
  const double* radii = body->GetRadii();
  const double largest = body->GetMaximumRadius();
  const GeographicLib::Geodesic geodesic(radii[0], 1.0 - radii[2] / radii[0]);
  const F::vec3 rs(static_cast<float>(radii[0] / largest), static_cast<float>(radii[1] / largest),
    static_cast<float>(radii[2] / largest));
  // Unit direction in scaled space of a geodetic point on the ellipsoid.
  auto direction = [&](double lon, double lat, double d[3]) {
    double x[3];
    body->GeodeticToCartesian(lon, lat, 0.0, x);
    double n = 0;
    for (int i = 0; i < 3; ++i)
    {
      d[i] = x[i] / radii[i];
      n += d[i] * d[i];
    }
    for (int i = 0; i < 3; ++i)
    {
      d[i] /= std::sqrt(n);
    }
  };
  // Ground distance (m) between two geodetic points (deg).
  auto distance = [&](double lon0, double lat0, double lon1, double lat1) {
    double s = 0;
    geodesic.Inverse(lat0, lon0, lat1, lon1, s);
    return s;
  };
  // The rendered places, and a local origin on the polar axis (its own branch).
  std::vector<Place> places(std::begin(Places), std::end(Places));
  places.push_back({ "(north pole)", 0.0, 90.0 });
  for (const Place& place : places)
  {
    double ref[3];
    direction(place.Lon, place.Lat, ref);
    // The reference's (lon, lat) as the CPU computes it (vtkGlobeLayerSet), hi + lo.
    double q[3];
    for (int i = 0; i < 3; ++i)
    {
      q[i] = ref[i] / (radii[i] / largest);
    }
    const double lon0 = std::atan2(q[1], q[0]), lat0 = std::atan2(q[2], std::hypot(q[0], q[1]));
    const float lonHi = static_cast<float>(lon0), latHi = static_cast<float>(lat0);
    const F::vec4 lonLat(lonHi, static_cast<float>(lon0 - lonHi), latHi, static_cast<float>(lat0 - latHi));
    const F::vec3 refF(static_cast<float>(ref[0]), static_cast<float>(ref[1]), static_cast<float>(ref[2]));
    double worst = 0.0, worstNear = 0.0, worstFloat = 0.0, worstRatio = 0.0;
    for (double d : { 0.1, 1.0, 10.0, 100.0, 1000.0, 1.0e4, 1.0e5 })
    {
      for (int k = 0; k < 8; ++k)
      {
        double lat1, lon1;
        geodesic.Direct(place.Lat, place.Lon, 45.0 * k + 10.0, d, lat1, lon1);
        double s[3];
        direction(lon1, lat1, s);
        // What the G-buffer holds: the offset from the origin, in float.
        const F::vec3 offset(static_cast<float>(s[0] - ref[0]), static_cast<float>(s[1] - ref[1]),
          static_cast<float>(s[2] - ref[2]));
        float hiLon = 0, loLon = 0, hiLat = 0, loLat = 0;
        F::globe_geodeticFromOffset(refF, lonLat, offset, rs, hiLon, loLon, hiLat, loLat);
        const double lon = vtkMath::DegreesFromRadians(static_cast<double>(hiLon) + loLon);
        const double lat = vtkMath::DegreesFromRadians(static_cast<double>(hiLat) + loLat);
        const double error = distance(lon1, lat1, lon, lat);
        worst = std::max(worst, error);
        worstNear = d <= 1000.0 ? std::max(worstNear, error) : worstNear;
        worstRatio = std::max(worstRatio, error / (1e-4 + 3e-7 * d));
        // The float path: a float unit direction, float (lon, lat).
        const F::vec3 sF(static_cast<float>(s[0]), static_cast<float>(s[1]), static_cast<float>(s[2]));
        float fLon = 0, fLat = 0;
        F::globe_lonLatFromNormal(F::globe_normalize(sF / rs), fLon, fLat);
        worstFloat = std::max(worstFloat,
          distance(lon1, lat1, vtkMath::DegreesFromRadians(fLon), vtkMath::DegreesFromRadians(fLat)));
      }
    }
    check.Expect(worstRatio <= 1.0,
      vtkGlobeTest::Printf("A %-15s origin + offset (float) within 0.1 mm + 3e-7 of the distance "
                           "(0.1 m .. 100 km): worst %.2g m, %.2g m up to 1 km; float (lon, lat) "
                           "path: worst %.2f m",
        place.Name, worst, worstNear, worstFloat));
  }
}

struct Measure
{
  int Checked = 0; // pixels at least 1 cm away from every cell edge
  int Wrong = 0;
  double GBufferWorst = 0.0;  // m: the G-buffer's position against the ray hit
  double GBufferMedian = 0.0; // m
  double RampWorst = 0.0;     // m: horizontal misplacement of the height ramp
  int RampPixels = 0;
};

// B: the checker inset at a place, seen from 20 m; counts wrong pixels and measures the
// G-buffer's position error.
void MeasureChecker(vtkGlobeTest::Scene& scene, const Place& place, Measure& m)
{
  vtkGlobeEllipsoid* body = scene.Body;
  double perLon, perLat;
  DegreesPerMetre(body, place.Lon, place.Lat, perLon, perLat);
  const int cells = 128; // 64 m
  const double cellLon = 0.5 * perLon, cellLat = 0.5 * perLat;
  const double west = place.Lon - 0.5 * cells * cellLon, north = place.Lat + 0.5 * cells * cellLat;
  std::vector<unsigned char> rgb(static_cast<size_t>(cells) * cells * 3);
  for (int j = 0; j < cells; ++j) // row 0 = north
  {
    for (int i = 0; i < cells; ++i)
    {
      unsigned char* c = &rgb[3 * (static_cast<size_t>(j) * cells + i)];
      c[0] = static_cast<unsigned char>(30 + 60 * (i % 4));
      c[1] = static_cast<unsigned char>(30 + 60 * (j % 4));
      c[2] = 128;
    }
  }
  vtkNew<vtkGlobeLayer> layer;
  layer->SetColorData(cells, cells, 3, rgb.data(), west, west + cells * cellLon,
    north - cells * cellLat, north);
  layer->SetInterpolationToNearest();
  scene.Mapper->RemoveAllLayers();
  scene.Mapper->AddLayer(layer);
  // 20 m up, 4 m south of the centre, looking at it (11 degrees off the vertical).
  const double camera[3] = { place.Lon, place.Lat - 4.0 * perLat, 20.0 };
  const double target[3] = { place.Lon, place.Lat, 0.0 };
  scene.Look(camera, target, 40.0);
  scene.Render();

  const int* size = scene.Window->GetSize();
  const std::vector<unsigned char> pixels = vtkGlobeTest::ReadPixels(scene.Window);
  const std::vector<float> gbuffer = vtkGlobeTest::ReadTexture(vtkGlobeMapperTesting::GetGBufferTexture(scene.Mapper));
  const double* eye = scene.Renderer->GetActiveCamera()->GetPosition();
  std::vector<double> gErrors;
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      const size_t at = static_cast<size_t>(y) * size[0] + x;
      double ray[3], hit[3], llh[3];
      vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
      if (!RayEllipsoid(body, eye, ray, hit) || !body->CartesianToGeodetic(hit, llh))
      {
        continue;
      }
      // The G-buffer's point: its direction (reference + offset, or the direction) on the
      // ellipsoid, against the exact hit.
      double g[3];
      vtkGlobeTest::GBufferPoint(scene, &gbuffer[4 * at], false, g);
      gErrors.push_back(vtkGlobeTest::Distance(g, hit));

      const double fx = std::remainder(llh[0] - west, 360.0) / cellLon;
      const double fy = (north - llh[1]) / cellLat;
      const double i = std::floor(fx), j = std::floor(fy);
      const double edge = 0.5 * std::min({ fx - i, i + 1 - fx, fy - j, j + 1 - fy }); // m
      if (i < 0 || j < 0 || i >= cells || j >= cells || edge < 0.01)
      {
        continue;
      }
      ++m.Checked;
      const unsigned char* c = &pixels[3 * at];
      const int ci = static_cast<int>(std::lround((c[0] - 30) / 60.0));
      const int cj = static_cast<int>(std::lround((c[1] - 30) / 60.0));
      m.Wrong += (ci != static_cast<int>(i) % 4 || cj != static_cast<int>(j) % 4) ? 1 : 0;
    }
  }
  if (!gErrors.empty())
  {
    std::sort(gErrors.begin(), gErrors.end());
    m.GBufferWorst = gErrors.back();
    m.GBufferMedian = gErrors[gErrors.size() / 2];
  }
}

// C: a ramp of 2 m rising north-east with slope 2 over 0.25 m posts at a place: the horizontal
// misplacement of the drawn surface in the middle of the ramp (0.5 .. 1.5 m, where the data is
// exactly linear, so the mesh is too).
void MeasureRamp(vtkGlobeTest::Scene& scene, const Place& place, Measure& m)
{
  vtkGlobeEllipsoid* body = scene.Body;
  double perLon, perLat;
  DegreesPerMetre(body, place.Lon, place.Lat, perLon, perLat);
  const int posts = 257; // 64 m, post (128, 128) at the centre
  const double post = 0.25;
  const double west = place.Lon - (posts / 2 + 0.5) * post * perLon;
  const double north = place.Lat + (posts / 2 + 0.5) * post * perLat;
  const double slope = 2.0, g = slope / std::sqrt(2.0); // per metre east and north
  std::vector<float> h(static_cast<size_t>(posts) * posts);
  for (int j = 0; j < posts; ++j)
  {
    for (int i = 0; i < posts; ++i)
    {
      const double east = (i - posts / 2) * post, northward = (posts / 2 - j) * post;
      h[static_cast<size_t>(j) * posts + i] =
        static_cast<float>(std::min(2.0, std::max(0.0, 1.0 + g * (east + northward))));
    }
  }
  vtkNew<vtkGlobeLayer> layer;
  layer->SetHeightData(posts, posts, h.data(), west, west + posts * post * perLon,
    north - posts * post * perLat, north);
  scene.Mapper->RemoveAllLayers();
  scene.Mapper->AddLayer(layer);
  const double camera[3] = { place.Lon, place.Lat - 4.0 * perLat, 20.0 };
  const double target[3] = { place.Lon, place.Lat, 1.0 };
  scene.Look(camera, target, 40.0);
  scene.Render();
  const std::vector<vtkGlobeLayer*> layers = { layer };
  const std::vector<std::array<double, 3>> llh = vtkGlobeTest::GeodeticPixels(scene);
  for (const auto& p : llh)
  {
    if (!(p[2] > 0.5 && p[2] < 1.5))
    {
      continue;
    }
    const double data = vtkGlobeTest::ComposedHeight(layers, p[0], p[1]);
    ++m.RampPixels;
    m.RampWorst = std::max(m.RampWorst, std::abs(p[2] - data) / slope);
  }
}
// D: far from the local origin the hi + lo pairs must still wrap at the date line and pass
// projections' domain checks: the whole hemisphere over (170 E, 40 N) from 8,000 km, with the
// global imagery and the EPSG:3413 polar cap (~50 degrees from the origin), rendered with the
// option on and off, must give the same picture (differences: rounding at a few pixels).
void CheckFarFromOrigin(vtkGlobeTest::Checklist& check)
{
  vtkGlobeTest::Scene scene(300, 225, 256);
  vtkGlobeClippingRange::Install(scene.Renderer);
  scene.Mapper->LightingOff();
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/world.tif", false));
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/world_north_polar_3413.tif", false));
  const double camera[3] = { 170.0, 40.0, 8.0e6 }, target[3] = { 170.0, 55.0, 0.0 };
  scene.Look(camera, target, 60.0);
  std::vector<unsigned char> images[2];
  for (bool highPrecision : { true, false })
  {
    scene.Mapper->SetHighPrecisionGeodetic(highPrecision);
    scene.Render();
    images[highPrecision ? 0 : 1] = vtkGlobeTest::ReadPixels(scene.Window);
  }
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  int covered = 0, differ = 0;
  for (size_t i = 0; i < depth.size(); ++i)
  {
    covered += depth[i] < 1.0f ? 1 : 0;
    int d = 0;
    for (int k = 0; k < 3; ++k)
    {
      d = std::max(d, std::abs(images[0][3 * i + k] - images[1][3 * i + k]));
    }
    differ += d > 24 ? 1 : 0;
  }
  check.Expect(covered > 20000 && differ < covered / 200,
    vtkGlobeTest::Printf("D hemisphere over (170 E, 40 N) with the polar cap: on and off differ "
                         "by more than 24 levels at %d of %d globe pixels",
      differ, covered));
}
} // namespace

int TestGlobeGeodeticPrecision(int, char*[])
{
  vtkGlobeTest::Checklist check;
  CheckFarFromOrigin(check);
  vtkGlobeTest::Scene scene(300, 225, 256);
  scene.Mapper->LightingOff();
  // The globe's clipping policy from the first frame on (it installs itself only when drawn).
  vtkGlobeClippingRange::Install(scene.Renderer);
  CheckMirror(check, scene.Body);

  check.Expect(scene.Mapper->GetHighPrecisionGeodetic(), "HighPrecisionGeodetic is on by default");
  const size_t count = sizeof(Places) / sizeof(Places[0]);
  Measure on[count], off[count];
  int builds[2] = { 0, 0 };
  for (bool highPrecision : { true, false })
  {
    scene.Mapper->SetHighPrecisionGeodetic(highPrecision);
    for (size_t k = 0; k < count; ++k)
    {
      Measure& m = highPrecision ? on[k] : off[k];
      MeasureChecker(scene, Places[k], m);
      MeasureRamp(scene, Places[k], m);
      std::printf("%-3s %-15s checker: %5d of %5d pixels wrong (%.2f %%); G-buffer position "
                  "error median %.3g m, worst %.3g m; ramp: %d pixels, worst misplacement %.3g m\n",
        highPrecision ? "on" : "off", Places[k].Name, m.Wrong, m.Checked,
        100.0 * m.Wrong / std::max(1, m.Checked), m.GBufferMedian, m.GBufferWorst, m.RampPixels,
        m.RampWorst);
    }
    // The shaders were built for this setting; frames that change nothing rebuild nothing.
    const int before = scene.Mapper->GetGridPass()->GetNumberOfShaderBuilds() +
      scene.Mapper->GetCompositePass()->GetNumberOfShaderBuilds();
    scene.Window->Render();
    builds[highPrecision ? 0 : 1] = scene.Mapper->GetGridPass()->GetNumberOfShaderBuilds() +
      scene.Mapper->GetCompositePass()->GetNumberOfShaderBuilds() - before;
  }
  check.Expect(builds[0] == 0 && builds[1] == 0, "no shader rebuilds on frames that change nothing");
  {
    // Switching back rebuilds the grid and composition programs (they differ).
    const int before = scene.Mapper->GetGridPass()->GetNumberOfShaderBuilds() +
      scene.Mapper->GetCompositePass()->GetNumberOfShaderBuilds();
    scene.Mapper->HighPrecisionGeodeticOn();
    scene.Window->Render();
    const int rebuilt = scene.Mapper->GetGridPass()->GetNumberOfShaderBuilds() +
      scene.Mapper->GetCompositePass()->GetNumberOfShaderBuilds() - before;
    check.Expect(rebuilt == 2,
      vtkGlobeTest::Printf("switching the option rebuilds the height and composition shaders "
                           "(%d builds)", rebuilt));
  }

  const double fraction0 = static_cast<double>(on[0].Wrong) / std::max(1, on[0].Checked);
  for (size_t k = 0; k < count; ++k)
  {
    const double fOn = static_cast<double>(on[k].Wrong) / std::max(1, on[k].Checked);
    const double fOff = static_cast<double>(off[k].Wrong) / std::max(1, off[k].Checked);
    check.Expect(on[k].Checked > 30000 && fOn <= 0.001 && fOn <= fraction0 + 0.0005,
      vtkGlobeTest::Printf("B on  %-15s wrong cells %.3f %% of %d pixels (at (0, 0): %.3f %%)",
        Places[k].Name, 100.0 * fOn, on[k].Checked, 100.0 * fraction0));
    check.Expect(on[k].GBufferWorst < 0.01,
      vtkGlobeTest::Printf("B on  %-15s G-buffer position within 1 cm of the ray hit: worst %.2g m",
        Places[k].Name, on[k].GBufferWorst));
    check.Expect(on[k].RampPixels > 3000 && on[k].RampWorst < 0.01,
      vtkGlobeTest::Printf("C on  %-15s height ramp within 1 cm of its place: %d pixels, worst %.2g m",
        Places[k].Name, on[k].RampPixels, on[k].RampWorst));
    if (std::abs(Places[k].Lon) > 100.0)
    {
      // Off, the far places are measurably worse: float (lon, lat) steps of 0.3 .. 1.5 m.
      check.Expect(fOff > 10.0 * std::max(fOn, 0.001) && off[k].RampWorst > 0.05,
        vtkGlobeTest::Printf("off %-15s measurably worse: wrong cells %.2f %%, G-buffer worst "
                             "%.2f m, ramp worst %.2f m",
          Places[k].Name, 100.0 * fOff, off[k].GBufferWorst, off[k].RampWorst));
    }
  }
  return check.Result();
}
