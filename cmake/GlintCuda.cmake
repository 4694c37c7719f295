# CUDA is optional. GLINT_CUDA=AUTO turns it on when nvcc is found (on PATH, via CUDACXX, or in
# /usr/local/cuda/bin), ON requires it, OFF never looks. The GPU code is built for sm_90 (H100/H200)
# as SASS plus compute_90 PTX, so newer GPUs can JIT it.
set(GLINT_HAVE_CUDA OFF)
if(NOT GLINT_CUDA STREQUAL "OFF")
  if(NOT DEFINED CMAKE_CUDA_COMPILER AND NOT DEFINED ENV{CUDACXX} AND EXISTS /usr/local/cuda/bin/nvcc)
    find_program(_glint_nvcc nvcc)
    if(NOT _glint_nvcc)
      set(CMAKE_CUDA_COMPILER /usr/local/cuda/bin/nvcc)
    endif()
  endif()
  include(CheckLanguage)
  check_language(CUDA)
  if(CMAKE_CUDA_COMPILER)
    if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
      set(CMAKE_CUDA_ARCHITECTURES 90-real 90-virtual)
    endif()
    enable_language(CUDA)
    find_package(CUDAToolkit REQUIRED)
    # Device code shares accel/ headers (std::span etc.) with the host, so it is C++20 too. CMake
    # 3.25 does not know that nvcc 13 accepts -std=c++20, so it is told the flag.
    set(CMAKE_CUDA20_STANDARD_COMPILE_OPTION "-std=c++20")
    set(CMAKE_CUDA20_EXTENSION_COMPILE_OPTION "-std=c++20")
    set(CMAKE_CUDA_STANDARD 20)
    set(CMAKE_CUDA_STANDARD_REQUIRED ON)
    set(GLINT_HAVE_CUDA ON)
    message(STATUS "glint: CUDA on (nvcc ${CMAKE_CUDA_COMPILER_VERSION}, architectures ${CMAKE_CUDA_ARCHITECTURES})")
  elseif(GLINT_CUDA STREQUAL "ON")
    message(FATAL_ERROR "glint: GLINT_CUDA=ON but no CUDA compiler (nvcc) was found; install the CUDA toolkit or set CUDACXX")
  else()
    message(STATUS "glint: CUDA off (no nvcc found; GLINT_CUDA=AUTO)")
  endif()
else()
  message(STATUS "glint: CUDA off (GLINT_CUDA=OFF)")
endif()

# src/cuda/ in two parts. The device BVHs and tracing over accel's triangles and rays (GPU builders,
# refit, SAH, the trace kernels, device query, accel-bench's GPU structures) need nothing but accel/
# and core/: with CUDA on they form glint_accel_cuda (glint::accel_cuda, installed beside
# glint::accel). The files that need the scene model, the RayTracer interface or GL (the cuda ray
# tracer backend, GL buffer interop, the GPU deformers; GLINT_CUDA_SCENE_REGEX) stay in glint, as do
# the `*_off.cpp` twins (empty when CUDA is on, the whole answer when it is off).
set(GLINT_CUDA_SCENE_REGEX ".*/src/cuda/(cuda_ray_tracer|gl_buffer_interop|gpu_scene_deformer|gpu_sine_deformer)[._].*")

# Sets OUT to glint_accel_cuda's sources (empty when CUDA is off: every src/cuda/*.cpp is then glint's).
function(glint_accel_cuda_sources out)
  set(_sources "")
  if(GLINT_HAVE_CUDA)
    file(GLOB _sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/cuda/*.cu ${CMAKE_SOURCE_DIR}/src/cuda/*.cpp)
    list(FILTER _sources EXCLUDE REGEX "${GLINT_CUDA_SCENE_REGEX}")
    list(FILTER _sources EXCLUDE REGEX ".*_off\\.cpp$")
  endif()
  set(${out} ${_sources} PARENT_SCOPE)
endfunction()

# The CUDA settings of a target holding .cu files: the runtime, nvcc's flags, GLINT_HAVE_CUDA=0/1
# for the C++ side (PUBLIC: headers test it).
function(glint_use_cuda target)
  if(GLINT_HAVE_CUDA)
    target_link_libraries(${target} PUBLIC CUDA::cudart)
    target_compile_definitions(${target} PUBLIC GLINT_HAVE_CUDA=1)
    target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:CUDA>:--expt-relaxed-constexpr -Xcompiler=-Wall>)
  else()
    target_compile_definitions(${target} PUBLIC GLINT_HAVE_CUDA=0)
  endif()
endfunction()

# Adds the scene-level src/cuda/*.cu (GLINT_CUDA_SCENE_REGEX) to TARGET when CUDA is on.
function(glint_add_cuda_sources target)
  glint_use_cuda(${target})
  if(GLINT_HAVE_CUDA)
    file(GLOB _cu CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/cuda/*.cu)
    list(FILTER _cu INCLUDE REGEX "${GLINT_CUDA_SCENE_REGEX}")
    target_sources(${target} PRIVATE ${_cu})
  endif()
endfunction()

# Source properties (directory-wide, whichever target compiles the file).
# The GPU deformer must pose meshes like the CPU one within 1e-5 (tests/cuda/gpu_deformer_test):
# the host code is compiled without contracting a * b + c into fused multiply-adds (ISO C++
# mode), so its device twin is too; fused normals differed by up to 5e-5 on an H100.
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/cuda/gpu_sine_deformer.cu PROPERTIES COMPILE_OPTIONS "-fmad=false")
# The same for the closest-hit kernel: a ray moved into an instance's space and tested against a
# triangle with the host's roundings gives the cpu backend's hits bit for bit; with contraction a
# grazing ray's t differed by 1 % (1 of 100k reflection rays on the reduced atrium).
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/cuda/gpu_trace.cu PROPERTIES COMPILE_OPTIONS "-fmad=false")
# And for the reflection hits' shadow rays, so they equal rt::hit_shadow_ray on the host bit for bit.
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/cuda/gpu_hit_shadow_rays.cu PROPERTIES COMPILE_OPTIONS "-fmad=false")
