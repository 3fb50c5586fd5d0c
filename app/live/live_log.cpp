#include "live/live_log.h"

#include "core/error.h"

namespace ms::live {

LiveLog::LiveLog(const std::filesystem::path& file) {
  if (file.empty()) return;
  file_ = std::fopen(file.c_str(), "w");
  if (!file_) fail_input("cannot create the log file", file.string(), 0, "--log");
}

LiveLog::~LiveLog() {
  if (file_ && file_ != stderr) std::fclose(file_);
}

void LiveLog::line(const std::string& text) {
  std::fprintf(file_, "%s\n", text.c_str());
  std::fflush(file_);
}

}  // namespace ms::live
