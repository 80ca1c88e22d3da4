#pragma once

#include <ros/duration.h>
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <ros/time.h>

#include <algorithm>
#include <boost/array.hpp>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace jetbot_rl {

/**
 * Walks the serialized bytes of a roscpp message through the message's own generated
 * `Serializer<M>::allInOne`, checking every array and string length against the bytes actually
 * left, without allocating anything (roscpp's deserializer resizes a vector to the length it reads
 * before looking at the bytes: a few bytes claiming 2^31 floats cost 8 GB).
 *
 * Rules: scalars, ros::Time/Duration and fixed-size messages need their size; a string needs its
 * length; an array of fixed-size elements needs `length x element size` (at least `length` bytes
 * for zero-size elements, whose vectors would otherwise grow without bytes); an array of
 * variable-size elements is walked element by element (each takes at least 4 bytes), so a lying
 * length fails after at most bytes/4 elements. Trailing bytes are allowed, as roscpp allows them.
 * Use through boundsViolation().
 */
class BoundsChecker {
 public:
  BoundsChecker(const std::uint8_t* data, std::uint32_t size) : data_(data), size_(size) {}

  /// Walks one message of type M from the current offset (`dummy` only selects the type).
  template <class M>
  void checkMessage(const M& dummy) {
    if (failed_) return;
    if (depth_ < kMaxDepth) frames_[depth_] = Frame{&fieldNames<M>};
    ++depth_;
    ros::serialization::Serializer<M>::template allInOne<BoundsChecker, const M&>(*this, dummy);
    if (!failed_) --depth_;  // on failure the path stays, for reason()
  }

  /// Called by allInOne for each field of the message being walked, in declaration order.
  template <class T>
  void next(const T& field) {
    if (failed_) return;
    if (depth_ <= kMaxDepth) {
      Frame& frame = frames_[depth_ - 1];
      frame.field_now = frame.field++;
      frame.element = -1;
    }
    check(field);
  }

  bool failed() const { return failed_; }
  /// The first failure: the field path, what did not fit, where; `type` names the top-level
  /// message (its ROS data type). Empty when nothing failed.
  std::string reason(const std::string& type) const;

 private:
  enum class Kind { kScalar, kLength, kString, kArray, kFixedArray };
  using NamesFn = const std::vector<std::string>& (*)();
  struct Frame {
    NamesFn names = nullptr;
    std::size_t field = 0;      // fields begun so far
    std::size_t field_now = 0;  // the field being checked
    std::int64_t element = -1;  // its element being checked, -1: none
  };
  static constexpr std::size_t kMaxDepth = 16;  // deeper fields are named by their ancestor

  /// Field names of M in allInOne order, parsed once from its definition text.
  template <class M>
  static const std::vector<std::string>& fieldNames() {
    static const std::vector<std::string> names =
        parseFieldNames(ros::message_traits::definition<M>());
    return names;
  }
  static std::vector<std::string> parseFieldNames(const char* definition);

  std::uint32_t left() const { return size_ - offset_; }
  /// Records the first failure: `needed` bytes (`count` elements of `each`) did not fit.
  void fail(Kind kind, std::uint64_t needed, std::uint64_t count = 0, std::uint64_t each = 0);
  /// Consumes `bytes` if that many are left, else fails.
  bool take(std::uint64_t bytes, Kind kind) {
    if (bytes > left()) {
      fail(kind, bytes);
      return false;
    }
    offset_ += static_cast<std::uint32_t>(bytes);
    return true;
  }
  bool readLength(std::uint32_t& length) {
    if (!take(4, Kind::kLength)) return false;
    std::memcpy(&length, data_ + offset_ - 4, 4);  // little-endian, as roscpp assumes
    return true;
  }
  void setElement(std::int64_t i) {
    if (depth_ <= kMaxDepth) frames_[depth_ - 1].element = i;
  }

  template <class T>
  static std::uint64_t fixedSize() {
    static const std::uint64_t size = ros::serialization::serializationLength(T());
    return size;
  }

  template <class T>
  std::enable_if_t<std::is_arithmetic<T>::value> check(const T&) {
    take(sizeof(T), Kind::kScalar);
  }
  void check(const ros::Time&) { take(8, Kind::kScalar); }
  void check(const ros::Duration&) { take(8, Kind::kScalar); }
  template <class Traits, class Alloc>
  void check(const std::basic_string<char, Traits, Alloc>&) {
    std::uint32_t length;
    if (readLength(length)) take(length, Kind::kString);
  }
  template <class T, class Alloc>
  void check(const std::vector<T, Alloc>&) {
    std::uint32_t length;
    if (readLength(length)) checkElements<T>(length, Kind::kArray);
  }
  template <class T, std::size_t N>
  void check(const boost::array<T, N>&) {
    checkElements<T>(N, Kind::kFixedArray);
  }
  /// Any other field is a generated message.
  template <class M, class = std::enable_if_t<!std::is_arithmetic<M>::value>>
  void check(const M& message) {
    checkMessage(message);
  }

  template <class T>
  void checkElements(std::uint64_t count, Kind kind) {
    if constexpr (ros::message_traits::IsFixedSize<T>::value) {
      const std::uint64_t each = fixedSize<T>();
      // Zero-size elements count as one byte: their vectors would otherwise grow for free.
      const std::uint64_t needed = count * std::max<std::uint64_t>(each, 1);
      if (needed > left()) {
        fail(kind, needed, count, each);
      } else {
        offset_ += static_cast<std::uint32_t>(count * each);
      }
    } else {
      // Each element takes at least 4 bytes (it holds a length): a lie fails after bytes/4.
      const T element{};
      for (std::uint64_t i = 0; i < count && !failed_; ++i) {
        setElement(static_cast<std::int64_t>(i));
        check(element);
      }
      if (!failed_) setElement(-1);
    }
  }

  const std::uint8_t* data_;
  std::uint32_t size_;
  std::uint32_t offset_ = 0;
  std::size_t depth_ = 0;
  Frame frames_[kMaxDepth];
  // The first failure, formatted only by reason().
  bool failed_ = false;
  Kind kind_ = Kind::kScalar;
  std::uint64_t needed_ = 0, count_ = 0, each_ = 0;
  std::uint32_t fail_offset_ = 0;
  std::size_t fail_depth_ = 0;
};

/**
 * Empty when the `size` serialized bytes at `data` hold a complete M whose every array and string
 * length fits in them (so roscpp's deserializer allocates at most in proportion to `size`);
 * otherwise the reason naming the field, e.g. "velocities: length 2147483648 x 4 bytes exceeds
 * the 0 bytes left (at byte 28 of a 28-byte jetbot_rl/WheelTargets)". Allocates nothing unless it
 * fails.
 */
template <class M>
std::string boundsViolation(const std::uint8_t* data, std::uint32_t size) {
  BoundsChecker checker(data, size);
  const M dummy{};
  checker.checkMessage(dummy);
  if (!checker.failed()) return std::string();
  return checker.reason(ros::message_traits::datatype<M>());
}

/// Deserializes `size` bytes at `data` into `msg` when boundsViolation() finds nothing and returns
/// an empty string; otherwise returns the reason and leaves `msg` unchanged.
template <class M>
std::string deserializeBounded(const std::uint8_t* data, std::uint32_t size, M& msg) {
  std::string reason = boundsViolation<M>(data, size);
  if (!reason.empty()) return reason;
  ros::serialization::IStream stream(const_cast<std::uint8_t*>(data), size);
  ros::serialization::deserialize(stream, msg);
  return reason;
}

}  // namespace jetbot_rl
