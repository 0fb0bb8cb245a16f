// Effects are generated only when asked for, and cost nothing otherwise:
//  - the composition shader of a scene without atmosphere, lines, night lights or water has
//    none of their code;
//  - changing a uniform-only setting (ambient, opacity, gamma, feather, valid range, filtering,
//    an effect's parameter, the light's colour) rebuilds no program and re-uploads no texture;
//  - switching an effect on rebuilds the composition program once, and its code appears.
// Each effect is then checked on the image: the atmosphere's sky lies inside the shell's
// silhouette (1.025 R) and not beyond; graticule pixels lie on 10-degree lines; contour pixels
// lie on 1,000 m contours of the composed heights; night lights brighten only the night side
// where the layer is bright; specular water brightens only masked (ocean) pixels. The final
// image (every effect on) is a regression baseline.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeCompositePass.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeLayerSet.h"
#include "vtkLight.h"
#include "vtkRegressionTestImage.h"

#include <cstdio>
#include <functional>

namespace
{
// The GPU's fwidth of a per-pixel quantity, as a 2x2-quad rasterizer computes it: the largest
// difference across the pixel's quad along x plus along y. `value` gives NaN off the globe;
// `difference` maps a difference (e.g. wraps longitude).
double QuadWidth(int x, int y, const std::function<double(int, int)>& value,
  const std::function<double(double)>& difference)
{
  const int qx = x & ~1, qy = y & ~1;
  double dx = 0.0, dy = 0.0;
  for (int k = 0; k < 2; ++k)
  {
    dx = std::max(dx, std::abs(difference(value(qx + 1, qy + k) - value(qx, qy + k))));
    dy = std::max(dy, std::abs(difference(value(qx + k, qy + 1) - value(qx + k, qy))));
  }
  return dx + dy;
}

} // namespace

int TestGlobeEffects(int argc, char* argv[])
{
  vtkGlobeTest::Checklist check;
  char what[200];

  vtkGlobeTest::Scene scene(300, 225, 256);
  scene.AddEarthLayers(true, false);
  auto world = vtkGlobeTest::FileLayer("earth/world.tif", false);
  scene.Mapper->AddLayer(world);
  // The sun over 20 N, 10 E: the night side is in view from the west.
  double sunPosition[3];
  vtkLight* sun = vtkGlobeTest::AddSunOver(scene, 10.0, 20.0, sunPosition);
  const double camera[3] = { -40.0, 25.0, 2.2e7 }, target[3] = { -40.0, 25.0, 0.0 };
  scene.Look(camera, target, 30.0);
  scene.Render();

  vtkGlobeCompositePass* composite = scene.Mapper->GetCompositePass();
  vtkGlobeGridPass* grid = scene.Mapper->GetGridPass();
  vtkGlobeLayerSet* layers = scene.Mapper->GetLayerSet();
  auto lacks = [&](const char* code) {
    return composite->GetFragmentShaderSource().find(code) == std::string::npos;
  };
  check.Expect(lacks("globe_atm") && lacks("globe_lineCoverage") && lacks("globe_composeNightLights") &&
      lacks("globe_composeMask") && lacks("globeSpecular.x"),
    "no atmosphere, line, night-light or water code without those effects");
  const std::vector<unsigned char> plain = vtkGlobeTest::ReadPixels(scene.Window);
  const auto llh = vtkGlobeTest::GeodeticPixels(scene);

  // Uniform-only changes: nothing rebuilt, nothing re-uploaded.
  const int compositeBuilds = composite->GetNumberOfShaderBuilds();
  const int gridBuilds = grid->GetNumberOfShaderBuilds();
  const int uploads = layers->GetNumberOfUploads();
  scene.Mapper->SetAmbient(0.25);
  world->SetOpacity(0.9);
  world->SetGamma(1.1);
  world->SetFeatherWidth(4.0);
  world->SetInterpolationToNearest();
  scene.Mapper->GetLayer(0)->SetValidRange(-12000.0, 9000.0);
  composite->SetGraticuleSpacing(15.0);
  composite->SetAtmosphereIntensity(18.0);
  sun->SetColor(1.0, 0.95, 0.9);
  scene.Render();
  std::snprintf(what, sizeof(what),
    "uniform-only changes: programs built %d -> %d (grid %d -> %d), uploads %d -> %d",
    compositeBuilds, composite->GetNumberOfShaderBuilds(), gridBuilds,
    grid->GetNumberOfShaderBuilds(), uploads, layers->GetNumberOfUploads());
  check.Expect(composite->GetNumberOfShaderBuilds() == compositeBuilds &&
      grid->GetNumberOfShaderBuilds() == gridBuilds && layers->GetNumberOfUploads() == uploads,
    what);
  scene.Mapper->SetAmbient(0.15);
  world->SetOpacity(1.0);
  world->SetGamma(1.0);
  world->SetFeatherWidth(8.0);
  world->SetInterpolationToLinear();
  composite->SetGraticuleSpacing(10.0);
  sun->SetColor(1.0, 1.0, 1.0);

  const int* size = scene.Window->GetSize();
  const int n = size[0] * size[1];
  const double R = scene.Body->GetMaximumRadius();

  // Atmosphere: one rebuild; sky pixels only inside the shell's silhouette.
  scene.Mapper->AtmosphereOn();
  scene.Render();
  check.Expect(composite->GetNumberOfShaderBuilds() == compositeBuilds + 1 && !lacks("globe_atmosphere"),
    "atmosphere on: one rebuild, its code present");
  {
    const std::vector<unsigned char> sky = vtkGlobeTest::ReadPixels(scene.Window);
    int skyPixels = 0, outside = 0, hazed = 0;
    double eye[3];
    scene.Renderer->GetActiveCamera()->GetPosition(eye);
    for (int y = 0; y < size[1]; ++y)
    {
      for (int x = 0; x < size[0]; ++x)
      {
        const size_t i = static_cast<size_t>(y) * size[0] + x;
        if (std::isnan(llh[i][0]))
        {
          if (sky[3 * i] + sky[3 * i + 1] + sky[3 * i + 2] > 6)
          {
            ++skyPixels;
            // Closest approach of the pixel's ray to the centre (double).
            double ray[3];
            vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
            const double t = -(eye[0] * ray[0] + eye[1] * ray[1] + eye[2] * ray[2]);
            double c[3] = { eye[0] + t * ray[0], eye[1] + t * ray[1], eye[2] + t * ray[2] };
            // One pixel at the limb is ~ 12 km from here: allow it.
            outside += std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) > 1.025 * R + 15000.0;
          }
        }
        else
        {
          hazed += sky[3 * i + 2] != plain[3 * i + 2];
        }
      }
    }
    std::snprintf(what, sizeof(what),
      "atmosphere: %d sky pixels, %d beyond the 1.025 R shell; %d terrain pixels hazed", skyPixels,
      outside, hazed);
    check.Expect(skyPixels > 300 && outside == 0 && hazed > 1000, what);
  }
  scene.Mapper->AtmosphereOff();

  // Graticule: changed pixels lie on 10-degree lines: within the line's half width plus the
  // antialiasing pixel (1.25 px), in units of the pixel's own change of longitude/latitude.
  scene.Mapper->GraticuleOn();
  scene.Render();
  check.Expect(!lacks("globe_lineCoverage"), "graticule on: its code present");
  auto at = [&](int x, int y, int c) {
    if (x < 0 || y < 0 || x >= size[0] || y >= size[1])
    {
      return static_cast<double>(NAN);
    }
    return llh[static_cast<size_t>(y) * size[0] + x][c];
  };
  auto plainDiff = [](double d) { return d; };
  auto wrapDiff = [](double d) { return d - 360.0 * std::round(d / 360.0); };
  auto interior = [&](int x, int y) {
    for (int dy = -2; dy <= 2; ++dy)
    {
      for (int dx = -2; dx <= 2; ++dx)
      {
        if (std::isnan(at(x + dx, y + dy, 0)))
        {
          return false;
        }
      }
    }
    return true;
  };
  {
    const std::vector<unsigned char> lines = vtkGlobeTest::ReadPixels(scene.Window);
    int changed = 0, off = 0;
    for (int y = 0; y < size[1]; ++y)
    {
      for (int x = 0; x < size[0]; ++x)
      {
        const size_t i = static_cast<size_t>(y) * size[0] + x;
        if (!interior(x, y) ||
          std::abs(lines[3 * i] - plain[3 * i]) + std::abs(lines[3 * i + 1] - plain[3 * i + 1]) < 24)
        {
          continue;
        }
        ++changed;
        auto toLine = [](double v) { return std::abs(v / 10.0 - std::round(v / 10.0)) * 10.0; };
        const double wLon =
          QuadWidth(x, y, [&](int u, int v) { return at(u, v, 0); }, wrapDiff);
        const double wLat =
          QuadWidth(x, y, [&](int u, int v) { return at(u, v, 1); }, plainDiff);
        const bool on = toLine(llh[i][0]) <= 1.5 * wLon || toLine(llh[i][1]) <= 1.5 * wLat;
        off += !on;
      }
    }
    std::snprintf(what, sizeof(what), "graticule: %d pixels drawn, %d of them off the lines", changed, off);
    check.Expect(changed > 500 && off == 0, what);
  }
  scene.Mapper->GraticuleOff();

  // Contours every 1,000 m of the composed heights (the C++ mirror at each pixel's position,
  // filtered to the pixel's footprint).
  composite->SetContourInterval(1000.0);
  scene.Mapper->ContoursOn();
  scene.Render();
  {
    const std::vector<unsigned char> lines = vtkGlobeTest::ReadPixels(scene.Window);
    const std::vector<vtkGlobeLayer*> all = vtkGlobeTest::HeightLayers(scene.Mapper);
    // Contours come from the heights the screen pass filters to each pixel's footprint.
    const std::vector<double> heights = vtkGlobeTest::PixelHeights(scene, all, llh);
    auto h = [&](int x, int y) {
      return (x < 0 || y < 0 || x >= size[0] || y >= size[1])
        ? static_cast<double>(NAN)
        : heights[static_cast<size_t>(y) * size[0] + x];
    };
    int changed = 0, off = 0;
    for (int y = 0; y < size[1]; ++y)
    {
      for (int x = 0; x < size[0]; ++x)
      {
        const size_t i = static_cast<size_t>(y) * size[0] + x;
        if (!interior(x, y) ||
          std::abs(lines[3 * i] - plain[3 * i]) + std::abs(lines[3 * i + 1] - plain[3 * i + 1]) +
              std::abs(lines[3 * i + 2] - plain[3 * i + 2]) < 30)
        {
          continue;
        }
        ++changed;
        const double toLine = std::abs(heights[i] / 1000.0 - std::round(heights[i] / 1000.0)) * 1000.0;
        const double width = QuadWidth(x, y, h, plainDiff);
        const bool on = toLine <= 1.5 * width + 1.0;
        off += !on;
      }
    }
    std::snprintf(what, sizeof(what), "contours: %d pixels drawn, %d of them off the 1 km contours", changed, off);
    check.Expect(changed > 300 && off == 0, what);
  }
  scene.Mapper->ContoursOff();

  // Night lights and specular water need their layers; they appear once the layers do.
  vtkGlobeTest::AddWaterMaskAndNightLights(scene.Mapper, scene.Mapper->GetLayer(0));
  scene.Mapper->NightLightsOff();
  scene.Mapper->SpecularWaterOff();
  scene.Render();
  check.Expect(lacks("globe_composeNightLights") && lacks("globeSpecular.x"),
    "layers present, effects off: no night-light or water code");
  const std::vector<unsigned char> dark = vtkGlobeTest::ReadPixels(scene.Window);
  scene.Mapper->NightLightsOn();
  scene.Render();
  {
    const std::vector<unsigned char> lit = vtkGlobeTest::ReadPixels(scene.Window);
    int brighter = 0, wrong = 0;
    vtkMath::Normalize(sunPosition);
    for (int i = 0; i < n; ++i)
    {
      if (std::isnan(llh[i][0]) || lit[3 * i] == dark[3 * i])
      {
        continue;
      }
      double e[3], nn[3], up[3];
      scene.Body->ComputeEastNorthUp(llh[i][0], llh[i][1], e, nn, up);
      ++brighter;
      wrong += vtkMath::Dot(up, sunPosition) > 0.11 || lit[3 * i] < dark[3 * i];
    }
    std::snprintf(what, sizeof(what), "night lights: %d pixels brighter, %d of them in daylight", brighter, wrong);
    check.Expect(!lacks("globe_composeNightLights") && brighter > 50 && wrong == 0, what);
  }
  const std::vector<unsigned char> night = vtkGlobeTest::ReadPixels(scene.Window);
  scene.Mapper->SpecularWaterOn();
  scene.Render();
  {
    const std::vector<unsigned char> shiny = vtkGlobeTest::ReadPixels(scene.Window);
    vtkGlobeLayer* relief = scene.Mapper->GetLayer(0);
    int brighter = 0, land = 0;
    for (int i = 0; i < n; ++i)
    {
      if (std::isnan(llh[i][0]) || shiny[3 * i + 2] <= night[3 * i + 2] + 8)
      {
        continue;
      }
      ++brighter;
      double z;
      // Land well inside a 2-degree cell of land (all four neighbours above sea level).
      bool dry = true;
      for (double dx : { -2.0, 2.0 })
      {
        for (double dy : { -2.0, 2.0 })
        {
          dry &= vtkGlobeTest::SampleHeight(relief, llh[i][0] + dx, llh[i][1] + dy, z) && z > 0.0;
        }
      }
      land += dry;
    }
    std::snprintf(what, sizeof(what), "specular water: %d pixels brighter, %d of them on dry land", brighter, land);
    check.Expect(!lacks("globeSpecular.x") && brighter > 100 && land == 0, what);
  }

  // Everything on: the baseline.
  scene.Mapper->AtmosphereOn();
  scene.Mapper->GraticuleOn();
  composite->SetGraticuleSpacing(30.0);
  scene.Render();
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  return (check.Result() == 0 && image == vtkTesting::PASSED) ? 0 : 1;
}
