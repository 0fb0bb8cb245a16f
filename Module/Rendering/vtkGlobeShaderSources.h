// Internal: assembles the GLSL shared by the globe's shader programs (not installed).
#ifndef vtkGlobeShaderSources_h
#define vtkGlobeShaderSources_h

#include "globe_ellipsoid.h"
#include "globe_pgm.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkShaderProgram.h"

#include <string>

namespace vtkGlobeShaderSources
{
/// The common-subset shader math (Module/Core/ShaderMath) with its GLSL prelude.
inline std::string Math()
{
  return std::string("#define GLOBE_OUT(T) out T\n"
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
