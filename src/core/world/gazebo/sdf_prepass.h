#pragma once

// What is done to a Gazebo world file before sdformat reads it: the XML checked (tinyxml2 names the
// line sdformat only prints), repeated and plain models taken out to be read here.

#include <functional>
#include <string>
#include <vector>

#include "world/gazebo/plain_models.h"
#include "world/gazebo/saved_state.h"

namespace jetbot_rl {

/// Turns an include's URI into a file or folder ("" when not found), as the world's loader does.
using IncludeFinder = std::function<std::string(const std::string& uri)>;

/// A world-level model that repeats an earlier one but for its name and pose.
struct RepeatedModel {
  std::string name;             ///< Its name.
  std::string like;             ///< The model it repeats.
  ignition::math::Pose3d pose;  ///< Its pose in the world (its <pose>).
};

/// A world file as sdformat is given it, and what was taken out of it to be read here.
struct PrepassedWorld {
  std::string text;  ///< The file's text as changed; "" when unchanged (sdformat reads the file).
  std::vector<RepeatedModel> repeats;  ///< Taken out: each is moved copies of its like's shapes.
  std::vector<PlainModel> plain;       ///< Taken out: read without sdformat (plain_models.h).
};

/**
 * The SDF world file at `path` prepared for sdformat, which copies a model's whole description
 * per model (about 13 ms and 2.5 MB each), and resolves frames in time that grows with their
 * square: every top-level `<model>` (or named `<include>` with a `<pose>`) that equals an earlier
 * one but for its name and six-number `<pose>` taken out as a repeat (a world of hundreds of like
 * posts, BARN's, parses as one post), every other plain model (plain_models.h; its visuals only
 * with `visuals`) taken out to be read here, and relative include URIs made absolute (`find`
 * tells which includes bring a model: the taken models keep their place among sdformat's).
 * Models with a placement frame, a name given twice or one sdformat questions are kept.
 * Unchanged when tinyxml2 cannot read the file (sdformat then reads it and reports why).
 * With `refused_inertias`: every <inertial> removed first, those sdformat refuses named in it
 * (stripInertials()), and the text returned whenever tinyxml2 reads the file. With `state`: the
 * world's first <state> taken into it and applied to the text (takeSavedState(); a model the
 * state poses, or whose links it poses, is left to sdformat).
 */
PrepassedWorld prepassWorld(const std::string& path, bool visuals, const IncludeFinder& find,
                            std::vector<std::string>* refused_inertias = nullptr,
                            SavedState* state = nullptr);

/// "" when the file at `path` is XML with an <sdf> root whose version is 1.0 up to `newest`
/// (sdformat's), else what is wrong: "PATH:LINE: ..." for XML that does not parse, "PATH: ..."
/// otherwise.
std::string sdfFileProblem(const std::string& path, const std::string& newest);

/// "" when the includes of the world at `path`, followed as sdformat follows them (a folder by its
/// model.config's <sdf>, else model.sdf), end; else what is wrong, naming the file and line: an
/// include chain that comes back to a file on it ("A includes B, which includes A"), one deeper
/// than kMaxIncludeDepth, more than kMaxIncludedFiles files, or a file that is not a regular
/// file. sdformat itself would recurse until memory runs out.
std::string includeProblem(const std::string& path, const IncludeFinder& find);

constexpr int kMaxIncludeDepth = 32;
constexpr int kMaxIncludedFiles = 100000;

}  // namespace jetbot_rl
