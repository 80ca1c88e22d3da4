#pragma once

// What a camera sees, as Embree scenes (Intel's ray-tracing kernels, on the CPU): the world's
// static bodies once, shared by every env (CameraWorld: the model), and per env a scene of the
// env's own bodies (CameraEnvScene: the data) and its people. Rendering traces one ray per pixel
// in packets of 16: the people first (exact upright shapes), then the world, then the env's
// bodies, each against what is left of the rays.

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/sensors/camera_model.h"
#include "jetbot_rl/sensors/surface_material.h"
#include "jetbot_rl/sensors/upright_shapes.h"

struct RTCDeviceTy;
struct RTCSceneTy;
struct RTCRay16;

namespace jetbot_rl {
class CameraRobot;
class RobotModel;
class WorldModel;
struct FloorImage;
struct Obstacle;

/// What a pixel shows (the label image's values).
enum class SurfaceClass : std::uint8_t {
  kNone = 0,  ///< Nothing within the far clip (the sky)
  kGround = 1,
  kWall = 2,      ///< The arena walls
  kMap = 3,       ///< The map's obstacle cells and a Gazebo world's solids
  kObstacle = 4,  ///< The env's obstacles
  kMover = 5,     ///< People (and the other robots of a world drawn as cylinders: none yet)
  kRobot = 6,     ///< The robots of the env's world, its own and the others, by their visuals
};

/// How an env's scene looks: the diffuse colour (RGB, each in [0, 1]) of each class of surface,
/// the light and the camera's exposure. The defaults are the fixed look; appearance randomisation
/// draws one per env at each reset (CameraSensor).
struct Appearance {
  Eigen::Vector3f ground{0.45f, 0.45f, 0.42f};
  Eigen::Vector3f wall{0.85f, 0.85f, 0.8f};
  Eigen::Vector3f map{0.6f, 0.62f, 0.65f};
  Eigen::Vector3f obstacle{0.9f, 0.45f, 0.1f};
  Eigen::Vector3f mover{0.2f, 0.35f, 0.75f};
  Eigen::Vector3f sky{0.75f, 0.82f, 0.92f};
  Eigen::Vector3f floor_tint = Eigen::Vector3f::Ones();  ///< Multiplies the floor image.
  /// The direction the light shines along (unit, pointing down): from above, ahead of x.
  Eigen::Vector3f light_direction = Eigen::Vector3f(0.3f, 0.2f, -1.0f).normalized();
  float light = 1.0f;     ///< The directional light's intensity.
  float ambient = 0.35f;  ///< The share of a colour lit whatever its side faces.
  float exposure = 1.0f;  ///< Gain on every intensity (before the clamp to 1).
  /// A Gazebo world's visuals keep their material colours; false (colours randomised): the map's.
  bool material_colours = true;

  /// The colour of surfaces of class `c` (kNone: the sky).
  const Eigen::Vector3f& colour(SurfaceClass c) const;
};

/// Where render() writes one camera's images, row by row from the top left; nullptr: an image
/// not made.
struct CameraImageView {
  std::uint8_t* rgb = nullptr;    ///< rgb8: width x height x 3
  float* depth = nullptr;         ///< 32FC1: width x height [m]
  std::uint8_t* label = nullptr;  ///< width x height SurfaceClass values
};

/// One camera's images, row by row from the top left.
struct CameraImages {
  std::vector<std::uint8_t> rgb;  ///< rgb8: width x height x 3
  /// 32FC1: distance along the optical axis [m]; +inf where nothing lies within the far clip,
  /// -inf where the surface is nearer than the near clip (REP 118).
  std::vector<float> depth;
  std::vector<std::uint8_t> label;  ///< SurfaceClass of each pixel

  /// All three, sized for `width` x `height`.
  CameraImageView resize(int width, int height);
};

/**
 * The static bodies of a WorldModel as one Embree scene, in the env frame: the arena walls, the
 * map's obstacle cells (blocks of world/obstacle_height) and a Gazebo world's visuals in their
 * colours when it was read with them, else its upright solids and cut cells (the ground, the
 * plane z = 0, is the renderer's). Built once; read concurrently by every env's scene.
 */
class CameraWorld {
 public:
  /// `world` (nullptr: the ground alone), `floor` (nullptr: a plain ground). ModelError with
  /// Embree's message when Embree cannot start.
  explicit CameraWorld(const WorldModel* world, std::shared_ptr<const FloorImage> floor = nullptr);
  ~CameraWorld();
  CameraWorld(const CameraWorld&) = delete;
  CameraWorld& operator=(const CameraWorld&) = delete;

  RTCDeviceTy* device() const { return device_; }
  RTCSceneTy* scene() const { return scene_; }
  /// A scene with nothing in it: what an instance holds while it shows nothing.
  RTCSceneTy* emptyShape() const { return empty_; }
  /// The class of the static scene's geometry `id`.
  SurfaceClass surfaceClass(unsigned id) const { return classes_.at(id); }
  /// The material colour of the static scene's geometry `id` (a Gazebo world's visuals) at its
  /// triangle `triangle` and Embree's barycentric `u`, `v` there (a texture's texel), or none
  /// (its class's colour).
  std::optional<Eigen::Vector3f> colourOf(unsigned id, unsigned triangle, float u, float v) const {
    if (id >= materials_.size() || !materials_[id]) return std::nullopt;
    return materials_[id]->at(triangle, u, v);
  }
  /// The scene may hold surfaces at the ground's height (a Gazebo world's visuals).
  bool hasFloorSurfaces() const { return !materials_.empty(); }
  /// The floor image on the ground, or nullptr.
  const FloorImage* floor() const { return floor_.get(); }
  /// `robot`'s URDF visuals as env scenes draw robots for a camera on `hidden_link` (its own
  /// link, left out of a robot's view of itself): made once per link, shared by the cameras on
  /// it. Not thread-safe (called while the cameras are made). ModelError naming the link of a
  /// visual mesh or texture that cannot be read.
  const CameraRobot* addRobot(const RobotModel& robot, const std::string& hidden_link);

 private:
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;
  RTCSceneTy* empty_ = nullptr;
  std::vector<SurfaceClass> classes_;  // per geometry id of scene_
  // A Gazebo world's visuals of one colour, or of one texture, per geometry id of scene_.
  std::vector<std::optional<SurfaceMaterial>> materials_;
  std::shared_ptr<const FloorImage> floor_;
  std::map<std::string, std::unique_ptr<CameraRobot>> robots_;  // by hidden link
};

/// One robot of an env's world where it stands: its bodies' link frames in the env frame.
struct RobotPose {
  bool own = false;  ///< The robot whose camera renders (seen without its camera's housing).
  std::vector<Eigen::Isometry3d> bodies;
};

/// One env's scene: the shared world, the env's own obstacles and its movers; renders its
/// camera's images.
class CameraEnvScene {
 public:
  /// The env's scene of `world`, its robots drawn as `robot` (CameraWorld::addRobot(); nullptr:
  /// setRobots() is not used).
  explicit CameraEnvScene(const CameraWorld& world, const CameraRobot* robot = nullptr);
  ~CameraEnvScene();
  CameraEnvScene(const CameraEnvScene&) = delete;
  CameraEnvScene& operator=(const CameraEnvScene&) = delete;

  /// Replaces the env's obstacles with the placed ones of `obstacles` (env frame).
  void setObstacles(const std::vector<Obstacle>& obstacles);
  /// The floor on the env's ground from now on (a task's painted track), or nullptr: the world's.
  void setFloor(std::shared_ptr<const FloorImage> floor) { floor_ = std::move(floor); }
  /// The floor the env's ground shows, or nullptr (a plain ground).
  const FloorImage* floor() const { return floor_ ? floor_.get() : world_.floor(); }
  /// How the scene looks from now on.
  void setAppearance(const Appearance& appearance) { appearance_ = appearance; }
  /// Shadows of the directional light: a surface the light does not reach gets the ambient share
  /// alone (one more ray per lit pixel). Off by default.
  void setShadows(bool on) { shadows_ = on; }
  const Appearance& appearance() const { return appearance_; }
  /// Replaces the env's movers (people, other robots as cylinders) with `movers` where they
  /// stand now (upright shapes, intersected exactly). `view`: only the movers its rays may meet
  /// are kept (none: all).
  void setMovers(const std::vector<Obstacle>& movers, const ViewCone* view = nullptr);
  /// Places the robots of the env's world (none before the first call), each body an instance of
  /// the scene's robot at its pose; robots beyond `robots.size()` are hidden. Needs a robot.
  /// `view`: only the bodies its rays may meet are placed.
  void setRobots(const std::vector<RobotPose>& robots, bool commit = true,
                 const ViewCone* view = nullptr);
  /// Renders what `model` sees from `pose` (its optical frame in the env frame: z forward, x
  /// right, y down) into `out`'s images, each model.width() x model.height(). Safe to call from
  /// several threads at once.
  void render(const CameraModel& model, const Eigen::Isometry3d& pose,
              const CameraImageView& out) const;
  /// render() into `images`, all three sized here.
  void render(const CameraModel& model, const Eigen::Isometry3d& pose, CameraImages& images) const;

 private:
  /// The instance id render() gives a hit in the world's own scene.
  static constexpr unsigned kWorldHit = 0xfffffffeu;
  /// The class of the geometry a ray hit (`instance`: kWorldHit, a mover's or a robot body's
  /// instance, or invalid: the env's obstacles).
  SurfaceClass classOf(unsigned geometry, unsigned instance) const;

  /// A robot body's instance in scene_: its geometry id, the body, which view of it, and the
  /// rotation that takes its normals to the env frame.
  struct RobotSlot {
    unsigned id = 0;
    int body = 0;
    bool own = false;
    RTCSceneTy* shown = nullptr;                       // the scene its instance holds
    bool enabled = false;                              // placed and maybe seen
    Eigen::Vector4f sphere = Eigen::Vector4f::Zero();  // bounding: centre and radius [m], env frame
    Eigen::Matrix3f normals = Eigen::Matrix3f::Identity();
  };
  /// A new instance of `shape` in scene_.
  unsigned addInstance(RTCSceneTy* shape);
  struct Frame;
  /// Renders the tile of pixels whose top left is (x0, y0) [px] into the frame's images.
  void renderTile(const Frame& frame, int x0, int y0) const;
  /// Sets `lit` to 0 in the lanes of `valid` whose ray from its origin in `rays` towards the
  /// light (against `light_direction`) meets anything (the movers too).
  void castShadows(const int* valid, const Eigen::Vector3f& light_direction, RTCRay16* rays,
                   float* lit) const;

  const CameraWorld& world_;
  const CameraRobot* robot_;  // how its robots look, or nullptr
  RTCSceneTy* scene_ = nullptr;
  unsigned obstacles_id_;  // the obstacles' geometry in scene_, or RTC_INVALID_GEOMETRY_ID
  std::vector<UprightShape> movers_;            // those placed (and maybe seen)
  std::vector<Eigen::Vector4f> mover_spheres_;  // bounding movers_: centres and radii [m]
  std::vector<int> mover_of_sphere_;            // the index in movers_ of each
  std::vector<RobotSlot> robots_;  // robot r's body b: r x bodies + b (unused ones disabled)
  std::vector<int> robot_of_id_;   // per geometry id of scene_: its slot in robots_, or -1
  std::vector<Eigen::Vector4f> obstacle_spheres_;  // bounding: centre and radius [m], env frame
  Appearance appearance_;
  bool shadows_ = false;
  std::shared_ptr<const FloorImage> floor_;  // the env's own, or none: the world's
};

/// The optical frame of a camera whose body frame (x forward, y left, z up: REP 103) is `body`.
Eigen::Isometry3d opticalFrame(const Eigen::Isometry3d& body);

}  // namespace jetbot_rl
