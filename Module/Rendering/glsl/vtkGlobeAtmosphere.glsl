// Single scattering in the spirit of O'Neil (GPU Gems 2, ch. 16): Rayleigh + Mie scattering
// in an exponential atmosphere of thickness 2.5 % of the radius and scale height a quarter of
// that, the optical depth towards the sun from O'Neil's fitted scale function, the optical
// depth towards the eye integrated along the ray. Lengths in units of the body's largest
// radius (the body is taken as the unit sphere here: the shell is thin, the effect soft).
const float globe_atmInner = 1.0;
const float globe_atmOuter = 1.025;
const float globe_atmScale = 1.0 / (1.025 - 1.0);
const float globe_atmScaleDepth = 0.25;
const float globe_atmKr = 0.0025;
const float globe_atmKm = 0.0010;
const float globe_atmG = -0.95;
const vec3 globe_atmInvWavelength = vec3(5.602, 9.473, 19.644); // 1 / (0.650, 0.570, 0.475)^4
const int globe_atmSamples = 8;

// O'Neil's fit of the optical depth from a point at the surface to the top of the
// atmosphere, along a direction at angle acos(c) from the vertical (scale depth 0.25).
float globe_atmScaleFunction(float c)
{
  float x = 1.0 - c;
  return globe_atmScaleDepth * exp(-0.00287 + x * (0.459 + x * (3.83 + x * (-6.80 + x * 5.25))));
}

float globe_atmDensity(float r)
{
  return exp((globe_atmInner - r) * globe_atmScale / globe_atmScaleDepth);
}

// Ray (eye + t ray, |ray| = 1) against the sphere of radius r: entry and exit t, false if
// it misses. The closest approach is taken from the component of eye across the ray, which
// keeps precision when the eye is far away.
bool globe_atmSphere(vec3 eye, vec3 ray, float r, out float t0, out float t1)
{
  float b = dot(eye, ray);
  vec3 across = eye - b * ray;
  float c2 = r * r - dot(across, across);
  if (c2 < 0.0)
  {
    t0 = 0.0;
    t1 = 0.0;
    return false;
  }
  float c = sqrt(c2);
  t0 = -b - c;
  t1 = -b + c;
  return t1 > 0.0;
}

// In-scattered light along eye + t ray, t in [t0, t1] (t1: the ground, or where the ray
// leaves the atmosphere), and the transmittance of that segment.
void globe_atmosphere(vec3 eye, vec3 ray, float t0, float t1, vec3 light, out vec3 rayleigh,
  out vec3 mie, out vec3 transmittance)
{
  vec3 extinction = globe_atmInvWavelength * (4.0 * 3.14159265 * globe_atmKr) +
    vec3(4.0 * 3.14159265 * globe_atmKm);
  float step = (t1 - t0) / float(globe_atmSamples);
  float viewDepth = 0.0;
  vec3 sum = vec3(0.0);
  for (int i = 0; i < globe_atmSamples; ++i)
  {
    vec3 p = eye + (t0 + (float(i) + 0.5) * step) * ray;
    float r = length(p);
    float density = globe_atmDensity(r);
    float segment = density * step * globe_atmScale;
    viewDepth += 0.5 * segment;
    float sunDepth = density * globe_atmScaleFunction(dot(light, p) / r);
    sum += exp(-(sunDepth + viewDepth) * extinction) * segment;
    viewDepth += 0.5 * segment;
  }
  rayleigh = sum * globe_atmInvWavelength * globe_atmKr;
  mie = sum * globe_atmKm;
  transmittance = exp(-viewDepth * extinction);
}

vec3 globe_atmPhased(vec3 rayleigh, vec3 mie, vec3 ray, vec3 light, float intensity)
{
  float c = -dot(light, ray); // O'Neil measures the angle towards the eye
  float g = globe_atmG;
  float phaseR = 0.75 * (1.0 + c * c);
  float phaseM = 1.5 * ((1.0 - g * g) / (2.0 + g * g)) * (1.0 + c * c) /
    pow(max(1.0 + g * g - 2.0 * g * c, 1e-6), 1.5);
  return intensity * (phaseR * rayleigh + phaseM * mie);
}

// The atmosphere along a pixel's ray: from the eye (or where the ray enters the shell) to
// tEnd (the ground) or, for tEnd < 0, to where the ray meets the body or leaves the shell.
// inscatter is tone-mapped; false where the ray misses the shell.
bool globe_atmosphereAlong(vec3 eye, vec3 ray, float tEnd, vec3 light, float intensity,
  out vec3 inscatter, out vec3 transmittance)
{
  float t0, t1, g0, g1;
  inscatter = vec3(0.0);
  transmittance = vec3(1.0);
  if (!globe_atmSphere(eye, ray, globe_atmOuter, t0, t1))
  {
    return false;
  }
  t0 = max(t0, 0.0);
  if (tEnd >= 0.0)
  {
    t1 = tEnd;
  }
  else if (globe_atmSphere(eye, ray, globe_atmInner, g0, g1) && g0 > 0.0)
  {
    t1 = g0;
  }
  if (t1 <= t0)
  {
    return false;
  }
  vec3 rayleigh, mie;
  globe_atmosphere(eye, ray, t0, t1, light, rayleigh, mie, transmittance);
  inscatter = 1.0 - exp(-globe_atmPhased(rayleigh, mie, ray, light, intensity));
  return true;
}
