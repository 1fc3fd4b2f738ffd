//VTK::System::Dec
// Tyndall: writes a depth-peeling stage's outputs from the volume's two ray
// casts (vtkTransmittancePeelingPass): frontImage and backImage hold the
// premultiplied radiance and opacity of the front and back depth ranges
// (vtkTransmittancePeelRangesFS.glsl; in the blending stage its one range is
// the front). The outputs, and the blending the pass set for them, are VTK
// 9.1's for its own ray caster: gl_FragData[0] the back colour,
// gl_FragData[1] the front colour under-blended onto the last peel's
// (the pass's front targets hold 1 - alpha, for MAX blending). Drawn over
// the pass's viewport-sized targets. The opacity of a pixel with radiance is
// raised (tyndallPeelColor()): VTK's ray caster never has more colour than
// opacity, Tyndall's emission can.
//TYNDALL::Constants
in vec2 texCoord;
uniform sampler2D frontImage;
uniform sampler2D backImage;
uniform sampler2D outerDepthTex;
uniform sampler2D lastFrontColorTex;
uniform sampler2D depthRangeTex;
uniform int peelStage; // TYNDALL_PEEL_INITIALIZING ..
uniform int opacityCoversRadiance;
//VTK::Output::Dec
//TYNDALL::Output

// A premultiplied colour as the pass's 8-bit targets take it: the opacity at
// least the radiance for an 8-bit compositor downstream (IceT, as
// vtkTransmittanceCompositeFS.glsl does), else at least 1/255 where there
// is radiance (the pass drops back fragments whose 8-bit opacity is 0);
// the colour through the mapper's display transform first (each range's
// light is mapped before VTK blends the peels).
vec4 tyndallPeelColor(vec4 c)
{
  c = tyndallDisplay(c);
  float radiance = max(c.r, max(c.g, c.b));
  if (opacityCoversRadiance == 1)
  {
    c.a = max(c.a, min(radiance, 1.0));
  }
  else if (radiance > 0.0)
  {
    c.a = max(c.a, 1.0 / 255.0);
  }
  return c;
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 front = tyndallPeelColor(texture(frontImage, texCoord));
  if (peelStage == TYNDALL_PEEL_BLENDING)
  {
    if (texelFetch(depthRangeTex, pixel, 0).x == -1.0)
    {
      discard; // peeled already
    }
    gl_FragData[0] = front;
    return;
  }
  vec4 back = tyndallPeelColor(texture(backImage, texCoord));
  if (peelStage == TYNDALL_PEEL_INITIALIZING)
  {
    gl_FragData[0] = back;
    gl_FragData[1] = front;
    return;
  }
  if (texelFetch(outerDepthTex, pixel, 0).x == -1.0)
  {
    discard; // peeled already
  }
  vec4 last = texelFetch(lastFrontColorTex, pixel, 0);
  last.a = 1.0 - last.a;
  gl_FragData[0] = back;
  gl_FragData[1] = vec4(last.a * front.rgb + last.rgb, 1.0 - last.a * (1.0 - front.a));
}
