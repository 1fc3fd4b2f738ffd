# Tests of Tyndall::IO (included from CMakeLists.txt).
vtk_add_test_cxx(TyndallIOCxxTests tests
  NO_DATA NO_VALID
  TestOpenVDBReaderSamples.cxx
  TestOpenVDBReaderBadFiles.cxx
  TestOpenVDBReaderGrids.cxx
  TestOpenVDBReaderStreaming.cxx
  TestOpenVDBWriterRoundTrip.cxx
  TestOpenVDBWriterSamples.cxx
  TestParticleFileReader.cxx
  TestVolumeFileReader.cxx)
# Rendering tests (need a display): baselines in Testing/Data/Baseline.
vtk_add_test_cxx(TyndallIOCxxTests tests
  TestOpenVDBSmokeRender.cxx)
vtk_test_cxx_executable(TyndallIOCxxTests tests
  RENDERING_FACTORY
  DISABLE_FLOATING_POINT_EXCEPTIONS)
# The tests compute expected values with OpenVDB's API themselves.
target_include_directories(TyndallIOCxxTests PRIVATE "${TYNDALL_OPENVDB_INCLUDE_DIR}")
target_link_libraries(TyndallIOCxxTests PRIVATE ${TYNDALL_OPENVDB_LINK})

# Every Tyndall::IO test must finish: a hang on a bad file is a failure.
foreach (_tyndall_io_test IN LISTS tests)
  get_filename_component(_tyndall_io_test "${_tyndall_io_test}" NAME_WE)
  set_tests_properties("Tyndall::IOCxx-${_tyndall_io_test}" PROPERTIES TIMEOUT 300)
endforeach ()

# The Python example, a thin front-end over the programs' kit, on a real
# MR head (skips with 125 when ../shared/data is absent).
if (TYNDALL_WRAP_PYTHON)
  add_test(NAME TyndallIO-TomographyPython-HeadMR
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/Examples/Python/render_tomography.py"
      "${TYNDALL_SHARED_DATA}/volumes/HeadMRVolume.mhd"
      --output "${CMAKE_BINARY_DIR}/Testing/Temporary/TomographyPython-HeadMR.png"
      --size 300 300 --check --skip-missing)
  set_tests_properties(TyndallIO-TomographyPython-HeadMR PROPERTIES
    ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/${TYNDALL_PYTHON_DESTINATION}"
    LABELS "Tyndall;IO;Python" SKIP_RETURN_CODE 125 TIMEOUT 300)
  # tyndall-render's outputs beyond one PNG: refused, not ignored.
  add_test(NAME TyndallIO-TomographyPython-RefusesVideo
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/Examples/Python/render_tomography.py"
      --orbit 90 --video "${CMAKE_BINARY_DIR}/Testing/Temporary/TomographyPython.ogv")
  set_tests_properties(TyndallIO-TomographyPython-RefusesVideo PROPERTIES
    ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/${TYNDALL_PYTHON_DESTINATION}"
    LABELS "Tyndall;IO;Python"
    PASS_REGULAR_EXPRESSION "--orbit is tyndall-render's; this example writes one PNG")
endif ()

# The reader's libFuzzer target and a short bounded fuzzing run (only when
# clang with libFuzzer works here; see Testing/Fuzz/CMakeLists.txt).
add_subdirectory("${CMAKE_SOURCE_DIR}/Testing/Fuzz" "${CMAKE_BINARY_DIR}/Testing/Fuzz")
