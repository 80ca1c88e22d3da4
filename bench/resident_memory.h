#pragma once
// Resident memory of the running process, for the benchmarks' rss_kib figure.
#include <cstdio>

namespace jetbot_rl {

/// Resident set size of this process [KiB], from /proc (0 where unavailable).
inline long residentKib() {
  std::FILE* status = std::fopen("/proc/self/status", "r");
  if (!status) return 0;
  char line[256];
  long kib = 0;
  while (std::fgets(line, sizeof line, status)) {
    if (std::sscanf(line, "VmRSS: %ld kB", &kib) == 1) break;
  }
  std::fclose(status);
  return kib;
}

}  // namespace jetbot_rl
