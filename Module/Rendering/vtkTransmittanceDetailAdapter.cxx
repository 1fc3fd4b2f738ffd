#include "vtkTransmittanceDetailAdapter.h"

#include "vtkMath.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallTransferTable.h"

// The GLSL of procedural detail, embedded at build time.
#include "vtkTransmittanceDetailFS.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// Whether the colour table's albedo is one colour (every entry the first).
bool UniformAlbedo(const vtkTyndallGridMedium& grid)
{
  const std::vector<double>& albedo = grid.GetTable().Albedo;
  for (size_t i = 3; i < albedo.size(); ++i)
  {
    if (albedo[i] != albedo[i % 3])
    {
      return false;
    }
  }
  return true;
}

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
  variant.DetailCameraGroups = -1; // all
  variant.DetailFilter = false;
  // The passes that read no colour take it too; the camera's decide in
  // DeclareColorSwitches().
  variant.DetailUniformAlbedo = UniformAlbedo(*detail.GetGrid());
  if (variant.DetailGroups > 0)
  {
    // Its arrays have one entry per group: none without waves.
    variant.MediumCode = vtkTransmittanceDetailFS;
    variant.DetailWaves = WaveConstants(detail);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceDetailAdapter::DeclareCameraSwitches(
  const vtkTyndallMedium& medium, double nearestPixel, Variant& variant) const
{
  const vtkTyndallDetailMedium& detail = Detail(medium);
  // The footprint filter on marched camera rays (the sampled ones follow the
  // unfiltered closed form).
  if (variant.DetailGroups == 0 || variant.DetailSamples > 0 || !(detail.GetFilterWidth() > 0.0))
  {
    return;
  }
  variant.DetailFilter = true;
  // A brute-force light march through guests samples the same function
  // with a footprint of 0 (every wave, unfiltered): it keeps them all.
  const bool lightMarches = variant.BruteForceLights && variant.Guests > 0;
  if (!lightMarches)
  {
    variant.DetailCameraGroups = (detail.GetLiveWaves(nearestPixel) + 3) / 4;
  }
}

//------------------------------------------------------------------------------
std::string vtkTransmittanceDetailAdapter::WaveConstants(const vtkTyndallDetailMedium& detail)
{
  // Per group of four: the wave vectors (field index), phases and
  // amplitudes; per group the filter's steps of level and its decay,
  // exp2(decay pixel^2) = exp(-|k|^2 (width pixel)^2 / 2) with the |k|^2 of
  // its level (FilterK2).
  const std::vector<vtkTyndallDetailMedium::Wave>& waves = detail.GetWaves();
  const int groups = static_cast<int>((waves.size() + 3) / 4);
  const char* names[5] = { "detailKx", "detailKy", "detailKz", "detailPhase", "detailAmplitude" };
  std::ostringstream os;
  os << std::scientific << std::setprecision(9);
  for (int a = 0; a < 5; ++a)
  {
    os << "const vec4 " << names[a] << "[TYNDALL_DETAIL_GROUPS] = vec4[TYNDALL_DETAIL_GROUPS](";
    for (int g = 0; g < groups; ++g)
    {
      os << (g > 0 ? ",\n  " : "\n  ") << "vec4(";
      for (int c = 0; c < 4; ++c)
      {
        const size_t i = 4 * static_cast<size_t>(g) + c;
        double value = 0.0; // the unused waves of the last group: amplitude 0
        if (i < waves.size())
        {
          const vtkTyndallDetailMedium::Wave& w = waves[i];
          const double values[5] = { w.K[0], w.K[1], w.K[2],
            std::remainder(w.Phase, 2.0 * vtkMath::Pi()), w.Amplitude };
          value = values[a];
        }
        os << (c > 0 ? ", " : "") << static_cast<float>(value);
      }
      os << ")";
    }
    os << ");\n";
  }
  // Per group: the levels of the filter climbed from the group before, or
  // MaximumLevelSteps + 1 where it takes its own exponential (LevelSteps()).
  const std::vector<int> steps = LevelSteps(detail);
  os << "#define TYNDALL_DETAIL_MAX_LEVEL_STEPS " << MaximumLevelSteps << "\n";
  os << "const int detailLevelSteps[TYNDALL_DETAIL_GROUPS] = int[TYNDALL_DETAIL_GROUPS](";
  for (int g = 0; g < groups; ++g)
  {
    os << (g > 0 ? ", " : "") << steps[static_cast<size_t>(g)];
  }
  os << ");\n";
  os << "const float detailDecay[TYNDALL_DETAIL_GROUPS] = float[TYNDALL_DETAIL_GROUPS](";
  for (int g = 0; g < groups; ++g)
  {
    os << (g > 0 ? ", " : "") << FilterDecay(detail, g);
  }
  os << ");\n";
  return os.str();
}

//------------------------------------------------------------------------------
float vtkTransmittanceDetailAdapter::FilterDecay(const vtkTyndallDetailMedium& detail, int group)
{
  const double k2 = detail.GetWaves().at(4 * static_cast<size_t>(group)).FilterK2;
  const double width = detail.GetFilterWidth();
  return static_cast<float>(-0.5 * k2 * width * width / std::log(2.0));
}

//------------------------------------------------------------------------------
std::vector<int> vtkTransmittanceDetailAdapter::LevelSteps(const vtkTyndallDetailMedium& detail)
{
  const std::vector<vtkTyndallDetailMedium::Wave>& waves = detail.GetWaves();
  std::vector<int> steps;
  int chained = 0; // levels climbed since the last exponential
  for (size_t i = 0; i < waves.size(); i += 4)
  {
    const int level = waves[i].FilterLevel;
    const int before = i > 0 ? waves[i - 4].FilterLevel : -1;
    const int climb = level - before;
    if (i == 0 || before < 0 || level < 0 || climb > MaximumLevelSteps ||
      chained + climb > MaximumChainedLevels)
    {
      steps.push_back(MaximumLevelSteps + 1);
      chained = 0;
    }
    else
    {
      steps.push_back(climb);
      chained += climb;
    }
  }
  return steps;
}

//------------------------------------------------------------------------------
void vtkTransmittanceDetailAdapter::DeclareColorSwitches(
  const vtkTyndallMedium& medium, Variant& variant) const
{
  const vtkTyndallDetailMedium& detail = Detail(medium);
  this->GridAdapter(detail).DeclareColorSwitches(*detail.GetGrid(), variant);
  // Emission from the table and a coloured particle cloud's albedo need the
  // scalar at the sample.
  variant.DetailUniformAlbedo =
    variant.DetailUniformAlbedo && !variant.Emission && !variant.ParticleColors;
}

//------------------------------------------------------------------------------
void vtkTransmittanceDetailAdapter::SetUniforms(vtkShaderProgram* program,
  const vtkTyndallMedium& medium, const vtkTransmittanceMediumTextures& textures) const
{
  const vtkTyndallDetailMedium& detail = Detail(medium);
  const vtkTyndallGridMedium& grid = *detail.GetGrid();
  this->GridAdapter(detail).SetUniforms(program, grid, textures);
  // The waves are the program's constants (WaveConstants()).
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
  const std::vector<double>& albedo = grid.GetTable().Albedo;
  if (albedo.size() >= 3)
  {
    // Declared only by the uniform-albedo variant.
    const float rgb[3] = { float(albedo[0]), float(albedo[1]), float(albedo[2]) };
    program->SetUniform3f("detailAlbedo", rgb);
  }
}

//------------------------------------------------------------------------------
double vtkTransmittanceDetailAdapter::GetLightMarchIterations(
  const vtkTyndallMedium& medium, double) const
{
  const int* n = Detail(medium).GetDimensions();
  return n[0] + n[1] + n[2] + 3.0;
}
