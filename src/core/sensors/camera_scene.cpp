#include "jetbot_rl/sensors/camera_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/floor_image.h"
#include "jetbot_rl/world/world_model.h"
#include "sensors/camera_robot.h"
#include "sensors/embree_geometry.h"

namespace jetbot_rl {
namespace {

// Rays go in packets of 16, a tile of 4 x 4 pixels (AVX-512's width; measured faster than 8 on
// this machine's Zen 4, docs/performance.md).
using Packet = RTCRayHit16;
constexpr int kLanes = 16, kTileWidth = 4, kTileHeight = 4;
// [m]: how far a shadow ray starts off its surface, so that it does not hit the surface itself.
constexpr float kShadowOffset = 1e-4f;
inline void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context,
                      Packet* packet) {
  rtcIntersect16(valid, scene, context, packet);
}

/// An intensity in [0, 1] as a byte, rounded to nearest (half up; lround's result, without its
/// cost per channel).
inline std::uint8_t toByte(float intensity) {
  return static_cast<std::uint8_t>(255.0f * intensity + 0.5f);
}

/// Whether `view`'s rays may meet upright `o` (standing on the ground): its bounding sphere.
bool mayBeSeen(const Obstacle& o, const ViewCone& view) {
  const double half = 0.5 * o.height;
  const double across = o.shape == Obstacle::Shape::kCylinder ? o.radius : o.half_extents.norm();
  return view.mayMeet(Eigen::Vector3d(o.center.x(), o.center.y(), half),
                      std::sqrt(across * across + half * half));
}

}  // namespace

CameraImageView CameraImages::resize(int width, int height) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  rgb.resize(3 * pixels);
  depth.resize(pixels);
  label.resize(pixels);
  return {rgb.data(), depth.data(), label.data()};
}

CameraEnvScene::CameraEnvScene(const CameraWorld& world)
    : world_(world), obstacles_id_(RTC_INVALID_GEOMETRY_ID) {
  scene_ = rtcNewScene(world_.device());
  if (!scene_) throwEmbree(world_.device(), "rtcNewScene");
  // Committed at every image with movers: a quick build of its few objects, each kept.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_DYNAMIC);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_LOW);
  RTCGeometry instance = rtcNewGeometry(world_.device(), RTC_GEOMETRY_TYPE_INSTANCE);
  if (!instance) throwEmbree(world_.device(), "an instance");
  rtcSetGeometryInstancedScene(instance, world_.scene());
  const float identity[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};  // 3 x 4, column-major
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, identity);
  rtcCommitGeometry(instance);
  world_id_ = rtcAttachGeometry(scene_, instance);
  rtcReleaseGeometry(instance);
  rtcCommitScene(scene_);
}

CameraEnvScene::~CameraEnvScene() {
  if (scene_) rtcReleaseScene(scene_);
}

void CameraEnvScene::setObstacles(const std::vector<Obstacle>& obstacles) {
  if (obstacles_id_ != RTC_INVALID_GEOMETRY_ID) rtcDetachGeometry(scene_, obstacles_id_);
  obstacles_id_ = RTC_INVALID_GEOMETRY_ID;
  std::vector<Eigen::Vector3d> corners;
  for (const Obstacle& o : obstacles) {
    if (o.placed) appendObstacleSurface(o, corners);
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
  if (of_id_.size() <= id) of_id_.resize(id + 1);
  return id;
}

void CameraEnvScene::setMovers(const std::vector<Obstacle>& movers, bool commit,
                               const ViewCone* view) {
  for (std::size_t i = 0; i < std::max(movers.size(), movers_.size()); ++i) {
    if (i == movers_.size()) {
      MoverSlot slot;
      slot.id = addInstance(world_.unitShape(true));
      of_id_[slot.id].mover = static_cast<int>(i);
      movers_.push_back(slot);
    }
    MoverSlot& slot = movers_[i];
    RTCGeometry instance = rtcGetGeometry(scene_, slot.id);
    if (i >= movers.size() || !movers[i].placed || (view && !mayBeSeen(movers[i], *view))) {
      rtcDisableGeometry(instance);
      continue;
    }
    const Obstacle& o = movers[i];
    const bool cylinder = o.shape == Obstacle::Shape::kCylinder;
    if (cylinder != slot.cylinder) {
      rtcSetGeometryInstancedScene(instance, world_.unitShape(cylinder));
      slot.cylinder = cylinder;
    }
    const Eigen::Vector3f scale =
        cylinder ? Eigen::Vector3f(o.radius, o.radius, o.height)
                 : Eigen::Vector3f(2.0 * o.half_extents.x(), 2.0 * o.half_extents.y(), o.height);
    const Eigen::Matrix3f rotation =
        Eigen::AngleAxisf(static_cast<float>(o.yaw), Eigen::Vector3f::UnitZ()).toRotationMatrix();
    Eigen::Matrix<float, 3, 4> transform;  // column-major, as Embree reads it
    transform.leftCols<3>() = rotation * scale.asDiagonal();
    transform.col(3) = Eigen::Vector3f(o.center.x(), o.center.y(), 0.5 * o.height);
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, transform.data());
    // Normals go by the inverse transpose: the rotation and the inverse scale.
    slot.normals = rotation * scale.cwiseInverse().asDiagonal();
    rtcEnableGeometry(instance);
    rtcCommitGeometry(instance);
  }
  if (commit) rtcCommitScene(scene_);
}

void CameraEnvScene::setRobots(const std::vector<RobotPose>& robots, bool commit,
                               const ViewCone* view) {
  const CameraRobot* robot = world_.robot();
  if (!robot) throw Error("CameraEnvScene::setRobots: the world has no robot (setRobot())");
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
      slot.shown = shape ? shape : world_.unitShape(true);
      slot.id = addInstance(slot.shown);
      slot.body = b;
      of_id_[slot.id].robot = static_cast<int>(i);
      robots_.push_back(slot);
    }
    RobotSlot& slot = robots_[i];
    RTCGeometry instance = rtcGetGeometry(scene_, slot.id);
    const Eigen::Isometry3d* pose =
        shape ? &robots[r].bodies[static_cast<std::size_t>(b)] : nullptr;
    if (pose && view) {
      const Eigen::Vector4d& sphere = robot->boundingSphere(b, own);
      if (!view->mayMeet(*pose * Eigen::Vector3d(sphere.head<3>()), sphere[3])) pose = nullptr;
    }
    if (!pose) {
      rtcDisableGeometry(instance);
      continue;
    }
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
  if (instance == world_id_) return world_.surfaceClass(geometry);
  if (instance == RTC_INVALID_GEOMETRY_ID) return SurfaceClass::kObstacle;
  return of_id_[instance].robot >= 0 ? SurfaceClass::kRobot : SurfaceClass::kMover;
}

const Eigen::Vector3f& Appearance::colour(SurfaceClass c) const {
  switch (c) {
    case SurfaceClass::kGround:
      return ground;
    case SurfaceClass::kWall:
      return wall;
    case SurfaceClass::kMap:
      return map;
    case SurfaceClass::kObstacle:
      return obstacle;
    case SurfaceClass::kMover:
    case SurfaceClass::kRobot:  // robots have their URDF colours (render())
      return mover;
    case SurfaceClass::kNone:
      break;
  }
  return sky;
}

void CameraEnvScene::render(const CameraModel& model, const Eigen::Isometry3d& pose,
                            CameraImages& images) const {
  render(model, pose, images.resize(model.width(), model.height()));
}

void CameraEnvScene::render(const CameraModel& model, const Eigen::Isometry3d& pose,
                            const CameraImageView& out) const {
  const int width = model.width(), height = model.height();
  const Eigen::Matrix3f rotation = pose.linear().cast<float>();
  const Eigen::Vector3f origin = pose.translation().cast<float>();
  const float near = static_cast<float>(model.intrinsics().near);
  const float far = static_cast<float>(model.intrinsics().far);
  const std::vector<Eigen::Vector3f>& rays = model.pixelRays();
  const FloorImage* floor = world_.floor();
  const Appearance& a = appearance_;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // neighbouring pixels: neighbouring rays

  // The ground is the plane z = 0, intersected here rather than in the trees: a ray towards it
  // ends there (Embree skips what lies beyond), and one that hits nothing before it hits it.
  // Tiles of kTileWidth x kTileHeight pixels, one packet each.
  for (int y0 = 0; y0 < height; y0 += kTileHeight) {
    for (int x0 = 0; x0 < width; x0 += kTileWidth) {
      alignas(64) int valid[kLanes];
      alignas(64) Packet packet;
      float ground[kLanes];  // distance to the ground along each ray (+inf: it does not go down)
      for (int k = 0; k < kLanes; ++k) {
        const int x = x0 + k % kTileWidth, y = y0 + k / kTileWidth;
        valid[k] = x < width && y < height ? -1 : 0;
        // A direction with z = 1 in the optical frame: the hit distance is the depth.
        const Eigen::Vector3f d =
            valid[k] ? Eigen::Vector3f(rotation * rays[static_cast<std::size_t>(y) * width + x])
                     : Eigen::Vector3f::UnitZ();
        packet.ray.org_x[k] = origin.x();
        packet.ray.org_y[k] = origin.y();
        packet.ray.org_z[k] = origin.z();
        packet.ray.dir_x[k] = d.x();
        packet.ray.dir_y[k] = d.y();
        packet.ray.dir_z[k] = d.z();
        ground[k] = d.z() < 0.0f && origin.z() > 0.0f ? -origin.z() / d.z()
                                                      : std::numeric_limits<float>::infinity();
        packet.ray.tnear[k] = 0.0f;
        packet.ray.tfar[k] = std::min(far, ground[k]);
        packet.ray.time[k] = 0.0f;
        packet.ray.mask[k] = ~0u;
        packet.ray.id[k] = static_cast<unsigned>(k);
        packet.ray.flags[k] = 0;
        packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
      }
      intersect(valid, scene_, &context, &packet);
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
        const bool on_ground = packet.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID && ground[k] <= far;
        if (packet.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID && !on_ground) {
          if (out.depth) out.depth[i] = std::numeric_limits<float>::infinity();
          if (out.label) out.label[i] = static_cast<std::uint8_t>(SurfaceClass::kNone);
          for (int c = 0; rgb && c < 3; ++c) {
            rgb[c] = toByte(std::min(1.0f, a.exposure * a.sky[c]));
          }
          continue;
        }
        const float t = on_ground ? ground[k] : packet.ray.tfar[k];
        if (out.depth) out.depth[i] = t < near ? -std::numeric_limits<float>::infinity() : t;
        const SurfaceClass surface = on_ground
                                         ? SurfaceClass::kGround
                                         : classOf(packet.hit.geomID[k], packet.hit.instID[0][k]);
        if (out.label) out.label[i] = static_cast<std::uint8_t>(surface);
        if (!rgb) continue;
        // The floor image where it lies (tinted), a robot's visual's colour, else the class's.
        const unsigned instance = packet.hit.instID[0][k];
        const RobotSlot* robot = surface == SurfaceClass::kRobot
                                     ? &robots_[static_cast<std::size_t>(of_id_[instance].robot)]
                                     : nullptr;
        const std::optional<Eigen::Vector3f> material = instance == world_id_ && a.material_colours
                                                            ? world_.colourOf(packet.hit.geomID[k])
                                                            : std::nullopt;
        Eigen::Vector3f albedo =
            robot      ? world_.robot()->colour(robot->body, robot->own, packet.hit.geomID[k])
            : material ? *material
                       : a.colour(surface);
        if (on_ground && floor &&
            floor->colourAt(origin.x() + t * packet.ray.dir_x[k],
                            origin.y() + t * packet.ray.dir_y[k], albedo)) {
          albedo = albedo.cwiseProduct(a.floor_tint);
        }
        // Lambert's diffuse light on the side facing the camera, plus the ambient share.
        Eigen::Vector3f normal =
            on_ground ? Eigen::Vector3f::UnitZ()
                      : Eigen::Vector3f(packet.hit.Ng_x[k], packet.hit.Ng_y[k], packet.hit.Ng_z[k]);
        // A mover's normal comes in its unit shape's frame, a robot body's in its link frame.
        if (robot) {
          normal = robot->normals * normal;
        } else if (!on_ground && instance != RTC_INVALID_GEOMETRY_ID && instance != world_id_) {
          normal = movers_[static_cast<std::size_t>(of_id_[instance].mover)].normals * normal;
        }
        const Eigen::Vector3f dir(packet.ray.dir_x[k], packet.ray.dir_y[k], packet.ray.dir_z[k]);
        if (normal.dot(dir) > 0.0f) normal = -normal;
        normal.normalize();
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
  }
}

void CameraEnvScene::castShadows(const int* valid, const Eigen::Vector3f& light_direction,
                                 RTCRay16* rays, float* lit) const {
  for (int k = 0; k < kLanes; ++k) {
    rays->dir_x[k] = -light_direction.x();
    rays->dir_y[k] = -light_direction.y();
    rays->dir_z[k] = -light_direction.z();
    rays->tnear[k] = 0.0f;
    rays->tfar[k] = std::numeric_limits<float>::infinity();
    rays->time[k] = 0.0f;
    rays->mask[k] = ~0u;
    rays->id[k] = static_cast<unsigned>(k);
    rays->flags[k] = 0;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded16(valid, scene_, &context, rays);
  for (int k = 0; k < kLanes; ++k) {
    if (valid[k] && rays->tfar[k] < 0.0f) lit[k] = 0.0f;  // Embree's mark of a blocked ray
  }
}

Eigen::Isometry3d opticalFrame(const Eigen::Isometry3d& body) {
  // Optical z is body x, optical x is body -y, optical y is body -z.
  Eigen::Matrix3d optical_in_body;
  optical_in_body << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  Eigen::Isometry3d out = body;
  out.linear() = body.linear() * optical_in_body;
  return out;
}

}  // namespace jetbot_rl
