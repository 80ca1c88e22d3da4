#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace jetbot_rl {

/// Base of every error the core reports; the message names the offending field, link or joint.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An invalid configuration value (names the field and the value).
class ConfigError : public Error {
 public:
  using Error::Error;
};

/// A robot description the core cannot simulate (names the link or joint).
class ModelError : public Error {
 public:
  using Error::Error;
};

/// Rejected input to step() or reset(); nothing was changed.
class InputError : public Error {
 public:
  using Error::Error;
};

/// Throws ConfigError "invalid <field> = <value>: <rule>".
template <typename T>
[[noreturn]] void throwInvalid(const std::string& field, const T& value, const std::string& rule) {
  std::ostringstream s;
  s << "invalid " << field << " = " << value << ": " << rule;
  throw ConfigError(s.str());
}

}  // namespace jetbot_rl
