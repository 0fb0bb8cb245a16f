// Reading streamed layers through their page tables (vtkGlobePageCache's layout; the design is
// in Documentation/streaming.md). A layer's table holds one texel per page of every level:
// (slot, level, column, row) of the page or of its finest resident ancestor, so a lookup never
// misses. Level l's rows start at 2 l + floor(2 rows0 (1 - 2^-l)) (rows0: level 0's page
// rows); rows and columns beyond a level's pages repeat its last ones. A layer's `pyramid`
// uniform: level 0's width and height in texels, the number of levels, rows0.

// x: payload texels per page side; y: border texels.
uniform vec2 globePageGeometry;

float globe_pageFirstRow(float level, float rows0)
{
  return 2.0 * level + floor(2.0 * rows0 * (1.0 - exp2(-level)));
}

// Atlas coordinates (x, y, slot) of level-0 texel coordinates t (x east, y south, as hi.xy +
// lo.zw; see "Exact addressing" in Documentation/streaming.md) at `level`, or at its finest
// resident ancestor; scale: atlas units per level-0 texel in the page found. The page-relative
// position is (hi 2^-l - column P) + lo 2^-l: the first difference is exact (both terms are
// multiples of hi's ulp, itself at most 1), so the position keeps float's relative precision
// within the page whatever the raster's size.
vec3 globe_pageCoord(sampler2D table, vec4 pyramid, vec4 t, int level, out vec2 scale)
{
  float P = globePageGeometry.x;
  float l = float(level);
  float first = globe_pageFirstRow(l, pyramid.w);
  float rows = globe_pageFirstRow(l + 1.0, pyramid.w) - first;
  vec2 page = clamp(floor((t.xy + t.zw) * exp2(-l) / P), vec2(0.0),
    vec2(float(textureSize(table, 0).x), rows) - 1.0);
  vec4 e = texelFetch(table, ivec2(page) + ivec2(0, int(first)), 0);
  float s = exp2(-e.y); // the found page's level: level 0's size / 2^level
  vec2 local = (t.xy * s - e.zw * P) + t.zw * s;
  float T = P + 2.0 * globePageGeometry.y;
  scale = vec2(s / T);
  return vec3((local + globePageGeometry.y) / T, e.x);
}

float globe_pageAt(sampler2DArray atlas, vec3 c, vec2 offset, bool nearest)
{
  vec3 q = vec3(c.xy + offset, c.z);
  float T = globePageGeometry.x + 2.0 * globePageGeometry.y;
  return nearest ? texelFetch(atlas, ivec3(ivec2(floor(q.xy * T)), int(q.z)), 0).r
                 : textureLod(atlas, q, 0.0).r;
}

// Heights at t and one level-0 texel east, west, north and south of it (the gradient),
// with one page lookup per level: the neighbours lie in the same page or its border (two
// texels, at least one level-0 texel at every level).
void globe_pageHeightsAt(sampler2DArray atlas, sampler2D table, vec4 pyramid, vec4 t, int l,
  bool nearest, out float v, out vec4 ewns)
{
  vec2 s;
  vec3 c = globe_pageCoord(table, pyramid, t, l, s);
  v = globe_pageAt(atlas, c, vec2(0.0), nearest);
  ewns = vec4(globe_pageAt(atlas, c, vec2(s.x, 0.0), nearest),
    globe_pageAt(atlas, c, vec2(-s.x, 0.0), nearest),
    globe_pageAt(atlas, c, vec2(0.0, -s.y), nearest),
    globe_pageAt(atlas, c, vec2(0.0, s.y), nearest));
}

void globe_pageHeights(sampler2DArray atlas, sampler2D table, vec4 pyramid, vec4 t,
  vec2 dx, vec2 dy, float stretch, float least, bool nearest, out float v, out vec4 ewns)
{
  float lod = clamp(max(globe_footprintLodHeights(pyramid, dx, dy, stretch), least), 0.0,
    pyramid.z - 1.0);
  if (nearest)
  {
    globe_pageHeightsAt(atlas, table, pyramid, t, int(floor(lod + 0.5)), true, v, ewns);
    return;
  }
  int l = int(floor(lod));
  float f = lod - float(l);
  globe_pageHeightsAt(atlas, table, pyramid, t, l, false, v, ewns);
  if (f > 0.0)
  {
    float v1;
    vec4 ewns1;
    globe_pageHeightsAt(atlas, table, pyramid, t, l + 1, false, v1, ewns1);
    v = mix(v, v1, f);
    ewns = mix(ewns, ewns1, f);
  }
}

// A streamed layer's filtered value at level-0 texel coordinates t (hi.xy + lo.zw), with the
// screen derivatives of its texture coordinates dx, dy. Linear: between the two levels around
// the footprint's, as OpenGL's LINEAR_MIPMAP_LINEAR; nearest: the nearest level's nearest texel.
vec4 globe_pageGrad(sampler2DArray atlas, sampler2D table, vec4 pyramid, vec4 t, vec2 dx,
  vec2 dy, bool nearest)
{
  float lod = globe_footprintLod(pyramid, dx, dy);
  vec2 scale;
  if (nearest)
  {
    vec3 c = globe_pageCoord(table, pyramid, t, int(floor(lod + 0.5)), scale);
    float T = globePageGeometry.x + 2.0 * globePageGeometry.y;
    return texelFetch(atlas, ivec3(ivec2(floor(c.xy * T)), int(c.z)), 0);
  }
  int l = int(floor(lod));
  float f = lod - float(l);
  vec4 a = textureLod(atlas, globe_pageCoord(table, pyramid, t, l, scale), 0.0);
  if (f > 0.0)
  {
    a = mix(a, textureLod(atlas, globe_pageCoord(table, pyramid, t, l + 1, scale), 0.0), f);
  }
  return a;
}
