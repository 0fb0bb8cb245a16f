// Internal: assembles the GLSL shared by the globe's shader programs (not installed).
#ifndef vtkGlobeShaderSources_h
#define vtkGlobeShaderSources_h

#include "globe_ellipsoid.h"
#include "globe_pgm.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <string>

namespace vtkGlobeShaderSources
{
/// The common-subset shader math (Module/Core/ShaderMath) with its GLSL prelude.
inline std::string Math()
{
  return std::string("#define GLOBE_OUT(T) out T\n"
                     "#define GLOBE_INOUT(T) inout T\n"
                     "#define GLOBE_NEWTON_TOLERANCE 4.8e-7\n") +
    globe_ellipsoid + "\n" + globe_pgm + "\n";
}

/// The body's radii as uniforms: globeRadii (m) and globeRadiiScaled (in units of the largest,
/// the scaled space's shape).
inline void SetRadii(vtkShaderProgram* program, vtkGlobeEllipsoid* body)
{
  const double* radii = body->GetRadii();
  const double largest = body->GetMaximumRadius();
  float metres[3], scaled[3];
  for (int i = 0; i < 3; ++i)
  {
    metres[i] = static_cast<float>(radii[i]);
    scaled[i] = static_cast<float>(radii[i] / largest);
  }
  program->SetUniform3f("globeRadii", metres);
  program->SetUniform3f("globeRadiiScaled", scaled);
}

/// The GL state of a full-screen pass into the globe's own framebuffers (grid pass, reduction,
/// page feedback): depth test, blending and scissor off and the framebuffer bindings pushed for
/// the pass; all of it, and the viewport, restored when it goes out of scope.
class ScopedOffscreenPass
{
public:
  explicit ScopedOffscreenPass(vtkOpenGLState* state)
    : State(state)
    , Viewport(state)
    , Depth(state, GL_DEPTH_TEST)
    , Blend(state, GL_BLEND)
    , Scissor(state, GL_SCISSOR_TEST)
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->PushFramebufferBindings();
  }
  ~ScopedOffscreenPass() { this->State->PopFramebufferBindings(); }
  ScopedOffscreenPass(const ScopedOffscreenPass&) = delete;
  void operator=(const ScopedOffscreenPass&) = delete;

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable Depth;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
};

/// Replaces the first occurrence of a marker line in a shader template.
inline std::string Replace(std::string source, const std::string& marker, const std::string& text)
{
  const size_t at = source.find(marker);
  if (at != std::string::npos)
  {
    source.replace(at, marker.size(), text);
  }
  return source;
}
}

#endif
