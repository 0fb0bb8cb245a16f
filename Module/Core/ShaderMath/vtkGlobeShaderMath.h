/**
 * vtkGlobeShaderMath.h: the C++ side of the GLSL/C++ common-subset shader math
 * (Documentation/geodesy.md, "The shader-math library").
 *
 * Includes the very GLSL text the GPU runs (globe_ellipsoid.glsl, globe_pgm.glsl,
 * globe_projection.glsl) twice,
 * with GLM types:
 *   vtkGlobeShaderMath::f::globe_...  in float, as the GPU computes it;
 *   vtkGlobeShaderMath::d::globe_...  in double, the same algorithm without rounding noise.
 * Tests compare both against the double-precision reference (GeographicLib).
 * Not installed: it is a test and CPU-mirror aid, not public API.
 */
#ifndef vtkGlobeShaderMath_h
#define vtkGlobeShaderMath_h

#include <glm/glm.hpp>

#include <cmath>

namespace vtkGlobeShaderMath
{
// The shader functions are not declared inline (GLSL has no such keyword), so each
// translation unit gets its own internal copy.
namespace f
{
namespace
{
using namespace glm;
#define GLOBE_OUT(T) T&
#define GLOBE_INOUT(T) T&
#define GLOBE_NEWTON_TOLERANCE 4.8e-7f /* 4 float ulp */
#include "globe_ellipsoid.glsl"
#include "globe_pgm.glsl"
#include "globe_projection.glsl"
#undef GLOBE_NEWTON_TOLERANCE
#undef GLOBE_OUT
#undef GLOBE_INOUT
} // namespace
} // namespace f

namespace d
{
namespace
{
using namespace glm;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
// GLSL promotes float literals freely; GLM's templates do not mix double and float.
inline double max(double a, double b)
{
  return a > b ? a : b;
}
inline double min(double a, double b)
{
  return a < b ? a : b;
}
inline double abs(double a)
{
  return std::abs(a);
}
inline dvec3 operator/(float s, const dvec3& v)
{
  return static_cast<double>(s) / v;
}
inline dvec3 operator+(float s, const dvec3& v)
{
  return static_cast<double>(s) + v;
}
inline dvec3 operator*(float s, const dvec3& v)
{
  return static_cast<double>(s) * v;
}
inline dvec3 operator-(const dvec3& v, float s)
{
  return v - static_cast<double>(s);
}
inline double clamp(double x, double lo, double hi)
{
  return x < lo ? lo : (x > hi ? hi : x);
}
inline double mix(double a, double b, double t)
{
  return a + (b - a) * t;
}
// globe_projection.glsl's exact branch (GLOBE_EXACT_MATH) uses these C library functions.
using std::expm1;
using std::log1p;
#define GLOBE_OUT(T) T&
#define GLOBE_INOUT(T) T&
#define GLOBE_NEWTON_TOLERANCE 8.9e-16 /* 4 double ulp */
#define GLOBE_EXACT_ATAN2
#define GLOBE_EXACT_MATH
#define float double
#include "globe_ellipsoid.glsl"
#include "globe_pgm.glsl"
#include "globe_projection.glsl"
#undef float
#undef GLOBE_EXACT_MATH
#undef GLOBE_EXACT_ATAN2
#undef GLOBE_NEWTON_TOLERANCE
#undef GLOBE_OUT
#undef GLOBE_INOUT
} // namespace
} // namespace d
} // namespace vtkGlobeShaderMath

#endif
