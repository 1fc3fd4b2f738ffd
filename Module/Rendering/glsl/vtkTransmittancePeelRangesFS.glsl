//VTK::System::Dec
// Tyndall: the window depths a volume's camera rays march in one stage of
// VTK's dual depth peeling (vtkDualDepthPeelingPass with
// UseDepthPeelingForVolumes; vtkTransmittancePeelingPass). Writes, per
// pixel, (start, end) of the front part in xy and of the back part in zw; a
// part with !(start < end) is empty. The rules are VTK 9.1's for its own
// ray caster (vtkDualDepthPeelingPass::PreReplaceVolumetricShaderValues),
// read from the textures the pass binds under the names it sets
// (SetShaderParameters). Drawn over the renderer's viewport in a texture of
// the window's size; the pass's textures are the viewport's size.
//TYNDALL::Constants
uniform sampler2D outerDepthTex; // (-near, far) depths of the peels so far
uniform sampler2D innerDepthTex; // the next peel's (-near, far) depths
uniform sampler2D opaqueDepthTex;
uniform sampler2D depthRangeTex; // the last stage's (-start, end)
uniform int peelStage;           // TYNDALL_PEEL_INITIALIZING ..
uniform vec2 viewportSize;       // the pass's textures' size
in vec2 texCoord;                // 0..1 over the renderer's viewport
//VTK::Output::Dec

const vec2 noRange = vec2(1.0, 0.0);

// Before the peels: the volume outside the translucent geometry's depths.
vec4 tyndallInitialRanges(ivec2 pixel)
{
  vec2 inner = texelFetch(innerDepthTex, pixel, 0).xy;
  vec2 outer = texelFetch(outerDepthTex, pixel, 0).xy;
  bool opaque = outer.y >= 0.0;
  bool translucent = inner.x != -1.0;
  if (!opaque && !translucent)
  {
    return vec4(noRange, 0.0, 1.0);
  }
  if (!translucent)
  {
    return vec4(noRange, 0.0, inner.y); // opaque geometry only
  }
  return vec4(0.0, -inner.x, inner.y, opaque ? outer.y : 1.0);
}

// One peel: from the last peel's near depth to this one's, and from this
// one's far depth to the last one's, cut at opaque geometry.
vec4 tyndallPeelRanges(ivec2 pixel)
{
  vec2 inner = texelFetch(innerDepthTex, pixel, 0).xy;
  vec2 outer = texelFetch(outerDepthTex, pixel, 0).xy;
  if (outer.x == -1.0)
  {
    return vec4(noRange, noRange); // peeled already
  }
  float frontStart = -outer.x, frontEnd = -inner.x;
  float backStart = inner.y, backEnd = outer.y;
  bool onlyBack = frontStart == backStart && frontEnd == backEnd;
  bool noInner = inner.x == -1.0;
  if (noInner)
  {
    frontEnd = outer.y;
  }
  float opaqueDepth = texelFetch(opaqueDepthTex, pixel, 0).x;
  bool endBehindOpaque = frontEnd >= opaqueDepth;
  vec2 front = onlyBack ? noRange : vec2(frontStart, endBehindOpaque ? opaqueDepth : frontEnd);
  vec2 back = !endBehindOpaque && !noInner ? vec2(backStart, backEnd) : noRange;
  return vec4(front, back);
}

// After the last peel: what lies between its depths.
vec4 tyndallBlendingRange(ivec2 pixel)
{
  vec2 range = texelFetch(depthRangeTex, pixel, 0).xy;
  return range.x == -1.0 ? vec4(noRange, noRange) : vec4(-range.x, range.y, noRange);
}

void main()
{
  ivec2 pixel = ivec2(texCoord * viewportSize); // the pass's pixel
  if (peelStage == TYNDALL_PEEL_INITIALIZING)
  {
    gl_FragData[0] = tyndallInitialRanges(pixel);
  }
  else if (peelStage == TYNDALL_PEEL_PEELING)
  {
    gl_FragData[0] = tyndallPeelRanges(pixel);
  }
  else
  {
    gl_FragData[0] = tyndallBlendingRange(pixel);
  }
}
