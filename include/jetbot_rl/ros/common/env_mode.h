#pragma once

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// How an env node advances the simulation (its `mode`; the policy node drives it accordingly).
enum class EnvMode {
  kLockstep,  ///< One control step per accepted WheelTargets or ~step call (training).
  kRealtime,  ///< Steps on a wall-clock timer with the latest targets (driving by hand).
};

inline const EnumNameList<EnvMode>& enumNames(EnvMode) {
  static const EnumNameList<EnvMode> names{{EnvMode::kLockstep, "lockstep"},
                                           {EnvMode::kRealtime, "realtime"}};
  return names;
}

}  // namespace jetbot_rl
