// globe_pgm.glsl: spherical Projective Grid Mapping (Mahsman 2010, with the corrections of
// Documentation/rendering.md, "PGM as implemented" and "Errata and degenerate cases"), in the
// GLSL/C++ common subset (see globe_ellipsoid.glsl for its rules).
//
// Everything here lives in the body's scaled space (x/a, y/b, z/c), where the ellipsoid is the
// unit sphere and the reference "spheres" have radii r near 1. Vectors are eye-relative; the
// large quantities (distances, altitudes, c - 1) arrive precomputed in double on the CPU.
//
// Frame parameters (computed in double by vtkGlobeProjectiveGrid):
//   nadir        unit vector from the eye to the centre; d the eye's distance from the centre
//   rP, aP       the primary sphere's radius and the eye's altitude over it, a = d - r (exact)
//   rS, aS       the same for the secondary sphere (rS <= 0: none)
//   tau0         asin(r_p / d), the primary tangent angle
//   blendStart   b = zeta * tau0; past it the secondary ray angle runs from blendStartS to tauS
//
// Positions never depend on a transcendental function: GPUs' sin/asin/atan are approximations
// (GLSL promises no accuracy; llvmpipe's are off by ~1e-4). Trigonometry only decides where the
// secondary sphere samples, and every vertex is placed consistently with the direction it
// samples.

// 1 / sqrt(x) to full float precision. GPU inversesqrt() (and normalize(), length(), and
// v / sqrt(x), which compilers rewrite into it) may be approximations: llvmpipe's has ~12 bits,
// 2.4e-4, which moved grid directions by 4e-4 rad. One Newton step squares the error away.
float globe_inverseSqrt(float x)
{
  float r = inversesqrt(x);
  return r * (1.5f - 0.5f * x * r * r);
}

vec3 globe_normalize(vec3 v)
{
  return v * globe_inverseSqrt(dot(v, v));
}

float globe_length(vec3 v)
{
  float x = dot(v, v);
  return x > 0.0f ? x * globe_inverseSqrt(x) : 0.0f;
}

// Front-facing hit of a ray with the sphere of radius r seen from distance d, altitude
// a = d - r (exact), for the ray at cos w / sin w from the nadir (k: the in-plane unit vector
// perpendicular to the nadir). Cancellation-free forms:
//   t = a (d + r) / D,  D = d cos w + S,  S = sqrt(r^2 - d^2 sin^2 w)
//   s = (-(d S + r^2 cos w) nadir + a (d + r) sin w k) / (r D)      (unit, from the centre)
// g = (cos, sin) of the normal angle (s = -cos g nadir + sin g k), from the two coefficients
// themselves: sin g read back from the float unit vector s (dot(s, k)) carries 1 ulp of its
// components, 6e-8 or 0.4 m on the Earth, wherever none of them is small.
// Returns false for a miss; past the tangent the tangent point is returned (S = 0), so every
// value stays finite.
bool globe_sphereHit(float cosW, float sinW, float d, float r, float a, vec3 nadir, vec3 k,
  GLOBE_OUT(float) t, GLOBE_OUT(vec3) s, GLOBE_OUT(vec2) g)
{
  // S^2 = r^2 - d^2 sin^2 w = (d cos w)^2 - a (d + r): the first form cancels near the tangent
  // (sin w ~ 1 carries an ulp), the second near the nadir; take the one that does not.
  float ds = d * sinW;
  float dc = d * cosW;
  float q = sinW < cosW ? (r - ds) * (r + ds) : dc * dc - a * (d + r);
  float root = sqrt(max(q, 0.0f));
  float denominator = dc + root;
  if (!(denominator > 0.0f))
  {
    t = 0.0f;
    s = -nadir;
    g = vec2(1.0f, 0.0f);
    return false;
  }
  t = a * (d + r) / denominator;
  float along = d * root + r * r * cosW;
  float across = a * (d + r) * sinW;
  g = vec2(along, across) * globe_inverseSqrt(along * along + across * across);
  s = globe_normalize(nadir * (-along) + k * across);
  return q >= 0.0f && cosW > 0.0f;
}

// The sampled direction s and eye-relative primary-sphere point p of a grid point whose ray
// meets the primary sphere with normal angle g (cos, sin) at ray angle omega, from the
// primary hit (s, p): past the blend start (erratum E2: f = 0 primary only, f = 1 secondary
// only), the direction is blended with the hit of a secondary ray whose angle runs from
// blendStartS (erratum E4: where the secondary continues the primary) to the secondary tangent
// tauS, and p becomes the primary-sphere point there.
void globe_pgmSecondary(float omega, vec2 g, vec3 nadir, vec3 k, float d, float rP, float aP,
  float tau0, float blendStart, float rS, float aS, float blendStartS, float tauS,
  GLOBE_INOUT(vec3) s, GLOBE_INOUT(vec3) p)
{
  if (!(rS > 0.0f) || !(omega > blendStart))
  {
    return;
  }
  float f = clamp((omega - blendStart) / (tau0 - blendStart), 0.0f, 1.0f);
  float omegaS = mix(blendStartS, tauS, f);
  float tS = 0.0f;
  vec3 sS = s;
  vec2 gS = g;
  globe_sphereHit(cos(omegaS), sin(omegaS), d, rS, aS, nadir, k, tS, sS, gS);
  // Both directions lie in the (nadir, k) plane: blend their (cos g, sin g) there, so sin g
  // keeps its relative precision (a camera 1 cm up sees normal angles of 1e-8 past the
  // blend start, below the float noise of a unit vector's dot product).
  vec2 m = mix(g, gS, f);
  m = m * globe_inverseSqrt(dot(m, m));
  // The primary-sphere point in direction s, relative to the eye, in the E1 form
  // (a + r (1 - cos g)) nadir + r sin g k: s * rP + nadir * d would subtract two numbers
  // of about 1 and leave float noise of 1 ulp of the radius (0.4 m on the Earth) in every
  // vertex past the blend start. cos g is taken from sin g so the point stays on the sphere.
  float sinG = clamp(m.y, 0.0f, 1.0f);
  float cosG = sqrt(max(1.0f - sinG * sinG, 0.0f));
  s = globe_normalize(nadir * (-cosG) + k * sinG);
  p = nadir * (aP + rP * sinG * sinG / (1.0f + cosG)) + k * (rP * sinG);
}

// One grid point: its ray (unit, scaled space) against the reference spheres. Writes the unit
// direction from the centre of the sampled point (s) and the point on the primary sphere
// relative to the eye (p). Returns 1 for a hit: before the blend start the point is the exact
// ray hit, p = t ray; past it, see globe_pgmSecondary.
// A ray that misses the primary sphere returns 0.5 (a valid vertex, not a hit) with the point
// the ray at the tangent angle tau0 in the same plane samples: the primary sphere's horizon
// there, or past the blend start the secondary sphere's tangent (the farthest terrain that can
// be seen in that direction). Triangles between hit grid points and these reach the terrain's
// silhouette, where dropping them would leave out a band up to one grid cell wide along the
// limb (Documentation/rendering.md "The limb"). The tangent point is written directly, without
// the cancellation of globe_sphereHit at S = 0 (an ulp of sin w there is a chord of 7e-4
// radii): with sin T = r / d and cos T = sqrt(a (d + r)) / d, the normal angle is
// g = (sin T, cos T) and p = d cos T (cos T nadir + sin T k), in the E1 form
// (a + r (1 - sin T)) nadir + r cos T k. Returns 0 (invalid) only when the eye is not above
// the primary sphere.
float globe_pgmGridPoint(vec3 ray, vec3 nadir, vec3 anyPerpendicular, float d, float rP,
  float aP, float tau0, float blendStart, float rS, float aS, float blendStartS, float tauS,
  GLOBE_OUT(vec3) s, GLOBE_OUT(vec3) p)
{
  float cosW = dot(ray, nadir);
  vec3 across = ray - nadir * cosW;
  float sinW = globe_length(across);
  // A ray along the nadir has no plane of its own: any perpendicular will do
  // (Documentation/rendering.md, "Errata and degenerate cases").
  vec3 k = sinW > 0.0f ? across / sinW : anyPerpendicular;
  float t = 0.0f;
  vec2 g = vec2(1.0f, 0.0f);
  if (globe_sphereHit(cosW, sinW, d, rP, aP, nadir, k, t, s, g))
  {
    p = ray * t;
    globe_pgmSecondary(atan(sinW, cosW), g, nadir, k, d, rP, aP, tau0, blendStart, rS, aS,
      blendStartS, tauS, s, p);
    return 1.0f;
  }
  if (!(aP > 0.0f) || !(d > 0.0f))
  {
    s = -nadir;
    p = vec3(0.0f);
    return 0.0f;
  }
  float sinT = rP / d;
  float cosT = sqrt(aP * (d + rP)) / d;
  g = vec2(sinT, cosT);
  s = globe_normalize(nadir * (-sinT) + k * cosT);
  p = nadir * (aP + rP * (1.0f - sinT)) + k * (rP * cosT);
  globe_pgmSecondary(tau0, g, nadir, k, d, rP, aP, tau0, blendStart, rS, aS, blendStartS,
    tauS, s, p);
  return 0.5f;
}

// CPU-side helpers (double), used by vtkGlobeProjectiveGrid to set up the blend.

// Normal angle (from the anti-nadir) of the front-facing hit of a ray at angle omega with a
// sphere seen from c = d / r, cancellation-free:
//   gamma = asin(c sin w) - w = asin( sin w (c^2 - 1) / (c cos w + sqrt(1 - c^2 sin^2 w)) ).
float globe_frontNormalAngle(float c, float cMinusOne, float omega)
{
  float s = sin(omega);
  float q = clamp(c * s, -1.0f, 1.0f);
  float root = sqrt(max(1.0f - q * q, 0.0f));
  float denominator = c * cos(omega) + root;
  float x = denominator > 0.0f ? s * cMinusOne * (c + 1.0f) / denominator : 1.0f;
  return asin(clamp(x, -1.0f, 1.0f));
}

// The ray angle at which a sphere (c = d / r) is hit with normal angle gamma:
// tan w = sin g / (c - cos g).
float globe_rayAngleForNormalAngle(float c, float gamma)
{
  return atan(sin(gamma), c - cos(gamma));
}
