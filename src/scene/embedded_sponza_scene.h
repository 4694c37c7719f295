#pragma once
// scenes/sponza.scene.json compiled into the binary (generated from cmake/embedded_sponza_scene.cpp.in
// at configure time), so the `sponza` preset works from any directory without the source tree.
#include <string_view>

namespace glint {

extern const std::string_view kEmbeddedSponzaSceneText;
// Where the file was in the source tree at build time: the base of its relative "assets" path.
extern const std::string_view kEmbeddedSponzaScenePath;

}  // namespace glint
