// Tyndall: progressive volumetric path tracing (appended after
// vtkTransmittanceRayCastFS.glsl, whose camera samples, lights and light
// transmittance it calls; vtkTransmittancePathTracePass). Each pixel
// traces pathSamples paths from its camera ray (the pixel's centre, as the
// CPU tracer's): free flights by delta tracking against one majorant (or
// the majorant grid's blocks: TYNDALL_PATH_BLOCKS), or through procedural
// detail in closed form (TYNDALL_PATH_CLOSED_FORM), next-event estimation
// towards every light at every collision (the light transmittance from the
// frame's maps, lightTransmittance(), or tracked: pathTrackedShadows,
// tyndallPathTransmittance()), Henyey-Greenstein scattering, a bounce limit
// and Russian roulette; emission arrays' light along every segment (this
// volume's, TYNDALL_EMISSION_ARRAY; the guests', TYNDALL_GUEST_EMISSION_ARRAY);
// with TYNDALL_PATH_ENVIRONMENT the renderer's sky, sampled at every
// collision and met by the paths that leave (multiple importance sampling,
// the power heuristic); a coloured
// extinction by spectral tracking (TYNDALL_CHROMATIC); with guests (other
// volumes) the camera ray's flight through the camera media, scattered
// flights through every medium (TYNDALL_CAMERA_GUESTS: tyndallEveryGuest)
// to the maps' box, a collision drawn as one medium's with its share of
// their extinction (tyndallPathCollisionMedium(), the CPU tracer's
// collision of one medium: its colour, emission and lighting, a shaded
// volume's own collision on its surface, a medium's Shade's surface term
// at its own).
// It writes the paths' mean radiance (premultiplied) and 1 - the mean of their first flights'
// escapes (an unbiased estimate of the view transmittance; per channel into
// a second image with a coloured extinction, the escapes weighted by
// spectral tracking); the still frames' images are averaged by
// vtkTransmittanceAccumulationPass. CPU twin:
// vtkVolumetricPathTracer (DELTA_TRACKING, or CLOSED_FORM through detail:
// the same estimator, term by term; Documentation/rendering-model.md, "Path
// tracing").
//
// Bounded work: every loop trip counts against pathBudget (a collision's
// light estimate from the maps as pathCollisionCost trips); a path still
// running when the budget is spent is kept as far as it got (its later
// bounces lost; a first flight cut short counts as an escape) and the pixel
// traces no more paths this frame.
uniform int pathFirstSample;    // the mean's samples before this frame: with the pixel and the
uniform int pathSeed;           // mapper's seed, a path's index in the mean picks its numbers
uniform int pathSamples;        // paths per pixel in this frame
uniform int pathBounces;        // the most scattering events of a path
uniform float pathMajorant;     // an upper bound of the extinction (per world unit)
uniform float pathFlightScale;  // the flights' majorants' factor (2 with a coloured extinction)
uniform int pathTrackedShadows; // 1: light transmittance tracked; 0: lightTransmittance()
uniform int pathBudget;         // loop trips one fragment may run
uniform int pathCollisionCost;  // trips of a collision's light estimate from the maps

int tyndallPathIterations = 0;
uint tyndallPathState = 0u;

// O'Neill's PCG output permutation (RXS-M-XS) of a 32-bit state.
uint tyndallPcgOutput(uint state)
{
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// The PCG hash (the permutation of one LCG step; Jarzynski and Olano,
// 2020): the seeds' mixer.
uint tyndallPcg(uint v)
{
  return tyndallPcgOutput(v * 747796405u + 2891336453u);
}

// A uniform number in [0, 1) (24 bits): PCG32, its LCG state stepped (one
// cycle of 2^32 through every state: two paths' numbers never merge, as
// the iterates of a hash do) and permuted.
float tyndallRandom()
{
  tyndallPathState = tyndallPathState * 747796405u + 2891336453u;
  return float(tyndallPcgOutput(tyndallPathState) >> 8u) * (1.0 / 16777216.0);
}

// A loop trip: false once the fragment's budget is spent.
bool tyndallPathStep()
{
  ++tyndallPathIterations;
  return tyndallPathIterations <= pathBudget;
}

bool tyndallPathSpent()
{
  return tyndallPathIterations > pathBudget;
}

// The tentative collisions of delta and ratio tracking along o + t w, t
// in (T, T1): against pathMajorant, or with TYNDALL_PATH_BLOCKS against
// the majorant grid's blocks (vtkTyndallMajorantGrid: table units times
// pathBlockScale), walked by DDA, so that a block of majorant 0 (empty)
// costs one loop trip and a thin one few tentative collisions.
struct TyndallWalk
{
  vec3 Origin;    // the segment's start: T is measured from it (precision far from the camera)
  vec3 Direction;
  float T;     // the last tentative collision (0 at first)
  float T1;    // the segment's end
  float Scale; // the majorants' factor (pathFlightScale for a flight, 1 for a shadow ray)
#if TYNDALL_PATH_BLOCKS
  vec3 BlockOrigin; // the ray in block coordinates (tyndallBlockRay())
  vec3 BlockDirection;
  float Nudge; // a ten-thousandth of a block along the ray: past a face
#endif
};

#if TYNDALL_PATH_BLOCKS
uniform float pathBlockScale;
#endif

TyndallWalk tyndallStartWalk(vec3 o, vec3 w, float t0, float t1, float scale)
{
  TyndallWalk walk;
  walk.Origin = o + t0 * w;
  walk.Direction = w;
  walk.T = 0.0;
  walk.T1 = t1 - t0;
  walk.Scale = scale;
#if TYNDALL_PATH_BLOCKS
  tyndallBlockRay(walk.Origin, w, walk.BlockOrigin, walk.BlockDirection);
  vec3 d = abs(walk.BlockDirection);
  walk.Nudge = 1e-4 / max(max(d.x, d.y), max(d.z, 1e-30));
#endif
  return walk;
}

// Moves the walk to its next tentative collision: true, with the
// majorant m there; false when the segment ends first or the budget is
// spent.
bool tyndallNextCollision(inout TyndallWalk walk, out float m)
{
#if TYNDALL_PATH_BLOCKS
  float tau = -log(1.0 - tyndallRandom());
  for (int i = 0; i < pathBudget; ++i)
  {
    if (!tyndallPathStep() || !(walk.T < walk.T1))
    {
      return false;
    }
    // The least step: a ten-thousandth of a block, or past T's rounding.
    float least = max(walk.Nudge, abs(walk.T) * 4e-7);
    vec3 p = walk.BlockOrigin + (walk.T + least) * walk.BlockDirection;
    vec3 cell = clamp(floor(p), vec3(0.0), blockCount - 1.0);
    m = texelFetch(blockTexture, ivec3(cell), 0).r * pathBlockScale * walk.Scale;
    // The edge blocks reach outward without end (outside the grid the
    // medium reads the edge samples or nothing): a ray outside it is one
    // block, not a stall at a face behind it.
    vec3 low = mix(cell, vec3(-1e30), equal(cell, vec3(0.0)));
    vec3 high = mix(cell + 1.0, vec3(1e30), equal(cell, blockCount - 1.0));
    vec3 bd = walk.BlockDirection;
    vec3 tFace = (mix(low, high, step(vec3(0.0), bd)) - walk.BlockOrigin) / bd;
    tFace = mix(vec3(1e30), tFace, notEqual(bd, vec3(0.0)));
    float tExit = min(max(min(min(tFace.x, tFace.y), tFace.z), walk.T + least), walk.T1);
    float depth = m * (tExit - walk.T);
    if (depth > tau)
    {
      walk.T += tau / m;
      return true;
    }
    tau -= depth;
    walk.T = tExit;
  }
  return false;
#else
  if (!tyndallPathStep())
  {
    return false;
  }
  m = pathMajorant * walk.Scale;
  walk.T -= log(1.0 - tyndallRandom()) / m;
  return walk.T < walk.T1;
#endif
}

#if TYNDALL_PATH_CLOSED_FORM
// A free flight through procedural detail in closed form (the cosine-noise
// paper's distance sampling): from x along w over (0, tEnd), the distance t
// at which the optical depth reaches `goal`, walking the shape's cells
// (vtkTransmittanceDetailFS.glsl; a loop trip each) and solving within the
// cell that holds it; false when the segment ends first or the budget is
// spent. The CPU twin: vtkTyndallDetailMedium::SampleDistance().
bool tyndallDetailFlight(vec3 x, vec3 w, float tEnd, float goal, out float t)
{
  t = tEnd;
  if (!(detailScale > 0.0))
  {
    return false;
  }
  TyndallDetailWalk k = tyndallDetailWalkStart(x, w);
  float target = goal / detailScale; // in the walk's unscaled integrals
  float tau = 0.0;
  for (int i = 0; i < detailMaxCells; ++i)
  {
    if (!tyndallPathStep())
    {
      return false;
    }
    float tNext = tyndallDetailCellEnd(k, tEnd);
    if (tNext > k.t)
    {
      vec3 pa;
      vec4 c;
      float whole = tyndallDetailCellIntegral(k, tNext, pa, c);
      if (whole > 0.0 && tau + whole >= target)
      {
        // The solve's iterations, counted at their most.
        tyndallPathIterations += TYNDALL_DETAIL_SOLVE_ITERATIONS;
        t = k.t + tyndallDetailSolve(pa, k.d, c, tNext - k.t, target - tau, whole);
        return true;
      }
      tau += whole;
    }
    if (tNext >= tEnd)
    {
      return false;
    }
    tyndallDetailWalkAdvance(k, tNext);
  }
  return false;
}
#endif

// A free flight from o along w over (t0, t1), by delta tracking (or in
// closed form: TYNDALL_PATH_CLOSED_FORM): true at a real collision, at x,
// with the medium's camera sample there; false when the flight leaves the
// segment or the budget is spent. With a coloured extinction
// (TYNDALL_CHROMATIC) spectral tracking: the grey (densest) extinction's
// collisions against twice its majorant (pathFlightScale 2), each channel's
// `weight` multiplied by extinctionColor at the real collision and by
// (m - e sigma) / (m - sigma) at each null one (the CPU tracer's FlightIn()).
bool tyndallFreeFlight(vec3 o, vec3 w, float t0, float t1, out vec3 x, out TyndallCameraSample s,
  inout TyndallTransmittance weight)
{
#if TYNDALL_PATH_CLOSED_FORM
  vec3 start = o + t0 * w;
  float t;
  bool collided = tyndallDetailFlight(start, w, t1 - t0, -log(1.0 - tyndallRandom()), t);
  x = start + t * w;
  if (collided)
  {
    s = tyndallCameraSample(x, x, w, 0.0);
  }
  return collided;
#else
  TyndallWalk walk = tyndallStartWalk(o, w, t0, t1, pathFlightScale);
  float m;
  for (int i = 0; i < pathBudget; ++i)
  {
    if (!tyndallNextCollision(walk, m))
    {
      break;
    }
    x = walk.Origin + walk.T * w;
    s = tyndallCameraSample(x, x, w, 0.0);
    if (tyndallRandom() * m < s.Sigma)
    {
#if TYNDALL_CHROMATIC
      weight *= extinctionColor;
#endif
      return true;
    }
#if TYNDALL_CHROMATIC
    weight *= (m - extinctionColor * s.Sigma) / (m - s.Sigma);
#endif
  }
  x = walk.Origin + walk.T * w;
  return false;
#endif
}

// Ratio tracking from x along dir over (0, tEnd): an unbiased estimate of
// the transmittance (per channel with a coloured extinction, against the
// grey majorant itself: no flight's weights to bound), with Russian
// roulette (survival 1/2) once its largest channel is below 0.1 (the CPU
// tracer's RatioTrack()); through every medium the light crosses, or with
// `flight` the media the path's flights cross (with guests: the camera ray's
// own media, tyndallEveryGuest).
TyndallTransmittance tyndallRatioTrack(vec3 x, vec3 dir, float tEnd, bool flight)
{
  TyndallWalk walk = tyndallStartWalk(x, dir, 0.0, tEnd, 1.0);
  TyndallTransmittance T = TyndallTransmittance(1.0);
  float m;
  for (int i = 0; i < pathBudget; ++i)
  {
    if (!tyndallNextCollision(walk, m))
    {
      break;
    }
    vec3 y = walk.Origin + walk.T * dir;
#if TYNDALL_CAMERA_GUESTS
    float sigma = flight ? tyndallCameraSample(y, y, dir, 0.0).Sigma : tyndallSceneExtinction(y, dir, 0.0);
#else
    float sigma = tyndallSceneExtinction(y, dir, 0.0);
#endif
#if TYNDALL_CHROMATIC
    T *= max(vec3(0.0), 1.0 - extinctionColor * (sigma / m));
#else
    T *= max(0.0, 1.0 - sigma / m);
#endif
    float largest = tyndallLargest(T);
    if (largest < 0.1)
    {
      if (largest <= 0.0 || tyndallRandom() < 0.5)
      {
        return TyndallTransmittance(0.0);
      }
      T *= 2.0;
    }
  }
  return T;
}

// The transmittance from x along dir over (0, tEnd): ratio tracked, or
// exact in closed form (TYNDALL_PATH_CLOSED_FORM: its walk counted as the
// most cells it can cross; no guests then); `flight`: see tyndallRatioTrack().
TyndallTransmittance tyndallPathTransmittance(vec3 x, vec3 dir, float tEnd, bool flight)
{
#if TYNDALL_PATH_CLOSED_FORM
  tyndallPathIterations += detailMaxCells;
  return exp(-tyndallDetailDepth(x, dir, tEnd));
#else
  return tyndallRatioTrack(x, dir, tEnd, flight);
#endif
}

// How a collision's medium is lit (vtkTyndallMediumParameters, the CPU
// tracer's `lit`): its phase function's anisotropy, its ambient radiance,
// its factor of the renderer's lights and its scattering model. With
// guests each medium's own (pathLighting[]: this volume's, then the
// guests'; the lights' colours pathLightColor[] times its LightScale), else
// this volume's uniforms (lightIrradiance[] carries its LightScale).
struct TyndallLighting
{
  float G;
  vec3 Ambient;
  float LightScale; // the lights' colours' factor (with guests; 1 alone)
  bool Scatters;    // single scattering, else emission-absorption (the path ends)
};

#if TYNDALL_CAMERA_GUESTS
// Per medium (this volume's first, then guest g's at g + 1): anisotropy,
// LightScale, AmbientIntensity, 1 for single scattering (else 0).
uniform vec4 pathLighting[TYNDALL_GUESTS + 1];
uniform vec3 pathLightColor[TYNDALL_MAX_LIGHTS]; // intensity x colour (unscaled)

// Medium m's lighting (-1: this volume's, else guest m's).
TyndallLighting tyndallPathLighting(int m)
{
  vec4 p = pathLighting[m + 1];
  return TyndallLighting(p.x, vec3(p.z), p.y, p.w > 0.5);
}

// Light l's irradiance as the medium lit as `lit` sees it.
vec3 tyndallPathLightIrradiance(int l, TyndallLighting lit)
{
  return lit.LightScale * pathLightColor[l];
}
#else
TyndallLighting tyndallPathLighting(int m)
{
  return TyndallLighting(anisotropy, ambient, 1.0, scatteringModel != 0);
}

vec3 tyndallPathLightIrradiance(int l, TyndallLighting lit)
{
  return lightIrradiance[l];
}
#endif

// The light scattered at x against the path's direction w, per unit of
// scattering, in the medium lit as `lit`: ambient + sum_l E_l p(mu_l) T_l
// (next-event estimation), T_l from the frame's method (the maps, a
// brute-force march or none: lightTransmittance()) or tracked to the light
// or the box's side (tyndallPathTransmittance(); a light whose method is
// None is unshadowed either way).
vec3 tyndallPathInScattering(vec3 x, vec3 w, TyndallLighting lit)
{
  bool tracked = pathTrackedShadows != 0;
  if (!tracked)
  {
    // The light loop and its brute-force marches, counted at once.
    tyndallPathIterations += pathCollisionCost;
  }
  vec3 sum = lit.Ambient;
  for (int l = 0; l < numberOfLights; ++l)
  {
    if (tracked && !tyndallPathStep())
    {
      break;
    }
    vec3 toLight;
    float distance;
    vec3 E = tyndallPathLightIrradiance(l, lit);
    if (!tyndallLightAt(l, x, E, toLight, distance) || occluded(l, x))
    {
      continue;
    }
    float phase = tyndallPhaseHG(lit.G, dot(toLight, w));
    if (!tracked)
    {
      sum += E * (phase * lightTransmittance(l, x, toLight, distance));
      continue;
    }
    TyndallTransmittance T = TyndallTransmittance(1.0);
    if (lightMethod[l] != TYNDALL_NONE)
    {
      T = tyndallPathTransmittance(
        x, toLight, min(tyndallIntersectMapBox(x, toLight).y, distance), false);
    }
    sum += E * phase * T;
  }
  return sum;
}

#if TYNDALL_EMISSION_ARRAY || TYNDALL_GUEST_EMISSION_ARRAY
uniform int pathEmissionSamples; // stratified points per segment (vtkTyndallMedium::PathEmissionSamples)

#if TYNDALL_GUEST_EMISSION_ARRAY
// The guests' emission arrays (a guest without one: its own volume, never
// read), each value's table coordinate, and each guest's EmissionScale (0
// without an array: its emission, if any, is its table's, at collisions).
uniform sampler3D guestEmission[TYNDALL_GUESTS];
uniform vec2 guestEmissionToTable[TYNDALL_GUESTS];
uniform float guestArrayEmissionScale[TYNDALL_GUESTS];

// Guest g's array emission at x (per unit length, scaled): its array's value
// through the emission row of its table; 0 outside its box or where the
// flight does not sample it (as tyndallGuestCameraSample()).
vec3 tyndallGuestArrayEmission(sampler3D emission, TYNDALL_GUEST_BRICKS_PARAMETER sampler2D table,
  int g, vec3 x)
{
  vec3 q = (guestWorldToBox[g] * vec4(x, 1.0)).xyz;
  if ((guestCamera[g] == 0.0 && !tyndallEveryGuest) || any(lessThan(q, vec3(0.0))) ||
    any(greaterThan(q, vec3(1.0))))
  {
    return vec3(0.0);
  }
  float value = texture(emission, tyndallGuestTexel(TYNDALL_GUEST_BRICKS_ARGUMENT g, q)).r;
  vec2 toTable = guestEmissionToTable[g];
  return guestArrayEmissionScale[g] *
    texture(table, vec2(value * toTable.x + toTable.y, TYNDALL_TABLE_EMISSION_ROW)).rgb;
}

// Samplers are indexed by constants only (GLSL 1.50): one statement per guest.
#define TYNDALL_GUEST_ARRAY_EMISSION(g) if (m == g) { e = tyndallGuestArrayEmission(guestEmission[g], TYNDALL_GUEST_BRICKS(g) guestTransfer[g], g, x); }
#endif

// Medium m's array emission at x (per unit length, scaled): this volume's
// (m -1) or guest m's.
vec3 tyndallPathEmissionAt(int m, vec3 x)
{
  vec3 e = vec3(0.0);
#if TYNDALL_EMISSION_ARRAY
  if (m < 0)
  {
    e = emissionScale * tyndallArrayEmission(x);
  }
#endif
#if TYNDALL_GUEST_EMISSION_ARRAY
  TYNDALL_FOR_GUESTS(TYNDALL_GUEST_ARRAY_EMISSION)
#endif
  return e;
}

// Medium m's array emission along the path's segment o + t w, t in (t0,
// t1), per unit of throughput, where the segment crosses its box (`toBox`:
// world to the box as [0,1]^3; the array's texture clamps to its edge): the
// length of that part over n times the sum over n stratified points of the
// emission there and the transmittance to it from the segment's start
// (through every medium the flight crosses: tyndallPathTransmittance()).
// The points ascend: the transmittance to each is the one before's times
// that of the part between them (independent estimates, so their product's
// mean is the transmittance), and the segment is tracked once per medium
// (from its start to the last point), not once per point (the CPU tracer's
// AddArrayEmission()).
vec3 tyndallPathMediumEmission(int m, mat4 toBox, vec3 o, vec3 w, float t0, float t1)
{
  vec2 box = tyndallIntersectBox(toBox, o, w);
  float a = max(t0, box.x);
  float b = min(t1, box.y);
  if (!(a < b))
  {
    return vec3(0.0);
  }
  float length = (b - a) / float(pathEmissionSamples);
  vec3 sum = vec3(0.0);
  TyndallTransmittance T = TyndallTransmittance(1.0); // from the segment's start to `from`
  float from = t0;
  for (int i = 0; i < pathEmissionSamples && tyndallLargest(T) > 0.0; ++i)
  {
    if (!tyndallPathStep())
    {
      break;
    }
    float t = a + (float(i) + tyndallRandom()) * length;
    vec3 e = tyndallPathEmissionAt(m, o + t * w);
    if (any(greaterThan(e, vec3(0.0))))
    {
      T *= tyndallPathTransmittance(o + from * w, w, t - from, true);
      from = t;
      sum += e * T;
    }
  }
  return length * sum;
}

// (A guest the flight does not sample, the camera ray's but for camera
// guests, is skipped: its points would all be 0.)
#define TYNDALL_GUEST_SEGMENT_EMISSION(g) if (guestArrayEmissionScale[g] > 0.0 && (tyndallEveryGuest || guestCamera[g] > 0.0)) { sum += tyndallPathMediumEmission(g, guestWorldToBox[g], o, w, t0, t1); }

// The emission arrays' light along the path's segment o + t w, t in (t0,
// t1), per unit of throughput: each medium's with one (this volume's, the
// guests' the flight samples) by its own stratified points
// (tyndallPathMediumEmission(); the CPU tracer's AddArrayEmission()):
// unbiased, and independent of where the flight collides.
vec3 tyndallPathArrayEmission(vec3 o, vec3 w, float t0, float t1)
{
  vec3 sum = vec3(0.0);
#if TYNDALL_EMISSION_ARRAY
  sum += tyndallPathMediumEmission(-1, worldToVolume, o, w, t0, t1);
#endif
#if TYNDALL_GUEST_EMISSION_ARRAY
  TYNDALL_FOR_GUESTS(TYNDALL_GUEST_SEGMENT_EMISSION)
#endif
  return sum;
}
#else
vec3 tyndallPathArrayEmission(vec3 o, vec3 w, float t0, float t1)
{
  return vec3(0.0); // no emission array
}
#endif

#if TYNDALL_PATH_ENVIRONMENT
uniform int pathSkySearchCost; // loop trips of a draw from the sky (its two searches)

// The power heuristic's weight of a strategy of density a against one of density b.
float tyndallPowerWeight(float a, float b)
{
  return a * a / (a * a + b * b);
}

// Next-event estimation of the sky at x, for the path's direction w, per
// unit of scattering: L(l) p(mu) T / pdf(l), l drawn from the sky
// (vtkTransmittanceEnvironmentFS.glsl), T to the box's side
// (tyndallPathTransmittance()),
// times the power heuristic's weight against the phase function's sampling
// (1 at the path's last collision, which draws no direction), for the
// phase function of anisotropy g. The CPU tracer's AddSkyEvent().
vec3 tyndallPathSkyEvent(vec3 x, vec3 w, float g, bool last)
{
  tyndallPathIterations += pathSkySearchCost;
  vec4 u = vec4(tyndallRandom(), tyndallRandom(), tyndallRandom(), tyndallRandom());
  vec3 l;
  vec3 L;
  float pdf = tyndallSampleSky(u, l, L);
  if (!(pdf > 0.0))
  {
    return vec3(0.0);
  }
  float phase = tyndallPhaseHG(g, dot(l, w));
  TyndallTransmittance T = tyndallPathTransmittance(x, l, tyndallIntersectMapBox(x, l).y, false);
  return L * (T * phase / pdf * (last ? 1.0 : tyndallPowerWeight(pdf, phase)));
}

// A scattered path leaving the media along w, drawn with the phase
// function's density phasePdf: L(w) times the power heuristic's weight
// against the sky's sampling (the CPU tracer's AddSkyEscape()).
vec3 tyndallPathSkyEscape(vec3 w, float phasePdf)
{
  return tyndallSkyRadiance(w) * tyndallPowerWeight(phasePdf, tyndallSkyPdf(w));
}
#else
// No sky: nothing to estimate at a collision, nothing met on leaving.
vec3 tyndallPathSkyEvent(vec3 x, vec3 w, float g, bool last)
{
  return vec3(0.0);
}

vec3 tyndallPathSkyEscape(vec3 w, float phasePdf)
{
  return vec3(0.0);
}
#endif

// The media a flight crosses: the camera ray's (the camera media) or a
// scattered one's (every medium: tyndallEveryGuest), with guests.
void tyndallPathFlightMedia(bool scattered)
{
#if TYNDALL_CAMERA_GUESTS
  tyndallEveryGuest = scattered;
#endif
}

// Where a scattered ray from x along w leaves the media: every medium's
// box (the maps') with guests, else the volume's.
float tyndallPathBoxExit(vec3 x, vec3 w)
{
#if TYNDALL_GUESTS > 0
  return tyndallIntersectMapBox(x, w).y;
#else
  return tyndallIntersectCameraBox(x, w).y;
#endif
}

// Russian roulette on the throughput: false when the path ends (nothing
// left, or below 1/4 and not drawn to survive; a survivor divided by the
// odds: the CPU tracer's Survive()).
bool tyndallPathRoulette(inout vec3 beta)
{
  float q = max(beta.r, max(beta.g, beta.b));
  if (!(q > 0.0))
  {
    return false;
  }
  if (q < 0.25)
  {
    if (tyndallRandom() >= q)
    {
      return false;
    }
    beta /= q;
  }
  return true;
}

// A direction drawn from the Henyey-Greenstein phase function of
// asymmetry g about w (the CPU tracer's SampleHenyeyGreenstein()).
vec3 tyndallSampleHG(vec3 w, float g)
{
  g = clamp(g, -0.99, 0.99);
  float u1 = tyndallRandom();
  float u2 = tyndallRandom();
  float mu = 1.0 - 2.0 * u1;
  if (abs(g) >= 1e-5)
  {
    float s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
    mu = (1.0 + g * g - s * s) / (2.0 * g);
  }
  mu = clamp(mu, -1.0, 1.0);
  float sinTheta = sqrt(max(0.0, 1.0 - mu * mu));
  float phi = 2.0 * TYNDALL_PI * u2;
  vec3 a = abs(w.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 u = normalize(cross(w, a));
  vec3 v = cross(w, u);
  return normalize(sinTheta * cos(phi) * u + sinTheta * sin(phi) * v + mu * w);
}

// This volume's colour (rgb) and extinction (a) in the collision's camera
// sample s: with guests (TYNDALL_CAMERA_GUESTS) its part of their mixture,
// else the sample's.
vec4 tyndallPathOwn(TyndallCameraSample s)
{
#if TYNDALL_CAMERA_GUESTS
  return s.Own;
#else
  return vec4(s.Color, s.Sigma);
#endif
}

// Draws the medium the collision s at x is of, with its share of the
// extinction (the CPU tracer's collisions are each one medium's): with
// guests this volume's with the probability s.Own.a / s.Sigma, else a
// guest's with its own share (each guest sampled again at x; the last of
// positive extinction takes what rounding leaves), and s then holds the
// medium's colour and emission (per unit of its extinction); alone this
// volume's, no number drawn. Returns its lighting; `own`: whether it is
// this volume's.
TyndallLighting tyndallPathCollisionMedium(vec3 x, inout TyndallCameraSample s, out bool own)
{
#if TYNDALL_CAMERA_GUESTS
  // (No number drawn where no guest is: a shaded volume's stream as before.)
  bool drawn = s.Guests.a <= 0.0;
  float u = drawn ? 0.0 : tyndallRandom() * s.Sigma;
  float below = s.Own.a;
  drawn = drawn || u < below;
  int medium = -1;
  vec3 color = s.Own.rgb;
  vec3 emission = s.OwnEmission;
  TYNDALL_FOR_GUESTS(TYNDALL_GUEST_DRAW)
  own = medium < 0;
  s.Color = color;
  s.Emission = emission;
  return tyndallPathLighting(medium);
#else
  own = true;
  return tyndallPathLighting(-1);
#endif
}

// How a collision scatters: with TYNDALL_SHADING (a plain property's
// Shade, vtkTyndallSurfaceLobe: its CPU twin) a lobe about the scalar's
// unit gradient n, towards where the path came from V (h = normalize(l +
// V)), with VTK 9.2's volumetric scattering blending's weight k:
//   f(l) = ((1 - k) (Kd c |n.l| + Ks |n.h|^p) + k Kd c) / (2 pi),
// drawn from the mixture of a two-sided cosine lobe, Blinn-Phong's
// half-vector lobe and the sphere (shares Diffuse, Specular and Volume);
// else the phase function (and with TYNDALL_SHADING_ADDITIVE, a
// vtkParticipatingMediumProperty's Shade, the phase function with the same
// lobe's light added: tyndallPathAddedSurface()). Independent components
// (TYNDALL_COMPONENT_SHADING): one drawn with its share of their parts in
// the mixture (which add up to P, not always 1), whose gradient, colour,
// coefficients and k make the lobe, f and Ka c times P (Scale). The renderer's
// lights and sky are pathLightUnit (vtkTyndallSurfaceLobe::LightUnit, 2 pi)
// brighter against the lobe, so that a light's first bounce is VTK's
// shading term, and a shaded collision exchanges its light from
// shadowOffset along its direction, as the map-based frame's shading takes
// T_l (a surface does not shadow itself).
struct TyndallScatterer
{
#if TYNDALL_SHADING
  vec3 N;
  vec3 V;
  vec3 Color;     // c
  vec4 K;         // Ka, Kd, Ks, p (shadingCoefficients[] of the component drawn)
  float Blend;    // k
  float Scale;    // f's factor (P)
  float Diffuse;  // the probability of the cosine lobe
  float Specular; // ... of the half-vector lobe
  float Volume;   // ... and of the sphere
#else
  float Unused;
#endif
};

#if TYNDALL_SHADING
uniform float pathLightUnit; // vtkTyndallSurfaceLobe::LightUnit

// The lobe of a collision at x (its camera sample s) for the path's
// direction w (the CPU tracer's SurfaceLobe(), vtkTyndallSurfaceLobe::Set()).
TyndallScatterer tyndallPathScatterer(vec3 x, vec3 w, TyndallCameraSample s)
{
  TyndallScatterer lobe;
  int part = 0;
  vec4 own = tyndallPathOwn(s);
  float sigma = own.a;
  lobe.Color = own.rgb;
  lobe.Scale = 1.0;
#if TYNDALL_COMPONENT_SHADING
  // The part drawn (the last of positive weight takes what rounding leaves).
  vec4 parts = max(s.Parts, vec4(0.0));
  lobe.Scale = parts.x + parts.y + parts.z + parts.w;
  float u = tyndallRandom() * lobe.Scale;
  float below = 0.0;
  bool drawn = false;
  for (int c = 0; c < TYNDALL_COMPONENTS; ++c)
  {
    if (parts[c] > 0.0 && !drawn)
    {
      below += parts[c];
      part = c;
      drawn = u < below;
    }
  }
  vec4 magnitudes;
  mat4x3 normals = tyndallComponentNormals(x, magnitudes);
  float magnitude = magnitudes[part];
  lobe.N = normals[part];
  lobe.Color = s.Colors[part];
  sigma = s.Sigmas[part];
#else
  vec3 g = tyndallScalarGradient(x);
  float magnitude = length(g);
  lobe.N = magnitude > 0.0 ? g / magnitude : vec3(0.0);
#endif
  lobe.V = -w;
  lobe.K = shadingCoefficients[part];
  lobe.Blend = clamp(tyndallBlendWeight(magnitude, part, sigma), 0.0, 1.0);
  float mean = max(lobe.K.y, 0.0) * (lobe.Color.r + lobe.Color.g + lobe.Color.b) / 3.0;
  float surface = magnitude > 0.0 ? 1.0 - lobe.Blend : 0.0;
  float d = surface * mean;
  float sp = surface * max(lobe.K.z, 0.0) * min(1.0, 4.0 / (max(lobe.K.w, 0.0) + 1.0));
  float v = lobe.Blend * 2.0 * mean;
  float total = d + sp + v;
  lobe.Diffuse = total > 0.0 ? d / total : 0.0;
  lobe.Specular = total > 0.0 ? sp / total : 0.0;
  lobe.Volume = total > 0.0 ? v / total : 0.0;
  return lobe;
}

bool tyndallLobeScatters(TyndallScatterer lobe)
{
  return lobe.Diffuse + lobe.Specular + lobe.Volume > 0.0;
}

// f(l) per channel (vtkTyndallSurfaceLobe::Evaluate()).
vec3 tyndallLobeValue(TyndallScatterer lobe, vec3 l)
{
  if (!tyndallLobeScatters(lobe))
  {
    return vec3(0.0);
  }
  vec4 k = lobe.K;
  vec3 lv = l + lobe.V;
  float specular = 0.0;
  if (length(lv) > 1e-6 && dot(lobe.N, lobe.N) > 0.0)
  {
    // (pow(0, 0) is undefined in GLSL: 1 as the CPU's std::pow, tyndallShadingTerm()'s guard.)
    specular = max(k.z, 0.0) * pow(max(abs(dot(lobe.N, normalize(lv))), 1e-30), max(k.w, 0.0));
  }
  vec3 diffuse = max(k.y, 0.0) * lobe.Color;
  return lobe.Scale *
    ((1.0 - lobe.Blend) * (diffuse * abs(dot(lobe.N, l)) + specular) + lobe.Blend * diffuse) /
    (2.0 * TYNDALL_PI);
}

// The density the lobe draws l with (vtkTyndallSurfaceLobe::Pdf()).
float tyndallLobePdf(TyndallScatterer lobe, vec3 l)
{
  float pdf =
    lobe.Diffuse * abs(dot(lobe.N, l)) / (2.0 * TYNDALL_PI) + lobe.Volume / (4.0 * TYNDALL_PI);
  vec3 lv = l + lobe.V;
  if (lobe.Specular > 0.0 && length(lv) > 1e-6)
  {
    vec3 h = normalize(lv);
    float vh = abs(dot(lobe.V, h));
    float p = max(lobe.K.w, 0.0);
    if (vh > 0.0)
    {
      pdf += lobe.Specular * (p + 1.0) / (2.0 * TYNDALL_PI) *
        pow(max(abs(dot(lobe.N, h)), 1e-30), p) / (4.0 * vh);
    }
  }
  return pdf;
}

// The unit direction at the cosine mu and the angle phi about the unit axis a.
vec3 tyndallAboutAxis(vec3 a, float mu, float phi)
{
  vec3 b = abs(a.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 u = normalize(cross(a, b));
  vec3 v = cross(a, u);
  float sinTheta = sqrt(max(0.0, 1.0 - mu * mu));
  return normalize(sinTheta * cos(phi) * u + sinTheta * sin(phi) * v + mu * a);
}

// A direction drawn from the lobe, its weight f / pdf and density pdf (0
// when the lobe does not scatter; vtkTyndallSurfaceLobe::Sample()).
vec3 tyndallSampleLobe(TyndallScatterer lobe, out vec3 weight, out float pdf)
{
  float u0 = tyndallRandom();
  float u1 = tyndallRandom();
  float phi = 2.0 * TYNDALL_PI * tyndallRandom();
  weight = vec3(0.0);
  pdf = 0.0;
  if (!tyndallLobeScatters(lobe))
  {
    return lobe.V;
  }
  vec3 l;
  if (u0 < lobe.Diffuse)
  {
    vec3 axis = u0 < 0.5 * lobe.Diffuse ? lobe.N : -lobe.N;
    l = tyndallAboutAxis(axis, sqrt(u1), phi);
  }
  else if (lobe.Volume > 0.0 && u0 >= lobe.Diffuse + lobe.Specular)
  {
    l = tyndallAboutAxis(vec3(0.0, 0.0, 1.0), 1.0 - 2.0 * u1, phi); // the blending's part
  }
  else
  {
    vec3 axis = dot(lobe.N, lobe.V) < 0.0 ? -lobe.N : lobe.N;
    vec3 h = tyndallAboutAxis(axis, pow(u1, 1.0 / (max(lobe.K.w, 0.0) + 1.0)), phi);
    l = normalize(2.0 * dot(lobe.V, h) * h - lobe.V);
  }
  pdf = tyndallLobePdf(lobe, l);
  if (pdf > 0.0)
  {
    weight = tyndallLobeValue(lobe, l) / pdf;
  }
  return l;
}

// The transmittance of a shaded collision at x towards l up to tEnd: from
// shadowOffset along l, by the frame's method for light `light` (-1: the
// sky, tracked) or tracked (the CPU tracer's SurfaceTransmittance()).
TyndallTransmittance tyndallLobeTransmittance(int light, vec3 x, vec3 l, float tEnd)
{
  vec3 y = x + shadowOffset * l;
  float length = max(min(tyndallIntersectMapBox(y, l).y, tEnd - shadowOffset), 0.0);
  if (light >= 0 && lightMethod[light] == TYNDALL_NONE)
  {
    return TyndallTransmittance(1.0);
  }
  if (light >= 0 && pathTrackedShadows == 0)
  {
    return lightTransmittance(light, y, l, tEnd - shadowOffset);
  }
  return tyndallPathTransmittance(y, l, length, false);
}

// Next-event estimation of the sky at a shaded collision x: LightUnit L(l)
// f(l) T / pdf(l), l drawn from the sky, T from shadowOffset along l,
// weighed by the power heuristic against the lobe's draws (1 at the path's
// last collision; the CPU tracer's SurfaceSource()); 0 without a sky.
vec3 tyndallLobeSkyEvent(vec3 x, TyndallScatterer lobe, bool last)
{
#if TYNDALL_PATH_ENVIRONMENT
  tyndallPathIterations += pathSkySearchCost;
  vec4 u = vec4(tyndallRandom(), tyndallRandom(), tyndallRandom(), tyndallRandom());
  vec3 l;
  vec3 L;
  float pdf = tyndallSampleSky(u, l, L);
  if (pdf > 0.0)
  {
    float weight = last ? 1.0 : tyndallPowerWeight(pdf, tyndallLobePdf(lobe, l));
    return pathLightUnit * L * tyndallLobeValue(lobe, l) *
      tyndallLobeTransmittance(-1, x, l, 1e30) * (weight / pdf);
  }
#endif
  return vec3(0.0);
}

// The lights' and the sky's light a shaded collision at x reflects by its
// lobe, per unit of throughput: each light's LightUnit E f(l) T_l and, with
// the sky, its next-event estimate (weighed against the lobe's sampling
// unless `last`; the CPU tracer's SurfaceSource() without Ka c).
vec3 tyndallLobeLight(vec3 x, TyndallScatterer lobe, bool last)
{
  vec3 sum = vec3(0.0);
  if (!tyndallLobeScatters(lobe))
  {
    return sum;
  }
  bool tracked = pathTrackedShadows != 0;
  if (!tracked)
  {
    // The light loop and its brute-force marches, counted at once.
    tyndallPathIterations += pathCollisionCost;
  }
  for (int l = 0; l < numberOfLights; ++l)
  {
    if (tracked && !tyndallPathStep())
    {
      break;
    }
    vec3 toLight;
    float distance;
    vec3 E = lightColor[l];
    if (!tyndallLightAt(l, x, E, toLight, distance) || occluded(l, x))
    {
      continue;
    }
    sum += pathLightUnit * E * tyndallLobeValue(lobe, toLight) *
      tyndallLobeTransmittance(l, x, toLight, distance);
  }
  return sum + tyndallLobeSkyEvent(x, lobe, last);
}
#else
TyndallScatterer tyndallPathScatterer(vec3 x, vec3 w, TyndallCameraSample s)
{
  return TyndallScatterer(0.0);
}
#endif

// A vtkParticipatingMediumProperty's Shade (TYNDALL_SHADING_ADDITIVE): the
// surface term its collisions add to their scattering, the lobe's light at
// x (the lights not scaled: LightUnit f is VTK's term per unit light), the
// sky's by next-event estimation alone (the lobe is never sampled: the
// medium scatters on by its phase function; the CPU tracer's
// AddSurfaceTerm()), at this volume's own collisions (`own`); 0 otherwise.
#if TYNDALL_SHADING_ADDITIVE
vec3 tyndallPathAddedSurface(vec3 x, bool own, TyndallScatterer lobe)
{
  return own ? tyndallLobeLight(x, lobe, true) : vec3(0.0);
}
#else
vec3 tyndallPathAddedSurface(vec3 x, bool own, TyndallScatterer lobe)
{
  return vec3(0.0);
}
#endif

// A medium's collision's light at x per unit of throughput, lit as `lit`:
// its colour times the in-scattered light (next-event estimation) and,
// with the sky, its estimate against the phase function's sampling, plus
// its emission and, at this volume's own (`own`), a medium's surface term
// (`surface`: its lobe).
vec3 tyndallMediumCollisionLight(vec3 x, vec3 w, TyndallCameraSample s, TyndallLighting lit,
  bool own, TyndallScatterer surface, bool last)
{
  vec3 light = tyndallPathInScattering(x, w, lit) + tyndallPathSkyEvent(x, w, lit.G, last);
  return s.Color * light + tyndallSampleEmission(s) + tyndallPathAddedSurface(x, own, surface);
}

// The throughput times a medium's collision's colour, then (unless the
// path ends there: Russian roulette) the scattered direction w drawn from
// the phase function of anisotropy g (its density phasePdf), from x (o).
bool tyndallMediumScatter(TyndallCameraSample s, float g, vec3 x, inout vec3 beta, inout vec3 w,
  out vec3 o, out float phasePdf)
{
  beta *= s.Color;
  o = x;
  phasePdf = 0.0;
  if (!tyndallPathRoulette(beta))
  {
    return false;
  }
  vec3 previous = w;
  w = tyndallSampleHG(w, g);
  phasePdf = tyndallPhaseHG(g, dot(w, previous));
  return true;
}

#if TYNDALL_SHADING && !TYNDALL_SHADING_ADDITIVE
// Whether the collision is on a shaded surface: this volume's own
// (`own`, tyndallPathCollisionMedium()), whose shaded surfaces scatter (a
// plain property's Shade).
bool tyndallPathOnSurface(bool own)
{
  return own;
}

// A shaded collision's light at x per unit of throughput (the CPU tracer's
// ScatterAtSurface()): VTK's ambient Ka c, and the lobe's light of the
// lights and the sky, the sky's against the lobe's sampling.
vec3 tyndallSurfaceCollisionLight(vec3 x, TyndallScatterer lobe, bool last)
{
  return lobe.Scale * lobe.K.x * lobe.Color + tyndallLobeLight(x, lobe, last);
}

// Draws the scattered direction w from the lobe (its density phasePdf),
// the throughput times its weight; false when the path ends there
// (Russian roulette, or a lobe that does not scatter). The scattered
// path leaves from shadowOffset along w (o).
bool tyndallSurfaceScatter(
  TyndallScatterer lobe, vec3 x, inout vec3 beta, inout vec3 w, out vec3 o, out float phasePdf)
{
  vec3 weight;
  w = tyndallSampleLobe(lobe, weight, phasePdf);
  beta *= weight;
  o = x + shadowOffset * w;
  return phasePdf > 0.0 && tyndallPathRoulette(beta);
}

// The sky's unit for a path that leaves after a collision: the lobe's
// (pathLightUnit: the lights and the sky are brighter against it), a
// medium's 1.
float tyndallPathSkyUnit(bool surface)
{
  return surface ? pathLightUnit : 1.0;
}
#else
// Without a plain property's Shade every collision is a medium's.
bool tyndallPathOnSurface(bool own)
{
  return false;
}

vec3 tyndallSurfaceCollisionLight(vec3 x, TyndallScatterer lobe, bool last)
{
  return vec3(0.0);
}

bool tyndallSurfaceScatter(
  TyndallScatterer lobe, vec3 x, inout vec3 beta, inout vec3 w, out vec3 o, out float phasePdf)
{
  o = x;
  phasePdf = 0.0;
  return false;
}

float tyndallPathSkyUnit(bool surface)
{
  return 1.0;
}
#endif

// A collision's light at x per unit of throughput, on a shaded surface
// (`surface`: its lobe) or in a medium lit as `lit` (`own`: this volume's).
vec3 tyndallPathCollisionLight(vec3 x, vec3 w, TyndallCameraSample s, TyndallLighting lit,
  bool own, TyndallScatterer lobe, bool surface, bool last)
{
  return surface ? tyndallSurfaceCollisionLight(x, lobe, last)
                 : tyndallMediumCollisionLight(x, w, s, lit, own, lobe, last);
}

// Scatters the path at a collision (see tyndallSurfaceScatter() and
// tyndallMediumScatter()); false when it ends there.
bool tyndallPathScatter(TyndallScatterer lobe, TyndallCameraSample s, TyndallLighting lit,
  bool surface, vec3 x, inout vec3 beta, inout vec3 w, out vec3 o, out float phasePdf)
{
  return surface ? tyndallSurfaceScatter(lobe, x, beta, w, o, phasePdf)
                 : tyndallMediumScatter(s, lit.G, x, beta, w, o, phasePdf);
}

// One path from the camera ray p0 + t w, t in [tNear, tFar]: adds its
// radiance to `radiance` and its first flight's escape (1 or 0) to
// `escaped`; false when the budget ran out on the way (the path is kept as
// far as it got; a first flight cut short counts as an escape).
bool tyndallTracePath(vec3 p0, vec3 w, float tNear, float tFar, inout vec3 radiance,
  inout TyndallTransmittance escaped)
{
  vec3 beta = vec3(1.0);
  vec3 o = p0;
  float t0 = tNear;
  float t1 = tFar;
  float phasePdf = 0.0; // the density of the last scattered direction
  bool surface = false; // whether the last collision was on a shaded surface
  for (int bounce = 0; bounce < pathBounces; ++bounce)
  {
    vec3 x;
    TyndallCameraSample s;
    tyndallPathFlightMedia(bounce > 0);
    radiance += beta * tyndallPathArrayEmission(o, w, t0, t1);
    TyndallTransmittance weight = TyndallTransmittance(1.0); // spectral tracking's
    bool collided = tyndallFreeFlight(o, w, t0, t1, x, s, weight);
    if (!collided && bounce == 0)
    {
      escaped += weight; // the camera sees the background, not the sky
    }
    beta *= weight;
    if (!collided)
    {
      if (bounce > 0 && !tyndallPathSpent())
      {
        radiance += beta * tyndallPathSkyUnit(surface) * tyndallPathSkyEscape(w, phasePdf);
      }
      break;
    }
    bool own;
    TyndallLighting lit = tyndallPathCollisionMedium(x, s, own);
    if (!lit.Scatters)
    {
      radiance += beta * s.Color; // emission-absorption: the colour, and the path ends
      break;
    }
    bool last = bounce + 1 >= pathBounces;
    surface = tyndallPathOnSurface(own);
    TyndallScatterer scatterer = tyndallPathScatterer(x, w, s);
    radiance += beta * tyndallPathCollisionLight(x, w, s, lit, own, scatterer, surface, last);
    if (last || tyndallPathSpent() ||
      !tyndallPathScatter(scatterer, s, lit, surface, x, beta, w, o, phasePdf))
    {
      break;
    }
    t0 = 0.0;
    t1 = tyndallPathBoxExit(o, w);
  }
  return !tyndallPathSpent();
}

// Writes the mean of n paths' radiance and 1 - the mean of their escapes
// (the view transmittance's estimate); with a coloured extinction 1 - the
// view transmittance per channel into the second image, the first image's
// opacity their mean (vtkTransmittanceRayCastFS.glsl's tyndallWrite()).
void tyndallPathWrite(vec3 radiance, TyndallTransmittance escaped, float n)
{
#if TYNDALL_CHROMATIC
  vec3 opacity = 1.0 - escaped / n;
  gl_FragData[0] = vec4(radiance / n, (opacity.r + opacity.g + opacity.b) / 3.0);
  gl_FragData[1] = vec4(opacity, gl_FragData[0].a);
#else
  gl_FragData[0] = vec4(radiance / n, 1.0 - escaped / n);
#endif
}

void main()
{
  vec3 p0, w;
  float tNear, tFar;
  tyndallCameraRay(p0, w, tNear, tFar);
  if (!(tNear < tFar))
  {
    discard; // the image was cleared: no radiance, transmittance 1
  }
  uvec2 pixel = uvec2(gl_FragCoord.xy);
  vec3 radiance = vec3(0.0);
  TyndallTransmittance escaped = TyndallTransmittance(0.0);
  int traced = 0;
  for (int k = 0; k < pathSamples; ++k)
  {
    // The path's index in the mean, mixed as sample i % 16 of block i / 16
    // (as the frame and the sample in it were when every frame had 16).
    uint i = uint(pathFirstSample + k);
    tyndallPathState = tyndallPcg(pixel.x +
      tyndallPcg(pixel.y + tyndallPcg((i & 15u) + tyndallPcg((i >> 4u) + tyndallPcg(uint(pathSeed))))));
    ++traced;
    if (!tyndallTracePath(p0, w, tNear, tFar, radiance, escaped))
    {
      break;
    }
  }
  tyndallPathWrite(radiance, escaped, float(traced));
}
