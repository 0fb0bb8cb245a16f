//VTK::System::Dec
//VTK::Output::Dec
// Page feedback: one sample per block of globeBlock x globeBlock pixels of the G-buffer, as
// three texels side by side: the block's centre pixel (G-buffer xyz, covered 1 or 0), its
// neighbour along x and its neighbour along y (G-buffer xyz, +1 or -1 for the side taken, 0
// when neither side is covered). The CPU turns them into (lon, lat) and its derivatives per
// pixel in double (vtkGlobePageFeedback), hence each streamed layer's level and pages.
in vec2 texCoord;

uniform sampler2D globeGBuffer;
uniform sampler2D globeDepth;
uniform int globeBlock;
uniform vec2 globeTargetSize;

bool globe_covered(ivec2 p, ivec2 size)
{
  return all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, size)) &&
    texelFetch(globeDepth, p, 0).r < 1.0;
}

void main()
{
  ivec2 o = ivec2(texCoord * globeTargetSize);
  int k = o.x % 3;
  ivec2 size = textureSize(globeDepth, 0);
  ivec2 p = min(ivec2(o.x / 3, o.y) * globeBlock + globeBlock / 2, size - ivec2(1));
  if (k == 0)
  {
    bool covered = globe_covered(p, size);
    gl_FragData[0] = vec4(texelFetch(globeGBuffer, p, 0).xyz, covered ? 1.0 : 0.0);
    return;
  }
  ivec2 step = k == 1 ? ivec2(1, 0) : ivec2(0, 1);
  float side = 1.0;
  ivec2 q = p + step;
  if (!globe_covered(q, size))
  {
    q = p - step;
    side = globe_covered(q, size) ? -1.0 : 0.0;
  }
  gl_FragData[0] = vec4(side != 0.0 ? texelFetch(globeGBuffer, q, 0).xyz : vec3(0.0), side);
}
