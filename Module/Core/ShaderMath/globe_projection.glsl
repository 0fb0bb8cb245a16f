// globe_projection.glsl: forward map projections for the composition shaders, geodetic
// (lon, lat) in radians -> a raster's normalized texture coordinates (u east, v south, [0, 1]
// over the raster's outer pixel edges). Common GLSL/C++ subset (see globe_ellipsoid.glsl).
//
// Float-safe by construction (Mahsman's trick; Documentation/projections.md, "GLSL
// parameterisation"): vtkGlobeMapProjection::
// ComputeShaderParameters evaluates the projection in double at a reference point r inside
// (or next to) the raster, and the GPU only computes the DIFFERENCE of the projection from
// r with formulas that keep relative accuracy for small differences. No planet radius, false
// northing or absolute northing enters float arithmetic: they are folded into a 2x2 matrix
// and r's texture coordinates. The conformal kinds (and equirectangular) are functions of
// w = psi + i*lambda (psi the isometric latitude):
//   equirectangular:  (dLon, dLat)                       linear
//   Mercator:         (dLon, psi - psi_r)                linear in w
//   polar stereogr.:  F = F_r * (exp(-(w - w_r)) - 1)    complex, F_r folded into the matrix
//   transverse Merc.: zeta' = gd(w), dzeta' = 2 atan(sinh(dw/2) / cosh(w_r + dw/2)), then
//                     Krueger's alpha_1, alpha_2 terms (their difference is small)
//   Lambert conf. conic: F = F_r * (exp(-n (w - w_r)) - 1)  (n = 1: polar stereographic)
// and the equal-area kinds are functions of q(lat) (the authalic function) and lambda:
//   cylindrical:      (dLon, q - q_r)                    linear
//   Albers, polar Lambert azimuthal: F = F_r * (sqrt(1 + K (q - q_r)) exp(i n dLon) - 1),
//   oblique Lambert azimuthal: the authalic sphere's azimuthal offsets (see its function).
// and the sinusoidal projection (a sphere, MODIS) is
//   (dLon cos lat + (lon_r - lon0)(cos lat - cos lat_r), dLat)   cos difference as a product
// Inputs are hi + lo pairs (lo may be 0): differences to the reference are taken hi - hi
// (exact by Sterbenz where it matters) plus lo - lo.
//
// Parameters: seven vec4 per layer (GLOBE_PROJECTION_VECTORS), filled by the CPU class:
//   p0 = (lon_r hi, lon_r lo, twin hi, twin lo)  twin = lon_r -+ 2 pi, for the wrap
//   p1 = (lat_r hi, lat_r lo, sin lat_r, cos lat_r)   (polar: lat times the hemisphere sign)
//   p2 = (u_r, v_r, e, hemisphere sign)
//   p3 = (m00, m01, m10, m11): (du, dv) = M (X, Y)
//   p4 = (central meridian, longitude half width, latitude min, latitude max): the domain
//   p5, p6: kind-specific (polar: p5.x = t(lat_r); transverse Mercator: p5 = (psi_r,
//       lon_r - lon0, xi'_r, eta'_r), p6 = (C_r xi, C_r eta, alpha_1, alpha_2); Lambert
//       conformal conic: p5 = (t(lat_r), n), p6.x = lon_r - lon0; Albers and Lambert
//       azimuthal equal-area: p5 = (K, n), K = -(1 - e^2) a^2 / (n rho_r^2), p6 = (lon_r -
//       lon0, (1 - e^2) / (q_p - q_r) for the azimuthal projection, else 0); oblique Lambert
//       azimuthal equal-area: p5 = (sin b_r, cos b_r, sin b1, cos b1), p6 = (lon_r - lon0,
//       (1 - e^2) / q_p, sin(lon_r - lon0), cos(lon_r - lon0)); sinusoidal:
//       p6.x = lon_r - lon0).
// Points outside the domain return (-1, -1): outside every raster.
//
// Transcendentals are polynomials here (GLSL leaves sin/exp/log/atan accuracy to the driver;
// llvmpipe's atan was metres off). The double C++ mirror defines GLOBE_EXACT_MATH and uses the
// library functions instead, so it checks the formulas free of the polynomials' rounding.

const int GLOBE_PROJECTION_VECTORS = 7;

const float GLOBE_PROJ_HALF_PI_HI = 1.5707963705062866f;
const float GLOBE_PROJ_HALF_PI_LO = -4.371138828673793e-08f;
const float GLOBE_PROJ_PI_HI = 3.1415927410125732f;
const float GLOBE_PROJ_PI_LO = -8.742277657347586e-08f;

#ifdef GLOBE_EXACT_MATH
void globe_sinCos(float x, GLOBE_OUT(float) s, GLOBE_OUT(float) c)
{
  s = sin(x);
  c = cos(x);
}
float globe_exp(float x)
{
  return exp(x);
}
float globe_expm1(float x)
{
  return expm1(x);
}
float globe_log1p(float x)
{
  return log1p(x);
}
float globe_sinh(float x)
{
  return sinh(x);
}
float globe_cosh(float x)
{
  return cosh(x);
}
float globe_atan2Rel(float y, float x)
{
  return atan(y, x);
}
float globe_log(float x)
{
  return log(x);
}
#else
// sin and cos for |x| <= ~4: Cody-Waite reduction by pi/2 (k * 1.5703125 is exact for the
// few quadrants used), then Taylor polynomials on |r| <= pi/4 (relative error ~1 ulp).
void globe_sinCos(float x, GLOBE_OUT(float) s, GLOBE_OUT(float) c)
{
  float k = floor(x * 0.6366197466850281f + 0.5f);
  float r = ((x - k * 1.5703125f) - k * 0.0004838267923332751f) - k * 2.5632829192545614e-12f;
  float r2 = r * r;
  float sr = r + r * r2 * (-0.16666666666666667f + r2 * (0.008333333333333333f +
    r2 * (-0.0001984126984126984f + r2 * (2.755731922398589e-06f +
    r2 * -2.505210838544172e-08f))));
  float cr = 1.0f - 0.5f * r2 + r2 * r2 * (0.041666666666666667f +
    r2 * (-0.001388888888888889f + r2 * (2.48015873015873e-05f +
    r2 * (-2.755731922398589e-07f + r2 * 2.08767569878681e-09f))));
  float q = k - 4.0f * floor(k * 0.25f);
  if (q < 0.5f)
  {
    s = sr;
    c = cr;
  }
  else if (q < 1.5f)
  {
    s = cr;
    c = -sr;
  }
  else if (q < 2.5f)
  {
    s = -sr;
    c = -cr;
  }
  else
  {
    s = -cr;
    c = sr;
  }
}

// exp(x) - 1 for |x| <= 0.35 (Taylor; relative error ~1 ulp).
float globe_expm1Small(float x)
{
  return x * (1.0f + x * (0.5f + x * (0.16666666666666667f + x * (0.041666666666666667f +
    x * (0.008333333333333333f + x * (0.001388888888888889f + x * (0.0001984126984126984f +
    x * (2.48015873015873e-05f + x * 2.755731922398589e-06f))))))));
}

// 2^k for an integral k in [-126, 127], exactly (products of powers of two).
float globe_pow2(float k)
{
  float m = abs(k);
  float b = k < 0.0f ? 0.5f : 2.0f;
  float p = 1.0f;
  for (int i = 0; i < 7; i++)
  {
    float h = floor(m * 0.5f);
    if (m - 2.0f * h > 0.5f)
    {
      p = p * b;
    }
    m = h;
    if (i < 6)
    {
      b = b * b;
    }
  }
  return p;
}

// exp(x): x = k ln2 + r with ln2 in two parts (k * 0.693145751953125 is exact).
float globe_exp(float x)
{
  float y = clamp(x, -87.0f, 88.0f);
  float k = floor(y * 1.4426950216293335f + 0.5f);
  float r = (y - k * 0.693145751953125f) - k * 1.428606765330187e-06f;
  return (1.0f + globe_expm1Small(r)) * globe_pow2(k);
}

float globe_expm1(float x)
{
  return abs(x) < 0.35f ? globe_expm1Small(x) : globe_exp(x) - 1.0f;
}

// atanh(s) for |s| <= 0.172 (odd Taylor series; relative error ~1 ulp).
float globe_atanhSmall(float s)
{
  float s2 = s * s;
  return s * (1.0f + s2 * (0.33333333333333333f + s2 * (0.2f + s2 * (0.14285714285714286f +
    s2 * (0.11111111111111111f + s2 * (0.09090909090909091f + s2 * 0.07692307692307693f))))));
}

// log(x), x > 0: exact power-of-two steps bring x into [1/sqrt2, sqrt2], then 2 atanh.
float globe_log(float x)
{
  float m = max(x, 1e-37f);
  float k = 0.0f;
  if (m >= 1.8446744073709552e+19f) { m = m * 5.421010862427522e-20f; k = k + 64.0f; }
  if (m >= 4294967296.0f) { m = m * 2.3283064365386963e-10f; k = k + 32.0f; }
  if (m >= 65536.0f) { m = m * 1.52587890625e-05f; k = k + 16.0f; }
  if (m >= 256.0f) { m = m * 0.00390625f; k = k + 8.0f; }
  if (m >= 16.0f) { m = m * 0.0625f; k = k + 4.0f; }
  if (m >= 4.0f) { m = m * 0.25f; k = k + 2.0f; }
  if (m >= 2.0f) { m = m * 0.5f; k = k + 1.0f; }
  if (m < 1.0842021724855044e-19f) { m = m * 1.8446744073709552e+19f; k = k - 64.0f; }
  if (m < 4.656612873077393e-10f) { m = m * 4294967296.0f; k = k - 32.0f; }
  if (m < 3.0517578125e-05f) { m = m * 65536.0f; k = k - 16.0f; }
  if (m < 0.0078125f) { m = m * 256.0f; k = k - 8.0f; }
  if (m < 0.125f) { m = m * 16.0f; k = k - 4.0f; }
  if (m < 0.5f) { m = m * 4.0f; k = k - 2.0f; }
  if (m < 1.0f) { m = m * 2.0f; k = k - 1.0f; }
  if (m > 1.4142135381698608f) { m = m * 0.5f; k = k + 1.0f; }
  return k * 0.693145751953125f +
    (k * 1.428606765330187e-06f + 2.0f * globe_atanhSmall((m - 1.0f) / (m + 1.0f)));
}

// log(1 + x), x > -1, relative accuracy for small x: 2 atanh(x / (2 + x)).
float globe_log1p(float x)
{
  return abs(x) < 0.29f ? 2.0f * globe_atanhSmall(x / (2.0f + x)) : globe_log(1.0f + x);
}

float globe_sinh(float x)
{
  if (abs(x) < 0.35f)
  {
    float x2 = x * x;
    return x * (1.0f + x2 * (0.16666666666666667f + x2 * (0.008333333333333333f +
      x2 * (0.0001984126984126984f + x2 * 2.755731922398589e-06f))));
  }
  float ex = globe_exp(x);
  return 0.5f * (ex - 1.0f / ex);
}

float globe_cosh(float x)
{
  float ex = globe_exp(x);
  return 0.5f * (ex + 1.0f / ex);
}

// atan(t) for |t| <= 1 with relative accuracy near 0 (globe_atan2's polynomial is accurate
// only absolutely): pi/4 + atan((t-1)/(t+1)) above tan(pi/8), Taylor series below.
float globe_atanUnit(float t)
{
  float at = abs(t);
  float base = 0.0f;
  float u = at;
  if (at > 0.41421356f)
  {
    u = (at - 1.0f) / (at + 1.0f);
    base = 0.7853981852531433f;
  }
  float u2 = u * u;
  float p = u * (1.0f + u2 * (-0.33333333333333333f + u2 * (0.2f + u2 * (-0.14285714285714286f +
    u2 * (0.11111111111111111f + u2 * (-0.09090909090909091f + u2 * (0.07692307692307693f +
    u2 * (-0.06666666666666667f + u2 * (0.058823529411764705f + u2 * (-0.05263157894736842f +
    u2 * 0.047619047619047616f))))))))));
  float r = base + p;
  return t < 0.0f ? -r : r;
}

// atan2(y, x) in (-pi, pi], relatively accurate for small angles.
float globe_atan2Rel(float y, float x)
{
  float ax = abs(x);
  float ay = abs(y);
  if (!(max(ax, ay) > 0.0f))
  {
    return 0.0f;
  }
  float a = ay <= ax ? globe_atanUnit(ay / ax)
                     : (GLOBE_PROJ_HALF_PI_HI - globe_atanUnit(ax / ay)) + GLOBE_PROJ_HALF_PI_LO;
  if (x < 0.0f)
  {
    a = (GLOBE_PROJ_PI_HI - a) + GLOBE_PROJ_PI_LO;
  }
  return y < 0.0f ? -a : a;
}
#endif

#ifdef GLOBE_EXACT_MATH
float globe_atanh(float s)
{
  return atanh(s);
}
float globe_asinh(float z)
{
  return asinh(z);
}
float globe_atanhRatio(float x)
{
  return x == 0.0f ? 1.0f : atanh(x) / x;
}
#else
// atanh(s), |s| < 1, relatively accurate for small s (the series below 0.17).
float globe_atanh(float s)
{
  return abs(s) < 0.17f ? globe_atanhSmall(s) : 0.5f * globe_log1p(2.0f * s / (1.0f - s));
}

// asinh(z): Taylor series below 0.25 (relative error ~1 ulp), log1p above; |z| is capped at
// 1e15 (the pole).
float globe_asinh(float z)
{
  float az = min(abs(z), 1e15f);
  float r = 0.0f;
  if (az < 0.25f)
  {
    float z2 = az * az;
    r = az * (1.0f + z2 * (-0.16666666666666667f + z2 * (0.075f + z2 * (-0.044642857142857144f +
      z2 * (0.030381944444444444f + z2 * (-0.022372159090909092f + z2 * (0.017352764423076924f +
      z2 * -0.01396484375f)))))));
  }
  else
  {
    r = globe_log1p(az + az * az / (1.0f + sqrt(1.0f + az * az)));
  }
  return z < 0.0f ? -r : r;
}

// atanh(x) / x for |x| <= 0.172 (the series of globe_atanhSmall without its factor x).
float globe_atanhRatio(float x)
{
  float s2 = x * x;
  return 1.0f + s2 * (0.33333333333333333f + s2 * (0.2f + s2 * (0.14285714285714286f +
    s2 * (0.11111111111111111f + s2 * (0.09090909090909091f + s2 * 0.07692307692307693f)))));
}
#endif

// sin and cos of a latitude given as hi + lo; the cosine comes from the colatitude, whose hi
// difference is exact near the poles, so it keeps relative accuracy up to them.
void globe_latitudeSinCos(float latHi, float latLo, GLOBE_OUT(float) s, GLOBE_OUT(float) c)
{
  float sg = latHi < 0.0f ? -1.0f : 1.0f;
  // float(pi/2) lies 4.4e-8 rad beyond the pole: clamp, so the pole is the pole.
  float colat =
    max((GLOBE_PROJ_HALF_PI_HI - sg * latHi) + (GLOBE_PROJ_HALF_PI_LO - sg * latLo), 0.0f);
  float sc = 0.0f;
  float cc = 0.0f;
  globe_sinCos(colat, sc, cc);
  c = sc;
  s = sg * cc;
}

// sin(lat) - sin(lat_r) = 2 cos(lat_r + dLat/2) sin(dLat/2), relatively accurate: the cosine of
// the mid latitude comes from its colatitude, taken from lat_r's hi + lo.
float globe_sineDifference(float dLat, vec4 p1)
{
  // |lat_r|'s colatitude: near pi (the south) it would lose the cosine's relative accuracy.
  float sg = p1.x < 0.0f ? -1.0f : 1.0f;
  float colatMid =
    ((GLOBE_PROJ_HALF_PI_HI - sg * p1.x) + (GLOBE_PROJ_HALF_PI_LO - sg * p1.y)) - sg * 0.5f * dLat;
  float cm = 0.0f;
  float sm = 0.0f;
  globe_sinCos(colatMid, cm, sm);
  float sh = 0.0f;
  float ch = 0.0f;
  globe_sinCos(0.5f * dLat, sh, ch);
  return 2.0f * cm * sh;
}

// psi(lat) - psi(lat_r) (isometric latitudes, eccentricity e) from dSin = sin lat - sin lat_r
// and the sines and cosines of both latitudes, relatively accurate for small differences:
//   asinh(dSin / (cos lat cos lat_r)) - e atanh(e dSin / (1 - e^2 sin lat sin lat_r)).
float globe_isometricLatitudeDifference(float dSin, float sinLat, float cosLat, float sinLatR,
  float cosLatR, float e)
{
  float g = globe_asinh(dSin / max(cosLat * cosLatR, 1e-30f));
  return g - e * globe_atanh(e * dSin / (1.0f - e * e * sinLat * sinLatR));
}

// (q(lat) - q(lat_r)) / (1 - e^2), q the authalic function of the equal-area projections
// (Snyder 3-12: q / (1 - e^2) = sin / (1 - e^2 sin^2) + atanh(e sin) / e), from dSin =
// sin lat - sin lat_r, relatively accurate for small differences (both terms are differences
// written as products: atanh a - atanh b = atanh((a - b) / (1 - a b))). e = 0: 2 dSin.
float globe_equalAreaDifference(float dSin, float sinLat, float sinLatR, float e)
{
  float e2 = e * e;
  float w = 1.0f - e2 * sinLat * sinLatR;
  float first = dSin * (1.0f + e2 * sinLat * sinLatR) /
    ((1.0f - e2 * sinLat * sinLat) * (1.0f - e2 * sinLatR * sinLatR));
  return first + dSin / w * globe_atanhRatio(e * dSin / w);
}

// Longitude and latitude differences from the reference point (hi - hi + lo - lo); the
// longitude difference is wrapped into [-pi, pi] by taking it from the reference's 2 pi twin
// (lon_r - 2 pi for lon_r >= 0, which serves differences below -pi; lon_r + 2 pi else). The
// wrap is decided on hi + lo and only in the twin's direction: a hi part alone (on its
// 2^-12 rad grid) rounds up to 1.2e-4 rad past pi, and a point just inside the antimeridian
// took the wrong twin, 2 pi away.
void globe_projectionDelta(float lonHi, float lonLo, float latHi, float latLo, vec4 p0, vec4 p1,
  GLOBE_OUT(float) dLon, GLOBE_OUT(float) dLat)
{
  float d = (lonHi - p0.x) + (lonLo - p0.y);
  bool twin = p0.z > p0.x ? d > GLOBE_PROJ_PI_HI : d < -GLOBE_PROJ_PI_HI;
  dLon = twin ? (lonHi - p0.z) + (lonLo - p0.w) : d;
  dLat = (latHi - p1.x) + (latLo - p1.y);
}

// The projection's domain (p4): longitude within a half width of the central meridian and a
// latitude band. Rough float checks: only the texture coordinates need to be precise. Callers
// pass hi + lo: a hi part alone rounds up to 1.2e-4 rad past the pole or the antimeridian.
bool globe_projectionInDomain(float lon, float lat, vec4 p4)
{
  float d = lon - p4.x;
  d = d > 3.14159265f ? d - 6.2831853f : (d < -3.14159265f ? d + 6.2831853f : d);
  return abs(d) <= p4.y && lat >= p4.z && lat <= p4.w;
}

vec2 globe_projectionTexture(float x, float y, vec4 p2, vec4 p3)
{
  return vec2(p2.x + (p3.x * x + p3.y * y), p2.y + (p3.z * x + p3.w * y));
}

// Equirectangular (any standard parallel, central meridian; geographic EPSG:4326 too).
vec2 globe_projectEquirectangular(float lonHi, float lonLo, float latHi, float latLo, vec4 p0,
  vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  if (!globe_projectionInDomain(lonHi + lonLo, latHi + latLo, p4))
  {
    return vec2(-1.0f, -1.0f);
  }
  float dLon = 0.0f;
  float dLat = 0.0f;
  globe_projectionDelta(lonHi, lonLo, latHi, latLo, p0, p1, dLon, dLat);
  return globe_projectionTexture(dLon, dLat, p2, p3);
}

// What the projections but equirectangular start from: Inside false outside the projection's
// domain; else the (lon, lat) offsets from the reference, sin and cos of the latitude and the
// difference of its sine from the reference's, with latitudes mirrored by hemi (-1: a south
// polar aspect).
struct GlobeProjectionStart
{
  bool Inside;
  float DLon;
  float DLat;
  float SinLat;
  float CosLat;
  float DSin;
};

GlobeProjectionStart globe_conformalStart(float lonHi, float lonLo, float latHi, float latLo,
  float hemi, vec4 p0, vec4 p1, vec4 p4)
{
  GlobeProjectionStart s;
  s.Inside = globe_projectionInDomain(lonHi + lonLo, latHi + latLo, p4);
  s.DLon = 0.0f;
  s.DLat = 0.0f;
  s.SinLat = 0.0f;
  s.CosLat = 0.0f;
  s.DSin = 0.0f;
  if (s.Inside)
  {
    globe_projectionDelta(lonHi, lonLo, hemi * latHi, hemi * latLo, p0, p1, s.DLon, s.DLat);
    globe_latitudeSinCos(hemi * latHi, hemi * latLo, s.SinLat, s.CosLat);
    s.DSin = globe_sineDifference(s.DLat, p1);
  }
  return s;
}

// Mercator on the ellipsoid (e = p2.z) and Web Mercator (e = 0: spherical formulas on the
// geodetic latitude).
vec2 globe_projectMercator(float lonHi, float lonLo, float latHi, float latLo, vec4 p0, vec4 p1,
  vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  GlobeProjectionStart s = globe_conformalStart(lonHi, lonLo, latHi, latLo, 1.0f, p0, p1, p4);
  if (!s.Inside)
  {
    return vec2(-1.0f, -1.0f);
  }
  float dPsi = globe_isometricLatitudeDifference(s.DSin, s.SinLat, s.CosLat, p1.z, p1.w, p2.z);
  return globe_projectionTexture(s.DLon, dPsi, p2, p3);
}

// The projections with an apex (polar stereographic, the conics, polar Lambert azimuthal
// equal-area) put a point at F = rho e^(i theta) from the apex: rho / rho_r = E and
// theta - theta_r = dTheta, so its offset from the reference is F_r (E e^(i dTheta) - 1) =
// F_r (X + iY), X = (E - 1) cos dTheta - 2 sin^2(dTheta / 2), Y = E sin dTheta; F_r (and the
// hemisphere's mirror) is in the matrix p3.
vec2 globe_azimuthalOffset(float ratio, float ratioM1, float dTheta, vec4 p2, vec4 p3)
{
  float sl = 0.0f;
  float cl = 0.0f;
  globe_sinCos(dTheta, sl, cl);
  float sh = 0.0f;
  float ch = 0.0f;
  globe_sinCos(0.5f * dTheta, sh, ch);
  return globe_projectionTexture(ratioM1 * cl - 2.0f * sh * sh, ratio * sl, p2, p3);
}

// The conics' angle from the central meridian stays in [-pi, pi] (the cone is cut opposite the
// central meridian, and n dLon is not 2 pi periodic for n < 1), but the reference's twin puts
// dLon in [-pi, pi] around the reference: add or take a turn where the two disagree.
// lonFromCentral: the reference's longitude from the central meridian (p6.x).
float globe_conicLongitudeDelta(float dLon, float lonFromCentral)
{
  float l = lonFromCentral + dLon;
  return l > GLOBE_PROJ_PI_HI ? (dLon - 2.0f * GLOBE_PROJ_PI_HI) - 2.0f * GLOBE_PROJ_PI_LO
    : (l < -GLOBE_PROJ_PI_HI ? (dLon + 2.0f * GLOBE_PROJ_PI_HI) + 2.0f * GLOBE_PROJ_PI_LO
                             : dLon);
}

// The conformal projections with an apex, north (p2.w = 1) or south (p2.w = -1, latitudes
// mirrored): polar stereographic is Lambert's conformal conic with cone constant n = 1. With
// E = (t(lat)/t(lat_r))^n = exp(-n (psi - psi_r)) and dLon = lon - lon_r, the map offset from
// the reference is F_r (E e^(i n dLon) - 1) (globe_azimuthalOffset). E - 1 comes from expm1 of
// the accurate psi difference near the reference and from the ratio of t = tan(colat/2)
// exp(e atanh(e sin lat)) elsewhere (the apex: t = 0); cut: keep n dLon within the cone's cut.
vec2 globe_conformalApex(float lonHi, float lonLo, float latHi, float latLo, float n, bool cut,
  vec4 p0, vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  float e = p2.z;
  GlobeProjectionStart s = globe_conformalStart(lonHi, lonLo, latHi, latLo, p2.w, p0, p1, p4);
  if (!s.Inside)
  {
    return vec2(-1.0f, -1.0f);
  }
  float ratio = 0.0f;
  float ratioM1 = 0.0f;
  if (abs(s.DSin) < 0.25f * s.CosLat * p1.w)
  {
    float dPsi = globe_isometricLatitudeDifference(s.DSin, s.SinLat, s.CosLat, p1.z, p1.w, e);
    ratioM1 = globe_expm1(-n * dPsi);
    ratio = 1.0f + ratioM1;
  }
  else
  {
    float t = s.CosLat / (1.0f + s.SinLat) * globe_exp(e * globe_atanh(e * s.SinLat));
    ratio = n == 1.0f ? t / p5.x : (t > 0.0f ? globe_exp(n * globe_log(t / p5.x)) : 0.0f);
    ratioM1 = ratio - 1.0f;
  }
  float dTheta = n * (cut ? globe_conicLongitudeDelta(s.DLon, p6.x) : s.DLon);
  return globe_azimuthalOffset(ratio, ratioM1, dTheta, p2, p3);
}

// Polar stereographic (p5.x = t(lat_r)).
vec2 globe_projectPolarStereographic(float lonHi, float lonLo, float latHi, float latLo,
  vec4 p0, vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  return globe_conformalApex(
    lonHi, lonLo, latHi, latLo, 1.0f, false, p0, p1, p2, p3, p4, p5, p6);
}

// Lambert conformal conic (p5 = (t(lat_r), n), n > 0 with latitudes mirrored for a southern
// apex; p6.x = lon_r - lon0).
vec2 globe_projectConformalConic(float lonHi, float lonLo, float latHi, float latLo, vec4 p0,
  vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  return globe_conformalApex(
    lonHi, lonLo, latHi, latLo, p5.y, true, p0, p1, p2, p3, p4, p5, p6);
}

// Albers equal-area conic, and Lambert azimuthal equal-area in a polar aspect (n = 1): the
// radius rho from the apex has rho^2 linear in q, so E = rho / rho_r = sqrt(1 + u) with
// u = K dq (K = p5.x, folded on the CPU) and E - 1 = u / (sqrt(1 + u) + 1).
vec2 globe_projectAlbersEqualArea(float lonHi, float lonLo, float latHi, float latLo, vec4 p0,
  vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  GlobeProjectionStart s = globe_conformalStart(lonHi, lonLo, latHi, latLo, p2.w, p0, p1, p4);
  if (!s.Inside)
  {
    return vec2(-1.0f, -1.0f);
  }
  float u = p5.x * globe_equalAreaDifference(s.DSin, s.SinLat, p1.z, p2.z);
  float root = 0.0f;
  float ratioM1 = 0.0f;
  if (p6.y > 0.0f && u < -0.5f)
  {
    // Towards the azimuthal projection's centre rho -> 0 and 1 + u cancels: E^2 =
    // (q_p - q) / (q_p - q_r) with q_p - q from 1 - sin lat = cos^2 / (1 + sin), relatively
    // accurate up to the pole (p6.y = (1 - e^2) / (q_p - q_r)).
    float toPole =
      globe_equalAreaDifference(s.CosLat * s.CosLat / (1.0f + s.SinLat), 1.0f, s.SinLat, p2.z);
    root = sqrt(toPole * p6.y);
    ratioM1 = root - 1.0f;
  }
  else
  {
    root = sqrt(max(1.0f + u, 0.0f));
    ratioM1 = u / (root + 1.0f);
  }
  float dTheta = p5.y < 1.0f ? p5.y * globe_conicLongitudeDelta(s.DLon, p6.x) : s.DLon;
  return globe_azimuthalOffset(root, ratioM1, dTheta, p2, p3);
}

// Lambert azimuthal equal-area, oblique and equatorial aspects (e.g. EPSG:3035): the spherical
// azimuthal projection of the authalic sphere (sin b = q / q_p), with D and 1 / D in the matrix.
// In the centre's frame a point's unit vector is v = (cos b sin L, cos b1 sin b - sin b1 cos b
// cos L, sin b1 sin b + cos b1 cos b cos L) (L = lon - lon0, b1 the centre's authalic latitude)
// and its offset k (vx, vy), k = sqrt(2 / (1 + vz)). From the reference: k dv + (k - k_r) v_r,
// dv from the differences of sin b, cos b, sin L and cos L written as products, and k - k_r =
// -2 dvz / ((1 + vz)(1 + vz_r)(k + k_r)): relatively accurate for small offsets. cos b comes
// from 1 - |sin b| = (q_p - |q|) / q_p, accurate up to the poles (cos b_r too, from the CPU). p5 = (sin b_r, cos b_r,
// sin b1, cos b1), p6 = (L_r, (1 - e^2) / q_p, sin L_r, cos L_r).
vec2 globe_projectObliqueAzimuthalEqualArea(float lonHi, float lonLo, float latHi, float latLo,
  vec4 p0, vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  GlobeProjectionStart s = globe_conformalStart(lonHi, lonLo, latHi, latLo, 1.0f, p0, p1, p4);
  if (!s.Inside)
  {
    return vec2(-1.0f, -1.0f);
  }
  float e = p2.z;
  float dSinB = p6.y * globe_equalAreaDifference(s.DSin, s.SinLat, p1.z, e);
  float sinB = p5.x + dSinB;
  float sg = s.SinLat < 0.0f ? -1.0f : 1.0f;
  float toPole = p6.y *
    globe_equalAreaDifference(s.CosLat * s.CosLat / (1.0f + sg * s.SinLat), 1.0f, sg * s.SinLat, e);
  float cosB = sqrt(max(toPole * (2.0f - toPole), 0.0f));
  // cos b - cos b_r as a quotient (relatively accurate away from the poles); within 1e-3 of a
  // pole the plain difference, whose terms are both accurate there (a point a rounding beyond
  // the pole has sin b off the pole but cos b = 0, and the quotient would blow that up).
  float dCosB = cosB + p5.y < 1e-3f ? cosB - p5.y : -dSinB * (sinB + p5.x) / (cosB + p5.y);
  float sm = 0.0f;
  float cm = 0.0f;
  globe_sinCos(p6.x + 0.5f * s.DLon, sm, cm);
  float sh = 0.0f;
  float ch = 0.0f;
  globe_sinCos(0.5f * s.DLon, sh, ch);
  float dSinL = 2.0f * cm * sh;
  float dCosL = -2.0f * sm * sh;
  // cos b cos L - cos b_r cos L_r
  float dCosBCosL = cosB * dCosL + dCosB * p6.w;
  float dvx = cosB * dSinL + dCosB * p6.z;
  float dvy = p5.w * dSinB - p5.z * dCosBCosL;
  float dvz = p5.z * dSinB + p5.w * dCosBCosL;
  float vxr = p5.y * p6.z;
  float vyr = p5.w * p5.x - p5.z * p5.y * p6.w;
  float onePlusR = 1.0f + (p5.z * p5.x + p5.w * p5.y * p6.w);
  float onePlus = onePlusR + dvz;
  if (!(onePlus > 0.0038053f))
  {
    return vec2(-1.0f, -1.0f); // within 5 degrees of the centre's antipode: outside the domain
  }
  float k = sqrt(2.0f / onePlus);
  float kr = sqrt(2.0f / onePlusR);
  float dk = -2.0f * dvz / (onePlus * onePlusR * (k + kr));
  return globe_projectionTexture(k * dvx + dk * vxr, k * dvy + dk * vyr, p2, p3);
}

// Lambert cylindrical equal-area (EASE-Grid 2.0 Global): linear in (dLon, dq).
vec2 globe_projectCylindricalEqualArea(float lonHi, float lonLo, float latHi, float latLo,
  vec4 p0, vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  GlobeProjectionStart s = globe_conformalStart(lonHi, lonLo, latHi, latLo, 1.0f, p0, p1, p4);
  if (!s.Inside)
  {
    return vec2(-1.0f, -1.0f);
  }
  return globe_projectionTexture(
    s.DLon, globe_equalAreaDifference(s.DSin, s.SinLat, p1.z, p2.z), p2, p3);
}

// Sinusoidal on a sphere (MODIS): x = R (lon - lon0) cos lat, y = R lat. The offset from the
// reference is X = dLon cos lat + (lon_r - lon0)(cos lat - cos lat_r), Y = dLat, with
// cos lat - cos lat_r = -2 sin(lat_r + dLat / 2) sin(dLat / 2): relatively accurate for small
// offsets. lon - lon0 lies in [-pi, pi): a point across the map's cut (the meridian opposite
// lon0) from the reference is a turn of longitude away from it.
vec2 globe_projectSinusoidal(float lonHi, float lonLo, float latHi, float latLo, vec4 p0,
  vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  if (!globe_projectionInDomain(lonHi + lonLo, latHi + latLo, p4))
  {
    return vec2(-1.0f, -1.0f);
  }
  float dLon = 0.0f;
  float dLat = 0.0f;
  globe_projectionDelta(lonHi, lonLo, latHi, latLo, p0, p1, dLon, dLat);
  // float(pi/2) lies 4.4e-8 rad beyond the pole, and y is linear in the latitude: clamp.
  dLat = clamp(dLat, (-GLOBE_PROJ_HALF_PI_HI - p1.x) + (-GLOBE_PROJ_HALF_PI_LO - p1.y),
    (GLOBE_PROJ_HALF_PI_HI - p1.x) + (GLOBE_PROJ_HALF_PI_LO - p1.y));
  float fromCentral = p6.x + dLon;
  if (fromCentral >= GLOBE_PROJ_PI_HI)
  {
    dLon = (dLon - 2.0f * GLOBE_PROJ_PI_HI) - 2.0f * GLOBE_PROJ_PI_LO;
  }
  else if (fromCentral < -GLOBE_PROJ_PI_HI)
  {
    dLon = (dLon + 2.0f * GLOBE_PROJ_PI_HI) + 2.0f * GLOBE_PROJ_PI_LO;
  }
  float sinLat = 0.0f;
  float cosLat = 0.0f;
  globe_latitudeSinCos(latHi, latLo, sinLat, cosLat);
  float sm = 0.0f;
  float cm = 0.0f;
  globe_sinCos(p1.x + (p1.y + 0.5f * dLat), sm, cm);
  float sh = 0.0f;
  float ch = 0.0f;
  globe_sinCos(0.5f * dLat, sh, ch);
  return globe_projectionTexture(dLon * cosLat - 2.0f * p6.x * sm * sh, dLat, p2, p3);
}

// Transverse Mercator (UTM): Krueger's series to alpha_2 on the conformal sphere's
// zeta' = xi' + i eta' = gd(psi + i (lon - lon0)), as differences from the reference.
vec2 globe_projectTransverseMercator(float lonHi, float lonLo, float latHi, float latLo,
  vec4 p0, vec4 p1, vec4 p2, vec4 p3, vec4 p4, vec4 p5, vec4 p6)
{
  GlobeProjectionStart s = globe_conformalStart(lonHi, lonLo, latHi, latLo, 1.0f, p0, p1, p4);
  if (!s.Inside)
  {
    return vec2(-1.0f, -1.0f);
  }
  float hx =
    0.5f * globe_isometricLatitudeDifference(s.DSin, s.SinLat, s.CosLat, p1.z, p1.w, p2.z);
  float hy = 0.5f * s.DLon;
  // Z = sinh(dw/2) / cosh(w_r + dw/2); dzeta' = 2 atan(Z).
  float sy = 0.0f;
  float cy = 0.0f;
  globe_sinCos(hy, sy, cy);
  float sx = globe_sinh(hx);
  float cx = globe_cosh(hx);
  float nr = sx * cy;
  float ni = cx * sy;
  float sb = 0.0f;
  float cb = 0.0f;
  globe_sinCos(p5.y + hy, sb, cb);
  float ma = p5.x + hx;
  float dr = globe_cosh(ma) * cb;
  float di = globe_sinh(ma) * sb;
  float dd = dr * dr + di * di;
  float zr = (nr * dr + ni * di) / dd;
  float zi = (ni * dr - nr * di) / dd;
  float dXi = globe_atan2Rel(2.0f * zr, (1.0f - zr * zr) - zi * zi);
  float dEta = 0.5f * globe_log1p(4.0f * zi / (zr * zr + (1.0f - zi) * (1.0f - zi)));
  // Krueger: zeta = zeta' + alpha_1 sin(2 zeta') + alpha_2 sin(4 zeta'), minus its value at r.
  float xi = p5.z + dXi;
  float eta = p5.w + dEta;
  float s2 = 0.0f;
  float c2 = 0.0f;
  globe_sinCos(2.0f * xi, s2, c2);
  float sh2 = globe_sinh(2.0f * eta);
  float ch2 = globe_cosh(2.0f * eta);
  float sinR = s2 * ch2; // sin(2 zeta')
  float sinI = c2 * sh2;
  float cosR = c2 * ch2; // cos(2 zeta')
  float cosI = -s2 * sh2;
  float sin4R = 2.0f * (sinR * cosR - sinI * cosI);
  float sin4I = 2.0f * (sinR * cosI + sinI * cosR);
  dXi = dXi + ((p6.z * sinR + p6.w * sin4R) - p6.x);
  dEta = dEta + ((p6.z * sinI + p6.w * sin4I) - p6.y);
  return globe_projectionTexture(dXi, dEta, p2, p3);
}
