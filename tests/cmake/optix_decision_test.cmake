# CTest OptixConfigureDecision (cmake -P, any machine): cmake/GlintOptix.cmake's glint_optix_decide
# turns the backend off with one line saying why when OptiX_INSTALL_DIR is unset, lacks
# include/optix.h, holds headers older than 9.0, or CUDA is off, and on only with 9.x headers and
# CUDA. Fake header folders are written under GLINT_TEST_WORK_DIR.
include(${GLINT_SOURCE_DIR}/cmake/GlintOptix.cmake)

set(_failures 0)
function(expect_decision label cuda_on dir want_on want_in_line)
  glint_optix_decide("${cuda_on}" "${dir}" _on _line _version)
  string(FIND "${_line}" "${want_in_line}" _at)
  string(FIND "${_line}" "\n" _newline)
  if(NOT "${_on}" STREQUAL "${want_on}" OR _at EQUAL -1 OR NOT _newline EQUAL -1)
    message(SEND_ERROR "${label}: got on=${_on} line \"${_line}\"; want on=${want_on} and a line with \"${want_in_line}\"")
  else()
    message(STATUS "${label}: ${_line}")
  endif()
endfunction()

function(write_fake_optix dir version)
  file(MAKE_DIRECTORY ${dir}/include)
  file(WRITE ${dir}/include/optix.h "#pragma once\n#define OPTIX_VERSION ${version}\n")
endfunction()

set(_work ${GLINT_TEST_WORK_DIR}/optix_decision)
file(REMOVE_RECURSE ${_work})
write_fake_optix(${_work}/optix-9.1 90100)
write_fake_optix(${_work}/optix-8.0 80000)
file(MAKE_DIRECTORY ${_work}/empty)

expect_decision("unset" ON "" OFF "OptiX backend off (OptiX_INSTALL_DIR is not set")
expect_decision("unset, no CUDA" OFF "" OFF "OptiX backend off (OptiX_INSTALL_DIR is not set")
expect_decision("no header" ON ${_work}/empty OFF "OptiX backend off (no include/optix.h in")
expect_decision("old headers" ON ${_work}/optix-8.0 OFF "glint needs OptiX 9.0 or newer")
expect_decision("CUDA off" OFF ${_work}/optix-9.1 OFF "OptiX backend off (it needs CUDA")
expect_decision("usable" ON ${_work}/optix-9.1 ON "OptiX backend on (OptiX 9.1.0 headers in")

glint_optix_decide(ON ${_work}/optix-9.1 _on _line _version)
if(NOT _version STREQUAL "90100")
  message(SEND_ERROR "version: got \"${_version}\", want 90100")
endif()
file(REMOVE_RECURSE ${_work})
