#pragma once
// `glint view --script FILE`: the viewer driven without input, for tests and demos. One command per
// line; blanks and everything after '#' are ignored:
//   set NAME VALUE        a renderer setting (viewer_settings.h) or scale 0.1..4, light follow|stay,
//                         view NAME (viewer_views.h), speed X (playback, 0.01..100)
//   frame N               go to walkthrough frame N (and stop playing)
//   play | pause          run the walkthrough at its frame rate times the speed, or stop
//   camera X,Y,Z X,Y,Z    fly: a free camera at the first point looking at the second
//   path                  back onto the walkthrough's camera
//   wait SECONDS          keep rendering (and playing) that long
//   screenshot FILE.png   the current frame and its debug views (FILE_<view>.png)
//   record start|stop     sample the flown camera twice a second
//   record save FILE      write the scene file with the recorded camera path
//   reload                load the scene file again
//   quit                  close the viewer (exit 0)
// The whole file is checked before the first command runs, settings combinations included, so a bad
// line is one glint::Error "FILE:LINE: ..." and nothing is written.
#include "app/render_command.h"

#include <filesystem>
#include <string>
#include <vector>

namespace glint::viewer {

enum class ScriptVerb { set, frame, play, pause, camera, path, wait, screenshot, record, reload, quit };

struct ScriptCommand {
  int line = 0;         // 1-based, for messages
  ScriptVerb verb = ScriptVerb::quit;
  std::vector<std::string> arguments;  // as written
};

// The names `set view` takes, in the panel's order.
const std::vector<std::string>& view_names();

// Parses and checks `text` (the contents of `path`, which names it in messages) for a scene of
// `frame_count` frames whose viewer starts with `options`.
std::vector<ScriptCommand> parse_viewer_script(const std::string& text, const std::filesystem::path& path,
                                               int frame_count, const RenderOptions& options);
// Reads and parses the file; glint::Error naming it when it cannot be read.
std::vector<ScriptCommand> load_viewer_script(const std::filesystem::path& path, int frame_count,
                                              const RenderOptions& options);

// "X,Y,Z" -> the point; glint::Error otherwise (parse_point_flag's message).
vec3 script_point(std::string_view what, std::string_view text);

}  // namespace glint::viewer
