// Tyndall: camera rays (appended to vtkTransmittanceCommonFS.glsl). Marches
// the pixel's ray through the volume up to the depth of opaque geometry and
// integrates emission-absorption or single scattering with the light
// transmittance of the selected method (Documentation/rendering-model.md).
// Writes premultiplied radiance and alpha = 1 - view transmittance; with a
// coloured extinction (TYNDALL_CHROMATIC, always accumulated) also 1 - the
// view transmittance per channel, into a second image (tyndallWrite()).
//
// A ray's steps n = firstStep .. endStep - 1 are marched by one pass: the
// whole ray in one (drawn straight into the window), or split over several
// passes (vtkTransmittanceAccumulationPass), each continuing from the state
// the previous one left in previousTexture (TYNDALL_ACCUMULATE). The ray
// itself: vtkTransmittanceCameraRayFS.glsl, before this file; the march's
// main(): vtkTransmittanceRayCastMainFS.glsl, after it (the path tracer,
// vtkTransmittancePathTraceFS.glsl, calls these functions from its own).
uniform int firstStep;
uniform int endStep;
#if TYNDALL_ACCUMULATE
uniform sampler2D previousTexture;
#endif

// Coloured extinction: TyndallTransmittance and extinctionColor are the
// common shader's (TYNDALL_CHROMATIC); the camera rays then track three view
// transmittances, written to a second image.
#if TYNDALL_CHROMATIC
#if !TYNDALL_ACCUMULATE
#error "A coloured extinction is drawn through the accumulation images."
#endif
uniform sampler2D previousOpacityTexture; // 1 - view transmittance per channel
#endif

float tyndallLargest(float t)
{
  return t;
}

float tyndallLargest(vec3 t)
{
  return max(max(t.r, t.g), t.b);
}

// (1 - exp(-sigma dt)) / sigma: a step's emission per unit length attenuated
// within the step; its series dt (1 - sigma dt / 2) where sigma dt is small
// (1 - exp() cancels in single precision there).
float tyndallAttenuatedLength(float sigma, float dt)
{
  float depth = sigma * dt;
  return depth > 1e-3 ? (1.0 - exp(-depth)) / sigma : dt * (1.0 - 0.5 * depth);
}

vec3 tyndallAttenuatedLength(vec3 sigma, float dt)
{
  return vec3(tyndallAttenuatedLength(sigma.r, dt), tyndallAttenuatedLength(sigma.g, dt),
    tyndallAttenuatedLength(sigma.b, dt));
}

// The pass's output: the rays' premultiplied radiance and 1 - their view
// transmittance (per channel in a second image with a coloured extinction;
// the first image's alpha is then 1 - the channels' mean).
// With TYNDALL_OPACITY_COVERS_RADIANCE the opacity of a ray drawn straight
// into the picture is at least its radiance (clamped to 1): an 8-bit
// compositor's unclamped "over" cannot wrap around. Accumulated images keep
// theirs (the next pass reads the view transmittance back; the composite
// raises it, vtkTransmittanceCompositeFS.glsl).
float tyndallOutputOpacity(vec3 radiance, float opacity)
{
#if TYNDALL_OPACITY_COVERS_RADIANCE && !TYNDALL_ACCUMULATE
  return max(opacity, min(max(radiance.r, max(radiance.g, radiance.b)), 1.0));
#else
  return opacity;
#endif
}

//TYNDALL::Output

// (The display transform acts only where the pass draws straight into the
// window: outputTransform is 0 for images.)
void tyndallWrite(vec3 radiance, TyndallTransmittance Tv)
{
#if TYNDALL_CHROMATIC
  float opacity = tyndallOutputOpacity(radiance, 1.0 - (Tv.r + Tv.g + Tv.b) / 3.0);
  gl_FragData[0] = vec4(radiance, opacity);
  gl_FragData[1] = vec4(1.0 - Tv, opacity);
#else
  vec4 shown = tyndallDisplay(vec4(radiance, 1.0 - Tv));
  gl_FragData[0] = vec4(shown.rgb, tyndallOutputOpacity(shown.rgb, shown.a));
#endif
}

uniform int scatteringModel; // 0: emission-absorption, 1: single scattering
uniform float stepLength;
uniform int lightSampleCount;
uniform float anisotropy;
uniform vec3 ambient; // vtkTyndallSceneReader::GetMapAmbient()
uniform float emissionScale;      // EmissionScale (0 without emission): the table's and an array's
uniform float tableEmissionScale; // emissionScale where this medium's table emits, else 0

// The lights' geometry (numberOfLights, tyndallLightAt()): vtkTransmittanceLightsFS.glsl.
uniform vec3 lightIrradiance[TYNDALL_MAX_LIGHTS];   // LightScale * intensity * colour
uniform int lightMethod[TYNDALL_MAX_LIGHTS];        // per light: map methods fall back to brute force

// What a frame needs is compiled in, not switched by uniforms (llvmpipe
// fetches the textures of a uniform branch not taken, and runs a loop of
// one that is not taken once, masked): TYNDALL_OCCLUSION, TYNDALL_EMISSION,
// TYNDALL_BRUTE_FORCE_LIGHTS, TYNDALL_LIGHT_CACHE (map lights read the
// transmittance cache), else TYNDALL_MAP_COEFFICIENTS (0: no light has a
// map; read from TYNDALL_MAP_LAYERS layers), TYNDALL_MAP_EXTINCTION and
// TYNDALL_ADAPTIVE_MAPS (bounds layer).
#if TYNDALL_OCCLUSION
uniform sampler3D occlusionTexture; // per light: distance to opaque geometry
uniform int occlusionSlices;
uniform float occlusionBias;
#endif

// Whether opaque geometry lies between x and light l.
bool occluded(int l, vec3 x)
{
#if TYNDALL_OCCLUSION
  if (lightHasFrustum[l] == 0)
  {
    return false;
  }
  vec2 ab = tyndallLightTexel(l, x);
  if (any(lessThan(ab, vec2(0.0))) || any(greaterThan(ab, vec2(1.0))))
  {
    return false;
  }
  vec3 origin, dir;
  tyndallLightRay(l, ab, origin, dir);
  float tOccluder = texture(occlusionTexture, vec3(ab, (float(l) + 0.5) / float(occlusionSlices))).r;
  return dot(x - origin, dir) > tOccluder + occlusionBias;
#else
  return false;
#endif
}

// Light transmittance through the medium (per channel with a coloured
// extinction) from x towards light l (world direction toLight); opaque
// geometry is occluded()'s.
TyndallTransmittance lightTransmittance(int l, vec3 x, vec3 toLight, float lightDistance)
{
  int m = lightMethod[l];
  if (m == TYNDALL_NONE)
  {
    return TyndallTransmittance(1.0);
  }
#if TYNDALL_BRUTE_FORCE_LIGHTS
  if (m == TYNDALL_BRUTE_FORCE)
  {
    vec2 range = tyndallIntersectMapBox(x, toLight); // the medium's box and its guests'
    float tEnd = min(range.y, lightDistance);
    if (tEnd <= 0.0)
    {
      return TyndallTransmittance(1.0);
    }
#if TYNDALL_DETAIL_GROUPS > 0 && TYNDALL_GUESTS == 0
    // Procedural detail: the closed form, exact at any distance (with
    // guests, the march below: the closed form knows the medium alone).
    return exp(-tyndallDetailDepth(x, toLight, tEnd) * extinctionColor);
#else
    float dt = tEnd / float(lightSampleCount);
    float tau = 0.0;
    // Eight samples per iteration: the inner loop has a constant trip count
    // and is unrolled, so the loop runs lightSampleCount / 8 times (Mesa's
    // llvmpipe stops a fragment's loops after 65535 iterations in all; see
    // the mapper's warning about it).
    for (int n = 0; n < lightSampleCount; n += 8)
    {
      for (int k = 0; k < 8; ++k)
      {
        if (n + k < lightSampleCount)
        {
          tau += tyndallSceneExtinction(x + (float(n + k) + 0.5) * dt * toLight, toLight, dt);
        }
      }
    }
    return exp(-tau * dt * extinctionColor);
#endif
  }
#endif
#if TYNDALL_LIGHT_CACHE
  return tyndallCachedTransmittance(l, x);
#elif TYNDALL_MAP_COEFFICIENTS > 0
  return tyndallMapTransmittance(l, x);
#else
  return TyndallTransmittance(1.0);
#endif
}

#if TYNDALL_EMISSION_ARRAY
// Emission from a separate array (fire: a temperature grid): the array's
// value at x, through the emission row of the table (blackbody or colour
// function, vtkTyndallTransferTable::TabulateEmission); per unit length,
// independent of the extinction; nothing where the medium is clipped.
uniform sampler3D emissionTexture;
uniform vec2 emissionToTable; // table coordinate = value * x + y

vec3 tyndallArrayEmission(vec3 x)
{
#if TYNDALL_CLIP
  if (tyndallClipped(x))
  {
    return vec3(0.0);
  }
#endif
  vec3 q = (worldToVolume * vec4(x, 1.0)).xyz;
  float value = texture(emissionTexture, tyndallVolumeTexel(q * volumeTexScale + volumeTexShift)).r;
  return tyndallEmissionColor(value * emissionToTable.x + emissionToTable.y);
}
#endif

#if TYNDALL_OCTAVES > 1
// a (scattering), b (extinction), c (anisotropy), k (build-up: the terms
// i >= 1 are multiplied by 1 - T^k; 0: off).
uniform vec4 octaveFactors;
#endif

#if TYNDALL_CHROMATIC
// tyndallOctaves() per channel, channel k seeing the light through T[k].
vec3 tyndallOctaves(float mu, vec3 T, vec3 albedo)
{
  vec3 sum = tyndallPhaseHG(anisotropy, mu) * T;
#if TYNDALL_OCTAVES > 1
  vec3 live = vec3(greaterThan(T, vec3(0.0)));
  vec3 logT = log(clamp(T, 1e-30, 1.0));
  vec3 buildUp = octaveFactors.w > 0.0 ? 1.0 - exp(octaveFactors.w * logT) : vec3(1.0);
  vec3 scale = vec3(1.0);
  float extinction = 1.0;
  float g = anisotropy;
  for (int i = 1; i < TYNDALL_OCTAVES; ++i)
  {
    scale *= octaveFactors.x * albedo;
    extinction *= octaveFactors.y;
    g *= octaveFactors.z;
    sum += live * buildUp * scale * tyndallPhaseHG(g, mu) * exp(extinction * logT);
  }
#endif
  return sum;
}
#endif

// p(g, mu) T, or with TYNDALL_OCTAVES > 1 the octaves' sum
// p(g, mu) T + (1 - T^k) sum_{i>=1} (a albedo)^i p(c^i g, mu) T^(b^i)
// (Documentation/rendering-model.md,
// "Multiple scattering"; CPU twin: vtkTransmittanceMapMath::OctaveScattering).
// The octave loop has a constant trip count: it is unrolled, and costs no
// loop iterations of llvmpipe's budget.
vec3 tyndallOctaves(float mu, float T, vec3 albedo)
{
  vec3 sum = vec3(tyndallPhaseHG(anisotropy, mu) * T);
#if TYNDALL_OCTAVES > 1
  if (T <= 0.0)
  {
    return vec3(0.0);
  }
  float logT = log(min(T, 1.0));
  float buildUp = octaveFactors.w > 0.0 ? 1.0 - exp(octaveFactors.w * logT) : 1.0;
  vec3 scale = vec3(1.0);
  float extinction = 1.0;
  float g = anisotropy;
  for (int i = 1; i < TYNDALL_OCTAVES; ++i)
  {
    scale *= octaveFactors.x * albedo;
    extinction *= octaveFactors.y;
    g *= octaveFactors.z;
    sum += buildUp * scale * tyndallPhaseHG(g, mu) * exp(extinction * logT);
  }
#endif
  return sum;
}


#if TYNDALL_SHADING || TYNDALL_ISOSURFACES
// A surface does not shadow itself: its T_l is taken this far towards the
// light (vtkTyndallShading::ShadowOffset voxels).
uniform float shadowOffset;
#else
const float shadowOffset = 0.0; // a medium's sample: T_l where it is
#endif

// In-scattered radiance per unit sigma_s at x, for the view direction w, at
// a sample of albedo `albedo` (which only the octaves read); an isosurface's
// light taken shadowOffset towards it.
vec3 inScattering(vec3 x, vec3 w, vec3 albedo)
{
  // An isosurface's light from shadowOffset towards it; a medium's where it is.
  float scatteringOffset = TYNDALL_ISOSURFACES != 0 ? shadowOffset : 0.0;
  vec3 sum = vec3(ambient);
  // The renderer's lights and the sky's.
  for (int l = 0; l < numberOfLights + numberOfSkyLights; ++l)
  {
    vec3 toLight;
    float distance;
    vec3 E = lightIrradiance[l];
    if (!tyndallLightAt(l, x, E, toLight, distance))
    {
      continue;
    }
    // mu: cosine between the light's travel direction and the direction
    // towards the camera.
    float mu = dot(-toLight, -w);
    if (occluded(l, x))
    {
      continue; // opaque geometry: no light in any channel
    }
    sum += E *
      tyndallOctaves(mu,
        lightTransmittance(l, x + scatteringOffset * toLight, toLight, distance - scatteringOffset),
        albedo);
  }
  return sum;
}

#if TYNDALL_SHADING
// A plain property's gradient shading (vtkTyndallShading, its CPU twin):
// Ka c + sum_l T_l E_l (Kd |n.l| c + Ks |n.h|^p), clamped to [0, 1]; n the
// scalar's unit gradient at normalAt (0 where it is 0), E_l the light's
// colour (intensity x colour, attenuated) at x, a headlight's direction
// along the ray. The lights: the renderer's and the sky's (its lights, or
// its mean from every direction: tyndallSkyMeanDiffuse()).
// (shadingCoefficients, lightColor, lightHeadlight: vtkTransmittanceLightsFS.glsl.)

// Light l at the shaded sample x (view direction -v): false where it does
// not reach x; else T_l E_l (TE), the direction s the normal meets it at
// and the half vector h.
bool tyndallShadingLight(int l, vec3 x, vec3 v, out vec3 TE, out vec3 s, out vec3 h)
{
  vec3 toLight;
  float distance;
  vec3 E = lightColor[l];
  if (!tyndallLightAt(l, x, E, toLight, distance) || occluded(l, x))
  {
    return false;
  }
  // A surface does not shadow itself: T_l from shadowOffset towards the light.
  TyndallTransmittance T =
    lightTransmittance(l, x + shadowOffset * toLight, toLight, distance - shadowOffset);
  TE = T * E;
  s = lightHeadlight[l] != 0 ? v : toLight;
  // h = 0 where the light faces the camera exactly (the CPU's guard).
  vec3 sv = s + v;
  float svLength = length(sv);
  h = svLength > 0.0 ? sv / svLength : vec3(0.0);
  return true;
}


#if TYNDALL_SCATTERING_BLEND
// VTK 9.2's volumetric scattering blending (vtkTyndallShading::BlendWeight(),
// its CPU twin; the variant for a blending above 0): the weight k of the
// volumetric term at a sample of gradient magnitude `gradient` (per world
// unit) and extinction sigma; blendGradientScale per component 2 / (s_max -
// s_min), blendStep h.
uniform float scatteringBlending; // b in (0, 2]
uniform vec4 blendGradientScale;
uniform float blendStep;

float tyndallBlendWeight(float gradient, int component, float sigma)
{
  float b = scatteringBlending;
  if (!(b > 0.0))
  {
    return 0.0;
  }
  // (VTK 9.2 passes b / 2 to its shader and picks the branch by b.)
  float e = exp(-b * gradient * blendGradientScale[component] * (1.0 - exp(-sigma * blendStep)));
  return b < 1.0 ? b * e : (2.0 - b) * e + b - 1.0;
}
#else
// No blending: the surface term alone (the path tracer's lobe reads it).
float tyndallBlendWeight(float gradient, int component, float sigma)
{
  return 0.0;
}
#endif

vec3 tyndallSurfaceShading(vec3 x, vec3 normalAt, vec3 w, vec3 color, float sigma)
{
  vec3 g = tyndallScalarGradient(normalAt);
  float magnitude = length(g);
  vec3 n = magnitude > 0.0 ? g / magnitude : vec3(0.0);
  vec3 v = -w;
  // The surface term and (blending) the volumetric one (isotropic, no normal),
  // with the sky's mean where it has no lights.
  vec3 sky = tyndallSkyMeanDiffuse(shadingCoefficients[0], color);
  vec3 surface = shadingCoefficients[0].x * color + (magnitude > 0.0 ? sky : vec3(0.0));
#if TYNDALL_SCATTERING_BLEND
  vec3 volume = shadingCoefficients[0].x * color + 2.0 * sky;
#endif
  // The renderer's lights and the sky's. tyndallShadingLight() written out:
  // called here, the common shaded frame took 7 % longer on llvmpipe
  // (BenchBlendModes: 801-813 ms against 730 ms written out, the same as
  // before the helper).
  for (int l = 0; l < numberOfLights + numberOfSkyLights; ++l)
  {
    vec3 toLight;
    float distance;
    vec3 E = lightColor[l];
    if (!tyndallLightAt(l, x, E, toLight, distance) || occluded(l, x))
    {
      continue;
    }
    TyndallTransmittance T =
      lightTransmittance(l, x + shadowOffset * toLight, toLight, distance - shadowOffset);
    vec3 s = lightHeadlight[l] != 0 ? v : toLight;
    vec3 sv = s + v;
    float svLength = length(sv);
    vec3 h = svLength > 0.0 ? sv / svLength : vec3(0.0);
    surface += T * E * tyndallShadingTerm(shadingCoefficients[0], n, s, h, color);
#if TYNDALL_SCATTERING_BLEND
    volume += T * E * shadingCoefficients[0].y * color;
#endif
  }
#if TYNDALL_SCATTERING_BLEND
  float k = tyndallBlendWeight(magnitude, 0, sigma);
  return clamp((1.0 - k) * surface + k * volume, 0.0, 1.0);
#else
  return clamp(surface, 0.0, 1.0);
#endif
}

#if TYNDALL_SHADING_ADDITIVE
// A vtkParticipatingMediumProperty's Shade (vtkTyndallShading, its CPU twin):
// the gradient surface term sum_l T_l E_l (Kd |n.l| c + Ks |n.h|^p), added
// to the sample's single scattering (no ambient term, no clamp).
vec3 tyndallSurfaceTerm(vec3 x, vec3 normalAt, vec3 w, vec3 color)
{
  vec3 g = tyndallScalarGradient(normalAt);
  float magnitude = length(g);
  vec3 n = magnitude > 0.0 ? g / magnitude : vec3(0.0);
  vec3 v = -w;
  vec3 surface =
    magnitude > 0.0 ? tyndallSkyMeanDiffuse(shadingCoefficients[0], color) : vec3(0.0);
  for (int l = 0; l < numberOfLights + numberOfSkyLights; ++l)
  {
    vec3 TE, s, h;
    if (tyndallShadingLight(l, x, v, TE, s, h))
    {
      surface += TE * tyndallShadingTerm(shadingCoefficients[0], n, s, h, color);
    }
  }
  return surface;
}
#endif

#if TYNDALL_COMPONENT_SHADING
// Independent components' shading (vtkTyndallShading): each component's
// colour shaded with its own unit gradient and coefficients, clamped, and
// the results mixed by `parts` (vtkTyndallComponents::Parts()).
vec3 tyndallComponentShading(
  vec3 x, vec3 normalAt, vec3 w, vec4 parts, mat4x3 colors, vec4 sigma)
{
  vec4 magnitudes;
  mat4x3 n = tyndallComponentNormals(normalAt, magnitudes);
  vec3 v = -w;
  mat4x3 surface;
  mat4x3 volume;
  for (int c = 0; c < TYNDALL_COMPONENTS; ++c)
  {
    vec3 sky = tyndallSkyMeanDiffuse(shadingCoefficients[c], colors[c]);
    surface[c] = shadingCoefficients[c].x * colors[c] + (magnitudes[c] > 0.0 ? sky : vec3(0.0));
    volume[c] = shadingCoefficients[c].x * colors[c] + 2.0 * sky;
  }
  for (int l = 0; l < numberOfLights + numberOfSkyLights; ++l)
  {
    vec3 TE, s, h;
    if (tyndallShadingLight(l, x, v, TE, s, h))
    {
      for (int c = 0; c < TYNDALL_COMPONENTS; ++c)
      {
        surface[c] += TE * tyndallShadingTerm(shadingCoefficients[c], n[c], s, h, colors[c]);
#if TYNDALL_SCATTERING_BLEND
        volume[c] += TE * shadingCoefficients[c].y * colors[c];
#endif
      }
    }
  }
  vec3 mixed = vec3(0.0);
  for (int c = 0; c < TYNDALL_COMPONENTS; ++c)
  {
#if TYNDALL_SCATTERING_BLEND
    float k = tyndallBlendWeight(magnitudes[c], c, sigma[c]);
    mixed += parts[c] * clamp((1.0 - k) * surface[c] + k * volume[c], 0.0, 1.0);
#else
    mixed += parts[c] * clamp(surface[c], 0.0, 1.0);
#endif
  }
  return mixed;
}
#endif
#endif

#if TYNDALL_CAMERA_GUESTS
// Guests drawn with this medium (vtkTyndallSceneReader::GetCameraGuests():
// they overlap it and are lit alike): 1 for a guest the camera rays sample.
uniform float guestCamera[TYNDALL_GUESTS];
// Every guest sampled, camera guest or not: the path tracer's scattered
// flights (vtkTransmittancePathTraceFS.glsl), which cross every medium.
bool tyndallEveryGuest = false;

#if TYNDALL_GUEST_COLORS
// Coloured particle clouds among the guests: 1 for such a guest, whose
// albedo is its scattering grid over its density (the others' samplers
// point at their own volumes and are not read).
uniform sampler3D guestScattering[TYNDALL_GUESTS];
uniform float guestColored[TYNDALL_GUESTS];
#define TYNDALL_GUEST_SCATTERING(g) guestScattering[g],
#else
#define TYNDALL_GUEST_SCATTERING(g)
#endif

#if TYNDALL_EMISSION
// Each guest's table emission scale (its EmissionScale; 0 when it does not
// emit, or emits from an array): its table's emission colour times it is
// its emission, as this medium's times tableEmissionScale.
uniform float guestEmissionScale[TYNDALL_GUESTS];
#endif

// Guest g's extinction at x (0 outside its box or when the camera rays do
// not sample it, unless tyndallEveryGuest); adds its colour and emission,
// weighted by it, to `color` and `emission`.
float tyndallGuestCameraSample(sampler3D volume, TYNDALL_GUEST_BRICKS_PARAMETER sampler2D table,
#if TYNDALL_GUEST_COLORS
  sampler3D scattering,
#endif
  int g, vec3 x, inout vec3 color, inout vec3 emission)
{
  vec3 q = (guestWorldToBox[g] * vec4(x, 1.0)).xyz;
  if ((guestCamera[g] == 0.0 && !tyndallEveryGuest) || any(lessThan(q, vec3(0.0))) ||
    any(greaterThan(q, vec3(1.0))))
  {
    return 0.0;
  }
  vec3 texel = tyndallGuestTexel(TYNDALL_GUEST_BRICKS_ARGUMENT g, q);
  float value = texture(volume, texel).r;
  vec2 toTable = guestScalarToTable[g];
  float coord = value * toTable.x + toTable.y;
  vec4 tf = texture(table, vec2(coord, TYNDALL_TABLE_ALBEDO_ROW));
  float sigma = guestDensity[g] * tf.a;
  vec3 albedo = tf.rgb;
#if TYNDALL_GUEST_COLORS
  if (guestColored[g] > 0.0)
  {
    albedo = value > 0.0 ? clamp(texture(scattering, texel).rgb / value, 0.0, 1.0) : vec3(1.0);
  }
#endif
  color += sigma * albedo;
#if TYNDALL_EMISSION
  emission += sigma * guestEmissionScale[g] *
    texture(table, vec2(coord, TYNDALL_TABLE_EMISSION_ROW)).rgb;
#endif
  return sigma;
}

// Samplers are indexed by constants only (GLSL 1.50): one statement per guest.
#define TYNDALL_GUEST_CAMERA_SAMPLE(g) sigma += tyndallGuestCameraSample(guestVolume[g], TYNDALL_GUEST_BRICKS(g) guestTransfer[g], TYNDALL_GUEST_SCATTERING(g) g, x, color, emission);

// The path tracer's draw of the medium a collision at x is of
// (tyndallPathCollisionMedium()), at guest g: while none is drawn (`drawn`
// false), a guest of positive extinction at x becomes the one so far (its
// index in `medium`, its colour and emission per unit of its extinction),
// and is drawn when u lies below the extinctions summed so far (`below`).
void tyndallGuestDraw(sampler3D volume, TYNDALL_GUEST_BRICKS_PARAMETER sampler2D table,
#if TYNDALL_GUEST_COLORS
  sampler3D scattering,
#endif
  int g, vec3 x, float u, inout float below, inout bool drawn, inout int medium,
  inout vec3 color, inout vec3 emission)
{
  if (drawn)
  {
    return;
  }
  vec3 c = vec3(0.0);
  vec3 e = vec3(0.0);
  float sigma = tyndallGuestCameraSample(volume, TYNDALL_GUEST_BRICKS_ARGUMENT table,
#if TYNDALL_GUEST_COLORS
    scattering,
#endif
    g, x, c, e);
  if (sigma > 0.0)
  {
    medium = g;
    color = c / sigma;
    emission = e / sigma;
    below += sigma;
    drawn = u < below;
  }
}

#define TYNDALL_GUEST_DRAW(g) tyndallGuestDraw(guestVolume[g], TYNDALL_GUEST_BRICKS(g) guestTransfer[g], TYNDALL_GUEST_SCATTERING(g) g, x, u, below, drawn, medium, color, emission);

// What the camera rays see at x: the extinction of this medium (empty
// outside its box) plus its camera guests', returned; their colours and
// emissions (each medium's colour times its own EmissionScale) mixed in
// proportion to their extinctions (the mixture's albedo and emission per
// unit extinction; CPU twin:
// vtkSingleScatteringReference's camera rays); this medium's own colour
// and extinction in `own`, the guests' in `guests` (their mixture's colour;
// the path tracer's collision is one or the other's), its emission per
// unit of its extinction in `ownEmission`.
float tyndallCameraMedium(vec3 x, out vec3 color, out vec3 emission, out vec4 own,
  out vec4 guests, out vec3 ownEmission)
{
  vec3 q = (worldToVolume * vec4(x, 1.0)).xyz;
  bool inside = all(greaterThanEqual(q, vec3(0.0))) && all(lessThanEqual(q, vec3(1.0)));
  vec3 ownColor = vec3(0.0);
  float tableCoord = 0.0;
  own.a = inside ? tyndallMedium(x, ownColor, tableCoord) : 0.0;
  own.rgb = ownColor;
  ownEmission = vec3(0.0);
  vec3 ownTotal = vec3(0.0);
#if TYNDALL_EMISSION
  if (own.a > 0.0)
  {
    ownEmission = tableEmissionScale * tyndallEmissionColor(tableCoord);
    ownTotal = own.a * tableEmissionScale * tyndallEmissionColor(tableCoord);
  }
#endif
  // The guests' sums apart (the mixture's less this medium's part would
  // lose their colour to rounding where their share is small).
  float sigma = 0.0;
  color = vec3(0.0);
  emission = vec3(0.0);
  TYNDALL_FOR_GUESTS(TYNDALL_GUEST_CAMERA_SAMPLE)
  guests = vec4(sigma > 0.0 ? color / sigma : vec3(0.0), sigma);
  sigma += own.a;
  color += own.a * ownColor;
  emission += ownTotal;
  if (sigma > 0.0)
  {
    color /= sigma;
    emission /= sigma;
  }
  return sigma;
}
#endif

#if TYNDALL_DETAIL_SAMPLES > 0
// Procedural detail, camera rays importance-sampled in closed form
// (Documentation/rendering-model.md, "Camera rays sampled in closed form"):
// TYNDALL_DETAIL_SAMPLES free-flight distances per pixel, stratified in
// transmittance, 1 - T(t_j) = (j + xi) / N, xi a per-pixel hash rotated by
// the golden ratio each still frame (detailFrame), so that frames averaged
// by vtkTransmittanceAccumulationPass fill the strata evenly. Each sample
// that lands before tFar contributes its source (per unit extinction); the
// mean over the N is an unbiased estimate of the premultiplied radiance,
// and the view transmittance is exact (the walk's closed form).
uniform int detailFrame;

// A hash of three integers to [0, 1) (the PCG3D permutation of Jarzynski
// and Olano, 2020).
float tyndallHash(uvec3 v)
{
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return float(v.x >> 8u) * (1.0 / 16777216.0);
}

vec4 tyndallSampledRay(vec3 p0, vec3 w, float tNear, float tFar)
{
  float xi = fract(tyndallHash(uvec3(uvec2(gl_FragCoord.xy), 7u)) +
    float(detailFrame) * 0.6180339887498949);
  float goals[TYNDALL_DETAIL_SAMPLES];
  for (int j = 0; j < TYNDALL_DETAIL_SAMPLES; ++j)
  {
    goals[j] = -log(1.0 - (float(j) + xi) / float(TYNDALL_DETAIL_SAMPLES));
  }
  vec3 x0 = p0 + tNear * w;
  float span = tFar - tNear;
  float opaque = -log(TYNDALL_VIEW_TERMINATION);
  float distances[TYNDALL_DETAIL_SAMPLES];
  float tau = tyndallDetailSampleDistances(x0, w, span, goals, opaque, distances);
  vec3 radiance = vec3(0.0);
  for (int j = 0; j < TYNDALL_DETAIL_SAMPLES; ++j)
  {
    if (distances[j] > span)
    {
      break; // ascending: the rest lie past the ray's end too
    }
    vec3 x = x0 + distances[j] * w;
    vec3 color;
    float tableCoord;
    tyndallMedium(x, color, tableCoord);
    vec3 source = color;
    if (scatteringModel != 0)
    {
      source *= inScattering(x, w, color);
#if TYNDALL_EMISSION
      source += tableEmissionScale * tyndallEmissionColor(tableCoord);
#endif
    }
    radiance += source;
  }
  return vec4(radiance / float(TYNDALL_DETAIL_SAMPLES), tau >= opaque ? 1.0 : 1.0 - exp(-tau));
}
#endif

// main()'s parts. The variants of a frame (the #if switches) live in these
// functions, never in main() itself: each compiles to what the variant needs.

// The start of this pass's part of the ray: the radiance and view
// transmittance the previous pass left (TYNDALL_ACCUMULATE), or none. False
// when the pixel is written already (a ray sampled in closed form:
// TYNDALL_DETAIL_SAMPLES) or discarded (a ray drawn in one pass that misses
// the box or its depth range; an image it is drawn into was cleared). An
// accumulated ray that misses or has ended gets an empty part (tFar =
// tNear), and main() writes its state back (a write here and a return made
// llvmpipe run every accumulated ray 1.6 times slower).
bool tyndallStartRay(vec3 p0, vec3 w, float tNear, inout float tFar, out vec3 radiance,
  out TyndallTransmittance Tv)
{
#if TYNDALL_ACCUMULATE
  vec4 previous = texelFetch(previousTexture, ivec2(gl_FragCoord.xy), 0);
#if TYNDALL_CHROMATIC
  vec3 previousTv = 1.0 - texelFetch(previousOpacityTexture, ivec2(gl_FragCoord.xy), 0).rgb;
#else
  float previousTv = 1.0 - previous.a;
#endif
  radiance = previous.rgb;
  Tv = previousTv;
  if (!(tNear < tFar) || tyndallLargest(previousTv) < TYNDALL_VIEW_TERMINATION)
  {
    tFar = tNear; // nothing (more) to march
    return true;
  }
#if TYNDALL_DETAIL_SAMPLES > 0
  gl_FragData[0] = tyndallSampledRay(p0, w, tNear, tFar);
  return false;
#endif
#else
  if (!(tNear < tFar))
  {
    discard;
  }
  radiance = vec3(0.0);
  Tv = TyndallTransmittance(1.0);
#endif
  return true;
}

// Empty-space skipping along the camera ray (TYNDALL_SKIP_EMPTY): the ray
// in the majorant grid's blocks, and where the non-empty block the samples
// are in ends.
struct TyndallSkip
{
  vec3 Origin;
  vec3 Direction;
  float BlockEnd;
};

TyndallSkip tyndallStartSkipping(vec3 p0, vec3 w)
{
  TyndallSkip skip;
  skip.Origin = vec3(0.0);
  skip.Direction = vec3(0.0);
#if TYNDALL_SKIP_EMPTY
  tyndallBlockRay(p0, w, skip.Origin, skip.Direction);
#endif
  skip.BlockEnd = -1.0;
  return skip;
}

// Whether the sample at ts lies in an empty block: then n has moved past
// it (tyndallSkipEmpty()); never without skipping.
bool tyndallSkipStep(inout TyndallSkip skip, float ts, inout int n, float tNear, float offset)
{
#if TYNDALL_SKIP_EMPTY
  return tyndallSkipEmpty(skip.Origin, skip.Direction, ts, skip.BlockEnd, n, tNear, stepLength,
    offset, endStep);
#else
  return false;
#endif
}

// What a camera ray samples at x: the volume's medium or, with camera
// guests (TYNDALL_CAMERA_GUESTS), the media it draws as one; its extinction
// (0: empty), colour (per unit extinction) and what its emission needs.
struct TyndallCameraSample
{
  float Sigma;
  vec3 Color;
  vec3 Emission;    // camera guests: the media's mixed emission (each scaled), per unit extinction
                    // (at a path's collision the drawn medium's: tyndallPathCollisionMedium())
  float TableCoord; // alone: the sample's position in the transfer table
  vec3 Position;    // where its light is looked up: the sample, or a step's first isosurface
  vec3 Normal;      // where a shaded sample's normal is taken: the sample, or an isosurface
                    // step's end (where VTK shades it)
#if TYNDALL_CAMERA_GUESTS
  vec4 Own;    // this medium's colour and extinction in the mixture (tyndallCameraMedium())
  vec4 Guests; // the guests' (their mixture's colour)
  vec3 OwnEmission; // this medium's emission (scaled) per unit of its extinction
#endif
#if TYNDALL_COMPONENT_SHADING
  vec4 Parts;    // independent components' parts in the colour (vtkTyndallComponents::Parts())
  mat4x3 Colors; // colours
  vec4 Sigmas;   // and extinctions
#endif
};

#if TYNDALL_DETAIL_FILTER
// The world width of a pixel at x: pixelWidth.x + pixelWidth.y * depth,
// depth = pixelDepthPlane . (x, 1) (vtkTyndallFootprint).
uniform vec4 pixelDepthPlane;
uniform vec2 pixelWidth;
#endif

// What procedural detail is filtered by at the camera sample x (the
// footprint of its pixel); 0: unfiltered.
float tyndallPixelFootprint(vec3 x)
{
#if TYNDALL_DETAIL_FILTER
  return pixelWidth.x + pixelWidth.y * max(dot(pixelDepthPlane.xyz, x) + pixelDepthPlane.w, 0.0);
#else
  return 0.0;
#endif
}

// Tells the medium the camera ray's direction w and its step dt
// (procedural detail takes each wave's mean over a step centred on the
// sample: tyndallDetailRayStep()); before the march and where the step
// changes.
void tyndallCameraStep(vec3 w, float dt)
{
#if TYNDALL_DETAIL_STEP_MEANS
  tyndallDetailRayStep(w, dt);
#endif
}

#if TYNDALL_ISOSURFACES
// The isosurfaces (TYNDALL_ISOSURFACES) the camera ray's step from x0
// along w, of length dt, crosses: their composite as the step's extinction
// -ln(1 - alpha) / dt and colour, evaluated where the first lies (CPU
// twin: vtkTyndallGridMedium::IsoSample()).
TyndallCameraSample tyndallIsoCameraSample(vec3 x0, vec3 w, float dt)
{
  TyndallCameraSample s;
  s.Sigma = 0.0;
  s.Color = vec3(0.0);
  s.Emission = vec3(0.0);
  s.TableCoord = 0.0;
  s.Position = x0;
  s.Normal = x0 + dt * w;
  float v0, v1, first;
  if (tyndallIsoValue(x0, v0) && tyndallIsoValue(x0 + dt * w, v1))
  {
    vec4 c = tyndallIsoCrossings(v0, v1, first);
    if (c.a > 0.0)
    {
      float a = min(c.a, TYNDALL_ISO_MAX_OPACITY);
      s.Sigma = -log(1.0 - a) / dt;
      s.Color = c.rgb / a;
      s.Position = x0 + first * dt * w;
    }
  }
#if TYNDALL_CAMERA_GUESTS
  s.Own = vec4(s.Color, s.Sigma); // the isosurfaces are this volume's alone
  s.Guests = vec4(0.0);
  s.OwnEmission = vec3(0.0);
#endif
  return s;
}
#endif

// What the camera ray sees at its sample x of the step from x0 along w of
// length dt.
TyndallCameraSample tyndallCameraSample(vec3 x, vec3 x0, vec3 w, float dt)
{
#if TYNDALL_ISOSURFACES
  return tyndallIsoCameraSample(x0, w, dt);
#endif
  TyndallCameraSample s;
  s.Position = x;
  s.Normal = x;
  tyndallFootprint = tyndallPixelFootprint(x);
#if TYNDALL_CAMERA_GUESTS
  s.TableCoord = 0.0;
  s.Sigma = tyndallCameraMedium(x, s.Color, s.Emission, s.Own, s.Guests, s.OwnEmission);
#else
  s.Emission = vec3(0.0);
  s.Sigma = tyndallMedium(x, s.Color, s.TableCoord);
#endif
#if TYNDALL_COMPONENT_SHADING
  s.Parts = tyndallComponentParts;
  s.Colors = tyndallComponentColors;
  s.Sigmas = tyndallComponentSigma;
#endif
  tyndallFootprint = 0.0; // the light rays from here see the unfiltered medium
  return s;
}

// The sample's emission (scaled; per unit extinction) in single
// scattering: from the transfer functions or the camera guests' mix (each
// medium's scaled by its own EmissionScale: tyndallCameraMedium(); at a
// path's collision the drawn medium's) (TYNDALL_EMISSION); none otherwise.
vec3 tyndallSampleEmission(TyndallCameraSample s)
{
#if TYNDALL_EMISSION && TYNDALL_CAMERA_GUESTS
  return s.Emission;
#elif TYNDALL_EMISSION
  return tableEmissionScale * tyndallEmissionColor(s.TableCoord);
#else
  return vec3(0.0);
#endif
}

// An emission array's light over the step of length dt at x (emission per
// unit length, attenuated within the step and by Tv before it); none
// without one (TYNDALL_EMISSION_ARRAY).
vec3 tyndallStepArrayEmission(vec3 x, float sigma, float dt, TyndallTransmittance Tv)
{
#if TYNDALL_EMISSION_ARRAY
  return Tv * emissionScale * tyndallArrayEmission(x) *
    tyndallAttenuatedLength(sigma * extinctionColor, dt);
#else
  return vec3(0.0);
#endif
}

// The source of the camera sample `medium` (view direction w), per unit
// extinction: its colour (emission-absorption), a plain property's gradient
// shading (TYNDALL_SHADING), or single scattering and emission; lit at its
// Position.
vec3 tyndallSource(TyndallCameraSample medium, vec3 w)
{
  if (scatteringModel == 0)
  {
    return medium.Color;
  }
#if TYNDALL_SHADING_ADDITIVE
  return medium.Color * inScattering(medium.Position, w, medium.Color) +
    tyndallSampleEmission(medium) +
    tyndallSurfaceTerm(medium.Position, medium.Normal, w, medium.Color);
#elif TYNDALL_COMPONENT_SHADING
  return tyndallComponentShading(
    medium.Position, medium.Normal, w, medium.Parts, medium.Colors, medium.Sigmas);
#elif TYNDALL_SHADING
  return tyndallSurfaceShading(medium.Position, medium.Normal, w, medium.Color, medium.Sigma);
#else
  return medium.Color * inScattering(medium.Position, w, medium.Color) +
    tyndallSampleEmission(medium);
#endif
}

