#include "app/image_writer_thread.h"

#include "core/error.h"
#include "core/log.h"

#include <algorithm>
#include <csignal>
#include <exception>

#include <pthread.h>

namespace glint {

ImageWriterThread::ImageWriterThread(std::size_t max_queued, std::size_t workers)
    : max_queued_(max_queued == 0 ? 1 : max_queued) {
  if (workers == 0) {
    const unsigned hardware = std::thread::hardware_concurrency();
    workers = std::clamp<std::size_t>(hardware > 1 ? hardware - 1 : 1, 1, 8);
  }
  for (std::size_t i = 0; i < workers; ++i) workers_.emplace_back([this] { work(); });
}

ImageWriterThread::~ImageWriterThread() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& worker : workers_) worker.join();
  if (error_ && !error_reported_) log_warning("{}", *error_);
}

void ImageWriterThread::write(std::filesystem::path path, ImageRgba8 image) {
  queue({std::move(path), std::move(image)});
}

void ImageWriterThread::write(std::filesystem::path path, ImageRgbaF image, ExrText text) {
  queue({std::move(path), LinearImage{std::move(image), std::move(text)}});
}

void ImageWriterThread::queue(Job job) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return error_ || queue_.size() < max_queued_; });
  if (error_) {
    error_reported_ = true;
    throw Error(*error_);
  }
  queue_.push_back(std::move(job));
  lock.unlock();
  changed_.notify_all();
}

void ImageWriterThread::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return error_ || (queue_.empty() && writing_ == 0); });
  if (error_) {
    error_reported_ = true;
    throw Error(*error_);
  }
}

void ImageWriterThread::work() {
  // SIGINT and SIGTERM go to the render loop's thread, which decides when to stop (core/interruption.h).
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, with every file written
    Job job = std::move(queue_.front());
    queue_.pop_front();
    ++writing_;
    lock.unlock();
    changed_.notify_all();  // room in the queue
    std::optional<std::string> failure;
    try {
      if (const auto* linear = std::get_if<LinearImage>(&job.image)) write_exr(job.path, linear->image, linear->text);
      else write_png(job.path, std::get<ImageRgba8>(job.image));
    } catch (const std::exception& error) {
      failure = error.what();
    }
    lock.lock();
    --writing_;
    if (failure && !error_) error_ = std::move(failure);
    if (error_) queue_.clear();  // nothing after a failure is written
    changed_.notify_all();
  }
}

}  // namespace glint
