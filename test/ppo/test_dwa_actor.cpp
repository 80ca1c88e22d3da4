// The DWA baseline driving a navigation batch (issue 48): it reaches goals in the open and past a
// wall across the way, never colliding; a batch it cannot drive (wheel actions, no scanner, not
// the navigation task) is refused naming what is missing.
#include <gtest/gtest.h>

#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/eval/dwa_actor.h"
#include "jetbot_rl/eval/nav_benchmark.h"

namespace jetbot_rl {
namespace {

EnvSetup navigationSetup(int envs) {
  EnvSetup setup;
  readEnvSetupFiles({std::string(JETBOT_RL_SOURCE_DIR) + "/config/navigation_env.yaml"}, setup);
  setup.task.task = TaskKind::kNavigation;
  setup.env.num_envs = envs;
  setup.env.num_threads = 1;
  setup.env.world.arena_size = {6.0, 6.0};
  setup.env.world.families.clear();
  return setup;
}

RobotModelConstPtr lidarJetbot() {
  return RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_lidar.urdf");
}

TEST(DwaActor, ReachesGoalsInTheArenaAndAmongBoxesWithoutColliding) {
  for (const int boxes : {0, 4}) {
    EnvSetup setup = navigationSetup(8);
    setup.env.world.num_boxes = boxes;
    const std::unique_ptr<BatchedEnv> env = makeEnv(lidarJetbot(), setup);
    DwaActor dwa(*env, DwaConfig());
    const BenchmarkResult r = runNavigationBenchmark(dwa, *env, 16, 4000, 0.6);
    EXPECT_FALSE(r.steps_ran_out) << boxes;
    EXPECT_GE(r.success, 0.9) << boxes << " boxes";
    EXPECT_LE(r.collision, 0.05) << boxes << " boxes";
  }
}

TEST(DwaActor, ABatchItCannotDriveIsRefusedNamingWhatIsMissing) {
  EnvSetup wheels = navigationSetup(1);
  wheels.env.action_space = ActionSpace::kWheels;
  try {
    DwaActor dwa(*makeEnv(lidarJetbot(), wheels), DwaConfig());
    ADD_FAILURE() << "accepted wheel actions";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("action_space twist"), std::string::npos) << e.what();
  }
  EnvSetup velocity;
  velocity.env.num_envs = 1;
  try {
    DwaActor dwa(*makeEnv(lidarJetbot(), velocity), DwaConfig());
    ADD_FAILURE() << "accepted the velocity task";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("navigation task (task = velocity)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace jetbot_rl
