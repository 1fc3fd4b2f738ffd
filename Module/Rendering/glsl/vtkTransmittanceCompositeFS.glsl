//VTK::System::Dec
// Tyndall: draws the ray cast's accumulated image (premultiplied radiance,
// alpha = 1 - view transmittance) over the renderer's viewport, upscaled
// with linear filtering when it was rendered at a reduced size
// (vtkTransmittanceAccumulationPass). Blended ONE, ONE_MINUS_SRC_ALPHA.
in vec2 texCoord;
uniform sampler2D accumulated;
//VTK::Output::Dec

void main()
{
  gl_FragData[0] = texture(accumulated, texCoord);
}
