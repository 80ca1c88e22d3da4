#include "jetbot_rl/ros/common/bounded_deserialization.h"

#include <sstream>

namespace jetbot_rl {

std::vector<std::string> BoundsChecker::parseFieldNames(const char* definition) {
  // The message's own section of the definition text ends at the first "===" line (the nested
  // types' sections follow); a field line is "type name", a constant "type NAME=value".
  std::vector<std::string> names;
  std::istringstream in(definition ? definition : "");
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, 3, "===") == 0) break;
    const std::size_t comment = line.find('#');
    if (comment != std::string::npos) line.erase(comment);
    if (line.find('=') != std::string::npos) continue;  // a constant
    std::istringstream fields(line);
    std::string type, name;
    if (fields >> type >> name) names.push_back(name);
  }
  return names;
}

void BoundsChecker::fail(Kind kind, std::uint64_t needed, std::uint64_t count, std::uint64_t each) {
  if (failed_) return;
  failed_ = true;
  kind_ = kind;
  needed_ = needed;
  count_ = count;
  each_ = each;
  fail_offset_ = offset_;
  fail_depth_ = depth_;
}

std::string BoundsChecker::reason(const std::string& type) const {
  if (!failed_) return std::string();
  std::ostringstream out;
  const std::size_t named = std::min(fail_depth_, kMaxDepth);
  for (std::size_t d = 0; d < named; ++d) {
    const Frame& frame = frames_[d];
    const std::vector<std::string>& names = frame.names();
    if (d > 0) out << '.';
    if (frame.field_now < names.size()) {
      out << names[frame.field_now];
    } else {
      out << "field " << frame.field_now;
    }
    if (frame.element >= 0) out << '[' << frame.element << ']';
  }
  if (fail_depth_ > kMaxDepth) out << ". ...";
  out << ": ";
  const std::uint32_t left = size_ - fail_offset_;
  switch (kind_) {
    case Kind::kScalar:
      out << "needs " << needed_ << " bytes, " << left << " left";
      break;
    case Kind::kLength:
      out << "its length needs 4 bytes, " << left << " left";
      break;
    case Kind::kString:
      out << "string length " << needed_ << " exceeds the " << left << " bytes left";
      break;
    case Kind::kArray:
      out << "length " << count_ << " x " << each_ << " bytes exceeds the " << left
          << " bytes left";
      break;
    case Kind::kFixedArray:
      out << count_ << " x " << each_ << " bytes exceed the " << left << " bytes left";
      break;
  }
  out << " (at byte " << fail_offset_ << " of a " << size_ << "-byte " << type << ")";
  return out.str();
}

}  // namespace jetbot_rl
