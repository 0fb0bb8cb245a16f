//VTK::System::Dec
//VTK::Output::Dec
// Minimum reduction of the visible planetary radius (scaled space, as rho - 1) over 4x4 blocks.
// The first level reads the G-buffer; the next ones their predecessor. Pixels without terrain
// contribute +1e30.
in vec2 texCoord;

//GLOBE::Math

uniform sampler2D globeSource;
uniform sampler2D globeDepth;
uniform int globeFirstLevel;
uniform vec3 globeRadiiScaled;
uniform vec3 globeRadii;
uniform vec2 globeOutputSize;
// Added to the G-buffer's xyz to give the direction: the local origin when it holds offsets
// from it (high-precision geodetic coordinates), zero when it holds the direction.
uniform vec3 globeReferenceDirection;

void main()
{
  ivec2 size = textureSize(globeSource, 0);
  ivec2 base = ivec2(texCoord * globeOutputSize) * 4;
  float m = 1e30;
  for (int j = 0; j < 4; j++)
  {
    for (int i = 0; i < 4; i++)
    {
      ivec2 ij = min(base + ivec2(i, j), size - ivec2(1));
      vec4 v = texelFetch(globeSource, ij, 0);
      if (globeFirstLevel == 1)
      {
        if (texelFetch(globeDepth, ij, 0).r >= 1.0)
        {
          continue;
        }
        // rho = |s + h n / radii|; rho - 1 without cancellation (|s| = 1).
        vec3 s = globe_normalize(globeReferenceDirection + v.xyz);
        vec3 q = v.w * globe_normalize(s / globeRadiiScaled) / globeRadii;
        float rho = globe_length(s + q);
        m = min(m, (2.0 * dot(s, q) + dot(q, q)) / (rho + 1.0));
      }
      else
      {
        m = min(m, v.r);
      }
    }
  }
  gl_FragData[0] = vec4(m, 0.0, 0.0, 1.0);
}
