# What CTest needs to know about Tyndall's tests beyond their commands, in one
# place (included from Testing/CMakeLists.txt; Documentation/testing.md,
# "What CI costs"):
#
# - their cost: CTest runs the tests of a parallel run in descending COST,
#   and without one (a fresh build has no CTestCostData.txt) in the order they
#   were added, which left the slowest ones for the end of a -j2 run, one core
#   idle. The seconds below were measured in one Release run (2 cores,
#   ctest -j2, llvmpipe, 2026-11-28); a test not listed costs 0 (a few
#   seconds at most). A new test of more than 5 s adds its line here.
# - the sanitizer selection: the tests labelled NoSanitizer are left out of
#   the sanitizer suite that setup.sh runs (ctest -LE NoSanitizer in
#   build-asan/; TYNDALL_SANITIZE_ALL=1 runs them too). Each is a rendering
#   test whose time goes to Mesa's llvmpipe running Tyndall's shaders (not
#   instrumented, so the sanitizers see nothing of it), and whose Tyndall C++
#   runs in tests kept in the selection: the list says which.
#
# tyndall_finish_tests(), called at the end of every testing directory (CMake
# 3.25 sets test properties only in the directory that added the test), applies
# both and the sanitizers' environment (tyndall_sanitize_tests()).

set(tyndall_test_costs
  TyndallBenchmark-Export 114
  TyndallViewer-TestViewerScripted 87
  Tyndall::RenderingCxx-TestTransmittanceParticleMapper 79
  Tyndall::RenderingCxx-TestTransmittanceMapperReference 70
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneShadows 48
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneCompositing 46
  Tyndall::RenderingCxx-TestTransmittanceMapperDetail 42
  Tyndall::RenderingCxx-TestTransmittanceMapperChromatic 41
  Tyndall::RenderingCxx-TestTransmittanceMapperEmptySpace 40
  Tyndall::RenderingCxx-TestTransmittanceMapperPathTrace 70
  Tyndall::RenderingCxx-TestTransmittanceMapperDenoise 8
  Tyndall::RenderingCxx-TestTransmittanceMapperSky 11
  Tyndall::RenderingCxx-TestTransmittanceMapperOctaves 37
  Tyndall::RenderingCxx-TestTransmittanceMapperTransmittanceCache 25
  TyndallParaView-MPI 24
  Tyndall::RenderingCxx-TestTransmittanceMapperManyLights 24
  Tyndall::RenderingCxx-TestTransmittanceMapperCaching 22
  Tyndall::RenderingCxx-TestTransmittanceMapperMaps 22
  TyndallPython-TestPythonRendering 20
  Tyndall::RenderingCxx-TestTransmittanceMapperSceneRules 20
  Tyndall::RenderingCxx-TestTransmittanceMapperClipping 18
  TyndallParaView-Plugin 18
  TyndallPython-TestPythonVDBRenderComparison 17
  TyndallCLI-SeveralVolumes 14
  TyndallCLI-Particles 13
  Tyndall::RenderingCxx-TestVolumeShadowReceiver 13
  TyndallCLI-DetailSampled 12
  Tyndall::RenderingCxx-TestTransmittanceMapperVTKScenes 160
  Tyndall::RenderingCxx-TestTransmittanceMapperScenes 10
  Tyndall::RenderingCxx-TestTransmittanceMapperDataTypes 12
  Tyndall::RenderingCxx-TestTransmittanceMapperBricks 8
  TyndallParaView-GUI 10
  Tyndall::ReferenceCxx-TestVolumetricPathTracer 15
  Tyndall::ReferenceCxx-TestVolumetricPathTracerScenes 13
  TyndallIO-FuzzOpenVDBReader 9
  Tyndall::MediumCxx-TestTyndallDetailMedium 8
  TyndallCLI-ExtinctionColor 7
  Tyndall::RenderingCxx-TestTransmittanceMapperOccluder 7
  TyndallCLI-Clipped 7
  Tyndall::RenderingCxx-TestTransmittanceMapperBadInput 7
  TyndallCLI-DefaultScene 7
  TyndallCLI-ParticlesMarched 6
  Tyndall::RenderingCxx-TestTransmittanceMapperMethods 6
  TyndallCLI-DefaultSceneExr 6
  Tyndall::RenderingCxx-TestTransmittanceMapperGeometry 5
  TyndallCLI-CloseUp 5
  TyndallCLI-Ground 5)

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
  # 70 s unsanitized: the CPU path tracer at 4096 spp beside the GPU's paths
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
