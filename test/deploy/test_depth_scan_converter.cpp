// DepthScanConverter (jetbot_depth_scan): a depth image and its CameraInfo give the scan
// training's depthToScan() gives for the simulated camera, from metres or millimetres, and an
// image it cannot read is refused naming why, leaving the scan as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "jetbot_rl/ros/deploy/depth_scan_publisher.h"
#include "jetbot_rl/sensors/camera_model.h"
#include "jetbot_rl/sensors/depth_scan.h"

namespace jetbot_rl {
namespace {

constexpr int kWidth = 16, kHeight = 6;

/// The camera as the env node's CameraInfo describes it (camera_output.cpp's cameraInfo()).
sensor_msgs::CameraInfo cameraInfoOf(const CameraModel& model) {
  sensor_msgs::CameraInfo info;
  info.width = model.width();
  info.height = model.height();
  info.distortion_model = "plumb_bob";
  const CameraIntrinsics& c = model.intrinsics();
  info.D = {c.k1, c.k2, c.p1, c.p2, c.k3};
  info.K = {model.fx(), 0.0, model.cx(), 0.0, model.fy(), model.cy(), 0.0, 0.0, 1.0};
  return info;
}

/// Depths in millimetres: walls 0.4 to 2.9 m away, some pixels without a reading (0).
std::vector<std::uint16_t> millimetres() {
  std::vector<std::uint16_t> mm(kWidth * kHeight);
  for (int i = 0; i < kWidth * kHeight; ++i) mm[i] = i % 7 == 3 ? 0 : 400 + (i * 263) % 2500;
  return mm;
}

sensor_msgs::Image depthImage(const std::string& encoding) {
  const std::vector<std::uint16_t> mm = millimetres();
  sensor_msgs::Image image;
  image.encoding = encoding;
  image.width = kWidth;
  image.height = kHeight;
  const bool metres = encoding == "32FC1";
  image.step = kWidth * (metres ? 4 : 2) + 3;  // rows padded
  image.data.assign(static_cast<std::size_t>(image.step) * kHeight, 0xCD);
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const std::uint16_t d = mm[v * kWidth + u];
      const float m = d == 0 ? std::numeric_limits<float>::quiet_NaN() : d * 0.001f;
      std::memcpy(&image.data[v * image.step + u * (metres ? 4 : 2)], metres ? (const void*)&m : &d,
                  metres ? 4 : 2);
    }
  }
  return image;
}

struct Scene {
  CameraIntrinsics c;
  Eigen::Isometry3d optical = Eigen::Isometry3d::Identity(), origin = Eigen::Isometry3d::Identity();
  DepthScanParams params;
  Scene() {
    c.width = kWidth;
    c.height = kHeight;
    c.horizontal_fov = 1.6;
    c.k1 = -0.05;
    // The camera 0.2 m above the ground, pitched 0.3 rad down, looking along the robot's x.
    Eigen::Matrix3d optical_axes;
    optical_axes << 0, 0, 1, -1, 0, 0, 0, -1, 0;
    optical.linear() =
        Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix() * optical_axes;
    optical.translation() = Eigen::Vector3d(0.05, 0.0, 0.2);
    origin.translation() = Eigen::Vector3d(0.0, 0.0, 0.03);
    params.samples = 9;
    params.angles = {-0.8, 0.8};
    params.range = {0.15, 3.5};
    params.min_height = -0.5;  // the pitched camera's points reach below its height: all count
    params.max_height = 0.5;
  }
};

TEST(DepthScanConverter, GivesTrainingsScanFromMetresOrMillimetres) {
  const Scene s;
  const CameraModel model(s.c);
  // Training's scan of the same depths (as floats in metres).
  ScannerSpec spec;
  spec.source = ScanSource::kCameraDepth;
  spec.samples = 9;
  spec.min_angle = -0.8;
  spec.max_angle = 0.8;
  spec.range_min = 0.15;
  spec.range_max = 3.5;
  spec.min_height = -0.5;
  spec.max_height = 0.5;
  std::vector<float> depth;
  for (std::uint16_t d : millimetres()) {
    depth.push_back(d == 0 ? std::numeric_limits<float>::quiet_NaN() : d * 0.001f);
  }
  std::vector<float> expected(9);
  depthToScan(spec, model, depth.data(), s.optical, s.origin, expected.data());
  int finite = 0;
  for (float r : expected) finite += std::isfinite(r) ? 1 : 0;
  ASSERT_GE(finite, 5);  // the test sees walls
  for (const std::string encoding : {"32FC1", "16UC1"}) {
    DepthScanConverter converter(s.params);
    sensor_msgs::LaserScan scan;
    ASSERT_EQ(
        converter.convert(depthImage(encoding), cameraInfoOf(model), s.optical, s.origin, scan),
        "");
    EXPECT_EQ(scan.ranges, expected) << encoding;
    EXPECT_FLOAT_EQ(scan.angle_min, -0.8f);
    EXPECT_FLOAT_EQ(scan.angle_max, 0.8f);
    EXPECT_FLOAT_EQ(scan.angle_increment, 0.2f);
    EXPECT_FLOAT_EQ(scan.range_min, 0.15f);
    EXPECT_FLOAT_EQ(scan.range_max, 3.5f);
  }
}

TEST(DepthScanConverter, ByDefaultASamplePerColumnOverTheCamerasFieldOfView) {
  Scene s;
  s.params.samples = 0;
  s.params.angles.clear();
  DepthScanConverter converter(s.params);
  sensor_msgs::LaserScan scan;
  ASSERT_EQ(converter.convert(depthImage("32FC1"), cameraInfoOf(CameraModel(s.c)), s.optical,
                              s.origin, scan),
            "");
  EXPECT_EQ(scan.ranges.size(), static_cast<std::size_t>(kWidth));
  EXPECT_FLOAT_EQ(scan.angle_min, -0.8f);  // half the horizontal field of view
  EXPECT_FLOAT_EQ(scan.angle_max, 0.8f);
}

TEST(DepthScanConverter, RefusesWhatItCannotReadNamingWhy) {
  const Scene s;
  const CameraModel model(s.c);
  DepthScanConverter converter(s.params);
  sensor_msgs::LaserScan scan;
  scan.ranges = {1.0f};
  const auto refused = [&](const sensor_msgs::Image& image, const sensor_msgs::CameraInfo& info,
                           const std::string& words) {
    const std::string why = converter.convert(image, info, s.optical, s.origin, scan);
    EXPECT_NE(why.find(words), std::string::npos) << why;
    EXPECT_EQ(scan.ranges, std::vector<float>{1.0f});  // left as it was
  };
  refused(depthImage("rgb8"), cameraInfoOf(model), "encoding 'rgb8'");
  sensor_msgs::CameraInfo wider = cameraInfoOf(model);
  wider.width = kWidth + 1;
  refused(depthImage("32FC1"), wider, "size 16 x 6 (its CameraInfo says 17 x 6)");
  sensor_msgs::Image short_data = depthImage("16UC1");
  short_data.data.resize(10);
  refused(short_data, cameraInfoOf(model), "10 bytes for 16 x 6 16UC1");
  sensor_msgs::CameraInfo no_focus = cameraInfoOf(model);
  no_focus.K[0] = 0.0;
  refused(depthImage("32FC1"), no_focus, "CameraInfo: invalid K = [fx 0");
  sensor_msgs::CameraInfo fisheye = cameraInfoOf(model);
  fisheye.distortion_model = "equidistant";
  refused(depthImage("32FC1"), fisheye, "distortion_model 'equidistant'");
  // The right camera again: read.
  EXPECT_EQ(converter.convert(depthImage("32FC1"), cameraInfoOf(model), s.optical, s.origin, scan),
            "");
  EXPECT_EQ(scan.ranges.size(), 9u);
}

}  // namespace
}  // namespace jetbot_rl
