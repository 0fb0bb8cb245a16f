//VTK::System::Dec
//VTK::Output::Dec
// Grid pass, step 1 (PGM): one fragment per grid point. Casts the grid point's ray from the
// sampling camera against the reference spheres (globe_pgmGridPoint; a ray that misses them
// takes the horizon point in its plane) and writes
//   out 0: the unit direction from the centre of the sampled point (scaled space), flag (1 hit,
//          0.5 horizon point, 0 invalid)
//   out 1: that point on the primary sphere, relative to the eye (scaled space)
in vec2 texCoord;

//GLOBE::Math

uniform vec2 globeGridSize;
uniform vec3 globeNadir;
uniform vec3 globeNadirPerpendicular;
uniform vec3 globeSamplingForward;
uniform vec3 globeSamplingRight;
uniform vec3 globeSamplingUp;
uniform vec4 globeSamplingExtent;
uniform float globeDistance;
uniform float globePrimaryRadius;
uniform float globePrimaryAltitude;
uniform float globeTau0;
uniform float globeBlendStart;
uniform float globeSecondaryRadius;
uniform float globeSecondaryAltitude;
uniform float globeBlendStartS;
uniform float globeTauS;

void main()
{
  // Grid point (i, j) sits at (i / (n - 1), j / (n - 1)): the grid spans the frustum edges.
  vec2 uv = (texCoord * globeGridSize - vec2(0.5)) / (globeGridSize - vec2(1.0));
  float x = mix(globeSamplingExtent.x, globeSamplingExtent.y, uv.x);
  float y = mix(globeSamplingExtent.z, globeSamplingExtent.w, uv.y);
  vec3 ray = globe_normalize(globeSamplingForward + x * globeSamplingRight + y * globeSamplingUp);
  vec3 s;
  vec3 p;
  float hit = globe_pgmGridPoint(ray, globeNadir, globeNadirPerpendicular, globeDistance,
    globePrimaryRadius, globePrimaryAltitude, globeTau0, globeBlendStart, globeSecondaryRadius,
    globeSecondaryAltitude, globeBlendStartS, globeTauS, s, p);
  gl_FragData[0] = vec4(s, hit);
  gl_FragData[1] = vec4(p, 0.0);
}
