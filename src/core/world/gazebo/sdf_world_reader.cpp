// loadGazeboWorld(): an SDF world's collision geometry through sdformat (its parser, its frame
// semantics, its <include> handling); only the shapes' surfaces are made here.
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
#include <sstream>

#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/package_path.h"
#include "world/gazebo/sdf_prepass.h"
#include "world/solid_surfaces.h"

namespace jetbot_rl {
namespace {

Eigen::Isometry3d toEigen(const ignition::math::Pose3d& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.Pos().X(), p.Pos().Y(), p.Pos().Z());
  t.linear() = Eigen::Quaterniond(p.Rot().W(), p.Rot().X(), p.Rot().Y(), p.Rot().Z())
                   .normalized()
                   .toRotationMatrix();
  return t;
}

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

// What a collision may measure and where it may lie [m]: beyond, it is refused naming it (a size
// of 1e300 would take the cut's loops for ever; a shape 100 km out, a grid of 4e12 cells).
constexpr double kMaxShapeSize = 1000.0;
constexpr double kMaxShapeDistance = 10000.0;

/// "FILE:LINE" of an SDF element (the world's file when sdformat read it from a string).
std::string whereIs(const sdf::ElementPtr& element, const std::string& world_path) {
  if (!element) return world_path;
  const std::string& file = element->FilePath();
  std::string where = file.rfind('/', 0) == 0 ? file : world_path;
  if (const std::optional<int> line = element->LineNumber()) where += ":" + std::to_string(*line);
  return where;
}

bool deprecationOnly(const sdf::Error& e) {
  return e.Code() == sdf::ErrorCode::VERSION_DEPRECATED ||
         e.Code() == sdf::ErrorCode::ELEMENT_DEPRECATED ||
         e.Code() == sdf::ErrorCode::ATTRIBUTE_DEPRECATED;
}

class Reader {
 public:
  Reader(GazeboWorld& world, const MeshResolver& resolver) : world_(world), resolver_(resolver) {}

  void model(const sdf::Model& m, const Eigen::Isometry3d& pose, const std::string& scope) {
    ++world_.models;
    const std::string name = scope.empty() ? m.Name() : scope + "::" + m.Name();
    for (uint64_t i = 0; i < m.LinkCount(); ++i) {
      const sdf::Link& link = *m.LinkByIndex(i);
      for (uint64_t c = 0; c < link.CollisionCount(); ++c) {
        const sdf::Collision& collision = *link.CollisionByIndex(c);
        ignition::math::Pose3d p;
        const sdf::Errors errors = collision.SemanticPose().Resolve(p, "__model__");
        const std::string scoped = name + "::" + link.Name() + "::" + collision.Name();
        if (!errors.empty()) {
          throw ConfigError(world_.path + ": the pose of collision '" + scoped +
                            "' cannot be resolved: " + errorText(errors, world_.path));
        }
        shape(collision, pose * toEigen(p), scoped);
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

  void skip(const std::string& what) { skipped_.push_back(what); }
  std::string skipped() const {
    std::string s;
    for (const std::string& w : skipped_) s += (s.empty() ? "" : ", ") + w;
    return s;
  }

 private:
  void shape(const sdf::Collision& collision, const Eigen::Isometry3d& pose,
             const std::string& name) {
    const sdf::Geometry& g = *collision.Geom();
    // Sizes in (0, kMaxShapeSize], the pose within kMaxShapeDistance: refused otherwise, naming
    // the collision, its file and line and the value.
    const auto refuse = [&](const std::string& what) {
      throw ConfigError(whereIs(collision.Element(), world_.path) + ": collision '" + name +
                        "': " + what);
    };
    const auto sized = [&](const char* what, std::initializer_list<double> values) {
      for (double v : values) {
        if (!(v > 0.0 && v <= kMaxShapeSize)) {
          std::ostringstream s;
          s << what << " " << v << " must be in (0, " << kMaxShapeSize << "] m";
          refuse(s.str());
        }
      }
    };
    if (!pose.translation().allFinite() ||
        pose.translation().cwiseAbs().maxCoeff() > kMaxShapeDistance) {
      std::ostringstream s;
      s << "its pose in the world (" << pose.translation().transpose() << ") must lie within "
        << kMaxShapeDistance << " m of the origin on every axis";
      refuse(s.str());
    }
    switch (g.Type()) {
      case sdf::GeometryType::BOX: {
        const auto b = g.BoxShape()->Size();
        sized("its box size", {b.X(), b.Y(), b.Z()});
        break;
      }
      case sdf::GeometryType::CYLINDER:
        sized("its cylinder radius and length",
              {g.CylinderShape()->Radius(), g.CylinderShape()->Length()});
        break;
      case sdf::GeometryType::SPHERE:
        sized("its sphere radius", {g.SphereShape()->Radius()});
        break;
      case sdf::GeometryType::ELLIPSOID: {
        const auto a = g.EllipsoidShape()->Radii();
        sized("its ellipsoid radii", {a.X(), a.Y(), a.Z()});
        break;
      }
      case sdf::GeometryType::CAPSULE:
        sized("its capsule radius and length",
              {g.CapsuleShape()->Radius(), g.CapsuleShape()->Length()});
        break;
      default:
        break;
    }
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
      case sdf::GeometryType::SPHERE:
        local = ellipsoidSurface(Eigen::Vector3d::Constant(g.SphereShape()->Radius()));
        break;
      case sdf::GeometryType::ELLIPSOID: {
        const auto a = g.EllipsoidShape()->Radii();
        local = ellipsoidSurface(Eigen::Vector3d(a.X(), a.Y(), a.Z()));
        break;
      }
      case sdf::GeometryType::CAPSULE: {
        const double radius = g.CapsuleShape()->Radius(), length = g.CapsuleShape()->Length();
        local = cylinderSurface(radius, length);
        for (double end : {-0.5 * length, 0.5 * length}) {
          const auto cap =
              ellipsoidSurface(Eigen::Vector3d::Constant(radius), Eigen::Vector3d(0, 0, end));
          local.insert(local.end(), cap.begin(), cap.end());
        }
        break;
      }
      case sdf::GeometryType::MESH:
        local = mesh(*g.MeshShape(), name);
        break;
      case sdf::GeometryType::PLANE:
        skip("plane '" + name + "' (the ground is the simulator's own)");
        return;
      case sdf::GeometryType::HEIGHTMAP:
        skip("heightmap '" + name + "'");
        return;
      default: {
        bool any = false;
        try {
          any = polyline(g, local);
        } catch (const ConfigError& e) {
          refuse(e.what());
        }
        if (!any) {
          skip("empty geometry '" + name + "'");
          return;
        }
      }
    }
    if (solid.upright) {
      setUpright(solid, *solid.upright, solid.bottom, solid.top);
    } else {
      setSurface(solid, local, pose);
    }
    world_.solids.push_back(std::move(solid));
  }

  std::vector<Eigen::Vector3d> mesh(const sdf::Mesh& m, const std::string& name) {
    std::string path;
    const std::string& uri = m.Uri();
    try {
      path = resolveMeshUri(uri, [&](const std::string& u) {
        if (u.rfind("model://", 0) == 0) {
          const std::string found = findGazeboModel(u);
          if (found.empty()) throw ConfigError("no model folder of that name");
          return found;
        }
        if (resolver_) return resolver_(u);
        const std::string found = findPackageUri(u);
        if (found.empty()) throw ConfigError("no such package on ROS_PACKAGE_PATH");
        return found;
      });
      if (!path.empty() && path[0] != '/') {  // relative to the SDF file that names it
        // Read from a string (sdf_prepass.h), the world's own models have no file path.
        const std::string& from = m.FilePath().rfind('/', 0) == 0 ? m.FilePath() : world_.path;
        const auto slash = from.rfind('/');
        if (slash != std::string::npos) path = from.substr(0, slash + 1) + path;
      }
      std::vector<Eigen::Vector3d> triangles = loadMeshTriangles(path);
      const auto s = m.Scale();
      const Eigen::Vector3d scale(s.X(), s.Y(), s.Z());
      for (Eigen::Vector3d& p : triangles) {
        p = p.cwiseProduct(scale);
        if (!(p.cwiseAbs().maxCoeff() <= kMaxShapeSize)) {
          std::ostringstream s;
          s << "a vertex of mesh '" << uri << "' at scale " << scale.transpose() << " lies at ("
            << p.transpose() << "), beyond " << kMaxShapeSize << " m of its origin";
          throw ConfigError(s.str());
        }
      }
      if (!m.Submesh().empty()) skip("submesh choice of '" + name + "' (the whole mesh is used)");
      return triangles;
    } catch (const Error& e) {
      throw ConfigError(world_.path + ": collision '" + name + "': " + e.what());
    }
  }

  /// A `<polyline>` (sdformat 12 has no class for it: read from its element). False if none.
  static bool polyline(const sdf::Geometry& g, std::vector<Eigen::Vector3d>& out) {
    const sdf::ElementPtr geometry = g.Element();
    if (!geometry || !geometry->HasElement("polyline")) return false;
    for (sdf::ElementPtr p = geometry->GetElement("polyline"); p;
         p = p->GetNextElement("polyline")) {
      std::vector<Eigen::Vector2d> points;
      for (sdf::ElementPtr q = p->HasElement("point") ? p->GetElement("point") : nullptr; q;
           q = q->GetNextElement("point")) {
        const auto v = q->Get<ignition::math::Vector2d>();
        if (!(std::abs(v.X()) <= kMaxShapeSize && std::abs(v.Y()) <= kMaxShapeSize)) {
          std::ostringstream text;
          text << "its polyline point (" << v.X() << ", " << v.Y() << ") lies beyond "
               << kMaxShapeSize << " m of its origin";
          throw ConfigError(text.str());
        }
        points.emplace_back(v.X(), v.Y());
      }
      if (const double height = p->Get<double>("height");
          !(height > 0.0 && height <= kMaxShapeSize)) {
        std::ostringstream text;
        text << "its polyline height " << height << " must be in (0, " << kMaxShapeSize << "] m";
        throw ConfigError(text.str());
      }
      const auto surface = polylineSurface(points, p->Get<double>("height"));
      out.insert(out.end(), surface.begin(), surface.end());
    }
    return !out.empty();
  }

  GazeboWorld& world_;
  const MeshResolver& resolver_;
  std::vector<std::string> skipped_;
};

}  // namespace

GazeboWorld loadGazeboWorld(const std::string& path, const MeshResolver& resolver) {
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
  // Repeated models parsed once; on any error the file itself is read again, for sdformat's
  // report with the file's own lines.
  std::vector<RepeatedModel> repeats;
  auto root = std::make_unique<sdf::Root>();
  sdf::Errors errors = load(*root, foldRepeatedModels(path, repeats));
  if (!errors.empty() && !repeats.empty()) {
    repeats.clear();
    root = std::make_unique<sdf::Root>();
    errors = load(*root, "");
  }
  if (!errors.empty()) throw ConfigError(errorText(errors, path));
  if (root->WorldCount() == 0) {
    throw ConfigError(path + ": holds no <world> (a Gazebo world file has one)");
  }
  const sdf::World& w = *root->WorldByIndex(0);
  world.name = w.Name();
  Reader reader(world, resolver);
  const auto worldPose = [&](const sdf::SemanticPose& pose, const std::string& what) {
    ignition::math::Pose3d p;
    const sdf::Errors e = pose.Resolve(p, "world");
    if (!e.empty()) {
      throw ConfigError(path + ": the pose of " + what +
                        " cannot be resolved: " + errorText(e, path));
    }
    return toEigen(p);
  };
  std::map<std::string, std::pair<std::size_t, std::size_t>> solids_of;  // model -> [from, to)
  std::map<std::string, int> models_in;
  for (uint64_t i = 0; i < w.ModelCount(); ++i) {
    const sdf::Model& m = *w.ModelByIndex(i);
    const std::size_t from = world.solids.size();
    const int models = world.models;
    reader.model(m, worldPose(m.SemanticPose(), "model '" + m.Name() + "'"), "");
    solids_of[m.Name()] = {from, world.solids.size()};
    models_in[m.Name()] = world.models - models;
  }
  for (const RepeatedModel& r : repeats) {
    const sdf::Model& like = *w.ModelByName(r.like);
    const Eigen::Isometry3d move =
        worldPose(w.FrameByName(r.name)->SemanticPose(), "model '" + r.name + "'") *
        worldPose(like.SemanticPose(), "model '" + r.like + "'").inverse();
    const auto [from, to] = solids_of.at(r.like);
    for (std::size_t k = from; k < to; ++k) {
      WorldSolid solid = moved(world.solids[k], move);
      solid.name = r.name + solid.name.substr(r.like.size());
      world.solids.push_back(std::move(solid));
    }
    world.models += models_in.at(r.like);
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
  if (root->WorldCount() > 1) reader.skip(std::to_string(root->WorldCount() - 1) + " more worlds");
  if (w.LightCount() > 0) reader.skip(std::to_string(w.LightCount()) + " lights");
  if (w.ActorCount() > 0) reader.skip(std::to_string(w.ActorCount()) + " actors");
  if (const sdf::ElementPtr e = w.Element()) {
    for (const char* tag : {"plugin", "physics", "gui", "scene", "spherical_coordinates", "state",
                            "population", "road"}) {
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
