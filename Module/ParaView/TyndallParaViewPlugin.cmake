# Included by Tyndall's top-level CMakeLists.txt: builds the ParaView plugin
# (Module/ParaView, a CMake project of its own, against ParaView 5.11's VTK)
# as an external project of the main build, when ParaView is usable, and
# says why not otherwise. Sets TYNDALL_PARAVIEW_PLUGIN_FILE (the plugin's
# library), TYNDALL_PVBATCH and TYNDALL_PARAVIEW_PYTHONPATH for the tests in
# Testing/ParaView, or leaves TYNDALL_PARAVIEW_PLUGIN_FILE empty.

set(TYNDALL_PARAVIEW_PLUGIN_FILE "")
set(_tyndall_paraview_default "/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11")
if (NOT ParaView_DIR AND EXISTS "${_tyndall_paraview_default}/paraview-config.cmake")
  set(ParaView_DIR "${_tyndall_paraview_default}" CACHE PATH
    "ParaView 5.11's CMake package, for Tyndall's plugin (Documentation/paraview.md)")
endif ()

# The install prefix that ParaView's imported targets resolve against: as
# many folders above ParaView_DIR as its targets file climbs (4 in Debian's
# lib/x86_64-linux-gnu/cmake/paraview-5.11, 3 in a lib/cmake/paraview-5.11).
function (_tyndall_paraview_prefix out)
  set(prefix "${ParaView_DIR}")
  set(targets "${ParaView_DIR}/ParaView-targets.cmake")
  if (EXISTS "${targets}")
    file(STRINGS "${targets}" climbs
      REGEX "get_filename_component\\(_IMPORT_PREFIX \"\\\${_IMPORT_PREFIX}\" PATH\\)")
  else ()
    set(climbs 1 2 3 4)
  endif ()
  foreach (climb IN LISTS climbs)
    get_filename_component(prefix "${prefix}" DIRECTORY)
  endforeach ()
  set("${out}" "${prefix}" PARENT_SCOPE)
endfunction ()

# Why the plugin cannot be built here, or nothing.
function (_tyndall_paraview_blocker out)
  set(reason "")
  if (NOT TYNDALL_PARAVIEW_PLUGIN)
    set(reason "TYNDALL_PARAVIEW_PLUGIN is OFF")
  elseif (TYNDALL_SANITIZE)
    set(reason "the sanitizer build leaves it out: ParaView's libraries and pvbatch are not instrumented, so the plugin could not be loaded without preloading the sanitizers' runtime into ParaView")
  elseif (NOT BUILD_SHARED_LIBS)
    set(reason "ParaView plugins are shared libraries: BUILD_SHARED_LIBS is OFF")
  elseif (NOT ParaView_DIR OR NOT EXISTS "${ParaView_DIR}/paraview-config.cmake")
    set(reason "ParaView 5.11's CMake package was not found (Debian 12: apt-get install paraview-dev, then Testing/Scripts/paraview-prefix.sh PREFIX and -DParaView_DIR=<what it prints>)")
  else ()
    # Debian's paraview-dev names files that only python3-paraview ships:
    # its CMake package then fails. Check one of them.
    file(GLOB _targets "${ParaView_DIR}/ParaViewPython-targets-*.cmake")
    if (_targets)
      list(GET _targets 0 _targets)
      file(STRINGS "${_targets}" _line REGEX "IMPORTED_LOCATION_[A-Z]+ \"" LIMIT_COUNT 1)
      string(REGEX REPLACE ".*\"\\\${_IMPORT_PREFIX}/([^\"]*)\".*" "\\1" _file "${_line}")
      _tyndall_paraview_prefix(_prefix)
      if (_file AND NOT EXISTS "${_prefix}/${_file}")
        set(reason "ParaView's CMake package in ${ParaView_DIR} names ${_prefix}/${_file}, which is missing (Debian's paraview-dev without python3-paraview: make a prefix with Testing/Scripts/paraview-prefix.sh PREFIX and pass -DParaView_DIR=<what it prints>)")
      endif ()
    endif ()
  endif ()
  set("${out}" "${reason}" PARENT_SCOPE)
endfunction ()

_tyndall_paraview_blocker(_tyndall_paraview_reason)
if (_tyndall_paraview_reason)
  message(STATUS "Tyndall: the ParaView plugin is skipped: ${_tyndall_paraview_reason}.")
  return ()
endif ()

message(STATUS "Tyndall: the ParaView plugin is built against ${ParaView_DIR}")
include(ExternalProject)
set(_tyndall_paraview_build "${CMAKE_BINARY_DIR}/paraview-plugin")
ExternalProject_Add(TyndallParaViewPlugin
  SOURCE_DIR      "${CMAKE_CURRENT_LIST_DIR}"
  BINARY_DIR      "${_tyndall_paraview_build}"
  CMAKE_ARGS
    "-DParaView_DIR=${ParaView_DIR}"
    "-DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}"
    "-DCMAKE_INSTALL_PREFIX=${CMAKE_INSTALL_PREFIX}"
    "-DCMAKE_INSTALL_LIBDIR=${CMAKE_INSTALL_LIBDIR}"
    "-DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}"
    "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}"
    "-DCMAKE_UNITY_BUILD=${TYNDALL_UNITY_BUILD}"
  INSTALL_COMMAND ""
  # The sub-build tracks its own sources (Module/Core, IO, Rendering too).
  BUILD_ALWAYS    ON)
set(TYNDALL_PARAVIEW_PLUGIN_FILE
  "${_tyndall_paraview_build}/${CMAKE_INSTALL_LIBDIR}/tyndall-paraview/Tyndall/Tyndall.so")
install(DIRECTORY "${_tyndall_paraview_build}/${CMAKE_INSTALL_LIBDIR}/tyndall-paraview"
  DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  USE_SOURCE_PERMISSIONS
  COMPONENT paraview)

_tyndall_paraview_prefix(_prefix)
find_program(TYNDALL_PVBATCH NAMES pvbatch HINTS "${_prefix}/bin"
  DOC "ParaView's pvbatch, for the plugin's tests")
# Where ParaView's Python modules are (Debian's layout, which the prefix of
# Testing/Scripts/paraview-prefix.sh has too; set it for another layout).
set(TYNDALL_PARAVIEW_PYTHONPATH "${_prefix}/lib/python3/dist-packages" CACHE PATH
  "ParaView's Python modules, put first on pvbatch's PYTHONPATH by the plugin's tests")
