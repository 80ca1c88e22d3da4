#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/scene/curriculum.h"
#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/tasks/task_capabilities.h"
#include "jetbot_rl/tasks/task_observer.h"
#include "jetbot_rl/tasks/track.h"

namespace jetbot_rl {

/// The road following task's vector observation: the body-frame forward speed and yaw rate and
/// the last action; the camera's image is the rest of it (ObserverSpec's camera terms).
class RoadObserver : public TaskObserver {
 public:
  explicit RoadObserver(int action_dim) : action_dim_(action_dim) {}
  std::vector<std::string> observationNames() const override;
  void observe(const MeasuredState& state, float* obs) const override;

 private:
  int action_dim_;
};

/**
 * Road following (the Jetbot notebooks' task): a track of floor tape is drawn under the robot at
 * every reset (road/...: a shape, or the user's points) and painted into the floor its camera
 * sees; the robot is rewarded for progress along the centreline, its episode ends when its root
 * link origin leaves the tape (Outcome::kOffTrack) or after road/lap laps or an open track's end
 * (kSuccess). Needs a camera with rgb images: the policy sees the track only through it.
 */
class RoadFollowingTask : public Task, public FloorDrawing {
 public:
  /// ConfigError naming the field for bad parameters or road/points the robot cannot drive.
  explicit RoadFollowingTask(const TrackConfig& config);

  std::string name() const override { return "road_following"; }
  const TaskObserver& observer() const override { return observer_; }
  void describeObservation(ObserverSpec& spec) const override;
  void attach(const TaskContext& context) override;
  void resize(int num_envs) override;
  std::shared_ptr<const FloorImage> drawFloor(int env, Rng& rng, const RootState& start) override;
  void sense(int env, const EnvSenses& senses) override;
  void observe(int env, const RootState& state, float* obs) const override;
  float reward(int env, const RootState& state) const override;
  bool terminated(int env, const RootState& state) const override;
  Outcome outcome(int env) const override { return static_cast<Outcome>(outcome_[env]); }

  /// Env `env`'s track of its episode, in its env frame.
  const Track& track(int env) const { return tracks_.at(env); }
  /// Where env `env`'s robot was after its last step (or its reset).
  const TrackPlace& place(int env) const { return places_.at(env); }
  /// How far env `env`'s robot drove along the centreline in its episode [m].
  double progress(int env) const { return progress_.at(env); }
  /// The difficulty env `env`'s next track is drawn at, in [0, 1] (road/curriculum; else 1).
  double difficulty(int env) const {
    return config_.curriculum ? curriculum_.difficulty(env) : 1.0;
  }

 private:
  struct Step {
    TrackPlace place;
    double along = 0.0;  // [m] along the centreline in the step
  };
  /// Where `state` lies on env `env`'s track, from its place after the last step.
  Step look(int env, const RootState& state) const;

  TrackConfig config_;
  Track user_track_;          // road/points, when given
  RoadObserver observer_{2};  // two actions until attach() gives the batch's
  TaskContext context_;
  std::vector<Track> tracks_;                   // per env
  std::vector<EnvSenses> senses_;               // per env
  mutable std::vector<TrackPlace> places_;      // per env: after its last step
  mutable std::vector<double> progress_;        // per env [m]
  mutable std::vector<unsigned char> outcome_;  // per env: of the episode that ended
  Curriculum curriculum_;                       // road/curriculum: per env, from its laps
  std::vector<unsigned char> drawn_;            // per env: a track was drawn (an episode began)
};

}  // namespace jetbot_rl
