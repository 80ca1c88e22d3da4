#include "jetbot_rl/ppo/ppo_config.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace ppo {
namespace {

std::string listText(const std::vector<int>& v) {
  std::ostringstream s;
  s << "[";
  for (std::size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
  s << "]";
  return s.str();
}

void checkPositive(const std::string& name, double value) {
  if (!std::isfinite(value) || value <= 0.0) throwInvalid(name, value, "must be a positive number");
}

void checkUnit(const std::string& name, double value) {
  if (!std::isfinite(value) || value < 0.0 || value > 1.0)
    throwInvalid(name, value, "must be in [0, 1]");
}

void checkDims(const std::string& name, const std::vector<int>& dims) {
  if (dims.empty()) throwInvalid(name, "[]", "needs at least one hidden layer");
  for (int d : dims) {
    if (d < 1 || d > 4096) throwInvalid(name, listText(dims), "every width must be in [1, 4096]");
  }
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

// --- YAML writing and reading of one field ---
void writeValue(std::ostream& s, int v) { s << v; }
void writeValue(std::ostream& s, double v) {
  s << std::setprecision(std::numeric_limits<double>::max_digits10) << v;
}
void writeValue(std::ostream& s, bool v) { s << (v ? "true" : "false"); }
void writeValue(std::ostream& s, const std::string& v) { s << v; }
void writeValue(std::ostream& s, const std::vector<int>& v) { s << listText(v); }

[[noreturn]] void badValue(const std::string& name, const std::string& text, const char* type) {
  throw ConfigError("invalid " + name + " = '" + text + "': must be " + type);
}

void readValue(const std::string& name, const std::string& text, int& v) {
  std::istringstream s(text);
  long long x;
  if (!(s >> x) || !(s >> std::ws).eof()) badValue(name, text, "an integer");
  v = static_cast<int>(x);
}
void readValue(const std::string& name, const std::string& text, double& v) {
  std::istringstream s(text);
  if (!(s >> v) || !(s >> std::ws).eof()) badValue(name, text, "a number");
}
void readValue(const std::string& name, const std::string& text, bool& v) {
  if (text == "true" || text == "True") {
    v = true;
  } else if (text == "false" || text == "False") {
    v = false;
  } else {
    badValue(name, text, "true or false");
  }
}
void readValue(const std::string&, const std::string& text, std::string& v) { v = text; }
void readValue(const std::string& name, const std::string& text, std::vector<int>& v) {
  if (text.size() < 2 || text.front() != '[' || text.back() != ']') {
    badValue(name, text, "a list of integers [a, b]");
  }
  std::vector<int> out;
  std::istringstream s(text.substr(1, text.size() - 2));
  std::string item;
  while (std::getline(s, item, ',')) {
    int x = 0;
    readValue(name, trim(item), x);
    out.push_back(x);
  }
  v = out;
}

}  // namespace

void validate(const PpoConfig& c) {
  if (c.seed < 0) throwInvalid("seed", c.seed, "must be >= 0");
  if (c.num_steps_per_env < 1 || c.num_steps_per_env > 100000) {
    throwInvalid("num_steps_per_env", c.num_steps_per_env, "must be in [1, 100000]");
  }
  checkDims("actor_hidden_dims", c.actor_hidden_dims);
  checkDims("critic_hidden_dims", c.critic_hidden_dims);
  if (c.activation != "elu" && c.activation != "tanh" && c.activation != "relu") {
    throwInvalid("activation", "'" + c.activation + "'", "must be elu, tanh or relu");
  }
  checkPositive("init_noise_std", c.init_noise_std);
  if (c.action_squash != "clip" && c.action_squash != "tanh") {
    throwInvalid("action_squash", "'" + c.action_squash + "'", "must be clip or tanh");
  }
  if (c.num_learning_epochs < 1 || c.num_learning_epochs > 1000) {
    throwInvalid("num_learning_epochs", c.num_learning_epochs, "must be in [1, 1000]");
  }
  if (c.num_mini_batches < 1) throwInvalid("num_mini_batches", c.num_mini_batches, "must be >= 1");
  checkPositive("learning_rate", c.learning_rate);
  if (c.schedule != "adaptive" && c.schedule != "fixed") {
    throwInvalid("schedule", "'" + c.schedule + "'", "must be adaptive or fixed");
  }
  checkPositive("desired_kl", c.desired_kl);
  checkPositive("min_learning_rate", c.min_learning_rate);
  checkPositive("max_learning_rate", c.max_learning_rate);
  if (c.min_learning_rate > c.max_learning_rate) {
    throwInvalid("min_learning_rate", c.min_learning_rate, "must be <= max_learning_rate");
  }
  checkUnit("gamma", c.gamma);
  checkUnit("lam", c.lam);
  checkPositive("clip_param", c.clip_param);
  if (!std::isfinite(c.value_loss_coef) || c.value_loss_coef < 0.0) {
    throwInvalid("value_loss_coef", c.value_loss_coef, "must be >= 0");
  }
  if (!std::isfinite(c.entropy_coef) || c.entropy_coef < 0.0) {
    throwInvalid("entropy_coef", c.entropy_coef, "must be >= 0");
  }
  checkPositive("max_grad_norm", c.max_grad_norm);
}

std::string toYaml(const PpoConfig& config) {
  std::ostringstream s;
  visitFields(config, [&s](const char* name, const auto& value) {
    s << name << ": ";
    writeValue(s, value);
    s << "\n";
  });
  return s.str();
}

PpoConfig fromYaml(const std::string& yaml, PpoConfig config) {
  std::istringstream lines(yaml);
  std::string line;
  while (std::getline(lines, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = trim(line.substr(0, colon));
    const std::string text = trim(line.substr(colon + 1));
    visitFields(config, [&](const char* name, auto& value) {
      if (key == name) readValue(key, text, value);
    });
  }
  return config;
}

bool sameArchitecture(const PpoConfig& a, const PpoConfig& b) {
  return a.actor_hidden_dims == b.actor_hidden_dims &&
         a.critic_hidden_dims == b.critic_hidden_dims && a.activation == b.activation;
}

}  // namespace ppo
}  // namespace jetbot_rl
