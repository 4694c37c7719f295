#pragma once
// The folder a run writes into (`glint render --out <folder>`) and the names of the files in it, so
// that every command and script agrees on them:
//   frame_00042.png           the final image of frame 42 (5 digits; more when the frame needs them)
//   frame_00042_<view>.png    a debug view of frame 42 (e.g. "ssr_mask", "normals")
//   <name>                    anything else the run writes there (timings.csv, run.json, video.mp4)
// Zero-padded names sort in frame order in every file browser and in `ffmpeg -i frame_%05d.png`.
#include <filesystem>
#include <string_view>

namespace glint {

class OutputFolder {
public:
  // Creates the folder and its parents when missing. A path that exists and is not a folder (or
  // cannot be created) is a glint::Error naming it.
  explicit OutputFolder(std::filesystem::path path);

  const std::filesystem::path& path() const { return path_; }

  // A negative frame is a glint::Error.
  std::filesystem::path frame_path(int frame) const;
  // `view` must be non-empty and made of letters, digits, '_' and '-' only, so a name can neither
  // leave the folder nor be mistaken for another frame's file.
  std::filesystem::path debug_view_path(int frame, std::string_view view) const;
  // A plain file name in the folder; it must not be empty or contain '/', nor be "." or "..".
  std::filesystem::path file(std::string_view name) const;

private:
  std::filesystem::path path_;
};

}  // namespace glint
