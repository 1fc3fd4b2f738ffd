# Tests of Tyndall::Rendering (included from CMakeLists.txt).
# The light frusta, the detail filter's constants (CPU).
vtk_add_test_cxx(TyndallRenderingCxxTests tests
  NO_DATA NO_VALID NO_OUTPUT
  TestTransmittanceDetailFilterChain.cxx
  TestTransmittanceLightFrustum.cxx)
# vtkTransmittanceVolumeMapper (needs a display). The sanitizer build leaves
# out the sources of the tests its suite does not run (NoSanitizer,
# tyndall_sanitizer_sources(); TYNDALL_SANITIZE_ALL_TESTS keeps them).
set(tyndall_mapper_tests
  TestTransmittanceMapperCaching.cxx
  TestTransmittanceMapperEmptySpace.cxx
  TestTransmittanceMapperInteractive.cxx
  TestTransmittanceMapperTransmittanceCache.cxx
  TestTransmittanceMapperBadInput.cxx
  TestTransmittanceMapperReference.cxx
  TestTransmittanceMapperOctaves.cxx
  TestTransmittanceMapperPathTrace.cxx
  TestTransmittanceMapperToneMapping.cxx
  TestTransmittanceMapperDenoise.cxx
  TestTransmittanceMapperSky.cxx
  TestTransmittanceMapperClipping.cxx
  TestTransmittanceMapperFire.cxx
  TestTransmittanceMapperChromatic.cxx
  TestVolumeShadowReceiver.cxx
  TestTransmittanceMapperSceneShadows.cxx
  TestTransmittanceMapperSceneCompositing.cxx
  TestTransmittanceParticleMapper.cxx
  TestTransmittanceMapperDetail.cxx
  TestTransmittanceMapperOccluder.cxx
  TestTransmittanceMapperGeometry.cxx
  TestTransmittanceMapperManyLights.cxx
  TestTransmittanceMapperMaps.cxx
  TestTransmittanceMapperSceneRules.cxx
  TestTransmittanceMapperDepthPeeling.cxx
  TestTransmittanceMapperDataTypes.cxx
  TestTransmittanceMapperTiling.cxx
  TestTransmittanceMapperBricks.cxx
  TestTransmittanceMapReducer.cxx)
tyndall_sanitizer_sources(tyndall_mapper_tests Tyndall::RenderingCxx-)
vtk_add_test_cxx(TyndallRenderingCxxTests tests
  NO_DATA NO_VALID NO_OUTPUT
  ${tyndall_mapper_tests})
# VTK's scenes against VTK's mapper (no baseline; -T: where their pictures go).
vtk_add_test_cxx(TyndallRenderingCxxTests tests
  NO_DATA NO_VALID
  TestTransmittanceMapperVTKScenes.cxx)
vtk_add_test_cxx(TyndallRenderingCxxTests tests
  TestTransmittanceMapperEmissionAbsorption.cxx
  TestTransmittanceMapperScenes.cxx
  TestTransmittanceMapperMethods.cxx)
vtk_test_cxx_executable(TyndallRenderingCxxTests tests
  RENDERING_FACTORY
  DISABLE_FLOATING_POINT_EXCEPTIONS)
# VTK's scenes read VTK's CT head from ../shared/data when it is there.
target_compile_definitions(TyndallRenderingCxxTests PRIVATE
  "TYNDALL_SHARED_DATA=\"${TYNDALL_SHARED_DATA}\"")
