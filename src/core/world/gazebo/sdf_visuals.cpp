#include "world/gazebo/sdf_visuals.h"

#include <filesystem>
#include <sstream>
#include <utility>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/package_path.h"
#include "world/gazebo/sdf_shapes.h"
#include "world/primitive_uv.h"

namespace jetbot_rl {

bool gazeboScriptColour(const std::string& script, Eigen::Vector3f& colour) {
  // The diffuse colours of Gazebo 11's media/materials/scripts/gazebo.material, the common ones.
  static const std::vector<std::pair<const char*, Eigen::Vector3f>> known{
      {"Gazebo/White", {1.0f, 1.0f, 1.0f}},        {"Gazebo/Grey", {0.7f, 0.7f, 0.7f}},
      {"Gazebo/Gray", {0.7f, 0.7f, 0.7f}},         {"Gazebo/DarkGrey", {0.35f, 0.35f, 0.35f}},
      {"Gazebo/DarkGray", {0.35f, 0.35f, 0.35f}},  {"Gazebo/Black", {0.0f, 0.0f, 0.0f}},
      {"Gazebo/FlatBlack", {0.1f, 0.1f, 0.1f}},    {"Gazebo/Red", {1.0f, 0.0f, 0.0f}},
      {"Gazebo/Green", {0.0f, 1.0f, 0.0f}},        {"Gazebo/Blue", {0.0f, 0.0f, 1.0f}},
      {"Gazebo/Yellow", {1.0f, 1.0f, 0.0f}},       {"Gazebo/Orange", {1.0f, 0.5088f, 0.0468f}},
      {"Gazebo/Purple", {1.0f, 0.0f, 1.0f}},       {"Gazebo/Turquoise", {0.0f, 1.0f, 1.0f}},
      {"Gazebo/Indigo", {0.33f, 0.0f, 0.5f}},      {"Gazebo/Wood", {0.52f, 0.37f, 0.26f}},
      {"Gazebo/WoodFloor", {0.6f, 0.45f, 0.3f}},   {"Gazebo/WoodPallet", {0.6f, 0.45f, 0.3f}},
      {"Gazebo/Bricks", {0.6f, 0.3f, 0.2f}},       {"Gazebo/Gold", {0.8f, 0.65f, 0.0f}},
      {"Gazebo/CeilingTiled", {0.8f, 0.8f, 0.8f}}, {"Gazebo/PaintedWall", {0.9f, 0.9f, 0.85f}},
  };
  for (const auto& [name, rgb] : known) {
    if (script == name) {
      colour = rgb;
      return true;
    }
  }
  return false;
}

VisualMaterial materialOf(const sdf::Visual& visual) {
  VisualMaterial m;
  if (const sdf::Material* material = visual.Material()) {
    const sdf::ElementPtr element = material->Element();
    if (element && element->HasElement("diffuse")) {
      const ignition::math::Color d = material->Diffuse();
      m.diffuse = Eigen::Vector3f(d.R(), d.G(), d.B());
    }
    m.script = material->ScriptName();
    m.file_path = material->FilePath();
    for (const auto type : {sdf::PbrWorkflowType::METAL, sdf::PbrWorkflowType::SPECULAR}) {
      const sdf::Pbr* pbr = material->PbrMaterial();
      const sdf::PbrWorkflow* workflow = pbr ? pbr->Workflow(type) : nullptr;
      if (workflow && !workflow->AlbedoMap().empty() && m.albedo_map.empty()) {
        m.albedo_map = workflow->AlbedoMap();
      }
    }
    if (element && element->HasElement("script")) {
      const sdf::ElementPtr script = element->GetElement("script");
      for (sdf::ElementPtr u = script->HasElement("uri") ? script->GetElement("uri") : nullptr; u;
           u = u->GetNextElement("uri")) {
        m.script_uris.push_back(u->Get<std::string>());
      }
    }
  }
  return m;
}

namespace {

/// The texture at `path` through `sink`'s cache (nullptr, noted once naming `name`, when it
/// cannot be read).
std::shared_ptr<const TextureImage> texture(const std::string& path, const std::string& name,
                                            VisualSink& sink) {
  const auto [at, first] = sink.textures.try_emplace(path);
  if (!first) return at->second;
  try {
    at->second = loadTextureImage(path, &sink.texture_bytes);
  } catch (const Error& e) {
    sink.notes->push_back(std::string(e.what()) + " of visual '" + name + "' (its colour drawn)");
  }
  return at->second;
}

/// A visual of mesh `m` without a <material>: one per material of its file.
void readMeshParts(const sdf::Mesh& m, const Eigen::Isometry3d& pose, const std::string& name,
                   VisualSink& sink) {
  for (MeshPart& part : sdfMeshParts(m, sink.world_path, sink.resolver, name, *sink.notes)) {
    WorldVisual v;
    v.name = name;
    v.triangles = std::move(part.triangles);
    for (Eigen::Vector3d& c : v.triangles) c = pose * c;
    if (part.colour) v.colour = part.colour->cwiseMax(0.0f).cwiseMin(1.0f);
    if (!part.texture.empty()) {
      v.texture = texture(part.texture, name, sink);
      if (v.texture) v.uv = std::move(part.uv);
    } else if (!part.texture_as_given.empty() &&
               sink.textures.try_emplace("?" + part.texture_as_given).second) {
      sink.notes->push_back("texture '" + part.texture_as_given + "' of visual '" + name +
                            "' (not found; its colour drawn)");
    }
    sink.out->push_back(std::move(v));
  }
}

/// The file of a world's `uri`: `model://` as Gazebo finds it, `file://` and other paths as
/// given, a relative one against the folder of `relative_to` (a file); "" when not found.
std::string worldFile(std::string uri, const std::string& relative_to) {
  namespace fs = std::filesystem;
  if (uri.rfind("model://", 0) == 0) {
    uri = findGazeboModel(uri);
    if (uri.empty()) return uri;
  } else if (uri.rfind("file://", 0) == 0) {
    uri = uri.substr(7);
  }
  if (!fs::path(uri).is_absolute()) uri = (fs::path(relative_to).parent_path() / uri).string();
  return fs::path(uri).lexically_normal().string();
}

/// A script texture's file: in one of the script's folders, or a `textures` folder beside one
/// (Gazebo finds it through its resource paths, which hold the model's `materials/textures`).
std::string scriptTexture(const std::string& name, const std::vector<std::string>& folders) {
  namespace fs = std::filesystem;
  std::error_code error;
  for (const std::string& folder : folders) {
    const fs::path dir =
        fs::is_directory(folder, error) ? fs::path(folder) : fs::path(folder).parent_path();
    for (const fs::path& candidate : {dir / name, dir.parent_path() / "textures" / name}) {
      if (fs::exists(candidate, error)) return candidate.lexically_normal().string();
    }
  }
  return "";
}

/// What a visual's <material> makes of it besides its shape: its colour, and the file of the
/// texture that covers it ("" for none; named `as_named`, its coordinates divided by `scale`).
struct Look {
  Eigen::Vector3f colour{0.7f, 0.7f, 0.7f};
  std::string texture, as_named;
  Eigen::Vector2f scale = Eigen::Vector2f::Ones();
};

/// `material`'s look: its <diffuse>, else its script's (Gazebo's own colours, else the script
/// files of its <uri>s: colour and texture), and over either its PBR albedo map; what cannot be
/// drawn as it says is noted.
Look lookOf(const VisualMaterial& material, const std::string& name, VisualSink& sink) {
  Look look;
  if (material.diffuse) {
    look.colour = material.diffuse->cwiseMax(0.0f).cwiseMin(1.0f);
  } else if (!material.script.empty() && !gazeboScriptColour(material.script, look.colour)) {
    std::vector<std::string> folders;
    for (const std::string& uri : material.script_uris) {
      const std::string folder = worldFile(uri, sink.world_path);
      if (!folder.empty()) folders.push_back(folder);
    }
    const auto m = sink.scripts.find(material.script, folders, *sink.notes);
    if (!m) {
      sink.notes->push_back("material '" + material.script + "' of visual '" + name +
                            "' (drawn grey)");
    } else {
      if (m->diffuse) look.colour = m->diffuse->cwiseMax(0.0f).cwiseMin(1.0f);
      look.as_named = m->texture;
      look.scale = m->scale;
      look.texture = m->texture.empty() ? "" : scriptTexture(m->texture, folders);
      if (!m->texture.empty() && look.texture.empty() &&
          sink.textures.try_emplace("?" + m->texture).second) {
        sink.notes->push_back("texture '" + m->texture + "' of material '" + material.script +
                              "' of visual '" + name + "' (not found; its colour drawn)");
      }
    }
  }
  if (!material.albedo_map.empty()) {  // a relative map against the SDF file naming it
    look.as_named = material.albedo_map;
    look.scale = Eigen::Vector2f::Ones();
    look.texture =
        worldFile(material.albedo_map,
                  material.file_path.rfind('/', 0) == 0 ? material.file_path : sink.world_path);
    if (look.texture.empty()) {
      sink.notes->push_back("albedo map '" + material.albedo_map + "' of visual '" + name +
                            "' (not found; its colour drawn)");
    }
  }
  return look;
}

/// The texture coordinates of a box's, cylinder's or sphere's surface `corners` in its own
/// frame (primitiveUv()); empty for other shapes.
std::vector<Eigen::Vector2f> primitiveUvOf(const sdf::Geometry& g,
                                           const std::vector<Eigen::Vector3d>& corners) {
  switch (g.Type()) {
    case sdf::GeometryType::BOX: {
      const auto s = g.BoxShape()->Size();
      return primitiveUv(UvShape::kBox, Eigen::Vector3d(s.X(), s.Y(), s.Z()), corners);
    }
    case sdf::GeometryType::CYLINDER:
      return primitiveUv(
          UvShape::kCylinder,
          Eigen::Vector3d(g.CylinderShape()->Radius(), g.CylinderShape()->Length(), 0), corners);
    case sdf::GeometryType::SPHERE:
      return primitiveUv(UvShape::kSphere, Eigen::Vector3d::Constant(g.SphereShape()->Radius()),
                         corners);
    default:
      return {};
  }
}

}  // namespace

void readVisual(const sdf::Geometry& g, const VisualMaterial& material,
                const Eigen::Isometry3d& pose, const std::string& name, const std::string& where,
                VisualSink& sink) {
  const auto refuse = [&](const std::string& what) {
    throw ConfigError(where + ": visual '" + name + "': " + what);
  };
  if (g.Type() == sdf::GeometryType::PLANE) return;  // the ground is the simulator's own
  if (const std::string bad = sdfPlacementProblem(g, pose); !bad.empty()) refuse(bad);
  if (g.Type() == sdf::GeometryType::MESH && !material.diffuse && material.script.empty() &&
      material.albedo_map.empty()) {
    try {
      readMeshParts(*g.MeshShape(), pose, name, sink);
    } catch (const Error& e) {
      refuse(e.what());
    }
    return;
  }
  const Look look = lookOf(material, name, sink);
  const std::shared_ptr<const TextureImage> image =
      look.texture.empty() ? nullptr : texture(look.texture, name, sink);
  WorldVisual v;
  v.name = name;
  v.colour = look.colour;
  try {
    if (image && g.Type() == sdf::GeometryType::MESH) {  // the texture on the whole mesh
      for (MeshPart& part :
           sdfMeshParts(*g.MeshShape(), sink.world_path, sink.resolver, name, *sink.notes)) {
        v.triangles.insert(v.triangles.end(), part.triangles.begin(), part.triangles.end());
        v.uv.insert(v.uv.end(), part.uv.begin(), part.uv.end());
      }
    } else {
      v.triangles = sdfSurface(g, sink.world_path, sink.resolver, name, *sink.notes);
      if (image) v.uv = primitiveUvOf(g, v.triangles);
    }
  } catch (const Error& e) {
    refuse(e.what());
  }
  if (v.triangles.empty()) {
    sink.notes->push_back("empty visual '" + name + "'");
    return;
  }
  if (image && v.uv.empty()) {
    sink.notes->push_back("texture '" + look.as_named + "' of visual '" + name +
                          "' (not drawn on this shape; its colour is)");
  } else if (image) {
    for (Eigen::Vector2f& c : v.uv) c = c.cwiseQuotient(look.scale);
    v.texture = image;
  }
  for (Eigen::Vector3d& c : v.triangles) c = pose * c;
  sink.out->push_back(std::move(v));
}

}  // namespace jetbot_rl
