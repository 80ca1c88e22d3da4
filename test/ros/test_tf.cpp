// tf frames of env_0 (and up to tf_envs envs): world -> env_<i>/<link> for every URDF link, at the
// env's origin on the grid, stamped with simulation time.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <string>
#include <vector>

#include "jetbot_rl/Reset.h"
#include "jetbot_rl/Step.h"

namespace {

const std::vector<std::string> kLinks{"base_link", "left_wheel", "right_wheel", "caster_link"};

TEST(EnvTf, FramesOfTheFirstEnvs) {
  ros::NodeHandle nh;
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);  // spins its own thread
  ros::ServiceClient reset = nh.serviceClient<jetbot_rl::Reset>("/jetbot_env/reset");
  ros::ServiceClient step = nh.serviceClient<jetbot_rl::Step>("/jetbot_env/step");
  ASSERT_TRUE(reset.waitForExistence(ros::Duration(60.0)));
  ASSERT_TRUE(step.waitForExistence(ros::Duration(60.0)));

  jetbot_rl::Reset r;
  ASSERT_TRUE(reset.call(r));
  ASSERT_TRUE(r.response.success);
  const std::uint32_t num_envs = r.response.state.num_envs;
  ASSERT_EQ(num_envs, 6u);
  std::uint64_t current = r.response.state.step;

  // Lockstep: tf goes out with steps (at most tf_rate Hz of simulation time), so step until the
  // listener has every frame of env_0 and env_3 (tf_envs = 4).
  auto all_frames = [&]() {
    for (const std::string env : {"env_0/", "env_3/"}) {
      for (const std::string& link : kLinks) {
        if (!buffer.canTransform("world", env + link, ros::Time(0))) return false;
      }
    }
    return true;
  };
  jetbot_rl::Step s;
  s.request.actions.velocities.assign(2 * num_envs, 4.0f);
  for (int i = 0; i < 600 && !all_frames(); ++i) {
    s.request.actions.step = current;
    ASSERT_TRUE(step.call(s));
    ASSERT_TRUE(s.response.success) << s.response.message;
    current = s.response.state.step;
    // wait (bounded) for this step's batch, if it had one
    buffer.canTransform("world", "env_3/caster_link", s.response.state.header.stamp,
                        ros::Duration(0.05));
  }
  ASSERT_TRUE(all_frames()) << "frames of env_0 / env_3 never arrived";

  // env_0 sits at its grid origin: 6 envs -> 3 rows x 2 columns, 4 m apart, centred on 0
  const geometry_msgs::TransformStamped base =
      buffer.lookupTransform("world", "env_0/base_link", ros::Time(0));
  EXPECT_NEAR(base.transform.translation.x, 4.0, 0.3);
  EXPECT_NEAR(base.transform.translation.y, -2.0, 0.3);
  EXPECT_GT(base.transform.translation.z, 0.0);
  EXPECT_LT(base.transform.translation.z, 0.3);
  EXPECT_GT(base.header.stamp.toSec(), 0.0);  // simulation time after some steps
  EXPECT_EQ(base.child_frame_id, "env_0/base_link");
  EXPECT_EQ(base.header.frame_id, "world");
  for (const char* wheel : {"env_0/left_wheel", "env_0/right_wheel"}) {
    const geometry_msgs::TransformStamped w =
        buffer.lookupTransform("env_0/base_link", wheel, ros::Time(0));
    const double dx = w.transform.translation.x, dy = w.transform.translation.y,
                 dz = w.transform.translation.z;
    EXPECT_LT(dx * dx + dy * dy + dz * dz, 0.2 * 0.2) << wheel << " is far from base_link";
    EXPECT_GT(std::abs(dy), 0.02) << wheel << " is not beside base_link";
  }
  // env_3 is elsewhere, env_4 gets no frames
  const geometry_msgs::TransformStamped third =
      buffer.lookupTransform("world", "env_3/base_link", ros::Time(0));
  EXPECT_GT(std::abs(third.transform.translation.x - base.transform.translation.x) +
                std::abs(third.transform.translation.y - base.transform.translation.y),
            3.0);
  EXPECT_FALSE(buffer._frameExists("env_4/base_link"));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_tf");
  ros::NodeHandle nh;  // keeps the node alive for the test
  return RUN_ALL_TESTS();
}
