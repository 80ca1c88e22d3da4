#pragma once

#include <ros/advertise_service_options.h>
#include <ros/node_handle.h>
#include <ros/service_callback_helper.h>
#include <ros/service_client.h>
#include <ros/service_server.h>

#include <boost/function.hpp>
#include <boost/make_shared.hpp>
#include <string>

#include "jetbot_rl/ros/common/bounded_deserialization.h"
#include "jetbot_rl/ros/common/bounded_subscription.h"

namespace jetbot_rl {

/**
 * roscpp's service helper for Srv that checks the request bytes with boundsViolation() before
 * handing them to the generated helper (`inner`): a request whose lengths lie is answered with a
 * service error carrying the reason (clients see "service call failed" / "responded with an error:
 * <reason>"), and `on_refusal` is told; the callback never runs.
 */
template <class Srv>
class BoundedServiceHelper : public ros::ServiceCallbackHelper {
 public:
  BoundedServiceHelper(ros::ServiceCallbackHelperPtr inner, RefusalHandler on_refusal)
      : inner_(std::move(inner)), on_refusal_(std::move(on_refusal)) {}

  bool call(ros::ServiceCallbackHelperCallParams& params) override {
    const ros::SerializedMessage& req = params.request;
    const auto offset = static_cast<std::size_t>(req.message_start - req.buf.get());
    const std::string reason = boundsViolation<typename Srv::Request>(
        req.message_start, static_cast<std::uint32_t>(req.num_bytes - offset));
    if (reason.empty()) return inner_->call(params);
    if (on_refusal_) on_refusal_(reason);
    // roscpp writes params.response as it is when call() returns true; it starts with the ok
    // byte, here 0, followed by the error string. (Returning false would send an empty error
    // string; throwing would log an unthrottled ROS_ERROR per request.)
    params.response = ros::serialization::serializeServiceResponse(false, reason);
    return true;
  }

 private:
  ros::ServiceCallbackHelperPtr inner_;
  RefusalHandler on_refusal_;
};

/**
 * nh.advertiseService() for service type Srv through BoundedServiceHelper: `callback` gets only
 * requests whose array and string lengths fit in their bytes; `on_refusal` gets the reason for
 * each one answered with an error instead. Uses nh's callback queue.
 */
template <class Srv>
ros::ServiceServer advertiseServiceBounded(
    ros::NodeHandle& nh, const std::string& service,
    const boost::function<bool(typename Srv::Request&, typename Srv::Response&)>& callback,
    RefusalHandler on_refusal) {
  ros::AdvertiseServiceOptions ops;
  ops.template init<Srv>(service, callback);
  ops.helper = boost::make_shared<BoundedServiceHelper<Srv>>(ops.helper, std::move(on_refusal));
  return nh.advertiseService(ops);
}

/**
 * client.call(srv) whose response is checked with boundsViolation() before it is deserialised.
 * Returns false with `reason` set when the call fails (roscpp's own reason is logged by it) or the
 * response's lengths lie (srv.response unchanged).
 */
template <class Srv>
bool callBounded(ros::ServiceClient& client, Srv& srv, std::string& reason) {
  ros::SerializedMessage request = ros::serialization::serializeMessage(srv.request);
  ros::SerializedMessage response;
  if (!client.call(request, response, ros::service_traits::md5sum(srv))) {
    reason = "call of " + client.getService() + " failed";
    return false;
  }
  const auto offset = static_cast<std::size_t>(response.message_start - response.buf.get());
  const std::string violation =
      deserializeBounded(response.message_start,
                         static_cast<std::uint32_t>(response.num_bytes - offset), srv.response);
  if (violation.empty()) return true;
  reason = "response of " + client.getService() + " refused: " + violation;
  return false;
}

}  // namespace jetbot_rl
