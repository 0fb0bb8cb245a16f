// Per-pixel terrain refinement (vtkGlobeMapper::SetTerrainRefinement, issue 18): the drawn
// surface's height against the data, pixel by pixel, without and with refinement.
//
// Every covered pixel (stride 2) is reconstructed from the depth buffer in double, and its
// geodetic height is compared with the heights composed on the CPU at its (lon, lat)
// (vtkGlobeTest::ComposedHeight, the layers at full resolution). Scenes:
//  A. Oblique over Rainier from 5 km above the ground, grid 128: distant terrain is where the
//     mesh's cells are kilometres long and the rasterized surface cuts through the relief.
//  B. The whole Earth from 22,000 km, grid 64: the sag of flat triangles on the curved body
//     puts the surface tens of metres low.
//  C. Nadir over Rainier from 12 km with logarithmic depth: the refined depth is written in
//     the scene's depth mode.
//  D. C in perspective depth without high-precision geodetic coordinates: the refinement is
//     off there (float unit directions carry 0.4 m of noise), picture and depth unchanged.
//  E. 2 m above the ground west of Rainier looking up at the summit: rays that climb meet the
//     slopes they see from below, where a step for level terrain would go the wrong way.
// Requirement: refinement divides the median and the 95th percentile of |dh| by at least 4 and
// 2 in A and E (the rest is visibility: the ray's first hit lies behind a ridge the mesh does
// not have, or the mesh has one the data do not), by 50 in B and C; with refinement the error no
// longer grows with the grid's cells (A at grid 64 within 2x of grid 256). The layers are
// read at full resolution (footprint filtering off), as the reference reads them.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeDepthPass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
vtkGlobeTest::Checklist Check;

struct Errors
{
  int Pixels = 0;
  double Median = 0.0, P95 = 0.0;
};

// |drawn height - data height| over the covered pixels (stride 2).
Errors Measure(vtkGlobeTest::Scene& scene, vtkGlobeDepthPass* depthPass)
{
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const std::vector<vtkGlobeLayer*> layers = vtkGlobeTest::HeightLayers(scene.Mapper);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const int* size = scene.Window->GetSize();
  std::vector<double> e;
  for (int y = 1; y < size[1]; y += 2)
  {
    for (int x = 1; x < size[0]; x += 2)
    {
      const float d = depth[static_cast<size_t>(y) * size[0] + x];
      if (!(d < 1.0f))
      {
        continue;
      }
      double p[3], llh[3];
      vtkGlobeTest::UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5,
        depthPass ? depthPass->GetPerspectiveDepth(d, camera) : d, p);
      if (!scene.Body->CartesianToGeodeticQuiet(p, llh))
      {
        continue;
      }
      e.push_back(std::abs(llh[2] - vtkGlobeTest::ComposedHeight(layers, llh[0], llh[1])));
    }
  }
  Errors r;
  r.Pixels = static_cast<int>(e.size());
  if (!e.empty())
  {
    std::sort(e.begin(), e.end());
    r.Median = e[e.size() / 2];
    r.P95 = e[e.size() * 95 / 100];
  }
  return r;
}

Errors Render(vtkGlobeTest::Scene& scene, int steps, vtkGlobeDepthPass* depthPass = nullptr)
{
  // The data at full resolution, as the reference composes it (filtered to the footprint, a
  // pixel kilometres long at a grazing angle holds the relief's average, not its heights).
  scene.Mapper->SetFootprintFiltering(false);
  scene.Mapper->SetTerrainRefinement(steps);
  scene.Render();
  return Measure(scene, depthPass);
}

// Without refinement, then with 2 steps: the median and p95 must shrink by the factors given.
void Compare(const char* what, vtkGlobeTest::Scene& scene, double medianFactor, double p95Factor,
  vtkGlobeDepthPass* depthPass = nullptr)
{
  const Errors off = Render(scene, 0, depthPass);
  const Errors on = Render(scene, 2, depthPass);
  Check.Expect(off.Pixels > 3000 && on.Pixels > 0.95 * off.Pixels &&
      on.Median * medianFactor <= std::max(off.Median, 1e-3) &&
      on.P95 * p95Factor <= std::max(off.P95, 1e-3),
    vtkGlobeTest::Printf("%s: %d pixels, |dh| median %.3f m, p95 %.3f m without refinement; "
                         "%d pixels, median %.3f m, p95 %.3f m with 2 steps (bound: %g and %gx "
                         "smaller)",
      what, off.Pixels, off.Median, off.P95, on.Pixels, on.Median, on.P95, medianFactor,
      p95Factor));
}
} // namespace

int TestGlobeTerrainRefinement(int, char*[])
{
  const double summit[3] = { -121.7603, 46.8523, 4392.0 };
  std::printf("A. Oblique over Rainier from 5 km above the ground:\n");
  {
    vtkGlobeTest::Scene scene(300, 225, 128);
    scene.AddEarthLayers();
    const double camera[3] = { -122.25, 46.45, 5500.0 };
    scene.Look(camera, summit, 40.0, 10.0, 1.0e6);
    // Where the mesh hides a ridge or shows one that is not there, the ray's first hit is
    // elsewhere: steps from the mesh point do not reach it (most of the remaining p95).
    Compare("grid 128", scene, 4.0, 2.0);
    // With refinement the grid's cells no longer set the error.
    Errors coarse, fine;
    scene.Mapper->SetGridResolution(64);
    coarse = Render(scene, 2);
    scene.Mapper->SetGridResolution(256);
    fine = Render(scene, 2);
    Check.Expect(coarse.P95 <= 2.0 * std::max(fine.P95, 0.05),
      vtkGlobeTest::Printf("refined p95 at grid 64: %.3f m; at grid 256: %.3f m (bound 2x)",
        coarse.P95, fine.P95));
  }
  std::printf("B. The whole Earth from 22,000 km, grid 64:\n");
  {
    vtkGlobeTest::Scene scene(300, 225, 64);
    scene.AddEarthLayers();
    const double camera[3] = { -100.0, 30.0, 2.2e7 }, target[3] = { -100.0, 30.0, 0.0 };
    scene.Look(camera, target, 40.0, 1.0e6, 5.0e7);
    Compare("whole Earth", scene, 50.0, 50.0);
  }
  std::printf("C. Nadir over Rainier from 12 km, logarithmic depth:\n");
  {
    vtkGlobeTest::Scene scene(300, 225, 128);
    scene.AddEarthLayers();
    vtkNew<vtkGlobeDepthPass> pass;
    pass->SetModeToLogarithmic();
    scene.Renderer->SetPass(pass);
    const double camera[3] = { -121.7603, 46.8523, 12000.0 };
    scene.Look(camera, summit, 40.0, 10.0, 1.0e6);
    Compare("nadir, logarithmic depth", scene, 50.0, 50.0, pass);
  }
  std::printf("D. The same without high-precision geodetic coordinates (perspective depth):\n");
  {
    vtkGlobeTest::Scene scene(300, 225, 128);
    scene.AddEarthLayers();
    scene.Mapper->HighPrecisionGeodeticOff();
    const double camera[3] = { -121.7603, 46.8523, 12000.0 };
    scene.Look(camera, summit, 40.0, 10.0, 1.0e6);
    // A float unit direction is 0.4 m on the Earth: the chord's sag is known only to that,
    // and a grazing ray turns it into steps of hundreds of metres. The refinement is off there:
    // the picture and its depth are the mesh's, bit for bit.
    scene.Mapper->SetTerrainRefinement(0);
    scene.Render();
    const std::vector<float> depthOff = vtkGlobeTest::ReadDepth(scene.Window);
    const std::vector<unsigned char> rgbOff = vtkGlobeTest::ReadPixels(scene.Window);
    scene.Mapper->SetTerrainRefinement(2);
    scene.Render();
    const bool same = depthOff == vtkGlobeTest::ReadDepth(scene.Window) &&
      rgbOff == vtkGlobeTest::ReadPixels(scene.Window);
    Check.Expect(same, "float directions: refinement asked for, the mesh's picture and depth kept");
  }
  std::printf("E. Along the ground, looking up at Rainier from 2 m above its western foot:\n");
  {
    vtkGlobeTest::Scene scene(300, 225, 128);
    scene.AddEarthLayers();
    const double lon = -121.95, lat = 46.85;
    const double ground =
      vtkGlobeTest::ComposedHeight(vtkGlobeTest::HeightLayers(scene.Mapper), lon, lat);
    const double camera[3] = { lon, lat, ground + 2.0 };
    scene.Look(camera, summit, 40.0, 1.0, 1.0e6);
    // The rays climb: each meets the slope it sees from below (the benchmark's satellite
    // scene). Steps that need a descending ray left every such pixel on the mesh.
    Compare("looking up the slope", scene, 4.0, 2.0);
  }
  return Check.Result();
}
