#pragma once

#include <nodelet/nodelet.h>

#include <atomic>
#include <functional>
#include <thread>

namespace jetbot_rl {

/// A nodelet whose work is one function run on its own thread until it returns or the nodelet
/// is unloaded (which sets the stop flag the function watches): the learners and the benchmark
/// as nodelets run what their programs run.
class ThreadNodelet : public nodelet::Nodelet {
 public:
  ~ThreadNodelet() override {
    stop_.store(true);
    if (thread_.joinable()) thread_.join();
  }

 protected:
  /// Starts `work` (returning an exit code, logged when not 0).
  void start(std::function<int(const std::atomic<bool>&)> work) {
    thread_ = std::thread([this, work = std::move(work)] {
      const int code = work(stop_);
      if (code != 0) NODELET_ERROR("%s ended with exit code %d", getName().c_str(), code);
    });
  }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace jetbot_rl
