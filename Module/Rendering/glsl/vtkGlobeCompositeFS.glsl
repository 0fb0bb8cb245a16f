//VTK::System::Dec
//VTK::Output::Dec
// Screen composition (deferred texturing): per pixel, the G-buffer's direction gives the
// geodetic (lon, lat); the colour and height layers are composed there at the window's
// resolution; terrain normals come from the composed height gradient; then the enabled
// effects. Writes colour and the G-buffer's depth into the renderer's framebuffer, with the
// depth test on, so other actors occlude the globe and are occluded by it.
in vec2 texCoord;

//GLOBE::Math
//GLOBE::Layers

uniform sampler2D globeGBuffer;
uniform sampler2D globeDepth;
uniform vec3 globeRadiiScaled;
uniform float globeMeanRadius;
uniform vec3 globeLightDirection;
uniform vec3 globeLightColor;
uniform float globeAmbient;
uniform vec3 globeBaseColor;

void main()
{
  float depth = texture(globeDepth, texCoord).r;
  vec4 g = texture(globeGBuffer, texCoord);
  bool covered = depth < 1.0 && dot(g.xyz, g.xyz) > 0.25;
  vec3 s = covered ? globe_normalize(g.xyz) : vec3(0.0, 0.0, 1.0);
  vec3 n = globe_normalize(s / globeRadiiScaled);
  float lon;
  float lat;
  globe_lonLatFromNormal(n, lon, lat);
  // Derivatives are taken before any discard, so every 2x2 quad has them.
  vec2 ll = vec2(lon, lat);
  vec2 dx = dFdx(ll);
  vec2 dy = dFdy(ll);
  vec2 gradient;
  globe_composeHeight(lon, lat, dx, dy, gradient);
  vec4 layerColor = globe_composeColor(lon, lat, dx, dy);
  if (!covered)
  {
    discard;
  }
  vec3 albedo = mix(globeBaseColor, layerColor.rgb, layerColor.a);

  // Terrain normal: the geodetic normal tilted by the slope (per metre east and north).
  float cosLat = max(cos(lat), 1e-6);
  vec3 east = vec3(-sin(lon), cos(lon), 0.0);
  vec3 north = vec3(-sin(lat) * cos(lon), -sin(lat) * sin(lon), cos(lat));
  vec2 slope = vec2(gradient.x / (globeMeanRadius * cosLat), gradient.y / globeMeanRadius);
  vec3 normal = normalize(n - slope.x * east - slope.y * north);

  float diffuse = max(dot(normal, globeLightDirection), 0.0);
  vec3 color = albedo * (globeAmbient + (1.0 - globeAmbient) * diffuse * globeLightColor);
  gl_FragData[0] = vec4(color, 1.0);
  // Depth hook: the G-buffer depth is already in the scene's depth mode (vtkGlobeDepthPass).
  gl_FragDepth = depth;
}
