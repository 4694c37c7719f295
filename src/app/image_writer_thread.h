#pragma once
// Encodes and writes image files (8-bit PNGs, linear EXRs) on worker threads, so a render loop hands
// a frame's image over and goes on with the next frame instead of spending 70-300 ms per 720p frame
// in the encoder. The queue is bounded (write() waits while it is full), so memory stays flat however
// far the encoders fall behind. Each file is written with write_png or write_exr (a temporary renamed
// when complete), so a run that stops leaves whole files only; finish() waits for every queued file.
//
// An error on the worker (a full disk, a folder gone) stops it: the next write() or finish() throws
// that glint::Error, one line naming the file, and later images are dropped.
//
//   ImageWriterThread writer;
//   for (...) writer.write(out.frame_path(frame), std::move(image));
//   writer.finish();  // every file is on disk, or the first error is thrown
#include "core/exr_image.h"
#include "core/image.h"

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

namespace glint {

class ImageWriterThread {
public:
  // `workers` 0: one per hardware thread but one (the render loop's), at least one, at most 8.
  explicit ImageWriterThread(std::size_t max_queued = 4, std::size_t workers = 0);
  // Finishes the queued files (errors are only logged here: call finish() to see them).
  ~ImageWriterThread();
  ImageWriterThread(const ImageWriterThread&) = delete;
  ImageWriterThread& operator=(const ImageWriterThread&) = delete;

  // Queues `image` for `path` as a PNG; waits while max_queued files are waiting. Throws the worker's error.
  void write(std::filesystem::path path, ImageRgba8 image);
  // The same for a linear image as an EXR (write_exr) with string attributes `text`.
  void write(std::filesystem::path path, ImageRgbaF image, ExrText text = {});
  // Waits until every queued file is written; throws the worker's first error. Idempotent.
  void finish();

private:
  struct LinearImage {
    ImageRgbaF image;
    ExrText text;
  };
  struct Job {
    std::filesystem::path path;
    std::variant<ImageRgba8, LinearImage> image;
  };
  void queue(Job job);
  void work();

  std::size_t max_queued_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  std::size_t writing_ = 0;  // files the workers took off the queue and are writing
  bool stopping_ = false;
  std::optional<std::string> error_;  // the first failure's message
  bool error_reported_ = false;       // thrown by write() or finish(), so the destructor stays quiet
  std::vector<std::thread> workers_;
};

}  // namespace glint
