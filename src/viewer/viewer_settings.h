#pragma once
// The renderer settings `glint view` changes live, as one table: the panels draw a control per row,
// the script's `set NAME VALUE` looks rows up by name, and a change to any row rebuilds the frame
// loop (every pipeline setting is fixed at construction). Each row edits a field of RenderOptions,
// so the settings go through render_pipeline_settings exactly as `glint render`'s flags do; a
// setting the renderer gains needs one row here. Names are `glint render`'s flags without "--".
#include "app/render_command.h"

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace glint::viewer {

struct ViewerSetting {
  std::string_view name;  // "reflections", "ssr-max-steps", ...
  std::variant<std::string RenderOptions::*, int RenderOptions::*, float RenderOptions::*> field;
  std::vector<std::string> choices;  // for text fields: the values it takes
  double min = 0.0;                  // for numbers: the range, inclusive, within what the renderer takes
  double max = 0.0;
  const char* format = "%.3f";       // for fractional numbers: how the panel shows them (printf)
  std::string_view label = {};       // the panel's label when it says more than `name` (a unit); "" = name
};

// Every row, in the order the panels show them.
const std::vector<ViewerSetting>& viewer_settings();
// The row named `name`, or null.
const ViewerSetting* find_viewer_setting(std::string_view name);

// Sets setting `name` of `options` from its text form. glint::Error for an unknown name (listing the
// known ones), a value not among the choices (listing them) or a number that does not parse or lies
// outside the range. Combinations are checked later, by render_pipeline_settings.
void set_viewer_setting(RenderOptions& options, std::string_view name, std::string_view value);
// The current value of `setting` in `options` as text (numbers as `glint render` takes them).
std::string viewer_setting_text(const RenderOptions& options, const ViewerSetting& setting);

// Whether the two option sets agree on every row and on the image size.
bool same_viewer_settings(const RenderOptions& a, const RenderOptions& b);

// The ray tracing backends this binary and machine can run: cpu, embree and gl always; cuda and
// optix when built in and a CUDA GPU is present.
std::vector<std::string> available_backends();

}  // namespace glint::viewer
