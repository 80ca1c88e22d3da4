#include "jetbot_rl/ppo/ppo_checkpoint.h"

#include <torch/serialize.h>

#include <filesystem>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

void saveCheckpoint(const std::string& path, Ppo& ppo, const CheckpointMeta& meta) {
  torch::serialize::OutputArchive archive, model, optimizer, normalizer;
  ppo.model()->save(model);
  ppo.optimizer().save(optimizer);
  ppo.normalizer()->save(normalizer);
  archive.write("model", model);
  archive.write("optimizer", optimizer);
  archive.write("normalizer", normalizer);
  writeCheckpointMeta(archive, meta, toYaml(ppo.config()));
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

CheckpointMeta loadCheckpoint(const std::string& path, Ppo& ppo) {
  torch::serialize::InputArchive archive = openCheckpoint(path);
  try {
    const CheckpointMeta meta = readCheckpointMeta(archive);
    checkCheckpointSizes(path, meta, ppo.model()->inputDim(), ppo.model()->actionDim());
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

PpoConfig readCheckpointConfig(const std::string& path) {
  torch::serialize::InputArchive archive = openCheckpoint(path);
  std::string yaml;
  try {
    readCheckpointMeta(archive, &yaml);
  } catch (const c10::Error& e) {
    throw Error("checkpoint " + path + " lacks metadata: " + e.what_without_backtrace());
  }
  return fromYaml(yaml);
}

}  // namespace ppo
}  // namespace jetbot_rl
