//VTK::System::Dec
//VTK::Output::Dec
// Grid pass, step 2 (height composition): one fragment per grid point. The grid point's
// geodetic (lon, lat) as hi + lo pairs; the height layers are composed there, filtered to the
// grid's own spacing: the step to the nearer neighbour along each grid axis chooses the level.
in vec2 texCoord;

// The grid step (radians of lon and lat) along the grid's i and j axes, towards the nearer
// neighbour: the height layers' level of detail (vtkGlobeLayerSet's GLOBE_GRID_FOOTPRINT).
#define GLOBE_GRID_FOOTPRINT
vec4 globeGridFootprint;

//GLOBE::Math
//GLOBE::Layers

uniform sampler2D globeDirection;
uniform sampler2D globePosition;
uniform vec3 globeRadiiScaled;
uniform vec3 globeNadir;
uniform float globePrimaryAltitude;
uniform float globePrimaryRadius;

// The geodetic (lon, lat) of grid point ij as hi + lo pairs (hi.x, lo.x, hi.y, lo.y).
vec4 globe_gridLonLat(ivec2 ij)
{
  float lonHi;
  float lonLo;
  float latHi;
  float latLo;
#ifdef GLOBE_HIGH_PRECISION_GEODETIC
  // The direction's offset from the sub-point (the local origin, -nadir) from the eye-relative
  // primary-sphere point p: eye + p = r_p s, so s - (-nadir) = (p - a_p nadir) / r_p, with no
  // difference of numbers near 1 (a float unit direction would be 0.4 m on the Earth).
  vec3 p = texelFetch(globePosition, ij, 0).xyz;
  vec3 offset = (p - globePrimaryAltitude * globeNadir) / globePrimaryRadius;
  globe_geodeticFromOffset(globeReferenceDirection, globeGeodeticReference, offset,
    globeRadiiScaled, lonHi, lonLo, latHi, latLo);
#else
  vec4 d = texelFetch(globeDirection, ij, 0);
  vec3 n = globe_normalize(d.xyz / globeRadiiScaled);
  globe_lonLatFromNormal(n, lonHi, latHi);
  lonLo = 0.0;
  latLo = 0.0;
#endif
  return vec4(lonHi, lonLo, latHi, latLo);
}

// Of the steps to the previous and the next grid point along one axis, the shorter: as a
// change of the scaled-space direction, from the eye-relative primary-sphere points (their
// difference is the directions' times r_p, exact where the steps are small: near the eye).
// Either may be missing at the grid's edge or NaN off the body.
vec3 globe_gridShorterStep(vec3 p, ivec2 ij, ivec2 axis, ivec2 size)
{
  vec3 best = vec3(0.0);
  float bestLength = 1e30;
  for (int k = -1; k <= 1; k += 2)
  {
    ivec2 at = ij + k * axis;
    if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, size)))
    {
      continue;
    }
    vec3 d = (texelFetch(globePosition, at, 0).xyz - p) / globePrimaryRadius;
    float l = length(d);
    if (!isnan(l) && l < bestLength)
    {
      best = d;
      bestLength = l;
    }
  }
  return best;
}

// A step of the scaled-space direction s as (dlon, dlat) in radians: on the unit sphere, with
// geocentric angles (within the body's flattening of the geodetic ones: enough for a level
// of detail).
vec2 globe_gridLonLatStep(vec3 s, vec3 step)
{
  float lon = atan(s.y, s.x);
  float cosLat = max(length(s.xy), 1e-7);
  vec3 east = vec3(-sin(lon), cos(lon), 0.0);
  vec3 north = vec3(-s.z * cos(lon), -s.z * sin(lon), cosLat);
  return vec2(dot(step, east) / cosLat, dot(step, north));
}

void main()
{
  ivec2 size = textureSize(globeDirection, 0);
  ivec2 ij = ivec2(texCoord * vec2(size));
  vec4 here = globe_gridLonLat(ij);
  vec3 p = texelFetch(globePosition, ij, 0).xyz;
  vec3 s = globe_normalize(texelFetch(globeDirection, ij, 0).xyz);
  globeGridFootprint = vec4(globe_gridLonLatStep(s, globe_gridShorterStep(p, ij, ivec2(1, 0), size)),
    globe_gridLonLatStep(s, globe_gridShorterStep(p, ij, ivec2(0, 1), size)));
  vec2 gradient;
  float h = globe_composeHeight(here.x, here.y, here.z, here.w, gradient);
  // Only .r is read; texCoord in .gb keeps the quad's texture coordinate alive when no height
  // layer is composed (h folds to 0 and the shader compiler would drop texCoordIn, which
  // vtkOpenGLQuadHelper reports as an error).
  gl_FragData[0] = vec4(h, texCoord, 1.0);
}
