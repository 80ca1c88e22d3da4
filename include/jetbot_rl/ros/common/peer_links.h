#pragma once

#include <string>
#include <vector>

namespace jetbot_rl {

/// The nodes (caller ids, e.g. "/mission") this node's publisher of `topic` (resolved) has a
/// connection to now; none when it does not publish it. A node's connections close when it
/// exits or dies (its sockets close), so this tells a peer that is gone, as `rosnode info` does.
std::vector<std::string> subscribersOf(const std::string& topic);

/// The node that sent an action goal with this id, as actionlib's clients (C++ and Python) make
/// goal ids: "<node name>-<count>-<stamp>"; "" when the id is not made so.
std::string goalSender(const std::string& goal_id);

}  // namespace jetbot_rl
