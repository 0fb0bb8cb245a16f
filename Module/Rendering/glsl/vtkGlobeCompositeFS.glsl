//VTK::System::Dec
//VTK::Output::Dec
// Screen composition (deferred texturing): per pixel, the G-buffer's direction (or its offset
// from the frame's local origin) gives the geodetic (lon, lat); the layers are composed there at the window's resolution; terrain
// normals come from the composed height gradient; then the enabled effects. The //GLOBE::
// markers are replaced by vtkGlobeCompositePass with the code of the enabled effects only
// (or nothing). Writes colour and the G-buffer's depth into the renderer's framebuffer, with
// the depth test on, so other actors occlude the globe and are occluded by it.
in vec2 texCoord;

// Each pixel's footprint (radians of lon and lat per pixel along x and y) from the step to the
// nearer covered neighbour: the layers' level of detail (vtkGlobeLayerSet's GLOBE_FOOTPRINT).
#define GLOBE_FOOTPRINT
vec4 globeFootprint;

//GLOBE::Math
//GLOBE::Layers
//GLOBE::EffectFunctions

uniform sampler2D globeGBuffer;
uniform sampler2D globeDepth;
uniform vec3 globeRadiiScaled;
uniform float globeMeanRadius;
uniform float globeMaximumRadius;
uniform vec3 globeLightDirection;
uniform vec3 globeLightColor;
uniform float globeAmbient;
uniform vec3 globeBaseColor;
// The eye in the body frame in units of the largest radius, and clip -> eye-relative body
// coordinates (directions only).
uniform vec3 globeEye;
uniform mat4 globeClipToEye;

// The step of the G-buffer's direction (or offset: their differences are the same) to the
// pixel `k` pixels along `axis`; 1e30 where that pixel is off the window or not the globe's.
vec3 globe_pixelStep(vec3 g, ivec2 ij, ivec2 axis, int k)
{
  ivec2 at = ij + k * axis;
  if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, textureSize(globeGBuffer, 0))) ||
    !(texelFetch(globeDepth, at, 0).r < 1.0))
  {
    return vec3(1e30);
  }
  return float(k) * (texelFetch(globeGBuffer, at, 0).xyz - g);
}

void main()
{
  float depth = texture(globeDepth, texCoord).r;
  vec4 g = texture(globeGBuffer, texCoord);
  // (lon, lat) as hi + lo pairs for the layers; lon and lat (one float each) for the effects.
  float lonHi;
  float lonLo;
  float latHi;
  float latLo;
#ifdef GLOBE_HIGH_PRECISION_GEODETIC
  // The G-buffer holds the direction's offset from the frame's local origin.
  bool covered = depth < 1.0;
  vec3 offset = covered ? g.xyz : vec3(0.0);
  vec3 s = globe_normalize(globeReferenceDirection + offset);
  vec3 n = globe_normalize(s / globeRadiiScaled);
  globe_geodeticFromOffset(globeReferenceDirection, globeGeodeticReference, offset,
    globeRadiiScaled, lonHi, lonLo, latHi, latLo);
  float lon = lonHi + lonLo;
#else
  bool covered = depth < 1.0 && dot(g.xyz, g.xyz) > 0.25;
  vec3 s = covered ? globe_normalize(g.xyz) : vec3(0.0, 0.0, 1.0);
  vec3 n = globe_normalize(s / globeRadiiScaled);
  globe_lonLatFromNormal(n, lonHi, latHi);
  lonLo = 0.0;
  latLo = 0.0;
  float lon = lonHi;
#endif
  float lat = latHi + latLo;
  {
    ivec2 ij = ivec2(texCoord * vec2(textureSize(globeGBuffer, 0)));
    vec3 stepX = globe_footprintShorterStep(
      globe_pixelStep(g.xyz, ij, ivec2(1, 0), -1), globe_pixelStep(g.xyz, ij, ivec2(1, 0), 1));
    vec3 stepY = globe_footprintShorterStep(
      globe_pixelStep(g.xyz, ij, ivec2(0, 1), -1), globe_pixelStep(g.xyz, ij, ivec2(0, 1), 1));
    globeFootprint = covered
      ? vec4(globe_footprintLonLatStep(s, stepX), globe_footprintLonLatStep(s, stepY))
      : vec4(0.0);
  }
  vec4 far = globeClipToEye * vec4(2.0 * texCoord - 1.0, 1.0, 1.0);
  vec3 ray = globe_normalize(far.xyz / far.w);

  // Everything that takes screen derivatives runs before any discard, so every 2x2 quad
  // has them.
  vec2 gradient;
  float h = globe_composeHeight(lonHi, lonLo, latHi, latLo, gradient);
  vec3 albedo = globeBaseColor;
  float lines = 0.0;
  vec3 lineColor = vec3(0.0);
  //GLOBE::Sample

  if (!covered)
  {
    //GLOBE::Sky
    discard;
  }

  // Terrain normal: the geodetic normal tilted by the slope (per metre east and north).
  float cosLat = max(cos(lat), 1e-6);
  vec3 east = vec3(-sin(lon), cos(lon), 0.0);
  vec3 north = vec3(-sin(lat) * cos(lon), -sin(lat) * sin(lon), cos(lat));
  vec3 tangentNormal =
    vec3(-gradient.x / (globeMeanRadius * cosLat), -gradient.y / globeMeanRadius, 1.0);
  //GLOBE::Normal
  tangentNormal = globe_normalize(tangentNormal);
  vec3 normal = tangentNormal.x * east + tangentNormal.y * north + tangentNormal.z * n;

  vec3 color = albedo;
  //GLOBE::Shade
  color = mix(color, lineColor, lines);
  gl_FragData[0] = vec4(color, 1.0);
  // Depth hook: the G-buffer depth is already in the scene's depth mode (vtkGlobeDepthPass).
  gl_FragDepth = depth;
}
