// policyImage(): a robot's camera image as an image policy takes it (the deploy node's input).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/ros/deploy/image_input.h"

namespace jetbot_rl {
namespace {

/// A `width` x `height` image of `encoding` whose byte k of pixel (x, y) is value(x, y, k), rows
/// `pad` bytes longer than the pixels.
template <class Value>
sensor_msgs::Image cameraImage(const std::string& encoding, int channels, int width, int height,
                               Value value, int pad = 0) {
  sensor_msgs::Image msg;
  msg.encoding = encoding;
  msg.width = width;
  msg.height = height;
  msg.step = width * channels + pad;
  msg.data.assign(static_cast<std::size_t>(msg.step) * height, 0xAB);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int k = 0; k < channels; ++k) {
        msg.data[y * msg.step + x * channels + k] = static_cast<std::uint8_t>(value(x, y, k));
      }
    }
  }
  return msg;
}

int pattern(int x, int y, int k) { return (37 * x + 11 * y + 70 * k) % 256; }

TEST(PolicyImage, ConvertsEveryEncodingToRgbAtTheSameSize) {
  const std::vector<std::uint8_t> expected =
      cameraImage("rgb8", 3, 5, 4, [](int x, int y, int k) { return pattern(x, y, k); }).data;
  struct Case {
    std::string encoding;
    int channels;
    int (*source)(int, int, int);  // its byte k of pixel (x, y)
  };
  const std::vector<Case> cases = {
      {"rgb8", 3, [](int x, int y, int k) { return pattern(x, y, k); }},
      {"bgr8", 3, [](int x, int y, int k) { return pattern(x, y, 2 - k); }},
      {"rgba8", 4, [](int x, int y, int k) { return k == 3 ? 255 : pattern(x, y, k); }},
      {"bgra8", 4, [](int x, int y, int k) { return k == 3 ? 7 : pattern(x, y, 2 - k); }},
  };
  for (const Case& c : cases) {
    for (int pad : {0, 3}) {
      std::vector<std::uint8_t> rgb;
      EXPECT_EQ(policyImage(cameraImage(c.encoding, c.channels, 5, 4, c.source, pad), 5, 4, rgb),
                "")
          << c.encoding;
      EXPECT_EQ(rgb, expected) << c.encoding << ", rows padded by " << pad;
    }
  }
  std::vector<std::uint8_t> rgb;
  ASSERT_EQ(
      policyImage(cameraImage("mono8", 1, 5, 4, [](int x, int y, int) { return pattern(x, y, 0); }),
                  5, 4, rgb),
      "");
  for (int i = 0; i < 20; ++i) {
    EXPECT_EQ(rgb[3 * i], expected[3 * i]);
    EXPECT_EQ(rgb[3 * i + 1], expected[3 * i]);
    EXPECT_EQ(rgb[3 * i + 2], expected[3 * i]);
  }
}

TEST(PolicyImage, ResizesByAveragingTheCameraPixelsAPolicyPixelCovers) {
  // 8 x 6 to 4 x 3: each policy pixel the mean of a 2 x 2 block; 224 to 32: of 7 x 7.
  const auto value = [](int x, int y, int k) { return 10 * x + 20 * y + k; };
  std::vector<std::uint8_t> rgb;
  ASSERT_EQ(policyImage(cameraImage("rgb8", 3, 8, 6, value), 4, 3, rgb), "");
  ASSERT_EQ(rgb.size(), 4u * 3u * 3u);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      for (int k = 0; k < 3; ++k) {
        const double mean = (value(2 * x, 2 * y, k) + value(2 * x + 1, 2 * y, k) +
                             value(2 * x, 2 * y + 1, k) + value(2 * x + 1, 2 * y + 1, k)) /
                            4.0;
        EXPECT_NEAR(rgb[(y * 4 + x) * 3 + k], mean, 0.5) << x << ", " << y << ", " << k;
      }
    }
  }
  const auto stripes = [](int x, int, int) { return x / 7 % 2 == 0 ? 0 : 210; };
  ASSERT_EQ(policyImage(cameraImage("bgr8", 3, 224, 224, stripes), 32, 32, rgb), "");
  for (int x = 0; x < 32; ++x) EXPECT_EQ(rgb[3 * x], x % 2 == 0 ? 0 : 210) << x;
}

TEST(PolicyImage, RefusesWhatItCannotReadNamingTheFieldAndLeavesTheInputAsItWas) {
  const auto grey = [](int, int, int) { return 128; };
  const std::vector<std::uint8_t> before(12, 9);
  std::vector<std::uint8_t> rgb = before;
  EXPECT_EQ(policyImage(cameraImage("16UC1", 2, 4, 3, grey), 2, 2, rgb),
            "with encoding '16UC1': the policy takes rgb8, bgr8, rgba8, bgra8 or mono8");
  EXPECT_EQ(
      policyImage(cameraImage("32FC1", 4, 4, 3, grey), 2, 2, rgb).rfind("with encoding '32FC1'", 0),
      0u);
  sensor_msgs::Image short_data = cameraImage("rgb8", 3, 4, 3, grey);
  short_data.data.pop_back();
  EXPECT_EQ(policyImage(short_data, 2, 2, rgb), "with 35 bytes of data, not step 12 x height 3");
  sensor_msgs::Image narrow_step = cameraImage("rgb8", 3, 4, 3, grey);
  narrow_step.step = 11;
  EXPECT_EQ(policyImage(narrow_step, 2, 2, rgb), "with step 11 < width 4 x 3 bytes (rgb8)");
  sensor_msgs::Image empty = cameraImage("mono8", 1, 4, 3, grey);
  empty.width = 0;
  EXPECT_EQ(policyImage(empty, 2, 2, rgb), "of width 0 x height 3");
  EXPECT_EQ(rgb, before);
}

}  // namespace
}  // namespace jetbot_rl
