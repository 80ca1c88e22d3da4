// jetbot_rl_camera_bench: camera frames per second of the Embree renderer (RGB, depth and labels
// at once) for a batch of envs in the office map, each with its own obstacles and camera pose.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/world/world_model.h"

namespace {

struct Options {
  int num_envs = 256;
  int width = 64;
  int height = 64;
  int frames = 20;  // per env
  int threads = 2;
  int obstacles = 10;  // per env
  int people = 0;      // per env: movers, moved before every frame as the batch moves them
  int shadows = 0;     // 1: the light casts shadows
  std::string map = JETBOT_RL_DEFAULT_MAP;
  std::string save;  // env 0's images as SAVE_rgb.ppm and SAVE_label.pgm, to look at
};

/// Writes a binary PPM (3 channels) or PGM (1) of `pixels`.
bool writeNetpbm(const std::string& path, int width, int height, int channels,
                 const std::vector<std::uint8_t>& pixels) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  std::fprintf(f, "P%d\n%d %d\n255\n", channels == 3 ? 6 : 5, width, height);
  const bool written = std::fwrite(pixels.data(), 1, pixels.size(), f) == pixels.size();
  return std::fclose(f) == 0 && written;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  Options o;
  std::string error;
  const bool parsed = parseOptions(
      argc, argv,
      [&o](const std::string& option, const std::string& value, std::string& err) {
        if (option == "--num-envs")
          return parseWholeNumber(option, value, 1, 100000, o.num_envs, err);
        if (option == "--width")
          return parseWholeNumber(option, value, 1, kMaxImageSide, o.width, err);
        if (option == "--height")
          return parseWholeNumber(option, value, 1, kMaxImageSide, o.height, err);
        if (option == "--frames") return parseWholeNumber(option, value, 1, 1000000, o.frames, err);
        if (option == "--threads") return parseWholeNumber(option, value, 1, 256, o.threads, err);
        if (option == "--obstacles")
          return parseWholeNumber(option, value, 0, 10000, o.obstacles, err);
        if (option == "--people") return parseWholeNumber(option, value, 0, 1000, o.people, err);
        if (option == "--shadows") return parseWholeNumber(option, value, 0, 1, o.shadows, err);
        if (option == "--map") {
          o.map = value;
          return true;
        }
        if (option == "--save") {
          o.save = value;
          return true;
        }
        return false;
      },
      error);
  if (!parsed) {
    std::fprintf(stderr,
                 "jetbot_rl_camera_bench: %s\nusage: jetbot_rl_camera_bench [--num-envs N] "
                 "[--width W] [--height H] [--frames F] [--threads T] [--obstacles K] [--people P] "
                 "[--shadows 0|1] [--map YAML] [--save PREFIX]\n",
                 error.c_str());
    return 2;
  }
  try {
    WorldConfig config;
    config.map = o.map;
    const WorldModel world(config, 0.1);
    const auto build_start = std::chrono::steady_clock::now();
    const CameraWorld camera_world(&world);
    CameraIntrinsics intrinsics;
    intrinsics.width = o.width;
    intrinsics.height = o.height;
    intrinsics.horizontal_fov = 2.0;  // about the Jetbot's wide angle
    const CameraModel model(intrinsics);
    // Each env: its own obstacles and a camera 10 cm above a free point, looking along a drawn
    // heading, as a robot's would.
    std::vector<std::unique_ptr<CameraEnvScene>> scenes;
    std::vector<Eigen::Isometry3d> poses;
    std::vector<std::vector<Obstacle>> people(o.num_envs);
    for (int e = 0; e < o.num_envs; ++e) {
      Rng rng(1, static_cast<std::uint64_t>(e));
      std::vector<Obstacle> obstacles;
      for (int k = 0; k < o.obstacles; ++k) {
        const std::optional<Eigen::Vector2d> p = world.drawFreePoint(rng, 0.3);
        if (!p) continue;
        Obstacle b;
        b.shape = k % 2 ? Obstacle::Shape::kCylinder : Obstacle::Shape::kBox;
        b.center = *p;
        b.half_extents = {uniform(rng, 0.05, 0.2), uniform(rng, 0.05, 0.2)};
        b.radius = uniform(rng, 0.05, 0.2);
        b.yaw = uniform(rng, -3.14, 3.14);
        b.height = 0.5;
        obstacles.push_back(b);
      }
      scenes.push_back(std::make_unique<CameraEnvScene>(camera_world));
      scenes.back()->setObstacles(obstacles);
      scenes.back()->setShadows(o.shadows != 0);
      for (int k = 0; k < o.people; ++k) {
        Obstacle person;
        person.shape = Obstacle::Shape::kCylinder;
        person.center = world.drawFreePoint(rng, 0.3).value_or(Eigen::Vector2d::Zero());
        person.radius = 0.2;
        person.height = 1.7;
        people[e].push_back(person);
      }
      const Eigen::Vector2d at = world.drawFreePoint(rng, 0.2).value_or(Eigen::Vector2d::Zero());
      poses.push_back(
          opticalFrame(Eigen::Translation3d(at.x(), at.y(), 0.1) *
                       Eigen::AngleAxisd(uniform(rng, -3.14, 3.14), Eigen::Vector3d::UnitZ())));
    }
    const double build_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
    // Envs split into one block per thread, as BatchedEnv steps them.
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> workers;
    for (int t = 0; t < o.threads; ++t) {
      workers.emplace_back([&, t] {
        CameraImages images;
        for (int f = 0; f < o.frames; ++f) {
          for (int e = t; e < o.num_envs; e += o.threads) {
            if (o.people > 0) {  // each a step of 2 cm, as the batch moves them before an image
              for (Obstacle& p : people[e]) p.center.x() += f % 2 ? -0.02 : 0.02;
              // As the batch does: those no ray can meet left out (all kept with shadows).
              const ViewCone view(model, poses[e]);
              scenes[e]->setMovers(people[e], o.shadows ? nullptr : &view);
            }
            scenes[e]->render(model, poses[e], images);
          }
        }
      });
    }
    for (std::thread& w : workers) w.join();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double frames = static_cast<double>(o.frames) * o.num_envs;
    std::printf(
        "envs=%d threads=%d image=%dx%d people=%d shadows=%d frames=%.0f wall_s=%.3f "
        "scenes_build_s=%.3f\n",
        o.num_envs, o.threads, o.width, o.height, o.people, o.shadows, frames, seconds, build_s);
    std::printf("frames_per_s=%.0f\n", frames / seconds);
    std::printf("megarays_per_s=%.1f\n", frames * o.width * o.height / seconds / 1e6);
    if (!o.save.empty()) {
      CameraImages images;
      scenes[0]->render(model, poses[0], images);
      if (!writeNetpbm(o.save + "_rgb.ppm", o.width, o.height, 3, images.rgb) ||
          !writeNetpbm(o.save + "_label.pgm", o.width, o.height, 1, images.label)) {
        std::fprintf(stderr, "jetbot_rl_camera_bench: cannot write %s_*\n", o.save.c_str());
        return 1;
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_camera_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
