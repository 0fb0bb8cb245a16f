// The composition shades only the blocks that hold terrain (issue "Cost proportional to what
// the frame shows"; vtkGlobeCompositePass::BlockCulling): the sky costs nothing.
//  A. The whole Earth from 60,000 km, off centre (a disc in a 400 x 300 window), B. Rainier
//     from 16 km up with the sky above the skyline: with culling on and off, the same frame
//     (0 pixels and 0 depth values differ), and the fragment shader invocations of the frame
//     (GL_ARB_pipeline_statistics_query) drop by the pixels outside the shaded spans: per band
//     of 64 rows, from the first to the last 16-pixel column that holds terrain, computed here
//     from the frame's own depth.
//  C. With the atmosphere (which shades the sky) nothing is culled: the invocations are the
//     same with culling on and off.
#include "vtkGlobeCompositePass.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdio>

namespace
{
vtkGlobeTest::Checklist Check;

// Fragment shader invocations of one frame (the scene settled beforehand).
double Invocations(vtkGlobeTest::Scene& scene)
{
  scene.Window->MakeCurrent();
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, query);
  scene.Window->Render();
  glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
  GLuint64 count = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &count);
  glDeleteQueries(1, &query);
  return static_cast<double>(count);
}

// The pixels the culled composition shades: per band of 64 rows, the span of 16-pixel columns
// that hold a terrain pixel (depth < 1: the globe is the only actor).
long ShadedSpans(const std::vector<float>& depth, int width, int height)
{
  long shaded = 0;
  for (int y0 = 0; y0 < height; y0 += 64)
  {
    const int y1 = std::min(y0 + 64, height);
    int first = width, last = -1;
    for (int y = y0; y < y1; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        if (depth[static_cast<size_t>(y) * width + x] < 1.0f)
        {
          first = std::min(first, x / 16);
          last = std::max(last, x / 16);
        }
      }
    }
    if (last >= 0)
    {
      shaded += static_cast<long>(std::min((last + 1) * 16, width) - first * 16) * (y1 - y0);
    }
  }
  return shaded;
}

// Culling on against off: the same frame, and the invocations saved against the sky outside
// the spans.
void Compare(vtkGlobeTest::Scene& scene, const char* what)
{
  const int width = scene.Window->GetSize()[0], height = scene.Window->GetSize()[1];
  vtkGlobeCompositePass* pass = scene.Mapper->GetCompositePass();
  pass->BlockCullingOn();
  scene.Render();
  const double on = Invocations(scene);
  const auto imageOn = vtkGlobeTest::ReadPixels(scene.Window);
  const auto depthOn = vtkGlobeTest::ReadDepth(scene.Window);
  pass->BlockCullingOff();
  scene.Render();
  const double off = Invocations(scene);
  const auto imageOff = vtkGlobeTest::ReadPixels(scene.Window);
  const auto depthOff = vtkGlobeTest::ReadDepth(scene.Window);
  pass->BlockCullingOn();
  int pixels = 0, depths = 0;
  vtkGlobeTest::CountDifferences(imageOn, depthOn, imageOff, depthOff, pixels, depths);
  const long covered = vtkGlobeTest::CoveredPixels(depthOn);
  const long all = static_cast<long>(width) * height;
  const long spans = ShadedSpans(depthOn, width, height);
  const double saved = off - on, sky = static_cast<double>(all - spans);
  std::printf("  %s: %ld of %ld pixels terrain, %ld in the shaded spans; invocations %.0f "
              "culled, %.0f not (%.0f saved, %.0f pixels outside the spans)\n",
    what, covered, all, spans, on, off, saved, sky);
  Check.Expect(pixels == 0 && depths == 0,
    vtkGlobeTest::Printf("%s: culling draws the same frame: %d pixels, %d depth values differ",
      what, pixels, depths));
  // llvmpipe counts whole 4 x 4 blocks where a triangle's edge cuts them, so the full-window
  // quad's diagonal and the bands' add a few per cent either way.
  Check.Expect(covered > 0 && spans < all && saved >= 0.95 * sky && saved <= 1.1 * sky,
    vtkGlobeTest::Printf("%s: culling saves the %.0f pixels outside the spans (%.0f "
                         "invocations saved, within -5/+10 %%)",
      what, sky, saved));
}
} // namespace

int TestGlobeCompositeCulling(int, char*[])
{
  vtkGlobeTest::Scene scene(400, 300);
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/relief_2deg.tif", true));
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/mt_rainier_90m.tif", true));
  scene.Mapper->AddLayer(vtkGlobeTest::FileLayer("earth/world.tif", false));

  std::printf("A. The whole Earth from 60,000 km, off centre:\n");
  const double far[3] = { 10.0, 20.0, 6.0e7 }, beside[3] = { 40.0, 20.0, 0.0 };
  scene.Look(far, beside, 30.0);
  Compare(scene, "whole Earth");

  std::printf("B. Rainier from 16 km up, the sky above the skyline:\n");
  const double camera[3] = { -121.86, 46.75, 16000.0 }, target[3] = { -121.70, 46.95, 12000.0 };
  scene.Look(camera, target, 40.0);
  Compare(scene, "Rainier");

  std::printf("C. With the atmosphere:\n");
  scene.Look(far, beside, 30.0);
  scene.Mapper->AtmosphereOn();
  vtkGlobeCompositePass* pass = scene.Mapper->GetCompositePass();
  scene.Render();
  const double on = Invocations(scene);
  pass->BlockCullingOff();
  scene.Render();
  const double off = Invocations(scene);
  pass->BlockCullingOn();
  std::printf("  invocations %.0f with culling on, %.0f off\n", on, off);
  Check.Expect(on == off, "the atmosphere shades the sky: nothing culled");
  Check.Expect(vtkGlobeTest::NoGLError(), "no GL error");
  return Check.Result();
}
