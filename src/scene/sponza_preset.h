#pragma once
// The `sponza` preset: the example scene file scenes/sponza.scene.json (compiled into the binary)
// over the Dabrovic Sponza and creature meshes in ../shared/assets. Throws a glint::Error naming the
// folders it looked in when the assets are not there.
#include "scene/load_options.h"
#include "scene/scene.h"

namespace glint {

Scene make_sponza_preset(const LoadOptions& options = {});

}  // namespace glint
