# Tests of Tyndall::Reference (included from CMakeLists.txt): the CPU
# integrators against closed forms, each other and their baseline image (no
# render window is opened; the mappers only describe the volumes).
vtk_add_test_cxx(TyndallReferenceCxxTests tests
  NO_DATA NO_VALID NO_OUTPUT
  TestSingleScatteringReference.cxx
  TestTyndallIsosurfaces.cxx
  TestVolumetricPathTracer.cxx
  TestVolumetricPathTracerScenes.cxx)
vtk_add_test_cxx(TyndallReferenceCxxTests tests
  TestSingleScatteringReferenceImage.cxx)
vtk_test_cxx_executable(TyndallReferenceCxxTests tests
  RENDERING_FACTORY
  DISABLE_FLOATING_POINT_EXCEPTIONS)
