// Reading streamed layers through their page tables (vtkGlobePageCache's layout; the design is
// in Documentation/streaming.md). A layer's table holds one texel per page of every level, two
// entries in it: the page's own and the one a lookup one level up finds (trilinear filtering
// reads both levels with one table read). An entry is (slot << 6 | level, column | row << 16)
// of the page or of its finest resident ancestor, so a lookup never misses. Level l's rows
// start at 2 l + floor(2 rows0 (1 - 2^-l)) (rows0: level 0's page rows); rows and columns
// beyond a level's pages repeat its last ones. A layer's `pyramid` uniform: level 0's width and
// height in texels, the number of levels, rows0.

// x: payload texels per page side; y: border texels.
uniform vec2 globePageGeometry;

float globe_pageFirstRow(float level, float rows0)
{
  return 2.0 * level + floor(2.0 * rows0 * (1.0 - exp2(-level)));
}

// Atlas coordinates (x, y, slot) of level-0 texel coordinates t (x east, y south, as hi.xy +
// lo.zw; see "Exact addressing" in Documentation/streaming.md) in the page of table entry e;
// scale: atlas units per level-0 texel there. The page-relative position is
// (hi 2^-l - column P) + lo 2^-l: the first difference is exact (both terms are multiples of
// hi's ulp, itself at most 1), so the position keeps float's relative precision within the page
// whatever the raster's size.
vec3 globe_pageEntryCoord(uvec2 e, vec4 t, out vec2 scale)
{
  float P = globePageGeometry.x;
  float s = exp2(-float(e.x & 63u)); // the found page's level: level 0's size / 2^level
  vec2 origin = vec2(float(e.y & 65535u), float(e.y >> 16u)) * P;
  vec2 local = (t.xy * s - origin) + t.zw * s;
  float T = P + 2.0 * globePageGeometry.y;
  scale = vec2(s / T);
  return vec3((local + globePageGeometry.y) / T, float(e.x >> 6u));
}

// Atlas coordinates of t at `level` (c0, scale0) and at level + 1 (c1, scale1; level itself at
// the coarsest level), each in the page or its finest resident ancestor: one table read.
void globe_pageCoords(usampler2D table, vec4 pyramid, vec4 t, int level, out vec3 c0,
  out vec2 scale0, out vec3 c1, out vec2 scale1)
{
  float P = globePageGeometry.x;
  float l = float(level);
  float first = globe_pageFirstRow(l, pyramid.w);
  float rows = globe_pageFirstRow(l + 1.0, pyramid.w) - first;
  vec2 page = clamp(floor((t.xy + t.zw) * exp2(-l) / P), vec2(0.0),
    vec2(float(textureSize(table, 0).x), rows) - 1.0);
  uvec4 e = texelFetch(table, ivec2(page) + ivec2(0, int(first)), 0);
  c0 = globe_pageEntryCoord(e.xy, t, scale0);
  c1 = globe_pageEntryCoord(e.zw, t, scale1);
}

float globe_pageAt(sampler2DArray atlas, vec3 c, vec2 offset, bool nearest)
{
  vec3 q = vec3(c.xy + offset, c.z);
  float T = globePageGeometry.x + 2.0 * globePageGeometry.y;
  return nearest ? texelFetch(atlas, ivec3(ivec2(floor(q.xy * T)), int(q.z)), 0).r
                 : textureLod(atlas, q, 0.0).r;
}

// The page's height at atlas coordinates c, bilinear with float weights (globe_heightLod says
// why the hardware's are not used for heights); the page's border holds the neighbours.
float globe_pageBilinear(sampler2DArray atlas, vec3 c)
{
  int T = int(globePageGeometry.x + 2.0 * globePageGeometry.y);
  vec2 x = c.xy * float(T) - 0.5;
  vec2 i = floor(x);
  vec2 f = x - i;
  ivec2 i0 = clamp(ivec2(i), ivec2(0), ivec2(T - 1));
  ivec2 i1 = clamp(ivec2(i) + 1, ivec2(0), ivec2(T - 1));
  int slot = int(c.z);
  float a = texelFetch(atlas, ivec3(i0, slot), 0).r;
  float b = texelFetch(atlas, ivec3(i1.x, i0.y, slot), 0).r;
  float cc = texelFetch(atlas, ivec3(i0.x, i1.y, slot), 0).r;
  float d = texelFetch(atlas, ivec3(i1, slot), 0).r;
  return mix(mix(a, b, f.x), mix(cc, d, f.x), f.y);
}

// Heights at t and one level-0 texel east, west, north and south of it (the gradient) in the
// page at atlas coordinates c (scale: atlas units per level-0 texel): the neighbours lie in the
// same page or its border (two texels, at least one level-0 texel at every level).
void globe_pageHeightsAt(sampler2DArray atlas, vec3 c, vec2 s, bool nearest, out float v,
  out vec4 ewns)
{
  // The value with float weights (where rays along the ground read it) unless the texture
  // unit filters exactly (vtkGlobeLayerSet::HeightFiltering); the gradient's neighbours
  // through the texture unit (they set a Newton step's length, not where it converges).
#ifdef GLOBE_HEIGHTS_IN_SHADER
  v = nearest ? globe_pageAt(atlas, c, vec2(0.0), true) : globe_pageBilinear(atlas, c);
#else
  v = globe_pageAt(atlas, c, vec2(0.0), nearest);
#endif
  ewns = vec4(globe_pageAt(atlas, c, vec2(s.x, 0.0), nearest),
    globe_pageAt(atlas, c, vec2(-s.x, 0.0), nearest),
    globe_pageAt(atlas, c, vec2(0.0, -s.y), nearest),
    globe_pageAt(atlas, c, vec2(0.0, s.y), nearest));
}

void globe_pageHeights(sampler2DArray atlas, usampler2D table, vec4 pyramid, vec4 t,
  vec2 dx, vec2 dy, float stretch, float least, bool nearest, out float v, out vec4 ewns)
{
  float lod = clamp(max(globe_footprintLodHeights(pyramid, dx, dy, stretch), least), 0.0,
    pyramid.z - 1.0);
  vec3 c0, c1;
  vec2 s0, s1;
  if (nearest)
  {
    globe_pageCoords(table, pyramid, t, int(floor(lod + 0.5)), c0, s0, c1, s1);
    globe_pageHeightsAt(atlas, c0, s0, true, v, ewns);
    return;
  }
  int l = int(floor(lod));
  float f = lod - float(l);
  globe_pageCoords(table, pyramid, t, l, c0, s0, c1, s1);
  globe_pageHeightsAt(atlas, c0, s0, false, v, ewns);
  if (f > 0.0)
  {
    float v1;
    vec4 ewns1;
    globe_pageHeightsAt(atlas, c1, s1, false, v1, ewns1);
    v = mix(v, v1, f);
    ewns = mix(ewns, ewns1, f);
  }
}

// A streamed layer's filtered value at level-0 texel coordinates t (hi.xy + lo.zw), with the
// screen derivatives of its texture coordinates dx, dy. Linear: between the two levels around
// the footprint's, as OpenGL's LINEAR_MIPMAP_LINEAR; nearest: the nearest level's nearest texel.
vec4 globe_pageGrad(sampler2DArray atlas, usampler2D table, vec4 pyramid, vec4 t, vec2 dx,
  vec2 dy, bool nearest)
{
  float lod = globe_footprintLod(pyramid, dx, dy);
  vec3 c0, c1;
  vec2 s0, s1;
  if (nearest)
  {
    globe_pageCoords(table, pyramid, t, int(floor(lod + 0.5)), c0, s0, c1, s1);
    float T = globePageGeometry.x + 2.0 * globePageGeometry.y;
    return texelFetch(atlas, ivec3(ivec2(floor(c0.xy * T)), int(c0.z)), 0);
  }
  int l = int(floor(lod));
  float f = lod - float(l);
  globe_pageCoords(table, pyramid, t, l, c0, s0, c1, s1);
  vec4 a = textureLod(atlas, c0, 0.0);
  if (f > 0.0)
  {
    a = mix(a, textureLod(atlas, c1, 0.0), f);
  }
  return a;
}
