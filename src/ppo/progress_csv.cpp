#include "jetbot_rl/ppo/progress_csv.h"

#include <filesystem>
#include <sstream>
#include <vector>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace ppo {

ProgressCsv::ProgressCsv(const std::string& path, std::int64_t keep_until,
                         const std::vector<std::string>& obs_names)
    : path_(path) {
  std::vector<std::string> kept;
  if (keep_until >= 0 && std::filesystem::exists(path)) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // header: rewritten below
    while (std::getline(in, line)) {
      std::istringstream s(line);
      long long iteration = 0;
      if (s >> iteration && iteration <= keep_until) kept.push_back(line);
    }
  }
  out_.open(path, std::ios::out | std::ios::trunc);
  if (!out_) throw Error("cannot write " + path);
  out_ << csvHeader(obs_names) << "\n";
  for (const std::string& line : kept) out_ << line << "\n";
  out_.flush();
}

void ProgressCsv::append(const IterationStats& stats) {
  out_ << csvRow(stats) << "\n";
  out_.flush();
  if (!out_) throw Error("cannot write " + path_);
}

}  // namespace ppo
}  // namespace jetbot_rl
