// Tyndall: fills one slice of a light's transmittance cache (appended to
// vtkTransmittanceCommonFS.glsl, compiled with the frame's map variant).
// One fragment per texel: the light's map transmittance at the texel's
// point of the camera rays' box (the medium's, or with camera guests the
// box around them all); texel (i, j) of slice k lies at box coordinate
// (i, j, k) / (n - 1), so the lattice's outer texels sit on the box's faces.
in vec2 texCoord;
//VTK::Output::Dec

uniform int lightIndex;
uniform vec3 lightCacheSize; // texels per axis of the light's lattice
uniform float sliceCoordinate; // k / (n_z - 1)
uniform mat4 boxToWorld;

void main()
{
  // texCoord is (i + 0.5) / n at the texel's centre.
  vec2 q = (texCoord * lightCacheSize.xy - 0.5) / (lightCacheSize.xy - 1.0);
  vec3 x = (boxToWorld * vec4(q, sliceCoordinate, 1.0)).xyz;
  // Per channel with a coloured extinction (an RGBA texture then), else in red.
  gl_FragData[0] = vec4(vec3(tyndallMapTransmittance(lightIndex, x)), 1.0);
}
