// Lines of constant pixel width on the globe (graticule, height contours): the coverage of a
// line family at the value x, spaced `spacing` apart, where x changes by `perPixel` between
// neighbouring pixels. Antialiased over one pixel.
float globe_lineCoverage(float x, float spacing, float perPixel, float widthPixels)
{
  float d = abs(fract(x / spacing + 0.5) - 0.5) * spacing;
  float pixels = d / max(perPixel, 1e-30);
  return 1.0 - clamp(pixels - 0.5 * widthPixels + 0.5, 0.0, 1.0);
}

// The per-pixel change of a longitude (radians) without the jump of a whole turn at the seam.
float globe_longitudePerPixel(float lon)
{
  vec2 d = vec2(dFdx(lon), dFdy(lon));
  d -= 6.283185307179586 * floor(d / 6.283185307179586 + 0.5);
  return abs(d.x) + abs(d.y);
}
