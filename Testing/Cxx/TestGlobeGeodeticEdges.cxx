// Projected layers at the places where a float longitude or latitude is at its edge (issue
// "Geodetic correctness", defects 1-3), with HighPrecisionGeodetic on (the default) and off:
//  A. The poles: polar stereographic layers (EPSG:3413 north, 3031 south) and a global
//     equidistant cylindrical layer (EPSG:4087) seen from 2.5 km, the pole in view. Every
//     pixel of the globe shows the layer; none the base colour. (Before: a hole 753 m wide
//     around the pole with high precision on: the latitude's hi part, rounded to its 2^-12 rad
//     grid, lay past 90 degrees and failed the projection's domain check.)
//  B. The antimeridian: full-width Web Mercator (EPSG:3857) and EPSG:4087 layers seen from
//     2.5 km with 180 degrees in view: no pixel of base colour. (Before: a gap 0.0065 degrees
//     wide: the longitude's hi part, rounded past pi, took the wrap to the reference's twin.)
//  C. The wrap: the same layers with distinct nearest-filtered texels and the default 8-texel
//     feather, seen from 1,500 km across 180 degrees: every pixel shows the texel the exact
//     projection (GeographicLib) puts there, on both sides. (Before: a full-width projected
//     layer was feathered at +-180 degrees, fading to the base colour over 8 texels.)
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"


#include <cmath>
#include <cstdio>

namespace
{
vtkGlobeTest::Checklist Check;
constexpr double HalfTurn = 3.14159265358979323846 * 6378137.0; // pi a, WGS84: half the equator

const std::array<unsigned char, 3> Uniform = { 200, 60, 30 };

struct Raster
{
  const char* Name;
  int EPSG, Width, Height;
  double West, North, Pixel;
};

// 100 km texels over +-1,500 km around the pole; the whole turn in 256 columns.
const Raster NorthPolar = { "EPSG:3413", 3413, 30, 30, -1.5e6, 1.5e6, 1.0e5 };
const Raster SouthPolar = { "EPSG:3031", 3031, 30, 30, -1.5e6, 1.5e6, 1.0e5 };
const Raster Equidistant = { "EPSG:4087", 4087, 256, 128, -HalfTurn, 0.5 * HalfTurn,
  2.0 * HalfTurn / 256 };
const Raster WebMercator = { "EPSG:3857", 3857, 256, 256, -HalfTurn, HalfTurn,
  2.0 * HalfTurn / 256 };

vtkSmartPointer<vtkGlobeLayer> Layer(const Raster& r, bool texels)
{
  return vtkGlobeTest::ProjectedImage(r.EPSG, r.Width, r.Height, r.West, r.North, r.Pixel,
    [texels](int i, int j) { return texels ? vtkGlobeTest::TexelColour(7, i, j) : Uniform; });
}

// Pixels of the globe that do not show the uniform layer colour, and how far the farthest of
// them lies from the target's ground point.
void CountHoles(const char* what, const Raster& r, bool highPrecision, const double camera[3],
  const double target[3])
{
  vtkGlobeTest::Scene scene;
  scene.Mapper->LightingOff();
  scene.Mapper->SetHighPrecisionGeodetic(highPrecision);
  scene.Mapper->AddLayer(Layer(r, false));
  scene.Look(camera, target, 60.0, 1.0, 1.0e6);
  scene.Render();
  const auto image = vtkGlobeTest::ReadPixels(scene.Window);
  const auto llh = vtkGlobeTest::GeodeticPixels(scene);
  double centre[3], p[3];
  const double ground[3] = { target[0], target[1], 0.0 };
  scene.Body->GeodeticToCartesian(ground, centre);
  int globe = 0, holes = 0;
  double farthest = 0.0;
  for (size_t i = 0; i < llh.size(); ++i)
  {
    if (std::isnan(llh[i][0]))
    {
      continue;
    }
    ++globe;
    bool same = true;
    for (int k = 0; k < 3; ++k)
    {
      same &= std::abs(image[3 * i + k] - Uniform[k]) <= 2;
    }
    if (!same)
    {
      ++holes;
      const double at[3] = { llh[i][0], llh[i][1], 0.0 };
      scene.Body->GeodeticToCartesian(at, p);
      farthest = std::max(farthest, std::sqrt(vtkMath::Distance2BetweenPoints(p, centre)));
    }
  }
  char text[300];
  std::snprintf(text, sizeof(text),
    "%s, %s, high precision %s: %d of %d globe pixels show another colour than the layer's "
    "(farthest %.0f m from the point looked at)",
    what, r.Name, highPrecision ? "on" : "off", holes, globe, farthest);
  Check.Expect(globe > 20000 && holes == 0, text);
}

void PartPoles()
{
  std::printf("A. The poles, 2.5 km up:\n");
  const double north[3] = { -45.0, 89.985, 2500.0 }, northPole[3] = { -45.0, 90.0, 0.0 };
  const double south[3] = { 0.0, -89.985, 2500.0 }, southPole[3] = { 0.0, -90.0, 0.0 };
  for (bool hp : { true, false })
  {
    CountHoles("north pole", NorthPolar, hp, north, northPole);
    CountHoles("south pole", SouthPolar, hp, south, southPole);
    CountHoles("north pole", Equidistant, hp, north, northPole);
    CountHoles("south pole", Equidistant, hp, south, southPole);
  }
}

void PartAntimeridian()
{
  std::printf("B. The antimeridian, 2.5 km up:\n");
  const double camera[3] = { 179.985, -0.01, 2500.0 }, target[3] = { 180.0, 0.0, 0.0 };
  for (bool hp : { true, false })
  {
    CountHoles("180 degrees", WebMercator, hp, camera, target);
    CountHoles("180 degrees", Equidistant, hp, camera, target);
  }
}

void PartWrap()
{
  std::printf("C. The wrap across 180 degrees, 1,500 km up, default feather:\n");
  const double camera[3] = { 170.0, 0.0, 1.5e6 }, target[3] = { 180.0, 5.0, 0.0 };
  for (const Raster* r : { &WebMercator, &Equidistant })
  {
    for (bool hp : { true, false })
    {
      vtkGlobeTest::Scene scene;
      scene.Mapper->LightingOff();
      scene.Mapper->SetHighPrecisionGeodetic(hp);
      auto layer = Layer(*r, true);
      layer->SetFeatherWidth(8.0);
      scene.Mapper->AddLayer(layer);
      scene.Look(camera, target, 40.0);
      scene.Render();
      const auto image = vtkGlobeTest::ReadPixels(scene.Window);
      const auto llh = vtkGlobeTest::GeodeticPixels(scene);
      int east = 0, west = 0, wrong = 0;
      for (size_t p = 0; p < llh.size(); ++p)
      {
        double u, v;
        if (std::isnan(llh[p][0]) ||
          !vtkGlobeTest::LayerUV(layer, llh[p][0], llh[p][1], u, v) || v < 0 || v >= 1)
        {
          continue;
        }
        u -= std::floor(u);
        const double x = u * r->Width, y = v * r->Height, margin = 0.03;
        if (x - std::floor(x) < margin || std::ceil(x) - x < margin ||
          y - std::floor(y) < margin || std::ceil(y) - y < margin)
        {
          continue;
        }
        const auto c = vtkGlobeTest::TexelColour(7, static_cast<int>(x), static_cast<int>(y));
        bool same = true;
        for (int k = 0; k < 3; ++k)
        {
          same &= std::abs(image[3 * p + k] - c[k]) <= 2;
        }
        wrong += !same;
        (llh[p][0] < 0.0 ? east : west) += 1;
      }
      char text[300];
      std::snprintf(text, sizeof(text),
        "%s, high precision %s, IsGlobal %d: %d pixels west and %d east of 180 degrees, %d "
        "show another texel than the exact projection's",
        r->Name, hp ? "on" : "off", layer->IsGlobal() ? 1 : 0, west, east, wrong);
      Check.Expect(layer->IsGlobal() && west > 5000 && east > 5000 && wrong == 0, text);
    }
  }
}
} // namespace

int TestGlobeGeodeticEdges(int, char*[])
{
  PartPoles();
  PartAntimeridian();
  PartWrap();
  return Check.Result();
}
