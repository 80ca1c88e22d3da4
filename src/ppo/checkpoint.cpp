#include "jetbot_rl/ppo/checkpoint.h"

#include <torch/serialize.h>
#include <torch/torch.h>

#include <cstdio>
#include <filesystem>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace ppo {
namespace {

// 2: the env's spec ("spec"); format 1 files are read without it.
constexpr std::int64_t kFormatVersion = 2;

/// BatchSpec's fields a policy runs with, as YAML (config_fields.h's format).
struct SpecFields {
  std::string task;
  double control_dt = 0.0;
  int max_episode_length = 0;
  std::vector<std::string> observation_names, action_names;
  std::vector<double> action_low, action_high;
  std::vector<double> scan_beam_angles, scan_range;  // absent in files written before them
};

template <typename C, typename V>
IfConfig<C, SpecFields> visitFields(C& c, V&& v) {
  v("task", c.task, AnyValue{}, "");
  v("control_dt", c.control_dt, AnyValue{}, "");
  v("max_episode_length", c.max_episode_length, AnyValue{}, "");
  v("observation_names", c.observation_names, AnyValue{}, "");
  v("action_names", c.action_names, AnyValue{}, "");
  v("action_low", c.action_low, AnyValue{}, "");
  v("action_high", c.action_high, AnyValue{}, "");
  v("scan_beam_angles", c.scan_beam_angles, AnyValue{}, "");
  v("scan_range", c.scan_range, AnyValue{}, "");
}

// SpecFields and BatchSpec name the fields they share alike: one copy serves both directions.
template <class From, class To>
void copySpec(const From& from, To& to) {
  to.task = from.task;
  to.control_dt = from.control_dt;
  to.max_episode_length = from.max_episode_length;
  to.observation_names = from.observation_names;
  to.action_names = from.action_names;
  to.action_low.assign(from.action_low.begin(), from.action_low.end());
  to.action_high.assign(from.action_high.begin(), from.action_high.end());
  to.scan_beam_angles = from.scan_beam_angles;
  to.scan_range = from.scan_range;
}

std::string specYaml(const BatchSpec& spec) {
  SpecFields f;
  copySpec(spec, f);
  return fieldsToYaml(f);
}

BatchSpec specFromYaml(const std::string& yaml, int obs_dim, int action_dim) {
  SpecFields f;
  fieldsFromYaml(yaml, f);
  BatchSpec spec;
  spec.obs_dim = obs_dim;
  spec.action_dim = action_dim;
  copySpec(f, spec);
  return spec;
}

void writeMeta(torch::serialize::OutputArchive& a, const CheckpointMeta& m) {
  a.write("format_version", c10::IValue(kFormatVersion));
  a.write("iteration", c10::IValue(m.iteration));
  a.write("env_steps", c10::IValue(m.env_steps));
  a.write("elapsed_s", c10::IValue(m.elapsed_s));
  a.write("best_reward", c10::IValue(m.best_reward));
  a.write("learning_rate", c10::IValue(m.learning_rate));
  a.write("obs_dim", c10::IValue(static_cast<std::int64_t>(m.obs_dim)));
  a.write("action_dim", c10::IValue(static_cast<std::int64_t>(m.action_dim)));
  a.write("config", c10::IValue(toYaml(m.config)));
  a.write("spec", c10::IValue(specYaml(m.spec)));
}

CheckpointMeta readMeta(torch::serialize::InputArchive& a) {
  c10::IValue v;
  a.read("format_version", v);
  const std::int64_t version = v.toInt();
  if (version < 1 || version > kFormatVersion) {
    throw Error("unsupported checkpoint format version " + std::to_string(version));
  }
  CheckpointMeta m;
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
  m.config = fromYaml(v.toStringRef());
  if (version >= 2) {
    a.read("spec", v);
    m.spec = specFromYaml(v.toStringRef(), m.obs_dim, m.action_dim);
  }
  return m;
}

torch::serialize::InputArchive openArchive(const std::string& path) {
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

void checkSizes(const std::string& path, const CheckpointMeta& m, int input_dim, int action_dim) {
  const int input = policyInputDim(m.config, m.obs_dim, m.action_dim);
  if (input != input_dim || m.action_dim != action_dim) {
    throw Error("checkpoint " + path + " is for input " + std::to_string(input) + " (obs_dim " +
                std::to_string(m.obs_dim) + "), action_dim " + std::to_string(m.action_dim) +
                "; the model has " + std::to_string(input_dim) + ", " + std::to_string(action_dim));
  }
}

}  // namespace

void saveCheckpoint(const std::string& path, Ppo& ppo, const CheckpointMeta& meta) {
  torch::serialize::OutputArchive archive, model, optimizer, normalizer;
  ppo.model()->save(model);
  ppo.optimizer().save(optimizer);
  ppo.normalizer()->save(normalizer);
  archive.write("model", model);
  archive.write("optimizer", optimizer);
  archive.write("normalizer", normalizer);
  writeMeta(archive, meta);
  const std::string tmp = path + ".tmp";
  try {
    archive.save_to(tmp);
  } catch (const c10::Error& e) {
    throw Error("cannot write checkpoint " + tmp + ": " + e.what_without_backtrace());
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw Error("cannot rename " + tmp + " to " + path + ": " + ec.message());
}

CheckpointMeta readCheckpointMeta(const std::string& path) {
  torch::serialize::InputArchive archive = openArchive(path);
  try {
    return readMeta(archive);
  } catch (const c10::Error& e) {
    throw Error("checkpoint " + path + " lacks metadata: " + e.what_without_backtrace());
  }
}

CheckpointMeta loadCheckpoint(const std::string& path, Ppo& ppo) {
  torch::serialize::InputArchive archive = openArchive(path);
  try {
    const CheckpointMeta meta = readMeta(archive);
    checkSizes(path, meta, ppo.model()->inputDim(), ppo.model()->actionDim());
    torch::serialize::InputArchive model, optimizer, normalizer;
    archive.read("model", model);
    archive.read("optimizer", optimizer);
    archive.read("normalizer", normalizer);
    ppo.model()->load(model);
    ppo.optimizer().load(optimizer);
    ppo.normalizer()->load(normalizer);
    ppo.setLearningRate(meta.learning_rate);
    return meta;
  } catch (const c10::Error& e) {
    throw Error("cannot load checkpoint " + path + ": " + e.what_without_backtrace());
  }
}

CheckpointMeta loadPolicy(const std::string& path, ActorCritic& model, ObsNormalizer& normalizer) {
  torch::serialize::InputArchive archive = openArchive(path);
  try {
    const CheckpointMeta meta = readMeta(archive);
    checkSizes(path, meta, model->inputDim(), model->actionDim());
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
