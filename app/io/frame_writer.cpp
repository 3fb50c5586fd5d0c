#include "io/frame_writer.h"

#include <algorithm>

#include "core/clock.h"

namespace ms {

FrameWriter::FrameWriter(std::size_t capacity, DoneFn done, WriteFn write, int threads)
    : capacity_(capacity < 1 ? 1 : capacity),
      done_(std::move(done)),
      write_(write ? std::move(write) : WriteFn([](const WriteJob& j) {
        write_image(j.image, j.path, j.meta);
        if (j.state.empty()) return;
        // Only after its frame: a checkpoint means the frame is there. It
        // carries the frame's fingerprint, binding it to this frame and run.
        const auto fp = j.meta.find(kFingerprintKey);
        write_checkpoint(j.state_path, j.state, fp == j.meta.end() ? std::string() : fp->second);
        if (!j.drop.empty()) remove_checkpoint(j.drop);  // with its Cube A file
      })) {
  for (int i = 0; i < std::max(threads, 1); ++i) threads_.emplace_back([this] { run(); });
}

FrameWriter::~FrameWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void FrameWriter::rethrow_locked() {
  if (error_) std::rethrow_exception(error_);
}

double FrameWriter::push(WriteJob job) {
  const Clock::time_point t0 = Clock::now();
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < capacity_ || error_; });
  rethrow_locked();
  queue_.push_back(std::move(job));
  lock.unlock();
  changed_.notify_all();
  return seconds_since(t0);
}

void FrameWriter::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return (queue_.empty() && writing_ == 0) || error_; });
  rethrow_locked();
}

int FrameWriter::written() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return written_;
}

double FrameWriter::busy_seconds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return busy_;
}

void FrameWriter::run() {
  for (;;) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
    // After a failure the rest would most likely fail the same way (a full
    // disk); they are dropped, and the renderer stops at its next push.
    if (queue_.empty() || error_) return;
    WriteJob job = std::move(queue_.front());
    queue_.pop_front();
    ++writing_;
    lock.unlock();
    changed_.notify_all();  // a slot is free

    const Clock::time_point t0 = Clock::now();
    std::exception_ptr err;
    try {
      write_(job);
    } catch (...) {
      err = std::current_exception();
    }
    const double took = seconds_since(t0);
    if (!err && done_) {
      try {
        done_(job, took);
      } catch (...) {
        err = std::current_exception();
      }
    }
    lock.lock();
    --writing_;
    busy_ += took;
    if (err) error_ = err;
    else ++written_;
    lock.unlock();
    changed_.notify_all();
  }
}

}  // namespace ms
