#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace jetbot_rl {

/**
 * Each subscriber connection's queue of some topics, bounded here instead of in roscpp, so that
 * every message dropped from it is counted (docs/reliability.md, "Counted losses").
 *
 * roscpp keeps a publisher's `queue_size` per connection by dropping the oldest message without
 * a count, a log line or any API that shows it (issue 49). A topic added here is advertised with
 * queue_size 0 (roscpp keeps everything) and trim() drops the oldest messages beyond
 * `max_messages` of each network connection (TCPROS and UDPROS) as roscpp would, counting them
 * per topic. The node calls trim() after every batch of publications, so a connection holds at
 * most one batch more than its bound. In-process subscribers (nodelets) get every message into
 * their own subscription queue, whose size they chose.
 */
class CountedSubscriberQueues {
 public:
  /// Messages dropped on one topic.
  struct TopicCount {
    std::string topic;
    std::uint64_t dropped = 0;
    std::string last_subscriber;  ///< caller id of the last connection that lost one
  };

  CountedSubscriberQueues();
  ~CountedSubscriberQueues();
  CountedSubscriberQueues(const CountedSubscriberQueues&) = delete;
  CountedSubscriberQueues& operator=(const CountedSubscriberQueues&) = delete;

  /// Bounds the connections of `topic` (resolved; advertised by this process with queue_size 0)
  /// to `max_messages` (>= 1, else std::invalid_argument) each. Returns false, adding nothing,
  /// when this process advertised `topic` earlier with another queue_size (a nodelet beside us:
  /// roscpp keeps that one's queue, and its drops stay uncounted).
  bool add(const std::string& topic, std::size_t max_messages);
  /// add() for `pub`'s topic.
  bool add(const ros::Publisher& pub, std::size_t max_messages);
  /// add() for `base` and every topic below it that this process advertises with queue_size 0
  /// (an image_transport publisher's plugins: base/compressed, ...). Returns the topics added.
  std::vector<std::string> addWithSubtopics(const std::string& base, std::size_t max_messages);
  /// Drops the oldest queued messages beyond each connection's bound; returns the topics that
  /// lost messages in this call, with this call's counts.
  std::vector<TopicCount> trim();
  /// Every topic added, with its count since start-up, in the order added.
  std::vector<TopicCount> counts() const;
  /// All topics' dropped messages since start-up.
  std::uint64_t total() const;

 private:
  struct Topic;
  mutable std::mutex mutex_;
  std::vector<std::unique_ptr<Topic>> topics_;
};

/// Says (WARN) that `topic` keeps roscpp's queue, when CountedSubscriberQueues::add refused it.
void warnUncounted(const std::string& topic);

/// Advertises `topic` of `M` under `nh` with queue_size 0 and bounds it in `queues` to
/// `max_messages` per connection.
template <typename M>
ros::Publisher advertiseCounted(ros::NodeHandle& nh, const std::string& topic,
                                std::size_t max_messages, CountedSubscriberQueues& queues,
                                bool latch = false) {
  ros::Publisher pub = nh.advertise<M>(topic, 0, latch);
  if (!queues.add(pub, max_messages)) warnUncounted(pub.getTopic());
  return pub;
}

}  // namespace jetbot_rl
