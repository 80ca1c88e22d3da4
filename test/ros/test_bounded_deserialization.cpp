// Bounded deserialisation without a master: every message the node and the learner receive
// passes and round-trips when valid, and is refused without allocating when an array or string
// length lies or the bytes end early; the subscription and service helpers drop / answer so.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Polygon.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <ros/serialization.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "jetbot_rl/EnvSpec.h"
#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/GetRandomization.h"
#include "jetbot_rl/Reset.h"
#include "jetbot_rl/SetCommand.h"
#include "jetbot_rl/Step.h"
#include "jetbot_rl/WheelTargets.h"
#include "jetbot_rl/ros/common/bounded_deserialization.h"
#include "jetbot_rl/ros/common/bounded_service.h"
#include "jetbot_rl/ros/common/bounded_subscription.h"

namespace jetbot_rl {
namespace {

using Bytes = std::vector<std::uint8_t>;

template <class M>
Bytes serialize(const M& msg) {
  Bytes bytes(ros::serialization::serializationLength(msg));
  ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::serialize(stream, msg);
  return bytes;
}

/// Peak resident set of this process [kB] (VmHWM).
long peakRssKb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      long kb = 0;
      status >> kb;
      return kb;
    }
    status.ignore(1 << 20, '\n');
  }
  return -1;
}

WheelTargets sampleTargets() {
  WheelTargets m;
  m.header.seq = 3;
  m.header.stamp = ros::Time(12, 345);
  m.header.frame_id = "base";
  m.step = 41;
  m.velocities = {1.0f, -2.0f, 3.5f, 4.0f};
  return m;
}

EnvStep sampleEnvStep() {
  EnvStep m;
  m.header.frame_id = "world";
  m.header.stamp = ros::Time(1, 2);
  m.step = 7;
  m.num_envs = 2;
  m.obs_dim = 3;
  m.observations = {1, 2, 3, 4, 5, 6};
  m.rewards = {0.5f, 0.25f};
  m.terminated = {0, 1};
  m.truncated = {1, 0};
  m.episode_steps = {10, 0};
  m.reset_env_ids = {1};
  m.final_observations = {7, 8, 9};
  return m;
}

/// One array or string field of a sample message: `grow` adds one element (or character).
template <class M>
struct Field {
  std::string name;            // as the reason must name it
  std::uint64_t element_size;  // the least an element takes [bytes]
  std::function<void(M&)> grow;
  bool walked = false;  // variable-size elements: the reason names the element that did not fit
};

/// The offset of a field's length: the first byte where the sample and the sample with the
/// field grown by one element differ (found independently of the checker).
template <class M>
std::size_t lengthOffset(const M& sample, const Field<M>& field) {
  M grown = sample;
  field.grow(grown);
  const Bytes a = serialize(sample), b = serialize(grown);
  std::size_t i = 0;
  while (i < a.size() && a[i] == b[i]) ++i;
  return i;
}

template <class M>
void expectValidPassesAndRoundTrips(const M& sample) {
  const Bytes bytes = serialize(sample);
  EXPECT_EQ(boundsViolation<M>(bytes.data(), bytes.size()), "");
  M out;
  EXPECT_EQ(deserializeBounded(bytes.data(), bytes.size(), out), "");
  EXPECT_EQ(serialize(out), bytes);
}

/// Every prefix of a valid message is refused; the whole one is not.
template <class M>
void expectTruncationsRefused(const M& sample) {
  const Bytes bytes = serialize(sample);
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    EXPECT_NE(boundsViolation<M>(bytes.data(), n), "") << "a prefix of " << n << " bytes";
  }
}

/// Every lying length of every field: 2^31, 2^32 - 1 and one element more than the bytes left.
template <class M>
void expectLyingLengthsRefused(const M& sample, const std::vector<Field<M>>& fields) {
  const Bytes bytes = serialize(sample);
  const long rss_before = peakRssKb();
  for (const Field<M>& field : fields) {
    const std::size_t offset = lengthOffset(sample, field);
    ASSERT_LE(offset + 4, bytes.size()) << field.name;
    const std::uint64_t left = bytes.size() - offset - 4;
    for (const std::uint64_t lie :
         {std::uint64_t{1} << 31, std::uint64_t{0xffffffff}, left / field.element_size + 1}) {
      Bytes hostile = bytes;
      const auto length = static_cast<std::uint32_t>(lie);
      std::memcpy(hostile.data() + offset, &length, 4);
      M out = sample;
      const std::string reason = deserializeBounded(hostile.data(), hostile.size(), out);
      if (field.walked) {
        EXPECT_EQ(reason.rfind(field.name + "[", 0), 0u)
            << "length " << lie << " of " << field.name << ": " << reason;
      } else {
        EXPECT_EQ(reason.rfind(field.name + ": ", 0), 0u)
            << "length " << lie << " of " << field.name << ": " << reason;
        EXPECT_NE(reason.find(std::to_string(lie)), std::string::npos) << reason;
      }
      EXPECT_NE(reason.find(ros::message_traits::datatype<M>()), std::string::npos) << reason;
      EXPECT_EQ(serialize(out), bytes) << "the message changed: " << field.name;
    }
  }
  // The generated deserializer alone would have resized to gigabytes (2^31 floats: 8 GB).
  EXPECT_LT(peakRssKb() - rss_before, 10 * 1024) << "peak resident set grew";
}

TEST(BoundedDeserialization, WheelTargets) {
  const WheelTargets sample = sampleTargets();
  expectValidPassesAndRoundTrips(sample);
  expectTruncationsRefused(sample);
  expectLyingLengthsRefused<WheelTargets>(
      sample, {{"header.frame_id", 1, [](WheelTargets& m) { m.header.frame_id += 'x'; }},
               {"velocities", 4, [](WheelTargets& m) { m.velocities.push_back(0); }}});
}

TEST(BoundedDeserialization, ReasonNamesFieldLengthBytesLeftAndType) {
  WheelTargets m;  // 30 bytes before the lie: the request
  Bytes bytes = serialize(m);
  const std::uint32_t lie = 1u << 31;
  std::memcpy(bytes.data() + bytes.size() - 4, &lie, 4);
  EXPECT_EQ(boundsViolation<WheelTargets>(bytes.data(), bytes.size()),
            "velocities: length 2147483648 x 4 bytes exceeds the 0 bytes left (at byte 28 of a "
            "28-byte jetbot_rl/WheelTargets)");
  EXPECT_EQ(boundsViolation<WheelTargets>(bytes.data(), 10),
            "header.stamp: needs 8 bytes, 6 left (at byte 4 of a 10-byte jetbot_rl/WheelTargets)");
}

TEST(BoundedDeserialization, StepRequest) {
  Step::Request sample;
  sample.actions = sampleTargets();
  expectValidPassesAndRoundTrips(sample);
  expectTruncationsRefused(sample);
  expectLyingLengthsRefused<Step::Request>(
      sample,
      {{"actions.header.frame_id", 1, [](Step::Request& m) { m.actions.header.frame_id += 'x'; }},
       {"actions.velocities", 4, [](Step::Request& m) { m.actions.velocities.push_back(0); }}});
}

TEST(BoundedDeserialization, ResetRequest) {
  Reset::Request sample;
  sample.env_ids = {0, 3, 5};
  sample.seed = -1;
  expectValidPassesAndRoundTrips(sample);
  expectTruncationsRefused(sample);
  expectLyingLengthsRefused<Reset::Request>(
      sample, {{"env_ids", 4, [](Reset::Request& m) { m.env_ids.push_back(9); }}});
}

TEST(BoundedDeserialization, GetRandomizationRequest) {
  GetRandomization::Request sample;
  sample.env_ids = {0, 3};
  expectValidPassesAndRoundTrips(sample);
  expectTruncationsRefused(sample);
  expectLyingLengthsRefused<GetRandomization::Request>(
      sample, {{"env_ids", 4, [](GetRandomization::Request& m) { m.env_ids.push_back(9); }}});
}

TEST(BoundedDeserialization, SetCommandRequestAndTwistHaveOnlyFixedFields) {
  SetCommand::Request command;
  command.env_id = 2;
  command.x = 1.0;
  command.y = -0.5;
  command.hold = true;
  expectValidPassesAndRoundTrips(command);
  expectTruncationsRefused(command);
  geometry_msgs::Twist twist;
  twist.linear.x = 0.3;
  twist.angular.z = -1.2;
  expectValidPassesAndRoundTrips(twist);
  expectTruncationsRefused(twist);
  geometry_msgs::TwistWithCovarianceStamped stamped;  // boost::array, nested header
  stamped.header.frame_id = "base_link";
  stamped.twist.covariance[35] = 2.0;
  expectValidPassesAndRoundTrips(stamped);
  expectTruncationsRefused(stamped);
}

TEST(BoundedDeserialization, EnvStep) {
  const EnvStep sample = sampleEnvStep();
  expectValidPassesAndRoundTrips(sample);
  expectTruncationsRefused(sample);
  expectLyingLengthsRefused<EnvStep>(
      sample, {{"header.frame_id", 1, [](EnvStep& m) { m.header.frame_id += 'x'; }},
               {"observations", 4, [](EnvStep& m) { m.observations.push_back(0); }},
               {"rewards", 4, [](EnvStep& m) { m.rewards.push_back(0); }},
               {"terminated", 1, [](EnvStep& m) { m.terminated.push_back(0); }},
               {"truncated", 1, [](EnvStep& m) { m.truncated.push_back(0); }},
               {"episode_steps", 4, [](EnvStep& m) { m.episode_steps.push_back(0); }},
               {"reset_env_ids", 4, [](EnvStep& m) { m.reset_env_ids.push_back(0); }},
               {"final_observations", 4, [](EnvStep& m) { m.final_observations.push_back(0); }}});
  Step::Response response;  // the learner reads the ~reset and ~step answers too
  response.success = true;
  response.message = "ok";
  response.state = sample;
  expectValidPassesAndRoundTrips(response);
  expectLyingLengthsRefused<Step::Response>(
      response,
      {{"message", 1, [](Step::Response& m) { m.message += 'x'; }},
       {"state.observations", 4, [](Step::Response& m) { m.state.observations.push_back(0); }}});
}

TEST(BoundedDeserialization, EnvSpecWalksStringArraysElementByElement) {
  EnvSpec sample;
  sample.num_envs = 2;
  sample.action_low = {-1, -1};
  sample.action_high = {1, 1};
  sample.task = "velocity";
  sample.observation_names = {"a", "bb", "ccc"};
  sample.action_names = {"left", "right"};
  expectValidPassesAndRoundTrips(sample);
  expectTruncationsRefused(sample);
  // A string[] element takes at least its 4-byte length: one more than left / 4 cannot fit.
  expectLyingLengthsRefused<EnvSpec>(
      sample,
      {{"action_low", 4, [](EnvSpec& m) { m.action_low.push_back(0); }},
       {"task", 1, [](EnvSpec& m) { m.task += 'x'; }},
       {"observation_names", 4, [](EnvSpec& m) { m.observation_names.emplace_back(); }, true},
       {"observation_names[1]", 1, [](EnvSpec& m) { m.observation_names[1] += 'x'; }},
       {"action_names", 4, [](EnvSpec& m) { m.action_names.emplace_back(); }, true}});
}

TEST(BoundedDeserialization, NestedMessageArraysAndConstants) {
  geometry_msgs::Polygon polygon;  // fixed-size message elements
  polygon.points.resize(3);
  polygon.points[2].z = 1.5f;
  expectValidPassesAndRoundTrips(polygon);
  expectLyingLengthsRefused<geometry_msgs::Polygon>(
      polygon, {{"points", 12, [](geometry_msgs::Polygon& m) { m.points.emplace_back(); }}});

  diagnostic_msgs::DiagnosticArray diag;  // variable-size elements; DiagnosticStatus has constants
  diag.status.resize(2);
  diag.status[1].name = "env";
  diag.status[1].values.resize(2);
  diag.status[1].values[1].key = "k";
  diag.status[1].values[1].value = "v";
  expectValidPassesAndRoundTrips(diag);
  expectTruncationsRefused(diag);
  using D = diagnostic_msgs::DiagnosticArray;
  expectLyingLengthsRefused<D>(
      diag, {{"status", 4, [](D& m) { m.status.emplace_back(); }, true},
             {"status[1].name", 1, [](D& m) { m.status[1].name += 'x'; }},
             {"status[1].values", 4, [](D& m) { m.status[1].values.emplace_back(); }, true},
             {"status[1].values[1].value", 1, [](D& m) { m.status[1].values[1].value += 'x'; }}});
}

TEST(BoundedSubscriptionHelper, DropsALyingMessageAndReportsWhyPassesAValidOne) {
  std::vector<std::string> refusals;
  int called = 0;
  BoundedSubscriptionHelper<WheelTargets> helper(
      [&](const WheelTargets::ConstPtr&) { ++called; },
      [&](const std::string& reason) { refusals.push_back(reason); });
  Bytes bytes = serialize(sampleTargets());
  ros::SubscriptionCallbackHelperDeserializeParams params;
  params.buffer = bytes.data();
  params.length = static_cast<std::uint32_t>(bytes.size());
  const ros::VoidConstPtr valid = helper.deserialize(params);
  ASSERT_TRUE(valid);
  EXPECT_EQ(static_cast<const WheelTargets*>(valid.get())->velocities, sampleTargets().velocities);
  EXPECT_TRUE(refusals.empty());

  const std::uint32_t lie = 0xffffffff;
  std::memcpy(bytes.data() + bytes.size() - 4 * 4 - 4, &lie, 4);
  EXPECT_FALSE(helper.deserialize(params));
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_EQ(refusals[0].rfind("velocities: length 4294967295 x 4 bytes exceeds", 0), 0u)
      << refusals[0];
  EXPECT_EQ(called, 0);
}

ros::SerializedMessage requestBytes(const Reset::Request& request) {
  // roscpp hands the service helper the bytes after the length prefix, in a buffer of their own
  const ros::SerializedMessage m = ros::serialization::serializeMessage(request);
  boost::shared_array<std::uint8_t> buf(new std::uint8_t[m.num_bytes - 4]);
  std::memcpy(buf.get(), m.message_start, m.num_bytes - 4);
  return ros::SerializedMessage(buf, m.num_bytes - 4);
}

TEST(BoundedServiceHelper, AnswersALyingRequestWithAnErrorAndNeverCallsTheCallback) {
  std::vector<std::string> refusals;
  std::vector<std::uint32_t> seen_ids;
  boost::function<bool(Reset::Request&, Reset::Response&)> callback = [&](Reset::Request& req,
                                                                          Reset::Response& res) {
    seen_ids = req.env_ids;
    res.success = true;
    return true;
  };
  BoundedServiceHelper<Reset> helper(
      boost::make_shared<
          ros::ServiceCallbackHelperT<ros::ServiceSpec<Reset::Request, Reset::Response>>>(callback),
      [&](const std::string& reason) { refusals.push_back(reason); });

  Reset::Request request;
  request.env_ids = {1, 2};
  ros::ServiceCallbackHelperCallParams params;
  params.request = requestBytes(request);
  ASSERT_TRUE(helper.call(params));
  EXPECT_EQ(seen_ids, request.env_ids);
  ASSERT_GE(params.response.num_bytes, 1u);
  EXPECT_EQ(params.response.buf[0], 1) << "ok byte of a valid call";

  seen_ids.clear();
  params = ros::ServiceCallbackHelperCallParams();
  params.request = requestBytes(request);
  const std::uint32_t lie = 1u << 31;
  std::memcpy(params.request.buf.get(), &lie, 4);  // env_ids' length
  ASSERT_TRUE(helper.call(params)) << "the helper answers the refusal itself";
  EXPECT_TRUE(seen_ids.empty()) << "the callback ran";
  ASSERT_EQ(refusals.size(), 1u);
  // The TCPROS error answer: ok byte 0, then the reason as a length-prefixed string.
  const ros::SerializedMessage& res = params.response;
  ASSERT_GE(res.num_bytes, 5u);
  EXPECT_EQ(res.buf[0], 0);
  std::uint32_t length;
  std::memcpy(&length, res.buf.get() + 1, 4);
  ASSERT_EQ(length + 5, res.num_bytes);
  const std::string error(reinterpret_cast<const char*>(res.buf.get()) + 5, length);
  EXPECT_EQ(error, refusals[0]);
  EXPECT_EQ(error.rfind("env_ids: length 2147483648 x 4 bytes exceeds the 20 bytes left", 0), 0u)
      << error;
}

}  // namespace
}  // namespace jetbot_rl
