// The mipmap level a footprint needs (Documentation/composition.md "Filtering to the
// footprint"), shared by whole-raster textures and streamed pages so that both filter alike.
// pyramid: level 0's width and height in texels and the number of levels (a streamed layer's
// pyramid uniform; .w is not read). dx, dy: screen derivatives of the texture coordinates.

// The level of detail from the footprint, as OpenGL chooses a mipmap level: log2 of the larger
// screen derivative in level-0 texels, within the pyramid.
float globe_footprintLod(vec4 pyramid, vec2 dx, vec2 dy)
{
  float rho = max(length(dx * pyramid.xy), length(dy * pyramid.xy));
  return clamp(log2(max(rho, 1e-30)), 0.0, pyramid.z - 1.0);
}

// The level of detail for heights near a pole. A geographic layer's texels there are metres
// wide and kilometres long (aspect cos lat), so a pixel metres wide spans many texels of
// longitude but a sliver of one in latitude, and the level OpenGL would choose (from the
// longer axis) averages heights degrees of latitude apart: a height is a position, and that
// moves the surface by hundreds of metres. Within 1 / stretch of the longer axis, the level
// comes from the footprint's shorter axis (the smaller singular value of its Jacobian in
// level-0 texels; the screen axes would not do: longitude changes fast along both of them).
// stretch: min(1, 10 cos lat) for geographic layers (1 below 84 degrees: OpenGL's level), 1
// for the conformal projections.
float globe_footprintLodHeights(vec4 pyramid, vec2 dx, vec2 dy, float stretch)
{
  vec2 a = dx * pyramid.xy, b = dy * pyramid.xy;
  float longer = max(length(a), length(b));
  if (stretch >= 1.0)
  {
    return clamp(log2(max(longer, 1e-30)), 0.0, pyramid.z - 1.0);
  }
  float t = dot(a, a) + dot(b, b);
  float det = abs(a.x * b.y - a.y * b.x);
  float major = sqrt(0.5 * t + sqrt(max(0.25 * t * t - det * det, 0.0)));
  float rho = max(det / max(major, 1e-30), longer * stretch);
  return clamp(log2(max(rho, 1e-30)), 0.0, pyramid.z - 1.0);
}

// A step of the scaled-space direction s as (dlon, dlat) in radians: on the unit sphere, with
// geocentric angles (within the body's flattening of the geodetic ones: enough for a level of
// detail). The grid pass and the screen pass take their footprints this way, from the step to
// the nearer neighbour along each axis (GLOBE_FOOTPRINT below).
vec2 globe_footprintLonLatStep(vec3 s, vec3 step)
{
  float lon = atan(s.y, s.x);
  float cosLat = max(length(s.xy), 1e-7);
  vec3 east = vec3(-sin(lon), cos(lon), 0.0);
  vec3 north = vec3(-s.z * cos(lon), -s.z * sin(lon), cosLat);
  return vec2(dot(step, east) / cosLat, dot(step, north));
}

// Of two steps to the neighbours on either side, the shorter; a missing one (vec3(1e30): beyond
// the grid or the window, or not on the body) or a NaN one loses: across a silhouette or the
// horizon one side jumps to another surface. So does a zero step: grid points past the limb
// share their horizon point (globe_pgmGridPoint), and a zero step says nothing of the
// footprint (it would ask for level 0).
vec3 globe_footprintShorterStep(vec3 before, vec3 after)
{
  float a = length(before), b = length(after);
  bool hasA = !isnan(a) && a > 0.0 && a < 1e29, hasB = !isnan(b) && b > 0.0 && b < 1e29;
  if (hasA && (!hasB || a <= b))
  {
    return before;
  }
  return hasB ? after : vec3(0.0);
}
