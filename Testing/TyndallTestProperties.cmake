# What CTest needs to know about Tyndall's tests beyond their commands, in one
# place (included from Testing/CMakeLists.txt; Documentation/testing.md,
# "What CI costs"):
#
# - their cost: CTest runs the tests of a parallel run in descending COST,
#   and without one (a fresh build has no CTestCostData.txt) in the order they
#   were added, which left the slowest ones for the end of a -j2 run, one core
#   idle. The seconds below were measured in one Release run (2 cores,
#   ctest -j2, llvmpipe, 2026-12-06); a test not listed costs 0 (a few
#   seconds at most). A new test of more than 5 s adds its line here.
# - the sanitizer selection: the tests labelled NoSanitizer are left out of
#   the sanitizer suite that setup.sh runs (ctest -LE NoSanitizer in
#   build-asan/, which does not even compile their sources:
#   tyndall_sanitizer_sources(); TYNDALL_SANITIZE_ALL=1 builds and runs them
#   too, TYNDALL_SANITIZE_ALL_TESTS=ON in CMake). Each is a rendering
#   test whose time goes to Mesa's llvmpipe running Tyndall's shaders (not
#   instrumented, so the sanitizers see nothing of it), and whose Tyndall C++
#   runs in tests kept in the selection: the list says which.
#
# tyndall_finish_tests(), called at the end of every testing directory (CMake
# 3.25 sets test properties only in the directory that added the test), applies
# both and the sanitizers' environment (tyndall_sanitize_tests()).

set(tyndall_test_costs
  Tyndall::RenderingCxx-TestTransmittanceMapperVTKScenes 234
  Tyndall::RenderingCxx-TestTransmittanceMapperPathTrace 140
  Tyndall::RenderingCxx-TestTransmittanceMapperReference 80
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneCompositing 80
  Tyndall::RenderingCxx-TestTransmittanceMapperChromatic 77
  Tyndall::RenderingCxx-TestTransmittanceParticleMapper 80
  Tyndall::RenderingCxx-TestTransmittanceMapperDetail 57
  TyndallParaView-Plugin 56
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneRules 41
  Tyndall::RenderingCxx-TestTransmittanceMapperTransmittanceCache 40
  Tyndall::RenderingCxx-TestTransmittanceMapperOctaves 39
  Tyndall::RenderingCxx-TestTransmittanceMapperEmptySpace 35
  Tyndall::RenderingCxx-TestTransmittanceMapperClipping 35
  TyndallPython-TestPythonRendering 33
  TyndallPython-TestPythonVDBRenderComparison 33
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneShadows 35
  TyndallViewer-TestViewerScripted 30
  Tyndall::RenderingCxx-TestTransmittanceMapperManyLights 28
  TyndallBenchmark-CinematicSkyQuick 27
  TyndallParaView-MPI 26
  Tyndall::RenderingCxx-TestTransmittanceMapperDepthPeeling 25
  Tyndall::ReferenceCxx-TestVolumetricPathTracer 36
  TyndallIO-FuzzOpenVDBReader 22
  Tyndall::RenderingCxx-TestTransmittanceMapperSky 17
  Tyndall::RenderingCxx-TestTransmittanceMapperBadInput 18
  TyndallParaView-Time 18
  Tyndall::RenderingCxx-TestTransmittanceMapperDenoise 17
  Tyndall::RenderingCxx-TestTransmittanceMapperScenes 17
  Tyndall::RenderingCxx-TestTransmittanceMapperOccluder 17
  Tyndall::RenderingCxx-TestTransmittanceMapperBricks 15
  TyndallBenchmark-DetailQuick 15
  TyndallParaView-GUI 14
  Tyndall::RenderingCxx-TestTransmittanceMapperDataTypes 13
  Tyndall::RenderingCxx-TestTransmittanceMapperTiling 13
  Tyndall::MediumCxx-TestTyndallDetailMedium 12
  Tyndall::ReferenceCxx-TestVolumetricPathTracerScenes 12
  Tyndall::RenderingCxx-TestTransmittanceMapperMethods 10
  Tyndall::RenderingCxx-TestTransmittanceMapperFire 9
  Tyndall::RenderingCxx-TestTransmittanceMapperToneMapping 9
  Tyndall::RenderingCxx-TestTransmittanceMapperGeometry 8
  TyndallBenchmark-BlendModesPeelingQuick 8
  TyndallBenchmark-Export 7
  TyndallViewer-TestViewerSequence 7
  TyndallBenchmark-BlendModesQuick 6)

# Left out of the sanitizer suite (seconds under the sanitizers, 2026-11-28;
# 1112 of the suite's 1476 s of test time). The Tyndall C++ they run is run
# under the sanitizers by the tests named after the colon.
set(tyndall_no_sanitizer_tests
  # 196 s: the particle medium's reading and voxelising (TestParticleKernel,
  # TestParticleFileReader, TyndallCLI-Particles*, TyndallBenchmark-ParticlesQuick)
  Tyndall::RenderingCxx-TestTransmittanceParticleMapper
  # 138 s: the benchmark's scenes and export (file writing); the mapper and the
  # CPU reference it drives (TestTransmittanceMapperMethods, TestSingleScatteringReference)
  TyndallBenchmark-Export
  # 103 s, 61 s, 99 s, 60 s, 56 s: the CPU reference on the cloud, with guests,
  # camera groups, coloured extinction and octaves (TestSingleScatteringReference,
  # TestVolumetricPathTracer, TestTransmittanceMapMath, TyndallCLI-SeveralVolumes,
  # TyndallCLI-ExtinctionColor)
  Tyndall::RenderingCxx-TestTransmittanceMapperReference
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneShadows
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneCompositing
  Tyndall::RenderingCxx-TestTransmittanceMapperChromatic
  Tyndall::RenderingCxx-TestTransmittanceMapperOctaves
  # 92 s: the viewer's scripted session (TyndallViewer-TestViewerFailures, the
  # scene builder's tests: TestTyndallSceneBuilder, TyndallCLI-*)
  TyndallViewer-TestViewerScripted
  # 56 s, 44 s: the scene reader's light and group rules (TestTyndallSceneBuilder,
  # TestTransmittanceMapperMethods, TyndallCLI-SeveralVolumes)
  Tyndall::RenderingCxx-TestTransmittanceMapperManyLights
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneRules
  # 47 s: the detail medium (TestTyndallDetailMedium, TyndallCLI-Detail*)
  Tyndall::RenderingCxx-TestTransmittanceMapperDetail
  # 88 s unsanitized: the CPU path tracer at 4096 spp beside the GPU's paths
  # (TestVolumetricPathTracer; the mapper's path-tracing mode: TyndallCLI-PathTrace*)
  Tyndall::RenderingCxx-TestTransmittanceMapperPathTrace
  # 8 s unsanitized: 1024 spp of paths at 64^2 (the denoiser's twin: TestTyndallDenoiser;
  # the mapper's denoised paths: TyndallCLI-PathTraceDenoise)
  Tyndall::RenderingCxx-TestTransmittanceMapperDenoise
  # 11 s unsanitized: 64 spp of paths at 32^2, seven times, beside the CPU tracer's (the sky's
  # twin: TestTyndallEnvironment; the programs' --sky: TyndallCLI-Sky*)
  Tyndall::RenderingCxx-TestTransmittanceMapperSky
  # 38 s: the majorant grid (TyndallCLI-*, every rendering test kept: skipping is on by default)
  Tyndall::RenderingCxx-TestTransmittanceMapperEmptySpace
  # 28 s: the CPU twin of the maps (TestTransmittanceMapMath, TestTransmittanceLightFrustum)
  Tyndall::RenderingCxx-TestTransmittanceMapperMaps
  # 26 s, 23 s: the mapper's cache and caching logic (TestTransmittanceMapperInteractive,
  # TestTransmittanceMapperMethods)
  Tyndall::RenderingCxx-TestTransmittanceMapperTransmittanceCache
  Tyndall::RenderingCxx-TestTransmittanceMapperCaching
  # 25 s: the clip region (TyndallCLI-Clipped, TestTyndallSceneBuilder)
  Tyndall::RenderingCxx-TestTransmittanceMapperClipping
  # 21 s: the OpenVDB reader and the wrapping (TestOpenVDBReader*, TyndallPython-TestPythonRendering)
  TyndallPython-TestPythonVDBRenderComparison)

# The test drivers' own code (its scenes, checks and statistics; the code
# under test is the modules', compiled with the build type's flags) compiles
# at -O1 in an optimised build and as harness in the sanitizer build (-O0,
# without UBSan's pointer checks: TyndallSanitizers.cmake): compile time is most of a build here, and a
# driver's own time is small beside the renders it asks for. Measured
# (Release flags, one source): TestOpenVDBReaderStreaming.cxx 19.0 s of CPU at
# -O3, 12.1 s at -O1; TestTransmittanceMapperVTKScenes.cxx 4.5 s, 3.7 s. Core's
# and Medium's drivers are left out: their tests compute exact math themselves
# (under the sanitizers at -O0 TestTransmittanceMapMath took 39 s instead of
# 17, TestTyndallDetailMedium 37 s instead of 21, for 5-6 s less compile).
function (tyndall_compile_test_drivers)
  if (NOT ARGN)
    message(FATAL_ERROR "tyndall_compile_test_drivers: name the drivers")
  endif ()
  if (TYNDALL_SANITIZE)
    tyndall_sanitizer_compile_harness(${ARGN})
    return ()
  endif ()
  foreach (target IN LISTS ARGN)
    if (TARGET "${target}")
      target_compile_options("${target}" PRIVATE
        "$<$<OR:$<CONFIG:Release>,$<CONFIG:RelWithDebInfo>,$<CONFIG:MinSizeRel>>:-O1>")
    endif ()
  endforeach ()
endfunction ()

# The sources of `listvar` (Test*.cxx) less those of the tests named
# `prefix`<source name> in tyndall_no_sanitizer_tests, in the sanitizer build
# (TYNDALL_SANITIZE) unless TYNDALL_SANITIZE_ALL_TESTS: its suite does not run
# them (setup.sh's -LE NoSanitizer), and their 17 sources were about 50 s of
# its compile on one core (3 s each at -O0 with the sanitizers).
function (tyndall_sanitizer_sources listvar prefix)
  if (NOT TYNDALL_SANITIZE OR TYNDALL_SANITIZE_ALL_TESTS)
    return ()
  endif ()
  set(kept)
  foreach (source IN LISTS "${listvar}")
    get_filename_component(name "${source}" NAME_WE)
    if (NOT "${prefix}${name}" IN_LIST tyndall_no_sanitizer_tests)
      list(APPEND kept "${source}")
    endif ()
  endforeach ()
  set("${listvar}" "${kept}" PARENT_SCOPE)
endfunction ()

function (tyndall_finish_tests)
  tyndall_sanitize_tests()
  get_property(tests DIRECTORY PROPERTY TESTS)
  set(costs ${tyndall_test_costs})
  while (costs)
    list(POP_FRONT costs name seconds)
    if (name IN_LIST tests)
      set_property(TEST "${name}" PROPERTY COST "${seconds}")
    endif ()
  endwhile ()
  foreach (name IN LISTS tyndall_no_sanitizer_tests)
    if (name IN_LIST tests)
      set_property(TEST "${name}" APPEND PROPERTY LABELS NoSanitizer)
    endif ()
  endforeach ()
endfunction ()
