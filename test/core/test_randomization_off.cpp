// Randomisation off (the default) changes nothing: trajectories hash to the value the core gave
// before randomisation existed, and no draw is taken from an env's random stream.
#include <cstring>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/tasks/command_task.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

/// FNV-1a over raw bytes.
struct Fnv {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  template <typename T>
  void add(const std::vector<T>& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    for (std::size_t i = 0; i < v.size() * sizeof(T); ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
  }
};

/// Every observation, reward, done flag, reset id and final observation of 700 steps of 16 envs
/// (two episodes and a bit, so auto-resets are in it), with random targets.
std::uint64_t trajectoryHash(const EnvConfig& config, std::unique_ptr<Task> task) {
  BatchedEnv env(jetbot(), config, std::move(task));
  Fnv fnv;
  fnv.add(env.state().observations);
  for (int s = 0; s < 700; ++s) {
    const StepResult& r = env.step(randomActions(16, s));
    fnv.add(r.observations);
    fnv.add(r.rewards);
    fnv.add(r.terminated);
    fnv.add(r.truncated);
    fnv.add(r.reset_env_ids);
    fnv.add(r.final_observations);
  }
  return fnv.h;
}

TEST(RandomizationOff, TrajectoriesAreThoseOfTheCoreWithoutRandomization) {
  // Recorded with the core of commit 51ff11a, before randomisation existed (Release build, Debian
  // 12's Bullet 3.24). A deliberate change of the physics changes them: record the new values.
  EXPECT_EQ(trajectoryHash(smallConfig(16, 1), std::make_unique<VelocityTask>()),
            0xe3e4ae2fad391109ULL);
  // The command task draws its command from the env's stream at every reset.
  EXPECT_EQ(trajectoryHash(smallConfig(16, 2), std::make_unique<CommandTask>()),
            0xb9c719fb967f9875ULL);
}

/// The velocity task, recording the first value the task draws from the env's stream at each
/// reset.
class DrawProbe : public VelocityTask {
 public:
  void resize(int num_envs) override { first_.assign(num_envs, {}); }
  void resetEnv(int env, Rng& rng) override { first_[env].push_back(rng.next()); }
  std::vector<std::vector<std::uint64_t>> first_;
};

/// The first draw the task saw at each env's first reset, against a fresh stream's first draw.
bool taskDrawsFirst(const EnvConfig& config) {
  auto probe = std::make_unique<DrawProbe>();
  const DrawProbe& seen = *probe;
  BatchedEnv env(jetbot(), config, std::move(probe));
  for (int e = 0; e < config.num_envs; ++e) {
    if (seen.first_[e].at(0) != Rng(config.seed, e).next()) return false;
  }
  return true;
}

TEST(RandomizationOff, NothingIsDrawnFromTheEnvStreams) {
  EnvConfig off = smallConfig(4);
  off.seed = 7;
  EXPECT_TRUE(taskDrawsFirst(off));
  // Noise has its own streams: the reset draws stay where they were.
  EnvConfig noise = off;
  noise.randomization.obs_noise_std = {0.1};
  noise.randomization.action_noise_std = 1.0;
  EXPECT_TRUE(taskDrawsFirst(noise));
  // The probe sees draws taken before the task's (the test can fail).
  EnvConfig on = off;
  on.randomization.mass_scale = {0.9, 1.1};
  EXPECT_FALSE(taskDrawsFirst(on));
  EnvConfig motor = off;
  motor.motor.enabled = true;
  EXPECT_TRUE(taskDrawsFirst(motor)) << "the motor model without ranges draws nothing";
  motor.motor.trim = {0.9, 1.0};
  EXPECT_FALSE(taskDrawsFirst(motor));
}

TEST(RandomizationOff, ValuesAreTheDefaults) {
  BatchedEnv env(jetbot(), smallConfig(2));
  const RandomizationDraw r = env.view(1).randomization();
  EXPECT_EQ(r.mass_scale, 1.0);
  EXPECT_EQ(r.wheel_friction, 1.0);
  EXPECT_EQ(r.drive_gain_scale, 1.0);
  EXPECT_EQ(r.effort_limit_scale, 1.0);
  EXPECT_EQ(r.wheel_radius_scale, 1.0);
  EXPECT_EQ(r.initial_yaw, 0.0);
  EXPECT_EQ(r.initial_speed, 0.0);
  EXPECT_EQ(r.action_delay_steps, 0);
  EXPECT_TRUE(r.motor_dead_zone.empty());
  EXPECT_TRUE(r.motor_trim.empty());
  EXPECT_THROW(env.view(2).randomization(), InputError);
}

}  // namespace
}  // namespace jetbot_rl
