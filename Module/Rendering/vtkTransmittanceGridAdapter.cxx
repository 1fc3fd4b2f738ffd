#include "vtkTransmittanceGridAdapter.h"

#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTyndallComponents.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallTransferTable.h"

//------------------------------------------------------------------------------
const vtkTyndallGridMedium& vtkTransmittanceGridAdapter::GetGrid(
  const vtkTyndallMedium& medium) const
{
  // For() gives this adapter grid media only.
  return static_cast<const vtkTyndallGridMedium&>(medium);
}

//------------------------------------------------------------------------------
vtkTransmittanceMediumTextures::Extras vtkTransmittanceGridAdapter::GetExtras(
  const vtkTyndallMedium&) const
{
  return {};
}

//------------------------------------------------------------------------------
void vtkTransmittanceGridAdapter::DeclareSwitches(const vtkTyndallMedium& medium,
  const vtkTransmittanceMediumTextures& textures, Variant& variant) const
{
  const vtkTyndallGridMedium& grid = this->GetGrid(medium);
  variant.MissingData = textures.GetValidityTexture() != nullptr;
  variant.VolumeTiled = textures.GetTiling().IsTiled();
  variant.VolumeBricked = textures.GetBricks().IsBricked();
  variant.Clip = grid.GetClip() != nullptr;
  variant.Chromatic = grid.GetParameters().GetChromatic();
  variant.GradientOpacity = grid.GetGradientOpacity();
  variant.Transfer2D = textures.GetTransfer2DTexture() != nullptr;
  variant.LabelMap = textures.GetLabelTexture() != nullptr &&
    textures.GetLabelRowsTexture() != nullptr && grid.GetLabelMap().Enabled();
  variant.Isosurfaces = grid.GetIsosurfaces().Enabled();
  variant.IsoCount = static_cast<int>(grid.GetIsosurfaces().GetValues().size());
  const vtkTyndallComponents& components = grid.GetComponents();
  variant.Components = components.GetCount();
  variant.ComponentMode = static_cast<int>(components.GetMode());
  variant.ComponentAdditive = components.GetAdditive();
  // Emission from a separate array glows where the extinction is 0, and
  // isosurfaces lie where the table may be empty: no block is empty then.
  variant.SkipEmpty = variant.SkipEmpty && !grid.GetEmissionFromArray() && !variant.Isosurfaces;
}

//------------------------------------------------------------------------------
void vtkTransmittanceGridAdapter::DeclareColorSwitches(
  const vtkTyndallMedium& medium, Variant& variant) const
{
  const vtkTyndallGridMedium& grid = this->GetGrid(medium);
  const vtkTyndallMediumParameters& parameters = grid.GetParameters();
  const bool emits = parameters.HasEmission && parameters.EmissionScale > 0.0;
  variant.EmissionArray = emits && grid.GetArrayEmission();
  // Isosurfaces emit nothing (vtkTyndallGridMedium::IsoSample()), nor does
  // a 2-D transfer function (the emission colour is of the 1-D scalar:
  // vtkTyndallGridMedium::FieldSample()).
  variant.Emission =
    emits && !variant.EmissionArray && !grid.GetIsosurfaces().Enabled() && !grid.GetTable().Has2D();
}

//------------------------------------------------------------------------------
void vtkTransmittanceGridAdapter::SetUniforms(vtkShaderProgram* program,
  const vtkTyndallMedium& medium, const vtkTransmittanceMediumTextures& textures) const
{
  const vtkTyndallGridMedium& grid = this->GetGrid(medium);
  const vtkTyndallTransferTable& table = grid.GetTable();
  program->SetUniformi("volumeTexture", textures.GetVolumeTexture()->GetTextureUnit());
  program->SetUniform2f("volumeValueMap", textures.GetValueMap());
  // Read by the tiled variant only (this volume's tiles or a guest's).
  float tiling[3], dims[3], textureDims[3];
  textures.GetTiling().GetUniforms(tiling, dims, textureDims);
  program->SetUniform3f("volumeTiling", tiling);
  program->SetUniform3f("volumeDims", dims);
  program->SetUniform3f("volumeTextureDims", textureDims);
  // Read by the bricked variant only (this volume's bricks or a guest's):
  // without bricks the indirection is the volume (never read).
  vtkTextureObject* indirection = textures.GetBrickTexture();
  const bool bricked = textures.GetBricks().IsBricked() && indirection;
  float unused[3], brickCounts[3], atlasDims[3];
  textures.GetBricks().GetUniforms(unused, brickCounts, atlasDims);
  program->SetUniformi(
    "brickTexture", (bricked ? indirection : textures.GetVolumeTexture())->GetTextureUnit());
  program->SetUniformi("volumeBricked", bricked ? 1 : 0);
  program->SetUniform3f("brickCounts", brickCounts);
  program->SetUniform3f("brickAtlasDims", atlasDims);
  if (vtkTextureObject* validity = textures.GetValidityTexture())
  {
    // Declared only by the missing-data variant.
    program->SetUniformi("validityTexture", validity->GetTextureUnit());
  }
  if (vtkTextureObject* blocks = textures.GetBlockTexture())
  {
    // Declared only by the skipping variant.
    const int* counts = textures.GetMajorantGrid().GetBlockCounts();
    const float blockCount[3] = { float(counts[0]), float(counts[1]), float(counts[2]) };
    program->SetUniformi("blockTexture", blocks->GetTextureUnit());
    program->SetUniform3f("blockCount", blockCount);
    program->SetUniform3f("boxToBlockScale", textures.GetBlockScale());
    program->SetUniform3f("boxToBlockShift", textures.GetBlockShift());
  }
  program->SetUniformi("transferTexture", textures.GetTransferTexture()->GetTextureUnit());
  program->SetUniform3f("volumeTexScale", textures.GetTextureScale());
  program->SetUniform3f("volumeTexShift", textures.GetTextureShift());
  const float toTable[2] = { static_cast<float>(table.TextureScale()),
    static_cast<float>(table.TextureShift()) };
  program->SetUniform2f("scalarToTable", toTable);
  program->SetUniformf("densityScale", static_cast<float>(grid.GetParameters().DensityScale));
  if (vtkTextureObject* transfer2D = textures.GetTransfer2DTexture())
  {
    // Declared only by the 2-D transfer function's variant: the scalar on
    // the function's x axis (the finite range), the extinction of its opacity.
    program->SetUniformi("transfer2DTexture", transfer2D->GetTextureUnit());
    const float toUnit[2] = { static_cast<float>(table.UnitScale()),
      static_cast<float>(table.UnitShift()) };
    program->SetUniform2f("transfer2DScalar", toUnit);
    program->SetUniformf("transfer2DExtinction",
      static_cast<float>(grid.GetParameters().DensityScale / grid.GetMinimumWorldSpacing()));
  }
  if (grid.GetGradientOpacity() || textures.GetTransfer2DTexture())
  {
    // Declared only by the gradient-opacity and 2-D function variants: d value / d q_i ->
    // the change per average voxel (q spans the box, BoxHigh - BoxLow samples).
    float toVoxel[3];
    for (int a = 0; a < 3; ++a)
    {
      toVoxel[a] = static_cast<float>(
        grid.GetGradientToVoxel()[a] / (grid.GetBoxHigh()[a] - grid.GetBoxLow()[a]));
    }
    program->SetUniform3f("gradientBoxToVoxel", toVoxel);
    program->SetUniformf("gradientToTable", static_cast<float>(1.0 / table.GradientMaximum));
  }
  if (grid.GetComponents().Enabled())
  {
    this->SetComponentUniforms(program, grid, textures);
  }
  if (textures.GetLabelTexture() && textures.GetLabelRowsTexture())
  {
    // Declared only by the label map's variant.
    const vtkTyndallLabelMap& labels = grid.GetLabelMap();
    program->SetUniformi("labelTexture", textures.GetLabelTexture()->GetTextureUnit());
    program->SetUniformi("labelRowsTexture", textures.GetLabelRowsTexture()->GetTextureUnit());
    program->SetUniformi("labelRows", labels.GetRowCount());
    program->SetUniformf("labelBlend", static_cast<float>(labels.GetBlend()));
    program->SetUniformf("labelStep", static_cast<float>(labels.GetStep()));
    const float toUnit[2] = { static_cast<float>(table.UnitScale()),
      static_cast<float>(table.UnitShift()) };
    program->SetUniform2f("labelScalar", toUnit);
  }
  const std::vector<double>& isoValues = grid.GetIsosurfaces().GetValues();
  if (grid.GetIsosurfaces().Enabled() && !isoValues.empty())
  {
    // Declared only by the isosurface variant.
    const std::vector<float> values(isoValues.begin(), isoValues.end());
    program->SetUniform1fv("isoValues", static_cast<int>(values.size()), values.data());
  }
  if (vtkTextureObject* emission = textures.GetEmissionTexture())
  {
    // Declared only by the camera rays' emission-array variant.
    program->SetUniformi("emissionTexture", emission->GetTextureUnit());
    const float toEmission[2] = { static_cast<float>(table.EmissionTextureScale()),
      static_cast<float>(table.EmissionTextureShift()) };
    program->SetUniform2f("emissionToTable", toEmission);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceGridAdapter::SetComponentUniforms(vtkShaderProgram* program,
  const vtkTyndallGridMedium& grid, const vtkTransmittanceMediumTextures& textures) const
{
  // Declared only by the components' variant (tyndallComponentMedium()):
  // table t's coordinate at its component's value, each component on its
  // finite range, the weights.
  const vtkTyndallComponents& components = grid.GetComponents();
  float toTable[8] = { 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f };
  for (int t = 0; t < components.GetTableCount(); ++t)
  {
    const vtkTyndallTransferTable& table = grid.GetComponentTable(t);
    toTable[t] = static_cast<float>(table.TextureScale());
    toTable[4 + t] = static_cast<float>(table.TextureShift());
  }
  float toUnit[8] = { 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f };
  float weights[4];
  for (int c = 0; c < vtkTyndallComponents::MaximumCount; ++c)
  {
    const double* r = grid.GetComponentRange(c);
    const double scale = c < components.GetCount() && r[1] > r[0] ? 1.0 / (r[1] - r[0]) : 0.0;
    toUnit[c] = static_cast<float>(scale);
    toUnit[4 + c] = static_cast<float>(-r[0] * scale);
    weights[c] = static_cast<float>(components.GetWeights()[c]);
  }
  program->SetUniform4fv("componentToTable", 2, toTable);
  program->SetUniform4fv("componentUnit", 2, toUnit);
  program->SetUniform4f("componentWeights", weights);
  if (vtkTextureObject* tables = textures.GetComponentTexture())
  {
    program->SetUniformi("componentTexture", tables->GetTextureUnit());
  }
}
