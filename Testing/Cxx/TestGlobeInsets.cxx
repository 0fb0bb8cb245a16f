// The New York and Boston imagery insets (0.00023 and 0.0018 deg/px, 760x and 95x finer than
// the global base) composed over the Blue Marble, with and without feathering, lit off so the
// framebuffer holds the composed albedo. Numeric: inside each inset (away from its feathered
// border) every pixel is the inset's own colour, sampled on the CPU at the pixel's
// depth-reconstructed position (registration). The feather ramp itself is checked exactly on
// an analytic layer in TestGlobeComposition. Regression baselines: the Boston view feathered
// (argument -feather) and hard-edged.
#include "vtkGlobeRenderingTestHelpers.h"

#include "vtkRegressionTestImage.h"
#include "vtkUnsignedCharArray.h"

#include <cstdio>

namespace
{
// The colour layer's RGBA as the GPU samples level 0: bilinear between texel centres.
bool SampleColor(vtkGlobeLayer* layer, double lon, double lat, double rgb[3])
{
  double u, v;
  if (!vtkGlobeTest::LayerUV(layer, lon, lat, u, v) || u < 0 || u > 1 || v < 0 || v > 1)
  {
    return false;
  }
  const int w = layer->GetWidth(), h = layer->GetHeight();
  vtkDataArray* data = layer->GetData();
  auto at = [&](int i, int j, int k) {
    i = std::max(0, std::min(i, w - 1));
    j = std::max(0, std::min(j, h - 1));
    return data->GetComponent(static_cast<vtkIdType>(j) * w + i, k);
  };
  const double x = u * w - 0.5, y = v * h - 0.5;
  const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
  const double fx = x - i, fy = y - j;
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = ((1 - fy) * ((1 - fx) * at(i, j, k) + fx * at(i + 1, j, k)) +
               fy * ((1 - fx) * at(i, j + 1, k) + fx * at(i + 1, j + 1, k))) /
      255.0;
  }
  return true;
}
}

int TestGlobeInsets(int argc, char* argv[])
{
  bool ok = true;
  auto expect = [&ok](bool condition, const std::string& what) {
    std::printf("  %-4s %s\n", condition ? "ok" : "FAIL", what.c_str());
    ok &= condition;
  };
  bool feather = false;
  for (int i = 1; i < argc; ++i)
  {
    feather |= std::string(argv[i]) == "-feather";
  }
  vtkGlobeTest::Scene scene(300, 225, 256);
  scene.Mapper->LightingOff();
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/world.tif", false));
  auto nyc = vtkGlobeTest::FileLayer("earth/nyc-inset-wgs84.tif", false);
  auto boston = vtkGlobeTest::FileLayer("earth/boston-inset-wgs84.tif", false);
  scene.Mapper->AddLayer(nyc);
  scene.Mapper->AddLayer(boston);
  for (vtkGlobeLayer* l : { nyc.Get(), boston.Get() })
  {
    l->SetFeatherWidth(feather ? 8.0 : 0.0);
  }
  std::printf("%s borders\n", feather ? "Feathered (8 texels)" : "Hard");

  struct Inset
  {
    vtkGlobeLayer* Layer;
    const char* Name;
    double Camera[3], Target[3];
  };
  // Each view frames its inset with some of the base around it.
  const Inset insets[] = { { nyc, "New York", { -73.95, 40.55, 30000.0 }, { -73.99, 40.72, 0.0 } },
    { boston, "Boston", { -71.02, 41.90, 140000.0 }, { -71.07, 42.33, 0.0 } } };
  for (const Inset& inset : insets)
  {
    scene.Look(inset.Camera, inset.Target, 40.0, 1000.0, 1.0e6);
    scene.Render();
    const int* size = scene.Window->GetSize();
    unsigned char* pixels = scene.Window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0);
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    double e[4];
    inset.Layer->GetGeographicExtent(e);
    const double texel = (e[1] - e[0]) / inset.Layer->GetWidth();
    int inside = 0, wrong = 0;
    double sum = 0.0;
    for (int y = 0; y < size[1]; y += 2)
    {
      for (int x = 0; x < size[0]; x += 2)
      {
        const size_t i = static_cast<size_t>(y) * size[0] + x;
        if (depth[i] >= 1.0f)
        {
          continue;
        }
        double p[3], llh[3], rgb[3];
        vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, depth[i], p);
        scene.Body->CartesianToGeodetic(p, llh);
        // Well inside: beyond the feather and a few texels of margin for the mesh's placement.
        const double margin = 12.0 * texel;
        if (llh[0] < e[0] + margin || llh[0] > e[1] - margin || llh[1] < e[2] + margin ||
          llh[1] > e[3] - margin || !SampleColor(inset.Layer, llh[0], llh[1], rgb))
        {
          continue;
        }
        ++inside;
        double d = 0.0;
        for (int k = 0; k < 3; ++k)
        {
          d = std::max(d, std::abs(pixels[3 * i + k] / 255.0 - rgb[k]));
        }
        sum += d;
        wrong += d > 0.1;
      }
    }
    delete[] pixels;
    char what[200];
    std::snprintf(what, sizeof(what),
      "%s: %d pixels inside, mean |rendered - inset| %.4f, %d off by more than 0.1", inset.Name,
      inside, inside ? sum / inside : 0.0, wrong);
    expect(inside > 2000 && sum / inside < 0.01 && wrong == 0, what);
  }

  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  std::printf("%s\n", ok ? "numeric checks passed" : "numeric checks FAILED");
  return (ok && image == vtkTesting::PASSED) ? 0 : 1;
}
