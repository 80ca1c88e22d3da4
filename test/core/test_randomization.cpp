// Domain randomisation: each randomised quantity changes the physics as it should, and the drawn
// values are reproducible per seed and independent of the threads and the rest of the batch
// (refused configurations: test_randomization_config.cpp; the motor model: test_motor_model.cpp).
#include <cmath>

#include "jetbot_rl/tasks/command_task.h"
#include "randomization_test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

// ---- each quantity acts as it should ----

TEST(Randomization, AHeavierChassisAcceleratesSlower) {
  EnvConfig heavy = smallConfig(1);
  heavy.randomization.mass_scale = {3.0, 3.0};
  BatchedEnv light_env(jetbot(), smallConfig(1)), heavy_env(jetbot(), heavy);
  EXPECT_EQ(heavy_env.view(0).randomization().mass_scale, 3.0);
  const double v_light = speedAfter(light_env, 5), v_heavy = speedAfter(heavy_env, 5);
  EXPECT_LT(v_heavy, 0.7 * v_light) << v_light << " " << v_heavy;
  // The heavy robot is torque-limited: a = 2 x 0.08 N m / 0.03 m over the chassis and caster
  // (3 x 0.82 kg), the wheels (0.06 kg) and their inertia (2 x 1.35e-5 kg m^2 / r^2 = 0.03 kg).
  // (The stock one spins its wheels: its start is limited by their grip.)
  const double a_heavy = v_heavy / (5 * heavy_env.controlDt());
  EXPECT_NEAR(a_heavy, 2 * 0.08 / test::kJetbotWheelRadius / (3 * 0.82 + 0.06 + 0.03),
              0.05 * a_heavy);
  // Both reach the same top speed: only the mass changed.
  EXPECT_NEAR(speedAfter(heavy_env, 200), speedAfter(light_env, 200), 0.01);
}

TEST(Randomization, LowerFrictionSlips) {
  EnvConfig slippery = smallConfig(1);
  slippery.randomization.wheel_friction = {0.05, 0.05};
  BatchedEnv grip_env(jetbot(), smallConfig(1)), slip_env(jetbot(), slippery);
  EXPECT_EQ(slip_env.view(0).randomization().wheel_friction, 0.05);
  // Slip: the wheels' rim speed less the body's speed, 10 steps after a full-speed start.
  const auto slip = [](BatchedEnv& env) {
    const double v = speedAfter(env, 10);
    const double rim =
        0.5 * (env.view(0).dofVelocity(0) + env.view(0).dofVelocity(1)) * test::kJetbotWheelRadius;
    return rim - v;
  };
  const double grip = slip(grip_env), slipping = slip(slip_env);
  EXPECT_LT(std::abs(grip), 0.02) << grip;
  EXPECT_GT(slipping, 0.2) << slipping;  // mu g = 0.5 m/s^2 cannot follow the wheels
}

TEST(Randomization, DriveGainAndEffortScalesWeakenTheDrive) {
  BatchedEnv normal(jetbot(), smallConfig(1));
  EnvConfig weak_effort = smallConfig(1);
  weak_effort.randomization.effort_limit_scale = {0.25, 0.25};
  BatchedEnv effort_env(jetbot(), weak_effort);
  EnvConfig weak_gain = smallConfig(1);
  weak_gain.randomization.drive_gain_scale = {0.0001, 0.0001};  // 0.001 N m s/rad
  BatchedEnv gain_env(jetbot(), weak_gain);
  const double v = speedAfter(normal, 5);
  EXPECT_LT(speedAfter(effort_env, 5), 0.5 * v);
  EXPECT_LT(speedAfter(gain_env, 5), 0.5 * v);
}

TEST(Randomization, BiggerWheelsDriveFasterAndStartOnTheGround) {
  EnvConfig big = smallConfig(1);
  big.randomization.wheel_radius_scale = {1.2, 1.2};
  EnvConfig small = smallConfig(1);
  small.randomization.wheel_radius_scale = {0.8, 0.8};
  BatchedEnv big_env(jetbot(), big), small_env(jetbot(), small);
  const double z_rest = BatchedEnv(jetbot(), smallConfig(1)).view(0).rootState().position.z();
  EXPECT_NEAR(big_env.view(0).rootState().position.z(), z_rest + 0.2 * test::kJetbotWheelRadius,
              1e-9);
  EXPECT_EQ(small_env.view(0).rootState().position.z(), z_rest);  // dropped onto its wheels
  // Top speed = wheel speed x radius.
  const double v_big = speedAfter(big_env, 200, 10.0f, 10.0f);
  const double v_small = speedAfter(small_env, 200, 10.0f, 10.0f);
  EXPECT_NEAR(v_big, 10.0 * 1.2 * test::kJetbotWheelRadius, 0.03 * v_big);
  EXPECT_NEAR(v_small, 10.0 * 0.8 * test::kJetbotWheelRadius, 0.03 * v_small);
  EXPECT_LT(big_env.view(0).maxJointError(), 1e-3);
}

TEST(Randomization, InitialYawAndSpeedAppearInTheFirstObservation) {
  EnvConfig c = smallConfig(8);
  c.randomization.initial_yaw = {-3.0, 3.0};
  c.randomization.initial_speed = {0.3, 0.3};
  BatchedEnv env(jetbot(), c, std::make_unique<CommandTask>());
  const auto& task = static_cast<const CommandTask&>(env.task());
  std::vector<double> yaws;
  for (int e = 0; e < 8; ++e) {
    const RandomizationDraw r = env.view(e).randomization();
    yaws.push_back(r.initial_yaw);
    EXPECT_GE(r.initial_yaw, -3.0);
    EXPECT_LE(r.initial_yaw, 3.0);
    const RootState s = env.view(e).rootState();
    const Eigen::Vector3d forward = s.orientation * Eigen::Vector3d::UnitX();
    EXPECT_NEAR(std::atan2(forward.y(), forward.x()), r.initial_yaw, 1e-6);
    // [dot(forward, command), cross.z, v_x]
    const Eigen::Vector2d cmd = task.command(e);
    const std::vector<float> obs = envObs(env, e);
    EXPECT_NEAR(obs[0], std::cos(std::atan2(cmd.y(), cmd.x()) - r.initial_yaw), 1e-5);
    EXPECT_NEAR(obs[2], 0.3, 1e-6);
    // The wheels roll with it.
    EXPECT_NEAR(env.view(e).dofVelocity(0) * test::kJetbotWheelRadius, 0.3, 1e-6);
  }
  EXPECT_GT(
      *std::max_element(yaws.begin(), yaws.end()) - *std::min_element(yaws.begin(), yaws.end()),
      1.0)
      << "8 envs drew about the same yaw";
  // Held at its wheel speed, the robot keeps its speed (no start-up jolt).
  for (int s = 0; s < 10; ++s) {
    env.step(uniformActions(env, 10.0f, 10.0f));
    EXPECT_NEAR(envObs(env, 0)[2], 0.3, 0.01) << "step " << s;
  }
}

/// The first step (1-based) at which env 0's forward speed exceeds 1 mm/s, driving at 20 rad/s.
int firstMovingStep(BatchedEnv& env) {
  for (int s = 1; s <= 50; ++s) {
    env.step(uniformActions(env, 20.0f, 20.0f));
    if (env.view(0).rootState().comLinearVelocityBody().x() > 1e-3) return s;
  }
  return -1;
}

TEST(Randomization, ADelayOfKStepsStartsTheResponseKStepsLater) {
  BatchedEnv prompt(jetbot(), smallConfig(1));
  const int first = firstMovingStep(prompt);
  ASSERT_EQ(first, 1);
  for (int k : {1, 3, 7}) {
    EnvConfig c = smallConfig(1);
    c.randomization.action_delay_steps = {k, k};
    BatchedEnv delayed(jetbot(), c);
    EXPECT_EQ(delayed.view(0).randomization().action_delay_steps, k);
    EXPECT_EQ(firstMovingStep(delayed), first + k) << "delay " << k;
  }
  // A range draws per env, and the drawn delay is the one applied.
  EnvConfig c = smallConfig(16);
  c.randomization.action_delay_steps = {0, 3};
  BatchedEnv batch(jetbot(), c);
  std::vector<int> seen(4, 0);
  for (int e = 0; e < 16; ++e) ++seen.at(batch.view(e).randomization().action_delay_steps);
  for (int k = 0; k < 4; ++k) EXPECT_GT(seen[k], 0) << "no env drew delay " << k;
  std::vector<int> moved(16, -1);
  for (int s = 1; s <= 10; ++s) {
    batch.step(uniformActions(batch, 20.0f, 20.0f));
    for (int e = 0; e < 16; ++e) {
      if (moved[e] < 0 && batch.view(e).rootState().comLinearVelocityBody().x() > 1e-3)
        moved[e] = s;
    }
  }
  for (int e = 0; e < 16; ++e) {
    EXPECT_EQ(moved[e], 1 + batch.view(e).randomization().action_delay_steps) << "env " << e;
  }
}

TEST(Randomization, ADelayedTargetIsTheOneGivenKStepsBefore) {
  // The wheel speed follows a changing target exactly as without delay, k steps later.
  EnvConfig c = smallConfig(1);
  c.randomization.action_delay_steps = {2, 2};
  BatchedEnv delayed(jetbot(), c), prompt(jetbot(), smallConfig(1));
  std::vector<double> prompt_wheel, delayed_wheel;
  for (int s = 0; s < 40; ++s) {
    const float target = s < 20 ? 12.0f : -5.0f;
    prompt.step(uniformActions(prompt, target, target));
    delayed.step(uniformActions(delayed, target, target));
    prompt_wheel.push_back(prompt.view(0).dofVelocity(0));
    delayed_wheel.push_back(delayed.view(0).dofVelocity(0));
  }
  for (int s = 0; s + 2 < 40; ++s) {
    EXPECT_NEAR(delayed_wheel[s + 2], prompt_wheel[s], 0.05) << "step " << s;
  }
}

TEST(Randomization, ActionNoiseChangesTheTrajectoryReproduciblyPerSeed) {
  EnvConfig c = smallConfig(4);
  c.randomization.action_noise_std = 2.0;
  EnvConfig other_seed = c;
  other_seed.seed = 1;
  BatchedEnv clean(jetbot(), smallConfig(4)), noisy(jetbot(), c), again(jetbot(), c),
      other(jetbot(), other_seed);
  for (int s = 0; s < 30; ++s) {
    const auto actions = uniformActions(clean, 8.0f, 8.0f);
    clean.step(actions);
    noisy.step(actions);
    again.step(actions);
    other.step(actions);
  }
  EXPECT_TRUE(bitEqual(noisy.state().observations, again.state().observations));
  EXPECT_FALSE(bitEqual(noisy.state().observations, clean.state().observations));
  EXPECT_FALSE(bitEqual(noisy.state().observations, other.state().observations));
  EXPECT_FALSE(bitEqual(envObs(noisy, 0), envObs(noisy, 1))) << "envs share their noise";
  // Noisy targets turn the robot a little; on average it still drives at about 8 rad/s.
  EXPECT_NEAR(noisy.view(0).rootState().comLinearVelocityBody().x(), 8.0 * test::kJetbotWheelRadius,
              0.05);
  // The noise stream restarts with a reseeding reset.
  noisy.reset({}, 3);
  again.reset({}, 3);
  for (int s = 0; s < 5; ++s) {
    noisy.step(uniformActions(noisy, 8.0f, 8.0f));
    again.step(uniformActions(again, 8.0f, 8.0f));
  }
  EXPECT_TRUE(bitEqual(noisy.state().observations, again.state().observations));
}

TEST(Randomization, ObservationNoiseHasTheConfiguredStdAndSparesThePhysics) {
  const int n = 32;
  const std::vector<double> stds{0.01, 0.02, 0.05};
  EnvConfig c = smallConfig(n, 2);
  c.episode_length_s = 1.0;  // time-outs every 59 steps: final observations too
  c.randomization.obs_noise_std = stds;
  EnvConfig clean_config = c;
  clean_config.randomization.obs_noise_std.clear();
  BatchedEnv noisy(jetbot(), c), clean(jetbot(), clean_config);
  std::vector<double> sum(3, 0.0), sum2(3, 0.0);
  long samples = 0;
  for (int s = 0; s < 300; ++s) {
    const auto actions = randomActions(n, s);
    const StepResult& a = noisy.step(actions);
    const StepResult& b = clean.step(actions);
    // The physics, and so the rewards (on the true state), are untouched.
    ASSERT_TRUE(bitEqual(a.rewards, b.rewards)) << "step " << s;
    ASSERT_EQ(a.reset_env_ids, b.reset_env_ids);
    ASSERT_EQ(a.final_observations.size(), b.final_observations.size());
    for (std::size_t i = 0; i < a.final_observations.size(); ++i) {
      EXPECT_NE(a.final_observations[i], b.final_observations[i]) << "step " << s;
    }
    for (int e = 0; e < n; ++e) {
      for (int k = 0; k < 3; ++k) {
        const double noise = a.observations[e * 3 + k] - b.observations[e * 3 + k];
        sum[k] += noise;
        sum2[k] += noise * noise;
      }
    }
    ++samples;
  }
  samples *= n;
  for (int k = 0; k < 3; ++k) {
    const double mean = sum[k] / samples;
    const double std = std::sqrt(sum2[k] / samples - mean * mean);
    EXPECT_NEAR(mean, 0.0, 4.0 * stds[k] / std::sqrt(samples)) << "component " << k;
    EXPECT_NEAR(std, stds[k], 0.03 * stds[k]) << "component " << k;  // 9,600 samples: +-0.7 %
  }
}

TEST(Randomization, AResetObservesOnlyTheResetEnvsWithObservationNoise) {
  EnvConfig c = smallConfig(3);
  c.randomization.obs_noise_std = {0.1};
  BatchedEnv env(jetbot(), c);
  env.step(uniformActions(env, 5.0f, 5.0f));
  const std::vector<float> before = env.state().observations;
  env.reset({1});
  EXPECT_TRUE(bitEqual(envObs(env, 0), std::vector<float>(before.begin(), before.begin() + 3)));
  EXPECT_TRUE(bitEqual(envObs(env, 2), std::vector<float>(before.begin() + 6, before.end())));
  EXPECT_FALSE(
      bitEqual(envObs(env, 1), std::vector<float>(before.begin() + 3, before.begin() + 6)));
}

// ---- draws: per env, per seed, independent of threads and batch ----

bool sameValues(const RandomizationDraw& a, const RandomizationDraw& b) {
  return a.mass_scale == b.mass_scale && a.wheel_friction == b.wheel_friction &&
         a.drive_gain_scale == b.drive_gain_scale && a.effort_limit_scale == b.effort_limit_scale &&
         a.wheel_radius_scale == b.wheel_radius_scale && a.initial_yaw == b.initial_yaw &&
         a.initial_speed == b.initial_speed && a.action_delay_steps == b.action_delay_steps &&
         a.motor_dead_zone == b.motor_dead_zone && a.motor_trim == b.motor_trim;
}

TEST(Randomization, DrawsAreInRangeDifferPerEnvAndRepeatPerSeed) {
  BatchedEnv env(jetbot(), everythingOn(6, 1));
  for (int e = 0; e < 6; ++e) {
    const RandomizationDraw r = env.view(e).randomization();
    EXPECT_GE(r.mass_scale, 0.8);
    EXPECT_LE(r.mass_scale, 1.3);
    EXPECT_GE(r.wheel_friction, 0.6);
    EXPECT_LE(r.wheel_friction, 1.2);
    EXPECT_GE(r.action_delay_steps, 0);
    EXPECT_LE(r.action_delay_steps, 3);
    ASSERT_EQ(r.motor_trim.size(), 2u);
    ASSERT_EQ(r.motor_dead_zone.size(), 2u);
    EXPECT_NE(r.motor_trim[0], r.motor_trim[1]);
    if (e > 0) {
      EXPECT_FALSE(sameValues(r, env.view(e - 1).randomization())) << "env " << e;
    }
  }
  // Every reset draws anew; a reset with the seed repeats the first draws.
  const RandomizationDraw first = env.view(2).randomization();
  env.reset({2});
  EXPECT_FALSE(sameValues(env.view(2).randomization(), first));
  env.reset({2}, 0);
  EXPECT_TRUE(sameValues(env.view(2).randomization(), first));
  // A time-out draws anew too.
  const RandomizationDraw before_timeout = env.view(4).randomization();
  for (int s = 0; s < env.maxEpisodeLength(); ++s) env.step(uniformActions(env, 1.0f, 1.0f));
  EXPECT_FALSE(sameValues(env.view(4).randomization(), before_timeout));
}

TEST(Randomization, TrajectoriesDoNotDependOnThreadsOrTheRestOfTheBatch) {
  BatchedEnv one(jetbot(), everythingOn(7, 1)), three(jetbot(), everythingOn(7, 3));
  BatchedEnv larger(jetbot(), everythingOn(11, 2));
  ASSERT_EQ(three.numThreads(), 3);
  for (int s = 0; s < 400; ++s) {  // past the first time-outs: redrawn values
    const auto actions = randomActions(7, s);
    auto actions_11 = randomActions(11, s, 5);
    std::copy(actions.begin(), actions.end(), actions_11.begin());
    const StepResult& a = one.step(actions);
    const StepResult& b = three.step(actions);
    larger.step(actions_11);
    ASSERT_TRUE(bitEqual(a.observations, b.observations)) << "step " << s;
    ASSERT_TRUE(bitEqual(a.rewards, b.rewards)) << "step " << s;
    ASSERT_TRUE(bitEqual(a.final_observations, b.final_observations)) << "step " << s;
    for (int e = 0; e < 7; ++e) {
      ASSERT_TRUE(bitEqual(envObs(one, e), envObs(larger, e))) << "step " << s << " env " << e;
    }
  }
  for (int e = 0; e < 7; ++e) {
    EXPECT_TRUE(sameValues(one.view(e).randomization(), three.view(e).randomization()));
    EXPECT_TRUE(sameValues(one.view(e).randomization(), larger.view(e).randomization()));
  }
}

TEST(Randomization, TheTribotIsRandomisedToo) {
  EnvConfig c = tribotConfig(4);
  c.randomization.wheel_radius_scale = {0.9, 1.1};
  c.randomization.initial_speed = {0.1, 0.1};
  c.randomization.mass_scale = {0.5, 2.0};
  BatchedEnv env(tribot(), c);
  for (int e = 0; e < 4; ++e) {
    // Its wheels are 0.033 m, their joint axes rotated: the forward speed is the drawn one.
    EXPECT_NEAR(env.view(e).rootState().comLinearVelocityBody().x(), 0.1, 1e-6);
    EXPECT_NEAR(std::abs(env.view(e).dofVelocity(0)) * 0.033 *
                    env.view(e).randomization().wheel_radius_scale,
                0.1, 1e-3);
  }
  for (int s = 0; s < 100; ++s) env.step(uniformActions(env, 0.0f, 0.0f));
  for (int e = 0; e < 4; ++e) EXPECT_LT(env.view(e).maxJointError(), 1e-3);
}

}  // namespace
}  // namespace jetbot_rl
