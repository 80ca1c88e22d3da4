#pragma once

// One list of fields per configuration struct drives everything done with it: a struct provides
// `visitFields(config, visitor)`, which calls `visitor(name, field, rule, meaning)` for every field
// in order, and the functions below validate it, echo it, write and read it as YAML and document
// it (the parameter tables of docs/ are generated from the same list); the ROS adapter reads it
// from parameters with the same list (jetbot_rl/ros/common/param_reader.h). A struct with rules
// between its fields declares `void checkFieldRules(const T&)` beside its visitFields.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

/// Enables visitFields(C&, V) for the configuration type T, const or not.
template <typename C, typename T>
using IfConfig = std::enable_if_t<std::is_same_v<std::remove_const_t<C>, T>>;

/// The names of an enum's values, for parameters and YAML. An enum gets them from a function
/// `const EnumNameList<E>& enumNames(E)` declared beside it (found by argument lookup).
template <typename E>
using EnumNameList = std::vector<std::pair<E, const char*>>;

template <typename T, typename = void>
struct IsNamedEnum : std::false_type {};
template <typename T>
struct IsNamedEnum<T, std::void_t<decltype(enumNames(std::declval<T>()))>> : std::true_type {};

/// The name of `value` as parameters and YAML spell it.
template <typename E>
std::string enumName(E value) {
  for (const auto& [v, name] : enumNames(value)) {
    if (v == value) return name;
  }
  return "?";
}

/// "a, b or c": the accepted names.
template <typename E>
std::string enumChoices() {
  const auto& list = enumNames(E{});
  std::string s;
  for (std::size_t i = 0; i < list.size(); ++i) {
    s += (i == 0 ? "" : i + 1 == list.size() ? " or " : ", ") + std::string(list[i].second);
  }
  return s;
}

/// Parses `text` for field `field`; ConfigError naming the field, the value and the choices.
template <typename E>
E parseEnum(const std::string& field, const std::string& text) {
  for (const auto& [v, name] : enumNames(E{})) {
    if (text == name) return v;
  }
  throwInvalid(field, "'" + text + "'", "must be " + enumChoices<E>());
}

// ---- rules: what a field's value must be ----

/// Any value of the type (bools, free strings, enums: an enum is checked when it is parsed).
struct AnyValue {
  const char* unit = "";
  const char* note = "";  ///< What a value means, e.g. "empty: none".
  template <typename T>
  void check(const std::string&, const T&) const {}
  std::string text() const { return *note ? note : ""; }
};

/// A number in [lo, hi], either end optionally open; infinite ends read as "> lo" / "<= hi".
template <typename T>
struct Range {
  T lo, hi;
  bool lo_open = false, hi_open = false;
  const char* unit = "";
  const char* note = "";  ///< Appended to the rule, e.g. "0: all cores".

  void check(const std::string& name, T value) const {
    if (!accepts(value)) throwInvalid(name, value, text());
  }
  bool accepts(T value) const {
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(value)) return false;
    }
    return (lo_open ? value > lo : value >= lo) && (hi_open ? value < hi : value <= hi);
  }
  std::string text() const {
    std::ostringstream s;
    const bool unbounded = hi == std::numeric_limits<T>::max() ||
                           (std::is_floating_point_v<T> && std::isinf(static_cast<double>(hi)));
    if (unbounded) {
      s << "must be " << (lo_open ? "> " : ">= ") << lo;
    } else {
      s << "must be in " << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
    }
    if (*unit) s << " " << unit;
    if (*note) s << " (" << note << ")";
    return s.str();
  }
};

/// [lo, hi] inclusive.
template <typename T>
Range<T> inRange(T lo, T hi, const char* unit = "", const char* note = "") {
  return {lo, hi, false, false, unit, note};
}
/// (0, hi] for durations and sizes that must be positive.
inline Range<double> positiveUpTo(double hi, const char* unit = "") {
  return {0.0, hi, true, false, unit, ""};
}
/// > 0, finite.
inline Range<double> positive(const char* unit = "") {
  return {0.0, std::numeric_limits<double>::infinity(), true, false, unit, ""};
}
/// >= lo, finite.
template <typename T>
Range<T> atLeast(T lo, const char* unit = "", const char* note = "") {
  const T hi = std::is_floating_point_v<T> ? std::numeric_limits<T>::infinity()
                                           : std::numeric_limits<T>::max();
  return {lo, hi, false, false, unit, note};
}

/// A non-empty list of distinct, non-empty names (or, when allowed, an empty one).
struct NameList {
  const char* unit = "";
  bool allow_empty = false;
  std::string text() const {
    return allow_empty ? "must be a list of distinct names"
                       : "must be a non-empty list of distinct names";
  }
  void check(const std::string& name, const std::vector<std::string>& names) const {
    if (names.empty() && !allow_empty) throwInvalid(name, "[]", "must name at least one");
    std::set<std::string> seen;
    for (const auto& n : names) {
      if (n.empty()) throwInvalid(name, "''", "names must not be empty");
      if (!seen.insert(n).second) throwInvalid(name, n, "is listed twice");
    }
  }
};

/// A non-empty list of integers, each in [lo, hi].
struct IntList {
  int lo, hi;
  const char* unit = "";
  void check(const std::string& name, const std::vector<int>& values) const;
  std::string text() const {
    return "must be a non-empty list, each value in [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "]";
  }
};

// ---- text of a value: the echo, YAML and error messages ----

inline void writeValue(std::ostream& s, bool v) { s << (v ? "true" : "false"); }
inline void writeValue(std::ostream& s, int v) { s << v; }
inline void writeValue(std::ostream& s, std::int64_t v) { s << v; }
inline void writeValue(std::ostream& s, std::uint64_t v) { s << v; }
/// The shortest text that reads back as the same double (0.99, not 0.98999999999999999);
/// infinities and NaN as YAML writes them (.inf, -.inf, .nan).
inline void writeValue(std::ostream& s, double v) {
  if (!std::isfinite(v)) {
    s << (std::isnan(v) ? ".nan" : v > 0 ? ".inf" : "-.inf");
    return;
  }
  char text[32];
  const std::to_chars_result end = std::to_chars(text, text + sizeof(text), v);
  s.write(text, end.ptr - text);
}
inline void writeValue(std::ostream& s, const std::string& v) { s << v; }
template <typename T>
void writeValue(std::ostream& s, const std::vector<T>& v) {
  s << "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s << ", ";
    writeValue(s, v[i]);
  }
  s << "]";
}
template <typename E, typename = std::enable_if_t<IsNamedEnum<E>::value>>
void writeValue(std::ostream& s, E v) {
  s << enumName(v);
}

// ---- rules on lists ----

/// "[a, b]" with the stream's default precision, for error messages.
template <typename T>
std::string listText(const std::vector<T>& v) {
  std::ostringstream s;
  s << "[";
  for (std::size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
  s << "]";
  return s.str();
}

/// True when `v` is pairs [min, max] one after another (at least one), min <= max in each, every
/// value accepted by `each`.
template <typename T>
bool arePairsOfRanges(const Range<T>& each, const std::vector<T>& v) {
  if (v.empty() || v.size() % 2 != 0) return false;
  for (std::size_t i = 0; i < v.size(); i += 2) {
    if (!each.accepts(v[i]) || !each.accepts(v[i + 1]) || v[i] > v[i + 1]) return false;
  }
  return true;
}

/// A range [min, max] to draw from: two values, min <= max, each accepted by `each` (finite).
/// [v, v] is the constant v.
template <typename T>
struct Interval {
  Range<T> each;
  const char* unit = each.unit;
  void check(const std::string& name, const std::vector<T>& v) const {
    if (v.size() == 2 && arePairsOfRanges(each, v)) return;
    throwInvalid(name, listText(v), text());
  }
  std::string text() const {
    return "must be [min, max] with min <= max; each value " + each.text();
  }
};
template <typename T>
Interval<T> intervalOf(Range<T> each) {
  return Interval<T>{each, each.unit};
}

/// Ranges [min, max] to draw from, one for all or one per item: two values, or pairs
/// [min_0, max_0, min_1, max_1, ...]; in each min <= max, every value accepted by `each`. A user
/// of the field checks the number of pairs it needs.
template <typename T>
struct Intervals {
  Range<T> each;
  const char* unit = each.unit;
  void check(const std::string& name, const std::vector<T>& v) const {
    if (arePairsOfRanges(each, v)) return;
    throwInvalid(name, listText(v), text());
  }
  std::string text() const {
    return "must be [min, max], or one [min, max] after another (one per dof), with min <= max; "
           "each value " +
           each.text();
  }
};
template <typename T>
Intervals<T> intervalsOf(Range<T> each) {
  return Intervals<T>{each, each.unit};
}

/// A list of values, each accepted by `each` (any length, empty included; a user of the field
/// checks the length it needs).
template <typename T>
struct EachValue {
  Range<T> each;
  const char* unit = each.unit;
  void check(const std::string& name, const std::vector<T>& v) const {
    for (T x : v) {
      if (!each.accepts(x)) throwInvalid(name, listText(v), text());
    }
  }
  std::string text() const { return "every value " + each.text(); }
};

/// Parses one YAML scalar or flow list into `v`; ConfigError naming `field` on a wrong type.
void readValue(const std::string& field, const std::string& text, bool& v);
void readValue(const std::string& field, const std::string& text, int& v);
void readValue(const std::string& field, const std::string& text, std::int64_t& v);
void readValue(const std::string& field, const std::string& text, std::uint64_t& v);
void readValue(const std::string& field, const std::string& text, double& v);
void readValue(const std::string& field, const std::string& text, float& v);
void readValue(const std::string& field, const std::string& text, std::string& v);
void readValue(const std::string& field, const std::string& text, std::vector<int>& v);
/// A flow list of numbers, or one number for a list of one.
void readValue(const std::string& field, const std::string& text, std::vector<double>& v);
void readValue(const std::string& field, const std::string& text, std::vector<float>& v);
void readValue(const std::string& field, const std::string& text, std::vector<std::string>& v);
template <typename E, typename = std::enable_if_t<IsNamedEnum<E>::value>>
void readValue(const std::string& field, const std::string& text, E& v) {
  v = parseEnum<E>(field, text);
}

// ---- what is done with a field list ----

/// Checks every field against its rule; ConfigError naming the first invalid one and its value.
template <typename C>
void validateFields(const C& config) {
  visitFields(config, [](const char* name, const auto& value, const auto& rule, const char*) {
    rule.check(name, value);
  });
}

template <typename T, typename = void>
struct HasFieldRules : std::false_type {};
template <typename T>
struct HasFieldRules<T, std::void_t<decltype(checkFieldRules(std::declval<const T&>()))>>
    : std::true_type {};

/// Checks every field against its rule, then the rules between fields (`checkFieldRules(config)`,
/// declared beside the struct's visitFields, when it has any); ConfigError naming the field.
template <typename C>
void validateConfig(const C& config) {
  validateFields(config);
  if constexpr (HasFieldRules<C>::value) checkFieldRules(config);
}

/// One "name: value [unit]" line per field (the start-up echo).
template <typename C>
std::string describeFields(const C& config) {
  std::ostringstream s;
  visitFields(config, [&s](const char* name, const auto& value, const auto& rule, const char*) {
    s << name << ": ";
    writeValue(s, value);
    if (*rule.unit) s << "  # " << rule.unit;
    s << "\n";
  });
  return s.str();
}

/// One "name: value" line per field that `visit(config, visitor)` names (a field list, or a part
/// of one such as NetworkConfig's visitNetworkFields), readable by fieldsFromYaml().
template <typename C, typename Visit>
std::string fieldsToYaml(const C& config, Visit&& visit) {
  std::ostringstream s;
  visit(config, [&s](const char* name, const auto& value, const auto&, const char*) {
    s << name << ": ";
    writeValue(s, value);
    s << "\n";
  });
  return s.str();
}

/// One "name: value" line per field, readable by fieldsFromYaml().
template <typename C>
std::string fieldsToYaml(const C& config) {
  return fieldsToYaml(config, [](const C& c, auto&& v) { visitFields(c, v); });
}

/// "key: value" lines of YAML (comments dropped), in order; a line of a block ("world:" and its
/// indented lines) is "world/key".
std::vector<std::pair<std::string, std::string>> yamlLines(const std::string& yaml);

/// Reads the fields present in `yaml` (fieldsToYaml's format) over `config`; unknown keys are
/// ignored. ConfigError for a value of the wrong type. Does not validate.
template <typename C>
void fieldsFromYaml(const std::string& yaml, C& config) {
  for (const auto& [key, text] : yamlLines(yaml)) {
    visitFields(config, [&key = key, &text = text](const char* name, auto& value, const auto&,
                                                   const char*) {
      if (key == name) readValue(key, text, value);
    });
  }
}

/// The names of every field of `config`, in order.
template <typename C>
std::vector<std::string> fieldNames(const C& config) {
  std::vector<std::string> names;
  visitFields(config, [&names](const char* name, const auto&, const auto&, const char*) {
    names.push_back(name);
  });
  return names;
}

}  // namespace jetbot_rl
