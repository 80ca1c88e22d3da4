#pragma once
// Option values of the programs' command lines, checked as strictly as the nodes' parameters.
#include <cerrno>
#include <cstdlib>
#include <functional>
#include <string>

namespace jetbot_rl {

/// `value` of `option` as a whole number in [minimum, maximum] into `out`; false (with `error`
/// naming the option and the value, `out` unchanged) otherwise.
inline bool parseWholeNumber(const std::string& option, const std::string& value, long long minimum,
                             long long maximum, long long& out, std::string& error) {
  char* end = nullptr;
  errno = 0;
  const long long number = std::strtoll(value.c_str(), &end, 10);
  if (value.empty() || *end != '\0' || errno != 0 || number < minimum || number > maximum) {
    error = "invalid " + option + " = " + value + " (a whole number in [" +
            std::to_string(minimum) + ", " + std::to_string(maximum) + "])";
    return false;
  }
  out = number;
  return true;
}

/// The same for an int.
inline bool parseWholeNumber(const std::string& option, const std::string& value, int minimum,
                             int maximum, int& out, std::string& error) {
  long long number = 0;
  if (!parseWholeNumber(option, value, static_cast<long long>(minimum),
                        static_cast<long long>(maximum), number, error)) {
    return false;
  }
  out = static_cast<int>(number);
  return true;
}

/// Takes argv as `--option value` pairs: `take(option, value, error)` stores one and returns false
/// for an option it does not know (or with `error` set for a bad value). False with `error`
/// naming the option when one is unknown, bad or lacks its value.
inline bool parseOptions(
    int argc, char** argv,
    const std::function<bool(const std::string&, const std::string&, std::string&)>& take,
    std::string& error) {
  for (int i = 1; i < argc; i += 2) {
    const std::string option = argv[i];
    if (i + 1 >= argc) {
      error = "option " + option + " needs a value";
      return false;
    }
    if (!take(option, argv[i + 1], error)) {
      if (error.empty()) error = "unknown option " + option;
      return false;
    }
    if (!error.empty()) return false;
  }
  return true;
}

}  // namespace jetbot_rl
