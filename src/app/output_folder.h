#pragma once
// The folder a run writes into (`glint render --out <folder>`) and the names of the files in it, so
// that every command and script agrees on them:
//   frame_00042.png           the final image of frame 42 (5 digits; more when the frame needs them)
//   frame_00042_<view>.png    a debug view of frame 42 (e.g. "ssr_mask", "normals")
//   frame_00042.exr, ...      the same as linear EXRs (`glint render --format exr`)
//   <name>                    anything else the run writes there (timings.csv, run.json, video.mp4)
// Zero-padded names sort in frame order in every file browser and in `ffmpeg -i frame_%05d.png`.
//
// A folder that already holds a run's files (a run record, a timings table, frames or a video) would
// mix two runs' frames, so the caller says what to do with them (EarlierRun). A folder this object
// created stays only if something was written into it: when the run fails before its first file
// (a scene that does not build, a GPU that is missing), the destructor removes the empty folder again.
#include <filesystem>
#include <string_view>

namespace glint {

enum class EarlierRun {
  refuse,   // glint::Error naming the folder and the flag that allows it (render without --overwrite)
  replace,  // remove the earlier run's files first (render --overwrite); other files are kept
  keep,     // leave them (bench, which resumes the run in its folder)
};

class OutputFolder {
public:
  // Creates the folder and its parents when missing and checks that a file can be created in it. A path
  // that exists and is not a folder, cannot be created or is not writable is a glint::Error naming it.
  // `overwrite_flag` is the flag named in the refusal ("--overwrite").
  explicit OutputFolder(std::filesystem::path path, EarlierRun earlier = EarlierRun::keep,
                        std::string_view overwrite_flag = "--overwrite");
  ~OutputFolder();  // removes the folder if this object created it and it is still empty
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // A negative frame is a glint::Error. `extension`: "png" or "exr" (anything else is a glint::Error).
  std::filesystem::path frame_path(int frame, std::string_view extension = "png") const;
  // `view` must be non-empty and made of letters, digits, '_' and '-' only, so a name can neither
  // leave the folder nor be mistaken for another frame's file.
  std::filesystem::path debug_view_path(int frame, std::string_view view, std::string_view extension = "png") const;
  // A plain file name in the folder; it must not be empty or contain '/', nor be "." or "..".
  std::filesystem::path file(std::string_view name) const;

private:
  std::filesystem::path path_;
  bool created_ = false;
};

// Whether `name` is one of the files a run writes (run.json, timings.csv, scopes.csv, walkthrough.mp4, frame_*.png,
// frame_*.exr)
// or a temporary left by one (".<name>.tmp-<pid>-<n>", see core/atomic_file.h).
bool is_run_output_name(std::string_view name);

}  // namespace glint
