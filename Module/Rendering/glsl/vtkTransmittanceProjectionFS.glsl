// Tyndall: VTK's projection blend modes (appended to
// vtkTransmittanceCommonFS.glsl and vtkTransmittanceCameraRayFS.glsl):
// maximum, minimum and average intensity, additive and the slice, as VTK
// 9.1's GPU mapper draws them (TYNDALL_PROJECTION: one of
// TYNDALL_PROJECTION_MAXIMUM .. _SLICE). The rules and their CPU twin: vtkTyndallProjection (Ray).
// One pass draws the whole ray straight into the window (one loop trip per
// step: vtkTransmittanceProjectionPass keeps the steps within llvmpipe's
// budget).
uniform float stepLength;
uniform int endStep;         // the most steps a ray takes
uniform vec2 valueToUnit;    // u = value * x + y: the scalar on the data's finite range
uniform vec2 averageRange;   // average intensity: the values counted
uniform float additiveScale; // additive: 1 / the property's unit distance

// What a ray has gathered: the extremum, or the sum and the samples counted.
struct TyndallProjection
{
  float Value;
  float Sum;
  int Count;
};

void tyndallProject(inout TyndallProjection p, float value, float dt)
{
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE
  p.Value = value; // the one sample, on the plane
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_MAXIMUM
  p.Value = p.Count > 0 ? max(p.Value, value) : value;
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_MINIMUM
  p.Value = p.Count > 0 ? min(p.Value, value) : value;
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_AVERAGE
  if (value < averageRange.x || value > averageRange.y)
  {
    return; // not counted
  }
  p.Sum += tyndallOpacityFunction(value) * (value * valueToUnit.x + valueToUnit.y);
#else
  p.Sum += tyndallOpacityFunction(value) * dt * additiveScale * (value * valueToUnit.x + valueToUnit.y);
#endif
  p.Count += 1;
}

// The ray's premultiplied pixel; false where it draws nothing.
bool tyndallProjectionPixel(TyndallProjection p, out vec4 pixel)
{
  pixel = vec4(0.0);
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_MAXIMUM || \
  TYNDALL_PROJECTION == TYNDALL_PROJECTION_MINIMUM || TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE
  if (p.Count == 0)
  {
    return false;
  }
  vec3 color = texture(transferTexture,
    vec2(p.Value * scalarToTable.x + scalarToTable.y, TYNDALL_TABLE_ALBEDO_ROW)).rgb;
  float alpha = tyndallOpacityFunction(p.Value);
  pixel = vec4(color * alpha, alpha);
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_AVERAGE
  if (p.Count == 0)
  {
    return false;
  }
  pixel = vec4(vec3(clamp(p.Sum / float(p.Count), 0.0, 1.0)), 1.0);
#else
  pixel = vec4(vec3(clamp(p.Sum, 0.0, 1.0)), 1.0);
#endif
  return true;
}

#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE
uniform vec4 slicePlane; // the slice: n . x + d = 0 (world), as (n, d)
#endif

// What the ray p0 + t w over [tNear, tFar] gathers: its samples, or for
// the slice the one where it meets the plane.
TyndallProjection tyndallGather(vec3 p0, vec3 w, float tNear, float tFar)
{
  TyndallProjection gathered = TyndallProjection(0.0, 0.0, 0);
  // The ray in texture coordinates: texel(t) = texel0 + t dTexel.
  vec3 texel0 = (worldToVolume * vec4(p0, 1.0)).xyz * volumeTexScale + volumeTexShift;
  vec3 dTexel = (worldToVolume * vec4(w, 0.0)).xyz * volumeTexScale;
  float value;
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE
  float denominator = dot(slicePlane.xyz, w);
  float ts = abs(denominator) > 1e-12 ? -(dot(slicePlane.xyz, p0) + slicePlane.w) / denominator
                                      : -1e30;
  if (ts >= tNear && ts <= tFar && tyndallKeptScalar(p0 + ts * w, texel0 + ts * dTexel, value))
  {
    tyndallProject(gathered, value, 0.0);
  }
#else
  // VTK's sample positions: one at the end of each step (no jitter: it
  // frays the edges of a crop or a clipping plane at VTK's step). Step n
  // spans [tNear + n stepLength, tNear + (n + 1) stepLength), the last one
  // cut at tFar.
  for (int n = 0; n < endStep; ++n)
  {
    float t0 = tNear + float(n) * stepLength;
    if (!(t0 < tFar))
    {
      break;
    }
    float dt = min(stepLength, tFar - t0);
    float ts = t0 + dt;
    if (tyndallKeptScalar(p0 + ts * w, texel0 + ts * dTexel, value))
    {
      tyndallProject(gathered, value, dt);
    }
  }
#endif
  return gathered;
}

void main()
{
  vec3 p0, w;
  float tNear, tFar;
  tyndallCameraRay(p0, w, tNear, tFar);
  if (!(tNear < tFar))
  {
    discard;
  }
  TyndallProjection gathered = tyndallGather(p0, w, tNear, tFar);
  vec4 pixel;
  if (!tyndallProjectionPixel(gathered, pixel))
  {
    discard;
  }
  gl_FragData[0] = pixel;
}
