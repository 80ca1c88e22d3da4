// One way to build an env: EnvSetup read from YAML files and makeEnv(), with the field and
// cross-field rules of validateConfig().
#include <algorithm>
#include <string>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/config/yaml_flatten.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/errors.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// The ConfigError's text, or a failure when `f` does not throw one.
template <typename F>
std::string configError(F&& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ConfigError";
  return "";
}

TEST(EnvSetup, MakeEnvBuildsTheConfiguredBatchAndTask) {
  EnvSetup setup;
  setup.env.num_envs = 3;
  setup.task.task = TaskKind::kCommand;
  setup.task.reward_variant = RewardVariant::kSum;
  const auto env = makeEnv(test::jetbot(), setup);
  EXPECT_EQ(env->numEnvs(), 3);
  ASSERT_EQ(env->task().name(), "command");
  EXPECT_EQ(dynamic_cast<const CommandTask&>(env->task()).variant(), CommandTask::Variant::kSum);
}

TEST(EnvSetup, MakeEnvRefusesAFieldAndACrossFieldRuleNamingTheField) {
  EnvSetup setup;
  setup.env.decimation = 0;
  EXPECT_NE(configError([&] { makeEnv(test::jetbot(), setup); }).find("decimation = 0"),
            std::string::npos);
  setup = EnvSetup();
  setup.env.episode_length_s = 0.01;  // fewer than 2 control steps: a rule between fields
  EXPECT_NE(configError([&] { validateConfig(setup); }).find("episode_length_s = 0.01"),
            std::string::npos);
  EXPECT_THROW(makeEnv(test::jetbot(), setup), ConfigError);
}

TEST(EnvSetup, FilesAreReadInOrderAndTheLastWins) {
  const std::string a = test::writeTempFile("setup_a.yaml",
                                            "num_envs: 7\ntask: command  # comment\n"
                                            "mode: realtime  # a node parameter: ignored\n");
  const std::string b = test::writeTempFile("setup_b.yaml", "num_envs: 9\nreward_variant: sum\n");
  EnvSetup setup;
  readEnvSetupFiles({a, b}, setup);
  EXPECT_EQ(setup.env.num_envs, 9);
  EXPECT_EQ(setup.task.task, TaskKind::kCommand);
  EXPECT_EQ(setup.task.reward_variant, RewardVariant::kSum);
}

TEST(EnvSetup, AnUnreadableFileOrAWrongTypeIsNamedAndChangesNothingAfterIt) {
  EnvSetup setup;
  const std::string missing = ::testing::TempDir() + "no_such_setup.yaml";
  EXPECT_NE(configError([&] { readEnvSetupFiles({missing}, setup); }).find(missing),
            std::string::npos);
  const std::string bad = test::writeTempFile("setup_bad.yaml", "num_envs: many\n");
  const std::string text = configError([&] { readEnvSetupFiles({bad}, setup); });
  EXPECT_NE(text.find(bad), std::string::npos) << text;
  EXPECT_NE(text.find("num_envs = 'many'"), std::string::npos) << text;
  EXPECT_EQ(setup.env.num_envs, EnvConfig().num_envs);
}

TEST(EnvSetup, FilesAreReadAsYamlListsInEitherStyleAsRosparamReadsThem) {
  // A block list (as PyYAML or a user writes one) means what the flow list means: the scanner's
  // angles were silently left as they were before.
  const std::string flow = test::writeTempFile(
      "setup_flow.yaml", "scan:\n  samples: 360\n  angles: [-3.1, 3.0]\nworld:\n  map: ''\n");
  const std::string block = test::writeTempFile(
      "setup_block.yaml",
      "scan:\n  angles:\n  - -3.1\n  -   3.0  # comment\n  samples: 360\nworld:\n  map: \"\"\n");
  for (const std::string& file : {flow, block}) {
    EnvSetup setup;
    setup.env.world.map = "maps/office.yaml";
    readEnvSetupFiles({file}, setup);
    EXPECT_EQ(setup.env.scan.samples, 360) << file;
    EXPECT_EQ(setup.env.scan.angles, (std::vector<double>{-3.1, 3.0})) << file;
    EXPECT_EQ(setup.env.world.map, "") << file;  // an empty string given, not left out
  }
  EXPECT_EQ(flattenYaml("a:\n  b: [x, y]\n  c:\n    - 1\n  d:\n"), "a/b: [x, y]\na/c: [1]\n");
  // Not YAML, or a list of lists: named, nothing read.
  EnvSetup setup;
  const std::string broken = test::writeTempFile("setup_broken.yaml", "num_envs: 7\nscan: [1,\n");
  std::string text = configError([&] { readEnvSetupFiles({broken}, setup); });
  EXPECT_NE(text.find(broken + ": no YAML at line"), std::string::npos) << text;
  EXPECT_EQ(text.find(broken), text.rfind(broken)) << text;  // the file named once
  const std::string nested =
      test::writeTempFile("setup_nested.yaml", "num_envs: 7\nscan:\n  angles:\n  - [1, 2]\n");
  text = configError([&] { readEnvSetupFiles({nested}, setup); });
  EXPECT_NE(text.find(nested + ": scan/angles holds a list or a map"), std::string::npos) << text;
  EXPECT_EQ(setup.env.num_envs, EnvConfig().num_envs);
}

TEST(EnvSetup, FieldNamesAreTheEnvsThenTheTasks) {
  const std::vector<std::string> names = fieldNames(EnvSetup());
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), "num_envs");
  EXPECT_NE(std::find(names.begin(), names.end(), "reward_variant"), names.end());
  EXPECT_EQ(names.back(), "road/curriculum_step");  // the last task's last
}

TEST(EnvProgramOptions, OptionsBuildTheSetupAndOldNamesAreRefused) {
  const std::string file = test::writeTempFile("setup_cli.yaml", "task: command\nnum_envs: 5\n");
  EnvProgramOptions options;
  std::string error;
  const auto take = [&options](const std::string& o, const std::string& v, std::string& e) {
    return options.take(o, v, e);
  };
  std::vector<std::string> words{"prog", "--config", file, "--num-envs", "2", "--threads", "1"};
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  ASSERT_TRUE(parseOptions(static_cast<int>(argv.size()), argv.data(), take, error)) << error;
  const EnvSetup setup = options.setup();
  EXPECT_EQ(setup.env.num_envs, 2);  // the option wins over the file
  EXPECT_EQ(setup.env.num_threads, 1);
  EXPECT_EQ(setup.task.task, TaskKind::kCommand);

  std::vector<std::string> old_words{"prog", "--envs", "4"};
  std::vector<char*> old_argv;
  for (auto& w : old_words) old_argv.push_back(w.data());
  EXPECT_FALSE(parseOptions(static_cast<int>(old_argv.size()), old_argv.data(), take, error));
  EXPECT_EQ(error, "--envs was renamed --num-envs");
  EXPECT_EQ(options.num_envs, 2);
}

}  // namespace
}  // namespace jetbot_rl
