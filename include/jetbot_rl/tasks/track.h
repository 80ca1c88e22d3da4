#pragma once

// The road following task's track (`road/...`): a closed or open centreline of floor tape, drawn
// at every reset from one of the configured shapes (or a user's points), checked against the
// smallest radius the robot can turn, painted into a floor image for the camera, and the robot's
// place along it.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/rng.h"

namespace jetbot_rl {

struct FloorImage;

/// The shapes a track is drawn from at every reset.
enum class TrackShape { kOval, kFigureEight, kSBend, kRandom };

inline const EnumNameList<TrackShape>& enumNames(TrackShape) {
  static const EnumNameList<TrackShape> names{{TrackShape::kOval, "oval"},
                                              {TrackShape::kFigureEight, "figure_eight"},
                                              {TrackShape::kSBend, "s_bend"},
                                              {TrackShape::kRandom, "random"}};
  return names;
}

/// The road following task's parameters (`road/...`).
struct TrackConfig {
  std::vector<std::string> shapes{"oval", "random"};  ///< Drawn from, one uniformly per reset.
  std::vector<double> points;          ///< A user's track [x0, y0, x1, y1, ...] [m]; empty: shapes.
  bool closed = true;                  ///< The user's track is a loop.
  bool spline = true;                  ///< The user's points are passed through by a smooth curve.
  std::vector<double> size{2.0, 3.5};  ///< [min, max] of a drawn track's longer side [m].
  double width = 0.2;                  ///< The tape's width [m].
  double min_radius = 0.3;             ///< The tightest curve the robot must turn [m].
  std::vector<double> tape_colour{0.95, 0.8, 0.15};  ///< RGB, each in [0, 1].
  std::vector<double> floor_colour{0.3, 0.3, 0.32};  ///< RGB, each in [0, 1].
  bool random_colours = false;      ///< Tape and floor colours drawn at every reset.
  double resolution = 0.01;         ///< The painted floor's cell [m].
  double lap = 1.0;                 ///< Success after this many laps of a closed track.
  double start_offset = 0.03;       ///< The start's sideways offset from the centreline, up to [m].
  double start_yaw = 0.2;           ///< The start's heading off the centreline's, up to [rad].
  double progress_reward = 10.0;    ///< Per metre along the centreline.
  double centre_cost = 0.02;        ///< Per step at the tape's edge, (offset / half width)^2.
  double off_track_penalty = 1.0;   ///< On leaving the tape.
  double lap_reward = 10.0;         ///< On success.
  bool curriculum = false;          ///< Each env's tracks start wide and tighten with its laps.
  double curriculum_radius = 1.0;   ///< The tightest curve of a track at difficulty 0 [m].
  int curriculum_episodes = 20;     ///< Episodes an env's lap rate is counted over.
  double curriculum_success = 0.8;  ///< The lap rate that raises its difficulty.
  double curriculum_step = 0.1;     ///< By this much (1: road/min_radius's tracks).
};

template <typename C, typename V>
IfConfig<C, TrackConfig> visitFields(C& c, V&& v) {
  v("road/shapes", c.shapes, NameList{},
    "The shapes a track is drawn from at every reset, one uniformly: oval (an ellipse), "
    "figure_eight, s_bend (open), random (a closed curve of random low harmonics); each scaled "
    "to a longer side drawn from road/size, and further until no curve is tighter than "
    "road/min_radius.");
  v("road/points", c.points, EachValue<double>{inRange(-1000.0, 1000.0, "m")},
    "A track of one's own instead of shapes: [x0, y0, x1, y1, ...], at least 2 points; placed "
    "at every reset so that a random point of it lies under the robot.");
  v("road/closed", c.closed, AnyValue{}, "road/points is a loop (its last point joins its first).");
  v("road/spline", c.spline, AnyValue{},
    "road/points are passed through by a smooth curve (Catmull-Rom); false: straight segments "
    "(their corners are curves of radius 0, refused unless road/min_radius is 0).");
  v("road/size", c.size, intervalOf(positiveUpTo(100.0, "m")),
    "Range of a drawn track's longer side, drawn at every reset.");
  v("road/width", c.width, positiveUpTo(10.0, "m"),
    "The tape's width: the episode ends (outcome off_track) when the root link origin is further "
    "than half of it from the centreline.");
  v("road/min_radius", c.min_radius, atLeast(0.0, "m"),
    "The tightest curve the robot must turn: drawn shapes are scaled up until none is tighter; "
    "road/points with a tighter one are refused, naming where and its radius.");
  v("road/tape_colour", c.tape_colour, EachValue<double>{inRange(0.0, 1.0)},
    "The tape's colour, [r, g, b].");
  v("road/floor_colour", c.floor_colour, EachValue<double>{inRange(0.0, 1.0)},
    "The floor's colour around it, [r, g, b] (everywhere: the ground takes it).");
  v("road/random_colours", c.random_colours, AnyValue{},
    "Tape and floor colours drawn at every reset instead (the tape lighter: each channel in "
    "[0.55, 1] against [0.05, 0.45]).");
  v("road/resolution", c.resolution, inRange(0.001, 0.1, "m"),
    "The cell of the floor image the track is painted into.");
  v("road/lap", c.lap, positiveUpTo(100.0),
    "A closed track's episode succeeds after this many laps; an open one's at its end.");
  v("road/start_offset", c.start_offset, atLeast(0.0, "m"),
    "The start's sideways offset from the centreline, uniform in [-this, this] (less than half "
    "road/width).");
  v("road/start_yaw", c.start_yaw, inRange(0.0, 3.15, "rad"),
    "The start's heading off the centreline's, uniform in [-this, this].");
  v("road/progress_reward", c.progress_reward, atLeast(0.0, "1/m"),
    "Reward per metre driven along the centreline (negative backwards).");
  v("road/centre_cost", c.centre_cost, atLeast(0.0),
    "Cost per step of (offset from the centreline / half road/width)^2.");
  v("road/off_track_penalty", c.off_track_penalty, atLeast(0.0),
    "Penalty on leaving the tape (terminated, outcome off_track): small, so that driving and "
    "leaving the tape early in training still gains (with 10 a policy learnt to stand still "
    "first, for 100 to 200 iterations or more).");
  v("road/lap_reward", c.lap_reward, atLeast(0.0),
    "Reward on success (road/lap laps, or an open track's end).");
  v("road/curriculum", c.curriculum, AnyValue{},
    "Drawn shapes: each env starts at difficulty 0, its tracks scaled up until no curve is "
    "tighter than road/curriculum_radius, and raises its difficulty by road/curriculum_step (up "
    "to 1) after each run of road/curriculum_episodes of its episodes in which at least "
    "road/curriculum_success completed their laps; at difficulty d no curve is tighter than "
    "min_radius + (1 - d) x (curriculum_radius - min_radius). Off: every track at difficulty 1.");
  v("road/curriculum_radius", c.curriculum_radius, positiveUpTo(100.0, "m"),
    "With the curriculum: the tightest curve of a track at difficulty 0 (at least "
    "road/min_radius).");
  v("road/curriculum_episodes", c.curriculum_episodes, inRange(1, 100000),
    "With the curriculum: the episodes of a run an env's lap rate is counted over.");
  v("road/curriculum_success", c.curriculum_success, inRange(0.0, 1.0),
    "With the curriculum: the share of a run's episodes with a lap that raises the env's "
    "difficulty.");
  v("road/curriculum_step", c.curriculum_step, inRange(0.0, 1.0),
    "With the curriculum: by this much.");
}

/// Shapes known, colours of 3 values, points in pairs, at least 2 of them, and start_offset below
/// half the width; ConfigError naming the field and its value.
void checkFieldRules(const TrackConfig& config);

/// Where a point lies along a track.
struct TrackPlace {
  int index = 0;        ///< The centreline segment nearest to it.
  double s = 0.0;       ///< Its arc length along the centreline [m], in [0, length).
  double offset = 0.0;  ///< Signed distance from the centreline, + to the left [m].
};

/**
 * A track's centreline, resampled every kSpacing metres along it; closed or open. Built
 * from points (a drawn shape's or a user's), checked against the tightest curve allowed.
 */
class Track {
 public:
  /// Spacing of the resampled centreline [m].
  static constexpr double kSpacing = 0.01;

  Track() = default;
  /// The centreline through `points` (straight segments between them; a closed one returns to
  /// its first). ConfigError naming `field` with fewer than 2 distinct points.
  Track(const std::vector<Eigen::Vector2d>& points, bool closed, const std::string& field);

  bool closed() const { return closed_; }
  double length() const { return length_; }  ///< [m]
  const std::vector<Eigen::Vector2d>& points() const { return points_; }
  /// The point at arc length `s` [m] (wrapped on a closed track, clamped on an open one).
  Eigen::Vector2d at(double s) const;
  /// The unit tangent at arc length `s`.
  Eigen::Vector2d tangent(double s) const;
  /// The smallest radius of curvature along it [m] and the arc length where it lies.
  double minRadius(double* where = nullptr) const;
  /// Where `p` lies: the nearest segment within `window` [m] of arc length of `hint`'s (the
  /// place of the last step: a crossing of a figure eight is not a shortcut), or of the whole
  /// track without a hint.
  TrackPlace place(const Eigen::Vector2d& p, const TrackPlace* hint, double window) const;
  /// The same track moved by `transform` (rotation and translation in the plane).
  Track transformed(const Eigen::Matrix2d& rotation, const Eigen::Vector2d& translation) const;
  /// The same track run backwards.
  Track reversed() const;

 private:
  std::vector<Eigen::Vector2d> points_;  // every kSpacing metres; a closed one not repeating
  bool closed_ = true;
  double length_ = 0.0;
  int segments() const { return static_cast<int>(points_.size()) - (closed_ ? 0 : 1); }
};

/// The points of a shape, centred on the origin, its longer side `size` [m], from `rng`.
std::vector<Eigen::Vector2d> shapePoints(TrackShape shape, double size, Rng& rng);

/// The user's track of `config` (road/points through a spline or as is), checked against
/// road/min_radius: ConfigError naming road/points, where and the radius.
Track userTrack(const TrackConfig& config);

/// A track drawn from `rng`: a shape of road/shapes at a size of road/size, scaled up until its
/// tightest curve is road/min_radius, or with road/curriculum at `difficulty` in [0, 1]
/// min_radius + (1 - difficulty) x (curriculum_radius - min_radius).
Track drawTrack(const TrackConfig& config, Rng& rng, double difficulty = 1.0);

/// `track` painted as tape of `width` [m] in `tape` on `floor` (RGB in [0, 1]) at `resolution`
/// [m per pixel], the ground beyond the image in `floor` too.
std::shared_ptr<FloorImage> paintTrack(const Track& track, double width,
                                       const Eigen::Vector3f& tape, const Eigen::Vector3f& floor,
                                       double resolution);

}  // namespace jetbot_rl
