//VTK::System::Dec
// The composition's geometry (vtkGlobeCompositePass): a rectangle per band of rows of the
// viewport, spanning only the columns whose blocks hold terrain in the G-buffer (the mapper's
// minimum reduction: below 1e29 where a block has a terrain pixel); none for a band without.
// Pixels of the sky outside it are never shaded: a software rasterizer runs the whole program
// for every pixel it covers, discard or not, and a GPU every group that has one covered pixel.
// Bands are tall (globeBand rows) because each rectangle is two triangles, and the blocks that
// their diagonal cuts are shaded twice.
// No attributes: gl_VertexID gives the band and the corner.

uniform sampler2D globeCoverage;
uniform ivec2 globeViewportSize;
uniform int globeBand;  // rows per band
uniform int globeBlock; // pixels per coverage texel; 0: every column (no coverage)

out vec2 texCoord;

void main()
{
  int band = gl_VertexID / 6;
  int corner = gl_VertexID - 6 * band;
  // Two triangles: (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1).
  bool right = corner == 1 || corner == 2 || corner == 4;
  bool top = corner == 2 || corner == 4 || corner == 5;
  int y0 = band * globeBand;
  int y1 = min(y0 + globeBand, globeViewportSize.y);
  int x0 = 0;
  int x1 = globeViewportSize.x;
  if (globeBlock > 0)
  {
    ivec2 size = textureSize(globeCoverage, 0);
    int first = size.x;
    int last = -1;
    for (int r = y0 / globeBlock; r < min((y1 + globeBlock - 1) / globeBlock, size.y); ++r)
    {
      for (int k = 0; k < size.x; ++k)
      {
        if (texelFetch(globeCoverage, ivec2(k, r), 0).r < 1e29)
        {
          first = min(first, k);
          last = max(last, k);
        }
      }
    }
    if (last < 0)
    {
      // Outside the clip volume: the band's triangles are dropped.
      gl_Position = vec4(2.0, 2.0, 0.0, 1.0);
      texCoord = vec2(0.0);
      return;
    }
    x0 = first * globeBlock;
    x1 = min((last + 1) * globeBlock, globeViewportSize.x);
  }
  texCoord = vec2(right ? x1 : x0, top ? y1 : y0) / vec2(globeViewportSize);
  gl_Position = vec4(2.0 * texCoord - 1.0, 0.0, 1.0);
}
