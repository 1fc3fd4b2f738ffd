// Tyndall: procedural detail, the GLSL twin of vtkTyndallDetailMedium
// (inserted into vtkTransmittanceCommonFS.glsl when the medium has a detail
// noise). Extinction = shape(p) * detailScale * max(0, noise(p)), p in field
// index coordinates; the shape is the pre-classified extinction, one texel
// per sample of the grid; the noise is detailOffset plus the waves, four per
// group (TYNDALL_DETAIL_GROUPS groups, coarsest first; unused waves have
// amplitude 0). The waves are constants of the program (detailKx, detailKy,
// detailKz: wave vectors in field index units; detailPhase, detailAmplitude;
// detailDecay: the footprint filter's, vtkTransmittanceDetailAdapter::
// WaveConstants()).
// TYNDALL_DETAIL_FOR_GROUPS(X) expands to X(0) X(1) .. X(groups - 1): the
// wave loops are unrolled by the preprocessor, so they count no loop
// iterations against llvmpipe's limit.
uniform sampler3D detailShapeTexture;
uniform vec3 detailDims;    // samples per axis
uniform vec3 detailBoxLow;  // the box [0,1]^3 -> field index: low + q size
uniform vec3 detailBoxSize;
uniform int detailMaxCells; // cells a ray can cross: the sum of detailDims, plus 3
uniform float detailOffset;
uniform float detailScale;
#if TYNDALL_DETAIL_UNIFORM_ALBEDO
uniform vec3 detailAlbedo; // the colour table's one colour
#endif

// cos(2 pi y) per component, y in cycles: y reduced to r in [-1/2, 1/2]
// cycles, then cos(2 pi r) = sin(2 pi s) with s = 1/4 - |r| in [-1/4, 1/4],
// an odd polynomial of degree 7 fitted to sin there (minimax: within 6e-7;
// beyond the reduction's rounding, 1e-5 at |y| = 100 cycles, the float
// phase's own uncertainty there). Cheaper than llvmpipe's built-in cos, and
// than the Taylor series of cos to x^16 on [-pi, pi] it replaced: 13
// operations a wave instead of 18, the unfiltered default scene's frame
// 0.93 s instead of 1.17 (llvmpipe, 512^2). The waves' constants are in
// radians; times 1 / (2 pi) they fold into literals.
#define TYNDALL_CYCLES 0.15915494309189535
vec4 tyndallCosCycles(vec4 y)
{
  vec4 s = 0.25 - abs(y - floor(y + 0.5));
  vec4 z = s * s;
  return s * (6.283164069 + z * (-41.33714633 + z * (81.34092084 + z * -70.99505451)));
}

// The phases of group g at field index point p, in cycles.
#define TYNDALL_DETAIL_CYCLES(g, p) ((detailKx[g] * TYNDALL_CYCLES) * p.x + (detailKy[g] * TYNDALL_CYCLES) * p.y + (detailKz[g] * TYNDALL_CYCLES) * p.z + detailPhase[g] * TYNDALL_CYCLES)

#if TYNDALL_DETAIL_STEP_MEANS
// A camera sample stands for the mean of the noise over a step's length
// centred on it (vtkTyndallDetailMedium::StepMeanNoise()): each wave at the
// sample times sinc(k . span / 2), span the step (field index), exactly
// however many periods the step spans. The samples are a step apart
// (jittered or not), so those spans tile the ray. So the march steps by
// the shape and the light, not the waves (only without brute-force lights,
// whose march through guests would take the same function:
// vtkTransmittanceFrame::UsesDetailStepMeans()). tyndallDetailRayStep()
// sets the amplitudes times their sinc for a ray's direction w (world) and
// step dt; the ray-cast pass calls it before the march and where the step
// changes (the last).
vec4 detailStepAmplitude[TYNDALL_DETAIL_GROUPS];

#define TYNDALL_DETAIL_STEP_GROUP(g) { vec4 x = 0.5 * (detailKx[g] * span.x + detailKy[g] * span.y + detailKz[g] * span.z); detailStepAmplitude[g] = detailAmplitude[g] * mix(sin(x) / x, vec4(1.0), lessThan(abs(x), vec4(1e-4))); }

void tyndallDetailRayStep(vec3 w, float dt)
{
  vec3 span = dt * (worldToVolume * vec4(w, 0.0)).xyz * detailBoxSize;
  TYNDALL_DETAIL_FOR_CAMERA_GROUPS(TYNDALL_DETAIL_STEP_GROUP)
}
#else
// The camera step resolves the waves (or brute-force lights march the
// same function with a footprint of 0): a sample takes them at its point.
#define detailStepAmplitude detailAmplitude
#endif

#define TYNDALL_DETAIL_NOISE_GROUP(g) sum += dot(detailAmplitude[g], tyndallCosCycles(TYNDALL_DETAIL_CYCLES(g, p)));

// The noise at field index point p.
float tyndallDetailNoise(vec3 p)
{
  float sum = detailOffset;
  TYNDALL_DETAIL_FOR_GROUPS(TYNDALL_DETAIL_NOISE_GROUP)
  return sum;
}

#if TYNDALL_DETAIL_FILTER
// The footprint filter of camera samples (vtkTyndallDetailMedium::
// FilteredNoise()): each group times its level's exp(-|k|^2 sigma^2 / 2)
// = exp2(decay pixel^2), sigma the filter's width times the pixel's, or 0
// below TYNDALL_DETAIL_CUTOFF; only the first TYNDALL_DETAIL_CAMERA_GROUPS
// groups, the waves a pixel of this frame can show. A level's factor is
// the one below it to the power 1.5 (|k|^2 1.5 times larger): e sqrt(e),
// detailLevelSteps[g] times from the group before, or where that is more
// than TYNDALL_DETAIL_MAX_LEVEL_STEPS (vtkTransmittanceDetailAdapter::
// MaximumLevelSteps, 5: the macro climbs five) its own exponential. The conditions are constants: the compiler keeps only the
// operations a group needs.
#define TYNDALL_DETAIL_FILTERED_GROUP(g) if (detailLevelSteps[g] > TYNDALL_DETAIL_MAX_LEVEL_STEPS) { e = exp2(detailDecay[g] * pixel2); } else { if (detailLevelSteps[g] > 0) { e *= sqrt(e); } if (detailLevelSteps[g] > 1) { e *= sqrt(e); } if (detailLevelSteps[g] > 2) { e *= sqrt(e); } if (detailLevelSteps[g] > 3) { e *= sqrt(e); } if (detailLevelSteps[g] > 4) { e *= sqrt(e); } } if (detailLevelSteps[g] > 0) { f = e * step(TYNDALL_DETAIL_CUTOFF, e); } sum += f * dot(detailStepAmplitude[g], tyndallCosCycles(TYNDALL_DETAIL_CYCLES(g, p)));

float tyndallDetailFilteredNoise(vec3 p, float pixel)
{
  float pixel2 = pixel * pixel;
  float sum = detailOffset;
  float e = 1.0; // the factor of the current level
  float f = 1.0; // the same, 0 below the cutoff
  TYNDALL_DETAIL_FOR_CAMERA_GROUPS(TYNDALL_DETAIL_FILTERED_GROUP)
  return sum;
}
#endif

// The extinction at box point q ([0,1]^3): filtered by the footprint of
// the camera sample being taken (tyndallFootprint, the world width of its
// pixel), and with TYNDALL_DETAIL_STEP_MEANS its mean over a step; unfiltered
// elsewhere (tyndallFootprint 0: light rays, maps).
float tyndallDetailExtinction(vec3 q)
{
  vec3 p = detailBoxLow + q * detailBoxSize;
  float shape = texture(detailShapeTexture, (p + 0.5) / detailDims).r;
  if (!(shape > 0.0))
  {
    return 0.0; // no waves where the shape is empty (a GPU branches; llvmpipe masks)
  }
#if TYNDALL_DETAIL_FILTER
  float noise = tyndallDetailFilteredNoise(p, tyndallFootprint);
#else
  float noise = tyndallDetailNoise(p);
#endif
  return shape * detailScale * max(noise, 0.0);
}

// Re(e^{i alpha} sum_n e_n K_n(theta)) per component, K_n(theta) =
// int_0^1 u^n e^{i theta u} du (vtkCosineNoise::PolynomialWaveIntegral):
// Horner's scheme of the Taylor series for |theta| < 1, the recurrence
// K_n = (e^{i theta} - n K_{n-1}) / (i theta) otherwise.
#define TYNDALL_DETAIL_HORNER(m) { vec4 f = theta * (1.0 / float(m + 1)); float g = dot(e, vec4(1.0 / float(m + 1), 1.0 / float(m + 2), 1.0 / float(m + 3), 1.0 / float(m + 4))); vec4 r = g - f * sIm; sIm = f * sRe; sRe = r; }
#define TYNDALL_DETAIL_RECURRENCE(n) { vec4 xRe = cosT - float(n) * kRe; vec4 xIm = sinT - float(n) * kIm; kRe = xIm * invT; kIm = -xRe * invT; rRe += e[n] * kRe; rIm += e[n] * kIm; }
vec4 tyndallWaveMoments(vec4 e, vec4 alpha, vec4 theta)
{
  vec4 sRe = vec4(0.0), sIm = vec4(0.0);
  TYNDALL_DETAIL_HORNER(11) TYNDALL_DETAIL_HORNER(10) TYNDALL_DETAIL_HORNER(9)
  TYNDALL_DETAIL_HORNER(8) TYNDALL_DETAIL_HORNER(7) TYNDALL_DETAIL_HORNER(6)
  TYNDALL_DETAIL_HORNER(5) TYNDALL_DETAIL_HORNER(4) TYNDALL_DETAIL_HORNER(3)
  TYNDALL_DETAIL_HORNER(2) TYNDALL_DETAIL_HORNER(1) TYNDALL_DETAIL_HORNER(0)
  vec4 cosT = cos(theta), sinT = sin(theta);
  vec4 invT = 1.0 / theta;
  vec4 kRe = sinT * invT, kIm = (1.0 - cosT) * invT;
  vec4 rRe = e[0] * kRe, rIm = e[0] * kIm;
  TYNDALL_DETAIL_RECURRENCE(1) TYNDALL_DETAIL_RECURRENCE(2) TYNDALL_DETAIL_RECURRENCE(3)
  bvec4 small = lessThan(abs(theta), vec4(1.0));
  vec4 re = mix(rRe, sRe, small);
  vec4 im = mix(rIm, sIm, small);
  return cos(alpha) * re - sin(alpha) * im;
}

#define TYNDALL_DETAIL_SEGMENT_GROUP(g) sum += dot(detailAmplitude[g], tyndallWaveMoments(e, detailKx[g] * pa.x + detailKy[g] * pa.y + detailKz[g] * pa.z + detailPhase[g], (detailKx[g] * d.x + detailKy[g] * d.y + detailKz[g] * d.z) * len));

// The integral of c(s) noise(pa + s d) over s in [0, len], c a cubic
// (coefficients of 1, s, s^2, s^3).
float tyndallDetailSegment(vec3 pa, vec3 d, vec4 c, float len)
{
  vec4 e = c * vec4(1.0, len, len * len, len * len * len);
  float sum = detailOffset * dot(e, vec4(1.0, 0.5, 1.0 / 3.0, 0.25));
  TYNDALL_DETAIL_FOR_GROUPS(TYNDALL_DETAIL_SEGMENT_GROUP)
  return len * sum;
}

// p * (l.x + l.y s) for a cubic p.
vec4 tyndallTimesLinear(vec4 p, vec2 l)
{
  return p * l.x + vec4(0.0, p.xyz) * l.y;
}

// The trilinear shape along pa + s d within the cell `region` (per axis:
// -1 below the samples, dims - 1 above them: the coordinate is clamped), as
// a cubic in s.
vec4 tyndallDetailCell(ivec3 region, vec3 pa, vec3 d)
{
  ivec3 last = ivec3(detailDims) - 2;
  ivec3 cell = clamp(region, ivec3(0), last);
  vec3 u0 = clamp(pa - vec3(cell), 0.0, 1.0);
  u0 = mix(u0, vec3(0.0), lessThan(region, ivec3(0)));
  u0 = mix(u0, vec3(1.0), greaterThan(region, last));
  vec3 du = mix(d, vec3(0.0), bvec3(ivec3(lessThan(region, ivec3(0))) + ivec3(greaterThan(region, last))));
  float v000 = texelFetch(detailShapeTexture, cell, 0).r;
  float v100 = texelFetch(detailShapeTexture, cell + ivec3(1, 0, 0), 0).r;
  float v010 = texelFetch(detailShapeTexture, cell + ivec3(0, 1, 0), 0).r;
  float v110 = texelFetch(detailShapeTexture, cell + ivec3(1, 1, 0), 0).r;
  float v001 = texelFetch(detailShapeTexture, cell + ivec3(0, 0, 1), 0).r;
  float v101 = texelFetch(detailShapeTexture, cell + ivec3(1, 0, 1), 0).r;
  float v011 = texelFetch(detailShapeTexture, cell + ivec3(0, 1, 1), 0).r;
  float v111 = texelFetch(detailShapeTexture, cell + ivec3(1, 1, 1), 0).r;
  vec4 x = vec4(u0.x, du.x, 0.0, 0.0);
  vec4 y = vec4(u0.y, du.y, 0.0, 0.0);
  vec4 xy = tyndallTimesLinear(x, vec2(u0.y, du.y));
  vec4 xz = tyndallTimesLinear(x, vec2(u0.z, du.z));
  vec4 yz = tyndallTimesLinear(y, vec2(u0.z, du.z));
  vec4 xyz = tyndallTimesLinear(xy, vec2(u0.z, du.z));
  vec4 z = vec4(u0.z, du.z, 0.0, 0.0);
  return vec4(v000, 0.0, 0.0, 0.0) + x * (v100 - v000) + y * (v010 - v000) + z * (v001 - v000) +
    xy * (v110 - v100 - v010 + v000) + xz * (v101 - v100 - v001 + v000) +
    yz * (v011 - v010 - v001 + v000) +
    xyz * (v111 - v110 - v101 - v011 + v100 + v010 + v001 - v000);
}

// A walk along a ray through the shape's cells (a 3-D DDA) in field index
// coordinates: p(t) = o + t d, t a world distance; `region` is the cell
// holding p(t) (per axis -1 below the samples, dims - 1 above them).
struct TyndallDetailWalk
{
  vec3 o;
  vec3 d;
  ivec3 region;
  float t;
  bvec3 crossing; // the axes whose cell boundary ends the current cell
};

TyndallDetailWalk tyndallDetailWalkStart(vec3 x, vec3 w)
{
  TyndallDetailWalk k;
  k.o = detailBoxLow + (worldToVolume * vec4(x, 1.0)).xyz * detailBoxSize;
  k.d = (worldToVolume * vec4(w, 0.0)).xyz * detailBoxSize;
  vec3 f = floor(k.o);
  k.region = ivec3(f) - ivec3(lessThan(k.d, vec3(0.0))) * ivec3(equal(f, k.o));
  k.region = clamp(k.region, ivec3(-1), ivec3(detailDims) - 1);
  k.t = 0.0;
  k.crossing = bvec3(false);
  return k;
}

// Where the current cell ends along the walk, at most tEnd (and at least
// k.t); records the axes crossed there.
float tyndallDetailCellEnd(inout TyndallDetailWalk k, float tEnd)
{
  ivec3 top = ivec3(detailDims) - 1;
  ivec3 plane = k.region + ivec3(greaterThan(k.d, vec3(0.0)));
  bvec3 valid = bvec3(ivec3(notEqual(k.d, vec3(0.0))) * ivec3(greaterThanEqual(plane, ivec3(0))) *
    ivec3(lessThanEqual(plane, top)));
  vec3 tPlane = mix(vec3(1e30), (vec3(plane) - k.o) / k.d, valid);
  float tNext = max(min(min(min(tPlane.x, tPlane.y), tPlane.z), tEnd), k.t);
  k.crossing = bvec3(ivec3(valid) * ivec3(lessThanEqual(tPlane, vec3(tNext))));
  return tNext;
}

// Moves the walk into the next cell, which starts at tNext.
void tyndallDetailWalkAdvance(inout TyndallDetailWalk k, float tNext)
{
  k.region += ivec3(sign(k.d)) * ivec3(k.crossing);
  k.t = tNext;
}

// The current cell's integral of shape x noise (unscaled) over [k.t,
// tNext], clamped at 0; its start pa and cubic c for a solve within it.
float tyndallDetailCellIntegral(TyndallDetailWalk k, float tNext, out vec3 pa, out vec4 c)
{
  pa = k.o + k.t * k.d;
  c = tyndallDetailCell(k.region, pa, k.d);
  if (all(equal(c, vec4(0.0))))
  {
    return 0.0; // an empty cell: no waves to integrate
  }
  return max(tyndallDetailSegment(pa, k.d, c, tNext - k.t), 0.0);
}

// The optical depth from world point x along the unit world direction w
// over t in [0, tEnd] (x inside the box), in closed form: the ray is walked
// cell by cell, each cell's integral clamped at 0.
float tyndallDetailDepth(vec3 x, vec3 w, float tEnd)
{
  TyndallDetailWalk k = tyndallDetailWalkStart(x, w);
  float tau = 0.0;
  for (int i = 0; i < detailMaxCells; ++i)
  {
    float tNext = tyndallDetailCellEnd(k, tEnd);
    if (tNext > k.t)
    {
      vec3 pa;
      vec4 c;
      tau += tyndallDetailCellIntegral(k, tNext, pa, c);
    }
    if (tNext >= tEnd)
    {
      break;
    }
    tyndallDetailWalkAdvance(k, tNext);
  }
  return detailScale * tau;
}

#if TYNDALL_DETAIL_SAMPLES > 0 || TYNDALL_PATH_CLOSED_FORM
// The s in [0, len] at which the cell's integral from 0 reaches goal (0 <
// goal <= whole, the integral over the whole cell): safeguarded Newton from
// the guess of a homogeneous cell, the derivative being the unscaled
// extinction c(s) noise(pa + s d); bisection where Newton leaves the
// bracket. The GLSL twin of the CPU's cell solve (vtkTyndallDetailMedium's
// RayWaves::Solve, which takes Halley steps from the same guess within the
// same bracket and finds the same root), to single precision.
float tyndallDetailSolve(vec3 pa, vec3 d, vec4 c, float len, float goal, float whole)
{
  float lo = 0.0, hi = len;
  float s = len * clamp(goal / whole, 0.0, 1.0);
  for (int i = 0; i < TYNDALL_DETAIL_SOLVE_ITERATIONS; ++i)
  {
    float value = tyndallDetailSegment(pa, d, c, s) - goal;
    if (abs(value) <= 1e-6 * goal || hi - lo <= 1e-5 * len)
    {
      break;
    }
    if (value < 0.0)
    {
      lo = s;
    }
    else
    {
      hi = s;
    }
    float slope = dot(c, vec4(1.0, s, s * s, s * s * s)) * tyndallDetailNoise(pa + s * d);
    float next = slope > 0.0 ? s - value / slope : -1.0;
    s = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  return s;
}
#endif

#if TYNDALL_DETAIL_SAMPLES > 0
// Free-flight distances along the camera ray x + t w, t in [0, tEnd], drawn
// in closed form (the paper's section 6, decoupled): one walk over the cells
// finds, for each optical depth goals[j] (ascending, scaled), the cell where
// the ray's optical depth reaches it and solves for the distance within it.
// distances[j] = tEnd + 1 where the ray ends first. Returns the ray's
// optical depth over [0, tEnd] (the walk stops early once every goal is met
// and the ray is opaque: depth >= opaque).
float tyndallDetailSampleDistances(vec3 x, vec3 w, float tEnd, float goals[TYNDALL_DETAIL_SAMPLES],
  float opaque, out float distances[TYNDALL_DETAIL_SAMPLES])
{
  for (int j = 0; j < TYNDALL_DETAIL_SAMPLES; ++j)
  {
    distances[j] = tEnd + 1.0;
  }
  TyndallDetailWalk k = tyndallDetailWalkStart(x, w);
  float inverseScale = 1.0 / detailScale;
  float tau = 0.0; // unscaled
  int next = 0;
  for (int i = 0; i < detailMaxCells; ++i)
  {
    float tNext = tyndallDetailCellEnd(k, tEnd);
    if (tNext > k.t)
    {
      vec3 pa;
      vec4 c;
      float whole = tyndallDetailCellIntegral(k, tNext, pa, c);
      for (int j = 0; j < TYNDALL_DETAIL_SAMPLES; ++j)
      {
        if (next >= TYNDALL_DETAIL_SAMPLES || tau + whole < goals[next] * inverseScale)
        {
          break;
        }
        float s = tyndallDetailSolve(pa, k.d, c, tNext - k.t, goals[next] * inverseScale - tau, whole);
        distances[next] = k.t + s;
        ++next;
      }
      tau += whole;
    }
    if (tNext >= tEnd || (next >= TYNDALL_DETAIL_SAMPLES && detailScale * tau >= opaque))
    {
      break;
    }
    tyndallDetailWalkAdvance(k, tNext);
  }
  return detailScale * tau;
}
#endif
