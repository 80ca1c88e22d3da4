// jetbot_rl_manager: a nodelet manager (nodelet::Loader, as `nodelet manager`) that stops on
// SIGINT and SIGTERM as the package's nodes do. Debian's `nodelet manager` shuts ROS down at
// SIGINT before it unloads its nodelets (the env's DELETEALL markers and the trainer's last
// messages never leave) and dies at once on SIGTERM; this one unloads them first, while ROS is
// up, then exits 0.
#include <nodelet/loader.h>
#include <ros/duration.h>
#include <ros/init.h>
#include <ros/spinner.h>

#include <atomic>

#include "jetbot_rl/ros/common/stop_signal.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "manager", ros::init_options::NoSigintHandler);
  const std::atomic<bool>& stop = jetbot_rl::installStopSignalHandlers();
  nodelet::Loader loader;  // load_nodelet, unload_nodelet, list on the manager's name
  ros::AsyncSpinner spinner(1);
  spinner.start();
  jetbot_rl::waitForStop(stop);
  loader.clear();  // each nodelet ends (and publishes its last messages) while ROS is up
  spinner.stop();
  ros::shutdown();
  return 0;
}
