#include "jetbot_rl/env/env_view.h"

#include <algorithm>
#include <cmath>

#include "env/env_physics.h"
#include "env/env_randomizer.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/scene/movers.h"
#include "robot/bullet_conversions.h"
#include "scene/env_scene.h"
#include "sensors/camera_sensor.h"
#include "sensors/scan_sensor.h"

namespace jetbot_rl {

Eigen::Vector3d EnvView::origin() const {
  // Isaac Sim's GridCloner layout: rows along -x, columns along +y, centred on the world origin.
  const int n = batch_->config_.num_envs;
  const int per_row = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
  const int rows = (n + per_row - 1) / per_row;
  const int cols = (n + rows - 1) / rows;
  const double spacing = batch_->config_.env_spacing;
  const int env = env_ / batch_->config_.team.robots_per_env;  // the robots of an env share it
  const int row = env / cols;
  const int col = env % cols;
  return {0.5 * spacing * (rows - 1) - row * spacing, col * spacing - 0.5 * spacing * (cols - 1),
          0.0};
}

RootState EnvView::rootState() const { return batch_->envs_[env_]->rootState(); }

BodyTwist EnvView::rootTwist() const {
  BodyTwist twist;
  batch_->envs_[env_]->rootLinkTwist(twist.linear, twist.angular);
  return twist;
}

std::vector<LinkPose> EnvView::linkPoses() const {
  std::vector<LinkPose> poses;
  Eigen::Isometry3d env_origin = Eigen::Isometry3d::Identity();
  env_origin.translation() = origin();
  const auto& bodies = batch_->robot_->bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Eigen::Isometry3d body = toEigen(batch_->envs_[env_]->linkPose(static_cast<int>(b)));
    for (const auto& link : bodies[b].links) {
      poses.push_back({link.name, env_origin * body * link.offset});
    }
  }
  return poses;
}

void EnvView::jointStates(JointStates& out) const {
  const EnvPhysics& physics = *batch_->envs_[env_];
  const std::vector<int>& dof_of_joint = batch_->dof_of_joint_;
  const std::size_t n = dof_of_joint.size();
  out.position.resize(n);
  out.velocity.resize(n);
  out.effort.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const int body = static_cast<int>(j) + 1;  // joint j drives body j + 1
    out.position[j] = physics.jointPosition(body);
    out.velocity[j] = physics.jointVelocity(body);
    out.effort[j] = dof_of_joint[j] < 0 ? 0.0 : physics.dofEffort(dof_of_joint[j]);
  }
}

double EnvView::dofVelocity(int dof) const {
  if (dof < 0 || dof >= static_cast<int>(batch_->wheel_low_.size())) {
    throw InputError("dof " + std::to_string(dof) + " is out of range");
  }
  return batch_->envs_[env_]->dofVelocity(dof);
}

double EnvView::maxJointError() const { return batch_->envs_[env_]->maxJointError(); }

RandomizationDraw EnvView::randomization() const { return batch_->randomizer_->values(env_); }

const EnvLayout& EnvView::layout() const { return batch_->scene_->layout(env_); }

bool EnvView::collided() const { return batch_->collided_[env_] != 0; }

const std::vector<Obstacle>& EnvView::movers() const {
  static const std::vector<Obstacle> kNone;
  const MoverSet* movers = batch_->scene_->movers();
  return movers ? movers->bodies(env_ / batch_->config_.team.robots_per_env) : kNone;
}

const float* EnvView::scan() const { return batch_->scan_ ? batch_->scan_->ranges(env_) : nullptr; }

bool EnvView::scanned() const { return batch_->scan_ && batch_->scan_->isNew(env_); }

EnvImages EnvView::images(int camera) const {
  EnvImages view;
  if (camera < 0 || camera >= batch_->numCameras()) return view;
  const BatchImages& images = batch_->cameras_[camera]->images();
  view.width = images.width;
  view.height = images.height;
  const auto pixels = static_cast<std::size_t>(images.width) * images.height;
  const auto e = static_cast<std::size_t>(env_);
  if (!images.rgb.empty()) view.rgb = &images.rgb[e * pixels * 3];
  if (!images.depth.empty()) view.depth = &images.depth[e * pixels];
  if (!images.label.empty()) view.label = &images.label[e * pixels];
  return view;
}

bool EnvView::imaged(int camera) const {
  return camera >= 0 && camera < batch_->numCameras() && batch_->cameras_[camera]->isNew(env_);
}

Eigen::Isometry3d EnvView::cameraPose(int camera) const {
  return camera >= 0 && camera < batch_->numCameras() ? batch_->cameras_[camera]->opticalPose(env_)
                                                      : Eigen::Isometry3d::Identity();
}

}  // namespace jetbot_rl
