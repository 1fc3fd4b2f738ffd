#include "vtkTransmittanceDetailAdapter.h"

#include "vtkMath.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallGridMedium.h"

// The GLSL of procedural detail, embedded at build time.
#include "vtkTransmittanceDetailFS.h"

#include <cmath>
#include <vector>

namespace
{
// For() gives this adapter detail media only, and only enabled ones have a grid.
const vtkTyndallDetailMedium& Detail(const vtkTyndallMedium& medium)
{
  return static_cast<const vtkTyndallDetailMedium&>(medium);
}
}

//------------------------------------------------------------------------------
const vtkTransmittanceMediumAdapter& vtkTransmittanceDetailAdapter::GridAdapter(
  const vtkTyndallDetailMedium& detail) const
{
  return this->GridLookup(*detail.GetGrid());
}

//------------------------------------------------------------------------------
const vtkTyndallGridMedium& vtkTransmittanceDetailAdapter::GetGrid(
  const vtkTyndallMedium& medium) const
{
  return *Detail(medium).GetGrid();
}

//------------------------------------------------------------------------------
vtkTransmittanceMediumTextures::Extras vtkTransmittanceDetailAdapter::GetExtras(
  const vtkTyndallMedium& medium) const
{
  const vtkTyndallDetailMedium& detail = Detail(medium);
  vtkTransmittanceMediumTextures::Extras extras =
    this->GridAdapter(detail).GetExtras(*detail.GetGrid());
  extras.Detail = &detail;
  return extras;
}

//------------------------------------------------------------------------------
void vtkTransmittanceDetailAdapter::DeclareSwitches(const vtkTyndallMedium& medium,
  const vtkTransmittanceMediumTextures& textures, Variant& variant) const
{
  const vtkTyndallDetailMedium& detail = Detail(medium);
  this->GridAdapter(detail).DeclareSwitches(*detail.GetGrid(), textures, variant);
  variant.DetailGroups = static_cast<int>((detail.GetWaves().size() + 3) / 4);
  if (variant.DetailGroups > 0)
  {
    // Its uniform arrays have one entry per group: none without waves.
    variant.MediumCode = vtkTransmittanceDetailFS;
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceDetailAdapter::DeclareColorSwitches(
  const vtkTyndallMedium& medium, Variant& variant) const
{
  const vtkTyndallDetailMedium& detail = Detail(medium);
  this->GridAdapter(detail).DeclareColorSwitches(*detail.GetGrid(), variant);
}

//------------------------------------------------------------------------------
void vtkTransmittanceDetailAdapter::SetUniforms(vtkShaderProgram* program,
  const vtkTyndallMedium& medium, const vtkTransmittanceMediumTextures& textures) const
{
  const vtkTyndallDetailMedium& detail = Detail(medium);
  const vtkTyndallGridMedium& grid = *detail.GetGrid();
  this->GridAdapter(detail).SetUniforms(program, grid, textures);
  // The waves, in groups of four (the unused ones of the last group 0).
  const std::vector<vtkTyndallDetailMedium::Wave>& waves = detail.GetWaves();
  const int groups = static_cast<int>((waves.size() + 3) / 4);
  std::vector<float> kx(4 * groups, 0.0f), ky(kx), kz(kx), phase(kx), amplitude(kx);
  for (size_t i = 0; i < waves.size(); ++i)
  {
    kx[i] = static_cast<float>(waves[i].K[0]);
    ky[i] = static_cast<float>(waves[i].K[1]);
    kz[i] = static_cast<float>(waves[i].K[2]);
    phase[i] = static_cast<float>(std::remainder(waves[i].Phase, 2.0 * vtkMath::Pi()));
    amplitude[i] = static_cast<float>(waves[i].Amplitude);
  }
  program->SetUniform4fv("detailKx", groups, reinterpret_cast<float(*)[4]>(kx.data()));
  program->SetUniform4fv("detailKy", groups, reinterpret_cast<float(*)[4]>(ky.data()));
  program->SetUniform4fv("detailKz", groups, reinterpret_cast<float(*)[4]>(kz.data()));
  program->SetUniform4fv("detailPhase", groups, reinterpret_cast<float(*)[4]>(phase.data()));
  program->SetUniform4fv(
    "detailAmplitude", groups, reinterpret_cast<float(*)[4]>(amplitude.data()));
  // The shape's samples over the grid's box.
  const int* n = detail.GetDimensions();
  const float dims[3] = { float(n[0]), float(n[1]), float(n[2]) };
  float low[3], size[3];
  for (int a = 0; a < 3; ++a)
  {
    low[a] = static_cast<float>(grid.GetBoxLow()[a]);
    size[a] = static_cast<float>(grid.GetBoxHigh()[a] - grid.GetBoxLow()[a]);
  }
  program->SetUniformi("detailShapeTexture", textures.GetDetailTexture()->GetTextureUnit());
  program->SetUniform3f("detailDims", dims);
  program->SetUniform3f("detailBoxLow", low);
  program->SetUniform3f("detailBoxSize", size);
  program->SetUniformi("detailMaxCells", n[0] + n[1] + n[2] + 3);
  program->SetUniformf("detailOffset", static_cast<float>(detail.GetOffset()));
  program->SetUniformf("detailScale", static_cast<float>(detail.GetScale()));
}

//------------------------------------------------------------------------------
double vtkTransmittanceDetailAdapter::GetLightMarchIterations(
  const vtkTyndallMedium& medium, double) const
{
  const int* n = Detail(medium).GetDimensions();
  return n[0] + n[1] + n[2] + 3.0;
}
