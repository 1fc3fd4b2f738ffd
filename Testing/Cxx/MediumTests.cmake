# Tests of Tyndall::Medium (included from CMakeLists.txt): the procedural
# detail's closed forms, the transfer-function presets and files (CPU).
vtk_add_test_cxx(TyndallMediumCxxTests tests
  NO_DATA NO_VALID NO_OUTPUT
  TestParticipatingMediumPropertyCopy.cxx
  TestTransferFunctionFileReader.cxx
  TestTransferFunctionPresets.cxx
  TestTyndallComponents.cxx
  TestTyndallDetailMedium.cxx
  TestTyndallEnvironment.cxx
  TestTyndallFootprintFilter.cxx
  TestTyndallLabelMap.cxx
  TestTyndallVolumeSettings.cxx)
vtk_test_cxx_executable(TyndallMediumCxxTests tests
  RENDERING_FACTORY
  DISABLE_FLOATING_POINT_EXCEPTIONS)
