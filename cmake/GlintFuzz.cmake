# Fuzzing glint's loaders with libFuzzer (docs/reliability.md, "Fuzzing").
#
# fuzz/fuzz_entries.cpp holds one entry function per target (OBJ+MTL, glTF/GLB, scene JSON, texture
# decoding). It is compiled into two kinds of build:
#   - every normal build: the library glint_fuzz_entries on top of `glint`, which the corpus replay test
#     (tests/fuzz/) links, so that every committed corpus and regression input runs in the test suite;
#   - the fuzz build (-DGLINT_FUZZ=ON, preset `fuzz`, clang): only the loaders' sources and the
#     parsers they use, instrumented with -fsanitize=fuzzer,address,undefined, and one libFuzzer
#     program per target, fuzz_<target>. Nothing else of glint is configured or built.

set(GLINT_FUZZ_TARGETS obj_mtl gltf scene_json texture)

# glint_fuzz_entries: the entry functions over `loaders`, the target providing glint's scene loaders.
function(glint_add_fuzz_entries loaders)
  add_library(glint_fuzz_entries STATIC ${CMAKE_SOURCE_DIR}/fuzz/fuzz_entries.cpp)
  target_include_directories(glint_fuzz_entries PUBLIC ${CMAKE_SOURCE_DIR}/fuzz)
  target_link_libraries(glint_fuzz_entries PUBLIC ${loaders})
  if(TARGET glint_warnings)
    target_link_libraries(glint_fuzz_entries PRIVATE glint_warnings)
  endif()
endfunction()

# The fuzz build: called instead of configuring glint.
function(glint_add_fuzz_build)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "GLINT_FUZZ needs clang (libFuzzer): configure with the `fuzz` preset "
                        "(CMAKE_CXX_COMPILER=clang++), not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  find_package(PkgConfig REQUIRED)
  find_package(glm REQUIRED)
  find_package(fmt REQUIRED)
  find_package(nlohmann_json 3 REQUIRED)
  find_package(TBB REQUIRED)  # src/accel's parallel builders: the one shared library the fuzzers link
  pkg_check_modules(STB REQUIRED stb)  # headers only: the implementation is compiled below

  # Everything here, glint's code and the parsers alike, runs under ASan and UBSan; the programs link
  # the sanitizer runtimes, libstdc++ and fmt statically so that they run on a machine without
  # Debian's libraries with only libtbb beside them (the GPU host: gpu-bundle.sh, run_fuzzers.sh).
  set(sanitize -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${sanitize})

  # src/accel, for the BVH the default walkthrough probes a loaded scene with (scene/scene_ray_probe.h;
  # not its Embree backend): sanitized but without libFuzzer's coverage, which is for the parsers.
  # Instrumented, its ray casts took most of each input's time.
  file(GLOB_RECURSE GLINT_FUZZ_ACCEL_SOURCES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/accel/*.cpp)
  add_library(glint_fuzz_accel STATIC ${GLINT_FUZZ_ACCEL_SOURCES})
  target_include_directories(glint_fuzz_accel PUBLIC ${CMAKE_SOURCE_DIR}/src)
  target_compile_definitions(glint_fuzz_accel PUBLIC GLM_FORCE_XYZW_ONLY GLM_ENABLE_EXPERIMENTAL
    GLINT_VERSION="${PROJECT_VERSION}")
  target_link_libraries(glint_fuzz_accel PUBLIC glm::glm fmt::fmt-header-only TBB::tbb)

  # The loaders: src/core and src/scene without the presets (the procedural atrium, the embedded
  # Sponza scene) and the deformer, which no loader calls, and the parsers' implementations.
  file(GLOB GLINT_FUZZ_LOADER_SOURCES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/core/*.cpp
       ${CMAKE_SOURCE_DIR}/src/scene/*.cpp)
  list(FILTER GLINT_FUZZ_LOADER_SOURCES EXCLUDE REGEX ".*/src/scene/(load_scene|presets|sponza_preset|sine_deformer)\\.cpp$")
  # OpenEXR (core/exr_image): render output and glint compare only, no loader reads EXRs.
  list(FILTER GLINT_FUZZ_LOADER_SOURCES EXCLUDE REGEX ".*/src/core/exr_image\\.cpp$")
  add_library(glint_fuzz_loaders STATIC ${GLINT_FUZZ_LOADER_SOURCES} ${CMAKE_SOURCE_DIR}/fuzz/third_party_implementations.cpp)
  target_compile_options(glint_fuzz_loaders PRIVATE -fsanitize=fuzzer-no-link)
  target_include_directories(glint_fuzz_loaders SYSTEM PRIVATE ${STB_INCLUDE_DIRS})
  target_link_libraries(glint_fuzz_loaders PUBLIC glint_fuzz_accel nlohmann_json::nlohmann_json)

  glint_add_fuzz_entries(glint_fuzz_loaders)
  foreach(name IN LISTS GLINT_FUZZ_TARGETS)
    add_executable(fuzz_${name} ${CMAKE_SOURCE_DIR}/fuzz/libfuzzer_main.cpp)
    target_compile_options(fuzz_${name} PRIVATE -fsanitize=fuzzer-no-link)
    target_compile_definitions(fuzz_${name} PRIVATE GLINT_FUZZ_TARGET="${name}")
    target_link_libraries(fuzz_${name} PRIVATE glint_fuzz_entries)
    target_link_options(fuzz_${name} PRIVATE -fsanitize=fuzzer ${sanitize} -static-libstdc++ -static-libgcc)
  endforeach()
endfunction()
