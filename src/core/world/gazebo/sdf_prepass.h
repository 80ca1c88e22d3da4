#pragma once

// What is done to a Gazebo world file before sdformat reads it: the XML checked (tinyxml2 names the
// line sdformat only prints) and repeated models folded into frames.

#include <functional>
#include <string>
#include <vector>

#include "world/gazebo/saved_state.h"

namespace jetbot_rl {

/// A world-level model that repeats an earlier one but for its name and pose.
struct RepeatedModel {
  std::string name;  ///< Its name: a <frame> of that name holds its pose.
  std::string like;  ///< The model it repeats.
};

/**
 * The SDF world file's text with every top-level `<model>` (or named `<include>`) that equals an
 * earlier one but for its name and `<pose>` replaced by a `<frame>` of its name and pose, and
 * relative include URIs made absolute. sdformat copies a model's whole description per model
 * (about 13 ms each): a world of hundreds of like posts (BARN's) parses as one post and frames.
 * Models with a placement frame are kept. "" with no repeats or when tinyxml2 cannot read the
 * file (sdformat then reads it and reports why).
 */
/// With `refused_inertias`: every <inertial> removed too, those sdformat refuses named in it
/// (stripInertials()), and the text returned whenever tinyxml2 reads the file. With `state`: the
/// world's first <state> taken into it and applied to the text (takeSavedState(); a model the
/// state poses is never folded), the text returned when that changed the world's models.
std::string foldRepeatedModels(const std::string& path, std::vector<RepeatedModel>& repeats,
                               std::vector<std::string>* refused_inertias = nullptr,
                               SavedState* state = nullptr);

/// "" when the file at `path` is XML with an <sdf> root whose version is 1.0 up to `newest`
/// (sdformat's), else what is wrong: "PATH:LINE: ..." for XML that does not parse, "PATH: ..."
/// otherwise.
std::string sdfFileProblem(const std::string& path, const std::string& newest);

/// Turns an include's URI into a file or folder ("" when not found), as the world's loader does.
using IncludeFinder = std::function<std::string(const std::string& uri)>;

/// "" when the includes of the world at `path`, followed as sdformat follows them (a folder by its
/// model.config's <sdf>, else model.sdf), end; else what is wrong, naming the file and line: an
/// include chain that comes back to a file on it ("A includes B, which includes A"), one deeper
/// than kMaxIncludeDepth, more than kMaxIncludedFiles files, or a file that is not a regular
/// file. sdformat itself would recurse until memory runs out.
std::string includeProblem(const std::string& path, const IncludeFinder& find);

constexpr int kMaxIncludeDepth = 32;
constexpr int kMaxIncludedFiles = 100000;

}  // namespace jetbot_rl
