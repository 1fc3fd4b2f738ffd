// Tyndall: VTK's projection blend modes (appended to
// vtkTransmittanceCommonFS.glsl and vtkTransmittanceCameraRayFS.glsl):
// maximum, minimum and average intensity, additive and the slice, as VTK
// 9.1's GPU mapper draws them (TYNDALL_PROJECTION: one of
// TYNDALL_PROJECTION_MAXIMUM .. _SLICE). The rules and their CPU twin: vtkTyndallProjection (Ray);
// the lights (VTK's slice is shaded): vtkTransmittanceLightsFS.glsl, before this file.
// One pass draws the whole ray straight into the window (one loop trip per
// step: vtkTransmittanceProjectionPass keeps the steps within llvmpipe's
// budget).
uniform float stepLength;
uniform int endStep;         // the most steps a ray takes
uniform vec2 valueToUnit;    // u = value * x + y: the scalar on the data's finite range
uniform vec2 averageRange;   // average intensity: the values counted
uniform float additiveScale; // additive: 1 / the property's unit distance

#if TYNDALL_COMPONENTS > 1
// Several components (vtkTyndallProjection::Ray's AddComponents() and
// ComponentPixel() are the CPU twins), read at each sample together.
#define TyndallSample vec4
#define tyndallKeptSample tyndallKeptComponents
uniform vec4 componentAdditiveScale; // additive: 1 / each component's unit distance
                                     // (dependent: the opacity component's, VTK's)

// What a ray has gathered: independent components each their extremum, sum
// and count; dependent ones the whole sample kept (Value), the sum and the
// count in x.
struct TyndallProjection
{
  vec4 Value;
  vec4 Sum;
  vec4 Count;
};

// Table t's opacity function at its component's value v.
float tyndallComponentOpacity(int t, float v)
{
  return tyndallComponentRow(t, v * componentToTable[0][t] + componentToTable[1][t], 1).a;
}

// Component c's value v on its finite range.
float tyndallComponentUnit(int c, float v)
{
  return v * componentUnit[0][c] + componentUnit[1][c];
}

#if TYNDALL_COMPONENT_MODE == TYNDALL_COMPONENTS_INDEPENDENT
void tyndallProject(inout TyndallProjection p, vec4 values, float dt)
{
  for (int i = 0; i < TYNDALL_COMPONENTS; ++i)
  {
    float v = values[i];
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE
    p.Value[i] = v;
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_MAXIMUM
    p.Value[i] = p.Count.x > 0.0 ? max(p.Value[i], v) : v;
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_MINIMUM
    p.Value[i] = p.Count.x > 0.0 ? min(p.Value[i], v) : v;
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_AVERAGE
    if (v >= averageRange.x && v <= averageRange.y)
    {
      p.Sum[i] += tyndallComponentOpacity(i, v) * tyndallComponentUnit(i, v);
      p.Count[i] += 1.0;
    }
#else
    p.Sum[i] += tyndallComponentOpacity(i, v) * dt * componentAdditiveScale[i] * tyndallComponentUnit(i, v);
#endif
  }
#if TYNDALL_PROJECTION != TYNDALL_PROJECTION_AVERAGE
  p.Count += vec4(1.0);
#endif
}

bool tyndallProjectionPixel(TyndallProjection p, out vec4 pixel)
{
  pixel = vec4(0.0);
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_AVERAGE || TYNDALL_PROJECTION == TYNDALL_PROJECTION_ADDITIVE
  float grey = 0.0;
  for (int i = 0; i < TYNDALL_COMPONENTS; ++i)
  {
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_AVERAGE
    grey += p.Count[i] > 0.0 ? componentWeights[i] * p.Sum[i] / p.Count[i] : 0.0;
#else
    grey += componentWeights[i] * p.Sum[i];
#endif
  }
  pixel = vec4(vec3(clamp(grey, 0.0, 1.0)), 1.0);
#else
  if (p.Count.x == 0.0)
  {
    return false;
  }
  for (int i = 0; i < TYNDALL_COMPONENTS; ++i)
  {
    float coord = p.Value[i] * componentToTable[0][i] + componentToTable[1][i];
    float a = tyndallComponentRow(i, coord, 1).a;
    pixel += componentWeights[i] * a * vec4(tyndallComponentRow(i, coord, 0).rgb, 1.0);
  }
  pixel = clamp(pixel, 0.0, 1.0);
#endif
  return true;
}
#else
// Dependent: the opacity component is the last; its table is table 1 of
// two components (table 0 is the colour's), table 0 of RGBA.
#if TYNDALL_COMPONENT_MODE == TYNDALL_COMPONENTS_LA
#define TYNDALL_OPACITY_COMPONENT 1
#define TYNDALL_OPACITY_TABLE 1
#else
#define TYNDALL_OPACITY_COMPONENT 3
#define TYNDALL_OPACITY_TABLE 0
#endif

void tyndallProject(inout TyndallProjection p, vec4 values, float dt)
{
  float opacity = values[TYNDALL_OPACITY_COMPONENT];
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE
  p.Value = values;
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_MAXIMUM
  if (p.Count.x == 0.0 || opacity > p.Value[TYNDALL_OPACITY_COMPONENT])
  {
    p.Value = values;
  }
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_MINIMUM
  if (p.Count.x == 0.0 || opacity < p.Value[TYNDALL_OPACITY_COMPONENT])
  {
    p.Value = values;
  }
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_AVERAGE
  if (values.x < averageRange.x || values.x > averageRange.y)
  {
    return; // not counted
  }
  p.Sum.x += tyndallComponentOpacity(TYNDALL_OPACITY_TABLE, opacity) * tyndallComponentUnit(0, values.x);
#else
  p.Sum.x += tyndallComponentOpacity(TYNDALL_OPACITY_TABLE, opacity) * dt *
    componentAdditiveScale[TYNDALL_OPACITY_COMPONENT] *
    tyndallComponentUnit(0, values.x);
#endif
  p.Count.x += 1.0;
}

bool tyndallProjectionPixel(TyndallProjection p, out vec4 pixel)
{
  pixel = vec4(0.0);
#if TYNDALL_PROJECTION != TYNDALL_PROJECTION_ADDITIVE
  if (p.Count.x == 0.0)
  {
    return false;
  }
#endif
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_AVERAGE
  pixel = vec4(vec3(clamp(p.Sum.x / p.Count.x, 0.0, 1.0)), 1.0);
#elif TYNDALL_PROJECTION == TYNDALL_PROJECTION_ADDITIVE
  pixel = vec4(vec3(clamp(p.Sum.x, 0.0, 1.0)), 1.0);
#else
  // The kept sample classified as the composite mode does.
  float a = tyndallComponentOpacity(TYNDALL_OPACITY_TABLE, p.Value[TYNDALL_OPACITY_COMPONENT]);
#if TYNDALL_COMPONENT_MODE == TYNDALL_COMPONENTS_LA
  vec3 color = tyndallComponentRow(0, p.Value.x * componentToTable[0].x + componentToTable[1].x, 0).rgb;
#else
  vec3 color = clamp(p.Value.rgb * componentUnit[0].rgb + componentUnit[1].rgb, 0.0, 1.0);
#endif
  pixel = vec4(color * a, a);
#endif
  return true;
}
#endif
#else
#define TyndallSample float
#define tyndallKeptSample tyndallKeptScalar

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
#endif

#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE
uniform vec4 slicePlane; // the slice: n . x + d = 0 (world), as (n, d)
// Where the slice's sample lies (world) and its texture coordinate.
vec3 slicePoint = vec3(0.0);
vec3 sliceTexel = vec3(0.0);
#endif

// The pixel (premultiplied) of what the ray gathered, as a surface. The
// slice of one component as VTK 9.1 draws it (CPU twin:
// vtkSingleScatteringReference's SliceSurface()): with Shade
// (TYNDALL_SHADING) the colour shaded as a surface by the lights,
// unshadowed (a projection has no maps), for the view direction w; with
// gradient opacity its alpha, not the colour's weight, multiplied by it.
// The other projections: the pixel as it is.
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE && TYNDALL_COMPONENTS == 1
void tyndallProjectionSurface(TyndallProjection gathered, vec3 w, inout vec4 pixel)
{
  float value = gathered.Value;
#if TYNDALL_SHADING
  vec3 color = texture(transferTexture,
    vec2(value * scalarToTable.x + scalarToTable.y, TYNDALL_TABLE_ALBEDO_ROW)).rgb;
  vec3 g = tyndallScalarGradient(slicePoint);
  float magnitude = length(g);
  vec3 n = magnitude > 0.0 ? g / magnitude : vec3(0.0);
  vec3 v = -w;
  vec3 surface = shadingCoefficients[0].x * color;
  for (int l = 0; l < numberOfLights; ++l)
  {
    vec3 toLight;
    float distance;
    vec3 E = lightColor[l];
    if (!tyndallLightAt(l, slicePoint, E, toLight, distance))
    {
      continue;
    }
    vec3 s = lightHeadlight[l] != 0 ? v : toLight;
    surface += E * tyndallShadingTerm(shadingCoefficients[0], n, s, tyndallHalfVector(s, v), color);
  }
  pixel.rgb = clamp(surface, 0.0, 1.0) * pixel.a;
#endif
#if TYNDALL_GRADIENT_OPACITY
  pixel.a *= tyndallGradientOpacity(sliceTexel);
#endif
}
#else
void tyndallProjectionSurface(TyndallProjection gathered, vec3 w, inout vec4 pixel)
{
}
#endif

// What the ray p0 + t w over [tNear, tFar] gathers: its samples, or for
// the slice the one where it meets the plane.
TyndallProjection tyndallGather(vec3 p0, vec3 w, float tNear, float tFar)
{
#if TYNDALL_COMPONENTS > 1
  TyndallProjection gathered = TyndallProjection(vec4(0.0), vec4(0.0), vec4(0.0));
#else
  TyndallProjection gathered = TyndallProjection(0.0, 0.0, 0);
#endif
  // The ray in texture coordinates: texel(t) = texel0 + t dTexel.
  vec3 texel0 = (worldToVolume * vec4(p0, 1.0)).xyz * volumeTexScale + volumeTexShift;
  vec3 dTexel = (worldToVolume * vec4(w, 0.0)).xyz * volumeTexScale;
  TyndallSample value;
#if TYNDALL_PROJECTION == TYNDALL_PROJECTION_SLICE
  float denominator = dot(slicePlane.xyz, w);
  float ts = abs(denominator) > 1e-12 ? -(dot(slicePlane.xyz, p0) + slicePlane.w) / denominator
                                      : -1e30;
  slicePoint = p0 + ts * w;
  sliceTexel = texel0 + ts * dTexel;
  if (ts >= tNear && ts <= tFar && tyndallKeptSample(slicePoint, sliceTexel, value))
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
    if (tyndallKeptSample(p0 + ts * w, texel0 + ts * dTexel, value))
    {
      tyndallProject(gathered, value, dt);
    }
  }
#endif
  return gathered;
}

//TYNDALL::Output

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
  tyndallProjectionSurface(gathered, w, pixel);
  gl_FragData[0] = tyndallDisplay(pixel);
}
