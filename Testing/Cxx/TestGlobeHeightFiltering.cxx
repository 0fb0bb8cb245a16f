// Heights are filtered with float weights (globe_heightLod, Documentation/composition.md "Exact
// height filtering"): the grid pass's heights, read back from the GPU, equal the CPU's trilinear
// filtering of the same pyramid (vtkGlobeTerrain::GetFilteredHeight, the grid's footprint rule)
// at the (lon, lat) the GPU sampled, to float rounding. The layer's texels are independent
// random heights of 0 to 1000 m, so a texture unit's 8-bit weights would be off by up to 2 m,
// magnified (level 0, where the grid is finer than the texels) from 20 and 150 km above it and
// in an oblique view across it. Coarser levels are not compared here: the CPU mirror follows
// the GPU's level to a few hundredths only, which moves trilinear values by decimetres;
// TestGlobeInsetWalls and TestGlobeProjectedLayers read them (they failed by hundreds of
// metres when the level sizes were wrong).
#include "vtkGlobeClippingRange.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include <array>
#include <cmath>
#include <cstdio>

int TestGlobeHeightFiltering(int, char*[])
{
  vtkGlobeTest::Scene scene(200, 150, 128);
  constexpr int n = 64;
  constexpr double west = 10.0, south = 30.0, span = 0.5;
  std::vector<float> heights(n * n);
  unsigned int state = 12345u;
  for (float& h : heights)
  {
    state = state * 1664525u + 1013904223u; // a fixed sequence: the same layer every run
    h = static_cast<float>((state >> 8) % 1001u);
  }
  vtkNew<vtkGlobeLayer> layer;
  layer->SetHeightData(n, n, heights.data(), west, west + span, south, south + span);
  scene.Mapper->AddLayer(layer);
  // The globe's clipping range (VTK's own would put the near plane beyond the terrain here).
  vtkGlobeClippingRange::Install(scene.Renderer);
  const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
  vtkGlobeEllipsoid* body = scene.Body;
  const double* radii = body->GetRadii();
  const double texel = span / n * 111320.0 * std::cos(vtkMath::RadiansFromDegrees(south));

  struct View
  {
    const char* Name;
    double Camera[3], Target[3];
  };
  const double c[2] = { west + 0.5 * span, south + 0.5 * span };
  const View views[] = { { "magnified, 20 km above", { c[0], c[1], 2e4 }, { c[0], c[1], 0 } },
    { "magnified, 150 km above", { c[0], c[1], 1.5e5 }, { c[0], c[1], 0 } },
    { "oblique from 3 km, 20 km south", { c[0], c[1] - 0.18, 3e3 }, { c[0], c[1], 0 } } };
  bool ok = true;
  // Automatic must be exact wherever it runs (it filters in the shader unless the texture unit
  // is exact); Shader always is.
  for (int mode :
    { vtkGlobeLayerSet::HeightFilteringAutomatic, vtkGlobeLayerSet::HeightFilteringShader })
  {
    scene.Mapper->GetLayerSet()->SetHeightFiltering(mode);
    for (const View& v : views)
    {
      vtkGlobeTest::LookAt(scene.Renderer, body, v.Camera, v.Target, 30.0);
      scene.Renderer->ResetCameraClippingRange();
      scene.Render();
      scene.Render();
      vtkGlobeGridPass* pass = scene.Mapper->GetGridPass();
      vtkGlobeProjectiveGrid* grid = scene.Mapper->GetProjectiveGrid();
      const int g = pass->GetResolution();
      const std::vector<float> direction = vtkGlobeTest::ReadTexture(pass->GetDirectionTexture());
      const std::vector<float> position = vtkGlobeTest::ReadTexture(pass->GetPositionTexture());
      const std::vector<float> height = vtkGlobeTest::ReadTexture(pass->GetHeightTexture());
      const double* eye = grid->GetEyeScaled();
      const int comps = static_cast<int>(height.size() / (static_cast<size_t>(g) * g));

      // Where the GPU sampled: its own float grid points (eye-relative, scaled space).
      std::vector<std::array<double, 3>> llh(static_cast<size_t>(g) * g);
      std::vector<char> hit(llh.size(), 0);
      for (size_t k = 0; k < llh.size(); ++k)
      {
        if (!(direction[4 * k + 3] > 0.5f))
        {
          continue;
        }
        double s[3];
        for (int i = 0; i < 3; ++i)
        {
          s[i] = eye[i] + position[4 * k + i];
        }
        const double norm = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
        double surface[3];
        for (int i = 0; i < 3; ++i)
        {
          surface[i] = s[i] / norm * radii[i];
        }
        body->CartesianToGeodeticQuiet(surface, llh[k].data());
        hit[k] = 1;
      }
      vtkGlobeTest::Worst error("GPU height vs float-weight trilinear / bound", "");
      double largest = 0.0;
      int inside = 0;
      for (int j = 0; j < g; ++j)
      {
        for (int i = 0; i < g; ++i)
        {
          const size_t k = static_cast<size_t>(j) * g + i;
          const double* p = llh[k].data();
          if (!hit[k] || p[0] < west + 0.01 || p[0] > west + span - 0.01 || p[1] < south + 0.01 ||
            p[1] > south + span - 0.01)
          {
            continue; // off the layer, or in its skirt
          }
          ++inside;
          double footprint[4];
          // The grid's footprint (vtkGlobeGridHeightFS): the step to the nearer neighbour per axis.
          vtkGlobeTest::GridShorterStep(llh, hit, g, i, j, 1, 0, 1e30, footprint);
          vtkGlobeTest::GridShorterStep(llh, hit, g, i, j, 0, 1, 1e30, footprint + 2);
          const double expected = vtkGlobeTest::ComposedHeight(layers, p[0], p[1], footprint);
          // Float rounding of the value (1000 m), of where it is sampled (0.1 mm + 3e-7 of the
          // distance from the frame's local origin below the eye, TestGlobeGeodeticPrecision,
          // and the layer's float texture coordinates) times the steepest texel step
          // (1000 m / texel).
          const double below[3] = { v.Camera[0], v.Camera[1], 0.0 };
          double centre[3];
          body->GeodeticToCartesianQuiet(below, centre);
          double here[3];
          const double ground[3] = { p[0], p[1], 0.0 };
          body->GeodeticToCartesianQuiet(ground, here);
          const double away = std::sqrt(vtkMath::Distance2BetweenPoints(centre, here));
          const double where = 1e-4 + 3e-7 * away + 3.0 / 16777216.0 * span * 111320.0;
          const double bound = 1e-3 + 1000.0 / texel * where;
          error.Add(std::abs(height[comps * k] - expected) / bound,
            vtkGlobeTest::Format("grid point (%g, %g), |dh| %.4g m", i, j,
              std::abs(height[comps * k] - expected)));
          largest = std::max(largest, bound);
        }
      }
      vtkGlobeLayerSet* set = scene.Mapper->GetLayerSet();
      std::printf("%s, %s (texture unit exact: %d, heights filtered in the shader: %d): %d of %d "
                  "grid points on the layer (texel %.0f m); the bound's largest %.3f m (8-bit "
                  "weights: up to %.2f m)\n",
        mode == vtkGlobeLayerSet::HeightFilteringShader ? "shader" : "automatic", v.Name,
        set->GetTextureUnitFiltersExactly(), set->GetFiltersHeightsInShader() ? 1 : 0, inside,
        g * g, texel, largest, 1000.0 / 512.0);
      ok &= inside > 200;
      ok &= error.Check(1.0);
      ok &= set->GetTextureUnitFiltersExactly() >= 0;
    }
  }
  std::printf("%s\n", ok ? "heights filtered exactly" : "FAILED");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
