// jetbot_rl_param_docs: the parameter tables of docs/ and the defaults, from the field lists.
//   jetbot_rl_param_docs tables            every table: "## ID" and its Markdown table
//   jetbot_rl_param_docs table ID          one Markdown table (ID: see kTables)
//   jetbot_rl_param_docs defaults NODE     "name: value" of every parameter of a node, defaults
// scripts/generate_param_docs.py writes the tables into docs/; test/docs checks that docs/, the
// config files and the launch files agree with these defaults.
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/planning/dwa_planner.h"
#include "jetbot_rl/ppo/ros/policy_params.h"
#include "jetbot_rl/ppo/ros/trainer_params.h"
#include "jetbot_rl/ros/deploy/deploy_params.h"
#include "jetbot_rl/ros/deploy/depth_scan_params.h"
#include "jetbot_rl/ros/env_node/node_params.h"
#include "lockstep_bench.h"

namespace jetbot_rl {
namespace {

struct Row {
  std::string name, type, value, rule, meaning;
};

const char* typeName(bool) { return "bool"; }
const char* typeName(int) { return "int"; }
const char* typeName(std::int64_t) { return "int"; }
const char* typeName(std::uint64_t) { return "int"; }
const char* typeName(double) { return "double"; }
const char* typeName(const std::string&) { return "string"; }
const char* typeName(const std::vector<int>&) { return "int list"; }
const char* typeName(const std::vector<double>&) { return "double list"; }
const char* typeName(const std::vector<std::string>&) { return "string list"; }
template <typename E, typename = std::enable_if_t<IsNamedEnum<E>::value>>
const char* typeName(E) {
  return "string";
}

/// The rule as a table cell (unit included): the rule's text without "must be ", or the
/// accepted values.
template <typename T, typename R>
std::string ruleText(const T&, const R& rule) {
  if constexpr (IsNamedEnum<T>::value) {
    return enumChoices<T>();
  } else if constexpr (std::is_same_v<T, bool>) {
    return "true or false";
  } else {
    std::string text = rule.text();
    const std::string prefix = "must be ";
    if (text.rfind(prefix, 0) == 0) text = text.substr(prefix.size());
    return text.empty() ? "any" : text;
  }
}

template <typename C>
std::vector<Row> rowsOf(const C& config) {
  std::vector<Row> rows;
  visitFields(config,
              [&rows](const char* name, const auto& value, const auto& rule, const char* meaning) {
                std::ostringstream v;
                writeValue(v, value);
                rows.push_back({name, typeName(value), v.str(), ruleText(value, rule), meaning});
              });
  return rows;
}

/// The rows of `all` whose names are not fields of `without`.
template <typename C>
std::vector<Row> rowsWithout(std::vector<Row> all, const C& without) {
  const std::vector<std::string> names = fieldNames(without);
  const std::set<std::string> drop(names.begin(), names.end());
  std::vector<Row> rows;
  for (Row& r : all) {
    if (!drop.count(r.name)) rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<Row> envRows() {
  std::vector<Row> rows = rowsWithout(rowsOf(EnvConfig{}), RandomizationConfig{});
  rows = rowsWithout(std::move(rows), MotorModelConfig{});
  rows = rowsWithout(std::move(rows), MoverConfig{});
  rows = rowsWithout(std::move(rows), TeamConfig{});
  return rowsWithout(rowsWithout(std::move(rows), WorldConfig{}), ScannerConfig{});
}

/// The tables of docs/, by ID (the markers' names).
const std::map<std::string, std::function<std::vector<Row>()>>& tables() {
  static const std::map<std::string, std::function<std::vector<Row>()>> t{
      {"env", envRows},
      {"task", [] { return rowsOf(TaskConfig{}); }},
      {"randomization", [] { return rowsOf(RandomizationConfig{}); }},
      {"motor", [] { return rowsOf(MotorModelConfig{}); }},
      {"world", [] { return rowsOf(WorldConfig{}); }},
      {"movers", [] { return rowsOf(MoverConfig{}); }},
      {"team", [] { return rowsOf(TeamConfig{}); }},
      {"scan", [] { return rowsOf(ScannerConfig{}); }},
      {"dwa", [] { return rowsOf(DwaConfig{}); }},
      {"env_node", [] { return rowsWithout(rowsOf(NodeParams{}), EnvSetup{}); }},
      {"trainer", [] { return rowsOf(ppo::TrainerParams{}); }},
      {"ppo", [] { return rowsOf(ppo::PpoConfig{}); }},
      {"policy_node", [] { return rowsOf(ppo::PolicyParams{}); }},
      {"deploy_node", [] { return rowsOf(DeployParams{}); }},
      {"depth_scan", [] { return rowsOf(DepthScanParams{}); }},
      {"lockstep_bench_nodelet", [] { return rowsOf(LockstepBenchParams{}); }},
  };
  return t;
}

/// Every parameter of each node, for the defaults.
const std::map<std::string, std::function<std::string()>>& nodes() {
  static const std::map<std::string, std::function<std::string()>> n{
      {"jetbot_env_node", [] { return fieldsToYaml(NodeParams{}); }},
      {"env_setup", [] { return fieldsToYaml(EnvSetup{}); }},
      {"jetbot_ppo_trainer", [] { return fieldsToYaml(ppo::TrainerConfig{}); }},
      {"jetbot_policy_node", [] { return fieldsToYaml(ppo::PolicyParams{}); }},
      {"jetbot_deploy_node", [] { return fieldsToYaml(DeployParams{}); }},
      {"jetbot_depth_scan", [] { return fieldsToYaml(DepthScanParams{}); }},
      {"lockstep_bench_nodelet", [] { return fieldsToYaml(LockstepBenchParams{}); }},
  };
  return n;
}

std::string cell(std::string text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string markdown(const std::vector<Row>& rows) {
  std::ostringstream s;
  s << "| Parameter | Type | Default | Rule | Meaning |\n| --- | --- | --- | --- | --- |\n";
  for (const Row& r : rows) {
    s << "| `" << r.name << "` | " << cell(r.type) << " | `" << cell(r.value) << "` | "
      << cell(r.rule) << " | " << cell(r.meaning) << " |\n";
  }
  return s.str();
}

int usage() {
  std::fprintf(stderr, "usage: jetbot_rl_param_docs tables | table ID | defaults NODE\n  IDs:");
  for (const auto& [id, rows] : tables()) std::fprintf(stderr, " %s", id.c_str());
  std::fprintf(stderr, "\n  NODEs:");
  for (const auto& [id, text] : nodes()) std::fprintf(stderr, " %s", id.c_str());
  std::fprintf(stderr, "\n");
  return 2;
}

}  // namespace
}  // namespace jetbot_rl

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && args[0] == "tables") {
    for (const auto& [id, rows] : tables()) std::cout << "## " << id << "\n" << markdown(rows());
    return 0;
  }
  if (args.size() == 2 && args[0] == "table" && tables().count(args[1])) {
    std::cout << markdown(tables().at(args[1])());
    return 0;
  }
  if (args.size() == 2 && args[0] == "defaults" && nodes().count(args[1])) {
    std::cout << nodes().at(args[1])();
    return 0;
  }
  return usage();
}
