// The New York and Boston imagery insets (0.00023 and 0.0018 deg/px, 760x and 95x finer than
// the global base) composed over the Blue Marble, with and without feathering, lit off so the
// framebuffer holds the composed albedo. Numeric: inside each inset (away from its feathered
// border) every pixel is the inset's own colour, sampled on the CPU at the pixel's
// depth-reconstructed position (registration) and filtered to its footprint (the level OpenGL
// takes from the neighbouring pixels' positions, trilinear in the layer's own pyramid). The feather ramp itself is checked exactly on
// an analytic layer in TestGlobeComposition. Regression baselines: the Boston view feathered
// (argument -feather) and hard-edged.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkRegressionTestImage.h"

#include <cstdio>

int TestGlobeInsets(int argc, char* argv[])
{
  vtkGlobeTest::Checklist check;
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
    const std::vector<unsigned char> pixels = vtkGlobeTest::ReadPixels(scene.Window);
    const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
    const auto llhs = vtkGlobeTest::GeodeticPixels(scene);
    double e[4];
    inset.Layer->GetGeographicExtent(e);
    const double texel = (e[1] - e[0]) / inset.Layer->GetNumberOfColumns();
    int inside = 0, wrong = 0;
    double maxLod = 0.0;
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
        double p[3], llh[3];
        vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, depth[i], p);
        scene.Body->CartesianToGeodetic(p, llh);
        // Well inside: beyond the feather and a few texels of margin for the mesh's placement.
        const double margin = 12.0 * texel;
        if (llh[0] < e[0] + margin || llh[0] > e[1] - margin || llh[1] < e[2] + margin ||
          llh[1] > e[3] - margin)
        {
          continue;
        }
        // The level the GPU filters to, from the pixel's footprint.
        double footprint[4];
        vtkGlobeTest::PixelFootprint(size, llhs, x, y, footprint);
        const double lod = vtkGlobeTest::PixelLod(inset.Layer, llh, footprint);
        maxLod = std::max(maxLod, lod);
        ++inside;
        double d = 0.0;
        for (int k = 0; k < 3; ++k)
        {
          double value = 0.0;
          vtkGlobeTest::SampleLayer(inset.Layer, llh[0], llh[1], k, value, lod);
          d = std::max(d, std::abs(pixels[3 * i + k] - value) / 255.0);
        }
        sum += d;
        wrong += d > 0.1;
      }
    }
    char what[200];
    std::snprintf(what, sizeof(what),
      "%s: %d pixels inside, mean |rendered - inset| %.4f, %d off by more than 0.1 (the inset "
      "filtered to each pixel's footprint, levels 0 to %.1f)", inset.Name,
      inside, inside ? sum / inside : 0.0, wrong, maxLod);
    check.Expect(inside > 2000 && sum / inside < 0.01 && wrong == 0, what);
  }

  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  return (check.Result() == 0 && image == vtkTesting::PASSED) ? 0 : 1;
}
