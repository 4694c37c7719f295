#include "viewer/viewer_script.h"

#include "core/error.h"
#include "core/untrusted_text.h"
#include "viewer/viewer_settings.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace glint::viewer {
namespace {

struct VerbName {
  std::string_view name;
  ScriptVerb verb;
  std::size_t arguments;
};
constexpr VerbName kVerbs[] = {
    {"set", ScriptVerb::set, 2},        {"frame", ScriptVerb::frame, 1},   {"play", ScriptVerb::play, 0},
    {"pause", ScriptVerb::pause, 0},    {"camera", ScriptVerb::camera, 2}, {"path", ScriptVerb::path, 0},
    {"wait", ScriptVerb::wait, 1},      {"screenshot", ScriptVerb::screenshot, 1},
    {"record", ScriptVerb::record, 1},  {"reload", ScriptVerb::reload, 0}, {"quit", ScriptVerb::quit, 0},
};

double parse_number(std::string_view what, const std::string& text, double min, double max) {
  double value = 0.0;
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || stop != text.data() + text.size() || !std::isfinite(value))
    fail("{}: \"{}\" is not a number", what, text);
  if (value < min || value > max) fail("{}: {} is outside {} to {}", what, text, min, max);
  return value;
}

// Checks one command against the options the script has set so far (updated by `set`).
void check_command(ScriptCommand& command, int frame_count, RenderOptions& options) {
  const std::vector<std::string>& a = command.arguments;
  switch (command.verb) {
    case ScriptVerb::set:
      if (a[0] == "scale") parse_number("scale", a[1], 0.1, 4.0);
      else if (a[0] == "speed") parse_number("speed", a[1], 0.01, 100.0);
      else if (a[0] == "light") {
        if (a[1] != "follow" && a[1] != "stay") fail("light: \"{}\" is not follow or stay", a[1]);
      } else if (a[0] == "view") {
        if (std::find(view_names().begin(), view_names().end(), a[1]) == view_names().end())
          fail("view: \"{}\" is not one of {}", a[1], fmt::join(view_names(), ", "));
      } else {
        set_viewer_setting(options, a[0], a[1]);
      }
      return;
    case ScriptVerb::frame: {
      const double frame = parse_number("frame", a[0], 0, frame_count - 1);
      if (frame != std::floor(frame)) fail("frame: {} is not a whole number", a[0]);
      break;
    }
    case ScriptVerb::camera:
      if (script_point("camera", a[0]) == script_point("target", a[1]))
        fail("camera: the camera and its target are the same point");
      return;
    case ScriptVerb::wait: parse_number("wait", a[0], 0.0, 3600.0); break;
    case ScriptVerb::screenshot: {
      const std::filesystem::path file(a[0]);
      if (file.extension() != ".png") fail("screenshot: {} does not end in .png", untrusted_text(a[0]));
      const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
      if (!std::filesystem::is_directory(folder)) fail("screenshot: folder {} does not exist", folder.string());
      break;
    }
    case ScriptVerb::record:
      if (a[0] != "start" && a[0] != "stop" && !a[0].starts_with("save="))
        fail("record: \"{}\" is not start, stop or save=FILE", untrusted_text(a[0]));
      return;
    default: return;
  }
  // The commands that render: the settings set so far must make a pipeline.
  (void)render_pipeline_settings(options);
}

}  // namespace

const std::vector<std::string>& view_names() {
  static const std::vector<std::string> names{"final",          "albedo",       "normals",           "positions",
                                              "depth",          "shadow_mask",  "ssr_reflection",    "failure_mask",
                                              "traced_reflection", "reflection", "difference"};
  return names;
}

vec3 script_point(std::string_view what, std::string_view text) { return parse_point_flag(what, text); }

std::vector<ScriptCommand> parse_viewer_script(const std::string& text, const std::filesystem::path& path,
                                               int frame_count, const RenderOptions& options) {
  std::vector<ScriptCommand> commands;
  RenderOptions checked = options;
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::vector<std::string> parts;
    for (std::string word; words >> word;) parts.push_back(word);
    if (parts.empty()) continue;
    try {
      const auto known = std::find_if(std::begin(kVerbs), std::end(kVerbs),
                                       [&](const VerbName& verb) { return verb.name == parts[0]; });
      if (known == std::end(kVerbs))
        fail("unknown command \"{}\"; commands: set, frame, play, pause, camera, path, wait, screenshot, record, "
             "reload, quit",
             untrusted_text(parts[0]));
      ScriptCommand command{number, known->verb, {parts.begin() + 1, parts.end()}};
      // `record save FILE` is two words after the verb; kept as one argument "save=FILE".
      if (command.verb == ScriptVerb::record && command.arguments.size() == 2 && command.arguments[0] == "save")
        command.arguments = {"save=" + command.arguments[1]};
      if (command.arguments.size() != known->arguments)
        fail("{} takes {} argument{}, got {}", known->name, known->arguments, known->arguments == 1 ? "" : "s",
             command.arguments.size());
      check_command(command, frame_count, checked);
      commands.push_back(std::move(command));
    } catch (const Error& error) {
      fail("{}:{}: {}", path.string(), number, error.what());
    }
  }
  return commands;
}

std::vector<ScriptCommand> load_viewer_script(const std::filesystem::path& path, int frame_count,
                                              const RenderOptions& options) {
  std::ifstream file(path, std::ios::binary);
  if (!file) fail("{}: cannot read the script", path.string());
  std::stringstream text;
  text << file.rdbuf();
  return parse_viewer_script(text.str(), path, frame_count, options);
}

}  // namespace glint::viewer
