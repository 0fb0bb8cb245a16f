#include "vtkGlobePageFeedback.h"

#include "vtkDoubleArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkGlobePageFeedbackFS.h"
#include "vtkGlobeShaderSources.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

vtkStandardNewMacro(vtkGlobePageFeedback);

class vtkGlobePageFeedback::vtkInternals
{
public:
  vtkSmartPointer<vtkTextureObject> Target;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  unsigned int Buffer = 0;
  size_t BufferBytes = 0;
  bool Pending = false;
  int Columns = 0, Rows = 0;
  double Reference[3] = { 0, 0, 0 };
  double Radii[3] = { 1, 1, 1 };
};

vtkGlobePageFeedback::vtkGlobePageFeedback()
  : Internals(new vtkInternals)
{
}

vtkGlobePageFeedback::~vtkGlobePageFeedback() = default;

bool vtkGlobePageFeedback::Render(vtkOpenGLRenderWindow* window, vtkTextureObject* gbuffer,
  vtkTextureObject* depth, const double reference[3], const double radii[3])
{
  auto& in = *this->Internals;
  const int b = this->BlockSize;
  const int columns = (static_cast<int>(gbuffer->GetWidth()) + b - 1) / b;
  const int rows = (static_cast<int>(gbuffer->GetHeight()) + b - 1) / b;
  if (!in.Target)
  {
    in.Target = vtkSmartPointer<vtkTextureObject>::New();
    in.Target->SetContext(window);
    in.Target->SetMinificationFilter(vtkTextureObject::Nearest);
    in.Target->SetMagnificationFilter(vtkTextureObject::Nearest);
    in.Target->Allocate2D(3 * columns, rows, 4, VTK_FLOAT);
    in.Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    in.Framebuffer->SetContext(window);
  }
  in.Target->Resize(3 * columns, rows);
  if (!in.Quad)
  {
    in.Quad.reset(new vtkOpenGLQuadHelper(window,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), vtkGlobePageFeedbackFS, ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(in.Quad->Program);
  }
  vtkShaderProgram* p = in.Quad->Program;
  if (!p || !p->GetCompiled())
  {
    vtkErrorMacro(<< "The globe's page feedback shader did not compile");
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  const vtkGlobeShaderSources::ScopedOffscreenPass offscreen(state);
  in.Framebuffer->Bind();
  in.Framebuffer->AddColorAttachment(0, in.Target);
  in.Framebuffer->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, 3 * columns, rows);
  gbuffer->Activate();
  depth->Activate();
  p->SetUniformi("globeGBuffer", gbuffer->GetTextureUnit());
  p->SetUniformi("globeDepth", depth->GetTextureUnit());
  p->SetUniformi("globeBlock", b);
  const float target[2] = { static_cast<float>(3 * columns), static_cast<float>(rows) };
  p->SetUniform2f("globeTargetSize", target);
  in.Quad->Render();
  depth->Deactivate();
  gbuffer->Deactivate();

  const size_t bytes = static_cast<size_t>(3 * columns) * rows * 4 * sizeof(float);
  if (!in.Buffer)
  {
    glGenBuffers(1, &in.Buffer);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, in.Buffer);
  if (bytes != in.BufferBytes)
  {
    glBufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STREAM_READ);
    in.BufferBytes = bytes;
  }
  in.Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  in.Framebuffer->ActivateReadBuffer(0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 3 * columns, rows, GL_RGBA, GL_FLOAT, nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  in.Framebuffer->RemoveColorAttachments(1);
  in.Pending = true;
  in.Columns = columns;
  in.Rows = rows;
  std::copy(reference, reference + 3, in.Reference);
  std::copy(radii, radii + 3, in.Radii);
  return true;
}

bool vtkGlobePageFeedback::IsPending()
{
  return this->Internals->Pending;
}

bool vtkGlobePageFeedback::Collect(vtkDoubleArray* footprints)
{
  auto& in = *this->Internals;
  footprints->SetNumberOfComponents(6);
  footprints->SetNumberOfTuples(0);
  if (!in.Pending)
  {
    return false;
  }
  in.Pending = false;
  std::vector<float> texels(in.BufferBytes / sizeof(float));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, in.Buffer);
  const void* mapped = glMapBufferRange(
    GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(in.BufferBytes), GL_MAP_READ_BIT);
  if (mapped)
  {
    std::memcpy(texels.data(), mapped, in.BufferBytes);
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  if (!mapped)
  {
    return false;
  }
  const double largest = std::max(in.Radii[0], std::max(in.Radii[1], in.Radii[2]));
  // (lon, lat) of G-buffer xyz, in double: the direction's geodetic normal is along
  // direction / scaled radii (vtkGlobeLayerSet::SetGeodeticReference).
  auto lonLat = [&](const float* g, double ll[2]) {
    double d[3], q[3];
    for (int i = 0; i < 3; ++i)
    {
      d[i] = in.Reference[i] + g[i];
    }
    for (int i = 0; i < 3; ++i)
    {
      q[i] = d[i] / (in.Radii[i] / largest);
    }
    ll[0] = std::atan2(q[1], q[0]);
    ll[1] = std::atan2(q[2], std::hypot(q[0], q[1]));
  };
  const double pi = 3.141592653589793;
  footprints->Allocate(static_cast<vtkIdType>(in.Columns) * in.Rows * 6);
  for (int r = 0; r < in.Rows; ++r)
  {
    for (int c = 0; c < in.Columns; ++c)
    {
      const float* t = &texels[4 * (static_cast<size_t>(r) * 3 * in.Columns + 3 * c)];
      if (t[3] != 1.0f)
      {
        continue; // not covered
      }
      double centre[2];
      lonLat(t, centre);
      double f[6] = { centre[0], centre[1], 0, 0, 0, 0 };
      for (int k = 1; k <= 2; ++k)
      {
        const float* n = t + 4 * k;
        if (n[3] == 0.0f)
        {
          continue; // an isolated pixel: no footprint (the finest level is asked for)
        }
        double other[2];
        lonLat(n, other);
        double dLon = other[0] - centre[0];
        dLon -= 2.0 * pi * std::floor(dLon / (2.0 * pi) + 0.5);
        f[2 * k] = n[3] * dLon;
        f[2 * k + 1] = n[3] * (other[1] - centre[1]);
      }
      footprints->InsertNextTuple(f);
    }
  }
  return true;
}

void vtkGlobePageFeedback::ReleaseGraphicsResources(vtkWindow* window)
{
  auto& in = *this->Internals;
  if (in.Target)
  {
    in.Target->ReleaseGraphicsResources(window);
    in.Target = nullptr;
  }
  if (in.Framebuffer)
  {
    in.Framebuffer->ReleaseGraphicsResources(window);
    in.Framebuffer = nullptr;
  }
  if (in.Quad)
  {
    in.Quad->ReleaseGraphicsResources(window);
    in.Quad.reset();
  }
  if (in.Buffer)
  {
    glDeleteBuffers(1, &in.Buffer);
    in.Buffer = 0;
    in.BufferBytes = 0;
  }
  in.Pending = false;
}

void vtkGlobePageFeedback::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BlockSize: " << this->BlockSize << "\n";
  os << indent << "Samples: " << this->Internals->Columns << " x " << this->Internals->Rows
     << (this->Internals->Pending ? " (read-back pending)" : "") << "\n";
}
