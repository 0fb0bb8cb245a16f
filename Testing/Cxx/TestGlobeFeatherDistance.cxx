// Height insets that meet the terrain below in a slope, not a wall (issue "Pictures": insets
// without walls): vtkGlobeLayer::FeatherDistance ramps an inset's weight over a distance in
// metres on the ground, whatever its resolution. vtkGlobeTerrain composes by the renderer's
// rules (its agreement with the GPU's depth is Rendering.TestGlobeTerrainQuery's), so the
// composed profile across the border is the rendered one.
//  A. A geographic inset 1000 m above a 0 m base (1 x 1 degree at 45-46 N, 0.01 degree texels):
//     with FeatherDistance 20 km the height 0, 5, ..., 25 km inside its west and south borders
//     is 1000 m times the distance over 20 km (within 1 m), so the steepest slope is 0.05;
//     FeatherWidth's 8 texels give a 6.2 km ramp there (slope 0.16) and 0 a wall.
//  B. A UTM inset (EPSG:32632, 10 x 10 km of 100 m texels) with FeatherDistance 2 km: the
//     same ramp in map metres across its west border.
//  C. The distance is capped at half the raster (a 1 km inset with 20 km: full weight only at
//     its centre), and a layer without data has no border.
#include "vtkGlobeLayerTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeMapProjection.h"
#include "vtkGlobeTerrain.h"
#include "vtkMath.h"

#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Checks;

vtkSmartPointer<vtkGlobeLayer> Constant(
  int w, int h, float value, double west, double east, double south, double north)
{
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  std::vector<float> values(static_cast<size_t>(w) * h, value);
  layer->SetHeightData(w, h, values.data(), west, east, south, north);
  layer->SetSkirtDistance(0.0); // the inward feather (part D: the skirt)
  return layer;
}


// The worst |h - expected| over distances 0..25 km inside a border, and the distance at which
// the height first reaches 999 m (the ramp's length).
struct Profile
{
  double Worst = 0.0;
  double Reach = 0.0;
};

template <typename F>
Profile Measure(double ramp, F&& at)
{
  Profile p;
  bool reached = false;
  for (double d = 0.0; d <= 25000.0; d += 250.0)
  {
    const double h = at(d);
    if (!reached && h >= 999.0)
    {
      p.Reach = d;
      reached = true;
    }
    if (ramp > 0.0 && static_cast<long>(d) % 5000 == 0)
    {
      p.Worst = std::max(p.Worst, std::abs(h - 1000.0 * std::min(1.0, d / ramp)));
    }
  }
  return p;
}
} // namespace

int TestGlobeFeatherDistance(int, char*[])
{
  std::printf("A. A geographic inset, 1000 m above the base:\n");
  auto base = Constant(8, 4, 0.0f, -180.0, 180.0, -90.0, 90.0);
  auto inset = Constant(100, 100, 1000.0f, 10.0, 11.0, 45.0, 46.0);
  vtkNew<vtkGlobeTerrain> terrain;
  terrain->AddLayer(base);
  terrain->AddLayer(inset);
  double parallel, meridian;
  vtkGlobeTest::WGS84Radii(45.5, parallel, meridian);
  auto west = [&](double d) {
    return terrain->GetHeight(10.0 + vtkMath::DegreesFromRadians(d / parallel), 45.5);
  };
  auto south = [&](double d) {
    return terrain->GetHeight(10.5, 45.0 + vtkMath::DegreesFromRadians(d / meridian));
  };
  struct Case
  {
    const char* Name;
    double Distance, Width; // FeatherDistance, FeatherWidth
    double West, South;     // the expected ramps (m)
  };
  const double texel = vtkMath::RadiansFromDegrees(0.01); // the inset's texel, radians
  const Case cases[] = { { "FeatherDistance 20 km", 20000.0, 8.0, 20000.0, 20000.0 },
    { "FeatherWidth 8 texels (default)", 0.0, 8.0, 8.0 * texel * parallel, 8.0 * texel * meridian },
    { "feather 0 (a wall)", 0.0, 0.0, 0.0, 0.0 } };
  for (const Case& c : cases)
  {
    inset->SetFeatherDistance(c.Distance);
    inset->SetFeatherWidth(c.Width);
    terrain->Update();
    const Profile w = Measure(c.West, west);
    const Profile s = Measure(c.South, south);
    const bool ok = w.Worst <= 1.0 && s.Worst <= 1.0 && std::abs(w.Reach - c.West) <= 260.0 &&
      std::abs(s.Reach - c.South) <= 260.0;
    Checks.Expect(ok,
      vtkGlobeTest::Printf("%s: full height %.2f km inside the west border (expected %.2f), "
                           "%.2f km inside the south one (%.2f); |h - ramp| <= %.3f m",
        c.Name, w.Reach / 1000.0, c.West / 1000.0, s.Reach / 1000.0, c.South / 1000.0,
        std::max(w.Worst, s.Worst)));
  }

  std::printf("B. A UTM inset (EPSG:32632), 10 x 10 km, FeatherDistance 2 km:\n");
  {
    auto utm = vtkGlobeTest::ProjectedHeights(
      32632, 100, 100, 495000.0, 5005000.0, 100.0, [](int, int) { return 1000.0f; });
    utm->SetSkirtDistance(0.0);
    utm->SetFeatherDistance(2000.0);
    vtkNew<vtkGlobeTerrain> t;
    t->AddLayer(Constant(8, 4, 0.0f, -180.0, 180.0, -90.0, 90.0));
    t->AddLayer(utm);
    t->Update();
    vtkNew<vtkGlobeMapProjection> p;
    p->SetFromEPSG(32632);
    double worst = 0.0;
    for (double d = 0.0; d <= 3000.0; d += 250.0)
    {
      double ll[2];
      p->Inverse(495000.0 + d, 5000000.0, ll);
      worst = std::max(worst, std::abs(t->GetHeight(ll[0], ll[1]) - 1000.0 * std::min(1.0, d / 2000.0)));
    }
    Checks.Expect(worst <= 1.0,
      vtkGlobeTest::Printf("across the west border at northing 5,000 km: |h - 1000 m x d / 2 km| "
                           "<= %.3f m over 0..3 km",
        worst));
  }

  std::printf("C. Limits:\n");
  {
    auto small = Constant(10, 10, 1000.0f, 10.0, 10.01, 45.0, 45.01);
    small->SetFeatherDistance(20000.0);
    small->Update();
    double border[2];
    small->GetFeatherBorder(border);
    vtkNew<vtkGlobeLayer> empty;
    empty->SetFeatherDistance(1000.0);
    double none[2];
    empty->GetFeatherBorder(none);
    Checks.Expect(border[0] == 0.5 && border[1] == 0.5 && none[0] == 0.0 && none[1] == 0.0,
      vtkGlobeTest::Printf("a 1 km inset with 20 km: border (%.2f, %.2f) of the raster (at most "
                           "half); a layer without data: (%.0f, %.0f)",
        border[0], border[1], none[0], none[1]));
  }
  std::printf("D. Skirts (the default for height layers): the ramp outside the raster:\n");
  {
    // A 1000 m geographic inset 1 x 1 degree at 45-46 N, 10-11 E, SkirtDistance 20 km: full
    // height everywhere inside, 1000 (1 - d / 20 km) at d outside its west (seen around the
    // turn: u > 1 there), east and south borders, 0 beyond.
    auto skirted = Constant(100, 100, 1000.0f, 10.0, 11.0, 45.0, 46.0);
    skirted->SetSkirtDistance(20000.0);
    vtkNew<vtkGlobeTerrain> t;
    t->AddLayer(Constant(8, 4, 0.0f, -180.0, 180.0, -90.0, 90.0));
    t->AddLayer(skirted);
    t->Update();
    double inside = 0.0, outside = 0.0;
    for (double d = 0.0; d <= 25000.0; d += 250.0)
    {
      const double expected = 1000.0 * std::max(0.0, 1.0 - d / 20000.0);
      const double dLon = vtkMath::DegreesFromRadians(d / parallel);
      const double dLat = vtkMath::DegreesFromRadians(d / meridian);
      outside = std::max({ outside, std::abs(t->GetHeight(10.0 - dLon, 45.5) - expected),
        std::abs(t->GetHeight(11.0 + dLon, 45.5) - expected),
        std::abs(t->GetHeight(10.5, 45.0 - dLat) - expected) });
      inside = std::max({ inside, std::abs(t->GetHeight(10.0 + dLon, 45.5) - 1000.0),
        std::abs(t->GetHeight(10.5, 45.0 + std::min(dLat, 0.5)) - 1000.0) });
    }
    double border[2], feather[2];
    skirted->GetSkirtBorder(border);
    skirted->GetFeatherBorder(feather);
    Checks.Expect(outside <= 1.0 && inside <= 1e-3 && feather[0] == 0.0 && feather[1] == 0.0,
      vtkGlobeTest::Printf("20 km skirt: |h - 1000 m (1 - d / 20 km)| <= %.3f m over 0..25 km "
                           "outside the west, east and south borders; inside |h - 1000| <= %.1e m "
                           "(no inward feather)",
        outside, inside));

    // The automatic skirt: min(5 km, a quarter of the shorter side); none for images.
    vtkNew<vtkGlobeLayer> automatic;
    std::vector<float> values(100 * 100, 1000.0f);
    automatic->SetHeightData(100, 100, values.data(), 10.0, 11.0, 45.0, 46.0);
    automatic->Update();
    double big[2];
    automatic->GetSkirtBorder(big);
    auto tiny = Constant(10, 10, 1000.0f, 10.0, 10.01, 45.0, 45.01);
    tiny->SetSkirtDistanceToAutomatic();
    tiny->Update();
    double small[2];
    tiny->GetSkirtBorder(small);
    const double width = vtkMath::RadiansFromDegrees(1.0) * parallel;
    const double tinyWidth = vtkMath::RadiansFromDegrees(0.01) * parallel;
    const double tinyHeight = vtkMath::RadiansFromDegrees(0.01) * meridian;
    vtkNew<vtkGlobeLayer> image;
    std::vector<unsigned char> rgba(4 * 16, 255);
    image->SetColorData(4, 4, 4, rgba.data(), 10.0, 11.0, 45.0, 46.0);
    image->Update();
    double none[2];
    image->GetSkirtBorder(none);
    Checks.Expect(std::abs(big[0] * width - 5000.0) < 1.0 &&
        std::abs(small[0] * tinyWidth - 0.25 * std::min(tinyWidth, tinyHeight)) < 0.01 &&
        none[0] == 0.0 && none[1] == 0.0,
      vtkGlobeTest::Printf("automatic: %.0f m for a 1 degree inset, %.1f m for a 0.01 degree one "
                           "(a quarter of its %.0f m side); images: (%g, %g)",
        big[0] * width, small[0] * tinyWidth, std::min(tinyWidth, tinyHeight), none[0], none[1]));

    // A UTM inset (EPSG:32632, 10 x 10 km of 100 m texels) with a 2 km skirt, west of its west
    // border in map metres.
    auto utm = vtkGlobeTest::ProjectedHeights(
      32632, 100, 100, 495000.0, 5005000.0, 100.0, [](int, int) { return 1000.0f; });
    utm->SetSkirtDistance(2000.0);
    vtkNew<vtkGlobeTerrain> tu;
    tu->AddLayer(Constant(8, 4, 0.0f, -180.0, 180.0, -90.0, 90.0));
    tu->AddLayer(utm);
    tu->Update();
    vtkNew<vtkGlobeMapProjection> p;
    p->SetFromEPSG(32632);
    double worst = 0.0;
    for (double d = 0.0; d <= 3000.0; d += 250.0)
    {
      double ll[2];
      p->Inverse(495000.0 - d, 5000000.0, ll);
      worst = std::max(worst, std::abs(tu->GetHeight(ll[0], ll[1]) - 1000.0 * std::max(0.0, 1.0 - d / 2000.0)));
    }
    Checks.Expect(worst <= 1.0,
      vtkGlobeTest::Printf("UTM, 2 km skirt west of the west border: |h - 1000 m (1 - d / 2 km)| "
                           "<= %.3f m over 0..3 km",
        worst));
  }
  return Checks.Result();
}
