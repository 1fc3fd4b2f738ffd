// Tyndall: the pixel's camera ray, for the passes that march one
// (appended to vtkTransmittanceCommonFS.glsl, before the pass's own file:
// vtkTransmittanceRayCastFS.glsl, vtkTransmittanceProjectionFS.glsl). The
// quad covers the renderer's viewport; its pixels may be a reduced image's
// (fragToWindow maps them to the window's).
in vec2 texCoord;
//VTK::Output::Dec

uniform mat4 ndcToWorld;
uniform sampler2D depthTexture; // the whole window's depth (or depth ranges, below)
uniform vec4 fragToWindow;      // window pixel = gl_FragCoord.xy * xy + zw
uniform int jitter;
#if TYNDALL_DEPTH_RANGES
// Drawn in a stage of VTK's dual depth peeling (vtkTransmittancePeelingPass):
// depthTexture holds two ranges of window depths per pixel, (start, end) of
// the front part in xy and of the back part in zw; the ray marches the half
// depthRangeHalf (0: xy, 1: zw) names.
uniform int depthRangeHalf;
#endif

vec3 unproject(vec2 ndcXY, float ndcZ)
{
  vec4 p = ndcToWorld * vec4(ndcXY, ndcZ, 1.0);
  return p.xyz / p.w;
}

// The window depths (0..1) the pixel's ray runs between: from the near plane
// to the opaque geometry, or in a depth-peeling stage the range it is given.
vec2 tyndallDepthRange(vec2 windowXY)
{
  vec4 depths = texture(depthTexture, windowXY / vec2(textureSize(depthTexture, 0)));
#if TYNDALL_DEPTH_RANGES
  return depthRangeHalf == 0 ? depths.xy : depths.zw;
#else
  return vec2(0.0, depths.r);
#endif
}

// The pixel's ray: its origin p0 on the near plane, its unit direction w,
// and the part [tNear, tFar] of it inside the camera rays' box and in its
// depth range (empty when !(tNear < tFar)).
void tyndallCameraRay(out vec3 p0, out vec3 w, out float tNear, out float tFar)
{
  vec2 ndc = 2.0 * texCoord - 1.0;
  vec2 depths = tyndallDepthRange(gl_FragCoord.xy * fragToWindow.xy + fragToWindow.zw);
  p0 = unproject(ndc, -1.0);
  w = normalize(unproject(ndc, 1.0) - p0);
  float tStart = depths.x > 0.0 ? dot(unproject(ndc, 2.0 * depths.x - 1.0) - p0, w) : 0.0;
  float tDepth = dot(unproject(ndc, 2.0 * depths.y - 1.0) - p0, w);
  vec2 range = tyndallIntersectCameraBox(p0, w);
  tNear = max(range.x, max(tStart, 0.0));
  tFar = min(range.y, depths.y > depths.x ? tDepth : -1.0);
}

// Where a step's sample lies within the step, as a fraction of it: the
// middle, or with jitter a fixed per-pixel hash (the same pixel gets the
// same offset every frame).
float tyndallStepOffset()
{
  if (jitter == 0)
  {
    return 0.5;
  }
  return fract(sin(dot(gl_FragCoord.xy, vec2(12.9898, 78.233))) * 43758.5453);
}
