# Tests of Tyndall::Core (included from CMakeLists.txt).
vtk_add_test_cxx(TyndallCoreCxxTests tests
  NO_DATA NO_VALID NO_OUTPUT
  TestBlackbody.cxx
  TestCosineNoiseClosedForm.cxx
  TestCosineNoiseSampleDistance.cxx
  TestCosineNoiseSource.cxx
  TestCosineNoiseBadInput.cxx
  TestParticleKernel.cxx
  TestTransmittanceMapMath.cxx
  TestTyndallDenoiser.cxx
  TestTyndallToneMapping.cxx)
vtk_add_test_cxx(TyndallCoreCxxTests tests
  TestCosineNoiseCloudRender.cxx)
vtk_test_cxx_executable(TyndallCoreCxxTests tests
  RENDERING_FACTORY
  DISABLE_FLOATING_POINT_EXCEPTIONS)
