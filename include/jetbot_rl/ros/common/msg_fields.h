#pragma once

// A flat ROS message's fields by name, for converting between a message and a core struct whose
// field list (config_fields.h's visitFields) names the same fields: the names come from the
// message's definition (ros::message_traits::Definition), the fields in the same order from its
// serializer (allInOne), so a field added to the .msg and the struct needs no conversion code.

#include <ros/message_traits.h>
#include <ros/serialization.h>

#include <string>
#include <type_traits>
#include <vector>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

/// The field names of a message definition without nested messages, in order (constants and
/// comments skipped). Error for a definition it cannot read.
std::vector<std::string> msgFieldNames(const std::string& definition);

namespace detail {

template <class V>
struct FieldWalker {
  const std::vector<std::string>& names;
  V& visit;
  std::size_t next_field = 0;
  template <class T>
  void next(T& field) {
    if (next_field >= names.size())
      throw Error("message definition has fewer fields than the type");
    visit(names[next_field++], field);
  }
};

template <class T>
struct IsVector : std::false_type {};
template <class T, class A>
struct IsVector<std::vector<T, A>> : std::true_type {};

}  // namespace detail

/// Calls `visit(name, field)` for every field of `msg` (a flat message: no nested message
/// types), in the order of its definition.
template <class M, class V>
void visitMsgFields(M& msg, V&& visit) {
  using Msg = std::remove_const_t<M>;
  static const std::vector<std::string> names =
      msgFieldNames(ros::message_traits::Definition<Msg>::value());
  detail::FieldWalker<std::remove_reference_t<V>> walker{names, visit};
  ros::serialization::Serializer<Msg>::template allInOne<decltype(walker), M&>(walker, msg);
}

/// Assigns `from` to `to` where a message field and a struct field of one name meet: numbers to
/// numbers (of any width), lists to lists, strings to strings. Error naming `name` for types
/// that cannot meet (a .msg type that does not fit the struct's).
template <class To, class From>
void assignField(const std::string& name, To& to, const From& from) {
  if constexpr (detail::IsVector<To>::value && detail::IsVector<From>::value) {
    using T = typename To::value_type;
    using F = typename From::value_type;
    if constexpr ((std::is_arithmetic_v<T> && std::is_arithmetic_v<F>) || std::is_same_v<T, F>) {
      to.assign(from.begin(), from.end());
      return;
    }
  } else if constexpr (std::is_arithmetic_v<To> && std::is_arithmetic_v<From>) {
    to = static_cast<To>(from);
    return;
  } else if constexpr (std::is_same_v<To, From>) {
    to = from;
    return;
  }
  throw Error("field " + name + ": the message's type and the struct's do not fit");
}

/// Appends `from` to the per-env array `to` where a message field and a struct field of one name
/// meet: a number to a list of numbers (of any width), a list to a list (concatenated). Error
/// naming `name` for types that cannot meet.
template <class To, class From>
void appendField(const std::string& name, To& to, const From& from) {
  if constexpr (detail::IsVector<To>::value) {
    using T = typename To::value_type;
    if constexpr (std::is_arithmetic_v<T> && std::is_arithmetic_v<From>) {
      to.push_back(static_cast<T>(from));
      return;
    } else if constexpr (detail::IsVector<From>::value) {
      if constexpr (std::is_arithmetic_v<T> && std::is_arithmetic_v<typename From::value_type>) {
        to.insert(to.end(), from.begin(), from.end());
        return;
      }
    }
  }
  throw Error("field " + name + ": the message's type and the struct's do not fit");
}

}  // namespace jetbot_rl
