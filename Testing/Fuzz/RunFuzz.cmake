# Runs the reader's fuzz target for a bounded time (the CTest test
# TyndallIO-FuzzOpenVDBReader). Variables: FUZZER (the executable), CORPUS (a
# scratch directory), SAMPLES (directory of sample .vdb files, may be
# absent), RUNS and MAX_TIME (libFuzzer's -runs and -max_total_time), SEED
# (libFuzzer's -seed: a fixed one makes the test's inputs the same on every run,
# so that CI's verdict does not depend on luck; 0 draws a new seed each run).
file(REMOVE_RECURSE "${CORPUS}")
file(MAKE_DIRECTORY "${CORPUS}")
# Seeds: the small real samples when present (the larger ones slow fuzzing
# down), plus the valid files the target writes itself.
foreach (sample fog_small.vdb torus.vdb)
  if (EXISTS "${SAMPLES}/${sample}")
    file(COPY "${SAMPLES}/${sample}" DESTINATION "${CORPUS}")
  endif ()
endforeach ()
set(ENV{TYNDALL_FUZZ_WRITE_SEEDS} "${CORPUS}")
set(ENV{TYNDALL_FUZZ_SCRATCH} "${CORPUS}/../scratch.vdb")
# OpenVDB allocates buffers of sizes read from the file; a failed allocation
# must become std::bad_alloc (which the reader reports), not a crash.
set(ENV{ASAN_OPTIONS} "allocator_may_return_null=1:detect_leaks=1")
# Known leaks inside OpenVDB's error paths (see the file).
set(ENV{LSAN_OPTIONS} "suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan-suppressions.txt")
# Address-space randomisation changes the order of pointer-keyed tables in
# OpenVDB and oneTBB, hence coverage, hence the inputs libFuzzer derives: run
# without it (setarch -R) where the kernel allows, so that the seed above
# fixes the test's inputs.
set(launcher)
find_program(SETARCH setarch)
if (SETARCH)
  execute_process(COMMAND uname -m OUTPUT_VARIABLE arch OUTPUT_STRIP_TRAILING_WHITESPACE)
  execute_process(COMMAND "${SETARCH}" "${arch}" -R true RESULT_VARIABLE norandom
    OUTPUT_QUIET ERROR_QUIET)
  if (norandom EQUAL 0)
    set(launcher "${SETARCH}" "${arch}" -R)
  endif ()
endif ()
execute_process(
  COMMAND ${launcher} "${FUZZER}" "${CORPUS}" -runs=${RUNS} -max_total_time=${MAX_TIME} -seed=${SEED} -reload=0
    -timeout=30 -rss_limit_mb=3072 -malloc_limit_mb=3072 -print_final_stats=1
    "-artifact_prefix=${CORPUS}/../crash-"
  RESULT_VARIABLE result)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "the fuzzer found a problem (exit code ${result}); see the reproducer "
    "next to ${CORPUS} (run the fuzzer with it as argument)")
endif ()
