// loadGazeboWorld(): an SDF world's collision (and visual) geometry through sdformat (its parser,
// its frame semantics, its <include> handling); the shapes' surfaces are sdf_shapes.cpp's.
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <sdf/sdf.hh>
#include <set>
#include <sstream>

#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/package_path.h"
#include "world/gazebo/inertia_free_models.h"
#include "world/gazebo/sdf_prepass.h"
#include "world/gazebo/sdf_shapes.h"
#include "world/gazebo/sdf_visuals.h"
#include "world/solid_surfaces.h"

namespace jetbot_rl {
namespace {

std::string errorText(const sdf::Errors& errors, const std::string& path) {
  std::ostringstream s;
  int shown = 0;
  for (const sdf::Error& e : errors) {
    if (shown++ == 3) {
      s << " (and " << errors.size() - 3 << " more)";
      break;
    }
    s << (shown > 1 ? "; " : "") << e.FilePath().value_or(path);
    if (e.LineNumber()) s << ":" << *e.LineNumber();
    s << ": " << e.Message();
  }
  return s.str();
}

/// True for an error sdformat reports of a link's inertia, or of the world or model around it.
bool inertiaOnly(const sdf::Errors& errors) {
  bool inertia = false;
  for (const sdf::Error& e : errors) {
    if (e.Code() == sdf::ErrorCode::LINK_INERTIA_INVALID) {
      inertia = true;
    } else if (e.Message() != "Failed to load a world." &&
               e.Message() != "Failed to load a model.") {
      return false;
    }
  }
  return inertia;
}

bool deprecationOnly(const sdf::Error& e) {
  return e.Code() == sdf::ErrorCode::VERSION_DEPRECATED ||
         e.Code() == sdf::ErrorCode::ELEMENT_DEPRECATED ||
         e.Code() == sdf::ErrorCode::ATTRIBUTE_DEPRECATED;
}

class Reader {
 public:
  Reader(GazeboWorld& world, const MeshResolver& resolver, bool visuals, const SavedState& state)
      : world_(world), resolver_(resolver), visuals_(visuals), state_(state) {
    sink_.world_path = world.path;
    sink_.resolver = resolver;
    sink_.out = &world.visuals;
    sink_.notes = &skipped_;
  }

  /// Model `m` at `pose` in the world (its parent's), unless the saved state poses it.
  void model(const sdf::Model& m, const Eigen::Isometry3d& parent_pose, const std::string& scope) {
    ++world_.models;
    const std::string name = scope.empty() ? m.Name() : scope + "::" + m.Name();
    read_.insert(name);
    const auto saved = state_.models.find(name);
    const Eigen::Isometry3d& pose = saved == state_.models.end() ? parent_pose : saved->second;
    for (uint64_t i = 0; i < m.LinkCount(); ++i) {
      const sdf::Link& link = *m.LinkByIndex(i);
      // A link the state poses: its shapes' poses in the model taken back to the link's, then
      // put at the link's saved pose.
      Eigen::Isometry3d frame = pose;
      read_.insert(name + "::" + link.Name());
      if (const auto it = state_.links.find(name + "::" + link.Name()); it != state_.links.end()) {
        ignition::math::Pose3d in_model;
        const sdf::Errors errors = link.SemanticPose().Resolve(in_model, "__model__");
        if (!errors.empty()) {
          throw ConfigError(world_.path + ": the pose of link '" + name + "::" + link.Name() +
                            "' cannot be resolved: " + errorText(errors, world_.path));
        }
        frame = it->second * toEigen(in_model).inverse();
      }
      for (uint64_t c = 0; c < link.CollisionCount(); ++c) {
        const sdf::Collision& collision = *link.CollisionByIndex(c);
        ignition::math::Pose3d p;
        const sdf::Errors errors = collision.SemanticPose().Resolve(p, "__model__");
        const std::string scoped = name + "::" + link.Name() + "::" + collision.Name();
        if (!errors.empty()) {
          throw ConfigError(world_.path + ": the pose of collision '" + scoped +
                            "' cannot be resolved: " + errorText(errors, world_.path));
        }
        shape(*collision.Geom(), frame * toEigen(p), scoped,
              whereIs(collision.Element(), world_.path));
      }
      for (uint64_t v = 0; visuals_ && v < link.VisualCount(); ++v) {
        const sdf::Visual& visual = *link.VisualByIndex(v);
        ignition::math::Pose3d p;
        const std::string scoped = name + "::" + link.Name() + "::" + visual.Name();
        if (!visual.SemanticPose().Resolve(p, "__model__").empty()) {
          skip("visual '" + scoped + "' (its pose cannot be resolved)");
          continue;
        }
        readVisual(*visual.Geom(), materialOf(visual), frame * toEigen(p), scoped,
                   whereIs(visual.Element(), world_.path), sink_);
      }
    }
    for (uint64_t i = 0; i < m.ModelCount(); ++i) {
      const sdf::Model& child = *m.ModelByIndex(i);
      ignition::math::Pose3d p;
      const sdf::Errors errors = child.SemanticPose().Resolve(p, "__model__");
      if (!errors.empty()) {
        throw ConfigError(world_.path + ": the pose of model '" + name + "::" + child.Name() +
                          "' cannot be resolved: " + errorText(errors, world_.path));
      }
      model(child, pose * toEigen(p), name);
    }
  }

  /// Plain model `m` (plain_models.h), read without sdformat: its shapes posed as sdformat
  /// poses them (ignition's poses composed link by collision, then in the world).
  void plainModel(const PlainModel& m) {
    ++world_.models;
    ++world_.plain_models;
    read_.insert(m.name);
    const Eigen::Isometry3d pose = toEigen(m.pose);
    const std::string where = world_.path + ":";
    for (const PlainLink& link : m.links) {
      read_.insert(m.name + "::" + link.name);
      for (const PlainShape& c : link.collisions) {
        shape(c.geometry, pose * toEigen(link.pose * c.pose),
              m.name + "::" + link.name + "::" + c.name, where + std::to_string(c.line));
      }
      for (const PlainShape& v : link.visuals) {
        readVisual(v.geometry, v.material, pose * toEigen(link.pose * v.pose),
                   m.name + "::" + link.name + "::" + v.name, where + std::to_string(v.line),
                   sink_);
      }
    }
    world_.warnings.insert(world_.warnings.end(), m.warnings.begin(), m.warnings.end());
  }

  void skip(const std::string& what) { skipped_.push_back(what); }
  /// Gazebo's "Unable to find model[...]" and "link[...]": what the state names and the world
  /// does not have, one warning each.
  void warnUnmatchedState() const {
    for (const auto* poses : {&state_.models, &state_.links}) {
      for (const auto& [name, pose] : *poses) {
        if (read_.count(name)) continue;
        world_.warnings.push_back(world_.path + ": its <state> poses " +
                                  (poses == &state_.models ? "model '" : "link '") + name +
                                  "', which the world does not have (Gazebo ignores it too)");
      }
    }
    for (const std::string& s : state_.scaled) {
      world_.warnings.push_back(s +
                                ": a <state> <scale> other than 1 1 1 is not applied "
                                "(the model's shapes are read at their own size)");
    }
  }
  std::string skipped() const {
    std::string s;
    for (const std::string& w : skipped_) s += (s.empty() ? "" : ", ") + w;
    return s;
  }

 private:
  /// Collision `name` of geometry `g` at `pose` in the world; `where`: its file and line.
  void shape(const sdf::Geometry& g, const Eigen::Isometry3d& pose, const std::string& name,
             const std::string& where) {
    // Sizes in (0, kMaxShapeSize], the pose within kMaxShapeDistance: refused otherwise, naming
    // the collision, its file and line and the value.
    const auto refuse = [&](const std::string& what) {
      throw ConfigError(where + ": collision '" + name + "': " + what);
    };
    if (const std::string bad = sdfPlacementProblem(g, pose); !bad.empty()) refuse(bad);
    const Eigen::Matrix3d& r = pose.linear();
    WorldSolid solid;
    solid.name = name;
    std::vector<Eigen::Vector3d> local;
    switch (g.Type()) {
      case sdf::GeometryType::BOX: {
        const auto s = g.BoxShape()->Size();
        const Eigen::Vector3d size(s.X(), s.Y(), s.Z());
        for (int k = 0; k < 3 && !solid.upright; ++k) {
          if (std::abs(r(2, k)) < kUprightCos) continue;
          const int i = (k + 1) % 3, j = (k + 2) % 3;
          Obstacle o;
          o.shape = Obstacle::Shape::kBox;
          o.center = pose.translation().head<2>();
          o.yaw = std::atan2(r(1, i), r(0, i));
          o.half_extents = 0.5 * Eigen::Vector2d(size[i], size[j]);
          solid.upright = o;
          solid.bottom = pose.translation().z() - 0.5 * size[k];
          solid.top = pose.translation().z() + 0.5 * size[k];
        }
        if (!solid.upright) local = boxSurface(size);
        break;
      }
      case sdf::GeometryType::CYLINDER: {
        const double radius = g.CylinderShape()->Radius(), length = g.CylinderShape()->Length();
        if (std::abs(r(2, 2)) >= kUprightCos) {
          Obstacle o;
          o.shape = Obstacle::Shape::kCylinder;
          o.center = pose.translation().head<2>();
          o.radius = radius;
          solid.upright = o;
          solid.bottom = pose.translation().z() - 0.5 * length;
          solid.top = pose.translation().z() + 0.5 * length;
        } else {
          local = cylinderSurface(radius, length);
        }
        break;
      }
      case sdf::GeometryType::PLANE:
        skip("plane '" + name + "' (the ground is the simulator's own)");
        return;
      case sdf::GeometryType::HEIGHTMAP:
        skip("heightmap '" + name + "'");
        return;
      case sdf::GeometryType::MESH:
        try {
          local = sdfMeshTriangles(*g.MeshShape(), world_.path, resolver_, name, skipped_);
        } catch (const Error& e) {
          throw ConfigError(world_.path + ": collision '" + name + "': " + e.what());
        }
        break;
      default:
        try {
          local = sdfSurface(g, world_.path, resolver_, name, skipped_);
        } catch (const Error& e) {
          refuse(e.what());
        }
        if (local.empty()) {
          skip("empty geometry '" + name + "'");
          return;
        }
    }
    if (solid.upright) {
      setUpright(solid, *solid.upright, solid.bottom, solid.top);
    } else {
      setSurface(solid, local, pose);
    }
    world_.solids.push_back(std::move(solid));
  }

  GazeboWorld& world_;
  const MeshResolver& resolver_;
  bool visuals_;
  const SavedState& state_;
  std::set<std::string> read_;  // the scoped names of the models and links read
  std::vector<std::string> skipped_;
  VisualSink sink_;  // after skipped_, which it appends to
};

}  // namespace

GazeboWorld loadGazeboWorld(const std::string& path, const MeshResolver& resolver, bool visuals) {
  GazeboWorld world;
  world.path = path;
  sdf::ParserConfig config;
  // model:// as Gazebo finds it; a relative path from the world file's folder (sdformat would
  // look in the working directory).
  const std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
  const auto find = [folder](const std::string& uri) {
    if (uri.find("://") == std::string::npos && !uri.empty() && uri[0] != '/') {
      const std::filesystem::path local = (folder / uri).lexically_normal();
      return std::filesystem::exists(local) ? local.string() : std::string();
    }
    return findGazeboModel(uri);
  };
  config.SetFindCallback(find);
  // sdformat 12 reads the includes of an included model with its global callback, not the
  // config's: without it a nested model:// include was dropped with a line on stderr.
  sdf::setFindCallback(find);
  config.SetWarningsPolicy(sdf::EnforcementPolicy::LOG);
  const auto load = [&](sdf::Root& root, const std::string& text) {
    sdf::Errors errors = text.empty() ? root.Load(path, config) : root.LoadSdfString(text, config);
    errors.erase(std::remove_if(errors.begin(), errors.end(), deprecationOnly), errors.end());
    return errors;
  };
  if (const std::string problem = fileProblem(path); !problem.empty()) {
    throw ConfigError(path + ": " + problem);
  }
  if (const std::string problem = sdfFileProblem(path, sdf::SDF::Version()); !problem.empty()) {
    throw ConfigError(problem);
  }
  // sdformat follows a model that includes itself until memory runs out: the chain is walked
  // first, and refused naming it.
  if (const std::string problem = includeProblem(path, find); !problem.empty()) {
    throw ConfigError(problem);
  }
  // Repeated and plain models taken out (prepassWorld()); on any error the file itself is read
  // again, for sdformat's report with the file's own lines.
  SavedState state;
  auto root = std::make_unique<sdf::Root>();
  PrepassedWorld prepassed = prepassWorld(path, visuals, find, nullptr, &state);
  sdf::Errors errors = load(*root, prepassed.text);
  if (!errors.empty() && (!prepassed.repeats.empty() || !prepassed.plain.empty())) {
    prepassed = PrepassedWorld();
    root = std::make_unique<sdf::Root>();
    errors = load(*root, "");
  }
  // A link's inertia that sdformat refuses and Gazebo 11 loads (published worlds have zero and
  // repeated moments): read again with every <inertial> left out, the models through copies.
  // (sdformat names neither the model nor the file and line: the copies do.) They live until the
  // reader has read the meshes they name, and are made only for such a world.
  std::optional<InertiaFreeModels> copies;
  if (inertiaOnly(errors)) {
    copies.emplace();
    const auto find_copy = [&copies, find](const std::string& uri) {
      const std::string found = find(uri);
      return found.empty() ? found : copies->copyOf(found);
    };
    config.SetFindCallback(find_copy);
    sdf::setFindCallback(find_copy);
    root = std::make_unique<sdf::Root>();
    prepassed = prepassWorld(path, visuals, find, &world.warnings, &state);
    errors = load(*root, prepassed.text);
    world.warnings.insert(world.warnings.end(), copies->refused().begin(), copies->refused().end());
  }
  if (!errors.empty()) throw ConfigError(errorText(errors, path));
  if (root->WorldCount() == 0) {
    throw ConfigError(path + ": holds no <world> (a Gazebo world file has one)");
  }
  const sdf::World& w = *root->WorldByIndex(0);
  world.name = w.Name();
  Reader reader(world, resolver, visuals, state);
  const auto worldPose = [&](const sdf::SemanticPose& pose, const std::string& what) {
    ignition::math::Pose3d p;
    const sdf::Errors e = pose.Resolve(p, "world");
    if (!e.empty()) {
      throw ConfigError(path + ": the pose of " + what +
                        " cannot be resolved: " + errorText(e, path));
    }
    return toEigen(p);
  };
  // What each model read gave (a repeat copies its like's): solids and visuals [from, to), its
  // pose in the world, the models it counts.
  struct Read {
    std::pair<std::size_t, std::size_t> solids, visuals;
    Eigen::Isometry3d pose;
    int models;
  };
  std::map<std::string, Read> read;
  const auto readOne = [&](const std::string& name, const auto& how) {
    const std::size_t from = world.solids.size(), visuals_from = world.visuals.size();
    const int models = world.models;
    const Eigen::Isometry3d pose = how();
    read[name] = {{from, world.solids.size()},
                  {visuals_from, world.visuals.size()},
                  pose,
                  world.models - models};
  };
  // In the file's order: sdformat's models with the plain ones in their places among them.
  std::size_t next_plain = 0;
  const auto plainUpTo = [&](std::size_t place) {
    for (; next_plain < prepassed.plain.size() && prepassed.plain[next_plain].place <= place;
         ++next_plain) {
      const PlainModel& m = prepassed.plain[next_plain];
      readOne(m.name, [&] {
        reader.plainModel(m);
        return toEigen(m.pose);
      });
    }
  };
  for (uint64_t i = 0; i < w.ModelCount(); ++i) {
    plainUpTo(i);
    const sdf::Model& m = *w.ModelByIndex(i);
    readOne(m.Name(), [&] {
      const Eigen::Isometry3d pose = worldPose(m.SemanticPose(), "model '" + m.Name() + "'");
      reader.model(m, pose, "");
      return pose;
    });
  }
  plainUpTo(w.ModelCount());
  for (const RepeatedModel& r : prepassed.repeats) {
    const Read& like = read.at(r.like);
    const Eigen::Isometry3d move = toEigen(r.pose) * like.pose.inverse();
    for (std::size_t k = like.solids.first; k < like.solids.second; ++k) {
      WorldSolid solid = moved(world.solids[k], move);
      solid.name = r.name + solid.name.substr(r.like.size());
      world.solids.push_back(std::move(solid));
    }
    for (std::size_t k = like.visuals.first; k < like.visuals.second; ++k) {
      WorldVisual visual = world.visuals[k];
      for (Eigen::Vector3d& c : visual.triangles) c = move * c;
      visual.name = r.name + visual.name.substr(r.like.size());
      world.visuals.push_back(std::move(visual));
    }
    world.models += like.models;
    ++world.repeated_models;
  }
  // A repeat is moved, not read again: where it lies is checked here, for every solid alike.
  for (const WorldSolid& solid : world.solids) {
    const double reach = std::max({solid.bounds.min().cwiseAbs().maxCoeff(),
                                   solid.bounds.max().cwiseAbs().maxCoeff(), std::abs(solid.bottom),
                                   std::abs(solid.top)});
    if (!(reach <= kMaxShapeDistance)) {
      std::ostringstream s;
      s << path << ": collision '" << solid.name << "': its pose in the world (" << reach
        << " m out) must lie within " << kMaxShapeDistance << " m of the origin on every axis";
      throw ConfigError(s.str());
    }
  }
  reader.warnUnmatchedState();
  if (root->WorldCount() > 1) reader.skip(std::to_string(root->WorldCount() - 1) + " more worlds");
  if (w.LightCount() > 0) reader.skip(std::to_string(w.LightCount()) + " lights");
  if (w.ActorCount() > 0) reader.skip(std::to_string(w.ActorCount()) + " actors");
  if (const sdf::ElementPtr e = w.Element()) {
    for (const char* tag :
         {"plugin", "physics", "gui", "scene", "spherical_coordinates", "population", "road"}) {
      int n = 0;
      for (sdf::ElementPtr c = e->HasElement(tag) ? e->GetElement(tag) : nullptr; c;
           c = c->GetNextElement(tag)) {
        n += c->GetExplicitlySetInFile() ? 1 : 0;  // not the defaults sdformat adds
      }
      if (n > 0) reader.skip(std::to_string(n) + " <" + tag + ">");
    }
  }
  world.skipped = reader.skipped();
  return world;
}

}  // namespace jetbot_rl
