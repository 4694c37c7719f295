# The Python module `glint` (python/, docs/python.md), built with Debian's pybind11 against Debian's
# Python 3. GLINT_PYTHON=AUTO (the default) builds it when pybind11 and the Python headers are found,
# ON requires them, OFF never looks. The module lands in <build>/python/ (PYTHONPATH=<build>/python);
# its tests (tests/python/, pytest) run in CTest with the same interpreter.
set(GLINT_PYTHON AUTO CACHE STRING "Build the Python module: AUTO (when pybind11 and Python 3 headers are found), ON or OFF")
set_property(CACHE GLINT_PYTHON PROPERTY STRINGS AUTO ON OFF)

function(glint_add_python_module)
  if(GLINT_PYTHON STREQUAL "OFF")
    message(STATUS "glint: Python module off (GLINT_PYTHON=OFF)")
    return()
  endif()
  # A sanitized module cannot be imported by an unsanitized interpreter (the runtime must load first).
  if(GLINT_PYTHON STREQUAL "AUTO" AND CMAKE_CXX_FLAGS MATCHES "-fsanitize")
    message(STATUS "glint: Python module off (sanitizer flags; GLINT_PYTHON=AUTO)")
    return()
  endif()
  # Debian's interpreter, where setup.sh installs numpy and pytest, rather than the first python3 on
  # PATH (a pyenv or virtualenv one may lack both, or have no headers); -DPython3_EXECUTABLE overrides.
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python 3 for the glint module and its tests")
  endif()
  find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
  if(Python3_FOUND)
    find_package(pybind11 CONFIG QUIET)
  endif()
  if(NOT Python3_FOUND OR NOT pybind11_FOUND)
    set(_why "needs pybind11-dev and python3-dev (scripts/setup.sh installs them)")
    if(GLINT_PYTHON STREQUAL "ON")
      message(FATAL_ERROR "glint: GLINT_PYTHON=ON but the Python module ${_why}")
    endif()
    message(STATUS "glint: Python module off (${_why}; GLINT_PYTHON=AUTO)")
    return()
  endif()
  message(STATUS "glint: Python module on (Python ${Python3_VERSION} ${Python3_EXECUTABLE}, pybind11 ${pybind11_VERSION})")

  file(GLOB _sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/python/*.cpp)
  # NO_EXTRAS: no link-time optimisation of the module (glint's static libraries are not LTO objects,
  # and an LTO link would cost minutes for nothing).
  pybind11_add_module(glint_python MODULE NO_EXTRAS ${_sources})
  set_target_properties(glint_python PROPERTIES OUTPUT_NAME glint LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/python
                                                INSTALL_RPATH_USE_LINK_PATH ON)  # the CUDA runtime, installed
  target_include_directories(glint_python PRIVATE ${CMAKE_SOURCE_DIR})  # "python/..." includes
  target_link_libraries(glint_python PRIVATE glint glint_warnings)
  # `cmake --install build --component python`: the module under the prefix where Debian's python3
  # looks for it with prefix /usr/local (lib/python3.X/dist-packages); GLINT_PYTHON_INSTALL_DIR changes it.
  set(GLINT_PYTHON_INSTALL_DIR "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages"
      CACHE STRING "Where `cmake --install` puts the Python module, under the prefix")
  install(TARGETS glint_python LIBRARY DESTINATION ${GLINT_PYTHON_INSTALL_DIR} COMPONENT python)

  if(GLINT_BUILD_TESTS)
    # tests/python/ with pytest; one CTest test per file keeps failures readable and runs them in parallel.
    file(GLOB _tests CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/python/test_*.py)
    foreach(_test IN LISTS _tests)
      get_filename_component(_name ${_test} NAME_WE)
      add_test(NAME Python.${_name}
               COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider ${_test}
               WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
      set_tests_properties(Python.${_name} PROPERTIES TIMEOUT 300
        ENVIRONMENT "PYTHONPATH=${CMAKE_BINARY_DIR}/python;GLINT_CLI=$<TARGET_FILE:glint_cli>;PYTHONDONTWRITEBYTECODE=1")
    endforeach()
  endif()
endfunction()
