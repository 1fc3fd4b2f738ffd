//VTK::System::Dec
// Tyndall: functions shared by the map-build and ray-cast fragment shaders.
// Formulas: Documentation/rendering-model.md. The CPU twins live in
// vtkTransmittanceMapMath (Tyndall::Core) and vtkSingleScatteringReference.

// Constants, #defined from their one C++ definition by
// vtkTransmittanceShaderSource: TYNDALL_MAX_LIGHTS, TYNDALL_MAX_COEFFICIENTS,
// TYNDALL_COEFFICIENTS_PER_LAYER, the methods TYNDALL_NONE ..
// TYNDALL_ADAPTIVE_ETM, the table rows TYNDALL_TABLE_ALBEDO_ROW and
// TYNDALL_TABLE_EMISSION_ROW, TYNDALL_NO_OCCLUDER, TYNDALL_PI; and the
// variant switches (see vtkTransmittanceShaderSource.h).
//TYNDALL::Constants

// The medium: scalars in a 3-D texture, transfer functions in a 2-D table
// (vtkTyndallTransferTable: albedo row rgb = colour or albedo, a =
// extinction per unit length before the density scale; emission row rgb =
// emission colour).
uniform sampler3D volumeTexture;
#if TYNDALL_MISSING_DATA
// NaN voxels (missing data): 0 there, 1 elsewhere; a sample whose filtered
// validity is below 1 is empty.
uniform sampler3D validityTexture;
#endif
uniform sampler2D transferTexture;
uniform mat4 worldToVolume;  // world -> the medium's box as [0,1]^3
uniform vec3 volumeTexScale; // box [0,1]^3 -> texture coordinates
uniform vec3 volumeTexShift;
uniform vec2 scalarToTable; // table coordinate = value * x + y
uniform float densityScale;

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

// Ray (world) against the volume's box: returns (t_in, t_out); t_in > t_out
// when the ray misses. worldToVolume is affine, so t stays a world distance.
vec2 tyndallIntersectVolume(vec3 origin, vec3 dir)
{
  vec3 o = (worldToVolume * vec4(origin, 1.0)).xyz;
  vec3 d = (worldToVolume * vec4(dir, 0.0)).xyz;
  vec3 invD = 1.0 / d; // IEEE: +-inf for zero components
  vec3 t0 = (vec3(0.0) - o) * invD;
  vec3 t1 = (vec3(1.0) - o) * invD;
  vec3 tMin = min(t0, t1);
  vec3 tMax = max(t0, t1);
  return vec2(max(max(tMin.x, tMin.y), tMin.z), min(min(tMax.x, tMax.y), tMax.z));
}

#if TYNDALL_SKIP_EMPTY
// Empty-space skipping: vtkTyndallMajorantGrid's blocks, one texel each
// holding the block's largest table extinction (0: every sample a renderer
// can take in the block has zero extinction). Block coordinates: block b
// spans [b, b + 1) per axis.
uniform sampler3D blockTexture;
uniform vec3 blockCount;
uniform vec3 boxToBlockScale; // box [0,1]^3 -> block coordinates
uniform vec3 boxToBlockShift;

// The world ray (origin, dir) in block coordinates: p(t) = bo + t bd.
void tyndallBlockRay(vec3 origin, vec3 dir, out vec3 bo, out vec3 bd)
{
  bo = (worldToVolume * vec4(origin, 1.0)).xyz * boxToBlockScale + boxToBlockShift;
  bd = (worldToVolume * vec4(dir, 0.0)).xyz * boxToBlockScale;
}

// The block holding p(t): returns the t at which the ray leaves it, and
// whether it is empty.
float tyndallBlockExit(vec3 bo, vec3 bd, float t, out bool empty)
{
  vec3 cell = clamp(floor(bo + t * bd), vec3(0.0), blockCount - 1.0);
  empty = texelFetch(blockTexture, ivec3(cell), 0).r <= 0.0;
  vec3 tFace = (cell + step(vec3(0.0), bd) - bo) / bd;
  tFace = mix(vec3(1e30), tFace, notEqual(bd, vec3(0.0)));
  return min(min(tFace.x, tFace.y), tFace.z);
}

// A march whose sample n lies at t(n) = tStart + (n + offset) dt, now at
// sample n (at ts): when ts has left the last block looked up (tBlockEnd),
// looks up the block of ts; when that block is empty, advances n to the
// first sample past it (at most nMax) and returns true: the caller skips.
// Samples keep their places, so a skip changes no sample that sees the
// medium; an empty block costs one loop iteration.
bool tyndallSkipEmpty(vec3 bo, vec3 bd, float ts, inout float tBlockEnd, inout int n,
  float tStart, float dt, float offset, int nMax)
{
  if (ts < tBlockEnd)
  {
    return false;
  }
  bool empty;
  tBlockEnd = tyndallBlockExit(bo, bd, ts, empty);
  if (!empty)
  {
    return false;
  }
  n = int(clamp(ceil((tBlockEnd - tStart) / dt - offset), float(n + 1), float(nMax)));
  return true;
}
#endif

#if TYNDALL_CLIP
// The mapper's clipping planes and cropping (vtkTyndallClipRegion): the
// medium is empty outside them, for camera rays and for the light. A plane
// (n, d) keeps n . x + d >= 0 (world); cropping keeps the regions of the
// 3 x 3 x 3 split of the data coordinates whose bit is set in cropFlags.
uniform vec4 clipPlanes[TYNDALL_MAX_CLIP_PLANES];
uniform int clipPlaneCount;
uniform int cropping;
uniform mat4 worldToData;
uniform vec3 cropLow;
uniform vec3 cropHigh;
uniform int cropFlags;

bool tyndallClipped(vec3 x)
{
  for (int i = 0; i < TYNDALL_MAX_CLIP_PLANES; ++i)
  {
    if (i < clipPlaneCount && dot(clipPlanes[i].xyz, x) + clipPlanes[i].w < 0.0)
    {
      return true;
    }
  }
  if (cropping != 0)
  {
    vec3 d = (worldToData * vec4(x, 1.0)).xyz;
    ivec3 r = ivec3(step(cropLow, d) + step(cropHigh, d));
    int region = r.x + 3 * r.y + 9 * r.z;
    return ((cropFlags >> region) & 1) == 0;
  }
  return false;
}
#endif

// Procedural detail (vtkTransmittanceDetailFS.glsl) when TYNDALL_DETAIL_GROUPS > 0.
//TYNDALL::Detail

// The medium at a world point: the extinction (density scale applied),
// returned; the colour (or albedo); and the point's transfer-table
// coordinate, with which tyndallEmissionColor() reads the emission row
// without sampling the volume again.
float tyndallMedium(vec3 x, out vec3 color, out float tableCoord)
{
#if TYNDALL_CLIP
  if (tyndallClipped(x))
  {
    color = vec3(0.0);
    tableCoord = 0.0;
    return 0.0;
  }
#endif
  vec3 q = (worldToVolume * vec4(x, 1.0)).xyz;
  vec3 texel = q * volumeTexScale + volumeTexShift;
#if TYNDALL_MISSING_DATA
  if (texture(validityTexture, texel).r < 0.999)
  {
    color = vec3(0.0);
    tableCoord = 0.0;
    return 0.0;
  }
#endif
  float value = texture(volumeTexture, texel).r;
  tableCoord = value * scalarToTable.x + scalarToTable.y;
  vec4 tf = texture(transferTexture, vec2(tableCoord, TYNDALL_TABLE_ALBEDO_ROW));
  color = tf.rgb;
#if TYNDALL_DETAIL_GROUPS > 0
  return tyndallDetailExtinction(q);
#else
  return densityScale * tf.a;
#endif
}

float tyndallExtinction(vec3 x)
{
  vec3 color;
  float tableCoord;
  return tyndallMedium(x, color, tableCoord);
}

vec3 tyndallEmissionColor(float tableCoord)
{
  return texture(transferTexture, vec2(tableCoord, TYNDALL_TABLE_EMISSION_ROW)).rgb;
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

// Light l's map transmittance from world point x to the light: the map
// texel of x, the position of x along the texel's light ray across the
// volume's box, the reconstruction there.
float tyndallMapTransmittance(int l, vec3 x)
{
  vec2 ab = tyndallLightTexel(l, x);
  vec3 origin, dir;
  tyndallLightRay(l, ab, origin, dir);
  vec2 range = tyndallIntersectVolume(origin, dir);
  if (range.x >= range.y)
  {
    return 1.0;
  }
  float s = (dot(x - origin, dir) - range.x) / (range.y - range.x);
  float c[TYNDALL_MAX_COEFFICIENTS];
  for (int j = 0; j < TYNDALL_MAX_COEFFICIENTS; ++j)
  {
    c[j] = 0.0;
  }
  int first = l * layersPerLight;
  for (int k = 0; k < TYNDALL_MAP_LAYERS; ++k)
  {
    vec4 v = texture(mapTexture, vec3(ab, (float(first + k) + 0.5) / float(mapSlices)));
    c[4 * k] = v.x;
    c[4 * k + 1] = v.y;
    c[4 * k + 2] = v.z;
    c[4 * k + 3] = v.w;
  }
  vec3 bounds = vec3(0.0, 1.0, 1.0);
#if TYNDALL_ADAPTIVE_MAPS
  bounds =
    texture(mapTexture, vec3(ab, (float(first + boundsLayer) + 0.5) / float(mapSlices))).xyz;
#endif
  return tyndallReconstruct(c, bounds, clamp(s, 0.0, 1.0));
}
#endif

#if TYNDALL_LIGHT_CACHE
// The transmittance cache (vtkTransmittanceLightCachePass): light l's map
// transmittance at the texels of a lattice over the volume's box, texel
// centres on the box's faces (box coordinate i / (n - 1)); the lights'
// lattices are stacked along the third axis, lightCacheSize.z slices each.
uniform sampler3D lightCacheTexture;
uniform vec3 lightCacheSize; // texels per axis of one light's lattice
uniform int lightCacheLights;

float tyndallCachedTransmittance(int l, vec3 x)
{
  vec3 q = clamp((worldToVolume * vec4(x, 1.0)).xyz, 0.0, 1.0);
  vec3 texel = q * (lightCacheSize - 1.0) + 0.5; // within [0.5, size - 0.5]: no bleeding
  texel.z += float(l) * lightCacheSize.z;
  return texture(
    lightCacheTexture, texel / vec3(lightCacheSize.xy, lightCacheSize.z * float(lightCacheLights)))
    .r;
}
#endif

// Henyey-Greenstein, normalised to 1/(4 pi) over the sphere.
float tyndallPhaseHG(float g, float mu)
{
  float denom = 1.0 + g * g - 2.0 * g * mu;
  return (1.0 - g * g) / (4.0 * TYNDALL_PI * denom * sqrt(denom));
}
