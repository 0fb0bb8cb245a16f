//VTK::System::Dec
//VTK::Output::Dec
// Grid pass, step 2 (height composition): one fragment per grid point. The grid point's
// geodetic (lon, lat) as hi + lo pairs; the height layers are composed there, filtered to the
// grid's own spacing: the step to the nearer neighbour along each grid axis chooses the level.
in vec2 texCoord;

// The grid step (radians of lon and lat) along the grid's i and j axes, towards the nearer
// neighbour: the height layers' level of detail (vtkGlobeLayerSet's GLOBE_FOOTPRINT), by the
// grid's rule (GLOBE_GRID_FOOTPRINT: the shorter axis within 16:1).
#define GLOBE_FOOTPRINT
#define GLOBE_GRID_FOOTPRINT
vec4 globeFootprint;

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

// The step to the neighbouring grid point `k` grid points along `axis` as a change of the
// scaled-space direction, from the eye-relative primary-sphere points (their difference is the
// directions' times r_p, exact where the steps are small: near the eye); 1e30 beyond the grid.
vec3 globe_gridStep(vec3 p, ivec2 ij, ivec2 axis, int k, ivec2 size)
{
  ivec2 at = ij + k * axis;
  if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, size)))
  {
    return vec3(1e30);
  }
  return float(k) * (texelFetch(globePosition, at, 0).xyz - p) / globePrimaryRadius;
}

void main()
{
  ivec2 size = textureSize(globeDirection, 0);
  ivec2 ij = ivec2(texCoord * vec2(size));
  vec4 here = globe_gridLonLat(ij);
  vec3 p = texelFetch(globePosition, ij, 0).xyz;
  vec3 s = globe_normalize(texelFetch(globeDirection, ij, 0).xyz);
  vec3 stepI = globe_footprintShorterStep(globe_gridStep(p, ij, ivec2(1, 0), -1, size),
    globe_gridStep(p, ij, ivec2(1, 0), 1, size));
  vec3 stepJ = globe_footprintShorterStep(globe_gridStep(p, ij, ivec2(0, 1), -1, size),
    globe_gridStep(p, ij, ivec2(0, 1), 1, size));
  globeFootprint = vec4(globe_footprintLonLatStep(s, stepI), globe_footprintLonLatStep(s, stepJ));
  vec2 gradient;
  float h = globe_composeHeight(here.x, here.y, here.z, here.w, gradient);
  // Only .r is read; texCoord in .gb keeps the quad's texture coordinate alive when no height
  // layer is composed (h folds to 0 and the shader compiler would drop texCoordIn, which
  // vtkOpenGLQuadHelper reports as an error).
  gl_FragData[0] = vec4(h, texCoord, 1.0);
}
