#include "vtkTransmittanceShaderSource.h"

#include "vtkMath.h"
#include "vtkShaderProgram.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceVolumeBricks.h"
#include "vtkTyndallClipRegion.h"
#include "vtkTyndallComponents.h"
#include "vtkTyndallDenoiser.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallIsosurfaces.h"
#include "vtkTyndallProjection.h"
#include "vtkTyndallSceneReader.h"
#include "vtkTyndallToneMapping.h"
#include "vtkTyndallTransferTable.h"

// The GLSL sources, embedded at build time from glsl/*.glsl.
#include "vtkTransmittanceCameraRayFS.h"
#include "vtkTransmittanceCommonFS.h"
#include "vtkTransmittanceCompositeFS.h"
#include "vtkTransmittanceDenoiseFS.h"
#include "vtkTransmittanceEnvironmentFS.h"
#include "vtkTransmittanceLightCacheFS.h"
#include "vtkTransmittanceLightMapFS.h"
#include "vtkTransmittanceLightsFS.h"
#include "vtkTransmittanceMapBuildFS.h"
#include "vtkTransmittanceOcclusionFS.h"
#include "vtkTransmittanceOutputFS.h"
#include "vtkTransmittancePathTraceFS.h"
#include "vtkTransmittancePeelCompositeFS.h"
#include "vtkTransmittancePeelRangesFS.h"
#include "vtkTransmittanceProjectionFS.h"
#include "vtkTransmittanceRayCastFS.h"
#include "vtkTransmittanceRayCastMainFS.h"
#include "vtkTransmittanceSplatFS.h"
#include "vtkTransmittanceSplatVS.h"
#include "vtkTransmittanceSurfaceFS.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

//------------------------------------------------------------------------------
std::string vtkTransmittanceShaderSource::GetConstants(const Variant& variant)
{
  using M = vtkTransmittanceMapMath;
  std::ostringstream os;
  os << std::setprecision(15) << std::showpoint;
  auto define = [&os](const char* name, auto value)
  { os << "#define TYNDALL_" << name << " " << value << "\n"; };
  define("MAX_LIGHTS", vtkTyndallSceneReader::MaximumNumberOfLights);
  define("MAX_COEFFICIENTS", static_cast<int>(M::MAXIMUM_NUMBER_OF_COEFFICIENTS));
  define("COEFFICIENTS_PER_LAYER", static_cast<int>(M::COEFFICIENTS_PER_LAYER));
  define("NONE", static_cast<int>(M::NONE));
  define("BRUTE_FORCE", static_cast<int>(M::BRUTE_FORCE));
  define("TFM", static_cast<int>(M::TFM));
  define("ADAPTIVE_TFM", static_cast<int>(M::ADAPTIVE_TFM));
  define("ETM", static_cast<int>(M::ETM));
  define("ADAPTIVE_ETM", static_cast<int>(M::ADAPTIVE_ETM));
  // The texture coordinate of a table row's centre.
  using Table = vtkTyndallTransferTable;
  define("TABLE_ALBEDO_ROW", (Table::AlbedoRow + 0.5) / Table::Rows);
  define("TABLE_EMISSION_ROW", (Table::EmissionRow + 0.5) / Table::Rows);
  define("TABLE_GRADIENT_ROW", (Table::GradientRow + 0.5) / Table::Rows);
  define("TABLE_SIZE", Table::Size);
  define("NO_OCCLUDER", static_cast<double>(NoOccluder));
  define("VIEW_TERMINATION", static_cast<double>(ViewTermination));
  define("PI", vtkMath::Pi());
  define("MISSING_DATA", variant.MissingData ? 1 : 0);
  define("VOLUME_TILED", variant.VolumeTiled ? 1 : 0);
  define("VOLUME_BRICKED", variant.VolumeBricked ? 1 : 0);
  define("BRICK_SIZE", vtkTransmittanceVolumeBricks::BrickSize);
  define("SKIP_EMPTY", variant.SkipEmpty ? 1 : 0);
  define("CLIP", variant.Clip ? 1 : 0);
  define("MAX_CLIP_PLANES", vtkTyndallClipRegion::MaximumPlanes);
  define("MAP_COEFFICIENTS", variant.MapCoefficients);
  define("MAP_LAYERS",
    (variant.MapCoefficients + M::COEFFICIENTS_PER_LAYER - 1) / M::COEFFICIENTS_PER_LAYER);
  define("MAP_EXTINCTION", variant.MapExtinction ? 1 : 0);
  define("ADAPTIVE_MAPS", variant.AdaptiveMaps ? 1 : 0);
  define("OCCLUSION", variant.Occlusion ? 1 : 0);
  define("EMISSION", variant.Emission ? 1 : 0);
  define("EMISSION_ARRAY", variant.EmissionArray ? 1 : 0);
  define("PARTICLE_COLORS", variant.ParticleColors ? 1 : 0);
  define("ACCUMULATE", variant.Accumulate ? 1 : 0);
  define("DEPTH_RANGES", variant.DepthRanges ? 1 : 0);
  define("BRUTE_FORCE_LIGHTS", variant.BruteForceLights ? 1 : 0);
  define("LIGHT_CACHE", variant.LightCache ? 1 : 0);
  define("OCTAVES", variant.Octaves);
  define("CHROMATIC", variant.Chromatic ? 1 : 0);
  define("SHADING", variant.Shading ? 1 : 0);
  define("SHADING_ADDITIVE", variant.Shading && variant.ShadingAdditive ? 1 : 0);
  define("SCATTERING_BLEND", variant.Shading && variant.ScatteringBlend ? 1 : 0);
  define("GRADIENT_OPACITY", variant.GradientOpacity ? 1 : 0);
  define("TRANSFER_2D", variant.Transfer2D ? 1 : 0);
  define("LABEL_MAP", variant.LabelMap ? 1 : 0);
  define("COMPONENTS", variant.Components);
  define("COMPONENT_MODE", variant.ComponentMode);
  define("COMPONENT_ADDITIVE", variant.ComponentAdditive ? 1 : 0);
  // Independent components shaded each on its own (vtkTyndallShading).
  define("COMPONENT_SHADING",
    variant.Shading && !variant.ShadingAdditive && variant.Components > 1 &&
        variant.ComponentMode == static_cast<int>(vtkTyndallComponents::Independent)
      ? 1
      : 0);
  define("COMPONENTS_INDEPENDENT", static_cast<int>(vtkTyndallComponents::Independent));
  define("COMPONENTS_LA", static_cast<int>(vtkTyndallComponents::DependentLA));
  define("COMPONENTS_RGBA", static_cast<int>(vtkTyndallComponents::DependentRGBA));
  define("ISOSURFACES", variant.Isosurfaces ? 1 : 0);
  define("ISO_COUNT", variant.IsoCount);
  define("ISO_MAX_OPACITY", vtkTyndallIsosurfaces::MaximumOpacity);
  define("CHANNEL_MAPS", variant.Chromatic && variant.ChannelMaps ? 1 : 0);
  define("PATH_BLOCKS", variant.SkipEmpty && variant.PathBlocks ? 1 : 0);
  define("PATH_ENVIRONMENT", variant.PathEnvironment ? 1 : 0);
  define("PATH_CLOSED_FORM", variant.DetailGroups > 0 && variant.PathClosedForm ? 1 : 0);
  using P = vtkTyndallProjection;
  define("PROJECTION", variant.Projection);
  define("PROJECTION_MAXIMUM", static_cast<int>(P::MAXIMUM));
  define("PROJECTION_MINIMUM", static_cast<int>(P::MINIMUM));
  define("PROJECTION_AVERAGE", static_cast<int>(P::AVERAGE));
  define("PROJECTION_ADDITIVE", static_cast<int>(P::ADDITIVE));
  define("PROJECTION_SLICE", static_cast<int>(P::SLICE));
  // Procedural detail: wave groups, and the preprocessor loop over them.
  define("DETAIL_GROUPS", variant.DetailGroups);
  define("DETAIL_SAMPLES", variant.DetailGroups > 0 ? variant.DetailSamples : 0);
  define("DETAIL_SOLVE_ITERATIONS", DetailSolveIterations);
  define("DETAIL_FILTER", variant.DetailGroups > 0 && variant.DetailFilter ? 1 : 0);
  define("DETAIL_STEP_MEANS",
    variant.DetailGroups > 0 && variant.DetailFilter && variant.DetailStepMeans ? 1 : 0);
  define("DETAIL_CUTOFF", vtkTyndallDetailMedium::FilterCutoff);
  define("DETAIL_UNIFORM_ALBEDO", variant.DetailGroups > 0 && variant.DetailUniformAlbedo ? 1 : 0);
  const int cameraGroups = variant.DetailCameraGroups >= 0
    ? std::min(variant.DetailCameraGroups, variant.DetailGroups)
    : variant.DetailGroups;
  os << "#define TYNDALL_DETAIL_FOR_GROUPS(X)";
  for (int g = 0; g < variant.DetailGroups; ++g)
  {
    os << " X(" << g << ")";
  }
  os << "\n#define TYNDALL_DETAIL_FOR_CAMERA_GROUPS(X)";
  for (int g = 0; g < cameraGroups; ++g)
  {
    os << " X(" << g << ")";
  }
  os << "\n";
  if (variant.DetailGroups > 0)
  {
    os << variant.DetailWaves;
  }
  // Guests: the other media the light crosses, and the loop over them.
  define("GUESTS", variant.Guests);
  define("MAP_BEYOND_MEDIUM", variant.MapBeyondMedium ? 1 : 0);
  define("OPACITY_COVERS_RADIANCE", variant.OpacityCoversRadiance ? 1 : 0);
  define("CAMERA_GUESTS", variant.Guests > 0 && variant.CameraGuests ? 1 : 0);
  define("GUEST_COLORS", variant.Guests > 0 && variant.CameraGuests && variant.GuestColors ? 1 : 0);
  define("GUEST_EMISSION_ARRAY",
    variant.Guests > 0 && variant.CameraGuests && variant.GuestEmissionArrays ? 1 : 0);
  os << "#define TYNDALL_FOR_GUESTS(X)";
  for (int g = 0; g < variant.Guests; ++g)
  {
    os << " X(" << g << ")";
  }
  os << "\n";
  return os.str();
}

//------------------------------------------------------------------------------
std::string vtkTransmittanceShaderSource::GetPeelingConstants()
{
  std::ostringstream os;
  os << "#define TYNDALL_PEEL_INITIALIZING " << PeelInitializing << "\n"
     << "#define TYNDALL_PEEL_PEELING " << PeelPeeling << "\n"
     << "#define TYNDALL_PEEL_BLENDING " << PeelBlending << "\n";
  return os.str();
}

//------------------------------------------------------------------------------
std::string vtkTransmittanceShaderSource::GetDenoiseConstants()
{
  using D = vtkTyndallDenoiser;
  std::ostringstream os;
  os << std::setprecision(9) << std::showpoint << "#define TYNDALL_DENOISE_EPSILON " << D::Epsilon
     << "\n#define TYNDALL_DENOISE_KERNEL_0 " << D::KernelWeight(0)
     << "\n#define TYNDALL_DENOISE_KERNEL_1 " << D::KernelWeight(1)
     << "\n#define TYNDALL_DENOISE_KERNEL_2 " << D::KernelWeight(2) << "\n";
  return os.str();
}

//------------------------------------------------------------------------------
std::string vtkTransmittanceShaderSource::GetOutputSource()
{
  using T = vtkTyndallToneMapping;
  std::ostringstream os;
  os << "#define TYNDALL_TONE_LINEAR " << T::LINEAR << "\n"
     << "#define TYNDALL_TONE_REINHARD " << T::REINHARD << "\n"
     << "#define TYNDALL_TONE_ACES " << T::ACES << "\n"
     << std::setprecision(9) << std::showpoint << "#define TYNDALL_TONE_LARGEST " << T::Largest
     << "\n";
  return os.str() + vtkTransmittanceOutputFS;
}

//------------------------------------------------------------------------------
std::string vtkTransmittanceShaderSource::GetLightMapLookup(const Variant& variant)
{
  return GetConstants(variant) + vtkTransmittanceLightMapFS;
}

//------------------------------------------------------------------------------
std::string vtkTransmittanceShaderSource::GetSurfaceLookup(const Variant& variant)
{
  return GetLightMapLookup(variant) + vtkTransmittanceSurfaceFS;
}

//------------------------------------------------------------------------------
void vtkTransmittanceShaderSource::GetSplatShaders(
  const Variant& variant, std::string& vertex, std::string& fragment)
{
  const std::string lookup = GetLightMapLookup(variant);
  vertex = vtkTransmittanceSplatVS;
  fragment = vtkTransmittanceSplatFS;
  vtkShaderProgram::Substitute(vertex, "//TYNDALL::LightMaps", lookup);
  vtkShaderProgram::Substitute(fragment, "//TYNDALL::LightMaps", lookup);
}

//------------------------------------------------------------------------------
std::string vtkTransmittanceShaderSource::GetFragmentShader(int pass, const Variant& variant)
{
  if (pass == COMPOSITE)
  {
    std::string source = vtkTransmittanceCompositeFS;
    vtkShaderProgram::Substitute(source, "//TYNDALL::Output", GetOutputSource());
    return source;
  }
  if (pass == DENOISE)
  {
    std::string source = vtkTransmittanceDenoiseFS;
    vtkShaderProgram::Substitute(source, "//TYNDALL::Constants", GetDenoiseConstants());
    return source;
  }
  if (pass == PEEL_RANGES || pass == PEEL_COMPOSITE)
  {
    std::string source =
      pass == PEEL_RANGES ? vtkTransmittancePeelRangesFS : vtkTransmittancePeelCompositeFS;
    vtkShaderProgram::Substitute(source, "//TYNDALL::Constants", GetPeelingConstants());
    vtkShaderProgram::Substitute(source, "//TYNDALL::Output", GetOutputSource());
    return source;
  }
  std::string source = vtkTransmittanceCommonFS;
  switch (pass)
  {
    case MAP_BUILD:
      source += vtkTransmittanceMapBuildFS;
      break;
    case OCCLUSION:
      source += vtkTransmittanceOcclusionFS;
      break;
    case LIGHT_CACHE:
      source += vtkTransmittanceLightCacheFS;
      break;
    case PROJECTION:
      source += vtkTransmittanceCameraRayFS;
      source += vtkTransmittanceLightsFS;
      source += vtkTransmittanceProjectionFS;
      break;
    case PATH_TRACE:
      source += vtkTransmittanceCameraRayFS;
      source += vtkTransmittanceLightsFS;
      source += vtkTransmittanceRayCastFS;
      source += vtkTransmittanceEnvironmentFS;
      source += vtkTransmittancePathTraceFS;
      break;
    default:
      source += vtkTransmittanceCameraRayFS;
      source += vtkTransmittanceLightsFS;
      source += vtkTransmittanceRayCastFS;
      source += vtkTransmittanceRayCastMainFS;
      break;
  }
  vtkShaderProgram::Substitute(source, "//TYNDALL::Constants", GetConstants(variant));
  vtkShaderProgram::Substitute(source, "//TYNDALL::LightMaps", vtkTransmittanceLightMapFS);
  vtkShaderProgram::Substitute(source, "//TYNDALL::Medium", variant.MediumCode);
  vtkShaderProgram::Substitute(source, "//TYNDALL::Output", GetOutputSource());
  return source;
}
