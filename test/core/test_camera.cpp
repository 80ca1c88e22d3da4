// The camera's projection (pinhole and Brown distortion) and its Embree rendering: pixels where
// the model puts a body, depth equal to the geometric distance, bad intrinsics named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

#include "camera_test_util.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {
namespace {

/// A camera at height `z` [m] at the env origin looking along +x (level).
Eigen::Isometry3d levelCamera(double z) {
  return opticalFrame(Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, z)));
}

TEST(CameraModel, FocalLengthIsGazebos) {
  const CameraModel m(cameraIntrinsics(224, 224, 2.0));
  EXPECT_DOUBLE_EQ(m.fx(), 112.0 / std::tan(1.0));
  EXPECT_DOUBLE_EQ(m.fy(), m.fx());
  EXPECT_DOUBLE_EQ(m.cx(), 111.5);
  EXPECT_DOUBLE_EQ(m.cy(), 111.5);
  // The optical axis lands on the principal point; a point at the fov's edge on the image's.
  EXPECT_TRUE(m.project({0, 0, 1})->isApprox(Eigen::Vector2d(111.5, 111.5)));
  EXPECT_NEAR(m.project({std::tan(1.0), 0, 1})->x(), 111.5 + 112.0, 1e-9);
}

TEST(CameraModel, DistortionRoundTrips) {
  CameraIntrinsics c = cameraIntrinsics(160, 120, 1.8);
  c.k1 = -0.1;
  c.k2 = 0.01;
  c.k3 = -0.0005;
  c.p1 = 0.001;
  c.p2 = -0.0015;
  const CameraModel m(c);
  ASSERT_TRUE(m.distorted());
  for (double v = 0.0; v <= 119.0; v += 7.0) {
    for (double u = 0.0; u <= 159.0; u += 7.0) {
      const std::optional<Eigen::Vector2d> back = m.project(m.ray(u, v));
      ASSERT_TRUE(back);
      EXPECT_NEAR(back->x(), u, 1e-6);
      EXPECT_NEAR(back->y(), v, 1e-6);
    }
  }
  // Barrel distortion (k1 < 0) pulls a corner's point inwards.
  const Eigen::Vector2d corner(0.8, 0.6);
  EXPECT_LT(m.distort(corner).norm(), corner.norm());
}

TEST(CameraModel, BadIntrinsicsAreNamed) {
  const auto refused = [](CameraIntrinsics c, const std::string& field) {
    try {
      CameraModel m(c, "camera/");
      ADD_FAILURE() << field << " accepted";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("camera/" + field + " = "), std::string::npos)
          << e.what();
    }
  };
  CameraIntrinsics c = cameraIntrinsics(64, 64, 1.0);
  c.width = 0;
  refused(c, "width");
  c = cameraIntrinsics(64, 5000, 1.0);
  refused(c, "height");
  refused(cameraIntrinsics(64, 64, 0.0), "horizontal_fov");
  refused(cameraIntrinsics(64, 64, 3.2), "horizontal_fov");
  c = cameraIntrinsics(64, 64, 1.0);
  c.near = 0.0;
  refused(c, "clip/near");
  c = cameraIntrinsics(64, 64, 1.0);
  c.far = c.near;
  refused(c, "clip/far");
  c = cameraIntrinsics(64, 64, 1.0);
  c.k1 = -3.0;  // its field ends inside the image
  refused(c, "distortion");
  c = cameraIntrinsics(160, 120, 1.8);
  c.k1 = -0.25;
  c.k2 = 0.06;
  c.k3 = -0.005;  // folds back before the corners at this fov
  refused(c, "distortion");
  c = cameraIntrinsics(64, 64, 1.0);
  c.p1 = std::nan("");
  refused(c, "distortion/p1");
}

class CameraRender : public ::testing::Test {
 protected:
  CameraRender() : world_(WorldConfig(), 0.1), camera_world_(&world_), scene_(camera_world_) {}

  WorldModel world_;
  CameraWorld camera_world_;
  CameraEnvScene scene_;
};

TEST_F(CameraRender, MoversAreSeenWhereTheyStandNow) {
  // A person (a cylinder of radius 0.25 m) 1.5 m ahead: the centre pixels show a mover at depth
  // 1.25 m; moved away, the ground and sky again.
  Obstacle person;
  person.shape = Obstacle::Shape::kCylinder;
  person.center = {1.5, 0.0};
  person.radius = 0.25;
  person.height = 1.8;
  scene_.setMovers({person});
  const CameraModel m(cameraIntrinsics(64, 48, 1.2));
  CameraImages images;
  scene_.render(m, levelCamera(0.3), images);
  const std::size_t centre = 24 * 64 + 32;
  EXPECT_EQ(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kMover));
  EXPECT_NEAR(images.depth[centre], 1.25, 1e-3);  // its round surface, exactly
  person.center = {1.5, 3.0};
  scene_.setMovers({person});
  scene_.render(m, levelCamera(0.3), images);
  EXPECT_NE(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kMover));
  // Obstacles and movers are told apart: the env's obstacles keep their class.
  scene_.setObstacles({standingBox(1.0, 0.0, 0.05, 0.5, 1.0)});
  scene_.render(m, levelCamera(0.3), images);
  EXPECT_EQ(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kObstacle));
}

TEST_F(CameraRender, DepthAtAWallIsItsDistance) {
  // A wall facing the camera 2 m ahead: its face is a plane at depth 1.95 m in every pixel.
  scene_.setObstacles({standingBox(2.0, 0.0, 0.05, 4.0, 2.0)});
  const CameraModel m(cameraIntrinsics(64, 48, 1.2));
  CameraImages images;
  scene_.render(m, levelCamera(0.3), images);
  int wall = 0;
  for (std::size_t i = 0; i < images.depth.size(); ++i) {
    if (images.label[i] != static_cast<std::uint8_t>(SurfaceClass::kObstacle)) continue;
    ++wall;
    EXPECT_NEAR(images.depth[i], 1.95, 1e-3) << "pixel " << i;
  }
  // Above the wall's top (2 m) no pixel at this fov; below it, the ground in the lower rows.
  EXPECT_GT(wall, 64 * 20);
  const std::size_t centre = 24 * 64 + 32;
  EXPECT_EQ(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kObstacle));
}

TEST_F(CameraRender, ABoxLandsOnThePixelsTheModelPredicts) {
  // A thin board (2 mm deep) 3 m ahead, off the axis: its face projects to a rectangle.
  const double x = 3.0, y = 0.4, hy = 0.25, top = 0.6, camera_z = 0.35;
  scene_.setObstacles({standingBox(x, y, 0.001, hy, top)});
  CameraIntrinsics c = cameraIntrinsics(96, 72, 1.3);
  const CameraModel m(c);
  CameraImages images;
  scene_.render(m, levelCamera(camera_z), images);
  // The face's corners in the optical frame (z forward, x right = -y, y down = -z).
  const double z = x - 0.001;
  const Eigen::Vector2d low = *m.project({-(y + hy), -(top - camera_z), z});
  const Eigen::Vector2d high = *m.project({-(y - hy), camera_z, z});
  int inside = 0;
  for (int v = 0; v < m.height(); ++v) {
    for (int u = 0; u < m.width(); ++u) {
      const bool is_box = images.label[static_cast<std::size_t>(v) * m.width() + u] ==
                          static_cast<std::uint8_t>(SurfaceClass::kObstacle);
      const double margin = 0.5;  // [px]
      const bool surely_in = u > low.x() + margin && u < high.x() - margin &&
                             v > low.y() + margin && v < high.y() - margin;
      const bool surely_out = u < low.x() - margin || u > high.x() + margin ||
                              v < low.y() - margin || v > high.y() + margin;
      if (surely_in) {
        ++inside;
        EXPECT_TRUE(is_box) << "pixel " << u << ", " << v;
      }
      if (surely_out) {
        EXPECT_FALSE(is_box) << "pixel " << u << ", " << v;
      }
    }
  }
  EXPECT_GT(inside, 50);
}

TEST_F(CameraRender, TheGroundBelowALookingDownCamera) {
  const double height = 0.8;
  // Optical z down: the body frame pitched by +pi/2 about y.
  const Eigen::Isometry3d body = Eigen::Translation3d(0.0, 0.0, height) *
                                 Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitY());
  const CameraModel m(cameraIntrinsics(33, 33, 1.0));
  CameraImages images;
  scene_.render(m, opticalFrame(body), images);
  const std::size_t centre = 16 * 33 + 16;
  EXPECT_EQ(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kGround));
  EXPECT_NEAR(images.depth[centre], height, 1e-4);
  for (float d : images.depth) EXPECT_NEAR(d, height, 1e-4);  // a plane facing the camera
}

TEST_F(CameraRender, NothingWithinFarIsInfinityAndNearerThanNearMinusInfinity) {
  CameraIntrinsics c = cameraIntrinsics(16, 16, 0.5);
  c.far = 1.0;
  const CameraModel m(c);
  CameraImages images;
  scene_.render(m, levelCamera(0.3), images);  // the horizon and above: beyond 1 m
  EXPECT_TRUE(std::isinf(images.depth[0]) && images.depth[0] > 0.0f);
  EXPECT_EQ(images.label[0], static_cast<std::uint8_t>(SurfaceClass::kNone));
  scene_.setObstacles({standingBox(0.03, 0.0, 0.001, 1.0, 1.0)});  // 3 cm ahead, nearer than near
  scene_.render(m, levelCamera(0.3), images);
  EXPECT_TRUE(std::isinf(images.depth[8 * 16 + 8]) && images.depth[8 * 16 + 8] < 0.0f);
}

TEST_F(CameraRender, MoversNoRayMeetsAreLeftOutAndTheImagesStayTheSame) {
  // People all around a camera: with its view cone the scene holds only those its rays may meet,
  // and renders the very same images.
  std::vector<Obstacle> people;
  for (int k = 0; k < 24; ++k) {
    Obstacle p;
    p.shape = Obstacle::Shape::kCylinder;
    const double angle = 2.0 * M_PI * k / 24.0, range = 0.8 + 0.3 * (k % 5);
    p.center = {range * std::cos(angle), range * std::sin(angle)};
    p.radius = 0.2;
    p.height = 1.7;
    people.push_back(p);
  }
  CameraIntrinsics c = cameraIntrinsics(48, 32, 1.6);
  c.k1 = -0.1;  // barrel: the widest rays are not the pinhole's
  const CameraModel m(c);
  const Eigen::Isometry3d pose = levelCamera(0.1);
  CameraImages all, culled;
  scene_.setMovers(people);
  scene_.render(m, pose, all);
  const ViewCone view(m, pose);
  int seen = 0;
  for (const Obstacle& p : people) {
    seen += view.mayMeet(Eigen::Vector3d(p.center.x(), p.center.y(), 0.85), std::hypot(0.2, 0.85));
  }
  EXPECT_GT(seen, 4);
  EXPECT_LT(seen, 18);  // those behind and beside it are left out
  scene_.setMovers(people, &view);
  scene_.render(m, pose, culled);
  expectSameImages(culled, all);
  EXPECT_GT(std::count(all.label.begin(), all.label.end(),
                       static_cast<std::uint8_t>(SurfaceClass::kMover)),
            100);
  // A far clip short of them all leaves every one out.
  c.far = 0.3;
  const CameraModel near_only(c);
  const ViewCone short_view(near_only, pose);
  for (const Obstacle& p : people) {
    EXPECT_FALSE(short_view.mayMeet(Eigen::Vector3d(p.center.x(), p.center.y(), 0.85), 0.21));
  }
}

TEST_F(CameraRender, ShadowsFallWhereTheLightIsBlocked) {
  // A 0.5 m tall post under a light shining along +x at 45 degrees: its shadow lies on the ground
  // from its +x face to 0.5 m beyond it; a camera 2 m up looks straight down.
  scene_.setObstacles({standingBox(0.0, 0.0, 0.1, 0.1, 0.5)});
  Appearance look;
  look.light_direction = Eigen::Vector3f(1.0f, 0.0f, -1.0f).normalized();
  scene_.setAppearance(look);
  const Eigen::Isometry3d pose =
      opticalFrame(Eigen::Translation3d(0.0, 0.0, 2.0) *
                   Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitY()));
  const CameraModel m(cameraIntrinsics(65, 65, 1.2));
  const auto pixelOf = [&](double x, double y) {
    const Eigen::Vector2d uv = *m.project(pose.inverse() * Eigen::Vector3d(x, y, 0.0));
    return static_cast<std::size_t>(uv.y()) * 65 + static_cast<std::size_t>(uv.x());
  };
  const std::size_t behind = pixelOf(0.35, 0.0), before = pixelOf(-0.35, 0.0),
                    aside = pixelOf(0.35, 0.4);
  CameraImages plain, shadowed;
  scene_.render(m, pose, plain);
  scene_.setShadows(true);
  scene_.render(m, pose, shadowed);
  for (std::size_t i : {behind, before, aside}) {
    ASSERT_EQ(shadowed.label[i], static_cast<std::uint8_t>(SurfaceClass::kGround));
  }
  // Without shadows the ground is one colour; with them, the shaded ground is the ambient share.
  EXPECT_EQ(plain.rgb[3 * behind], plain.rgb[3 * before]);
  const float lit = -Eigen::Vector3f::UnitZ().dot(look.light_direction);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(shadowed.rgb[3 * before + c], plain.rgb[3 * before + c]);
    EXPECT_EQ(shadowed.rgb[3 * aside + c], plain.rgb[3 * aside + c]);
    const float ambient = look.ground[c] * look.ambient;
    EXPECT_NEAR(shadowed.rgb[3 * behind + c], 255.0f * ambient, 1.0f) << "channel " << c;
    EXPECT_NEAR(plain.rgb[3 * behind + c],
                255.0f * look.ground[c] * (look.ambient + (1.0f - look.ambient) * lit), 1.0f);
  }
  EXPECT_EQ(shadowed.depth, plain.depth);  // shadows change colours only
}

TEST_F(CameraRender, SameImagesEveryTimeAndFromTwoThreads) {
  scene_.setObstacles(
      {standingBox(1.5, -0.3, 0.2, 0.2, 0.4), standingBox(2.5, 0.6, 0.3, 0.1, 0.8)});
  const CameraModel m(cameraIntrinsics(64, 64, 1.5));
  CameraImages first, again, a, b;
  scene_.render(m, levelCamera(0.2), first);
  scene_.render(m, levelCamera(0.2), again);
  std::thread ta([&] { scene_.render(m, levelCamera(0.2), a); });
  std::thread tb([&] { scene_.render(m, levelCamera(0.2), b); });
  ta.join();
  tb.join();
  for (const CameraImages* other : {&again, &a, &b}) expectSameImages(*other, first);
  // Lit faces differ from the ground: the image is not one colour.
  EXPECT_NE(std::count(first.rgb.begin(), first.rgb.end(), first.rgb[0]),
            static_cast<long>(first.rgb.size()));
}

}  // namespace
}  // namespace jetbot_rl
