# Tests of Tyndall::Application, the programs' kit (included from
# CMakeLists.txt): the options table (parser, help, viewer keys) and the
# scene builder (no display needed: nothing is rendered).
vtk_add_test_cxx(TyndallApplicationCxxTests tests
  NO_DATA NO_VALID NO_OUTPUT
  TestTyndallFrameSequence.cxx
  TestTyndallOptions.cxx
  TestTyndallSceneBuilder.cxx
  TestTyndallSky.cxx)
vtk_test_cxx_executable(TyndallApplicationCxxTests tests)
