# CTest LibraryExampleBuilds, in script mode: installs the `development` component of the glint build
# GLINT_BUILD_DIR into GLINT_WORK_DIR/prefix, then configures, builds and runs the example project
# GLINT_EXAMPLE_DIR against it, as a user of the installed package would
# (find_package(glint CONFIG REQUIRED)). Fails on any step's non-zero exit or when the example's
# output lacks its closest hit. Compiles only the example, never glint.
foreach(var GLINT_BUILD_DIR GLINT_EXAMPLE_DIR GLINT_WORK_DIR GLINT_CXX_COMPILER GLINT_GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "GlintExampleTest.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "example test: ${what} failed (${result}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${GLINT_WORK_DIR})
set(prefix ${GLINT_WORK_DIR}/prefix)
run_step("cmake --install" ${CMAKE_COMMAND} --install ${GLINT_BUILD_DIR} --prefix ${prefix} --component development)

set(configure ${CMAKE_COMMAND} -S ${GLINT_EXAMPLE_DIR} -B ${GLINT_WORK_DIR}/build -G ${GLINT_GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${GLINT_CXX_COMPILER}
    # glint's own flags (the asan preset's sanitizers: the example links its instrumented library)
    "-DCMAKE_CXX_FLAGS=${GLINT_CXX_FLAGS}")
if(GLINT_CUDA_COMPILER)
  # The package looks the CUDA toolkit up again (glint::accel_cuda links its runtime).
  get_filename_component(cuda_bin ${GLINT_CUDA_COMPILER} DIRECTORY)
  get_filename_component(cuda_root ${cuda_bin} DIRECTORY)
  list(APPEND configure -DCUDAToolkit_ROOT=${cuda_root})
endif()
run_step("configuring the example" ${configure})
run_step("building the example" ${CMAKE_COMMAND} --build ${GLINT_WORK_DIR}/build)
run_step("running the example" ${GLINT_WORK_DIR}/build/accel_trace)
message(STATUS "example output:\n${step_output}")
if(NOT step_output MATCHES "closest hit: triangle 1 at t = 2")
  message(FATAL_ERROR "example test: unexpected output:\n${step_output}")
endif()

# With CUDA the example also built accel_trace_cuda (glint::accel_cuda): it must trace on a GPU, or
# say in one line that there is none.
if(EXISTS ${GLINT_WORK_DIR}/build/accel_trace_cuda)
  execute_process(COMMAND ${GLINT_WORK_DIR}/build/accel_trace_cuda RESULT_VARIABLE result OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(result EQUAL 0 AND out MATCHES "cuda lbvh: closest hit: triangle 1 at t = 2")
    message(STATUS "example output (GPU):\n${out}")
  elseif(NOT result EQUAL 0 AND err MATCHES "needs a CUDA GPU")
    message(STATUS "accel_trace_cuda built; not run here: ${err}")
  else()
    message(FATAL_ERROR "example test: accel_trace_cuda failed (${result}):\n${out}\n${err}")
  endif()
endif()
