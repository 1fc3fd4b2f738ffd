# Run with cmake -P; see CMakeLists.txt beside this file.
function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "Failed (${result}): ${ARGN}\n${out}")
  endif ()
  message(STATUS "${out}")
endfunction ()

# In a sanitizer build the test runs with libasan preloaded (for Python);
# the build tools (cmake, make, the compiler) must not run under it.
set(preload "$ENV{LD_PRELOAD}")
set(ENV{LD_PRELOAD} "")

file(REMOVE_RECURSE "${PREFIX}" "${PROJECT_BINARY}")
run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}")
# A sanitizer build's libraries need the sanitizers' runtime in the program.
set(flags)
if (SANITIZE)
  set(flags "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
    "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif ()
run("${CMAKE_COMMAND}" -S "${PROJECT_SOURCE}" -B "${PROJECT_BINARY}" -G "${GENERATOR}"
  "-DTyndall_DIR=${PREFIX}/${CMAKE_DIR}" ${flags})
run("${CMAKE_COMMAND}" --build "${PROJECT_BINARY}")
run("${PROJECT_BINARY}/tyndall-downstream")

if (PYTHON AND PYTHON_DESTINATION)
  # The installed Python package, with the build tree out of sight.
  set(ENV{LD_PRELOAD} "${preload}")
  set(ENV{PYTHONPATH} "${PREFIX}/${PYTHON_DESTINATION}")
  run("${PYTHON}" -c
    "import tyndall, sys; assert tyndall.__file__.startswith('${PREFIX}'), tyndall.__file__; s = tyndall.vtkCosineNoiseSource(); s.SetWholeExtent(0, 7, 0, 7, 0, 7); s.Update(); assert s.GetOutput().GetNumberOfPoints() == 512; print('installed python package ok:', tyndall.__file__)")
endif ()
