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
#ifdef GLOBE_REFINE
// vtkGlobeCompositePass::SetRefinementFrame.
uniform vec4 globeChord;
uniform vec4 globeClipW;
uniform vec3 globeDepthMap;
#endif

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
#ifdef GLOBE_REFINE
  // The refinement's compositions place points, so they filter heights as the grid pass does
  // (the footprint's shorter axis within 16:1); the shading's composition comes after it.
  globe_heightStretch = 1.0 / 16.0;
#endif
  float h = globe_composeHeight(lonHi, lonLo, latHi, latLo, gradient);
  float outDepth = depth;
#ifdef GLOBE_REFINE
  // Terrain refinement (Documentation/rendering.md "Terrain refinement"): Newton steps along
  // the pixel's ray from the mesh point to the composed heights, in metres relative to the
  // mesh point (never an absolute position); the layers are then composed at the refined
  // (lon, lat), moved by the steps' small shifts in the lo parts, and its depth is written.
  // (Only with high-precision geodetic coordinates: vtkGlobeCompositePass defines GLOBE_REFINE
  // with them alone.)
  {
    vec3 chordOffset = offset;
    // The mesh point lies inside the unit sphere of directions by the chord's sag.
    float s2 = -globeChord.w - 2.0 * dot(chordOffset, globeChord.xyz) - dot(chordOffset, chordOffset);
    float shortfall = s2 / (1.0 + sqrt(max(1.0 - s2, 0.0)));
    float height = g.w - length(s * globeRadiiScaled) * globeMaximumRadius * shortfall;
    float a = globeMaximumRadius * globeRadiiScaled.x;
    float b = globeMaximumRadius * globeRadiiScaled.z;
    float e2 = 1.0 - (b * b) / (a * a);
    // What a failed refinement returns to.
    // (The heights are composed again below, at the point kept.)
    float lonLo0 = lonLo, latLo0 = latLo, lon0 = lon, lat0 = lat;
    vec3 n0 = n;
    float residual0 = height - h;
    float t = 0.0;
    // Not with a parallel projection (globeDepthMap.x 2), nor where even the footprint's
    // shorter axis exceeds 300 km: the relief is then a few hundredths of a pixel, and steps
    // along rays that graze a disc a few pixels wide chased heights filtered over hundreds of
    // kilometres (TestGlobeVeryFar: 146 m median error unrefined, 451 m refined at 1e9 m).
    float footprint = globeMeanRadius *
      min(length(vec2(globeFootprint.x * cos(lat), globeFootprint.y)),
        length(vec2(globeFootprint.z * cos(lat), globeFootprint.w)));
    bool refine = covered && !isnan(residual0) && globeDepthMap.x < 1.5 && footprint < 3e5;
    for (int k = 0; k < GLOBE_REFINE; ++k)
    {
      float sinLat = sin(lat);
      float cosLat = max(cos(lat), 1e-6);
      vec3 east = vec3(-sin(lon), cos(lon), 0.0);
      vec3 north = vec3(-sinLat * cos(lon), -sinLat * sin(lon), cosLat);
      float w = inversesqrt(1.0 - e2 * sinLat * sinLat);
      float meridian = a * (1.0 - e2) * w * w * w + h;
      float vertical = a * w + h;
      float rayUp = dot(ray, n);
      float rayEast = dot(ray, east);
      float rayNorth = dot(ray, north);
      // d(height - data)/dt: the ray's descent less the terrain's rise along it.
      float rate = rayUp - gradient.x / (vertical * cosLat) * rayEast - gradient.y / meridian * rayNorth;
      // Newton where the ray enters the terrain clearly. A descending ray on a back slope (or
      // where the slope would send the step the wrong way) takes the step for level terrain
      // instead. A climbing ray (along the ground, at a slope seen from below) has no such
      // step: Newton where the terrain rises clearly faster than the ray, else no step.
      bool descending = rayUp < -1e-3;
      bool step = refine && abs(lat) < 1.5707 && (descending || rate < -0.02);
      float dt = step ? -(height - h) / (descending && !(rate < 0.25 * rayUp) ? rayUp : rate) : 0.0;
      float dEast = dt * rayEast;
      float dNorth = dt * rayNorth;
      float dLon = dEast / (vertical * cosLat);
      float dLat = dNorth / meridian;
      // The new point's height above the (curved) ellipsoid.
      height += dt * rayUp + 0.5 * (dEast * dEast / vertical + dNorth * dNorth / meridian);
      lonLo += dLon;
      latLo += dLat;
      lon += dLon;
      lat += dLat;
      n = globe_normalize(n + dLon * cosLat * east + dLat * north);
      t += dt;
      h = globe_composeHeight(lonHi, lonLo, latHi, latLo, gradient);
    }
    if (!(abs(height - h) <= abs(residual0)))
    {
      lonLo = lonLo0;
      latLo = latLo0;
      lon = lon0;
      lat = lat0;
      n = n0;
      t = 0.0;
    }
    // The shading's composition at the point kept: OpenGL's level (the longer axis), as
    // without refinement, so the gradient is filtered to the pixel (TestGlobeAliasing).
    globe_heightStretch = 1.0;
    h = globe_composeHeight(lonHi, lonLo, latHi, latLo, gradient);
    // The depth of the refined point, as a change of the mesh point's (clip w = globeClipW . x).
    float w0 = globeDepthMap.x < 0.5 ? globeDepthMap.z / max(globeDepthMap.y - depth, 1e-30)
                                     : exp2(depth / globeDepthMap.y) - 1.0;
    float dw = t * dot(globeClipW.xyz, ray);
    float w1 = max(w0 + dw, 1e-6);
    // log2(1 + x) for the small ratio x of the logarithmic mode, without rounding 1 + x.
    float x = dw / (1.0 + w0);
    float log2OnePlusX = abs(x) < 1e-3 ? x * (1.0 - 0.5 * x) * 1.4426950408889634 : log2(1.0 + x);
    outDepth = t == 0.0 ? depth
      : globeDepthMap.x < 0.5 ? depth + globeDepthMap.z * dw / (w0 * w1)
                              : depth + globeDepthMap.y * log2OnePlusX;
    outDepth = clamp(outDepth, 0.0, 1.0);
  }
#endif
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
  gl_FragDepth = outDepth;
}
