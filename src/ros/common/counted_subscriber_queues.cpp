#include "jetbot_rl/ros/common/counted_subscriber_queues.h"

#include <ros/console.h>
#include <ros/publication.h>
#include <ros/topic_manager.h>
#include <ros/transport_subscriber_link.h>

#include <boost/thread/mutex.hpp>
#include <queue>
#include <stdexcept>

namespace jetbot_rl {
namespace {

// roscpp has no API to a publication's subscriber connections or to a connection's queue. The
// standard lets an explicit template instantiation name private members (C++17 [temp.spec]/6),
// which hands us pointers to them; the types are checked against Debian's roscpp headers at
// compile time, so a roscpp that changes them fails to build rather than misbehaving.
template <typename Tag, typename Tag::type Member>
struct PrivateMember {
  friend typename Tag::type get(Tag) { return Member; }
};

struct PublicationLinks {
  using type = ros::V_SubscriberLink ros::Publication::*;
  friend type get(PublicationLinks);
};
struct PublicationLinksMutex {
  using type = boost::mutex ros::Publication::*;
  friend type get(PublicationLinksMutex);
};
struct LinkOutbox {
  using type = std::queue<ros::SerializedMessage> ros::TransportSubscriberLink::*;
  friend type get(LinkOutbox);
};
struct LinkOutboxMutex {
  using type = boost::mutex ros::TransportSubscriberLink::*;
  friend type get(LinkOutboxMutex);
};

template struct PrivateMember<PublicationLinks, &ros::Publication::subscriber_links_>;
template struct PrivateMember<PublicationLinksMutex, &ros::Publication::subscriber_links_mutex_>;
template struct PrivateMember<LinkOutbox, &ros::TransportSubscriberLink::outbox_>;
template struct PrivateMember<LinkOutboxMutex, &ros::TransportSubscriberLink::outbox_mutex_>;

/// The publication's network connections (not the in-process ones), copied under its lock.
std::vector<boost::shared_ptr<ros::TransportSubscriberLink>> networkLinks(ros::Publication& p) {
  std::vector<boost::shared_ptr<ros::TransportSubscriberLink>> links;
  boost::mutex::scoped_lock lock(p.*get(PublicationLinksMutex{}));
  for (const ros::SubscriberLinkPtr& link : p.*get(PublicationLinks{})) {
    if (auto transport = boost::dynamic_pointer_cast<ros::TransportSubscriberLink>(link)) {
      links.push_back(std::move(transport));
    }
  }
  return links;
}

}  // namespace

struct CountedSubscriberQueues::Topic {
  std::string name;
  std::size_t max_messages = 0;
  boost::weak_ptr<ros::Publication> publication;  // roscpp's; gone after ros::shutdown()
  TopicCount count;
};

CountedSubscriberQueues::CountedSubscriberQueues() = default;
CountedSubscriberQueues::~CountedSubscriberQueues() = default;

bool CountedSubscriberQueues::add(const std::string& topic, std::size_t max_messages) {
  if (max_messages < 1) {
    throw std::invalid_argument("CountedSubscriberQueues: max_messages of " + topic +
                                " must be >= 1");
  }
  const ros::PublicationPtr publication = ros::TopicManager::instance()->lookupPublication(topic);
  if (!publication) {
    throw std::invalid_argument("CountedSubscriberQueues: " + topic +
                                " is not advertised by this process");
  }
  if (publication->getMaxQueue() != 0) return false;
  auto entry = std::make_unique<Topic>();
  entry->name = topic;
  entry->max_messages = max_messages;
  entry->publication = publication;
  entry->count.topic = topic;
  std::lock_guard<std::mutex> lock(mutex_);
  topics_.push_back(std::move(entry));
  return true;
}

bool CountedSubscriberQueues::add(const ros::Publisher& pub, std::size_t max_messages) {
  return add(pub.getTopic(), max_messages);
}

std::vector<std::string> CountedSubscriberQueues::addWithSubtopics(const std::string& base,
                                                                   std::size_t max_messages) {
  ros::V_string advertised;
  ros::TopicManager::instance()->getAdvertisedTopics(advertised);
  std::vector<std::string> added;
  for (const std::string& topic : advertised) {
    if (topic != base && topic.rfind(base + "/", 0) != 0) continue;
    if (add(topic, max_messages)) added.push_back(topic);
  }
  return added;
}

void warnUncounted(const std::string& topic) {
  ROS_WARN(
      "%s was advertised in this process before, with a queue_size other than 0: roscpp keeps "
      "that queue, and what it drops there is not counted",
      topic.c_str());
}

std::vector<CountedSubscriberQueues::TopicCount> CountedSubscriberQueues::trim() {
  std::vector<TopicCount> dropped_now;
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& topic : topics_) {
    const ros::PublicationPtr publication = topic->publication.lock();
    if (!publication) continue;
    TopicCount now{topic->name, 0, ""};
    for (const auto& link : networkLinks(*publication)) {
      std::uint64_t dropped = 0;
      {
        boost::mutex::scoped_lock outbox_lock((*link).*get(LinkOutboxMutex{}));
        std::queue<ros::SerializedMessage>& outbox = (*link).*get(LinkOutbox{});
        while (outbox.size() > topic->max_messages) {
          outbox.pop();  // the oldest not yet being written, as roscpp drops
          ++dropped;
        }
      }
      if (dropped == 0) continue;
      now.dropped += dropped;
      now.last_subscriber = link->getDestinationCallerID();
    }
    if (now.dropped == 0) continue;
    topic->count.dropped += now.dropped;
    topic->count.last_subscriber = now.last_subscriber;
    dropped_now.push_back(std::move(now));
  }
  return dropped_now;
}

std::vector<CountedSubscriberQueues::TopicCount> CountedSubscriberQueues::counts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<TopicCount> counts;
  for (const auto& topic : topics_) counts.push_back(topic->count);
  return counts;
}

std::uint64_t CountedSubscriberQueues::total() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::uint64_t sum = 0;
  for (const auto& topic : topics_) sum += topic->count.dropped;
  return sum;
}

}  // namespace jetbot_rl
