// The road following task's track: shapes, the user's points, the centreline and its paint.
#include "jetbot_rl/tasks/track.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/sensors/floor_image.h"

namespace jetbot_rl {
namespace {

constexpr int kShapeSamples = 4000;   // a shape's points before resampling: a few mm apart
constexpr int kSplineSamples = 64;    // per segment of the user's points
constexpr double kCurveChord = 0.05;  // curvature is measured over points this far apart [m]
constexpr int kMaxPaintSide = 4096;   // a painted floor's largest side [px]

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// Uniform Catmull-Rom through `p`, returning to p[0] when `closed`.
std::vector<Eigen::Vector2d> catmullRom(const std::vector<Eigen::Vector2d>& p, bool closed) {
  const int n = static_cast<int>(p.size());
  const auto point = [&](int i) {
    if (closed) return p[static_cast<std::size_t>(((i % n) + n) % n)];
    return p[static_cast<std::size_t>(std::clamp(i, 0, n - 1))];
  };
  std::vector<Eigen::Vector2d> out;
  const int pieces = closed ? n : n - 1;
  for (int i = 0; i < pieces; ++i) {
    const Eigen::Vector2d p0 = point(i - 1), p1 = point(i), p2 = point(i + 1), p3 = point(i + 2);
    for (int k = 0; k < kSplineSamples; ++k) {
      const double t = static_cast<double>(k) / kSplineSamples, t2 = t * t, t3 = t2 * t;
      out.push_back(0.5 * (2.0 * p1 + (p2 - p0) * t + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2 +
                           (3.0 * p1 - p0 - 3.0 * p2 + p3) * t3));
    }
  }
  if (!closed) out.push_back(p.back());
  return out;
}

/// `points` scaled so that their bounding box's longer side is `size`, centred on the origin.
std::vector<Eigen::Vector2d> fitted(std::vector<Eigen::Vector2d> points, double size) {
  Eigen::Vector2d lo = points.front(), hi = points.front();
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector2d centre = 0.5 * (lo + hi);
  const double scale = size / (hi - lo).maxCoeff();
  for (auto& p : points) p = scale * (p - centre);
  return points;
}

}  // namespace

void checkFieldRules(const TrackConfig& c) {
  for (const std::string& s : c.shapes) parseEnum<TrackShape>("road/shapes", s);
  if (c.points.size() % 2 != 0) {
    throwInvalid("road/points", listText(c.points), "must be pairs x, y");
  }
  if (!c.points.empty() && c.points.size() < 4) {
    throwInvalid("road/points", listText(c.points), "must hold at least 2 points");
  }
  if (c.tape_colour.size() != 3) {
    throwInvalid("road/tape_colour", listText(c.tape_colour), "must be [r, g, b]");
  }
  if (c.floor_colour.size() != 3) {
    throwInvalid("road/floor_colour", listText(c.floor_colour), "must be [r, g, b]");
  }
  if (c.start_offset >= 0.5 * c.width) {
    throwInvalid("road/start_offset", c.start_offset,
                 "must be below half road/width (" + std::to_string(0.5 * c.width) + " m)");
  }
  if (c.curriculum && c.curriculum_radius < c.min_radius) {
    throwInvalid("road/curriculum_radius", c.curriculum_radius,
                 "must be at least road/min_radius " + std::to_string(c.min_radius) +
                     " m (the curriculum's tracks start no tighter than its last)");
  }
  // Half the painted floor's side: room for the margins and for a track scaled up for its curves.
  if (c.size[1] / c.resolution > kMaxPaintSide / 2) {
    throwInvalid("road/size", listText(c.size),
                 "its max over road/resolution (" + std::to_string(c.resolution) +
                     " m) must be at most " + std::to_string(kMaxPaintSide / 2) + " px");
  }
}

Track::Track(const std::vector<Eigen::Vector2d>& given, bool closed, const std::string& field)
    : closed_(closed) {
  std::vector<Eigen::Vector2d> pts;
  for (const auto& p : given) {
    if (pts.empty() || (p - pts.back()).norm() > 1e-9) pts.push_back(p);
  }
  if (closed && pts.size() > 1 && (pts.front() - pts.back()).norm() <= 1e-9) pts.pop_back();
  if (pts.size() < 2) {
    throw ConfigError(field + ": a track needs at least 2 distinct points, got " +
                      std::to_string(pts.size()));
  }
  if (closed) pts.push_back(pts.front());
  std::vector<double> at(pts.size(), 0.0);
  for (std::size_t i = 1; i < pts.size(); ++i) at[i] = at[i - 1] + (pts[i] - pts[i - 1]).norm();
  length_ = at.back();
  // Every point kSpacing (or a little less, so that they divide the length) apart.
  const int n = std::max(2, static_cast<int>(std::ceil(length_ / kSpacing)));
  const int count = closed ? n : n + 1;
  const double step = length_ / n;
  std::size_t j = 0;
  for (int i = 0; i < count; ++i) {
    const double s = std::min(i * step, length_);
    while (j + 2 < pts.size() && at[j + 1] < s) ++j;
    const double piece = at[j + 1] - at[j];
    const double t = piece > 0.0 ? std::clamp((s - at[j]) / piece, 0.0, 1.0) : 0.0;
    points_.push_back(pts[j] + t * (pts[j + 1] - pts[j]));
  }
}

namespace {
double spacingOf(double length, std::size_t points, bool closed) {
  return length / static_cast<double>(closed ? points : points - 1);
}
}  // namespace

Eigen::Vector2d Track::at(double s) const {
  const double h = spacingOf(length_, points_.size(), closed_);
  s = closed_ ? s - length_ * std::floor(s / length_) : std::clamp(s, 0.0, length_);
  const int n = static_cast<int>(points_.size());
  int i = std::min(static_cast<int>(s / h), closed_ ? n - 1 : n - 2);
  const double t = s / h - i;
  const Eigen::Vector2d& a = points_[static_cast<std::size_t>(i)];
  const Eigen::Vector2d& b = points_[static_cast<std::size_t>((i + 1) % n)];
  return a + t * (b - a);
}

Eigen::Vector2d Track::tangent(double s) const {
  const double h = spacingOf(length_, points_.size(), closed_);
  const Eigen::Vector2d d = at(s + 0.5 * h) - at(s - 0.5 * h);
  if (d.norm() > 0.0) return d.normalized();
  return (points_[1] - points_[0]).normalized();
}

double Track::minRadius(double* where) const {
  const int n = static_cast<int>(points_.size());
  const double h = spacingOf(length_, points_.size(), closed_);
  const int k = std::max(1, static_cast<int>(std::lround(kCurveChord / h)));
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = closed_ ? 0 : k; i < (closed_ ? n : n - k); ++i) {
    const Eigen::Vector2d& a = points_[static_cast<std::size_t>((i - k + n) % n)];
    const Eigen::Vector2d& b = points_[static_cast<std::size_t>(i)];
    const Eigen::Vector2d& c = points_[static_cast<std::size_t>((i + k) % n)];
    const double area2 = std::abs(cross(b - a, c - a));
    if (area2 <= 0.0) continue;
    const double r = (b - a).norm() * (c - b).norm() * (c - a).norm() / (2.0 * area2);
    if (r < smallest) {
      smallest = r;
      if (where) *where = i * h;
    }
  }
  return smallest;
}

TrackPlace Track::place(const Eigen::Vector2d& p, const TrackPlace* hint, double window) const {
  const int n = static_cast<int>(points_.size());
  const int segs = segments();
  const double h = spacingOf(length_, points_.size(), closed_);
  int first = 0, last = segs - 1;
  if (hint) {
    const int w = static_cast<int>(std::ceil(window / h));
    first = hint->index - w;
    last = hint->index + w;
    if (!closed_) {
      first = std::max(first, 0);
      last = std::min(last, segs - 1);
    } else if (last - first + 1 > segs) {
      first = 0;
      last = segs - 1;
    }
  }
  TrackPlace best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int j = first; j <= last; ++j) {
    const int i = closed_ ? ((j % segs) + segs) % segs : j;
    const Eigen::Vector2d& a = points_[static_cast<std::size_t>(i)];
    const Eigen::Vector2d& b = points_[static_cast<std::size_t>((i + 1) % n)];
    const Eigen::Vector2d d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const double d2 = (a + t * d - p).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.index = i;
      best.s = (i + t) * h;
      best.offset = (cross(d, p - a) >= 0.0 ? 1.0 : -1.0) * std::sqrt(d2);
    }
  }
  if (closed_ && best.s >= length_) best.s -= length_;
  return best;
}

Track Track::transformed(const Eigen::Matrix2d& rotation,
                         const Eigen::Vector2d& translation) const {
  Track t = *this;
  for (auto& p : t.points_) p = rotation * p + translation;
  return t;
}

Track Track::reversed() const {
  Track t = *this;
  std::reverse(t.points_.begin(), t.points_.end());
  if (closed_) std::rotate(t.points_.rbegin(), t.points_.rbegin() + 1, t.points_.rend());
  return t;
}

std::vector<Eigen::Vector2d> shapePoints(TrackShape shape, double size, Rng& rng) {
  std::vector<Eigen::Vector2d> p;
  p.reserve(kShapeSamples + 1);
  switch (shape) {
    case TrackShape::kOval: {
      const double b = uniform(rng, 0.45, 1.0);
      for (int i = 0; i < kShapeSamples; ++i) {
        const double t = 2.0 * kPi * i / kShapeSamples;
        p.emplace_back(std::cos(t), b * std::sin(t));
      }
      break;
    }
    case TrackShape::kFigureEight: {  // Gerono's lemniscate, its lobes' width drawn
      const double b = uniform(rng, 0.7, 1.2);
      for (int i = 0; i < kShapeSamples; ++i) {
        const double t = 2.0 * kPi * i / kShapeSamples;
        p.emplace_back(std::sin(t), b * std::sin(t) * std::cos(t));
      }
      break;
    }
    case TrackShape::kSBend: {  // one period of a sine: open
      const double amplitude = uniform(rng, 0.1, 0.22);
      for (int i = 0; i <= kShapeSamples; ++i) {
        const double x = static_cast<double>(i) / kShapeSamples;
        p.emplace_back(x, amplitude * std::sin(2.0 * kPi * x));
      }
      break;
    }
    case TrackShape::kRandom: {  // a circle bent by harmonics 2 to 4, then squeezed
      double a[5] = {0, 0, 0, 0, 0}, phase[5] = {0, 0, 0, 0, 0};
      for (int k = 2; k <= 4; ++k) {
        a[k] = uniform(rng, -0.3 / k, 0.3 / k);
        phase[k] = uniform(rng, -kPi, kPi);
      }
      const double squeeze = uniform(rng, 0.6, 1.0);
      for (int i = 0; i < kShapeSamples; ++i) {
        const double t = 2.0 * kPi * i / kShapeSamples;
        double r = 1.0;
        for (int k = 2; k <= 4; ++k) r += a[k] * std::cos(k * t + phase[k]);
        p.emplace_back(r * std::cos(t), squeeze * r * std::sin(t));
      }
      break;
    }
  }
  return fitted(std::move(p), size);
}

Track userTrack(const TrackConfig& config) {
  std::vector<Eigen::Vector2d> given;
  for (std::size_t i = 0; i + 1 < config.points.size(); i += 2) {
    given.emplace_back(config.points[i], config.points[i + 1]);
  }
  const std::vector<Eigen::Vector2d> curve =
      config.spline && given.size() > 2 ? catmullRom(given, config.closed) : given;
  Track track(curve, config.closed, "road/points");
  double where = 0.0;
  const double radius = track.minRadius(&where);
  if (radius < config.min_radius) {
    const Eigen::Vector2d at = track.at(where);
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < given.size(); ++i) {
      if ((given[i] - at).norm() < (given[nearest] - at).norm()) nearest = i;
    }
    std::ostringstream s;
    s << "road/points: the track turns with a radius of " << radius << " m near point " << nearest
      << " (" << given[nearest].x() << ", " << given[nearest].y()
      << "), tighter than road/min_radius " << config.min_radius << " m";
    throw ConfigError(s.str());
  }
  return track;
}

namespace {

/// The tightest curve a track drawn at `difficulty` may have [m].
double tightestRadius(const TrackConfig& config, double difficulty) {
  if (!config.curriculum) return config.min_radius;
  return config.min_radius + (1.0 - difficulty) * (config.curriculum_radius - config.min_radius);
}

}  // namespace

Track drawTrack(const TrackConfig& config, Rng& rng, double difficulty) {
  const auto which = static_cast<std::size_t>(
      std::min<double>(rng.uniform() * config.shapes.size(), config.shapes.size() - 1));
  const TrackShape shape = parseEnum<TrackShape>("road/shapes", config.shapes[which]);
  const double size = uniform(rng, config.size[0], config.size[1]);
  std::vector<Eigen::Vector2d> points = shapePoints(shape, size, rng);
  const bool closed = shape != TrackShape::kSBend;
  Track track(points, closed, "road/shapes");
  const double radius = track.minRadius(), tightest = tightestRadius(config, difficulty);
  if (radius < tightest) {  // curvature radius grows with the scale
    const double scale = tightest / radius * (1.0 + 1e-6);
    for (auto& p : points) p *= scale;
    track = Track(points, closed, "road/shapes");
  }
  return track;
}

std::shared_ptr<FloorImage> paintTrack(const Track& track, double width,
                                       const Eigen::Vector3f& tape, const Eigen::Vector3f& floor,
                                       double resolution) {
  const double half = 0.5 * width;
  Eigen::Vector2d lo = track.points().front(), hi = lo;
  for (const auto& p : track.points()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  lo.array() -= half + 2.0 * resolution;
  hi.array() += half + 2.0 * resolution;
  // A track scaled up past road/size for its curves gets coarser cells, not more of them.
  const double cell = std::max(resolution, (hi - lo).maxCoeff() / kMaxPaintSide);
  auto image = std::make_shared<FloorImage>();
  image->resolution = cell;
  image->origin_x = lo.x();
  image->origin_y = lo.y();
  image->width = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell));
  image->height = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell));
  image->outside = floor;
  const auto byte = [](float c) { return static_cast<std::uint8_t>(std::lround(255.0f * c)); };
  const std::uint8_t floor_rgb[3] = {byte(floor[0]), byte(floor[1]), byte(floor[2])};
  const std::uint8_t tape_rgb[3] = {byte(tape[0]), byte(tape[1]), byte(tape[2])};
  const std::size_t cells = static_cast<std::size_t>(image->width) * image->height;
  image->rgb.resize(cells * 3);
  for (std::size_t i = 0; i < cells; ++i) std::copy_n(floor_rgb, 3, &image->rgb[i * 3]);
  // The tape is every cell whose centre lies within half the width of the centreline.
  const std::vector<Eigen::Vector2d>& pts = track.points();
  const std::size_t n = pts.size();
  const std::size_t segs = track.closed() ? n : n - 1;
  const double piece = track.length() / static_cast<double>(segs);
  const int reach = static_cast<int>(std::ceil((half + piece) / cell)) + 1;
  const double h2 = half * half;
  for (std::size_t i = 0; i < segs; ++i) {
    const Eigen::Vector2d& a = pts[i];
    const Eigen::Vector2d d = pts[(i + 1) % n] - a;
    const int u0 = static_cast<int>((a.x() - lo.x()) / cell),
              v0 = static_cast<int>((a.y() - lo.y()) / cell);
    for (int v = std::max(0, v0 - reach); v <= std::min(image->height - 1, v0 + reach); ++v) {
      for (int u = std::max(0, u0 - reach); u <= std::min(image->width - 1, u0 + reach); ++u) {
        const Eigen::Vector2d c(lo.x() + (u + 0.5) * cell, lo.y() + (v + 0.5) * cell);
        const double t = std::clamp((c - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
        if ((a + t * d - c).squaredNorm() <= h2) {
          std::copy_n(tape_rgb, 3,
                      &image->rgb[(static_cast<std::size_t>(v) * image->width + u) * 3]);
        }
      }
    }
  }
  return image;
}

}  // namespace jetbot_rl
