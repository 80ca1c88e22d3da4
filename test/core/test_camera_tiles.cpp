// The people's exact shapes and the tiles a camera leaves untraced: rays meet the shapes where
// geometry says, and no pixel changes for what the tiles' cones leave out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "camera_test_util.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/sensors/upright_shapes.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {
namespace {

TEST(UprightShapes, RaysMeetThemWhereTheGeometrySays) {
  // One ray per lane: the nearest hit beyond 0 and below what the lane holds, with its normal.
  const auto cast = [](const Obstacle& o,
                       const std::vector<std::pair<Eigen::Vector3f, Eigen::Vector3f>>& rays) {
    PacketRays packet{};
    UprightHits hits;
    int valid[kPacketLanes] = {};
    for (std::size_t k = 0; k < rays.size(); ++k) {
      packet.org_x[k] = rays[k].first.x();
      packet.org_y[k] = rays[k].first.y();
      packet.org_z[k] = rays[k].first.z();
      packet.dir_x[k] = rays[k].second.x();
      packet.dir_y[k] = rays[k].second.y();
      packet.dir_z[k] = rays[k].second.z();
      valid[k] = -1;
    }
    for (int k = 0; k < kPacketLanes; ++k) {
      hits.t[k] = 100.0f;
      hits.shape[k] = -1;
    }
    intersectUpright(UprightShape::of(o), 3, packet, valid, hits);
    return hits;
  };
  Obstacle person;
  person.shape = Obstacle::Shape::kCylinder;
  person.center = {2.0, 0.0};
  person.radius = 0.5;
  person.height = 1.0;
  const UprightHits c = cast(person, {{{0, 0, 0.5f}, {1, 0, 0}},       // its side, from outside
                                      {{2, 0, 3}, {0, 0, -1}},         // its top, from above
                                      {{2, 0, 0.5f}, {1, 0, 0}},       // from inside: the way out
                                      {{0, 0, 1.5f}, {1, 0, 0}},       // above it
                                      {{0, 0.6f, 0.5f}, {1, 0, 0}}});  // beside it
  EXPECT_FLOAT_EQ(c.t[0], 1.5f);
  EXPECT_EQ(c.shape[0], 3);
  EXPECT_FLOAT_EQ(c.normal_x[0], -1.0f);
  EXPECT_FLOAT_EQ(c.t[1], 2.0f);
  EXPECT_FLOAT_EQ(c.normal_z[1], 1.0f);
  EXPECT_FLOAT_EQ(c.t[2], 0.5f);
  for (int k : {3, 4}) {
    EXPECT_EQ(c.shape[k], -1) << "lane " << k;
    EXPECT_EQ(c.t[k], 100.0f);
  }
  // A box turned a quarter: its 0.25 m half faces the ray; a lane holding a nearer hit keeps it.
  Obstacle box = standingBox(3.0, 0.0, 0.5, 0.25, 1.0);
  box.yaw = 0.5 * M_PI;
  const UprightHits b = cast(box, {{{0, 0, 0.5f}, {1, 0, 0}}, {{3, 2, 0.5f}, {0, -1, 0}}});
  EXPECT_NEAR(b.t[0], 2.75f, 1e-6f);
  EXPECT_NEAR(b.normal_x[0], -1.0f, 1e-6f);
  EXPECT_NEAR(b.normal_y[0], 0.0f, 1e-6f);
  EXPECT_NEAR(b.t[1], 1.5f, 1e-6f);  // its long side, 0.5 m from its centre
  EXPECT_NEAR(b.normal_y[1], 1.0f, 1e-6f);
}

TEST(CameraTiles, EveryPixelShowsTheNearestBodyWhateverTheTilesLeaveOut) {
  const WorldModel world(WorldConfig(), 0.1);  // the ground alone
  const CameraWorld camera_world(&world);
  CameraEnvScene scene(camera_world);
  // Boxes (the env's obstacles, Embree's triangles) and people (upright cylinders and boxes,
  // intersected exactly) scattered about cameras at random poses, some standing inside a
  // person's bounding spheres: every pixel's depth and class are those of the nearest body its
  // ray meets, found here by testing every body with every ray. A tile wrongly left out would
  // show the ground or the sky behind a body.
  Rng rng(7, 0);
  CameraIntrinsics c = cameraIntrinsics(52, 38, 1.6);  // tiles cut by the image's edges
  c.k1 = -0.05;  // barrel: the tiles' cones are not the pinhole's
  const CameraModel m(c);
  int bodies_seen = 0, mismatched = 0, pixels = 0;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<Obstacle> obstacles, people;
    std::vector<UprightShape> shapes;  // obstacles first, then the people
    for (int k = 0; k < 14; ++k) {
      Obstacle o =
          standingBox(uniform(rng, -3.0, 3.0), uniform(rng, -3.0, 3.0), uniform(rng, 0.03, 0.3),
                      uniform(rng, 0.03, 0.3), uniform(rng, 0.1, 1.8));
      o.yaw = uniform(rng, -3.0, 3.0);
      if (k % 2) {
        o.shape = k % 4 == 1 ? Obstacle::Shape::kCylinder : Obstacle::Shape::kBox;
        o.radius = uniform(rng, 0.05, 0.3);
        people.push_back(o);
      } else {
        obstacles.push_back(o);
      }
    }
    for (const auto* group : {&obstacles, &people}) {
      for (const Obstacle& o : *group) shapes.push_back(UprightShape::of(o));
    }
    scene.setObstacles(obstacles);
    scene.setMovers(people);
    // Half the cameras beside a person (within its bounding spheres), tilted and rolled.
    Eigen::Vector3d at(uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0), uniform(rng, 0.05, 1.0));
    if (trial % 2) at.head<2>() = people[0].center + Eigen::Vector2d(0.35, 0.0);
    const Eigen::Isometry3d pose =
        opticalFrame(Eigen::Translation3d(at) *
                     Eigen::AngleAxisd(uniform(rng, -3.1, 3.1), Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(uniform(rng, -0.5, 0.5), Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(uniform(rng, -0.3, 0.3), Eigen::Vector3d::UnitX()));
    CameraImages images;
    scene.render(m, pose, images);
    const Eigen::Matrix3f rotation = pose.linear().cast<float>();
    for (int y = 0; y < m.height(); ++y) {
      for (int x = 0; x < m.width(); x += kPacketLanes) {
        PacketRays rays;
        UprightHits hits;
        int valid[kPacketLanes];
        for (int k = 0; k < kPacketLanes; ++k) {
          valid[k] = x + k < m.width() ? -1 : 0;
          const Eigen::Vector3f d =
              rotation * m.pixelRays()[static_cast<std::size_t>(y) * m.width() +
                                       std::min(x + k, m.width() - 1)];
          rays.org_x[k] = static_cast<float>(at.x());
          rays.org_y[k] = static_cast<float>(at.y());
          rays.org_z[k] = static_cast<float>(at.z());
          rays.dir_x[k] = d.x();
          rays.dir_y[k] = d.y();
          rays.dir_z[k] = d.z();
          hits.t[k] = d.z() < 0.0f ? static_cast<float>(-at.z() / d.z()) : 1e9f;
          hits.shape[k] = -1;
        }
        for (std::size_t s = 0; s < shapes.size(); ++s) {
          intersectUpright(shapes[s], static_cast<int>(s), rays, valid, hits);
        }
        for (int k = 0; k < kPacketLanes && valid[k]; ++k) {
          const std::size_t i = static_cast<std::size_t>(y) * m.width() + x + k;
          const int shape = hits.shape[k];
          const SurfaceClass expected =
              shape < 0 ? (hits.t[k] <= c.far ? SurfaceClass::kGround : SurfaceClass::kNone)
              : static_cast<std::size_t>(shape) < obstacles.size() ? SurfaceClass::kObstacle
                                                                   : SurfaceClass::kMover;
          bodies_seen += shape >= 0;
          ++pixels;
          const bool depth_ok = expected == SurfaceClass::kNone
                                    ? std::isinf(images.depth[i])
                                    : std::abs(images.depth[i] - hits.t[k]) < 1e-3f;
          // Rays grazing an edge may go either way: a few, never a tile's worth.
          mismatched += images.label[i] != static_cast<std::uint8_t>(expected) || !depth_ok;
        }
      }
    }
  }
  EXPECT_GT(bodies_seen, pixels / 10);
  EXPECT_LE(mismatched, pixels / 2000) << "of " << pixels;
}

}  // namespace
}  // namespace jetbot_rl
