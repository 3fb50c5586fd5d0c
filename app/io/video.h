// Encoding a finished image sequence into a video with ffmpeg, when it is
// installed. ffmpeg is found on PATH and run directly (no shell), so
// patterns and paths need no quoting.
#pragma once
#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/deadline.h"

namespace ms {

// The full path of `program` in a PATH directory (executable regular
// file), or empty when there is none.
std::filesystem::path find_on_path(const std::string& program);

// Ends a child (ffmpeg): SIGTERM, two seconds to finish, then SIGKILL; reaped.
void end_child(pid_t pid);

// How a path reaches ffmpeg and ffprobe: an absolute "file:" URL, so that
// a name starting with '-' is never an option and one with ':' never a
// protocol ("v:1.mp4", "concat:a|b"). ffmpeg's file protocol takes the
// rest verbatim (no percent-decoding). Every call also passes
// `-protocol_whitelist file`, so that a playlist or concat script inside
// a file cannot reach anything but files.
std::string ffmpeg_file_url(const std::filesystem::path& p);

// Check before rendering that `out` can be written: a file name with an
// extension (ffmpeg picks the container by it), an existing writable
// directory. Throws bad_input naming --video.
void check_video_path(const std::filesystem::path& out);

struct VideoJob {
  std::filesystem::path ffmpeg;  // from find_on_path("ffmpeg")
  std::string pattern;           // printf-style frame pattern, as ffmpeg's image2 reads it
  int first_frame = 0;
  double fps = 24.0;
  std::filesystem::path output;
  Deadline deadline;                 // --timeout for the encoding (default: none)
  std::function<int()> stop_signal;  // non-zero: a signal asked us to stop (may be empty)
  int frames = 0;                    // how many: ffmpeg's own bound is encode_seconds(frames)
};

// The bound on one encoding, whatever --timeout says: 60 s, and 10 s a
// frame, far beyond what x264 needs even for 4K frames on a slow CPU, so
// that an ffmpeg that never finishes (a FIFO where a frame should be) does
// not hold the process for ever.
double encode_seconds(int frames);

// Run ffmpeg: H.264-compatible yuv420p (odd sizes padded to even), written
// to a temporary beside `output` and renamed into place, as images are.
// ffmpeg dies with us (PR_SET_PDEATHSIG), and on a timeout or a stop
// signal it is ended and its temporary removed. Returns false when stopped
// by a signal; throws system naming --video when ffmpeg cannot start,
// fails or outlasts encode_seconds(), and the --timeout error when the
// deadline passes.
bool encode_video(const VideoJob& job);

// Removes temporaries of `output` left by processes that no longer run
// (a killed encode); returns them.
std::vector<std::filesystem::path> remove_stale_video_temps(const std::filesystem::path& output);

}  // namespace ms
