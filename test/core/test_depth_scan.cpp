// A scan from the camera's depth image (scan/source camera_depth): the reduction itself (the
// floor is no obstacle, the nearest point of a bearing wins, REP 117's ends), what it reads in a
// world against a laser on the same bearings, and the settings it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "camera_test_util.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/depth_scan.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// The camera Jetbot in a 3 x 3 m arena with two boxes, its 96 x 12 depth image read as a scan of
/// 32 samples (config/navigation_camera_env.yaml's), or (`laser`) a laser on its root link over
/// the same bearings.
EnvConfig depthScanConfig(bool laser) {
  EnvConfig c = test::smallConfig(2, 1);
  c.world.arena_size = {3.0, 3.0};
  c.world.num_boxes = 2;
  c.world.random_start = true;
  c.camera.width = 96;
  c.camera.height = 12;
  c.camera.images = {"depth"};
  c.camera.batch_images = false;
  c.camera.update_every = 1;
  c.scan.samples = 32;
  c.scan.range = {0.15, 3.5};
  if (laser) {
    c.scan.link = "base_link";
    c.scan.angles = {-1.325, 1.325};  // the camera's field of view, as the depth scan's default
  } else {
    c.scan.source = ScanSource::kCameraDepth;
  }
  return c;
}

TEST(DepthScan, TheNearestPointOfABearingWinsTheFloorIsNone) {
  const CameraModel model(cameraIntrinsics(5, 3, 1.6));
  ScannerSpec spec;
  spec.samples = 5;
  spec.min_angle = -0.8;
  spec.max_angle = 0.8;
  spec.range_min = 0.15;
  spec.range_max = 3.5;
  spec.min_height = 0.03;
  spec.max_height = 0.5;
  // The camera 0.1 m above the ground at the origin, looking along x (optical z), level.
  Eigen::Isometry3d optical = Eigen::Isometry3d::Identity();
  optical.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  optical.translation() = Eigen::Vector3d(0.0, 0.0, 0.1);
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> depth(15, inf);
  const auto at = [&](int u, int v) -> float& {
    return depth[static_cast<std::size_t>(v) * 5 + u];
  };
  at(2, 1) = 2.0f;  // straight ahead, at the camera's height: 2 m
  at(2, 0) = 0.8f;  // above it (0.43 m up), nearer: the nearest of the bearing wins
  at(1, 0) = 1.2f;  // up and left (sample 3): 0.59 m up, over max_height: passes over the robot
  // The bottom row's rays meet the ground: no obstacle.
  at(2, 2) = 0.1f / model.pixelRays()[2 * 5 + 2].y();
  at(0, 2) = 0.1f / model.pixelRays()[2 * 5].y();
  at(4, 1) = 0.1f;  // nearer than range_min (bearing -0.69 rad: sample 0)
  at(0, 1) = 5.0f;  // beyond range_max (bearing 0.69 rad: sample 4)
  std::vector<float> ranges(5, 0.0f);
  depthToScan(spec, model, depth.data(), optical, Eigen::Isometry3d::Identity(), ranges.data());
  EXPECT_NEAR(ranges[2], 0.8f, 1e-4f);
  EXPECT_EQ(ranges[0], kTooClose);  // REP 117
  EXPECT_EQ(ranges[1], kNoReturn);  // nothing
  EXPECT_EQ(ranges[3], kNoReturn);  // over the robot
  EXPECT_EQ(ranges[4], kNoReturn);  // the ground and a point out of range
  // The robot turned and moved: bearings and ranges from its origin.
  Eigen::Isometry3d moved = Eigen::Isometry3d::Identity();
  moved.translation() = Eigen::Vector3d(-0.5, 0.0, 0.05);
  depthToScan(spec, model, depth.data(), optical, moved, ranges.data());
  // From 0.5 m back, the too near point lies ahead too (sample 2), nearer than the one at 1.3 m.
  const Eigen::Vector3d near_point = optical * (model.pixelRays()[1 * 5 + 4].cast<double>() * 0.1);
  EXPECT_NEAR(ranges[2], std::hypot(near_point.x() + 0.5, near_point.y()), 1e-4);
  EXPECT_LT(ranges[2], 1.3f);
  EXPECT_EQ(ranges[0], kNoReturn);
}

TEST(DepthScan, ReadsWhatALaserReadsOnTheSameBearings) {
  BatchedEnv depth(cameraJetbot(), depthScanConfig(false), test::navigationTask());
  BatchedEnv laser(cameraJetbot(), depthScanConfig(true), test::navigationTask());
  const ScannerSpec& spec = *depth.scanner();
  EXPECT_EQ(spec.samples, 32);
  EXPECT_NEAR(spec.max_angle, 1.325, 1e-9);
  EXPECT_EQ(depth.state().observations.size(), laser.state().observations.size());
  int compared = 0, close = 0, returns = 0;
  for (int step = 0; step < 60; ++step) {
    const std::vector<float> actions = test::randomActions(2, step);
    depth.step(actions);
    laser.step(actions);
    for (int e = 0; e < 2; ++e) {
      ASSERT_TRUE(depth.view(e).scanned());
      const float* a = depth.view(e).scan();
      const float* b = laser.view(e).scan();
      // The middle samples: at the edges the base's origin sees past the camera's field of view.
      for (int k = 3; k < 29; ++k) {
        if (!std::isfinite(b[k]) || b[k] > 3.0f) continue;
        ++compared;
        returns += std::isfinite(a[k]) ? 1 : 0;
        // A laser reads the surface at the sample's angle, the depth the nearest point within
        // half a sample of it: nearer, by the surface's slant.
        if (std::isfinite(a[k]) && a[k] <= b[k] + 0.02f && a[k] >= b[k] - 0.25f) ++close;
      }
    }
  }
  ASSERT_GT(compared, 500);
  EXPECT_EQ(returns, compared);  // nothing a laser sees is missed
  EXPECT_GT(close, 0.95 * compared) << close << " of " << compared;
}

TEST(DepthScan, RefusesWhatItCannotMakeNamingTheField) {
  const auto refused = [](EnvConfig c, const std::vector<std::string>& words) {
    try {
      BatchedEnv env(cameraJetbot(), c, test::navigationTask());
      ADD_FAILURE() << "accepted; expected an error naming " << words.front();
    } catch (const ConfigError& e) {
      for (const std::string& w : words) {
        EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what();
      }
    }
  };
  EnvConfig rgb_only = depthScanConfig(false);
  rgb_only.camera.images = {"rgb"};
  refused(rgb_only, {"scan/source", "camera/images", "depth"});
  EnvConfig with_link = depthScanConfig(false);
  with_link.scan.link = "base_link";
  refused(with_link, {"scan/link", "base_link", "camera_depth"});
  EnvConfig upside_down = depthScanConfig(false);
  upside_down.scan.min_height = 0.5;
  refused(upside_down, {"scan/min_height", "0.5", "scan/max_height"});
  EnvConfig noisy = depthScanConfig(false);
  noisy.scan.noise_std = 0.01;
  refused(noisy, {"scan/noise_std", "0.01"});
  EnvConfig no_camera = depthScanConfig(false);
  no_camera.camera.enabled = false;
  refused(no_camera, {"scan/source", "needs a camera"});
}

TEST(DepthScan, ARobotCamerasRaysFromItsCameraInfoAreTheSimulatedOnesBitForBit) {
  // The simulated camera's CameraInfo (K: f, f, (w - 1) / 2, (h - 1) / 2; plumb_bob D) gives its
  // pixel rays back exactly, distorted or not: jetbot_depth_scan on a robot reads as training.
  for (const bool distorted : {false, true}) {
    CameraIntrinsics c = cameraIntrinsics(24, 10, 1.9);
    if (distorted) {
      c.k1 = -0.2;
      c.k2 = 0.05;
      c.p1 = 0.002;
      c.p2 = -0.001;
      c.k3 = -0.004;
    }
    const CameraModel model(c);
    const std::vector<Eigen::Vector3f> rays =
        pinholeRays(c.width, c.height, model.fx(), model.fy(), model.cx(), model.cy(),
                    {c.k1, c.k2, c.p1, c.p2, c.k3});
    ASSERT_EQ(rays.size(), model.pixelRays().size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
      ASSERT_EQ(rays[i], model.pixelRays()[i]) << "pixel " << i << (distorted ? ", distorted" : "");
    }
  }
  // Another camera's K: the ray through (cx, cy) is the axis, fx and fy scale x and y apart.
  const std::vector<Eigen::Vector3f> rays = pinholeRays(5, 3, 100.0, 50.0, 2.0, 1.0, {});
  EXPECT_EQ(rays[1 * 5 + 2], Eigen::Vector3f(0.0f, 0.0f, 1.0f));
  EXPECT_FLOAT_EQ(rays[0].x(), -0.02f);
  EXPECT_FLOAT_EQ(rays[0].y(), -0.02f);
  const auto error = [](auto&& make) {
    try {
      make();
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::string e = error([] { pinholeRays(5, 3, 0.0, 50.0, 2.0, 1.0, {}); });
  EXPECT_NE(e.find("invalid K = [fx 0, fy 50"), std::string::npos) << e;
  e = error([] { pinholeRays(5, 3, 100.0, 50.0, 2.0, 1.0, {0.1, 0.0, 0.0}); });
  EXPECT_NE(e.find("invalid D = [0.1, 0, 0]"), std::string::npos) << e;
  e = error([] { pinholeRays(0, 3, 100.0, 50.0, 2.0, 1.0, {}); });
  EXPECT_NE(e.find("camera_info/width"), std::string::npos) << e;
}

}  // namespace
}  // namespace jetbot_rl
