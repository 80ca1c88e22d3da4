// keepFreedMemory(): what the process frees stays in its heap for the next allocations.
#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "jetbot_rl/ppo/freed_memory.h"

namespace jetbot_rl {
namespace ppo {
namespace {

TEST(FreedMemory, BlocksComeFromTheHeapAndStayThereWhenFreed) {
  ASSERT_EQ(keepFreedMemory(), "");
  // 96 MiB: more than glibc's own thresholds would ever keep (at most 32 MiB mapped blocks, a
  // heap trimmed above 64 MiB of free space at its top).
  constexpr std::size_t kBlock = std::size_t{1} << 20, kBlocks = 96;
  const std::size_t mapped_before = mallinfo2().hblkhd;  // libraries' own mapped blocks
  std::vector<void*> blocks;
  for (std::size_t i = 0; i < kBlocks; ++i) {
    void* block = std::malloc(kBlock);
    ASSERT_NE(block, nullptr);
    std::memset(block, 1, kBlock);
    blocks.push_back(block);
  }
  EXPECT_LT(mallinfo2().hblkhd, mapped_before + kBlock) << "blocks of 1 MiB were mapped one by one";
  for (void* block : blocks) std::free(block);
  EXPECT_GE(mallinfo2().fordblks, kBlocks * kBlock) << "the freed blocks went back to the system";
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
