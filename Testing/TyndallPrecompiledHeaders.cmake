# Precompiled headers (TYNDALL_PRECOMPILED_HEADERS, default ON): the VTK and
# standard headers that most of Tyndall's sources include, parsed once per
# target instead of once per source. Included at the end of the top-level
# CMakeLists.txt, once every target exists. Documentation/testing.md, "What
# CI costs", has the build times with and without.
option(TYNDALL_PRECOMPILED_HEADERS "Precompile the common VTK and standard headers" ON)
if (NOT TYNDALL_PRECOMPILED_HEADERS)
  return ()
endif ()

set(tyndall_precompiled_headers
  <algorithm>
  <cmath>
  <iostream>
  <sstream>
  <string>
  <vector>
  <vtkDataArray.h>
  <vtkImageData.h>
  <vtkMath.h>
  <vtkNew.h>
  <vtkObject.h>
  <vtkObjectFactory.h>
  <vtkPointData.h>
  <vtkSmartPointer.h>)
set(tyndall_precompiled_rendering_headers
  <vtkCamera.h>
  <vtkRenderWindow.h>
  <vtkRenderer.h>
  <vtkVolume.h>)

# The library and program targets that compile more than a few sources.
function (_tyndall_precompile target)
  if (NOT TARGET "${target}")
    return ()
  endif ()
  get_target_property(aliased "${target}" ALIASED_TARGET)
  if (aliased)
    set(target "${aliased}")
  endif ()
  target_precompile_headers("${target}" PRIVATE ${tyndall_precompiled_headers} ${ARGN})
endfunction ()

_tyndall_precompile(Tyndall::Core)
_tyndall_precompile(Tyndall::IO)
_tyndall_precompile(Tyndall::Rendering ${tyndall_precompiled_rendering_headers})
_tyndall_precompile(Tyndall::Application ${tyndall_precompiled_rendering_headers})
_tyndall_precompile(TyndallCoreCxxTests)
_tyndall_precompile(TyndallIOCxxTests)
_tyndall_precompile(TyndallRenderingCxxTests ${tyndall_precompiled_rendering_headers})
_tyndall_precompile(TyndallApplicationCxxTests ${tyndall_precompiled_rendering_headers})
