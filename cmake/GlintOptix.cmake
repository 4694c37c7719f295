# The optional OptiX backend (src/optix/, docs/optix.md), pbrt-v4 style: OptiX is header-only at build
# time and the NVIDIA driver has its runtime, so the backend is built when the cache path
# OptiX_INSTALL_DIR (default: the environment variable of the same name) holds include/optix.h and
# CUDA is on. Otherwise configuration prints one line saying the backend is off and why, and the rest
# of glint builds as before (make_ray_tracer("optix") then explains how to enable it).
#
# The decision is the function glint_optix_decide, which runs in script mode too
# (tests/cmake/optix_decision_test.cmake checks it with `cmake -P`); in script mode this file defines
# it and returns.

# glint_optix_decide(<cuda_on> <install_dir> <out_on> <out_line> <out_version>):
# <out_on> = ON when the backend can be built, <out_line> = the one configure line saying so or why
# not, <out_version> = the headers' OPTIX_VERSION (e.g. 90100), empty when unknown.
function(glint_optix_decide cuda_on install_dir out_on out_line out_version)
  set(_on OFF)
  set(_version "")
  set(_enable "pass -DOptiX_INSTALL_DIR=<OptiX SDK folder> (or set the environment variable OptiX_INSTALL_DIR) to build it")
  if("${install_dir}" STREQUAL "")
    set(_line "glint: OptiX backend off (OptiX_INSTALL_DIR is not set; ${_enable})")
  elseif(NOT EXISTS "${install_dir}/include/optix.h")
    set(_line "glint: OptiX backend off (no include/optix.h in OptiX_INSTALL_DIR=${install_dir})")
  else()
    file(STRINGS "${install_dir}/include/optix.h" _define REGEX "^#define[ \t]+OPTIX_VERSION[ \t]+[0-9]+")
    string(REGEX MATCH "[0-9]+$" _version "${_define}")
    if(_version STREQUAL "")
      set(_line "glint: OptiX backend off (no OPTIX_VERSION in ${install_dir}/include/optix.h)")
    elseif(_version LESS 90000)
      set(_line "glint: OptiX backend off (${install_dir} has OptiX ${_version}; glint needs OptiX 9.0 or newer)")
    elseif(NOT cuda_on)
      set(_line "glint: OptiX backend off (it needs CUDA, which is off: see GLINT_CUDA)")
    else()
      math(EXPR _major "${_version} / 10000")
      math(EXPR _minor "${_version} % 10000 / 100")
      math(EXPR _micro "${_version} % 100")
      set(_on ON)
      set(_line "glint: OptiX backend on (OptiX ${_major}.${_minor}.${_micro} headers in ${install_dir})")
    endif()
  endif()
  set(${out_on} ${_on} PARENT_SCOPE)
  set(${out_line} "${_line}" PARENT_SCOPE)
  set(${out_version} "${_version}" PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()

set(OptiX_INSTALL_DIR "$ENV{OptiX_INSTALL_DIR}" CACHE PATH
    "OptiX SDK folder (holding include/optix.h) for the optix backend; empty: the backend is off")
glint_optix_decide("${GLINT_HAVE_CUDA}" "${OptiX_INSTALL_DIR}" GLINT_HAVE_OPTIX _glint_optix_line GLINT_OPTIX_VERSION)
message(STATUS "${_glint_optix_line}")

# Adds src/optix/*.cpp and the embedded device programs (src/optix/device/*.cu, one module each) to
# TARGET when the backend is on, and defines GLINT_HAVE_OPTIX=0/1 for the C++ side.
function(glint_add_optix_sources target)
  if(NOT GLINT_HAVE_OPTIX)
    target_compile_definitions(${target} PUBLIC GLINT_HAVE_OPTIX=0)
    return()
  endif()
  file(GLOB _host_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/optix/*.cpp)
  file(GLOB _device_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/optix/device/*.cu)
  file(GLOB _shared_headers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/optix/*.h)
  set(_modules "")
  foreach(_source IN LISTS _device_sources)
    get_filename_component(_name ${_source} NAME_WE)
    set(_module ${CMAKE_BINARY_DIR}/optix/${_name}.optixir)
    # OptiX-IR, OptiX's preferred input (nvcc 13's -ptx output fails its own ptxas check on OptiX's
    # intrinsics), for sm_90 (H100/H200) like the CUDA code; OptiX compiles it for the GPU it runs on.
    add_custom_command(
      OUTPUT ${_module}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/optix
      COMMAND ${CMAKE_CUDA_COMPILER} --optix-ir -arch=sm_90 -std=c++20
              -I${OptiX_INSTALL_DIR}/include -I${CMAKE_SOURCE_DIR}/src -o ${_module} ${_source}
      DEPENDS ${_source} ${_shared_headers}
      COMMENT "Compiling OptiX device programs ${_name}.cu to OptiX-IR"
      VERBATIM)
    list(APPEND _modules ${_module})
  endforeach()
  set(_embedded ${CMAKE_BINARY_DIR}/generated/embedded_optix_modules.cpp)
  add_custom_command(
    OUTPUT ${_embedded}
    COMMAND ${CMAKE_COMMAND} "-DGLINT_EMBED_INPUTS=${_modules}" -DGLINT_EMBED_OUTPUT=${_embedded}
            -P ${CMAKE_SOURCE_DIR}/cmake/GlintEmbedOptixModules.cmake
    DEPENDS ${_modules} ${CMAKE_SOURCE_DIR}/cmake/GlintEmbedOptixModules.cmake
    COMMENT "Embedding the OptiX device programs"
    VERBATIM)
  target_sources(${target} PRIVATE ${_host_sources} ${_embedded})
  target_include_directories(${target} SYSTEM PRIVATE ${OptiX_INSTALL_DIR}/include)
  target_compile_definitions(${target} PUBLIC GLINT_HAVE_OPTIX=1)
endfunction()
