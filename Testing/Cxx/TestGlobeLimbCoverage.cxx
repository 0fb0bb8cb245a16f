// The limb at any grid (Documentation/rendering.md "The limb"): the bare WGS84 ellipsoid (no
// layers, so the exact silhouette is known) seen from space and from low orbit and 2 km up
// towards the horizon, at grids from 24^2 (cells of about 12 px) to the automatic one. Every
// pixel whose four corner rays all hit the ellipsoid (by an exact ray-ellipsoid intersection
// in double) must be covered, and every pixel whose four corner rays all miss must not be.
// Before grid points past the limb took their horizon point (globe_pgmGridPoint), the
// triangles touching them were dropped, and a band up to one grid cell wide along the limb
// showed the background (at 24^2 from space: hundreds of pixels).
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include <cmath>
#include <cstdio>

int TestGlobeLimbCoverage(int, char*[])
{
  vtkGlobeTest::Checklist check;
  constexpr int W = 300, H = 225;
  struct View
  {
    const char* Name;
    double Camera[3];
    double Target[3];
    double Near; // 0: VTK's clipping range
    double Far;
  };
  const View views[] = {
    { "space, 22,000 km", { -40.0, 25.0, 2.2e7 }, { -40.0, 25.0, 0.0 }, 0, 0 },
    { "low orbit, 400 km, towards the limb", { 10.0, 45.0, 4.0e5 }, { 10.0, 10.0, 0.0 }, 0, 0 },
    { "2 km up, towards the horizon", { 86.9, 28.0, 2000.0 }, { 88.5, 27.5, 0.0 }, 100.0, 1.0e6 },
  };
  for (const View& view : views)
  {
    for (int grid : { 24, 64, 0 })
    {
      vtkGlobeTest::Scene scene(W, H, 256);
      if (grid > 0)
      {
        scene.Mapper->SetGridResolution(grid);
      }
      else
      {
        scene.Mapper->SetGridPixelsPerCell(1.6);
      }
      scene.Look(view.Camera, view.Target, 40.0, view.Near, view.Far);
      scene.Render();
      const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
      double eye[3];
      scene.Renderer->GetActiveCamera()->GetPosition(eye);
      // Corner rays: (W + 1) x (H + 1).
      std::vector<char> corner(static_cast<size_t>(W + 1) * (H + 1));
      for (int y = 0; y <= H; ++y)
      {
        for (int x = 0; x <= W; ++x)
        {
          double ray[3];
          vtkGlobeTest::PixelRay(scene.Renderer, x, y, ray);
          double t[2];
          corner[y * (W + 1) + x] = scene.Body->IntersectRay(eye, ray, t) > 0 ? 1 : 0;
        }
      }
      int inside = 0, outside = 0, missing = 0, extra = 0;
      for (int y = 0; y < H; ++y)
      {
        for (int x = 0; x < W; ++x)
        {
          const int hits = corner[y * (W + 1) + x] + corner[y * (W + 1) + x + 1] +
            corner[(y + 1) * (W + 1) + x] + corner[(y + 1) * (W + 1) + x + 1];
          const bool covered = depth[y * W + x] < 1.0f;
          if (hits == 4)
          {
            ++inside;
            missing += covered ? 0 : 1;
          }
          else if (hits == 0)
          {
            ++outside;
            extra += covered ? 1 : 0;
          }
        }
      }
      check.Expect(inside > 1000 && outside > 1000 && missing == 0 && extra == 0,
        vtkGlobeTest::Printf("%s, grid %d (%d in use): %d of %d pixels inside the limb not "
                             "covered, %d of %d outside it covered",
          view.Name, grid, scene.Mapper->GetGridResolution(), missing, inside, extra, outside));
    }
  }
  return check.Result();
}
