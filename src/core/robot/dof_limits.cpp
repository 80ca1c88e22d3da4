#include "jetbot_rl/robot/dof_limits.h"

#include <sstream>

namespace jetbot_rl {
namespace {

void describeLimit(std::ostream& s, const char* what, double value, const char* unit,
                   LimitSource source, const char* parameter, double urdf) {
  s << what << ' ' << value << ' ' << unit << " (";
  if (source == LimitSource::kUrdf) {
    s << "URDF)";
    return;
  }
  s << (source == LimitSource::kGazebo ? "Gazebo diff drive plugin" : parameter) << "; URDF: ";
  if (urdf > 0.0) {
    s << urdf << ' ' << unit << ", overridden)";
  } else {
    s << "none)";
  }
}

}  // namespace

std::string describeDofLimits(const DofLimits& limits) {
  std::ostringstream s;
  s << limits.name << ": ";
  describeLimit(s, "velocity limit", limits.velocity_limit, "rad/s", limits.velocity_source,
                "wheel_velocity_limit", limits.urdf_velocity_limit);
  s << ", ";
  describeLimit(s, "effort limit", limits.effort_limit, "N m", limits.effort_source, "effort_limit",
                limits.urdf_effort_limit);
  return s.str();
}

}  // namespace jetbot_rl
