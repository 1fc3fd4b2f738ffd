//VTK::System::Dec
// Tyndall: functions shared by the map-build and ray-cast fragment shaders.
// Formulas: Documentation/rendering-model.md. The CPU twins live in
// vtkTransmittanceMapMath (Tyndall::Core) and vtkSingleScatteringReference.

// Constants, #defined from their one C++ definition by
// vtkTransmittanceShaderSource: TYNDALL_MAX_LIGHTS, TYNDALL_MAX_COEFFICIENTS,
// TYNDALL_COEFFICIENTS_PER_LAYER, the methods TYNDALL_NONE ..
// TYNDALL_ADAPTIVE_ETM, the table rows TYNDALL_TABLE_ALBEDO_ROW,
// TYNDALL_TABLE_EMISSION_ROW and TYNDALL_TABLE_GRADIENT_ROW, the table's
// TYNDALL_TABLE_SIZE entries, TYNDALL_NO_OCCLUDER, TYNDALL_PI; and the
// variant switches (see vtkTransmittanceShaderSource.h).
//TYNDALL::Constants

// The medium: scalars in a 3-D texture, transfer functions in a 2-D table
// (vtkTyndallTransferTable: albedo row rgb = colour or albedo, a =
// extinction per unit length before the density scale; emission row rgb =
// emission colour, a = the scalar opacity function, which the projection
// blend modes read; gradient row r = a plain property's gradient opacity).
uniform sampler3D volumeTexture;
// The scalars from the volume texture's texels: value = texel * x + y (the
// data's own 8- or 16-bit integers read normalized; floats: (1, 0)).
uniform vec2 volumeValueMap;
#if TYNDALL_PARTICLE_COLORS
// A coloured particle cloud: density x albedo per node, beside the density.
uniform sampler3D scatteringTexture;
#endif
#if TYNDALL_MISSING_DATA
// NaN voxels (missing data): 0 there, 1 elsewhere; a sample whose filtered
// validity is below 1 is empty.
uniform sampler3D validityTexture;
#endif
uniform sampler2D transferTexture;
uniform vec3 volumeTexScale; // box [0,1]^3 -> texture coordinates
uniform vec3 volumeTexShift;
uniform vec2 scalarToTable; // table coordinate = value * x + y
uniform float densityScale;
uniform mat4 worldToVolume; // world -> the medium's box as [0,1]^3

// The volume's textures (the scalars and those at their resolution:
// validity, labels, emission) are read at the volume texture coordinate t
// (texel i's centre at (i + 0.5) / n). A volume deeper than the GPU's 3-D
// texture size is stored as tiles of slices side by side
// (vtkTransmittanceVolumeTiling, whose MapCoordinate() is this function's
// CPU twin): `tiling` = (tiles across x, S: slices from one tile to the
// next, tiles), `dims` the volume's samples, `textureDims` the texture's.
// Clamping the sample coordinate to the samples is clamp-to-edge, and
// keeps each tile's filtering off its neighbours.
vec3 tyndallTiledTexel(vec3 t, vec3 dims, vec3 tiling, vec3 textureDims)
{
  vec3 v = clamp(t * dims - 0.5, vec3(0.0), dims - 1.0);
  float k = min(floor(v.z / tiling.y), tiling.z - 1.0);
  float row = floor(k / tiling.x);
  vec2 origin = vec2(k - row * tiling.x, row) * dims.xy;
  return (vec3(origin + v.xy, v.z - k * tiling.y) + 0.5) / textureDims;
}

#if TYNDALL_VOLUME_BRICKED
// A volume stored as the bricks that vary (vtkTransmittanceVolumeBricks,
// whose MapCoordinate() is this function's CPU twin): the sample coordinate
// v = t dims - 0.5 clamped to the samples (clamp-to-edge), its brick b
// (TYNDALL_BRICK_SIZE samples a side; the last holds the volume's end), the
// brick's slot in the atlas from the indirection texture (8-bit RGB, one texel
// per brick), and the texel v - b TYNDALL_BRICK_SIZE in the slot, whose
// TYNDALL_BRICK_SIZE + 1 texels a side hold every sample its filtering reads.
vec3 tyndallBrickedTexel(sampler3D bricks, vec3 t, vec3 dims, vec3 counts, vec3 atlasDims)
{
  float size = float(TYNDALL_BRICK_SIZE);
  vec3 v = clamp(t * dims - 0.5, vec3(0.0), dims - 1.0);
  vec3 b = min(floor(v / size), counts - 1.0);
  vec3 slot = floor(texelFetch(bricks, ivec3(b), 0).xyz * 255.0 + 0.5); // RGB8
  return (slot * (size + 1.0) + (v - b * size) + 0.5) / atlasDims;
}
uniform sampler3D brickTexture; // the indirection (the volume itself when not bricked)
uniform int volumeBricked;      // 0: this volume is dense (a guest's are bricked)
uniform vec3 brickCounts;
uniform vec3 brickAtlasDims;
#endif

#if TYNDALL_VOLUME_TILED || TYNDALL_VOLUME_BRICKED
uniform vec3 volumeDims;
#endif
#if TYNDALL_VOLUME_TILED
uniform vec3 volumeTiling;
uniform vec3 volumeTextureDims;
#endif
vec3 tyndallVolumeTexel(vec3 t)
{
  // (One tile, not bricked: the texture is the volume, clamp-to-edge.)
#if TYNDALL_VOLUME_TILED
  t = tyndallTiledTexel(t, volumeDims, volumeTiling, volumeTextureDims);
#endif
#if TYNDALL_VOLUME_BRICKED
  if (volumeBricked > 0)
  {
    t = tyndallBrickedTexel(brickTexture, t, volumeDims, brickCounts, brickAtlasDims);
  }
#endif
  return t;
}
// One sample's step in volume texture coordinates.
vec3 tyndallVolumeTexelSize()
{
#if TYNDALL_VOLUME_TILED || TYNDALL_VOLUME_BRICKED
  return 1.0 / volumeDims;
#else
  return 1.0 / vec3(textureSize(volumeTexture, 0));
#endif
}

// The scalars' texels at the volume texture coordinate t.
vec4 tyndallVolumeAt(vec3 t)
{
  return texture(volumeTexture, tyndallVolumeTexel(t));
}
#if TYNDALL_MISSING_DATA
float tyndallValidityAt(vec3 t)
{
  return texture(validityTexture, tyndallVolumeTexel(t)).r;
}
#endif
// World -> the camera rays' box as [0,1]^3: the medium's, or the box around
// it and the guests drawn with it (TYNDALL_CAMERA_GUESTS).
uniform mat4 worldToCameraBox;

//TYNDALL::LightMaps

// Ray (world) against the camera rays' box (see tyndallIntersectBox()).
vec2 tyndallIntersectCameraBox(vec3 origin, vec3 dir)
{
  return tyndallIntersectBox(worldToCameraBox, origin, dir);
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

// The world width of a pixel at the camera sample being taken, which
// procedural detail is filtered by (the ray-cast pass sets it around its
// samples of the medium); 0 for every other sample (light rays, maps).
float tyndallFootprint = 0.0;

// The medium's own functions, from its adapter (vtkTransmittanceMediumAdapter):
// procedural detail brings vtkTransmittanceDetailFS.glsl (TYNDALL_DETAIL_GROUPS > 0).
//TYNDALL::Medium

#if TYNDALL_SHADING || TYNDALL_GRADIENT_OPACITY || TYNDALL_TRANSFER_2D
// Every channel's change across one texel each way along each texture
// axis at the texture coordinate t, F(t + d_i) - F(t - d_i) (d_i one
// texel): dx, dy, dz; 0 where a difference meets missing data.
void tyndallChannelDifferences(vec3 t, out vec3 d, out vec4 dx, out vec4 dy, out vec4 dz)
{
  d = tyndallVolumeTexelSize();
  dx = dy = dz = vec4(0.0);
#if TYNDALL_MISSING_DATA
  float valid = min(min(min(tyndallValidityAt(t + vec3(d.x, 0.0, 0.0)),
                              tyndallValidityAt(t - vec3(d.x, 0.0, 0.0))),
                          min(tyndallValidityAt(t + vec3(0.0, d.y, 0.0)),
                            tyndallValidityAt(t - vec3(0.0, d.y, 0.0)))),
    min(tyndallValidityAt(t + vec3(0.0, 0.0, d.z)),
      tyndallValidityAt(t - vec3(0.0, 0.0, d.z))));
  if (valid < 0.999)
  {
    return;
  }
#endif
  dx = (tyndallVolumeAt(t + vec3(d.x, 0.0, 0.0)) -
         tyndallVolumeAt(t - vec3(d.x, 0.0, 0.0))) * volumeValueMap.x;
  dy = (tyndallVolumeAt(t + vec3(0.0, d.y, 0.0)) -
         tyndallVolumeAt(t - vec3(0.0, d.y, 0.0))) * volumeValueMap.x;
  dz = (tyndallVolumeAt(t + vec3(0.0, 0.0, d.z)) -
         tyndallVolumeAt(t - vec3(0.0, 0.0, d.z))) * volumeValueMap.x;
}

// The first channel's (the scalar's) differences (tyndallChannelDifferences()).
// d value / d q (box coordinates q) is this times volumeTexScale / (2 d).
vec3 tyndallTexelDifferences(vec3 t, out vec3 d)
{
  vec4 dx, dy, dz;
  tyndallChannelDifferences(t, d, dx, dy, dz);
  return vec3(dx.r, dy.r, dz.r);
}
#endif

#if TYNDALL_SHADING
// The scalar's gradient at the world point x, per world unit in world axes
// (CPU twin: vtkTyndallGridMedium::FieldGradient()): central differences
// one texel apart along each texture axis, d/dx = (dq/dx)^T d/dq for the
// box coordinates q; 0 where a difference meets missing data.
vec3 tyndallScalarGradient(vec3 x)
{
  vec3 t = (worldToVolume * vec4(x, 1.0)).xyz * volumeTexScale + volumeTexShift;
  vec3 d;
  vec3 perBox = tyndallTexelDifferences(t, d) * volumeTexScale / (2.0 * d);
  return transpose(mat3(worldToVolume)) * perBox;
}
#endif

#if TYNDALL_COMPONENT_SHADING
// Each component's unit gradient at the world point x (columns; 0 where
// the gradient is 0 or meets missing data) and its length (per world
// unit): tyndallScalarGradient() of every channel (CPU twin:
// vtkTyndallGridMedium::FieldGradient() of a component).
mat4x3 tyndallComponentNormals(vec3 x, out vec4 magnitudes)
{
  vec3 t = (worldToVolume * vec4(x, 1.0)).xyz * volumeTexScale + volumeTexShift;
  vec3 d;
  vec4 dx, dy, dz;
  tyndallChannelDifferences(t, d, dx, dy, dz);
  mat3 toWorld = transpose(mat3(worldToVolume));
  vec3 perTexel = volumeTexScale / (2.0 * d);
  mat4x3 normals;
  for (int c = 0; c < 4; ++c)
  {
    vec3 g = toWorld * (vec3(dx[c], dy[c], dz[c]) * perTexel);
    magnitudes[c] = length(g);
    normals[c] = magnitudes[c] > 0.0 ? g / magnitudes[c] : vec3(0.0);
  }
  return normals;
}
#endif

#if TYNDALL_GRADIENT_OPACITY || TYNDALL_TRANSFER_2D
// The scalar's change per average voxel at the texture coordinate t,
// |d value / d q_i * gradientBoxToVoxel_i|, over GradientMaximum
// (gradientToTable: its inverse), clamped to 1: what a plain property's
// gradient opacity and 2-D transfer function read, as VTK 9.1 does (CPU
// twin: vtkTyndallGridMedium::GradientOpacityAt(), Transfer2DSample()).
uniform vec3 gradientBoxToVoxel;
uniform float gradientToTable;

float tyndallGradientMagnitude(vec3 t)
{
  vec3 d;
  vec3 perBox = tyndallTexelDifferences(t, d) * volumeTexScale / (2.0 * d);
  return min(length(perBox * gradientBoxToVoxel) * gradientToTable, 1.0);
}
#endif

#if TYNDALL_GRADIENT_OPACITY
// A plain property's gradient opacity at the texture coordinate t: the
// table's gradient row at tyndallGradientMagnitude().
float tyndallGradientOpacity(vec3 t)
{
  float coord = tyndallGradientMagnitude(t) * (float(TYNDALL_TABLE_SIZE) - 1.0) /
      float(TYNDALL_TABLE_SIZE) + 0.5 / float(TYNDALL_TABLE_SIZE);
  return texture(transferTexture, vec2(coord, TYNDALL_TABLE_GRADIENT_ROW)).r;
}
#endif

#if TYNDALL_TRANSFER_2D
// A plain property's 2-D transfer function (CPU twin:
// vtkTyndallGridMedium::Transfer2DSample()): RGBA at (the scalar on its
// range, tyndallGradientMagnitude()), its opacity per VTK's automatic step
// as an extinction (transfer2DExtinction: the density scale over the
// smallest spacing).
uniform sampler2D transfer2DTexture;
uniform vec2 transfer2DScalar; // u = value * x + y
uniform float transfer2DExtinction;

float tyndallTransfer2D(float value, vec3 t, out vec3 color)
{
  vec4 tf = texture(transfer2DTexture,
    vec2(value * transfer2DScalar.x + transfer2DScalar.y, tyndallGradientMagnitude(t)));
  color = tf.rgb;
  return -log(1.0 - min(tf.a, 0.999999)) * transfer2DExtinction;
}
#endif

#if TYNDALL_LABEL_MAP
// A label map (vtkTyndallLabelMap, whose Mix() is the CPU twin): the label
// of the sample's nearest sample (labelTexture, label / 255); label L > 0
// reads its row (at most labelRows) at the entry the scalar falls in
// (labelRowsTexture, nearest), and the colour and opacity mix with the
// volume's by the blend factor, the volume's opacity and the mix's at
// VTK's step labelStep.
uniform sampler3D labelTexture;
uniform sampler2D labelRowsTexture;
uniform int labelRows;
uniform float labelBlend;
uniform float labelStep;
uniform vec2 labelScalar; // u = value * x + y

float tyndallLabelMix(vec3 texel, float value, float sigma, inout vec3 color)
{
  int label = int(texture(labelTexture, tyndallVolumeTexel(texel)).r * 255.0 + 0.5);
  if (label == 0)
  {
    return sigma;
  }
  float row = (float(min(label, labelRows)) + 0.5) / float(labelRows + 1);
  vec4 rgba = texture(labelRowsTexture, vec2(value * labelScalar.x + labelScalar.y, row));
  float own = densityScale > 0.0 ? 1.0 - exp(-sigma / densityScale * labelStep) : 0.0;
  float alpha = min(mix(own, rgba.a, labelBlend), 0.999999);
  color = mix(own > 0.0 ? color : vec3(0.0), rgba.rgb, labelBlend); // VTK's 0 where own is
  return densityScale * -log(1.0 - alpha) / labelStep;
}
#else
// No label map: the medium as it is.
float tyndallLabelMix(vec3 texel, float value, float sigma, inout vec3 color)
{
  return sigma;
}
#endif

#if TYNDALL_COMPONENTS > 1
// Several components (vtkTyndallComponents, whose Mix() is the CPU twin):
// each interpolated on its own (the volume texture's channels), table t
// read at its component's value (table 0: transferTexture; tables 1..: two
// rows each of componentTexture, tyndallComponentRow()), then mixed into one
// extinction and colour.
uniform vec4 componentToTable[2]; // table t's coordinate: value * [0][t] + [1][t]
uniform vec4 componentUnit[2];    // component c on its finite range: value * [0][c] + [1][c]
uniform vec4 componentWeights;
#if TYNDALL_COMPONENT_SHADING
// The last sample's parts and colours of independent components, for their
// shading (set by tyndallComponentMix()).
vec4 tyndallComponentParts = vec4(0.0);
mat4x3 tyndallComponentColors = mat4x3(0.0);
vec4 tyndallComponentSigma = vec4(0.0); // each component's extinction, the density applied
#endif
#if TYNDALL_COMPONENT_MODE != TYNDALL_COMPONENTS_RGBA
uniform sampler2D componentTexture;
#endif

// Row `row` of table t at its coordinate: 0 its (colour, extinction), 1
// its (emission, opacity function); componentTexture holds both rows of
// each table from 1 on.
vec4 tyndallComponentRow(int t, float coord, int row)
{
#if TYNDALL_COMPONENT_MODE != TYNDALL_COMPONENTS_RGBA
  if (t > 0)
  {
    int rows = 2 * (TYNDALL_COMPONENT_MODE == TYNDALL_COMPONENTS_LA ? 1 : TYNDALL_COMPONENTS - 1);
    return texture(componentTexture, vec2(coord, (float(2 * (t - 1) + row) + 0.5) / float(rows)));
  }
#endif
  return texture(transferTexture,
    vec2(coord, row == 0 ? TYNDALL_TABLE_ALBEDO_ROW : TYNDALL_TABLE_EMISSION_ROW));
}

// Table t's (colour, extinction) at its coordinate.
vec4 tyndallComponentTable(int t, float coord)
{
  return tyndallComponentRow(t, coord, 0);
}

// The extinction (table units), colour and table 0's coordinate of the
// components `v`.
float tyndallComponentMix(vec4 v, out vec3 color, out float tableCoord)
{
#if TYNDALL_COMPONENT_MODE == TYNDALL_COMPONENTS_LA
  // Colour from component 0 (table 0), opacity from component 1 (table 1).
  vec2 coords = v.xy * componentToTable[0].xy + componentToTable[1].xy;
  tableCoord = coords.x;
  color = tyndallComponentTable(0, coords.x).rgb;
  return tyndallComponentTable(1, coords.y).a;
#elif TYNDALL_COMPONENT_MODE == TYNDALL_COMPONENTS_RGBA
  // Colour: components 0..2 on their ranges; opacity from component 3 (table 0).
  tableCoord = v.w * componentToTable[0].x + componentToTable[1].x;
  color = clamp(v.rgb * componentUnit[0].rgb + componentUnit[1].rgb, 0.0, 1.0);
  return tyndallComponentTable(0, tableCoord).a;
#else
  // Independent: VTK's mixing (or, additive, extinctions that add).
  vec4 coords = v * componentToTable[0] + componentToTable[1];
  tableCoord = coords.x;
  float weighted = 0.0;
  float squares = 0.0;
  vec3 emission = vec3(0.0);
  for (int t = 0; t < TYNDALL_COMPONENTS; ++t)
  {
    vec4 tf = tyndallComponentTable(t, coords[t]);
    float w = componentWeights[t];
    if (w > 0.0)
    {
      weighted += w * tf.a;
      squares += tf.a * tf.a;
      emission += w * tf.a * tf.rgb;
    }
#if TYNDALL_COMPONENT_SHADING
    tyndallComponentParts[t] = w > 0.0 ? w * tf.a : 0.0;
    tyndallComponentColors[t] = tf.rgb;
    tyndallComponentSigma[t] = densityScale * tf.a;
#endif
  }
#if TYNDALL_COMPONENT_ADDITIVE
  float sigma = weighted;
#else
  float sigma = weighted > 0.0 ? squares / weighted : 0.0;
#endif
  color = sigma > 0.0 ? emission / sigma : vec3(0.0);
#if TYNDALL_COMPONENT_SHADING
  // What the shading of the components mixes (vtkTyndallComponents::Parts()).
  tyndallComponentParts = sigma > 0.0 ? tyndallComponentParts / sigma : vec4(0.0);
#endif
  return sigma;
#endif
}
#endif

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
  if (tyndallValidityAt(texel) < 0.999)
  {
    color = vec3(0.0);
    tableCoord = 0.0;
    return 0.0;
  }
#endif
#if TYNDALL_COMPONENTS > 1
  vec4 components = tyndallVolumeAt(texel) * volumeValueMap.x + volumeValueMap.y;
  return densityScale * tyndallComponentMix(components, color, tableCoord);
#endif
#if TYNDALL_DETAIL_UNIFORM_ALBEDO
  // Procedural detail of one colour that emits nothing from the table: the
  // shape is the extinction, and the scalar is not needed.
  color = detailAlbedo;
  tableCoord = 0.0;
  return tyndallDetailExtinction(q);
#endif
  float value = tyndallVolumeAt(texel).r * volumeValueMap.x + volumeValueMap.y;
  tableCoord = value * scalarToTable.x + scalarToTable.y;
  vec4 tf = texture(transferTexture, vec2(tableCoord, TYNDALL_TABLE_ALBEDO_ROW));
#if TYNDALL_PARTICLE_COLORS
  // A coloured particle cloud: the interpolated scattering density over the
  // interpolated density, the nodes' colours weighted by their extinctions.
  color = value > 0.0 ? clamp(texture(scatteringTexture, tyndallVolumeTexel(texel)).rgb / value, 0.0, 1.0) : vec3(1.0);
#else
  color = tf.rgb;
#endif
#if TYNDALL_DETAIL_GROUPS > 0
  return tyndallDetailExtinction(q);
#elif TYNDALL_TRANSFER_2D
  return tyndallTransfer2D(value, texel, color);
#else
  float sigma = densityScale * tf.a;
#if TYNDALL_GRADIENT_OPACITY
  sigma *= tyndallGradientOpacity(texel);
#endif
  return tyndallLabelMix(texel, value, sigma, color);
#endif
}

float tyndallExtinction(vec3 x)
{
  vec3 color;
  float tableCoord;
  return tyndallMedium(x, color, tableCoord);
}

// Whether the world point x, whose texture coordinate is `texel`, is kept
// for VTK's blend modes that read the scalars (the projections, the
// isosurfaces): false where x is clipped away or its data are missing (NaN).
bool tyndallKept(vec3 x, vec3 texel)
{
#if TYNDALL_CLIP
  if (tyndallClipped(x))
  {
    return false;
  }
#endif
#if TYNDALL_MISSING_DATA
  if (tyndallValidityAt(texel) < 0.999)
  {
    return false;
  }
#endif
  return true;
}

// The scalar there, where tyndallKept().
bool tyndallKeptScalar(vec3 x, vec3 texel, out float value)
{
  value = 0.0;
  if (!tyndallKept(x, texel))
  {
    return false;
  }
  value = tyndallVolumeAt(texel).r * volumeValueMap.x + volumeValueMap.y;
  return true;
}

#if TYNDALL_COMPONENTS > 1
// Every component there, where tyndallKept() (each interpolated on its own).
bool tyndallKeptComponents(vec3 x, vec3 texel, out vec4 values)
{
  values = vec4(0.0);
  if (!tyndallKept(x, texel))
  {
    return false;
  }
  values = tyndallVolumeAt(texel) * volumeValueMap.x + volumeValueMap.y;
  return true;
}
#endif

// The opacity function at a scalar value, as VTK reads it (not corrected
// for a step: the table's emission row holds it in a).
float tyndallOpacityFunction(float value)
{
  return texture(transferTexture, vec2(value * scalarToTable.x + scalarToTable.y,
                                    TYNDALL_TABLE_EMISSION_ROW)).a;
}

#if TYNDALL_ISOSURFACES
// VTK's isosurface blend mode (vtkTyndallIsosurfaces, whose Composite() and
// OpticalDepth() are the CPU twins): the scalar at a step's two ends; the
// step crosses iso value s when exactly one end lies below s.
uniform float isoValues[TYNDALL_ISO_COUNT > 0 ? TYNDALL_ISO_COUNT : 1]; // ascending

// The scalar at x for a step's end: false where x lies outside the box
// (beyond a thousandth of it), is clipped away or its data are missing.
bool tyndallIsoValue(vec3 x, out float value)
{
  value = 0.0;
  vec3 q = (worldToVolume * vec4(x, 1.0)).xyz;
  if (any(lessThan(q, vec3(-1e-3))) || any(greaterThan(q, vec3(1.001))))
  {
    return false;
  }
  return tyndallKeptScalar(x, q * volumeTexScale + volumeTexShift, value);
}

// The surfaces a step from scalar v0 to v1 crosses, composited front to
// back in the order the ray meets them: premultiplied colour, opacity (the
// colour and opacity functions at each iso value; the opacity is the
// emission row's a); `first`: where the first of opacity above 0 lies in
// the step, 0..1.
vec4 tyndallIsoCrossings(float v0, float v1, out float first)
{
  vec4 sum = vec4(0.0);
  first = -1.0;
  for (int j = 0; j < TYNDALL_ISO_COUNT; ++j)
  {
    float s = isoValues[v1 >= v0 ? j : TYNDALL_ISO_COUNT - 1 - j];
    if ((v0 < s) != (v1 < s))
    {
      float a = tyndallOpacityFunction(s);
      first = first < 0.0 && a > 0.0 ? (s - v0) / (v1 - v0) : first;
      vec3 c = texture(transferTexture,
        vec2(s * scalarToTable.x + scalarToTable.y, TYNDALL_TABLE_ALBEDO_ROW)).rgb;
      sum += (1.0 - sum.a) * vec4(a * c, a);
    }
  }
  return sum;
}

// The extinction the light meets over the step of length dt centred at x
// along dir: each surface crossed, -ln(1 - a(s)), spread over the step. The
// step is cut to the volume's box first (a light's steps may straddle its
// faces; the CPU's march starts and ends on them).
float tyndallIsoExtinction(vec3 x, vec3 dir, float dt)
{
  vec3 xa = x - 0.5 * dt * dir;
  vec3 qa = (worldToVolume * vec4(xa, 1.0)).xyz;
  vec3 dq = (worldToVolume * vec4(dt * dir, 0.0)).xyz;
  float u0 = 0.0;
  float u1 = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    if (abs(dq[a]) < 1e-12)
    {
      if (qa[a] < 0.0 || qa[a] > 1.0)
      {
        return 0.0; // parallel to the faces, outside
      }
      continue;
    }
    float ta = -qa[a] / dq[a];
    float tb = (1.0 - qa[a]) / dq[a];
    u0 = max(u0, min(ta, tb));
    u1 = min(u1, max(ta, tb));
  }
  float v0, v1;
  if (!(u0 < u1) || !tyndallIsoValue(xa + u0 * dt * dir, v0) ||
    !tyndallIsoValue(xa + u1 * dt * dir, v1))
  {
    return 0.0;
  }
  float tau = 0.0;
  for (int j = 0; j < TYNDALL_ISO_COUNT; ++j)
  {
    float s = isoValues[j];
    if ((v0 < s) != (v1 < s))
    {
      tau -= log(1.0 - min(tyndallOpacityFunction(s), TYNDALL_ISO_MAX_OPACITY));
    }
  }
  return tau / dt;
}
#endif

#if TYNDALL_GUESTS > 0
// Guests (vtkTyndallSceneReader::GetGuests()): the other media the light
// crosses. Each has its scalars and table (its own mapper's textures), its
// world -> box matrix, box -> texture coordinates, texel -> table
// coordinate (its volume's value map folded in: a coloured particle
// cloud's texels are its float densities) and density scale; it is empty
// outside its box.
uniform sampler3D guestVolume[TYNDALL_GUESTS];
uniform sampler2D guestTransfer[TYNDALL_GUESTS];
uniform mat4 guestWorldToBox[TYNDALL_GUESTS];
uniform vec3 guestTexScale[TYNDALL_GUESTS];
uniform vec3 guestTexShift[TYNDALL_GUESTS];
uniform vec2 guestScalarToTable[TYNDALL_GUESTS];
uniform float guestDensity[TYNDALL_GUESTS];
#if TYNDALL_VOLUME_TILED || TYNDALL_VOLUME_BRICKED
uniform vec3 guestDims[TYNDALL_GUESTS];
#endif
#if TYNDALL_VOLUME_TILED
// Each guest's tiles (tyndallTiledTexel(); one tile when its volume fits).
uniform vec3 guestTiling[TYNDALL_GUESTS];
uniform vec3 guestTextureDims[TYNDALL_GUESTS];
#endif
#if TYNDALL_VOLUME_BRICKED
// Each guest's bricks (tyndallBrickedTexel(); guestBricked 0 for a dense one).
uniform sampler3D guestBricks[TYNDALL_GUESTS];
uniform int guestBricked[TYNDALL_GUESTS];
uniform vec3 guestBrickCounts[TYNDALL_GUESTS];
uniform vec3 guestAtlasDims[TYNDALL_GUESTS];
// The guest's indirection as a function's argument (samplers are indexed by
// constants only), and the parameter that takes it.
#define TYNDALL_GUEST_BRICKS(g) guestBricks[g],
#define TYNDALL_GUEST_BRICKS_PARAMETER sampler3D bricks,
#define TYNDALL_GUEST_BRICKS_ARGUMENT bricks,
#else
#define TYNDALL_GUEST_BRICKS(g)
#define TYNDALL_GUEST_BRICKS_PARAMETER
#define TYNDALL_GUEST_BRICKS_ARGUMENT
#endif

// Guest g's texture coordinate of its box coordinate q.
vec3 tyndallGuestTexel(TYNDALL_GUEST_BRICKS_PARAMETER int g, vec3 q)
{
  vec3 t = q * guestTexScale[g] + guestTexShift[g];
#if TYNDALL_VOLUME_TILED
  t = tyndallTiledTexel(t, guestDims[g], guestTiling[g], guestTextureDims[g]);
#endif
#if TYNDALL_VOLUME_BRICKED
  if (guestBricked[g] > 0)
  {
    t = tyndallBrickedTexel(bricks, t, guestDims[g], guestBrickCounts[g], guestAtlasDims[g]);
  }
#endif
  return t;
}

float tyndallGuestExtinction(sampler3D volume, TYNDALL_GUEST_BRICKS_PARAMETER sampler2D table, int g, vec3 x)
{
  vec3 q = (guestWorldToBox[g] * vec4(x, 1.0)).xyz;
  if (any(lessThan(q, vec3(0.0))) || any(greaterThan(q, vec3(1.0))))
  {
    return 0.0;
  }
  float value = texture(volume, tyndallGuestTexel(TYNDALL_GUEST_BRICKS_ARGUMENT g, q)).r;
  vec2 toTable = guestScalarToTable[g];
  return guestDensity[g] *
    texture(table, vec2(value * toTable.x + toTable.y, TYNDALL_TABLE_ALBEDO_ROW)).a;
}

// Samplers are indexed by constants only (GLSL 1.50): one term per guest.
#define TYNDALL_GUEST_EXTINCTION(g) +tyndallGuestExtinction(guestVolume[g], TYNDALL_GUEST_BRICKS(g) guestTransfer[g], g, x)
#endif

// The extinction the light sees at the world point x, the middle of a step
// of length dt along dir: the medium's (empty outside its box; with
// isosurfaces, theirs over the step) and, with guests, theirs. The map
// build and the brute-force light march integrate it.
float tyndallSceneExtinction(vec3 x, vec3 dir, float dt)
{
#if TYNDALL_ISOSURFACES
  return tyndallIsoExtinction(x, dir, dt)TYNDALL_FOR_GUESTS(TYNDALL_GUEST_EXTINCTION);
#elif TYNDALL_GUESTS > 0 || TYNDALL_MAP_BEYOND_MEDIUM
  vec3 q = (worldToVolume * vec4(x, 1.0)).xyz;
  bool inside = all(greaterThanEqual(q, vec3(0.0))) && all(lessThanEqual(q, vec3(1.0)));
  return (inside ? tyndallExtinction(x) : 0.0)TYNDALL_FOR_GUESTS(TYNDALL_GUEST_EXTINCTION);
#else
  return tyndallExtinction(x);
#endif
}

vec3 tyndallEmissionColor(float tableCoord)
{
  return texture(transferTexture, vec2(tableCoord, TYNDALL_TABLE_EMISSION_ROW)).rgb;
}

#if TYNDALL_LIGHT_CACHE
// The transmittance cache (vtkTransmittanceLightCachePass): light l's map
// transmittance at the texels of a lattice over the camera rays' box,
// texel centres on the box's faces (box coordinate i / (n - 1)); the
// lights' lattices are stacked along the third axis, lightCacheSize.z
// slices each.
uniform sampler3D lightCacheTexture;
uniform vec3 lightCacheSize; // texels per axis of one light's lattice
uniform int lightCacheLights;

TyndallTransmittance tyndallCachedTransmittance(int l, vec3 x)
{
  vec3 q = clamp((worldToCameraBox * vec4(x, 1.0)).xyz, 0.0, 1.0);
  vec3 texel = q * (lightCacheSize - 1.0) + 0.5; // within [0.5, size - 0.5]: no bleeding
  texel.z += float(l) * lightCacheSize.z;
  vec4 T = texture(
    lightCacheTexture, texel / vec3(lightCacheSize.xy, lightCacheSize.z * float(lightCacheLights)));
#if TYNDALL_CHROMATIC
  return T.rgb; // per channel
#else
  return T.r;
#endif
}
#endif

// Henyey-Greenstein, normalised to 1/(4 pi) over the sphere.
float tyndallPhaseHG(float g, float mu)
{
  float denom = 1.0 + g * g - 2.0 * g * mu;
  return (1.0 - g * g) / (4.0 * TYNDALL_PI * denom * sqrt(denom));
}
