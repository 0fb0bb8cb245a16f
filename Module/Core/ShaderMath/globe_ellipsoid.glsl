// globe_ellipsoid.glsl: the ellipsoid functions the GPU runs.
//
// Written in the common subset of GLSL (>= 1.50) and C++ with GLM (Documentation/geodesy.md,
// "The shader-math library"), so this very
// text is compiled into shaders by the Rendering module and, through vtkGlobeShaderMath.h,
// into C++ unit tests in float (GPU semantics) and in double. Rules of the subset:
//   - no swizzles beyond .x/.y/.z/.w; literals carry an f suffix (exact binary values only);
//   - out-parameters are written GLOBE_OUT(type), in-out ones GLOBE_INOUT(type); no arrays,
//     no structs;
//   - every helper starts with globe_ and is free of side effects.
// Lengths may be in any unit (metres, or units of a radius); each function normalises by the
// largest radius internally so squares stay in range for 1 mm .. 1e11 m.

// Iteration cap of the geodetic Newton solver; its relative step tolerance comes from the
// prelude (GLOBE_NEWTON_TOLERANCE): a few ulp of the precision the text is compiled in.
const int GLOBE_NEWTON_MAX_ITERATIONS = 16;

float globe_maxComponent(vec3 v)
{
  return max(v.x, max(v.y, v.z));
}

float globe_minComponent(vec3 v)
{
  return min(v.x, min(v.y, v.z));
}

// Unit geodetic normal for longitude/latitude in radians.
vec3 globe_normalFromLonLat(float lon, float lat)
{
  float cosLat = cos(lat);
  return vec3(cosLat * cos(lon), cosLat * sin(lon), sin(lat));
}

// atan2(y, x) in (-pi, pi] to ~2e-8 rad with + - * / only (the double C++ mirror, which
// defines GLOBE_EXACT_ATAN2, uses the library's atan2 so it stays exact). GPU atan() is an approximation
// whose accuracy GLSL does not specify (on llvmpipe it put texture lookups metres off); this
// is Abramowitz & Stegun 4.4.49 (|error| <= 2e-8 on [0, 1]) after reduction to that range.
#ifdef GLOBE_EXACT_ATAN2
float globe_atan2(float y, float x)
{
  return atan(y, x);
}
#else
float globe_atan2(float y, float x)
{
  float ax = abs(x);
  float ay = abs(y);
  float big = max(ax, ay);
  if (!(big > 0.0f))
  {
    return 0.0f;
  }
  float t = min(ax, ay) / big;
  float t2 = t * t;
  float a = ((((((( -0.0040540580f * t2 + 0.0218612288f) * t2 - 0.0559098861f) * t2 +
    0.0964200441f) * t2 - 0.1390853351f) * t2 + 0.1994653599f) * t2 - 0.3332985605f) * t2 +
    0.9999993329f) * t;
  if (ay > ax)
  {
    a = 1.5707963267948966f - a;
  }
  if (x < 0.0f)
  {
    a = 3.1415926535897932f - a;
  }
  return y < 0.0f ? -a : a;
}
#endif

// Longitude in (-pi, pi] and latitude in [-pi/2, pi/2] of a unit normal. atan2 for both:
// asin loses precision near the poles.
void globe_lonLatFromNormal(vec3 n, GLOBE_OUT(float) lon, GLOBE_OUT(float) lat)
{
  lon = globe_atan2(n.y, n.x);
  lat = globe_atan2(n.z, sqrt(n.x * n.x + n.y * n.y));
}

// atan2(y, x) with full relative accuracy for angles up to 14 degrees (|y| <= x / 4: odd Taylor
// series, relative error < 2e-11), globe_atan2 beyond. The offsets from a local origin are such
// angles, and globe_atan2's polynomial is accurate only to 2e-8 rad absolutely (13 cm on the
// Earth).
float globe_atan2Offset(float y, float x)
{
  if (x > 0.0f && abs(y) <= 0.25f * x)
  {
    float t = y / x;
    float t2 = t * t;
    return t * (1.0f - t2 * (0.33333333333333333f - t2 * (0.2f - t2 * (0.14285714285714286f -
      t2 * (0.11111111111111111f - t2 * (0.09090909090909091f - t2 * (0.07692307692307693f -
      t2 * 0.06666666666666667f)))))));
  }
  return globe_atan2(y, x);
}

// float(2 pi) and the rest, and the grid of the hi parts below (2^-12 rad).
const float GLOBE_TWO_PI_HI = 6.2831854820251465f;
const float GLOBE_TWO_PI_LO = -1.7484555314695172e-07f;
const float GLOBE_HI_GRID = 4096.0f;

// A value given as base (hi + lo) + delta, as a hi + lo pair whose hi is the value rounded to a
// multiple of 2^-12 and whose lo is the small rest. Both hi - base.hi and, for any other number
// that is a multiple of 2^-12 (a layer's edge), hi - that number are exact in float, so the
// pair can be differenced without cancellation; and hi is the value to 1.2e-4, which is what
// range checks (a projection's domain, the wrap of longitudes) need. `turn` (0, +-1) adds
// whole turns of 2 pi, in hi + lo.
void globe_splitOnGrid(float baseHi, float baseLo, float delta, float turn, GLOBE_OUT(float) hi,
  GLOBE_OUT(float) lo)
{
  hi = floor((baseHi + delta + turn * GLOBE_TWO_PI_HI) * GLOBE_HI_GRID + 0.5f) / GLOBE_HI_GRID;
  lo = ((baseHi + turn * GLOBE_TWO_PI_HI) - hi) + ((baseLo + turn * GLOBE_TWO_PI_LO) + delta);
}

// Geodetic longitude and latitude, each as a hi + lo pair (globe_splitOnGrid: hi on a 2^-12 rad
// grid, the longitude's in [-pi, pi]), of the point in direction reference + offset (body
// scaled space), from a local origin: `reference` is a direction whose (lon, lat) the CPU
// computed in double and passes as hi + lo (referenceLonLat: lon hi, lon lo, lat hi, lat lo),
// `offset` the (small) difference of the point's direction from it. Only products of the
// offset are formed, never a difference of two numbers near 1 or pi, so the pairs are as
// precise as the offset (a float longitude near +-pi is 1.5 m on the Earth; a float unit
// direction 0.4 m). A reference on the polar axis has no longitude: there the point's own
// longitude is taken (within 6 m of the axis a float longitude is 1.5 mm per km from it).
void globe_geodeticFromOffset(vec3 reference, vec4 referenceLonLat, vec3 offset,
  vec3 radiiScaled, GLOBE_OUT(float) lonHi, GLOBE_OUT(float) lonLo, GLOBE_OUT(float) latHi,
  GLOBE_OUT(float) latLo)
{
  // Geodetic normals point along direction / radii: only angles of these are needed.
  vec3 q0 = reference / radiiScaled;
  vec3 dq = offset / radiiScaled;
  vec3 q = q0 + dq;
  float rho02 = q0.x * q0.x + q0.y * q0.y;
  float rho0 = sqrt(rho02);
  float rho = sqrt(q.x * q.x + q.y * q.y);
  // rho - rho0 and the angles between (rho0, q0.z) and (rho, q.z), and between q0.xy and q.xy,
  // as atan2(cross, dot) with the cross products in the offset only.
  float dRho = (dq.x * (2.0f * q0.x + dq.x) + dq.y * (2.0f * q0.y + dq.y)) / max(rho + rho0, 1e-30f);
  float dLat = globe_atan2Offset(rho0 * dq.z - q0.z * dRho, rho0 * rho + q0.z * q.z);
  globe_splitOnGrid(referenceLonLat.z, referenceLonLat.w, dLat, 0.0f, latHi, latLo);
  bool polar = !(rho02 > 1e-12f);
  float baseHi = polar ? 0.0f : referenceLonLat.x;
  float baseLo = polar ? 0.0f : referenceLonLat.y;
  float dLon = polar ? globe_atan2(q.y, q.x)
                     : globe_atan2Offset(q0.x * dq.y - q0.y * dq.x, q0.x * q.x + q0.y * q.y);
  float rough = baseHi + dLon;
  float turn = rough > 3.14159265f ? -1.0f : (rough < -3.14159265f ? 1.0f : 0.0f);
  globe_splitOnGrid(baseHi, baseLo, dLon, turn, lonHi, lonLo);
}

// Unit normal of the ellipsoid at a point on (or near) its surface: normalize(p / radii^2).
vec3 globe_geodeticSurfaceNormal(vec3 p, vec3 radii)
{
  float unit = globe_maxComponent(radii);
  vec3 r = radii / unit;
  return normalize((p / unit) / (r * r));
}

// The surface point whose geodetic normal is n (unit).
vec3 globe_surfaceFromNormal(vec3 n, vec3 radii)
{
  float unit = globe_maxComponent(radii);
  vec3 r = radii / unit;
  vec3 k = r * r * n;
  return (k * inversesqrt(dot(k, n))) * unit;
}

vec3 globe_geodeticToCartesian(float lon, float lat, float height, vec3 radii)
{
  vec3 n = globe_normalFromLonLat(lon, lat);
  return globe_surfaceFromNormal(n, radii) + n * height;
}

// The surface point on the line from the centre through p (Cozzi & Ring, eq. 2.11). The
// centre itself maps to the end of the shortest axis.
vec3 globe_scaleToGeocentricSurface(vec3 p, vec3 radii)
{
  float unit = globe_maxComponent(radii);
  vec3 q = (p / unit) / (radii / unit);
  float q2 = dot(q, q);
  if (!(q2 > 0.0f))
  {
    float rmin = globe_minComponent(radii);
    return rmin == radii.z ? vec3(0.0f, 0.0f, rmin)
                           : (rmin == radii.y ? vec3(0.0f, rmin, 0.0f) : vec3(rmin, 0.0f, 0.0f));
  }
  return p * inversesqrt(q2);
}

// The surface point whose geodetic normal passes through p (the nearest one).
//
// Cozzi & Ring's Newton iteration (Listing 2.9) solves S(alpha) = sum q_i^2 r_i^2/(r_i^2 +
// alpha)^2 - 1 = 0, but never returns for (0, 0, 1 m), overshoots past the pole of S at
// alpha = -min(r)^2 for points inside the body, and in float loses alpha + min(r)^2 to
// cancellation near the centre. Here the unknown is s = alpha + min(r)^2 > 0 (Eberly's
// form): G(s) = sum (k_i / (s + d_i))^2 - 1 with k_i = r_i q_i and d_i = r_i^2 - min(r)^2 >= 0,
// convex and decreasing, bracketed by [lo, hi] with lo = |k| over the shortest axes and
// hi = |k|. Newton starts from Cozzi's guess clamped into the bracket; after one step it
// approaches the root from the left, monotonically, and the loop is capped.
// A point on the plane of the longer axes inside the evolute (lo == 0, G(0) < 0) has its
// nearest point off that plane, at s = 0, in closed form.
vec3 globe_scaleToGeodeticSurface(vec3 p, vec3 radii, GLOBE_OUT(int) iterations)
{
  float unit = globe_maxComponent(radii);
  vec3 r = radii / unit;
  vec3 q = p / unit;
  vec3 r2 = r * r;
  float rmin2 = globe_minComponent(r2);
  vec3 d = r2 - rmin2;
  vec3 k = r * q;
  vec3 k2 = k * k;
  vec3 isShortest = vec3(d.x > 0.0f ? 0.0f : 1.0f, d.y > 0.0f ? 0.0f : 1.0f, d.z > 0.0f ? 0.0f : 1.0f);
  float lo = sqrt(dot(k2, isShortest));
  float hi = sqrt(dot(k2, vec3(1.0f, 1.0f, 1.0f)));
  iterations = 0;

  // One shortest axis (z first: the pole of an oblate body) for the closed forms below.
  vec3 shortest = isShortest.z > 0.0f ? vec3(0.0f, 0.0f, 1.0f)
                                      : (isShortest.y > 0.0f ? vec3(0.0f, 1.0f, 0.0f)
                                                             : vec3(1.0f, 0.0f, 0.0f));
  if (!(hi > 0.0f))
  {
    // The centre: the end of the shortest axis.
    return r * shortest * unit;
  }
  if (!(lo > 0.0f))
  {
    // On the plane of the longer axes; inside the evolute the nearest point leaves it.
    vec3 xde = k / (d + isShortest) * (vec3(1.0f, 1.0f, 1.0f) - isShortest);
    float discr = 1.0f - dot(xde, xde);
    if (discr > 0.0f)
    {
      return (r * xde + r * shortest * sqrt(discr)) * unit;
    }
    // Otherwise the root is in s > 0; keep 0/0 out of the shortest-axis terms.
    lo = 1e-30f;
  }

  // Cozzi's initial guess (the geocentric surface point), as s.
  float beta = inversesqrt(dot(q * q, 1.0f / r2));
  float alpha0 = (1.0f - beta) * length(q) / (beta * length(q / r2));
  float s = clamp(rmin2 + alpha0, lo, hi);

  for (int i = 0; i < GLOBE_NEWTON_MAX_ITERATIONS; i++)
  {
    iterations = iterations + 1;
    vec3 e = k / (s + d);
    vec3 e2 = e * e;
    float g = e2.x + e2.y + e2.z - 1.0f;
    vec3 f = e2 / (s + d);
    float dg = -2.0f * (f.x + f.y + f.z);
    if (g > 0.0f)
    {
      lo = s;
    }
    else
    {
      hi = s;
    }
    float next = dg < 0.0f ? s - g / dg : 0.5f * (lo + hi);
    next = (next >= lo && next <= hi) ? next : 0.5f * (lo + hi);
    float step = abs(next - s);
    s = next;
    // Converged when the step is a few ulp of s, or when the residual is down to rounding
    // noise (then s cannot get better: its remaining steps are that noise over dg).
    if (!(step > GLOBE_NEWTON_TOLERANCE * s) || !(abs(g) > 4.0f * GLOBE_NEWTON_TOLERANCE))
    {
      break;
    }
  }
  return (r2 * q / (s + d)) * unit;
}

// Body-fixed Cartesian -> geodetic (radians, height in the unit of p).
void globe_cartesianToGeodetic(vec3 p, vec3 radii, GLOBE_OUT(float) lon, GLOBE_OUT(float) lat,
  GLOBE_OUT(float) height)
{
  int iterations = 0;
  vec3 s = globe_scaleToGeodeticSurface(p, radii, iterations);
  vec3 n = globe_geodeticSurfaceNormal(s, radii);
  globe_lonLatFromNormal(n, lon, lat);
  height = dot(p - s, n);
}

// Ray origin + t * direction against the ellipsoid, in its scaled (unit sphere) space with
// the stable quadratic formula. Returns the number of hits; t0 <= t1 (t may be negative).
int globe_intersectEllipsoid(vec3 origin, vec3 direction, vec3 radii, GLOBE_OUT(float) t0,
  GLOBE_OUT(float) t1)
{
  vec3 o = origin / radii;
  vec3 d = direction / radii;
  float a = dot(d, d);
  float b = dot(o, d);
  float c = dot(o, o) - 1.0f;
  float disc = b * b - a * c;
  t0 = 0.0f;
  t1 = 0.0f;
  if (!(disc >= 0.0f) || !(a > 0.0f))
  {
    return 0;
  }
  float root = sqrt(disc);
  float q = -(b + (b < 0.0f ? -root : root));
  float ta = q / a;
  float tb = q != 0.0f ? c / q : ta;
  t0 = min(ta, tb);
  t1 = max(ta, tb);
  return disc > 0.0f ? 2 : 1;
}
