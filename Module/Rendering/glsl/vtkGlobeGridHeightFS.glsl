//VTK::System::Dec
//VTK::Output::Dec
// Grid pass, step 2 (height composition): one fragment per grid point. The direction from
// step 1 gives the geodetic (lon, lat); the height layers are composed there. Texture
// derivatives between neighbouring grid points choose the mipmap level, so the heights are
// filtered to the grid's own spacing.
in vec2 texCoord;

//GLOBE::Math
//GLOBE::Layers

uniform sampler2D globeDirection;
uniform vec3 globeRadiiScaled;

void main()
{
  vec4 d = texelFetch(globeDirection, ivec2(texCoord * vec2(textureSize(globeDirection, 0))), 0);
  vec3 n = globe_normalize(d.xyz / globeRadiiScaled);
  float lon;
  float lat;
  globe_lonLatFromNormal(n, lon, lat);
  vec2 gradient;
  float h = globe_composeHeight(lon, lat, gradient);
  gl_FragData[0] = vec4(h, 0.0, 0.0, 1.0);
}
