// How far a height inset's feather reaches into the terrain (issue 18, defect 4: "height
// blending alters terrain 9-11.5 texels inside the north edges of the Rainier and Everest
// insets, beyond the documented 8 texels"). The Rainier inset seen from the south (the demo's
// view), rendered with the default feather (8 texels) and with none: a pixel is altered where
// the G-buffer heights differ. The weight ramp itself ends at 8 texels (TestGlobeComposition
// checks it exactly); what reaches further is the grid: heights are composed at the grid's
// points and the surface is linear between them, so a cell that straddles the ramp's end
// carries the blend up to one cell beyond it. The north edge is the far one, where a cell
// spans the most texels. The test shows it: the reach beyond 8 texels stays within 1.5 grid
// cells (estimated from the screen: the window's width over the grid's cells, times the
// texels per pixel there) and shrinks as the grid refines, from 128^2 to 1024^2 by more than
// 4x. (The camera is inside the inset, over its south half: its other edges are out of view.)
#include "vtkGlobeMapperTesting.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"
#include <cstdio>

int TestGlobeFeatherReach(int, char*[])
{
  vtkGlobeTest::Checklist check;
  std::vector<double> north;
  for (int grid : { 128, 256, 512, 1024 })
  {
    vtkGlobeTest::Scene scene(400, 300, grid);
    scene.AddEarthLayers();
    vtkGlobeLayer* inset = scene.Mapper->GetLayer(1);
    const double camera[3] = { -121.86, 46.75, 16000.0 }, target[3] = { -121.7603, 46.8523, 4392.0 };
    scene.Look(camera, target, 40.0, 20.0, 4.0e5);
    std::vector<float> g[2];
    for (int k = 0; k < 2; ++k)
    {
      inset->SetSkirtDistance(0.0); // the inward feather this test is about
      inset->SetFeatherWidth(k == 0 ? 8.0 : 0.0);
      scene.Render();
      scene.Render();
      g[k] = vtkGlobeTest::ReadTexture(vtkGlobeMapperTesting::GetGBufferTexture(scene.Mapper));
    }
    double e[4];
    inset->GetGeographicExtent(e);
    const int cols = inset->GetNumberOfColumns(), rows = inset->GetNumberOfRows();
    double reach[4] = { 0, 0, 0, 0 }; // W E N S
    int altered = 0;
    double worstRatio = 0;
    for (size_t i = 0; i + 3 < g[0].size(); i += 4)
    {
      if (!(g[0][i + 3] > -1e6) || std::abs(g[0][i + 3] - g[1][i + 3]) <= 0.01)
        continue;
      double p[3], llh[3];
      vtkGlobeTest::GBufferPoint(scene, &g[0][i], false, p);
      scene.Body->CartesianToGeodetic(p, llh);
      const double u = (llh[0] - e[0]) / (e[1] - e[0]) * cols, v = (e[3] - llh[1]) / (e[3] - e[2]) * rows;
      if (u < 0 || u > cols || v < 0 || v > rows) continue;
      ++altered;
      const double d[4] = { u, cols - u, v, rows - v };
      int k = 0;
      for (int j = 1; j < 4; ++j) if (d[j] < d[k]) k = j;
      reach[k] = std::max(reach[k], d[k]);
      // texels per pixel here, from the pixel's neighbours
      const size_t idx = i / 4;
      const int x = idx % 400, y = idx / 400;
      double tpp = 0;
      for (int n = 0; n < 2; ++n)
      {
        const int nx = x + (n == 0), ny = y + (n == 1);
        if (nx >= 400 || ny >= 300) continue;
        const size_t j = (static_cast<size_t>(ny) * 400 + nx) * 4;
        double q[3], lq[3];
        vtkGlobeTest::GBufferPoint(scene, &g[0][j], false, q);
        scene.Body->CartesianToGeodetic(q, lq);
        const double du = (lq[0] - llh[0]) / (e[1] - e[0]) * cols, dv = (e[3] - lq[1]) / (e[3] - e[2]) * rows - v;
        tpp = std::max(tpp, std::sqrt(du * du + dv * dv));
      }
      const double cell = tpp * 400.0 / (grid - 1);
      if (d[k] > 8.0) worstRatio = std::max(worstRatio, (d[k] - 8.0) / cell);
    }
    north.push_back(reach[2]);
    // (Only the north edge is in view: the camera is over the inset's south half.)
    check.Expect(altered > 20 && worstRatio <= 1.5,
      vtkGlobeTest::Printf("grid %4d^2: %d altered pixels, reach from the west, east, north, "
                           "south edges %.2f, %.2f, %.2f, %.2f texels; beyond 8: %.2f grid cells",
        grid, altered, reach[0], reach[1], reach[2], reach[3], worstRatio));
  }
  check.Expect(north[0] > north[1] && north[1] > north[2] && north[2] > north[3] &&
      north[3] - 8.0 < 0.25 * (north[0] - 8.0),
    vtkGlobeTest::Printf("the reach past 8 texels shrinks with the grid: %.2f, %.2f, %.2f, %.2f",
      north[0] - 8.0, north[1] - 8.0, north[2] - 8.0, north[3] - 8.0));
  return check.Result();
}
