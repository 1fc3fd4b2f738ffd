# AddressSanitizer and UndefinedBehaviorSanitizer for a whole Tyndall build
# (TYNDALL_SANITIZE=ON, in a build directory of its own: see
# Testing/Scripts/setup.sh, which builds build-asan/ beside build/ and runs
# the whole suite in both). Included from the top-level CMakeLists.txt.
#
# Every Tyndall target (modules, programs, tests, benchmarks) is compiled and
# linked with -fsanitize=address,undefined (the harness without UBSan's
# pointer checks: tyndall_sanitizer_compile_harness() below); any undefined
# behaviour aborts the process (-fno-sanitize-recover), so a finding fails
# its test. VTK, OpenVDB, Mesa and Python are used as Debian ships them (not
# instrumented).
#
# tyndall_sanitize_tests() gives every test the sanitizers'
# options: leak checking on, with the suppressions in
# Testing/Sanitizers/lsan-suppressions.txt (each names a third-party library
# and says why), and, for tests that run /usr/bin/python3 (not instrumented),
# LD_PRELOAD of the compiler's libasan so that the instrumented Tyndall
# modules can be imported.

if (NOT TYNDALL_SANITIZE)
  # Only tyndall_sanitize_tests() (below), which then does nothing.
elseif (NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  message(FATAL_ERROR "TYNDALL_SANITIZE needs GCC or Clang, not ${CMAKE_CXX_COMPILER_ID}")
else ()

  set(TYNDALL_SANITIZER_FLAGS
    -fsanitize=address,undefined
    -fno-sanitize-recover=undefined
    -fno-omit-frame-pointer)
  add_compile_options(${TYNDALL_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined)

  execute_process(
    COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=libasan.so
    OUTPUT_VARIABLE TYNDALL_ASAN_LIBRARY
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if (NOT IS_ABSOLUTE "${TYNDALL_ASAN_LIBRARY}" OR NOT EXISTS "${TYNDALL_ASAN_LIBRARY}")
    message(FATAL_ERROR "TYNDALL_SANITIZE: the compiler's libasan.so was not found "
      "(got '${TYNDALL_ASAN_LIBRARY}')")
  endif ()
  get_filename_component(TYNDALL_ASAN_LIBRARY "${TYNDALL_ASAN_LIBRARY}" REALPATH)
  message(STATUS "Sanitizers: AddressSanitizer + UndefinedBehaviorSanitizer (${TYNDALL_ASAN_LIBRARY})")

  # Mesa's software driver. Mesa unloads it (dlclose) when the last GL context
  # goes; allocations it still holds then belong to an unmapped module, which
  # LeakSanitizer reports as leaks from "<unknown module>" (240 bytes a process
  # here) and no suppression can name. Preloading it keeps it mapped, its memory
  # stays reachable, and leak checking stays on for every rendering test.
  find_file(TYNDALL_SANITIZER_GL_DRIVER swrast_dri.so
    PATHS /usr/lib/x86_64-linux-gnu/dri /usr/lib/aarch64-linux-gnu/dri /usr/lib64/dri /usr/lib/dri
    NO_DEFAULT_PATH
    DOC "Mesa's software GL driver, preloaded in sanitizer test runs")
  set(_tyndall_preload "${TYNDALL_ASAN_LIBRARY}")
  if (TYNDALL_SANITIZER_GL_DRIVER)
    string(APPEND _tyndall_preload " ${TYNDALL_SANITIZER_GL_DRIVER}")
  else ()
    message(STATUS "Sanitizers: Mesa's swrast_dri.so not found; rendering tests may report "
      "the driver's memory as leaked at exit")
  endif ()

  # The options every test runs with. detect_leaks: LeakSanitizer at exit.
  # allocator_may_return_null: a huge allocation (a header that claims 10^15
  # voxels) must come back as std::bad_alloc or nullptr, which Tyndall reports,
  # instead of ASan's own abort. halt_on_error/abort_on_error: a finding ends
  # the test with a failure.
  set(_tyndall_sanitizer_dir "${CMAKE_CURRENT_LIST_DIR}")
  set(TYNDALL_SANITIZER_ENVIRONMENT
    "ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:detect_stack_use_after_return=0:strict_string_checks=1:check_initialization_order=1:abort_on_error=0:halt_on_error=1"
    "LSAN_OPTIONS=suppressions=${_tyndall_sanitizer_dir}/lsan-suppressions.txt:print_suppressions=0"
    "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
endif ()

# The sanitizer build compiles the harness, code whose own run time is small
# beside what it calls and which is not what the tests test (the programs, the
# benchmarks, the generated Python wrappers, most test drivers:
# tyndall_compile_test_drivers() in TyndallTestProperties.cmake), more
# lightly than the modules:
# - at -O0 instead of the build type's -O1 (TestOpenVDBReaderStreaming.cxx:
#   40 s -> 23 s); both sanitizers instrument every optimisation level;
# - with AddressSanitizer and UBSan's value checks (signed overflow, shifts,
#   division by zero, bool and enum loads, bounds, unreachable, missing
#   returns) but without UBSan's pointer checks (null, alignment, vptr,
#   object-size, pointer-overflow, nonnull-attribute,
#   returns-nonnull-attribute), which doubled the compile of a driver that
#   builds OpenVDB grids (TestOpenVDBReaderGrids.cxx: 62 s with them, 35 s
#   without, 32 s with AddressSanitizer alone): their time went to
#   OpenVDB's templates, instantiated there to write the test files.
#   AddressSanitizer still checks every access of that code.
# The modules' libraries, and Core's and Medium's drivers (they run the
# modules' inline math themselves), keep -O1 and every check (the modules'
# inline code that a harness source compiles into itself goes as that
# source does): the modules are what the sanitizers are for, and the CPU
# renderers are most of the sanitizer suite's C++ time.
set(TYNDALL_SANITIZER_HARNESS_OPTIONS
  -O0
  -fno-sanitize=null,alignment,vptr,object-size,pointer-overflow,nonnull-attribute,returns-nonnull-attribute)
# With targets: those; without: every target of the calling directory and
# below it. Without TYNDALL_SANITIZE it does nothing.
function (tyndall_sanitizer_compile_harness)
  if (NOT TYNDALL_SANITIZE)
    return ()
  endif ()
  if (ARGN)
    foreach (target IN LISTS ARGN)
      if (TARGET "${target}")
        target_compile_options("${target}" PRIVATE ${TYNDALL_SANITIZER_HARNESS_OPTIONS})
      endif ()
    endforeach ()
  else ()
    set_property(DIRECTORY APPEND PROPERTY COMPILE_OPTIONS ${TYNDALL_SANITIZER_HARNESS_OPTIONS})
  endif ()
endfunction ()

# Gives the tests of the calling directory the sanitizers' environment: the
# options above and LD_PRELOAD of the compiler's libasan (Python is not
# instrumented: the runtime must come first for the instrumented modules to
# import; harmless for instrumented programs) and of Mesa's driver (above). Every testing
# directory calls it at its end (CMake 3.25 sets test properties only in the
# directory that added the test); without TYNDALL_SANITIZE it does nothing.
#
# A test whose own process never renders and whose children may (the CLI
# tests' TyndallCLICheck, which runs tyndall-render) sets the test property
# TYNDALL_SANITIZER_GL_IN_CHILD: its process gets libasan alone and the full
# preload goes to its children through TYNDALL_SANITIZER_CHILD_PRELOAD
# (TyndallCLICheck puts it in their LD_PRELOAD). Loading Mesa's driver, LLVM
# and their libraries costs a process 0.25 s under the sanitizers (0.43 s ->
# 0.18 s for TyndallCLICheck alone), and 350 CLI tests start one each.
function (tyndall_sanitize_tests)
  if (NOT TYNDALL_SANITIZE)
    return ()
  endif ()
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach (test IN LISTS tests)
    get_property(gl_in_child TEST "${test}" PROPERTY TYNDALL_SANITIZER_GL_IN_CHILD)
    if (gl_in_child)
      set(preload "LD_PRELOAD=${TYNDALL_ASAN_LIBRARY}"
        "TYNDALL_SANITIZER_CHILD_PRELOAD=${_tyndall_preload}")
    else ()
      set(preload "LD_PRELOAD=${_tyndall_preload}")
    endif ()
    set_property(TEST "${test}" APPEND PROPERTY ENVIRONMENT
      ${TYNDALL_SANITIZER_ENVIRONMENT} ${preload})
  endforeach ()
endfunction ()
