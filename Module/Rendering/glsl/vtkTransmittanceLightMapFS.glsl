// Tyndall: the light maps' lookup (inserted into vtkTransmittanceCommonFS.glsl
// at //TYNDALL::LightMaps, and into the fragment shaders of opaque surfaces
// that receive the medium's shadow, vtkVolumeShadowReceiverPass): the medium's
// box, the lights' frusta, the reconstruction of a map texel's series and
// tyndallMapTransmittance(). It declares no sampler but mapTexture (with
// TYNDALL_MAP_COEFFICIENTS > 0), so a shader that is not Tyndall's can take it.
// Constants: vtkTransmittanceShaderSource.
// The light maps' box as [0,1]^3: the medium's box, or with guests (other
// media the light crosses) the world-axis box around them all.
uniform mat4 worldToMapBox;

// Coloured extinction (Documentation/rendering-model.md, "Coloured
// extinction"): channel k's extinction is extinctionColor[k] times the
// medium's (the densest channel's: the largest component is 1), so a light
// or view transmittance is per channel, TyndallTransmittance a vec3; else
// it is a float and extinctionColor the constant 1.
#if TYNDALL_CHROMATIC
#define TyndallTransmittance vec3
uniform vec3 extinctionColor;

// The channels' transmittances T^extinctionColor from the densest channel's
// T (a channel without extinction sees 1).
vec3 tyndallChannels(float T)
{
  return T > 0.0 ? exp(extinctionColor * log(min(T, 1.0)))
                 : vec3(equal(extinctionColor, vec3(0.0)));
}
#else
#define TyndallTransmittance float
const float extinctionColor = 1.0;

float tyndallChannels(float T)
{
  return T;
}
#endif

// Light frusta: texel (a, b) in [0,1]^2 is the ray origin(a, b) + t dir(a, b).
// Directional: origin = lightOrigin + a * lightAxisX + b * lightAxisY,
// dir = lightAxisZ. Positional: origin = lightOrigin, dir =
// normalize(lightAxisZ + (2a - 1) lightAxisX + (2b - 1) lightAxisY).
uniform int lightPositional[TYNDALL_MAX_LIGHTS];
uniform int lightHasFrustum[TYNDALL_MAX_LIGHTS]; // 0: light inside the bounds
uniform vec3 lightOrigin[TYNDALL_MAX_LIGHTS];
uniform vec3 lightAxisX[TYNDALL_MAX_LIGHTS];
uniform vec3 lightAxisY[TYNDALL_MAX_LIGHTS];
uniform vec3 lightAxisZ[TYNDALL_MAX_LIGHTS];

// Ray (world) against the box `worldToBox` maps to [0,1]^3: returns (t_in,
// t_out); t_in > t_out when the ray misses. The map is affine, so t stays a
// world distance.
vec2 tyndallIntersectBox(mat4 worldToBox, vec3 origin, vec3 dir)
{
  vec3 o = (worldToBox * vec4(origin, 1.0)).xyz;
  vec3 d = (worldToBox * vec4(dir, 0.0)).xyz;
  vec3 invD = 1.0 / d; // IEEE: +-inf for zero components
  vec3 t0 = (vec3(0.0) - o) * invD;
  vec3 t1 = (vec3(1.0) - o) * invD;
  vec3 tMin = min(t0, t1);
  vec3 tMax = max(t0, t1);
  return vec2(max(max(tMin.x, tMin.y), tMin.z), min(min(tMax.x, tMax.y), tMax.z));
}

// Ray (world) against the light maps' box.
vec2 tyndallIntersectMapBox(vec3 origin, vec3 dir)
{
  return tyndallIntersectBox(worldToMapBox, origin, dir);
}

// The light ray of texel (a, b) of light l.
void tyndallLightRay(int l, vec2 ab, out vec3 origin, out vec3 dir)
{
  if (lightPositional[l] == 0)
  {
    origin = lightOrigin[l] + ab.x * lightAxisX[l] + ab.y * lightAxisY[l];
    dir = lightAxisZ[l];
  }
  else
  {
    origin = lightOrigin[l];
    dir = normalize(lightAxisZ[l] + (2.0 * ab.x - 1.0) * lightAxisX[l] +
      (2.0 * ab.y - 1.0) * lightAxisY[l]);
  }
}

// Texel coordinates (a, b) of a world point in light l's map.
vec2 tyndallLightTexel(int l, vec3 x)
{
  vec3 v = x - lightOrigin[l];
  if (lightPositional[l] == 0)
  {
    return vec2(dot(v, lightAxisX[l]) / dot(lightAxisX[l], lightAxisX[l]),
      dot(v, lightAxisY[l]) / dot(lightAxisY[l], lightAxisY[l]));
  }
  float z = dot(v, lightAxisZ[l]);
  float ax = dot(v, lightAxisX[l]) / (z * dot(lightAxisX[l], lightAxisX[l]));
  float ay = dot(v, lightAxisY[l]) / (z * dot(lightAxisY[l], lightAxisY[l]));
  return vec2(0.5 * (ax + 1.0), 0.5 * (ay + 1.0));
}

#if TYNDALL_MAP_COEFFICIENTS > 0
// Reconstruction (vtkTransmittanceMapMath::Reconstruct) of the frame's map
// method, compiled for it: TYNDALL_MAP_COEFFICIENTS coefficients,
// TYNDALL_MAP_EXTINCTION (1: the series is the extinction, ETM; 0: the
// transmittance, TFM) and TYNDALL_ADAPTIVE_MAPS (s is mapped through the
// texel's bounds).
float tyndallReconstruct(float c[TYNDALL_MAX_COEFFICIENTS], vec3 bounds, float s)
{
#if TYNDALL_ADAPTIVE_MAPS
  if (s <= bounds.x)
  {
    return 1.0;
  }
  if (s >= bounds.y)
  {
    return bounds.z;
  }
  float u = (s - bounds.x) / max(bounds.y - bounds.x, 1e-12);
#else
  float u = s;
#endif
  u = clamp(u, 0.0, 1.0);
  // cos(j pi u) and sin(j pi u) by the angle-addition recurrence: one cos
  // and one sin per reconstruction instead of one per coefficient.
  float c1 = cos(TYNDALL_PI * u);
  float s1 = sin(TYNDALL_PI * u);
  float cj = 1.0;
  float sj = 0.0;
#if TYNDALL_MAP_EXTINCTION
  float tau = 0.5 * c[0] * u;
  for (int j = 1; j < TYNDALL_MAP_COEFFICIENTS; ++j)
  {
    float cNext = cj * c1 - sj * s1;
    sj = sj * c1 + cj * s1;
    cj = cNext;
    tau += c[j] * sj / (float(j) * TYNDALL_PI);
  }
  return exp(-max(tau, 0.0));
#else
  float T = 0.5 * c[0];
  for (int j = 1; j < TYNDALL_MAP_COEFFICIENTS; ++j)
  {
    float cNext = cj * c1 - sj * s1;
    sj = sj * c1 + cj * s1;
    cj = cNext;
    T += c[j] * cj;
  }
  return clamp(T, 0.0, 1.0);
#endif
}
#endif

#if TYNDALL_MAP_COEFFICIENTS > 0
// The transmittance maps (vtkTransmittanceMapPass): every layer of every
// light is a slice of mapTexture; light l's layers start at l *
// layersPerLight, its bounds layer (adaptive methods) is boundsLayer.
uniform sampler3D mapTexture;
uniform int layersPerLight;
uniform int boundsLayer;
uniform int mapSlices;
// TYNDALL_CHANNEL_MAPS (transmittance functions of a coloured extinction):
// three sets of maps, one per channel, set k's slices mapSetStride after
// set k - 1's.
uniform int mapSetStride;

#if TYNDALL_ADAPTIVE_MAPS
// One texel's series at s: texel `texel` of the layers from slice `first`,
// reconstructed over its own range (its bounds layer).
float tyndallMapTexel(int first, ivec2 texel, float s)
{
  float c[TYNDALL_MAX_COEFFICIENTS];
  for (int j = 0; j < TYNDALL_MAX_COEFFICIENTS; ++j)
  {
    c[j] = 0.0;
  }
  for (int k = 0; k < TYNDALL_MAP_LAYERS; ++k)
  {
    vec4 v = texelFetch(mapTexture, ivec3(texel, first + k), 0);
    c[4 * k] = v.x;
    c[4 * k + 1] = v.y;
    c[4 * k + 2] = v.z;
    c[4 * k + 3] = v.w;
  }
  vec3 bounds = texelFetch(mapTexture, ivec3(texel, first + boundsLayer), 0).xyz;
  return tyndallReconstruct(c, bounds, s);
}
#endif

// Map set `set` of light l at its texel ab, at the position s in [0, 1]
// along the texel's light ray across the volume's box. Plain maps: the
// coefficients are interpolated bilinearly (the reconstruction is linear in
// them). Adaptive maps: each texel's series covers its own range
// [s_min, s_max], so interpolated coefficients and bounds would mix series
// of different ranges (thin dark streaks along the light where neighbouring
// ranges differ); the four nearest texels are reconstructed, each over its
// own range, and their transmittances interpolated bilinearly.
float tyndallMapSet(int l, int set, vec2 ab, float s)
{
  int first = l * layersPerLight + set * mapSetStride;
  s = clamp(s, 0.0, 1.0);
#if TYNDALL_ADAPTIVE_MAPS
  ivec2 size = textureSize(mapTexture, 0).xy;
  ivec2 top = size - 1;
  vec2 p = clamp(ab, 0.0, 1.0) * vec2(size) - 0.5;
  vec2 corner = floor(p);
  vec2 f = p - corner;
  ivec2 i0 = ivec2(corner);
  float T00 = tyndallMapTexel(first, clamp(i0, ivec2(0), top), s);
  float T10 = tyndallMapTexel(first, clamp(i0 + ivec2(1, 0), ivec2(0), top), s);
  float T01 = tyndallMapTexel(first, clamp(i0 + ivec2(0, 1), ivec2(0), top), s);
  float T11 = tyndallMapTexel(first, clamp(i0 + ivec2(1, 1), ivec2(0), top), s);
  return mix(mix(T00, T10, f.x), mix(T01, T11, f.x), f.y);
#else
  float c[TYNDALL_MAX_COEFFICIENTS];
  for (int j = 0; j < TYNDALL_MAX_COEFFICIENTS; ++j)
  {
    c[j] = 0.0;
  }
  for (int k = 0; k < TYNDALL_MAP_LAYERS; ++k)
  {
    vec4 v = texture(mapTexture, vec3(ab, (float(first + k) + 0.5) / float(mapSlices)));
    c[4 * k] = v.x;
    c[4 * k + 1] = v.y;
    c[4 * k + 2] = v.z;
    c[4 * k + 3] = v.w;
  }
  return tyndallReconstruct(c, vec3(0.0, 1.0, 1.0), s);
#endif
}

// Light l's map transmittance from world point x to the light (per channel
// with a coloured extinction): the map texel of x, the position of x along
// the texel's light ray across the maps' box, the reconstruction there.
TyndallTransmittance tyndallMapTransmittance(int l, vec3 x)
{
  vec2 ab = tyndallLightTexel(l, x);
  vec3 origin, dir;
  tyndallLightRay(l, ab, origin, dir);
  vec2 range = tyndallIntersectMapBox(origin, dir);
  if (range.x >= range.y)
  {
    return TyndallTransmittance(1.0);
  }
  float s = (dot(x - origin, dir) - range.x) / (range.y - range.x);
#if TYNDALL_CHANNEL_MAPS
  return vec3(tyndallMapSet(l, 0, ab, s), tyndallMapSet(l, 1, ab, s), tyndallMapSet(l, 2, ab, s));
#else
  // ETM: exp(-e tau) is exactly T^e.
  return tyndallChannels(tyndallMapSet(l, 0, ab, s));
#endif
}
#endif

