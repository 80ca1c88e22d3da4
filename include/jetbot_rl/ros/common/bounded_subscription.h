#pragma once

#include <ros/node_handle.h>
#include <ros/subscribe_options.h>
#include <ros/subscriber.h>
#include <ros/subscription_callback_helper.h>
#include <ros/transport_hints.h>

#include <boost/function.hpp>
#include <boost/make_shared.hpp>
#include <functional>
#include <string>

#include "jetbot_rl/ros/common/bounded_deserialization.h"

namespace jetbot_rl {

/// Told the reason (boundsViolation()) when a message or request is refused unread.
using RefusalHandler = std::function<void(const std::string& reason)>;

/**
 * roscpp's subscription helper for M (the generated type, unchanged) that checks the received
 * bytes with boundsViolation() before deserialising: a message whose lengths lie is dropped (roscpp
 * skips a null message silently) and `on_refusal` is told why. Runs where roscpp deserialises: in
 * the subscription's callback queue, just before the callback would.
 */
template <class M>
class BoundedSubscriptionHelper
    : public ros::SubscriptionCallbackHelperT<const boost::shared_ptr<M const>&> {
 public:
  using Base = ros::SubscriptionCallbackHelperT<const boost::shared_ptr<M const>&>;

  BoundedSubscriptionHelper(const typename Base::Callback& callback, RefusalHandler on_refusal)
      : Base(callback, &create), on_refusal_(std::move(on_refusal)) {}

  ros::VoidConstPtr deserialize(
      const ros::SubscriptionCallbackHelperDeserializeParams& params) override {
    const std::string reason = boundsViolation<M>(params.buffer, params.length);
    if (!reason.empty()) {
      if (on_refusal_) on_refusal_(reason);
      return ros::VoidConstPtr();
    }
    return Base::deserialize(params);
  }

 private:
  // A function pointer rather than roscpp's empty DefaultMessageCreator functor: copying that one
  // into a boost::function trips GCC 12's -Wuninitialized.
  static boost::shared_ptr<M> create() { return boost::make_shared<M>(); }

  RefusalHandler on_refusal_;
};

/**
 * nh.subscribe() for message type M through BoundedSubscriptionHelper: `callback` gets only
 * messages whose array and string lengths fit in their bytes; `on_refusal` gets the reason for
 * each one dropped. Uses nh's callback queue. (roscpp shares one deserialisation per message
 * among the subscriptions of a process to a topic with the same type: subscribe to it only here.)
 */
template <class M>
ros::Subscriber subscribeBounded(
    ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue_size,
    const boost::function<void(const boost::shared_ptr<M const>&)>& callback,
    RefusalHandler on_refusal, const ros::TransportHints& hints = ros::TransportHints()) {
  ros::SubscribeOptions ops;
  ops.template init<M>(topic, queue_size, callback);
  ops.helper = boost::make_shared<BoundedSubscriptionHelper<M>>(callback, std::move(on_refusal));
  ops.transport_hints = hints;
  return nh.subscribe(ops);
}

}  // namespace jetbot_rl
