#include "jetbot_rl/ros/common/stop_signal.h"

#include <ros/ros.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

namespace jetbot_rl {
namespace {

std::atomic<bool> g_stop{false};

void onSignal(int) { g_stop.store(true); }

}  // namespace

const std::atomic<bool>& installStopSignalHandlers() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  return g_stop;
}

void waitForStop(const std::atomic<bool>& stop, ros::CallbackQueue* queue) {
  const ros::WallDuration period(0.1);
  while (!stop.load() && ros::ok()) {
    if (queue) {
      queue->callAvailable(period);
    } else {
      period.sleep();
    }
  }
}

bool endParentLaunch(const std::atomic<bool>& stop) {
  const pid_t parent = getppid();
  std::ifstream cmdline("/proc/" + std::to_string(parent) + "/cmdline");
  const std::string command((std::istreambuf_iterator<char>(cmdline)),
                            std::istreambuf_iterator<char>());
  if (command.find("roslaunch") == std::string::npos) return false;
  std::fflush(stdout);  // our last lines before roslaunch's shutdown messages
  kill(parent, SIGINT);
  // roslaunch answers by stopping its nodes, this one first among them; a signal cannot wake a
  // condition variable, so the flag is checked every 20 ms.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!stop.load() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

}  // namespace jetbot_rl
