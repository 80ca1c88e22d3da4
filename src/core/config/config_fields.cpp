#include "jetbot_rl/config/config_fields.h"

#include <cctype>

namespace jetbot_rl {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

[[noreturn]] void badValue(const std::string& field, const std::string& text, const char* type) {
  throwInvalid(field, "'" + text + "'", std::string("must be ") + type);
}

/// The items of a flow list "[a, b]".
std::vector<std::string> listItems(const std::string& field, const std::string& text,
                                   const char* type) {
  if (text.size() < 2 || text.front() != '[' || text.back() != ']') badValue(field, text, type);
  std::vector<std::string> items;
  std::istringstream s(text.substr(1, text.size() - 2));
  std::string item;
  while (std::getline(s, item, ',')) items.push_back(trim(item));
  if (items.size() == 1 && items[0].empty()) items.clear();
  return items;
}

}  // namespace

void IntList::check(const std::string& name, const std::vector<int>& values) const {
  std::ostringstream text;
  writeValue(text, values);
  if (values.empty()) throwInvalid(name, "[]", "needs at least one value");
  for (int v : values) {
    if (v < lo || v > hi) {
      throwInvalid(
          name, text.str(),
          "every value must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
  }
}

void readValue(const std::string& field, const std::string& text, bool& v) {
  if (text == "true" || text == "True") {
    v = true;
  } else if (text == "false" || text == "False") {
    v = false;
  } else {
    badValue(field, text, "true or false");
  }
}

void readValue(const std::string& field, const std::string& text, int& v) {
  std::istringstream s(text);
  long long x;
  if (!(s >> x) || !(s >> std::ws).eof() || x < std::numeric_limits<int>::min() ||
      x > std::numeric_limits<int>::max()) {
    badValue(field, text, "an integer");
  }
  v = static_cast<int>(x);
}

void readValue(const std::string& field, const std::string& text, std::int64_t& v) {
  std::istringstream s(text);
  if (!(s >> v) || !(s >> std::ws).eof()) badValue(field, text, "an integer");
}

void readValue(const std::string& field, const std::string& text, std::uint64_t& v) {
  std::istringstream s(text);
  if (text.empty() || text[0] == '-' || !(s >> v) || !(s >> std::ws).eof()) {
    badValue(field, text, "an integer >= 0");
  }
}

void readValue(const std::string& field, const std::string& text, double& v) {
  // YAML's infinities and NaN (.inf, -.inf, .nan, any case), which streams do not read.
  std::string lower = text;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == ".inf" || lower == "+.inf" || lower == "-.inf") {
    v = lower[0] == '-' ? -std::numeric_limits<double>::infinity()
                        : std::numeric_limits<double>::infinity();
    return;
  }
  if (lower == ".nan") {
    v = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  std::istringstream s(text);
  if (!(s >> v) || !(s >> std::ws).eof()) badValue(field, text, "a number");
}

void readValue(const std::string& field, const std::string& text, float& v) {
  double x = 0.0;
  readValue(field, text, x);
  v = static_cast<float>(x);
}

void readValue(const std::string&, const std::string& text, std::string& v) {
  // A quoted scalar ('' or "...") stands for its contents.
  const bool quoted = text.size() >= 2 && (text.front() == '\'' || text.front() == '"') &&
                      text.back() == text.front();
  v = quoted ? text.substr(1, text.size() - 2) : text;
}

// All items are read before `v` changes: a bad item leaves it as it was.
template <typename T>
void readList(const std::string& field, const std::string& text, const char* what,
              std::vector<T>& v) {
  std::vector<T> out;
  for (const auto& item : listItems(field, text, what)) {
    T x{};
    readValue(field, item, x);
    out.push_back(x);
  }
  v = out;
}

void readValue(const std::string& field, const std::string& text, std::vector<int>& v) {
  readList(field, text, "a list of integers [a, b]", v);
}

void readValue(const std::string& field, const std::string& text, std::vector<double>& v) {
  if (!text.empty() && text.front() != '[') {  // a single number stands for a list of one
    double x = 0;
    readValue(field, text, x);
    v = {x};
    return;
  }
  readList(field, text, "a list of numbers [a, b]", v);
}

void readValue(const std::string& field, const std::string& text, std::vector<float>& v) {
  readList(field, text, "a list of numbers [a, b]", v);
}

void readValue(const std::string& field, const std::string& text, std::vector<std::string>& v) {
  v = listItems(field, text, "a list of names [a, b]");
}

std::vector<std::pair<std::string, std::string>> yamlLines(const std::string& yaml) {
  std::vector<std::pair<std::string, std::string>> lines;
  std::vector<std::pair<std::size_t, std::string>> parents;  // indentation, key of open blocks
  std::istringstream in(yaml);
  std::string line;
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::size_t indent = line.find_first_not_of(" \t");
    while (!parents.empty() && parents.back().first >= indent) parents.pop_back();
    std::string key = trim(line.substr(0, colon));
    for (auto p = parents.rbegin(); p != parents.rend(); ++p) key = p->second + "/" + key;
    const std::string value = trim(line.substr(colon + 1));
    if (value.empty()) {  // a block: its indented lines are "key/child"
      parents.emplace_back(indent, trim(line.substr(0, colon)));
      continue;
    }
    lines.emplace_back(key, value);
  }
  return lines;
}

}  // namespace jetbot_rl
