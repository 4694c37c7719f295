# `cmake --install` (docs/library.md): the `glint` CMake package with glint::accel (the acceleration
# structures and CPU tracing: no GL, no window system, no Embree) and, in a build with CUDA,
# glint::accel_cuda (the device BVHs and tracing); headers under include/glint/ in src/'s layout, so
# a consumer writes #include "accel/builders/builder.h" as glint does. Components: `development`
# (libraries, headers, the package files), `runtime` (the glint command) and `python` (the module,
# cmake/GlintPython.cmake). The example project
# examples/accel_trace builds against an install in the test suite (LibraryExampleBuilds).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GLINT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/glint)
set(GLINT_EXPORTED_TARGETS glint_accel)
if(GLINT_HAVE_CUDA)
  list(APPEND GLINT_EXPORTED_TARGETS glint_accel_cuda)
endif()
install(TARGETS ${GLINT_EXPORTED_TARGETS} EXPORT glintTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)

# Headers: accel/ with its subfolders (no Embree: its wrapper lives in rt/embree/), the core/ headers
# accel/ and cuda/ include, and with CUDA the src/cuda/ headers of glint_accel_cuda (not those of the
# files that stay in glint).
install(DIRECTORY ${CMAKE_SOURCE_DIR}/src/accel/ DESTINATION include/glint/accel COMPONENT development
        FILES_MATCHING PATTERN "*.h")
install(FILES ${CMAKE_SOURCE_DIR}/src/core/error.h ${CMAKE_SOURCE_DIR}/src/core/error_type.h
              ${CMAKE_SOURCE_DIR}/src/core/enum_names.h ${CMAKE_SOURCE_DIR}/src/core/stopwatch.h
              ${CMAKE_SOURCE_DIR}/src/core/math.h
        DESTINATION include/glint/core COMPONENT development)
if(GLINT_HAVE_CUDA)
  file(GLOB _glint_cuda_headers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/cuda/*.h ${CMAKE_SOURCE_DIR}/src/cuda/*.cuh)
  list(FILTER _glint_cuda_headers EXCLUDE REGEX "${GLINT_CUDA_SCENE_REGEX}")
  install(FILES ${_glint_cuda_headers} DESTINATION include/glint/cuda COMPONENT development)
endif()

install(EXPORT glintTargets NAMESPACE glint:: DESTINATION ${GLINT_INSTALL_CMAKEDIR} COMPONENT development)
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/glintConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/generated/glintConfig.cmake
                              INSTALL_DESTINATION ${GLINT_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/generated/glintConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/generated/glintConfig.cmake ${CMAKE_BINARY_DIR}/generated/glintConfigVersion.cmake
        DESTINATION ${GLINT_INSTALL_CMAKEDIR} COMPONENT development)

install(TARGETS glint_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)

# The example project against an install of this build (the development component into a folder of
# the build tree): configure, build and run examples/accel_trace. Only the small example is
# compiled; glint itself is already built (the test depends on nothing being rebuilt).
if(GLINT_BUILD_TESTS)
  add_test(NAME LibraryExampleBuilds
           COMMAND ${CMAKE_COMMAND} -DGLINT_BUILD_DIR=${CMAKE_BINARY_DIR}
                   -DGLINT_EXAMPLE_DIR=${CMAKE_SOURCE_DIR}/examples/accel_trace
                   -DGLINT_WORK_DIR=${CMAKE_BINARY_DIR}/example-test
                   -DGLINT_CXX_COMPILER=${CMAKE_CXX_COMPILER}
                   "-DGLINT_CXX_FLAGS=${CMAKE_CXX_FLAGS}"
                   -DGLINT_CUDA_COMPILER=${CMAKE_CUDA_COMPILER}
                   -DGLINT_GENERATOR=${CMAKE_GENERATOR}
                   -P ${CMAKE_SOURCE_DIR}/cmake/GlintExampleTest.cmake)
  set_tests_properties(LibraryExampleBuilds PROPERTIES TIMEOUT 300)
endif()
