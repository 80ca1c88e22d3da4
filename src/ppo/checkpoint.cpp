#include "jetbot_rl/ppo/checkpoint.h"

#include <torch/serialize.h>

#include <cstdio>
#include <filesystem>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

// 2: the env's spec ("spec"); format 1 files are read without it.
// 3: the spec's observation contract (spec.observer: log_beams, goal_radius, path_clearance,
// footprint_radius, ...); format 2 files read it at its defaults.
constexpr std::int64_t kFormatVersion = kObservationContractFormat;

/// The env's spec as YAML (its field list: config_fields.h's format); a file written before a
/// field existed reads it at its default. obs_dim and action_dim are the meta's.
BatchSpec specFromYaml(const std::string& yaml, int obs_dim, int action_dim) {
  BatchSpec spec;
  fieldsFromYaml(yaml, spec);
  spec.obs_dim = obs_dim;
  spec.action_dim = action_dim;
  return spec;
}

}  // namespace

void writeCheckpointMeta(torch::serialize::OutputArchive& a, const CheckpointMeta& m,
                         const std::string& config_yaml) {
  a.write("format_version", c10::IValue(kFormatVersion));
  a.write("iteration", c10::IValue(m.iteration));
  a.write("env_steps", c10::IValue(m.env_steps));
  a.write("elapsed_s", c10::IValue(m.elapsed_s));
  a.write("best_reward", c10::IValue(m.best_reward));
  a.write("learning_rate", c10::IValue(m.learning_rate));
  a.write("obs_dim", c10::IValue(static_cast<std::int64_t>(m.obs_dim)));
  a.write("action_dim", c10::IValue(static_cast<std::int64_t>(m.action_dim)));
  a.write("config", c10::IValue(config_yaml));
  a.write("spec", c10::IValue(fieldsToYaml(m.spec)));
}

CheckpointMeta readCheckpointMeta(torch::serialize::InputArchive& a, std::string* config_yaml) {
  c10::IValue v;
  a.read("format_version", v);
  const std::int64_t version = v.toInt();
  if (version < 1 || version > kFormatVersion) {
    throw Error("unsupported checkpoint format version " + std::to_string(version));
  }
  CheckpointMeta m;
  m.format_version = version;
  a.read("iteration", v);
  m.iteration = v.toInt();
  a.read("env_steps", v);
  m.env_steps = v.toInt();
  a.read("elapsed_s", v);
  m.elapsed_s = v.toDouble();
  a.read("best_reward", v);
  m.best_reward = v.toDouble();
  a.read("learning_rate", v);
  m.learning_rate = v.toDouble();
  a.read("obs_dim", v);
  m.obs_dim = static_cast<int>(v.toInt());
  a.read("action_dim", v);
  m.action_dim = static_cast<int>(v.toInt());
  a.read("config", v);
  fieldsFromYaml(v.toStringRef(), m.config);  // the trainer's fields are not the policy's
  if (config_yaml) *config_yaml = v.toStringRef();
  if (version >= 2) {
    a.read("spec", v);
    m.spec = specFromYaml(v.toStringRef(), m.obs_dim, m.action_dim);
  }
  return m;
}

void requireObservationContract(const CheckpointMeta& meta, const std::string& path) {
  if (meta.format_version >= kObservationContractFormat) return;
  throw Error("checkpoint " + path + " (format " + std::to_string(meta.format_version) +
              ") was written before checkpoints held the observation contract a robot builds its "
              "observer from (scan beams and their scale, goal radius, path settings, the robot's "
              "geometry): resume it for one iteration (train.launch resume:=RUN_DIR/checkpoints/"
              "latest.pt iterations:=N+1, with the env parameters it was trained with), which "
              "saves it in format " +
              std::to_string(kObservationContractFormat));
}

torch::serialize::InputArchive openCheckpoint(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) {
    throw Error("checkpoint " + path + " does not exist or is not a file");
  }
  torch::serialize::InputArchive archive;
  try {
    archive.load_from(path);
  } catch (const c10::Error& e) {
    throw Error("cannot read checkpoint " + path + ": " + e.what_without_backtrace());
  }
  return archive;
}

void checkCheckpointSizes(const std::string& path, const CheckpointMeta& m, int input_dim,
                          int action_dim) {
  const int input = policyInputDim(m.config, m.obs_dim, m.action_dim);
  if (input != input_dim || m.action_dim != action_dim) {
    throw Error("checkpoint " + path + " is for input " + std::to_string(input) + " (obs_dim " +
                std::to_string(m.obs_dim) + "), action_dim " + std::to_string(m.action_dim) +
                "; the model has " + std::to_string(input_dim) + ", " + std::to_string(action_dim));
  }
}

CheckpointMeta readCheckpointMeta(const std::string& path) {
  torch::serialize::InputArchive archive = openCheckpoint(path);
  try {
    return readCheckpointMeta(archive);
  } catch (const c10::Error& e) {
    throw Error("checkpoint " + path + " lacks metadata: " + e.what_without_backtrace());
  }
}

CheckpointMeta loadPolicy(const std::string& path, ActorCritic& model, ObsNormalizer& normalizer) {
  torch::serialize::InputArchive archive = openCheckpoint(path);
  try {
    const CheckpointMeta meta = readCheckpointMeta(archive);
    checkCheckpointSizes(path, meta, model->inputDim(), model->actionDim());
    torch::serialize::InputArchive model_archive, normalizer_archive;
    archive.read("model", model_archive);
    archive.read("normalizer", normalizer_archive);
    model->load(model_archive);
    normalizer->load(normalizer_archive);
    return meta;
  } catch (const c10::Error& e) {
    throw Error("cannot load checkpoint " + path + ": " + e.what_without_backtrace());
  }
}

}  // namespace ppo
}  // namespace jetbot_rl
