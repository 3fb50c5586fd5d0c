#include "core/memory_budget.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "core/error.h"

namespace ms {

double memory_budget() {
  double budget = 4.0 * 1024 * 1024 * 1024;
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) budget = std::min(budget, 0.5 * static_cast<double>(pages) * static_cast<double>(page));
  return budget;
}

std::string format_bytes(double bytes) {
  char buf[32];
  if (bytes >= 1024.0 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  else std::snprintf(buf, sizeof buf, "%.0f MiB", bytes / (1024.0 * 1024));
  return buf;
}

void check_input_memory(double bytes, const std::string& what, const std::string& file, const std::string& hint) {
  const double budget = memory_budget();
  if (bytes <= budget) return;
  fail_input(what + " needs " + format_bytes(bytes) + ", over the " + format_bytes(budget) + " memory budget", file, 0,
             {}, hint);
}

}  // namespace ms
