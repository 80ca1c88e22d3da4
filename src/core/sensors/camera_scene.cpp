#include "jetbot_rl/sensors/camera_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/floor_image.h"
#include "jetbot_rl/world/world_model.h"
#include "sensors/camera_robot.h"
#include "sensors/embree_geometry.h"
#include "sensors/seen_spheres.h"

namespace jetbot_rl {
namespace {

// Rays go in packets of 16, a tile of 4 x 4 pixels (AVX-512's width; measured faster than 8 on
// this machine's Zen 4, docs/performance.md).
using Packet = RTCRayHit16;
constexpr int kLanes = 16, kTileWidth = kTileSide, kTileHeight = kTileSide;
static_assert(kTileWidth * kTileHeight == kLanes && TileRays::kLanes == kLanes,
              "a packet is a tile of the camera model");
// [m]: how far a shadow ray starts off its surface, so that it does not hit the surface itself.
constexpr float kShadowOffset = 1e-4f;
/// How far below the ground a world's surface is still drawn over it [m].
constexpr float kFloorDepth = 1e-3f;
constexpr float kInfinity = std::numeric_limits<float>::infinity();
inline void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context,
                      Packet* packet) {
  rtcIntersect16(valid, scene, context, packet);
}

/// An intensity in [0, 1] as a byte, rounded to nearest (half up; lround's result, without its
/// cost per channel).
inline std::uint8_t toByte(float intensity) {
  return static_cast<std::uint8_t>(255.0f * intensity + 0.5f);
}

/// Whether `view`'s rays may meet upright `o`.
bool mayBeSeen(const Obstacle& o, const ViewCone& view) {
  const Eigen::Vector4d sphere = uprightBoundingSphere(o);
  return view.mayMeet(sphere.head<3>(), sphere[3]);
}

}  // namespace

CameraEnvScene::CameraEnvScene(const CameraWorld& world, const CameraRobot* robot)
    : world_(world), robot_(robot), obstacles_id_(RTC_INVALID_GEOMETRY_ID) {
  // The env's own bodies only; the world's are traced first, in their own scene (render()).
  scene_ = rtcNewScene(world_.device());
  if (!scene_) throwEmbree(world_.device(), "rtcNewScene");
  // Committed at every image with movers: a quick build of its few objects, each kept.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_DYNAMIC);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_LOW);
  rtcCommitScene(scene_);
}

CameraEnvScene::~CameraEnvScene() {
  if (scene_) rtcReleaseScene(scene_);
}

void CameraEnvScene::setObstacles(const std::vector<Obstacle>& obstacles) {
  if (obstacles_id_ != RTC_INVALID_GEOMETRY_ID) rtcDetachGeometry(scene_, obstacles_id_);
  obstacles_id_ = RTC_INVALID_GEOMETRY_ID;
  std::vector<Eigen::Vector3d> corners;
  obstacle_spheres_.clear();
  for (const Obstacle& o : obstacles) {
    if (!o.placed) continue;
    appendObstacleSurface(o, corners);
    appendBoundingSpheres(o, obstacle_spheres_);
  }
  if (!corners.empty()) obstacles_id_ = attachTriangles(world_.device(), scene_, corners);
  rtcCommitScene(scene_);
}

unsigned CameraEnvScene::addInstance(RTCSceneTy* shape) {
  RTCDevice device = world_.device();
  RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  if (!instance) throwEmbree(device, "an instance");
  rtcSetGeometryInstancedScene(instance, shape);
  const unsigned id = rtcAttachGeometry(scene_, instance);
  rtcReleaseGeometry(instance);
  if (robot_of_id_.size() <= id) robot_of_id_.resize(id + 1, -1);
  return id;
}

void CameraEnvScene::setMovers(const std::vector<Obstacle>& movers, const ViewCone* view) {
  movers_.clear();
  mover_spheres_.clear();
  mover_of_sphere_.clear();
  for (const Obstacle& o : movers) {
    if (!o.placed || (view && !mayBeSeen(o, *view))) continue;
    appendBoundingSpheres(o, mover_spheres_);
    mover_of_sphere_.resize(mover_spheres_.size(), static_cast<int>(movers_.size()));
    movers_.push_back(UprightShape::of(o));
  }
}

void CameraEnvScene::setRobots(const std::vector<RobotPose>& robots, bool commit,
                               const ViewCone* view) {
  const CameraRobot* robot = robot_;
  if (!robot) throw Error("CameraEnvScene::setRobots: the scene has no robot (addRobot())");
  const auto bodies = static_cast<std::size_t>(robot->numBodies());
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (robots[r].bodies.size() != bodies) {
      throw Error("CameraEnvScene::setRobots: robot " + std::to_string(r) + " has " +
                  std::to_string(robots[r].bodies.size()) + " body poses, not " +
                  std::to_string(bodies));
    }
  }
  for (std::size_t i = 0; i < std::max(robots.size() * bodies, robots_.size()); ++i) {
    const std::size_t r = i / bodies;
    const int b = static_cast<int>(i % bodies);
    const bool own = r < robots.size() && robots[r].own;
    RTCScene shape = r < robots.size() ? robot->body(b, own) : nullptr;
    if (i == robots_.size()) {
      RobotSlot slot;
      // A unit shape stands in for a body without visuals: every slot keeps an instance.
      slot.shown = shape ? shape : world_.emptyShape();
      slot.id = addInstance(slot.shown);
      slot.body = b;
      robot_of_id_[slot.id] = static_cast<int>(i);
      robots_.push_back(slot);
    }
    RobotSlot& slot = robots_[i];
    RTCGeometry instance = rtcGetGeometry(scene_, slot.id);
    const Eigen::Isometry3d* pose =
        shape ? &robots[r].bodies[static_cast<std::size_t>(b)] : nullptr;
    slot.enabled = false;
    Eigen::Vector4d sphere;
    if (pose) {
      sphere = robot->boundingSphere(b, own);
      sphere.head<3>() = *pose * Eigen::Vector3d(sphere.head<3>());
      if (view && !view->mayMeet(sphere.head<3>(), sphere[3])) pose = nullptr;
    }
    if (!pose) {
      rtcDisableGeometry(instance);
      continue;
    }
    slot.enabled = true;
    slot.sphere = sphere.cast<float>();
    if (shape != slot.shown) {
      rtcSetGeometryInstancedScene(instance, shape);
      slot.shown = shape;
    }
    slot.own = own;
    Eigen::Matrix<float, 3, 4> transform;  // column-major, as Embree reads it
    transform.leftCols<3>() = pose->linear().cast<float>();
    transform.col(3) = pose->translation().cast<float>();
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, transform.data());
    slot.normals = transform.leftCols<3>();  // a rotation: its own inverse transpose
    rtcEnableGeometry(instance);
    rtcCommitGeometry(instance);
  }
  if (commit) rtcCommitScene(scene_);
}

SurfaceClass CameraEnvScene::classOf(unsigned geometry, unsigned instance) const {
  if (instance == kWorldHit) return world_.surfaceClass(geometry);
  if (instance == RTC_INVALID_GEOMETRY_ID) return SurfaceClass::kObstacle;
  return SurfaceClass::kRobot;
}

void CameraEnvScene::render(const CameraModel& model, const Eigen::Isometry3d& pose,
                            CameraImages& images) const {
  render(model, pose, images.resize(model.width(), model.height()));
}

/// What every tile of one image shares: the camera, where it writes, and the env's bodies and
/// people as it sees them (of these, those the current group of tiles may meet).
struct CameraEnvScene::Frame {
  Frame(const CameraModel& m, const Eigen::Isometry3d& pose, const CameraImageView& images)
      : model(m),
        out(images),
        rotation(pose.linear().cast<float>()),
        origin(pose.translation().cast<float>()),
        near(static_cast<float>(m.intrinsics().near)),
        far(static_cast<float>(m.intrinsics().far)) {}

  const CameraModel& model;
  const CameraImageView& out;
  Eigen::Matrix3f rotation;
  Eigen::Vector3f origin;
  float near, far;
  const std::vector<SeenSphere>* bodies = nullptr;  // those the current group may meet
  const std::vector<SeenSphere>* movers = nullptr;
  // The sky's colour, and the bare ground's where every point of it looks the same (no floor
  // image, no shadows): computed once, as the shading would compute them.
  std::uint8_t sky[3] = {0, 0, 0}, ground[3] = {0, 0, 0};
  bool plain_ground = false;
};

void CameraEnvScene::render(const CameraModel& model, const Eigen::Isometry3d& pose,
                            const CameraImageView& out) const {
  Frame frame(model, pose, out);
  // The env's bodies and people as the camera sees them: a tile whose rays can meet none of them
  // is not traced against them.
  // Buffers kept by each thread: no allocation per image.
  thread_local std::vector<Eigen::Vector4f> bodies;
  thread_local std::vector<SeenSphere> seen_bodies, seen_movers, group_bodies, group_movers;
  bodies = obstacle_spheres_;
  for (const RobotSlot& r : robots_) {
    if (r.enabled) bodies.push_back(r.sphere);
  }
  frame.bodies = &group_bodies;
  frame.movers = &group_movers;
  const Appearance& a = appearance_;
  frame.plain_ground = !floor() && !shadows_;
  const float ground_lit = std::max(0.0f, -Eigen::Vector3f::UnitZ().dot(a.light_direction));
  const float ground_shade = a.exposure * (a.ambient + (1.0f - a.ambient) * a.light * ground_lit);
  for (int c = 0; c < 3; ++c) {
    frame.sky[c] = toByte(std::min(1.0f, a.exposure * a.sky[c]));
    frame.ground[c] = toByte(std::min(1.0f, a.ground[c] * ground_shade));
  }
  seenSpheres(bodies, nullptr, pose, frame.far, seen_bodies);
  seenSpheres(mover_spheres_, &mover_of_sphere_, pose, frame.far, seen_movers);
  // Those a group of tiles may meet, and of them those a tile may: two cheap tests, not many.
  const auto meeting = [](const std::vector<SeenSphere>& all, const TileCone& cone,
                          std::vector<SeenSphere>& out) {
    out.clear();
    std::copy_if(all.begin(), all.end(), std::back_inserter(out),
                 [&cone](const SeenSphere& s) { return s.meets(cone); });
  };
  const int width = model.width(), height = model.height();
  constexpr int kGroupWidth = kGroupSide * kTileWidth, kGroupHeight = kGroupSide * kTileHeight;
  for (int gy = 0; gy < height; gy += kGroupHeight) {
    for (int gx = 0; gx < width; gx += kGroupWidth) {
      const TileCone& group = model.groupCones()[static_cast<std::size_t>(
          gy / kGroupHeight * model.groupsAcross() + gx / kGroupWidth)];
      meeting(seen_bodies, group, group_bodies);
      meeting(seen_movers, group, group_movers);
      for (int y0 = gy; y0 < std::min(height, gy + kGroupHeight); y0 += kTileHeight) {
        for (int x0 = gx; x0 < std::min(width, gx + kGroupWidth); x0 += kTileWidth) {
          renderTile(frame, x0, y0);
        }
      }
    }
  }
}

void CameraEnvScene::renderTile(const Frame& frame, int x0, int y0) const {
  const CameraModel& model = frame.model;
  const CameraImageView& out = frame.out;
  const Eigen::Matrix3f& rotation = frame.rotation;
  const Eigen::Vector3f& origin = frame.origin;
  const float far = frame.far;
  const int width = model.width();
  const Appearance& a = appearance_;
  const std::size_t tile =
      static_cast<std::size_t>(y0 / kTileHeight * model.tilesAcross() + x0 / kTileWidth);
  const TileRays& tile_rays = model.tileRays()[tile];
  const int* valid = tile_rays.valid;
  alignas(64) Packet packet;
  PacketRays lanes;
  UprightHits people;
  alignas(64) float ground[kLanes];  // distance to the ground along each ray (+inf: upwards)
  // Plain loops over the lanes, which the compiler vectorises. A direction with z = 1 in the
  // optical frame: the hit distance is the depth. The ground is the plane z = 0, intersected here
  // rather than in the trees: a ray towards it ends there (Embree skips what lies beyond), and
  // one that hits nothing before it hits it.
  for (int k = 0; k < kLanes; ++k) {
    const float x = tile_rays.x[k], y = tile_rays.y[k], z = tile_rays.z[k];
    lanes.dir_x[k] = rotation(0, 0) * x + rotation(0, 1) * y + rotation(0, 2) * z;
    lanes.dir_y[k] = rotation(1, 0) * x + rotation(1, 1) * y + rotation(1, 2) * z;
    lanes.dir_z[k] = rotation(2, 0) * x + rotation(2, 1) * y + rotation(2, 2) * z;
    lanes.org_x[k] = origin.x();
    lanes.org_y[k] = origin.y();
    lanes.org_z[k] = origin.z();
  }
  for (int k = 0; k < kLanes; ++k) {
    const float dz = lanes.dir_z[k];
    ground[k] = dz < 0.0f && origin.z() > 0.0f ? -origin.z() / dz : kInfinity;
    people.t[k] = std::min(far, ground[k]);
    people.shape[k] = -1;
  }
  std::copy_n(lanes.org_x, kLanes, packet.ray.org_x);
  std::copy_n(lanes.org_y, kLanes, packet.ray.org_y);
  std::copy_n(lanes.org_z, kLanes, packet.ray.org_z);
  std::copy_n(lanes.dir_x, kLanes, packet.ray.dir_x);
  std::copy_n(lanes.dir_y, kLanes, packet.ray.dir_y);
  std::copy_n(lanes.dir_z, kLanes, packet.ray.dir_z);
  for (int k = 0; k < kLanes; ++k) {
    packet.ray.tnear[k] = 0.0f;
    packet.ray.time[k] = 0.0f;
    packet.ray.mask[k] = ~0u;
    packet.ray.id[k] = static_cast<unsigned>(k);
    packet.ray.flags[k] = 0;
    packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
  }
  const TileCone& cone = model.tileCones()[tile];
  // The people first (a mover's spheres are consecutive: one test of its shape per tile).
  const std::vector<SeenSphere>& movers = *frame.movers;
  for (std::size_t m = 0, last = movers_.size(); m < movers.size(); ++m) {
    const auto owner = static_cast<std::size_t>(movers[m].owner);
    if (owner == last || !movers[m].meets(cone)) continue;
    last = owner;
    intersectUpright(movers_[owner], static_cast<int>(owner), lanes, valid, people);
  }
  // Then the world, in its own tree, and the env's bodies, each against what is left of the
  // rays: most of them end at a wall, a person or the ground first.
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // neighbouring pixels: neighbouring rays
  std::copy_n(people.t, kLanes, packet.ray.tfar);
  // A Gazebo world's own floor (a floor mesh at z = 0, or just below) is drawn over the ground:
  // its rays reach kFloorDepth below it (not the others': blocks' bottoms lie at z = 0).
  for (int k = 0; world_.hasFloorSurfaces() && k < kLanes; ++k) {
    const float dz = lanes.dir_z[k];
    const float below = dz < 0.0f ? (origin.z() + kFloorDepth) / -dz : kInfinity;
    if (people.shape[k] < 0) packet.ray.tfar[k] = std::min(far, below);
  }
  intersect(valid, world_.scene(), &context, &packet);
  // The world's hits; those the env's bodies do not cover keep their triangle and u, v.
  unsigned world_geometry[kLanes];
  for (int k = 0; k < kLanes; ++k) {
    world_geometry[k] = packet.hit.geomID[k];
    packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
  }
  if (std::any_of(frame.bodies->begin(), frame.bodies->end(),
                  [&cone](const SeenSphere& b) { return b.meets(cone); })) {
    intersect(valid, scene_, &context, &packet);
  }
  // Per lane: the light it gets (-1: no shading, the sky or no rgb), its colour, and whether a
  // shadow ray asks if the light reaches it.
  float lit[kLanes];
  Eigen::Vector3f albedos[kLanes];
  alignas(64) int shaded[kLanes];
  alignas(64) RTCRay16 shadow;
  for (int k = 0; k < kLanes; ++k) {
    lit[k] = -1.0f;
    shaded[k] = 0;
    shadow.org_x[k] = shadow.org_y[k] = shadow.org_z[k] = 0.0f;
    if (!valid[k]) continue;
    const std::size_t i =
        static_cast<std::size_t>(y0 + k / kTileWidth) * width + (x0 + k % kTileWidth);
    std::uint8_t* rgb = out.rgb ? out.rgb + 3 * i : nullptr;
    // The nearest of: an env's body, the world, a person, the ground, else the sky.
    unsigned geometry = packet.hit.geomID[k], instance = packet.hit.instID[0][k];
    if (geometry == RTC_INVALID_GEOMETRY_ID && world_geometry[k] != RTC_INVALID_GEOMETRY_ID) {
      geometry = world_geometry[k];
      instance = kWorldHit;
    }
    const bool embree_hit = geometry != RTC_INVALID_GEOMETRY_ID;
    const bool person = !embree_hit && people.shape[k] >= 0;
    const bool on_ground = !embree_hit && !person && ground[k] <= far;
    if (!embree_hit && !person && !on_ground) {
      if (out.depth) out.depth[i] = kInfinity;
      if (out.label) out.label[i] = static_cast<std::uint8_t>(SurfaceClass::kNone);
      if (rgb) std::copy_n(frame.sky, 3, rgb);
      continue;
    }
    if (on_ground && frame.plain_ground) {
      if (out.depth) out.depth[i] = ground[k] < frame.near ? -kInfinity : ground[k];
      if (out.label) out.label[i] = static_cast<std::uint8_t>(SurfaceClass::kGround);
      if (rgb) std::copy_n(frame.ground, 3, rgb);
      continue;
    }
    const float t = embree_hit ? packet.ray.tfar[k] : person ? people.t[k] : ground[k];
    if (out.depth) out.depth[i] = t < frame.near ? -kInfinity : t;
    const SurfaceClass surface = embree_hit ? classOf(geometry, instance)
                                 : person   ? SurfaceClass::kMover
                                            : SurfaceClass::kGround;
    if (out.label) out.label[i] = static_cast<std::uint8_t>(surface);
    if (!rgb) continue;
    // The floor image where it lies (tinted), a robot's visual's colour, else the class's.
    const RobotSlot* robot = surface == SurfaceClass::kRobot
                                 ? &robots_[static_cast<std::size_t>(robot_of_id_[instance])]
                                 : nullptr;
    const std::optional<Eigen::Vector3f> material =
        instance == kWorldHit && a.material_colours
            ? world_.colourOf(geometry, packet.hit.primID[k], packet.hit.u[k], packet.hit.v[k])
            : std::nullopt;
    Eigen::Vector3f albedo =
        robot      ? robot_->colour(robot->body, robot->own, geometry, packet.hit.primID[k],
                                    packet.hit.u[k], packet.hit.v[k])
        : material ? *material
                   : a.colour(surface);
    const FloorImage* floor = this->floor();
    if (on_ground && floor &&
        floor->colourAt(origin.x() + t * lanes.dir_x[k], origin.y() + t * lanes.dir_y[k], albedo)) {
      albedo = albedo.cwiseProduct(a.floor_tint);
    }
    // Lambert's diffuse light on the side facing the camera, plus the ambient share.
    Eigen::Vector3f normal =
        on_ground ? Eigen::Vector3f::UnitZ()
        : person  ? Eigen::Vector3f(people.normal_x[k], people.normal_y[k], people.normal_z[k])
                  : Eigen::Vector3f(packet.hit.Ng_x[k], packet.hit.Ng_y[k], packet.hit.Ng_z[k]);
    if (robot) normal = robot->normals * normal;  // it comes in its link frame
    const Eigen::Vector3f dir(lanes.dir_x[k], lanes.dir_y[k], lanes.dir_z[k]);
    if (normal.dot(dir) > 0.0f) normal = -normal;
    normal *= 1.0f / normal.norm();
    lit[k] = std::max(0.0f, -normal.dot(a.light_direction));
    albedos[k] = albedo;
    // A shadow ray leaves the surface a little along its normal, towards the light.
    const Eigen::Vector3f at = origin + t * dir + kShadowOffset * normal;
    shadow.org_x[k] = at.x();
    shadow.org_y[k] = at.y();
    shadow.org_z[k] = at.z();
    shaded[k] = shadows_ && lit[k] > 0.0f ? -1 : 0;
  }
  if (shadows_) castShadows(shaded, a.light_direction, &shadow, lit);
  for (int k = 0; k < kLanes; ++k) {
    if (!valid[k] || lit[k] < 0.0f || !out.rgb) continue;
    std::uint8_t* rgb = out.rgb + 3 * (static_cast<std::size_t>(y0 + k / kTileWidth) * width +
                                       (x0 + k % kTileWidth));
    const float shade = a.exposure * (a.ambient + (1.0f - a.ambient) * a.light * lit[k]);
    for (int c = 0; c < 3; ++c) {
      rgb[c] = toByte(std::min(1.0f, albedos[k][c] * shade));
    }
  }
}

void CameraEnvScene::castShadows(const int* valid, const Eigen::Vector3f& light_direction,
                                 RTCRay16* rays, float* lit) const {
  PacketRays lanes;
  UprightHits people;
  for (int k = 0; k < kLanes; ++k) {
    rays->dir_x[k] = lanes.dir_x[k] = -light_direction.x();
    rays->dir_y[k] = lanes.dir_y[k] = -light_direction.y();
    rays->dir_z[k] = lanes.dir_z[k] = -light_direction.z();
    lanes.org_x[k] = rays->org_x[k];
    lanes.org_y[k] = rays->org_y[k];
    lanes.org_z[k] = rays->org_z[k];
    rays->tnear[k] = 0.0f;
    rays->tfar[k] = people.t[k] = std::numeric_limits<float>::infinity();
    people.shape[k] = -1;
    rays->time[k] = 0.0f;
    rays->mask[k] = ~0u;
    rays->id[k] = static_cast<unsigned>(k);
    rays->flags[k] = 0;
  }
  for (std::size_t m = 0; m < movers_.size(); ++m) {
    intersectUpright(movers_[m], static_cast<int>(m), lanes, valid, people);
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded16(valid, world_.scene(), &context, rays);
  alignas(64) int open[kLanes];  // lanes the world did not block: the env's own bodies may
  for (int k = 0; k < kLanes; ++k) open[k] = valid[k] && rays->tfar[k] >= 0.0f ? -1 : 0;
  rtcOccluded16(open, scene_, &context, rays);
  for (int k = 0; k < kLanes; ++k) {
    // Embree marks a blocked ray with tfar < 0.
    if (valid[k] && (rays->tfar[k] < 0.0f || people.shape[k] >= 0)) lit[k] = 0.0f;
  }
}

}  // namespace jetbot_rl
