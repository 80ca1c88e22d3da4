// keepFreedMemory(): glibc's allocator told to keep what the trainer frees (freed_memory.h).
#include "jetbot_rl/ppo/freed_memory.h"

#include <malloc.h>

namespace jetbot_rl {
namespace ppo {

std::string keepFreedMemory() {
  // 32 MiB is the largest mmap threshold glibc accepts (half its heap size on 64 bits); a rollout's
  // tensors are smaller. Setting either turns glibc's own adjustment of both off.
  constexpr int kMmapThreshold = 32 << 20;
  constexpr int kTrimThreshold = 1 << 30;
  if (mallopt(M_MMAP_THRESHOLD, kMmapThreshold) != 1) {
    return "mallopt(M_MMAP_THRESHOLD, " + std::to_string(kMmapThreshold) + ") failed";
  }
  if (mallopt(M_TRIM_THRESHOLD, kTrimThreshold) != 1) {
    return "mallopt(M_TRIM_THRESHOLD, " + std::to_string(kTrimThreshold) + ") failed";
  }
  return "";
}

}  // namespace ppo
}  // namespace jetbot_rl
