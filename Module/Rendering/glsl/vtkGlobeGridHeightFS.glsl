//VTK::System::Dec
//VTK::Output::Dec
// Grid pass, step 2 (height composition): one fragment per grid point. The grid point's
// geodetic (lon, lat) as hi + lo pairs; the height layers are composed there. Texture
// derivatives between neighbouring grid points choose the mipmap level, so the heights are
// filtered to the grid's own spacing.
in vec2 texCoord;

//GLOBE::Math
//GLOBE::Layers

uniform sampler2D globeDirection;
uniform sampler2D globePosition;
uniform vec3 globeRadiiScaled;
uniform vec3 globeNadir;
uniform float globePrimaryAltitude;
uniform float globePrimaryRadius;

void main()
{
  ivec2 ij = ivec2(texCoord * vec2(textureSize(globeDirection, 0)));
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
  vec2 gradient;
  float h = globe_composeHeight(lonHi, lonLo, latHi, latLo, gradient);
  // Only .r is read; texCoord in .gb keeps the quad's texture coordinate alive when no height
  // layer is composed (h folds to 0 and the shader compiler would drop texCoordIn, which
  // vtkOpenGLQuadHelper reports as an error).
  gl_FragData[0] = vec4(h, texCoord, 1.0);
}
