// BatchSpec's one schema: its field list and EnvSpec.msg name the same fields, the message
// conversion goes both ways field for field (and refuses an inconsistent message naming the
// field), a spec's YAML reads back equal, and the agreement checks name every field that differs.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/msg_conversion.h"
#include "jetbot_rl/ros/common/msg_fields.h"
#include "jetbot_rl/tasks/task.h"

namespace jetbot_rl {
namespace {

/// A spec with a distinct value in every field.
BatchSpec sampleSpec() {
  BatchSpec s;
  s.num_envs = 7;
  s.task = "navigation";
  s.obs_dim = 3;
  s.action_dim = 2;
  s.observation_names = {"beam_0", "goal_cos", "ang_vel_z"};
  s.action_names = {"linear_x", "angular_z"};
  s.has_goals = true;
  s.observer.scan_beam_angles = {0.5};
  s.observer.scan_range = {0.15, 3.5};
  s.observer.scan_beam_width = 0.2;
  s.observer.log_beams = true;
  s.observer.goal_radius = 0.25;
  s.observer.path_lookahead = 0.6;
  s.observer.path_clearance = 0.35;
  s.observer.path_clearance_cost = 2.5;
  s.observer.footprint_radius = 0.095;
  s.observer.speed_limit_path = {0.06, 0.074, -0.074};
  s.observer.speed_limit_distances = {0.1, 0.4};
  s.action_low = {0.0f, -10.5f};
  s.action_high = {0.6f, 10.5f};
  s.control_dt = 0.05;
  s.max_episode_length = 400;
  s.observation_low = {0.25f, -1.0f, -std::numeric_limits<float>::infinity()};
  s.observation_high = {1.0f, 1.0f, std::numeric_limits<float>::infinity()};
  s.observer.wheel_radius = 0.03;
  s.observer.wheel_separation = 0.1;
  s.image_kinds = {"rgb", "depth"};
  s.image_width = 4;
  s.image_height = 2;
  return s;
}

TEST(SpecSchema, TheStructAndTheMessageNameTheSameFields) {
  std::vector<std::string> msg_fields =
      msgFieldNames(ros::message_traits::Definition<EnvSpec>::value());
  std::vector<std::string> struct_fields = fieldNames(BatchSpec());
  std::sort(msg_fields.begin(), msg_fields.end());
  std::sort(struct_fields.begin(), struct_fields.end());
  EXPECT_EQ(msg_fields, struct_fields);
}

TEST(SpecSchema, TheMessageConversionGoesBothWaysFieldForField) {
  const BatchSpec spec = sampleSpec();
  const EnvSpec msg = toMsg(spec);
  EXPECT_EQ(msg.num_envs, 7u);
  EXPECT_TRUE(msg.has_goals);
  EXPECT_EQ(msg.wheel_separation, 0.1);
  EXPECT_EQ(msg.observation_low[0], 0.25f);
  EXPECT_EQ(msg.scan_range, (std::vector<double>{0.15, 3.5}));
  EXPECT_TRUE(msg.log_beams);
  EXPECT_EQ(msg.footprint_radius, 0.095);
  EXPECT_EQ(msg.speed_limit_distances, (std::vector<double>{0.1, 0.4}));
  EXPECT_EQ(fieldsToYaml(fromMsg(msg)), fieldsToYaml(spec));
}

TEST(SpecSchema, AnInconsistentMessageIsRefusedNamingTheField) {
  EnvSpec msg = toMsg(sampleSpec());
  msg.observation_high.pop_back();
  try {
    fromMsg(msg);
    FAIL() << "accepted two observation bounds for three components";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("inconsistent EnvSpec: invalid observation_high = 2 "
                                         "values: must hold 3 (obs_dim)"),
              std::string::npos)
        << e.what();
  }
  msg = toMsg(sampleSpec());
  msg.scan_range.clear();
  EXPECT_THROW(fromMsg(msg), Error);
  // Image kinds: known ones, each once, in order; a size with them and none without.
  const auto refused = [](const EnvSpec& bad, const std::string& text) {
    try {
      fromMsg(bad);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  for (const std::vector<std::string>& kinds :
       std::vector<std::vector<std::string>>{{"rgb", "colour"}, {"depth", "rgb"}, {"rgb", "rgb"}}) {
    msg = toMsg(sampleSpec());
    msg.image_kinds = kinds;
    refused(msg, "invalid image_kinds = " + kinds[1]);
  }
  msg = toMsg(sampleSpec());
  msg.image_width = 0;
  refused(msg, "invalid image_width = 0: must be in [1, 4096] px");
  msg = toMsg(sampleSpec());
  msg.image_kinds.clear();
  refused(msg, "invalid image_width = 4: must be 0 without image_kinds");
}

TEST(SpecSchema, ItsYamlReadsBackEqualInfinitiesIncluded) {
  const BatchSpec spec = sampleSpec();
  const std::string yaml = fieldsToYaml(spec);
  EXPECT_NE(yaml.find("observation_low: [0.25, -1, -.inf]"), std::string::npos) << yaml;
  BatchSpec read;
  fieldsFromYaml(yaml, read);
  EXPECT_EQ(fieldsToYaml(read), yaml);
  EXPECT_EQ(read.observation_high[2], std::numeric_limits<float>::infinity());
}

TEST(SpecSchema, DifferencesNameEveryFieldButNumEnvsAndCanKeepToThePolicysFields) {
  const BatchSpec mine = sampleSpec();
  BatchSpec theirs = sampleSpec();
  theirs.num_envs = 100;  // never a difference
  EXPECT_TRUE(specDifferences(mine, theirs, false, false).empty());
  theirs.control_dt = 0.1;
  theirs.observer.scan_range = {0.15, 12.0};
  const std::vector<std::string> all = specDifferences(mine, theirs, false, false);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0], "scan_range: [0.15, 12] differs from [0.15, 3.5]");
  EXPECT_EQ(all[1], "control_dt: 0.1 differs from 0.05");
  const std::vector<std::string> bound = specDifferences(mine, theirs, true, false);
  ASSERT_EQ(bound.size(), 1u);
  EXPECT_EQ(bound[0], all[0]);
  // A field `mine` does not hold (a checkpoint written before it existed) is not compared.
  BatchSpec old = mine;
  old.observer.wheel_radius = 0.0;
  theirs = mine;
  EXPECT_EQ(specDifferences(old, theirs, false, false).size(), 1u);
  EXPECT_TRUE(specDifferences(old, theirs, false, true).empty());
}

TEST(MsgFields, ConstantsAndCommentsAreNoFieldsAndAnUnreadableLineIsRefused) {
  EXPECT_EQ(msgFieldNames("# a comment\nuint8 A=2  # a constant\nfloat32[] x  # [m]\n\nstring y"),
            (std::vector<std::string>{"x", "y"}));
  EXPECT_THROW(msgFieldNames("uint8 a b"), Error);
}

/// A step of `spec` whose images hold distinct values, with envs 2, 5 and 6 ended (time-outs).
StepResult sampleStep(const BatchSpec& spec) {
  StepResult r;
  const auto n = static_cast<std::size_t>(spec.num_envs);
  r.observations.assign(n * spec.obs_dim, 0.0f);
  r.rewards.assign(n, 0.0f);
  r.terminated.assign(n, 0);
  r.truncated.assign(n, 0);
  r.episode_steps.assign(n, 0);
  r.reset_env_ids = {2, 5, 6};
  r.final_observations.assign(3 * spec.obs_dim, 0.0f);
  r.outcomes.assign(3, 0);
  const auto pixels = static_cast<std::size_t>(spec.image_width) * spec.image_height;
  r.images.width = r.final_images.width = spec.image_width;
  r.images.height = r.final_images.height = spec.image_height;
  for (std::size_t i = 0; i < n * pixels * 3; ++i) r.images.rgb.push_back(i % 251);
  for (std::size_t i = 0; i < n * pixels; ++i) r.images.depth.push_back(0.5f * i);
  r.images.depth[1] = std::numeric_limits<float>::infinity();  // REP 118 crosses
  r.images.label.assign(n * pixels, 3);
  r.images.fresh.assign(n, 1);
  r.images.fresh[4] = 0;
  for (std::size_t i = 0; i < 3 * pixels * 3; ++i) r.final_images.rgb.push_back(i % 7);
  for (std::size_t i = 0; i < 3 * pixels; ++i) r.final_images.depth.push_back(-0.25f * i);
  return r;
}

TEST(StepConversion, TheImagesOfTheSpecsKindsCrossBothWaysAndOthersStayHome) {
  const BatchSpec spec = sampleSpec();  // rgb and depth, not label
  const StepResult r = sampleStep(spec);
  EnvStep msg;
  toMsg(r, spec, ros::Time(1.0), msg);
  EXPECT_EQ(msg.images_rgb.size(), 7u * 8 * 3);
  EXPECT_TRUE(msg.images_label.empty());  // label is not among the spec's kinds
  StepResult back;
  fromMsg(msg, spec, back);
  EXPECT_EQ(back.images.rgb, r.images.rgb);
  EXPECT_EQ(back.images.depth, r.images.depth);
  EXPECT_EQ(back.images.fresh, r.images.fresh);
  EXPECT_TRUE(back.images.label.empty());
  EXPECT_EQ(back.final_images.rgb, r.final_images.rgb);
  EXPECT_EQ(back.final_images.depth, r.final_images.depth);
  EXPECT_EQ(back.images.width, 4);
  EXPECT_EQ(back.final_images.height, 2);
  // A message whose images do not fit the spec is refused, naming the field.
  const auto refused = [&](EnvStep bad, const std::string& field) {
    try {
      fromMsg(bad, spec, back);
      ADD_FAILURE() << field << " of a wrong size accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(field + " has"), std::string::npos) << e.what();
    }
  };
  EnvStep bad = msg;
  bad.images_rgb.pop_back();
  refused(bad, "images_rgb");
  bad = msg;
  bad.images_label.assign(7 * 8, 0);
  refused(bad, "images_label");
  bad = msg;
  bad.final_images_depth.resize(2 * 8);
  refused(bad, "final_images_depth");
  bad = msg;
  bad.images_fresh.clear();
  refused(bad, "images_fresh");
}

TEST(StepConversion, MoverAndRobotCollisionsAndWaitsCrossAndAnUnknownOutcomeIsRefused) {
  const BatchSpec spec = sampleSpec();
  StepResult r = sampleStep(spec);
  r.outcomes = {static_cast<std::uint8_t>(Outcome::kCollisionMover),
                static_cast<std::uint8_t>(Outcome::kWaited),
                static_cast<std::uint8_t>(Outcome::kOffTrack)};
  EnvStep msg;
  toMsg(r, spec, ros::Time(1.0), msg);
  EXPECT_EQ(msg.outcomes[0], EnvStep::OUTCOME_COLLISION_MOVER);
  EXPECT_EQ(msg.outcomes[1], EnvStep::OUTCOME_WAITED);
  EXPECT_EQ(msg.outcomes[2], EnvStep::OUTCOME_OFF_TRACK);
  StepResult back;
  fromMsg(msg, spec, back);
  EXPECT_EQ(back.outcomes, r.outcomes);
  msg.outcomes[2] = static_cast<std::uint8_t>(Outcome::kCollisionRobot);
  fromMsg(msg, spec, back);
  EXPECT_EQ(back.outcomes[2], EnvStep::OUTCOME_COLLISION_ROBOT);
  msg.outcomes[1] = EnvStep::OUTCOME_OFF_TRACK + 1;
  try {
    fromMsg(msg, spec, back);
    ADD_FAILURE() << "outcome 7 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("outcomes holds 7, not 0 to 6"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace jetbot_rl
