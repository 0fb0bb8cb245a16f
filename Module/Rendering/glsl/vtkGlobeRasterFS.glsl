//VTK::System::Dec
//VTK::Output::Dec
// Rasterization: writes the G-buffer (direction, or with high-precision geodetic coordinates its
// offset from the frame's local origin, and height per pixel) and depth. Directions are
// interpolated, never longitudes (no 0/360 degree seam).
in vec4 globeDirectionHeight;
in float globeValid;

void main()
{
  // A triangle touching an invalid grid point (no horizon: the eye not above the primary
  // sphere) is dropped.
  if (globeValid < 0.9999)
  {
    discard;
  }
  gl_FragData[0] = globeDirectionHeight;
}
