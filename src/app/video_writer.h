#pragma once
// `glint render --video out.mp4`: rendered frames are piped to an ffmpeg child process as raw RGBA
// and encoded to H.264 (yuv420p, the pixel format every player accepts). glint links no codec
// library; ffmpeg is an optional program found on PATH.
//
// Like every glint output the video appears whole or not at all: ffmpeg writes a temporary sibling
// of the target (core/atomic_file.h) that finish() renames onto the target only after ffmpeg exited
// successfully. A writer destroyed without finish() (an error while rendering) kills ffmpeg and
// removes the temporary.
#include "core/image.h"

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace glint {

// The first executable file named `program` in the folders of $PATH, as a shell would find it.
std::optional<std::filesystem::path> find_program_on_path(std::string_view program);

class FfmpegVideoWriter {
public:
  // Starts ffmpeg. The container follows the extension: .mp4/.m4v, .mov or .mkv (anything else is an
  // error). Odd widths or heights are padded with one black column or row, since yuv420p needs even
  // sizes. Errors: no ffmpeg on PATH ("--video needs ffmpeg on PATH"), a missing folder, a size or
  // frame rate that is not positive.
  FfmpegVideoWriter(std::filesystem::path path, int width, int height, double fps);
  ~FfmpegVideoWriter();
  FfmpegVideoWriter(const FfmpegVideoWriter&) = delete;
  FfmpegVideoWriter& operator=(const FfmpegVideoWriter&) = delete;

  // Sends one frame (top row first, as rendered). A frame of another size is an error; so is ffmpeg
  // having stopped, with the tail of its error output in the message.
  void add_frame(const ImageRgba8& frame);

  // Ends the stream, waits for ffmpeg and checks its exit status (an error quotes the tail of its
  // output), then renames the video onto its path. A video without frames is an error.
  void finish();

  const std::filesystem::path& path() const { return path_; }
  int frame_count() const { return frames_; }

private:
  [[noreturn]] void fail_with_ffmpeg_output(std::string_view what);
  int wait_for_ffmpeg();  // reaps the child; returns its wait status
  void abandon();         // kills ffmpeg (if running) and removes the temporary

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  int width_;
  int height_;
  pid_t pid_ = -1;
  int pipe_fd_ = -1;  // ffmpeg's stdin
  int log_fd_ = -1;   // ffmpeg's stderr, an unlinked temporary file read back for error messages
  int frames_ = 0;
  bool finished_ = false;
};

}  // namespace glint
