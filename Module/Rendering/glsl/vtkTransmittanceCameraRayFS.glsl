// Tyndall: the pixel's camera ray, for the passes that march one
// (appended to vtkTransmittanceCommonFS.glsl, before the pass's own file:
// vtkTransmittanceRayCastFS.glsl, vtkTransmittanceProjectionFS.glsl). The
// quad covers the renderer's viewport; its pixels may be a reduced image's
// (fragToWindow maps them to the window's).
in vec2 texCoord;
//VTK::Output::Dec

uniform mat4 ndcToWorld;
uniform sampler2D depthTexture; // the whole window's depth
uniform vec4 fragToWindow;      // window pixel = gl_FragCoord.xy * xy + zw
uniform int jitter;

vec3 unproject(vec2 ndcXY, float ndcZ)
{
  vec4 p = ndcToWorld * vec4(ndcXY, ndcZ, 1.0);
  return p.xyz / p.w;
}

// The pixel's ray: its origin p0 on the near plane, its unit direction w,
// and the part [tNear, tFar] of it inside the camera rays' box and in front
// of opaque geometry (empty when !(tNear < tFar)).
void tyndallCameraRay(out vec3 p0, out vec3 w, out float tNear, out float tFar)
{
  vec2 ndc = 2.0 * texCoord - 1.0;
  vec2 windowXY = gl_FragCoord.xy * fragToWindow.xy + fragToWindow.zw;
  float depthNdc =
    2.0 * texture(depthTexture, windowXY / vec2(textureSize(depthTexture, 0))).r - 1.0;
  p0 = unproject(ndc, -1.0);
  vec3 p1 = unproject(ndc, depthNdc);
  w = normalize(p1 - p0);
  float tDepth = length(p1 - p0);
  vec2 range = tyndallIntersectCameraBox(p0, w);
  tNear = max(range.x, 0.0);
  tFar = min(range.y, tDepth);
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
