// Layers in several map projections composed per pixel (issue: composition of projections):
//  A. Rainier in geographic coordinates and the same SRTM tile re-projected to UTM 10N: each
//     alone renders the terrain of its data (every pixel within its bound, the CPU mirror
//     projecting with GeographicLib), and the two registrations agree: the height difference
//     of the two renders, pixel by pixel, is no larger than the difference of the two data
//     sets themselves at the same points (the re-projection's own interpolation error).
//  B. The global imagery (equirectangular) and the north polar cap (EPSG:3413 polar
//     stereographic): the two register to a fraction of a pixel (best shift of the cap's image
//     against the base's in the ring both cover), and their composition has no seam (every
//     pixel lies between the two layers' colours around it) and no polar pinch (near the pole it is the
//     cap). Regression baseline: the composition.
//  C. A synthetic planet seen through three projections at different resolutions (Kooima's
//     test): nearest-filtered checkerboards in equirectangular, polar stereographic and UTM,
//     each texel a different colour; every pixel shows the texel the exact projection (CPU,
//     GeographicLib) puts there, except within a margin of texel edges.
//  D. Kooima's projection-quality weight: an equirectangular and a polar stereographic layer
//     averaged by their weights give the exact mixture at 30, 60 and 85 degrees north (weights
//     0.931, 2/3 and 0 for equirectangular; 1 for the conformal polar projection).
//  E. The same for the families PROJ's database supplies: cylindrical equal-area (EASE-Grid 2.0
//     Global) as the base, Lambert conformal conic (Lambert-93), Albers (Conus), polar
//     Lambert azimuthal equal-area (EASE-Grid 2.0 South) and oblique Lambert azimuthal
//     equal-area (LAEA Europe, over Scandinavia), drawn without reprojection.
//  F. The same for a CRS without an EPSG code: MODIS's sinusoidal grid (a PROJ string; in the
//     Streamed. variant a PNG whose .prj holds it, paged), across the map's cut at the
//     antimeridian and near a pole.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeCompositePass.h"
#include "vtkGlobeLayerSet.h"
#include "vtkRegressionTestImage.h"

#include <cstdio>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Check;

void PartRainier()
{
  std::printf("A. Rainier, geographic and UTM 10N:\n");
  const double camera[3] = { -121.86, 46.75, 16000.0 }, target[3] = { -121.7603, 46.8523, 4392.0 };
  auto render = [&](bool geographic, bool utm, vtkGlobeTest::Scene& scene) {
    scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
    if (geographic)
    {
      scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/mt_rainier_90m.tif", true));
    }
    if (utm)
    {
      scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/mt_rainier_utm10n.tif", true));
    }
    scene.Look(camera, target, 40.0, 100.0, 1.0e6);
    scene.Render();
  };
  vtkGlobeTest::Scene geo, utm, both;
  render(true, false, geo);
  render(false, true, utm);
  render(true, true, both);
  for (auto* s : { &geo, &utm, &both })
  {
    const vtkGlobeTest::TerrainCheck check = vtkGlobeTest::CheckTerrain(*s, 2);
    char what[200];
    std::snprintf(what, sizeof(what),
      "%s: %d pixels, median |dh| %.2f m, worst/bound %.2f, %d beyond, %d NaN",
      s == &geo ? "geographic alone" : (s == &utm ? "UTM alone" : "both composed"), check.Pixels,
      check.MedianError, check.WorstRatio, check.Failures, check.NaNs);
    Check.Expect(check.Pixels > 10000 && check.Failures == 0 && check.NaNs == 0, what);
  }
  Check.Expect(utm.Mapper->GetLayerSet()->GetNumberOfActiveHeightLayers() == 2,
    "the UTM layer is active (composed, not refused)");

  // Registration, seen almost straight down with a narrow view (so a height difference barely
  // moves where a ray meets the ground): the rendered height differences pixel by pixel against
  // the two data sets' own differences at the same points.
  const double above[3] = { -121.7603, 46.8423, 30000.0 }, summit[3] = { -121.7603, 46.8523, 0.0 };
  for (auto* s : { &geo, &utm })
  {
    s->Look(above, summit, 15.0, 1000.0, 1.0e5);
    s->Render();
  }
  const auto a = vtkGlobeTest::GeodeticPixels(geo), b = vtkGlobeTest::GeodeticPixels(utm);
  vtkGlobeLayer* geoLayer = geo.Mapper->GetLayer(1);
  vtkGlobeLayer* utmLayer = utm.Mapper->GetLayer(1);
  double rendered = 0.0, data = 0.0, halfPost = 0.0;
  int n = 0;
  for (size_t i = 0; i < a.size(); i += 3)
  {
    double hg, hu, hs;
    if (std::isnan(a[i][0]) || std::isnan(b[i][0]) ||
      !vtkGlobeTest::SampleHeight(geoLayer, a[i][0], a[i][1], hg) ||
      !vtkGlobeTest::SampleHeight(utmLayer, a[i][0], a[i][1], hu) ||
      !vtkGlobeTest::SampleHeight(geoLayer, a[i][0] + 1.0 / 1200.0, a[i][1], hs) ||
      vtkGlobeTest::CoverageWeight(geoLayer, a[i][0], a[i][1]) < 1.0 ||
      vtkGlobeTest::CoverageWeight(utmLayer, a[i][0], a[i][1]) < 1.0)
    {
      continue;
    }
    // The same pixel's two renders: heights along the same ray differ by the terrain's.
    rendered += (a[i][2] - b[i][2]) * (a[i][2] - b[i][2]);
    data += (hg - hu) * (hg - hu);
    halfPost += (hg - hs) * (hg - hs);
    ++n;
  }
  rendered = std::sqrt(rendered / n);
  data = std::sqrt(data / n);
  halfPost = std::sqrt(halfPost / n);
  char what[240];
  std::snprintf(what, sizeof(what),
    "%d pixels: RMS height difference of the renders %.2f m; of the two data sets at the same "
    "points %.2f m (the data shifted by one 90 m post: %.2f m)",
    n, rendered, data, halfPost);
  Check.Expect(n > 5000 && rendered <= 1.25 * data + 1.0 && data < halfPost, what);
}

void PartPolarCap(int argc, char* argv[], bool& imageOk)
{
  std::printf("B. Global imagery and the EPSG:3413 polar cap:\n");
  vtkGlobeTest::Scene scene;
  scene.Mapper->LightingOff();
  auto base = vtkGlobeTest::FileLayer("earth/world.tif", false);
  auto cap = vtkGlobeTest::FileLayer("earth/world_north_polar_3413.tif", false);
  scene.Mapper->AddLayer(base);
  scene.Mapper->AddLayer(cap);
  const double camera[3] = { -45.0, 62.0, 4.0e6 }, target[3] = { -45.0, 85.0, 0.0 };
  scene.Look(camera, target, 45.0);
  const int uploads0 = scene.Mapper->GetLayerSet()->GetNumberOfUploads();
  cap->EnabledOff();
  scene.Render();
  const auto imageBase = vtkGlobeTest::ReadPixels(scene.Window);
  cap->EnabledOn();
  base->EnabledOff();
  scene.Render();
  const auto imageCap = vtkGlobeTest::ReadPixels(scene.Window);
  base->EnabledOn();
  scene.Render();
  const auto imageBoth = vtkGlobeTest::ReadPixels(scene.Window);
  const auto llh = vtkGlobeTest::GeodeticPixels(scene);
  // Streamed, the layers upload pages, never whole textures.
  const int expected = vtkGlobeTest::Streamed() ? 0 : 2;
  Check.Expect(scene.Mapper->GetLayerSet()->GetNumberOfUploads() - uploads0 == expected,
    vtkGlobeTest::Printf("enabling and disabling layers re-uploads nothing (%d uploads in all)", expected));

  const int* size = scene.Window->GetSize();
  const int w = size[0], h = size[1];
  // Ring both cover well inside: 62..72 N. Best integer shift, then a parabola for sub-pixel.
  auto sad = [&](int sx, int sy) {
    double sum = 0.0;
    int count = 0;
    for (int y = 4; y < h - 4; ++y)
    {
      for (int x = 4; x < w - 4; ++x)
      {
        const size_t i = static_cast<size_t>(y) * w + x;
        if (std::isnan(llh[i][1]) || llh[i][1] < 62.0 || llh[i][1] > 72.0)
        {
          continue;
        }
        const size_t j = static_cast<size_t>(y + sy) * w + (x + sx);
        for (int k = 0; k < 3; ++k)
        {
          sum += std::abs(imageBase[3 * i + k] - imageCap[3 * j + k]);
        }
        ++count;
      }
    }
    return count ? sum / count : 1e30;
  };
  int bx = 0, by = 0;
  double best = 1e30;
  for (int sy = -3; sy <= 3; ++sy)
  {
    for (int sx = -3; sx <= 3; ++sx)
    {
      const double v = sad(sx, sy);
      if (v < best)
      {
        best = v;
        bx = sx;
        by = sy;
      }
    }
  }
  auto refine = [&](double m, double c, double p) {
    const double d = m - 2 * c + p;
    return d > 0 ? 0.5 * (m - p) / d : 0.0;
  };
  const double fx = bx + refine(sad(bx - 1, by), best, sad(bx + 1, by));
  const double fy = by + refine(sad(bx, by - 1), best, sad(bx, by + 1));
  char what[200];
  std::snprintf(what, sizeof(what),
    "registration of the cap against the base in 62..72 N: shift (%.2f, %.2f) px, mean |diff| %.1f",
    fx, fy, best);
  Check.Expect(std::hypot(fx, fy) < 0.5, what);

  // No seam: every covered pixel lies between the two layers' colours (a hole or a line of
  // base colour would not). "Between" takes the 3 x 3 neighbourhood of both pictures: the
  // composition's program is not the single layers' programs, and a sub-pixel difference in a
  // texture coordinate moves a sharp coastline by a fraction of a pixel.
  int covered = 0, outside = 0, nearPole = 0, poleMismatch = 0;
  for (size_t i = 0; i < llh.size(); ++i)
  {
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    if (std::isnan(llh[i][0]) || x == 0 || y == 0 || x == w - 1 || y == h - 1)
    {
      continue;
    }
    ++covered;
    for (int k = 0; k < 3; ++k)
    {
      int lo = 255, hi = 0;
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          const size_t j = 3 * (i + dy * w + dx) + k;
          lo = std::min({ lo, static_cast<int>(imageBase[j]), static_cast<int>(imageCap[j]) });
          hi = std::max({ hi, static_cast<int>(imageBase[j]), static_cast<int>(imageCap[j]) });
        }
      }
      if (imageBoth[3 * i + k] < lo - 2 || imageBoth[3 * i + k] > hi + 2)
      {
        ++outside;
        break;
      }
    }
    if (llh[i][1] > 85.0)
    {
      ++nearPole;
      poleMismatch += std::abs(imageBoth[3 * i] - imageCap[3 * i]) > 2;
    }
  }
  // (A pixel may round differently at a layer's anti-aliased edge: allow 1 in 10,000.)
  std::snprintf(what, sizeof(what), "no seam: %d of %d pixels outside the two layers' colours",
    outside, covered);
  Check.Expect(covered > 20000 && outside == 0, what);
  std::snprintf(what, sizeof(what), "no pinch: %d of %d pixels above 85 N differ from the cap", poleMismatch, nearPole);
  Check.Expect(nearPole > 500 && poleMismatch == 0, what);
  imageOk = vtkRegressionTestImageThreshold(scene.Window, 0.05) == vtkTesting::PASSED;
}

struct ViewPoint
{
  double Camera[3], Target[3];
};

// Renders each view of a scene of nearest-filtered layers with distinct texel colours
// (vtkGlobeTest::TexelColour(layer index, i, j)) and counts the pixels that show another
// texel than the exact projection (CPU, GeographicLib) puts there: the top layer covering the
// pixel's ground point, away from texel edges (the mesh and depth put a pixel's point a little
// off its true ground position).
int WrongTexels(vtkGlobeTest::Scene& scene, const std::vector<vtkGlobeLayer*>& layers,
  const std::vector<ViewPoint>& views, int& checked, std::vector<int>& perLayer)
{
  const int n = static_cast<int>(layers.size());
  int wrong = 0;
  checked = 0;
  perLayer.assign(n, 0);
  for (const ViewPoint& v : views)
  {
    scene.Look(v.Camera, v.Target, 40.0);
    scene.Render();
    const auto image = vtkGlobeTest::ReadPixels(scene.Window);
    const auto llh = vtkGlobeTest::GeodeticPixels(scene);
    const int* size = scene.Window->GetSize();
    const int w = size[0], h = size[1];
    for (size_t p = 0; p < llh.size(); ++p)
    {
      // Not on the silhouette (a 4-neighbour off the globe): a grazing ray's ground point is
      // ill-conditioned there (next to the limb one pixel spans up to 17 degrees of longitude
      // in these views), and the mesh draws it as the grid cell across the limb allows
      // (Documentation/rendering.md "The limb").
      const int px = static_cast<int>(p % w), py = static_cast<int>(p / w);
      if (std::isnan(llh[p][0]) || px == 0 || py == 0 || px == w - 1 || py == h - 1 ||
        std::isnan(llh[p - 1][0]) || std::isnan(llh[p + 1][0]) || std::isnan(llh[p - w][0]) ||
        std::isnan(llh[p + w][0]))
      {
        continue;
      }
      int top = -1, ti = 0, tj = 0;
      bool edge = false;
      for (int l = n - 1; l >= 0 && top < 0; --l)
      {
        double u, vv;
        if (!vtkGlobeTest::LayerUV(layers[l], llh[p][0], llh[p][1], u, vv) || u < 0 || u >= 1 ||
          vv < 0 || vv >= 1)
        {
          continue;
        }
        const double x = u * layers[l]->GetNumberOfColumns(), y = vv * layers[l]->GetNumberOfRows();
        const double margin = 0.03;
        edge = x - std::floor(x) < margin || std::ceil(x) - x < margin || y - std::floor(y) < margin ||
          std::ceil(y) - y < margin;
        top = l;
        ti = static_cast<int>(x);
        tj = static_cast<int>(y);
      }
      if (top < 0 || edge)
      {
        continue;
      }
      const auto c = vtkGlobeTest::TexelColour(top, ti, tj);
      ++checked;
      ++perLayer[top];
      bool same = true;
      for (int k = 0; k < 3; ++k)
      {
        same &= std::abs(image[3 * p + k] - c[k]) <= 2;
      }
      wrong += !same;
    }
  }
  return wrong;
}

void PartSynthetic()
{
  std::printf("C. A synthetic planet through three projections (nearest-filtered texels):\n");
  vtkGlobeTest::Scene scene;
  scene.Mapper->LightingOff();
  // Equirectangular base: 2-degree texels.
  auto equirect = vtkSmartPointer<vtkGlobeLayer>::New();
  {
    std::vector<unsigned char> rgb;
    for (int j = 0; j < 90; ++j)
    {
      for (int i = 0; i < 180; ++i)
      {
        const auto c = vtkGlobeTest::TexelColour(0, i, j);
        rgb.insert(rgb.end(), { c[0], c[1], c[2] });
      }
    }
    equirect->SetColorData(180, 90, 3, rgb.data(), -180, 180, -90, 90);
    equirect->SetFeatherWidth(0.0);
    equirect->SetInterpolationToNearest();
  }
  // Polar stereographic north (EPSG:3413), 100 km texels over +-1,500 km.
  auto polar = vtkGlobeTest::ProjectedImage(3413, 30, 30, -1.5e6, 1.5e6, 1.0e5,
    [](int i, int j) { return vtkGlobeTest::TexelColour(1, i, j); });
  // UTM 33N, 25 km texels, 500 x 1,000 km from (250 km E, 5,500 km N).
  auto utm = vtkGlobeTest::ProjectedImage(32633, 20, 40, 250000.0, 6.5e6, 25000.0,
    [](int i, int j) { return vtkGlobeTest::TexelColour(2, i, j); });
  scene.Mapper->AddLayer(equirect);
  scene.Mapper->AddLayer(polar);
  scene.Mapper->AddLayer(utm);

  const std::vector<ViewPoint> views = { { { 15.0, 40.0, 3.0e6 }, { 15.0, 53.0, 0.0 } },
    { { 0.0, 70.0, 2.5e6 }, { 0.0, 86.0, 0.0 } }, { { 170.0, 60.0, 4.0e6 }, { 178.0, 80.0, 0.0 } } };
  int checked = 0;
  std::vector<int> perLayer;
  const int wrong = WrongTexels(scene, { equirect, polar, utm }, views, checked, perLayer);
  char what[200];
  std::snprintf(what, sizeof(what),
    "%d pixels (equirectangular %d, polar %d, UTM %d): %d show another texel than the exact "
    "projection's", checked, perLayer[0], perLayer[1], perLayer[2], wrong);
  Check.Expect(perLayer[0] > 2000 && perLayer[1] > 2000 && perLayer[2] > 2000 && wrong == 0, what);
}
// The families PROJ's database defines and the GPU draws exactly (Documentation/projections.md):
// a cylindrical equal-area base (EASE-Grid 2.0 Global), Lambert-93 over France, Conus Albers,
// and EASE-Grid 2.0 South (polar Lambert azimuthal equal-area) over Antarctica.
void PartConicsAndEqualArea()
{
  std::printf("E. Lambert conformal conic, Albers, polar and oblique Lambert azimuthal and "
              "cylindrical equal-area (nearest-filtered texels):\n");
  vtkGlobeTest::Scene scene;
  scene.Mapper->LightingOff();
  // EPSG:6933: 36 x 15 square texels from the north-west corner of the whole map (x +-17,367,530
  // m, y +-7,314,540 m); it wraps east-west. In the Streamed. variant the rasters are files
  // (a PNG with a world file and a .prj each), which stream; in-memory data are always whole.
  const double ceaW = 17367530.445161499, ceaH = 7314540.8306386121;
  auto layer = [](const char* name, int index, int epsg, int w, int h, double west,
                 double north, double pixel) {
    const auto colour = [index](int i, int j) { return vtkGlobeTest::TexelColour(index, i, j); };
    if (!vtkGlobeTest::Streamed())
    {
      return vtkGlobeTest::ProjectedImage(epsg, w, h, west, north, pixel, colour);
    }
    auto file = vtkSmartPointer<vtkGlobeLayer>::New();
    file->SetFileName(
      vtkGlobeTest::WriteWorldFilePNG(std::string(VTKGLOBE_TEMP_DIR) + "/" + name, epsg, w, h, west, north, pixel, colour).c_str());
    file->SetRoleToColor();
    file->SetStreamingToOn();
    return file;
  };
  auto cea = layer("cea_6933", 0, 6933, 36, 15, -ceaW, ceaH, 2.0 * ceaW / 36.0);
  auto lambert93 = layer("lambert93_2154", 1, 2154, 24, 24, 100000.0, 7150000.0, 50000.0);
  auto albers = layer("conus_albers_5070", 2, 5070, 32, 20, -2400000.0, 3200000.0, 150000.0);
  auto south = layer("ease2_south_6932", 3, 6932, 30, 30, -3.0e6, 3.0e6, 2.0e5);
  // EPSG:3035 from (5 E, 68 N) on: Scandinavia, 1,200 km square.
  auto laea = layer("laea_europe_3035", 4, 3035, 24, 24, 4.0e6, 5.0e6, 50000.0);
  std::vector<vtkGlobeLayer*> layers = { cea, lambert93, albers, south, laea };
  for (vtkGlobeLayer* l : layers)
  {
    l->SetFeatherWidth(0.0);
    l->SetInterpolationToNearest();
    scene.Mapper->AddLayer(l);
  }
  const std::vector<ViewPoint> views = { { { 2.0, 38.0, 2.5e6 }, { 2.5, 46.5, 0.0 } },
    { { -98.0, 25.0, 5.0e6 }, { -98.0, 39.0, 0.0 } }, { { 20.0, -55.0, 4.0e6 }, { 0.0, -80.0, 0.0 } },
    { { 179.0, 10.0, 8.0e6 }, { 179.0, 20.0, 0.0 } }, { { 15.0, 52.0, 2.5e6 }, { 15.0, 62.0, 0.0 } } };
  int checked = 0;
  std::vector<int> perLayer;
  const int wrong = WrongTexels(scene, layers, views, checked, perLayer);
  char what[240];
  std::snprintf(what, sizeof(what),
    "%d pixels (EPSG:6933 %d, 2154 %d, 5070 %d, 6932 %d, 3035 %d): %d show another texel than "
    "the exact projection's; %d active projected layers%s", checked, perLayer[0], perLayer[1],
    perLayer[2], perLayer[3], perLayer[4], wrong,
    scene.Mapper->GetLayerSet()->GetNumberOfActiveColorLayers(),
    lambert93->IsStreamed() ? ", streamed" : "");
  Check.Expect(perLayer[0] > 2000 && perLayer[1] > 2000 && perLayer[2] > 2000 &&
      perLayer[3] > 2000 && perLayer[4] > 2000 && wrong == 0 &&
      lambert93->GetReprojectedFromEPSG() == 0 && laea->GetReprojectedFromEPSG() == 0 &&
      lambert93->IsStreamed() == vtkGlobeTest::Streamed() &&
      scene.Mapper->GetLayerSet()->GetNumberOfActiveColorLayers() == 5,
    what);
}

// A CRS without an EPSG code: MODIS's sinusoidal grid (its PROJ string, as the reader keeps a
// GeoTIFF's user-defined keys), whole map, over the antimeridian (the map's cut) and a pole.
void PartSinusoidal()
{
  std::printf("F. MODIS sinusoidal, a CRS without an EPSG code (nearest-filtered texels):\n");
  vtkGlobeTest::Scene scene;
  scene.Mapper->LightingOff();
  const double R = 6371007.181, pi = 3.14159265358979323846;
  // 72 x 36 square texels over the whole map (x +-pi R, y +-pi R / 2); those outside the
  // sinusoids at +-180 degrees are never shown.
  const char* crs = "+proj=sinu +lon_0=0 +x_0=0 +y_0=0 +R=6371007.181 +units=m +no_defs +type=crs";
  const auto colour = [](int i, int j) { return vtkGlobeTest::TexelColour(0, i, j); };
  // In the Streamed. variant: a PNG with a world file and the PROJ string as its .prj, paged.
  vtkSmartPointer<vtkGlobeLayer> modis;
  if (vtkGlobeTest::Streamed())
  {
    modis = vtkSmartPointer<vtkGlobeLayer>::New();
    modis->SetFileName(vtkGlobeTest::WriteWorldFilePNG(std::string(VTKGLOBE_TEMP_DIR) + "/modis_sinusoidal",
      0, 72, 36, -pi * R, 0.5 * pi * R, 2.0 * pi * R / 72.0, colour, crs)
                         .c_str());
    modis->SetRoleToColor();
    modis->SetStreamingToOn();
    modis->SetFeatherWidth(0.0);
    modis->SetInterpolationToNearest();
  }
  else
  {
    modis = vtkGlobeTest::ProjectedImage(0, 72, 36, -pi * R, 0.5 * pi * R, 2.0 * pi * R / 72.0, colour, crs);
  }
  scene.Mapper->AddLayer(modis);
  const std::vector<ViewPoint> views = { { { 0.0, 20.0, 8.0e6 }, { 0.0, 30.0, 0.0 } },
    { { 177.0, 14.0, 3.0e6 }, { 179.8, 20.0, 0.0 } }, { { 0.0, 84.0, 2.0e6 }, { 0.0, 90.0, 0.0 } },
    { { -100.0, -50.0, 5.0e6 }, { -120.0, -70.0, 0.0 } } };
  int checked = 0;
  std::vector<int> perLayer;
  const int wrong = WrongTexels(scene, { modis }, views, checked, perLayer);
  char what[240];
  std::snprintf(what, sizeof(what),
    "%d pixels: %d show another texel than the exact projection's; EPSG %d, %d active layer(s)",
    checked, wrong, modis->GetEPSG(), scene.Mapper->GetLayerSet()->GetNumberOfActiveColorLayers());
  Check.Expect(checked > 20000 && wrong == 0 && modis->GetEPSG() == 0 && !modis->IsReprojected() &&
      modis->IsStreamed() == vtkGlobeTest::Streamed() &&
      scene.Mapper->GetLayerSet()->GetNumberOfActiveColorLayers() == 1,
    std::string(what) + (modis->IsStreamed() ? ", streamed" : ""));
}

void PartQualityWeight()
{
  std::printf("D. Kooima's projection-quality weight (two layers averaged, lighting off):\n");
  vtkGlobeTest::Scene scene;
  scene.Mapper->LightingOff();
  auto equirect = vtkSmartPointer<vtkGlobeLayer>::New();
  std::vector<unsigned char> red;
  for (int i = 0; i < 36 * 18; ++i)
  {
    red.insert(red.end(), { 255, 0, 0 });
  }
  equirect->SetColorData(36, 18, 3, red.data(), -180, 180, -90, 90);
  auto polar = vtkGlobeTest::ProjectedImage(3413, 8, 8, -4.0e6, 4.0e6, 1.0e6,
    [](int, int) { return std::array<unsigned char, 3>{ 0, 0, 255 }; });
  for (vtkGlobeLayer* l : { equirect.Get(), polar.Get() })
  {
    l->SetBlendModeToAverage();
    l->ProjectionQualityWeightOn();
    l->SetFeatherWidth(0.0);
    scene.Mapper->AddLayer(l);
  }
  // A global 2:1 equirectangular raster has texel aspect k = 1 / cos(lat): weight
  // 1 - ln(1/cos lat) / ln 8 (exactly 2/3 at 60 N, 0 above ~82.8 N); polar stereographic is
  // conformal (k = 1, weight 1). The average is (w_e red + w_p blue) / (w_e + w_p).
  for (double lat : { 30.0, 60.0, 85.0 })
  {
    const double we = std::max(0.0, 1.0 - std::log(1.0 / std::cos(lat * vtkMath::Pi() / 180.0)) / std::log(8.0));
    // Outside the polar raster (30 N) only the equirectangular weight counts, and the average
    // replaces the base colour by min(sum of weights, 1).
    const double wp = lat > 50.0 ? 1.0 : 0.0, sum = we + wp;
    const double average[3] = { we / sum, 0.0, wp / sum };
    const double* base = scene.Mapper->GetCompositePass()->GetBaseColor();
    double expected[3];
    for (int k = 0; k < 3; ++k)
    {
      expected[k] = base[k] + (average[k] - base[k]) * std::min(sum, 1.0);
    }
    const double camera[3] = { -45.0, lat - 0.5, 50000.0 }, target[3] = { -45.0, lat, 0.0 };
    scene.Look(camera, target, 10.0, 1000.0, 1.0e6);
    scene.Render();
    const int* size = scene.Window->GetSize();
    unsigned char* pixel = scene.Window->GetPixelData(size[0] / 2, size[1] / 2, size[0] / 2, size[1] / 2, 0);
    double worst = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      worst = std::max(worst, std::abs(pixel[k] / 255.0 - expected[k]));
    }
    char what[200];
    std::snprintf(what, sizeof(what), "at %2.0f N: (%.3f %.3f %.3f), expected (%.3f %.3f %.3f)", lat,
      pixel[0] / 255.0, pixel[1] / 255.0, pixel[2] / 255.0, expected[0], expected[1], expected[2]);
    delete[] pixel;
    Check.Expect(worst < 0.01, what);
  }
}
} // namespace

int TestGlobeProjectedLayers(int argc, char* argv[])
{
  PartRainier();
  bool image = true;
  PartPolarCap(argc, argv, image);
  PartSynthetic();
  PartConicsAndEqualArea();
  PartSinusoidal();
  PartQualityWeight();
  return Check.Result() == 0 && image ? 0 : 1;
}
