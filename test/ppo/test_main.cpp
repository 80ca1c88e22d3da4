#include <gtest/gtest.h>
#include <torch/utils.h>

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  torch::set_num_threads(1);  // deterministic and polite on a shared 2-core machine
  return RUN_ALL_TESTS();
}
