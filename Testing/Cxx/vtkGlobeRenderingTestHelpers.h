// Helpers shared by the rendering tests: an offscreen window, camera placement in geodetic
// terms, texture and depth readback, and the exact ray/ellipsoid reference.
#ifndef vtkGlobeRenderingTestHelpers_h
#define vtkGlobeRenderingTestHelpers_h

#include "vtkCamera.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPixelBufferObject.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include <cmath>
#include <string>
#include <vector>

namespace vtkGlobeTest
{
/// Points the renderer's camera from a geodetic position at a geodetic target, with the
/// local up as view-up.
inline void LookAt(vtkRenderer* renderer, vtkGlobeEllipsoid* body, const double camera[3],
  const double target[3], double viewAngle)
{
  double eye[3], focus[3], east[3], north[3], up[3];
  body->GeodeticToCartesian(camera, eye);
  body->GeodeticToCartesian(target, focus);
  body->ComputeEastNorthUp(camera[0], camera[1], east, north, up);
  vtkCamera* c = renderer->GetActiveCamera();
  c->SetPosition(eye);
  c->SetFocalPoint(focus);
  // Looking down the vertical, "up" is the view direction itself: use north instead.
  double view[3] = { focus[0] - eye[0], focus[1] - eye[1], focus[2] - eye[2] };
  const double length = std::sqrt(view[0] * view[0] + view[1] * view[1] + view[2] * view[2]);
  const double along = (view[0] * up[0] + view[1] * up[1] + view[2] * up[2]) / length;
  c->SetViewUp(std::abs(along) > 0.999 ? north : up);
  c->SetViewAngle(viewAngle);
  c->OrthogonalizeViewUp();
}

/// Reads a float texture back: width * height * components values, row 0 at the bottom.
inline std::vector<float> ReadTexture(vtkTextureObject* texture)
{
  const unsigned int w = texture->GetWidth(), h = texture->GetHeight();
  const int comps = texture->GetComponents();
  std::vector<float> values(static_cast<size_t>(w) * h * comps);
  vtkPixelBufferObject* pbo = texture->Download();
  unsigned int dims[2] = { w, h };
  vtkIdType increments[2] = { 0, 0 };
  pbo->Download2D(VTK_FLOAT, values.data(), dims, comps, increments);
  pbo->Delete();
  return values;
}

/// The z-buffer of the window (VTK's depth convention, 0 near .. 1 far), row 0 at the bottom.
inline std::vector<float> ReadDepth(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  std::vector<float> depth(static_cast<size_t>(size[0]) * size[1]);
  window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth.data());
  return depth;
}

/// World position of a window pixel from its depth value, through the inverse of the
/// camera's composite projection (double).
inline void UnprojectPixel(vtkRenderer* renderer, double x, double y, double depth, double world[3])
{
  renderer->SetDisplayPoint(x, y, depth);
  renderer->DisplayToWorld();
  double p[4];
  renderer->GetWorldPoint(p);
  world[0] = p[0] / p[3];
  world[1] = p[1] / p[3];
  world[2] = p[2] / p[3];
}

/// The view ray (unit, world) through a pixel centre.
inline void PixelRay(vtkRenderer* renderer, double x, double y, double ray[3])
{
  double nearPoint[3], farPoint[3];
  UnprojectPixel(renderer, x, y, 0.0, nearPoint);
  UnprojectPixel(renderer, x, y, 1.0, farPoint);
  double n = 0;
  for (int i = 0; i < 3; ++i)
  {
    ray[i] = farPoint[i] - nearPoint[i];
    n += ray[i] * ray[i];
  }
  n = std::sqrt(n);
  for (int i = 0; i < 3; ++i)
  {
    ray[i] /= n;
  }
}
} // namespace vtkGlobeTest

#endif
