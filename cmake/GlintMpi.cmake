# MPI is optional: `mpirun -np N glint bench|render ...` splits the work over ranks (docs/scale-out.md).
# GLINT_MPI=AUTO turns it on when find_package(MPI COMPONENTS C) finds an MPI (Debian's libopenmpi-dev),
# ON requires it, OFF never looks. Only the C interface is used (C++ bindings are gone from MPI 3).
#
# The code lives in src/app/mpi/: a file that includes <mpi.h> has an `<name>_off.cpp` twin that
# answers "one rank" when MPI is off, as src/cuda/ does for CUDA; glint_filter_mpi_sources keeps one
# of each pair.
set(GLINT_MPI AUTO CACHE STRING "Split bench and render over MPI ranks: AUTO (when an MPI is found), ON or OFF")
set_property(CACHE GLINT_MPI PROPERTY STRINGS AUTO ON OFF)

set(GLINT_HAVE_MPI OFF)
if(NOT GLINT_MPI STREQUAL "OFF")
  enable_language(C)  # FindMPI's C component probes with the C compiler (glint itself is C++)
  find_package(MPI COMPONENTS C QUIET)
  if(MPI_C_FOUND)
    set(GLINT_HAVE_MPI ON)
    message(STATUS "glint: MPI on (MPI ${MPI_C_VERSION}, ${MPIEXEC_EXECUTABLE})")
  elseif(GLINT_MPI STREQUAL "ON")
    message(FATAL_ERROR "glint: GLINT_MPI=ON but no MPI was found; install libopenmpi-dev and openmpi-bin "
                        "(scripts/setup.sh does)")
  else()
    message(STATUS "glint: MPI off (no MPI found; GLINT_MPI=AUTO; libopenmpi-dev turns it on)")
  endif()
else()
  message(STATUS "glint: MPI off (GLINT_MPI=OFF)")
endif()

# Removes from the list named LIST_VAR, of src/app/mpi/ files, the half of each `<name>.cpp` /
# `<name>_off.cpp` pair that this build does not use.
function(glint_filter_mpi_sources list_var)
  set(_sources ${${list_var}})
  file(GLOB _off CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/app/mpi/*_off.cpp)
  foreach(_off_file IN LISTS _off)
    string(REGEX REPLACE "_off\\.cpp$" ".cpp" _on_file "${_off_file}")
    if(GLINT_HAVE_MPI)
      list(REMOVE_ITEM _sources "${_off_file}")
    else()
      list(REMOVE_ITEM _sources "${_on_file}")
    endif()
  endforeach()
  set(${list_var} ${_sources} PARENT_SCOPE)
endfunction()

# Links MPI into TARGET when on. Only the files of src/app/mpi/ that include <mpi.h> (those with an
# `_off.cpp` twin) see its headers and definitions: the rest of glint's compile lines stay as they
# are, so turning MPI on or off rebuilds those few files only. C++ code asks mpi::built_with_mpi().
function(glint_use_mpi target)
  if(NOT GLINT_HAVE_MPI)
    return()
  endif()
  target_link_libraries(${target} PUBLIC ${MPI_C_LIBRARIES})
  file(GLOB _off CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/app/mpi/*_off.cpp)
  set(_options "")
  foreach(_dir IN LISTS MPI_C_INCLUDE_DIRS)
    list(APPEND _options "-isystem" "${_dir}")  # system headers: glint's warnings are not theirs
  endforeach()
  foreach(_off_file IN LISTS _off)
    string(REGEX REPLACE "_off\\.cpp$" ".cpp" _on_file "${_off_file}")
    # Open MPI's and MPICH's mpi.h would pull in their deprecated C++ bindings otherwise.
    set_source_files_properties(${_on_file} PROPERTIES COMPILE_OPTIONS "${_options}"
                                COMPILE_DEFINITIONS "OMPI_SKIP_MPICXX=1;MPICH_SKIP_MPICXX=1")
  endforeach()
endfunction()

# CTest tests of the split (tests/mpi/mpi_scaleout_test.py): `mpirun -np 2` and `-np 3` of
# `glint bench --quick` and of a 12-frame render against one process, a rank made to fail, and an
# interrupted run resumed.
# Without MPI they are registered all the same and report themselves skipped (exit 77).
function(glint_add_mpi_tests)
  find_package(Python3 COMPONENTS Interpreter QUIET)
  if(NOT Python3_Interpreter_FOUND)
    return()
  endif()
  set(_mpirun "")
  if(GLINT_HAVE_MPI)
    set(_mpirun "${MPIEXEC_EXECUTABLE}")
  endif()
  foreach(_case IN ITEMS bench_np2 bench_np3 render_np2 render_np3 failed_rank interrupted)
    add_test(NAME Mpi.${_case}
             COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/mpi/mpi_scaleout_test.py ${_case}
             WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    set_tests_properties(Mpi.${_case} PROPERTIES TIMEOUT 600 SKIP_RETURN_CODE 77
      ENVIRONMENT "GLINT_CLI=$<TARGET_FILE:glint_cli>;GLINT_MPIRUN=${_mpirun};GLINT_TEST_WORK=${CMAKE_BINARY_DIR}/mpi-tests")
  endforeach()
endfunction()
