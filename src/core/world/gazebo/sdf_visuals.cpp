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

/// The folders (or files) of a script's <uri>s: `model://` as Gazebo finds it, `file://` and
/// other paths as given, relative ones against the world file's folder; those not found left out.
std::vector<std::string> scriptFolders(const VisualMaterial& material,
                                       const std::string& world_path) {
  namespace fs = std::filesystem;
  std::vector<std::string> folders;
  for (std::string uri : material.script_uris) {
    if (uri.rfind("model://", 0) == 0) {
      uri = findGazeboModel(uri);
      if (uri.empty()) continue;
    } else if (uri.rfind("file://", 0) == 0) {
      uri = uri.substr(7);
    }
    if (!fs::path(uri).is_absolute()) uri = (fs::path(world_path).parent_path() / uri).string();
    folders.push_back(uri);
  }
  return folders;
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

/// Visual `v` (its triangles in its own frame) covered by the texture in `file` (named
/// `as_named`; coordinates divided by `scale`): a mesh by its coordinates, a box, cylinder or
/// sphere across its faces; on other shapes, or when the file cannot be read, noted.
void coverWith(const sdf::Geometry& g, const std::string& file, const std::string& as_named,
               const Eigen::Vector2f& scale, const std::string& name, VisualSink& sink,
               WorldVisual& v) {
  std::shared_ptr<const TextureImage> image = texture(file, name, sink);
  if (!image) return;
  std::vector<Eigen::Vector2f> uv;
  if (g.Type() == sdf::GeometryType::MESH) {  // the texture on the whole mesh
    std::vector<Eigen::Vector3d> corners;
    for (MeshPart& part :
         sdfMeshParts(*g.MeshShape(), sink.world_path, sink.resolver, name, *sink.notes)) {
      corners.insert(corners.end(), part.triangles.begin(), part.triangles.end());
      uv.insert(uv.end(), part.uv.begin(), part.uv.end());
    }
    v.triangles = std::move(corners);
  } else if (g.Type() == sdf::GeometryType::BOX) {
    const auto s = g.BoxShape()->Size();
    uv = primitiveUv(UvShape::kBox, Eigen::Vector3d(s.X(), s.Y(), s.Z()), v.triangles);
  } else if (g.Type() == sdf::GeometryType::CYLINDER) {
    uv = primitiveUv(UvShape::kCylinder,
                     Eigen::Vector3d(g.CylinderShape()->Radius(), g.CylinderShape()->Length(), 0),
                     v.triangles);
  } else if (g.Type() == sdf::GeometryType::SPHERE) {
    uv = primitiveUv(UvShape::kSphere, Eigen::Vector3d::Constant(g.SphereShape()->Radius()),
                     v.triangles);
  }
  if (uv.empty()) {
    sink.notes->push_back("texture '" + as_named + "' of visual '" + name +
                          "' (not drawn on this shape; its colour is)");
    return;
  }
  for (Eigen::Vector2f& c : uv) c = c.cwiseQuotient(scale);
  v.texture = std::move(image);
  v.uv = std::move(uv);
}

/// Visual `v` (its triangles in its own frame) in the colour and texture of its material script,
/// found in the script's folders; what cannot be drawn as the script says is noted.
void applyScript(const sdf::Geometry& g, const VisualMaterial& material, const std::string& name,
                 VisualSink& sink, WorldVisual& v) {
  const std::vector<std::string> folders = scriptFolders(material, sink.world_path);
  const std::optional<ScriptMaterial> m = sink.scripts.find(material.script, folders, *sink.notes);
  if (!m) {
    sink.notes->push_back("material '" + material.script + "' of visual '" + name +
                          "' (drawn grey)");
    return;
  }
  if (m->diffuse) v.colour = m->diffuse->cwiseMax(0.0f).cwiseMin(1.0f);
  if (m->texture.empty()) return;
  const std::string file = scriptTexture(m->texture, folders);
  if (file.empty()) {
    if (sink.textures.try_emplace("?" + m->texture).second) {
      sink.notes->push_back("texture '" + m->texture + "' of material '" + material.script +
                            "' of visual '" + name + "' (not found; its colour drawn)");
    }
    return;
  }
  coverWith(g, file, m->texture, m->scale, name, sink, v);
}

/// A visual's PBR albedo map (`<pbr><metal|specular><albedo_map>`, as Gazebo Sim's worlds give
/// their textures): `model://`, `file://` or a path (a relative one against the SDF file naming
/// it); drawn as a script's texture is.
void applyAlbedoMap(const sdf::Geometry& g, const VisualMaterial& material, const std::string& name,
                    VisualSink& sink, WorldVisual& v) {
  namespace fs = std::filesystem;
  std::string file = material.albedo_map;
  if (file.rfind("model://", 0) == 0) {
    file = findGazeboModel(file);
  } else if (file.rfind("file://", 0) == 0) {
    file = file.substr(7);
  }
  if (!file.empty() && !fs::path(file).is_absolute()) {
    const std::string& from =
        material.file_path.rfind('/', 0) == 0 ? material.file_path : sink.world_path;
    file = (fs::path(from).parent_path() / file).lexically_normal().string();
  }
  if (file.empty()) {
    sink.notes->push_back("albedo map '" + material.albedo_map + "' of visual '" + name +
                          "' (not found; its colour drawn)");
    return;
  }
  coverWith(g, file, material.albedo_map, Eigen::Vector2f::Ones(), name, sink, v);
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
  WorldVisual v;
  v.name = name;
  try {
    v.triangles = sdfSurface(g, sink.world_path, sink.resolver, name, *sink.notes);
  } catch (const Error& e) {
    refuse(e.what());
  }
  if (v.triangles.empty()) {
    sink.notes->push_back("empty visual '" + name + "'");
    return;
  }
  if (material.diffuse) {
    v.colour = material.diffuse->cwiseMax(0.0f).cwiseMin(1.0f);
  } else if (!material.script.empty() && !gazeboScriptColour(material.script, v.colour)) {
    try {
      applyScript(g, material, name, sink, v);
    } catch (const Error& e) {
      refuse(e.what());
    }
  }
  if (!material.albedo_map.empty()) {
    try {
      applyAlbedoMap(g, material, name, sink, v);
    } catch (const Error& e) {
      refuse(e.what());
    }
  }
  for (Eigen::Vector3d& c : v.triangles) c = pose * c;
  sink.out->push_back(std::move(v));
}

}  // namespace jetbot_rl
