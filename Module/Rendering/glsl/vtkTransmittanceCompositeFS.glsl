//VTK::System::Dec
// Tyndall: draws the ray cast's accumulated image (premultiplied radiance,
// alpha = 1 - view transmittance) over the renderer's viewport, upscaled
// with linear filtering when it was rendered at a reduced size
// (vtkTransmittanceAccumulationPass). Blended ONE, ONE_MINUS_SRC_ALPHA.
// The colour goes through the mapper's display transform first
// (tyndallDisplay(), vtkTransmittanceOutputFS.glsl). With
// opacityCoversRadiance 1 (the picture goes to an 8-bit compositor that
// blends without clamping, IceT under MPI) the alpha is raised to the
// colour.
in vec2 texCoord;
uniform sampler2D accumulated;
uniform int opacityCoversRadiance;
// With a coloured extinction (chromaticBehind 1) the background is seen
// through the transmittance per channel, 1 - transmittanceImage.
uniform int chromaticBehind;
uniform sampler2D transmittanceImage;
//VTK::Output::Dec
//TYNDALL::Output

void main()
{
  vec4 value = texture(accumulated, texCoord);
  value = chromaticBehind == 1
    ? tyndallDisplayBehind(value, vec3(1.0) - texture(transmittanceImage, texCoord).rgb)
    : tyndallDisplay(value);
  if (opacityCoversRadiance == 1)
  {
    value.a = max(value.a, min(max(value.r, max(value.g, value.b)), 1.0));
  }
  gl_FragData[0] = value;
}
