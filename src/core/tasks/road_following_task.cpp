#include "jetbot_rl/tasks/road_following_task.h"

#include <Eigen/Geometry>
#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "jetbot_rl/sensors/floor_image.h"
#include "jetbot_rl/tasks/observer_spec.h"

namespace jetbot_rl {
namespace {

// How far along the centreline a step's place is looked for from the last one's [m]: more than
// a step drives, less than a figure eight's crossing is away along it.
constexpr double kPlaceWindow = 0.3;
// An open track is done this short of its end [m] (the root link origin never reaches it).
constexpr double kEndMargin = 0.02;

Eigen::Vector3f colourOf(const std::vector<double>& c) {
  return Eigen::Vector3d(c[0], c[1], c[2]).cast<float>();
}

}  // namespace

std::vector<std::string> RoadObserver::observationNames() const {
  std::vector<std::string> names{"lin_vel_b_x", "ang_vel_b_z"};
  for (int a = 0; a < action_dim_; ++a) names.push_back("last_action_" + std::to_string(a));
  return names;
}

void RoadObserver::observe(const MeasuredState& state, float* obs) const {
  obs[0] = static_cast<float>(state.root.comLinearVelocityBody().x());
  obs[1] =
      static_cast<float>((state.root.orientation.conjugate() * state.root.angular_velocity).z());
  for (int a = 0; a < action_dim_; ++a) {
    obs[2 + a] = state.last_action ? state.last_action[a] : 0.0f;
  }
}

RoadFollowingTask::RoadFollowingTask(const TrackConfig& config) : config_(config) {
  validateConfig(config_);
  if (!config_.points.empty()) user_track_ = userTrack(config_);
}

void RoadFollowingTask::attach(const TaskContext& context) {
  context_ = context;
  if (!context.camera || !context.camera->rgb) {
    throw ConfigError(
        "invalid task = road_following: it observes the camera's rgb image; give the robot a "
        "camera (a Gazebo camera block, e.g. urdf/jetbot_camera.urdf, or camera/link) with rgb "
        "among camera/images and camera/batch_images true");
  }
  observer_ = RoadObserver(context.action_dim > 0 ? context.action_dim : 2);
}

void RoadFollowingTask::describeObservation(ObserverSpec& spec) const {
  if (!context_.camera) return;
  spec.camera_image = "rgb";
  spec.camera_width = context_.camera->intrinsics.width;
  spec.camera_height = context_.camera->intrinsics.height;
  spec.camera_hfov = context_.camera->intrinsics.horizontal_fov;
}

void RoadFollowingTask::resize(int num_envs) {
  const auto n = static_cast<std::size_t>(num_envs);
  tracks_.assign(n, Track());
  senses_.assign(n, EnvSenses());
  places_.assign(n, TrackPlace());
  progress_.assign(n, 0.0);
  outcome_.assign(n, static_cast<unsigned char>(Outcome::kTimeOut));
  curriculum_ = Curriculum(config_.curriculum, 0.0, config_.curriculum_episodes,
                           config_.curriculum_success, config_.curriculum_step, 0.0, num_envs);
  drawn_.assign(n, 0);
}

std::shared_ptr<const FloorImage> RoadFollowingTask::drawFloor(int env, Rng& rng,
                                                               const RootState& start) {
  // The episode that ends here counts for the curriculum: a lap, or not (off the tape, out of
  // time, reset by a caller).
  if (drawn_[env]) {
    curriculum_.episodeEnded(env, outcome_[env] == static_cast<unsigned char>(Outcome::kSuccess));
  }
  drawn_[env] = 1;
  Track track = config_.points.empty() ? drawTrack(config_, rng, difficulty(env)) : user_track_;
  if (track.closed() && rng.uniform() < 0.5) track = track.reversed();
  // A point of it under the robot, a little aside and askew: the track is placed about the
  // start, not the start on the track (the robot stands where the scene put it).
  const double s0 = uniform(rng, 0.0, track.closed() ? track.length() : 0.25 * track.length());
  const double offset = uniform(rng, -config_.start_offset, config_.start_offset);
  const double yaw_off = uniform(rng, -config_.start_yaw, config_.start_yaw);
  const Eigen::Vector2d t = track.tangent(s0), normal(-t.y(), t.x());
  const Eigen::Vector2d robot_on_track = track.at(s0) + offset * normal;
  const Eigen::Matrix3d r = start.orientation.toRotationMatrix();
  const double yaw = std::atan2(r(1, 0), r(0, 0));
  const Eigen::Matrix2d turn =
      Eigen::Rotation2Dd(yaw - (std::atan2(t.y(), t.x()) + yaw_off)).toRotationMatrix();
  const Eigen::Vector2d p = start.position.head<2>();
  tracks_[env] = track.transformed(turn, p - turn * robot_on_track);
  places_[env] = tracks_[env].place(p, nullptr, 0.0);
  progress_[env] = 0.0;
  Eigen::Vector3f tape = colourOf(config_.tape_colour), floor = colourOf(config_.floor_colour);
  if (config_.random_colours) {
    tape = uniformColour(rng, 0.55, 1.0);
    floor = uniformColour(rng, 0.05, 0.45);
  }
  return paintTrack(tracks_[env], config_.width, tape, floor, config_.resolution);
}

void RoadFollowingTask::sense(int env, const EnvSenses& senses) { senses_[env] = senses; }

void RoadFollowingTask::observe(int env, const RootState& state, float* obs) const {
  MeasuredState measured;
  measured.root = state;
  measured.last_action = senses_[env].action;
  observer_.observe(measured, obs);
}

RoadFollowingTask::Step RoadFollowingTask::look(int env, const RootState& state) const {
  const Track& track = tracks_[env];
  Step step;
  step.place = track.place(state.position.head<2>(), &places_[env], kPlaceWindow);
  step.along = step.place.s - places_[env].s;
  if (track.closed()) {  // across the start of the loop
    if (step.along > 0.5 * track.length()) step.along -= track.length();
    if (step.along < -0.5 * track.length()) step.along += track.length();
  }
  return step;
}

bool RoadFollowingTask::terminated(int env, const RootState& state) const {
  const Step step = look(env, state);
  const Track& track = tracks_[env];
  Outcome o = Outcome::kTimeOut;
  if (std::abs(step.place.offset) > 0.5 * config_.width) {
    o = Outcome::kOffTrack;
  } else if (track.closed() ? progress_[env] + step.along >= config_.lap * track.length()
                            : step.place.s >= track.length() - kEndMargin) {
    o = Outcome::kSuccess;
  }
  outcome_[env] = static_cast<unsigned char>(o);
  return o != Outcome::kTimeOut;
}

float RoadFollowingTask::reward(int env, const RootState& state) const {
  const Step step = look(env, state);
  places_[env] = step.place;
  progress_[env] += step.along;
  const double edge = step.place.offset / (0.5 * config_.width);
  double r = config_.progress_reward * step.along - config_.centre_cost * edge * edge;
  const auto o = static_cast<Outcome>(outcome_[env]);
  if (o == Outcome::kOffTrack) r -= config_.off_track_penalty;
  if (o == Outcome::kSuccess) r += config_.lap_reward;
  return static_cast<float>(r);
}

}  // namespace jetbot_rl
