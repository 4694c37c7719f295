// The fuzz build compiles the implementations of the header-only parsers glint's loaders use, from
// Debian's headers (libstb-dev, libtinygltf-dev, libtinyobjloader-dev) with their default settings,
// as Debian builds libstb.so, libtinygltf.so and libtinyobjloader.so for the normal build. Compiled
// here they are instrumented like glint's own code: libFuzzer sees their branches, ASan/UBSan their
// memory, and the fuzzers link without those shared libraries.
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

// tiny_gltf.h would include stb's headers again by their bare names; they are in already.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_INCLUDE_STB_IMAGE_WRITE
#include <tiny_gltf.h>
