// The road following task: its tracks (shapes no tighter than the robot turns, places along them,
// the user's points refused with the field and the radius named), the tape the camera sees, the
// reward for progress along it, its ends (off the tape, success) and its determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "camera_test_util.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/sensors/floor_image.h"
#include "jetbot_rl/tasks/task_factory.h"
#include "jetbot_rl/tasks/track.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// A batch of camera Jetbots (32 x 32, an image every step) on tracks of `road`.
EnvConfig roadEnvConfig(int num_envs, int threads = 1) {
  EnvConfig c = test::smallConfig(num_envs, threads);
  c.camera.width = 32;
  c.camera.height = 32;
  c.camera.update_every = 1;
  c.episode_length_s = 10.0;
  return c;
}

std::unique_ptr<Task> roadTask(const TrackConfig& road) {
  TaskConfig t;
  t.task = TaskKind::kRoadFollowing;
  t.road = road;
  return makeTask(t);
}

/// A straight open track 2 m long, the robot started on its centreline along it.
TrackConfig straightRoad() {
  TrackConfig road;
  road.points = {0.0, 0.0, 2.0, 0.0};
  road.closed = false;
  road.start_offset = 0.0;
  road.start_yaw = 0.0;
  return road;
}

std::vector<Eigen::Vector2d> roadCircle(double radius, int n) {
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    p.emplace_back(radius * std::cos(a), radius * std::sin(a));
  }
  return p;
}

void expectRoadRefused(const TrackConfig& road, const std::vector<std::string>& words) {
  try {
    roadTask(road);
    ADD_FAILURE() << "accepted; expected an error naming " << words.front();
  } catch (const ConfigError& e) {
    for (const std::string& w : words) {
      EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what();
    }
  }
}

TEST(Track, DrawnShapesAreNoTighterThanTheRobotTurns) {
  for (const char* shape : {"oval", "figure_eight", "s_bend", "random"}) {
    TrackConfig road;
    road.shapes = {shape};
    Rng rng(7);
    double tightest_unscaled = 1e9;
    for (int k = 0; k < 20; ++k) {
      const Track track = drawTrack(road, rng);
      EXPECT_GE(track.minRadius(), road.min_radius * 0.99) << shape;
      EXPECT_EQ(track.closed(), std::string(shape) != "s_bend") << shape;
      EXPECT_GT(track.length(), road.size[0]) << shape;
      Rng same(7 + k);
      tightest_unscaled = std::min(
          tightest_unscaled,
          Track(shapePoints(parseEnum<TrackShape>("s", shape), road.size[0], same), true, "s")
              .minRadius());
    }
    // The bound is the scaling's doing for the shapes that are tighter as drawn.
    if (std::string(shape) != "s_bend") {
      EXPECT_LT(tightest_unscaled, 2.0) << shape;
    }
  }
}

TEST(Track, TheCurriculumStartsWithWideCurvesAndEndsAtTheRobotsTurn) {
  TrackConfig road;
  road.shapes = {"oval", "figure_eight", "s_bend", "random"};
  TrackConfig curriculum = road;
  curriculum.curriculum = true;
  curriculum.curriculum_radius = 1.0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    Rng easy(seed), middle(seed), last(seed), off(seed);
    EXPECT_GE(drawTrack(curriculum, easy, 0.0).minRadius(), 0.99) << seed;
    EXPECT_GE(drawTrack(curriculum, middle, 0.5).minRadius(), 0.65 * 0.99) << seed;
    // At difficulty 1 the curriculum's tracks are those drawn without it, from the same draws.
    const Track hardest = drawTrack(curriculum, last, 1.0), plain = drawTrack(road, off);
    EXPECT_EQ(hardest.points(), plain.points()) << seed;
    EXPECT_EQ(last.uniform(), off.uniform()) << seed;
  }
  curriculum.curriculum_radius = 0.2;
  expectRoadRefused(curriculum, {"road/curriculum_radius", "0.2", "road/min_radius"});
}

TEST(Track, APlaceIsItsArcLengthAndSignedOffset) {
  const Track ring(roadCircle(1.0, 720), true, "test");  // counter-clockwise from (1, 0)
  EXPECT_NEAR(ring.length(), 2.0 * kPi, 1e-3);
  EXPECT_NEAR(ring.minRadius(), 1.0, 0.01);
  const TrackPlace outside = ring.place({1.1, 0.001}, nullptr, 0.0);
  EXPECT_NEAR(outside.offset, -0.1, 1e-3);  // right of the way it runs
  EXPECT_NEAR(outside.s, 0.001, 2e-3);
  const TrackPlace inside = ring.place({0.0, 0.9}, nullptr, 0.0);
  EXPECT_NEAR(inside.offset, 0.1, 1e-3);
  EXPECT_NEAR(inside.s, 0.5 * kPi, 2e-3);
  const Track back = ring.reversed();
  EXPECT_NEAR(back.place({0.0, 0.9}, nullptr, 0.0).offset, -0.1, 1e-3);
}

TEST(Track, AFigureEightsCrossingIsNoShortcut) {
  TrackConfig road;
  road.shapes = {"figure_eight"};
  Rng rng(3);
  const Track eight = drawTrack(road, rng);
  TrackPlace last = eight.place(eight.at(0.0), nullptr, 0.0);
  for (double s = 0.02; s < eight.length(); s += 0.02) {
    const TrackPlace p = eight.place(eight.at(s), &last, 0.3);
    ASSERT_NEAR(p.s, s, 0.01) << "at " << s << " of " << eight.length();
    last = p;
  }
}

TEST(RoadFollowing, BadTracksAreRefusedNamingTheField) {
  TrackConfig one_point;
  one_point.points = {0.0, 0.0};
  expectRoadRefused(one_point, {"road/points", "at least 2"});
  TrackConfig same_points;
  same_points.points = {1.0, 1.0, 1.0, 1.0};
  expectRoadRefused(same_points, {"road/points", "2 distinct points"});
  TrackConfig no_width;
  no_width.width = 0.0;
  expectRoadRefused(no_width, {"road/width", "0"});
  TrackConfig odd;
  odd.points = {0.0, 0.0, 1.0};
  expectRoadRefused(odd, {"road/points", "pairs"});
  TrackConfig unknown;
  unknown.shapes = {"oval", "spiral"};
  expectRoadRefused(unknown, {"road/shapes", "spiral"});
  // A square's corners as straight segments, and a small square through a spline: too tight.
  TrackConfig corners;
  corners.points = {0.0, 0.0, 2.0, 0.0, 2.0, 2.0, 0.0, 2.0};
  corners.spline = false;
  expectRoadRefused(corners, {"road/points", "radius", "road/min_radius 0.3"});
  TrackConfig small = corners;
  small.spline = true;
  small.points = {0.0, 0.0, 0.4, 0.0, 0.4, 0.4, 0.0, 0.4};
  expectRoadRefused(small, {"road/points", "radius", "near point"});
  TrackConfig large = small;
  large.points = {0.0, 0.0, 4.0, 0.0, 4.0, 4.0, 0.0, 4.0};
  EXPECT_NO_THROW(roadTask(large));
}

TEST(RoadFollowing, NeedsACameraWithImagesForTheBatch) {
  try {
    BatchedEnv env(test::jetbot(), test::smallConfig(1), roadTask(straightRoad()));
    ADD_FAILURE() << "a robot without a camera was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("road_following"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("camera"), std::string::npos) << e.what();
  }
  EnvConfig no_batch_images = roadEnvConfig(1);
  no_batch_images.camera.batch_images = false;
  EXPECT_THROW(BatchedEnv(cameraJetbot(), no_batch_images, roadTask(straightRoad())), ConfigError);
}

TEST(RoadFollowing, TheContractNamesTheImageThePolicySees) {
  BatchedEnv env(cameraJetbot(), roadEnvConfig(1), roadTask(straightRoad()));
  const BatchSpec spec = env.spec();
  EXPECT_EQ(spec.task, "road_following");
  EXPECT_EQ(spec.observer.camera_image, "rgb");
  EXPECT_EQ(spec.observer.camera_width, 32);
  EXPECT_EQ(spec.observer.camera_height, 32);
  EXPECT_DOUBLE_EQ(spec.observer.camera_hfov, 2.65);
  EXPECT_EQ(makeObserver(spec)->observationNames(), spec.observation_names);
  EXPECT_EQ(spec.observation_names, (std::vector<std::string>{"lin_vel_b_x", "ang_vel_b_z",
                                                              "last_action_0", "last_action_1"}));
  BatchSpec other = spec;
  other.image_width = 64;
  EXPECT_THROW(checkFieldRules(other), ConfigError);
}

TEST(RoadFollowing, TheCameraSeesTheTapeAheadAndTheFloorBeside) {
  BatchedEnv env(cameraJetbot(), roadEnvConfig(1), roadTask(straightRoad()));
  const BatchImages& images = env.state().images;
  ASSERT_EQ(images.rgb.size(), 32u * 32u * 3u);
  const auto pixel = [&](int x, int y) {
    return &images.rgb[(static_cast<std::size_t>(y) * 32 + x) * 3];
  };
  // Below the centre: the yellow tape ahead; at the sides: the grey floor beside it (the lens
  // is wide: the bottom row looks almost straight down, onto the tape).
  const std::uint8_t* tape = pixel(16, 24);
  EXPECT_GT(tape[0], 180);
  EXPECT_GT(tape[1], 150);
  EXPECT_LT(tape[2], 80);
  for (int x : {0, 31}) {
    const std::uint8_t* floor = pixel(x, 20);
    EXPECT_LT(floor[0], 110) << x;
    EXPECT_NEAR(floor[0], floor[2], 15) << x;
  }
}

TEST(RoadFollowing, ProgressIsRewardedTheEndSucceedsLeavingTheTapeFails) {
  TrackConfig road = straightRoad();
  road.curriculum = true;  // each episode a run: a lap raises the difficulty by half
  road.curriculum_episodes = 1;
  road.curriculum_success = 1.0;
  road.curriculum_step = 0.5;
  BatchedEnv env(cameraJetbot(), roadEnvConfig(1), roadTask(road));
  const auto& task = dynamic_cast<const RoadFollowingTask&>(env.task());
  EXPECT_NEAR(task.place(0).offset, 0.0, 1e-9);
  EXPECT_EQ(task.difficulty(0), 0.0);
  // Straight ahead along the tape: rewarded, to the end of the track.
  double rewards = 0.0;
  std::uint8_t outcome = 255;
  for (int step = 0; step < 1000 && outcome == 255; ++step) {
    const StepResult& r = env.step(test::uniformActions(env, 15.0f, 15.0f));
    rewards += r.rewards[0];
    if (!r.reset_env_ids.empty()) outcome = r.outcomes[0];
  }
  EXPECT_EQ(outcome, static_cast<std::uint8_t>(Outcome::kSuccess));
  EXPECT_GT(rewards, 10.0 + 10.0 * 1.4);  // the lap reward and at least 1.5 m of progress
  EXPECT_EQ(task.difficulty(0), 0.5);
  // Turning on the spot: off the tape within a quarter turn, penalised.
  outcome = 255;
  float last = 0.0f;
  for (int step = 0; step < 300 && outcome == 255; ++step) {
    const StepResult& r = env.step(test::uniformActions(env, 10.0f, 20.0f));
    last = r.rewards[0];
    if (!r.reset_env_ids.empty()) outcome = r.outcomes[0];
  }
  EXPECT_EQ(outcome, static_cast<std::uint8_t>(Outcome::kOffTrack));
  EXPECT_LT(last, -0.95f);             // road/off_track_penalty 1, little progress on the spot
  EXPECT_EQ(task.difficulty(0), 0.5);  // no lap: not raised
}

TEST(RoadFollowing, SameSeedSameTracksAndImagesOnOneAndTwoThreads) {
  TrackConfig road;
  road.shapes = {"oval", "figure_eight", "s_bend", "random"};
  road.random_colours = true;
  std::vector<std::vector<std::uint8_t>> images;
  std::vector<std::vector<float>> observations;
  for (int threads : {1, 2}) {
    BatchedEnv env(cameraJetbot(), roadEnvConfig(4, threads), roadTask(road));
    for (int step = 0; step < 40; ++step) env.step(test::randomActions(4, step));
    images.push_back(env.state().images.rgb);
    observations.push_back(env.state().observations);
    const auto& task = dynamic_cast<const RoadFollowingTask&>(env.task());
    EXPECT_NE(task.track(0).length(), task.track(1).length());
  }
  EXPECT_EQ(images[0], images[1]);
  EXPECT_TRUE(test::bitEqual(observations[0], observations[1]));
}

}  // namespace
}  // namespace jetbot_rl
