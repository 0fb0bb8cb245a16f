//VTK::System::Dec
// Rasterization: the grid as a mesh. Each vertex fetches its grid point, is displaced from the
// primary sphere to the terrain along the geodetic normal, and is projected eye-relative:
// no large coordinate is ever formed on the GPU.
//GLOBE::Math

uniform sampler2D globeDirection;
uniform sampler2D globePosition;
uniform sampler2D globeHeight;
uniform int globeGridN;
uniform mat4 globeEyeToClip;
uniform vec3 globeRadii;
uniform vec3 globeRadiiScaled;
uniform float globeOneMinusRp;
uniform vec3 globeNadir;
uniform float globePrimaryAltitude;
uniform float globePrimaryRadius;

out vec4 globeDirectionHeight;
out float globeValid;

void main()
{
  ivec2 ij = ivec2(gl_VertexID % globeGridN, gl_VertexID / globeGridN);
  vec4 d = texelFetch(globeDirection, ij, 0);
  vec3 p = texelFetch(globePosition, ij, 0).xyz;
  float h = texelFetch(globeHeight, ij, 0).r;
  vec3 n = globe_normalize(d.xyz / globeRadiiScaled);
  // Terrain = ellipsoid point on the direction + h along the normal; relative to the eye that
  // is the primary-sphere point p plus (1 - r_p) along the direction, in metres.
  vec3 eyeRelative = (p + globeOneMinusRp * d.xyz) * globeRadii + h * n;
  gl_Position = globeEyeToClip * vec4(eyeRelative, 1.0);
#ifdef GLOBE_HIGH_PRECISION_GEODETIC
  // The G-buffer holds the direction's offset from the sub-point (the local origin), as the
  // height pass computes it: precise where a float unit direction is 0.4 m on the Earth.
  globeDirectionHeight = vec4((p - globePrimaryAltitude * globeNadir) / globePrimaryRadius, h);
#else
  globeDirectionHeight = vec4(d.xyz, h);
#endif
  // Horizon points (0.5) are valid vertices: their triangles reach the limb.
  globeValid = d.w > 0.25 ? 1.0 : 0.0;
}
