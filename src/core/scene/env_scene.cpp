// An env's scene (EnvScene): its world, layouts, curriculum, people and other robots.
#include "scene/env_scene.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "env/env_physics.h"
#include "jetbot_rl/scene/movers.h"
#include "jetbot_rl/tasks/task_capabilities.h"
#include "jetbot_rl/world/world_generation.h"
#include "scene/people_bodies.h"
#include "scene/robot_team.h"
#include "world/world_shapes.h"

namespace jetbot_rl {

EnvScene::EnvScene(const EnvConfig& config, double robot_radius, WorldDrawing* drawer,
                   FloorDrawing* floor_drawer)
    : config_(config),
      drawer_(drawer),
      floor_drawer_(floor_drawer),
      k_(config.team.robots_per_env) {
  const int n = config_.numRows();
  if (config_.world.enabled()) {
    world_ = std::make_shared<const WorldModel>(config_.world, robot_radius);
    shapes_ = std::make_unique<WorldShapes>(*world_);
    if (config_.movers.count() > 0) {
      movers_ = std::make_unique<MoverSet>(config_.movers, *world_, config_.num_envs, config_.seed);
      people_ =
          std::make_unique<PeopleBodies>(*movers_, k_, config_.decimation, config_.physics_dt);
      moving_.push_back(people_.get());
    }
  }
  for (int e = 0; e < n; ++e) rngs_.emplace_back(config_.seed, e);
  layouts_.resize(n);
  curriculum_ = Curriculum(config_.world, n);
  robot_at_.assign(n, Eigen::Vector2d::Zero());
  present_.assign(n, 1);
  redraw_people_.assign(config_.num_envs, 0);
  generated_ = !config_.world.families.empty();
  shared_obstacles_ = config_.world.num_boxes + config_.world.num_cylinders > 0 || generated_;
  redraw_obstacles_.assign(config_.num_envs, 1);
  if (generated_ && k_ > 1) grids_.resize(config_.num_envs);
}

EnvScene::~EnvScene() = default;

void EnvScene::attach(std::vector<std::unique_ptr<EnvPhysics>>& envs, double robot_height) {
  envs_ = &envs;
  if (!world_ || (k_ == 1 && config_.team.swap_radius <= 0.0)) return;
  team_ = std::make_unique<RobotTeam>(config_.team, *world_, config_.num_envs,
                                      world_->robotRadius(), robot_height, config_.physics_dt);
  for (auto& env : envs) env->setPeers(team_->footprints());
  moving_.push_back(team_.get());
  seen_.resize(moving_.size() > 1 ? config_.num_envs : 0);
}

void EnvScene::beginReset(const std::vector<std::uint8_t>& selected,
                          std::optional<std::uint64_t> seed) {
  if (!team_) return;
  // Robots reset together start free of each other, whatever they did before.
  for (std::size_t e = 0; e < selected.size(); ++e) {
    if (selected[e]) team_->forget(static_cast<int>(e));
  }
  // A world whose robots all start anew gets new obstacles; one robot starts among the old.
  for (int g = 0; g < config_.num_envs; ++g) {
    if (std::all_of(selected.begin() + g * k_, selected.begin() + (g + 1) * k_,
                    [](std::uint8_t s) { return s != 0; })) {
      redraw_obstacles_[g] = 1;
    }
  }
  // A world whose robots are all reset gets new people once they stand at their starts;
  // otherwise its people walk on and a robot starts clear of them.
  for (int g = 0; people_ && g < config_.num_envs; ++g) {
    redraw_people_[g] = std::all_of(selected.begin() + g * k_, selected.begin() + (g + 1) * k_,
                                    [](std::uint8_t s) { return s != 0; });
    if (redraw_people_[g] && seed) movers_->reseed(g, *seed);
  }
}

void EnvScene::reseed(int row, std::uint64_t seed) {
  rngs_[row] = Rng(seed, row);
  if (movers_ && !team_) movers_->reseed(row, seed);  // a team's: per world (beginReset())
}

void EnvScene::endReset() {
  for (int g = 0; team_ && people_ && g < config_.num_envs; ++g) {
    if (redraw_people_[g]) redrawPeople(g);
  }
}

void EnvScene::beginRound(int world) {
  for (int e = world * k_; e < (world + 1) * k_; ++e) team_->forget(e);
  redraw_obstacles_[world] = 1;
  if (people_) redraw_people_[world] = 1;
}

void EnvScene::endRound(int world) {
  if (people_) redrawPeople(world);
}

void EnvScene::place(int row) {
  if (team_) {
    placeTeamRobot(row);
  } else if (world_) {
    placeRobot(row);
  }
  if (floor_drawer_) {
    layouts_[row].floor = floor_drawer_->drawFloor(row, rngs_[row], (*envs_)[row]->rootState());
  }
}

void EnvScene::placeRobot(int row) {
  // The layout from the row's own stream: its start, the task's goal, the obstacles.
  EnvPhysics& physics = *(*envs_)[row];
  EnvLayout& layout = layouts_[row];
  const double difficulty = curriculum_.drawDifficulty(row, rngs_[row]);
  world_->drawLayout(rngs_[row], row, difficulty, drawer_, layout);
  physics.moveRobot(layout.start);
  physics.setObstacles(layout.obstacles);
  given_up_ += static_cast<std::uint64_t>(layout.given_up);
  if (layout.unmade) ++unmade_;
  if (people_) {
    movers_given_up_ += static_cast<std::uint64_t>(movers_->reset(row, layout));
    people_->enter(row, physics);
  }
}

void EnvScene::placeTeamRobot(int row) {
  EnvPhysics& physics = *(*envs_)[row];
  EnvLayout& layout = layouts_[row];
  Rng& rng = rngs_[row];
  std::optional<Eigen::Vector2d> goal;
  double yaw = 0.0;
  const bool avoid_people = people_ && !redraw_people_[row / k_];
  if (!shared_obstacles_) {
    team_->drawStart(row, rng, layout.start, goal, yaw,
                     avoid_people ? &people_->bodies(row) : nullptr);
    layout.obstacles.clear();
  } else {
    const int world = row / k_;
    if (redraw_obstacles_[world]) drawWorldObstacles(row);  // by the robot placed first
    if (generated_) {
      // Each robot its own start on the layout's free floor, and a goal it has a path to.
      const FootprintGrid& grid = *grids_[world];
      const auto fits = [&](const Eigen::Vector2d& p) {
        return fitsGeneratedStart(*world_, grid, layout.obstacles, p);
      };
      if (!team_->drawStart(row, rng, layout.start, goal, yaw,
                            avoid_people ? &people_->bodies(row) : nullptr, fits)) {
        ++unmade_;
      }
    } else {
      std::vector<Obstacle> avoid = avoid_people ? people_->bodies(row) : std::vector<Obstacle>();
      avoid.insert(avoid.end(), layout.obstacles.begin(), layout.obstacles.end());
      team_->drawStart(row, rng, layout.start, goal, yaw, &avoid);
    }
    physics.setObstacles(layout.obstacles);
  }
  if (drawer_) {
    WorldDraft draft;
    draft.start = layout.start;
    draft.goal = goal;
    std::optional<FootprintGrid> reach;
    if (shared_obstacles_) draft.obstacles = &layout.obstacles;
    if (generated_) {
      reach.emplace(*grids_[row / k_]);
      reach->reachFrom(layout.start);
      draft.reach = &*reach;
    }
    std::vector<Eigen::Vector2d> keep_free{layout.start};
    drawer_->drawInWorld(row, rng, *world_, draft, keep_free);
    drawer_->layoutDrawn(row, *world_, layout);
  }
  if (yaw != 0.0) {  // facing the circle's centre, turned by the drawn initial_yaw
    RootState s = physics.rootState();
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
    s.orientation = turn * s.orientation;
    s.com_linear_velocity = turn * s.com_linear_velocity;
    s.angular_velocity = turn * s.angular_velocity;
    physics.setRootState(s);
  }
  physics.moveRobot(layout.start);
  team_->started(row);
  team_->capture(row, physics);
}

void EnvScene::drawWorldObstacles(int row) {
  const int world = row / k_;
  EnvLayout& layout = layouts_[row];
  Rng& rng = rngs_[row];
  if (generated_) {
    const double difficulty = curriculum_.drawDifficulty(row, rng);
    grids_[world] = std::make_unique<FootprintGrid>(
        drawSharedGeneratedLayout(*world_, rng, difficulty, layout));
    if (layout.unmade) ++unmade_;
  } else {
    world_->drawObstacles(rng, {}, layout);
  }
  given_up_ += static_cast<std::uint64_t>(layout.given_up);
  for (int e = world * k_; e < (world + 1) * k_; ++e) {
    if (e == row) continue;
    layouts_[e].obstacles = layout.obstacles;
    layouts_[e].family = layout.family;
    layouts_[e].difficulty = layout.difficulty;
    layouts_[e].unmade = layout.unmade;
  }
  redraw_obstacles_[world] = 0;
}

void EnvScene::redrawPeople(int world) {
  const int first = world * k_;
  for (int e = first; e < first + k_; ++e) robot_at_[e] = layouts_[e].start;
  movers_given_up_ +=
      static_cast<std::uint64_t>(movers_->reset(world, layouts_[first], &robot_at_[first], k_));
  for (int e = first; e < first + k_; ++e) people_->enter(e, *(*envs_)[e]);
  redraw_people_[world] = 0;
}

void EnvScene::robotMoved(int row) {
  if (team_) team_->capture(row, *(*envs_)[row]);
}

void EnvScene::beginWorldStep(int world) {
  if (!people_) return;  // the other robots need no plan: they were captured
  const int first = world * k_;
  for (int e = first; e < first + k_; ++e) {
    robot_at_[e] = (*envs_)[e]->rootState().position.head<2>();
    present_[e] = !team_ || !team_->waiting(e);
  }
  WorldStep step;
  step.world = world;
  step.layout = &layouts_[first];
  step.robots = &robot_at_[first];
  step.present = &present_[first];
  step.num_robots = k_;
  step.dt = config_.controlDt();
  for (MovingBodies* bodies : moving_) bodies->beginWorldStep(step);
}

SensedEnv EnvScene::sensed(int row) const {
  // The people and the other robots of its world, where they are now.
  const std::vector<Obstacle>* moving = nullptr;
  if (moving_.size() == 1) {
    moving = &moving_.front()->bodies(row);
  } else if (moving_.size() > 1) {
    std::vector<Obstacle>& all = seen_[row / k_];
    all.clear();
    for (const MovingBodies* bodies : moving_) {
      const std::vector<Obstacle>& b = bodies->bodies(row);
      all.insert(all.end(), b.begin(), b.end());
    }
    moving = &all;
  }
  SensedEnv sensed{*(*envs_)[row], layouts_[row], moving, nullptr, {}};
  if (people_) sensed.people = &people_->bodies(row);
  if (team_) sensed.robots = {envs_, &present_, row / k_ * k_, k_};
  return sensed;
}

}  // namespace jetbot_rl
