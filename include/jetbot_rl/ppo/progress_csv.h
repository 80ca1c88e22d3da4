#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "jetbot_rl/ppo/iteration_stats.h"

namespace jetbot_rl {
namespace ppo {

/// progress.csv of a run: the header, then one flushed row per iteration.
class ProgressCsv {
 public:
  /// Creates `path` with the header; when `keep_until` >= 0 and the file exists (a resumed run),
  /// keeps its rows up to iteration `keep_until` and appends after them. `obs_names` name the
  /// obs_mean_* columns. Throws Error.
  ProgressCsv(const std::string& path, std::int64_t keep_until = -1,
              const std::vector<std::string>& obs_names = {});

  /// Appends and flushes one row.
  void append(const IterationStats& stats);

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace ppo
}  // namespace jetbot_rl
