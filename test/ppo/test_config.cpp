// PpoConfig: YAML round trip and validation messages that name the parameter.
#include <gtest/gtest.h>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/ppo_config.h"

namespace jetbot_rl {
namespace ppo {
namespace {

TEST(PpoConfig, DefaultsAreValid) { EXPECT_NO_THROW(validate(PpoConfig())); }

TEST(PpoConfig, YamlRoundTrip) {
  PpoConfig c;
  c.seed = 3;
  c.actor_hidden_dims = {64, 32, 16};
  c.activation = Activation::kRelu;
  c.learning_rate = 3.14159e-4;
  c.use_clipped_value_loss = false;
  c.schedule = LrSchedule::kFixed;
  const PpoConfig back = fromYaml(toYaml(c));
  EXPECT_EQ(toYaml(back), toYaml(c));
  EXPECT_EQ(back.actor_hidden_dims, c.actor_hidden_dims);
  EXPECT_DOUBLE_EQ(back.learning_rate, c.learning_rate);
  EXPECT_FALSE(back.use_clipped_value_loss);
}

TEST(PpoConfig, EnumsAreParsedOnceAndBadNamesAreNamed) {
  EXPECT_EQ(fromYaml("activation: relu\nschedule: fixed\naction_squash: tanh\n").activation,
            Activation::kRelu);
  for (const auto& [yaml, field] :
       {std::pair{"activation: sigmoid", "activation = 'sigmoid': must be elu, tanh or relu"},
        std::pair{"schedule: cosine", "schedule = 'cosine': must be adaptive or fixed"},
        std::pair{"action_squash: none", "action_squash = 'none': must be clip or tanh"}}) {
    try {
      fromYaml(yaml);
      FAIL() << "accepted " << yaml;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
}

TEST(PpoConfig, FromYamlIgnoresCommentsAndUnknownKeys) {
  const PpoConfig c = fromYaml("# comment\ngamma: 0.5  # discount\nunknown: 3\n");
  EXPECT_DOUBLE_EQ(c.gamma, 0.5);
  EXPECT_THROW(fromYaml("gamma: fast\n"), ConfigError);
  EXPECT_THROW(fromYaml("actor_hidden_dims: 32\n"), ConfigError);
}

void expectInvalid(const PpoConfig& c, const std::string& name) {
  try {
    validate(c);
    FAIL() << "accepted an invalid " << name;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
}

TEST(PpoConfig, InvalidValuesNameTheParameter) {
  PpoConfig c;
  c.num_steps_per_env = 0;
  expectInvalid(c, "num_steps_per_env");
  c = PpoConfig();
  c.gamma = 1.5;
  expectInvalid(c, "gamma");
  c = PpoConfig();
  c.actor_hidden_dims = {};
  expectInvalid(c, "actor_hidden_dims");
  c = PpoConfig();
  c.learning_rate = -1;
  expectInvalid(c, "learning_rate");
  c = PpoConfig();
  c.num_mini_batches = 0;
  expectInvalid(c, "num_mini_batches");
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
