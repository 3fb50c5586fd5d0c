// A bounded queue with writer threads: the render loop hands over each
// finished frame and goes on rendering the next while a writer encodes and
// writes it (atomically, through write_image). Bounded, so a slow disk holds
// the renderer back instead of filling memory with frames. More than one
// writer only pays where rendering is much faster than PNG encoding (a
// GPU); frames may then land out of order.
#pragma once
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "io/image.h"
#include "io/checkpoint.h"
#include "io/image_io.h"

namespace ms {

struct WriteJob {
  int frame = 0;
  Image image;
  std::filesystem::path path;
  ImageMetadata meta;
  // A stateful sequence's checkpoint (io/checkpoint.h), written after the
  // frame; then the one before it, `drop`, is removed.
  BufferState state;
  std::filesystem::path state_path, drop;
};

class FrameWriter {
 public:
  // Called on a writer thread for each job; the default is write_image.
  using WriteFn = std::function<void(const WriteJob&)>;
  // Called on a writer thread after each successful write, with the
  // seconds the write took (progress, stdout).
  using DoneFn = std::function<void(const WriteJob&, double seconds)>;

  // `capacity`: frames waiting (not counting those being written);
  // `threads`: writers working at once.
  explicit FrameWriter(std::size_t capacity = 4, DoneFn done = {}, WriteFn write = {}, int threads = 1);
  // Writes whatever is still queued (unless a write failed), then joins.
  ~FrameWriter();
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  // Queue a frame; blocks while `capacity` frames are waiting. Returns the
  // seconds it blocked. Rethrows the writer's first error, if any.
  double push(WriteJob job);
  // Wait until every queued frame is written; rethrows the first error.
  void finish();
  // Frames written so far.
  int written() const;
  // Total seconds the writer threads spent in WriteFn (summed).
  double busy_seconds() const;

 private:
  void run();
  void rethrow_locked();

  const std::size_t capacity_;
  const DoneFn done_;
  const WriteFn write_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<WriteJob> queue_;
  bool closing_ = false;
  int writing_ = 0;  // jobs out of the queue but not yet written
  int written_ = 0;
  double busy_ = 0.0;
  std::exception_ptr error_;
  std::vector<std::thread> threads_;  // last: started after every member above exists
};

}  // namespace ms
