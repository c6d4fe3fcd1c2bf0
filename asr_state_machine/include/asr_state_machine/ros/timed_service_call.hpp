#pragma once

#include <ros/ros.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "asr_state_machine/parts.hpp"

namespace asr_state_machine::ros_interface {

/// Which node a part talks to, how long (wall seconds) it may take to answer.
struct PartEndpoint {
  std::string node;       // named in a PartFailure, e.g. "next_best_view"
  double timeout = 60.0;  // wall seconds; a hang guard, not a deadline of the search
};

/// How often a call that ends without an answer is made before it is a PartFailure. On a loaded
/// machine one call now and then fails though the node is fine (the master's lookup or the new
/// connection fails; a demo search was aborted so once). The suite's nodes answer bad input in
/// the response; only the detectors refuse a request (types they do not know), which a second
/// attempt refuses again at once, so trying again costs nothing where the node means it.
constexpr int kServiceCallAttempts = 3;

namespace detail {

enum class CallOutcome { kAnswered, kFailed, kTimedOut };

/// One call of service `name`, waiting at most `timeout` wall seconds. roscpp's call() has no
/// timeout and blocks for as long as a node stalls, so it runs in a thread of its own that is
/// left behind if the node never answers. `service` is written only if the node answered.
template <typename Service>
CallOutcome callOnce(const std::string& name, Service& service, double timeout) {
  struct Call {
    std::mutex mutex;
    std::condition_variable done_changed;
    bool done = false;
    bool answered = false;
    Service service;
  };
  auto call = std::make_shared<Call>();
  call->service = service;
  std::thread([call, name] {
    ros::ServiceClient client = ros::NodeHandle().serviceClient<Service>(name);
    const bool answered = client.call(call->service);
    std::lock_guard<std::mutex> lock(call->mutex);
    call->answered = answered;
    call->done = true;
    call->done_changed.notify_all();
  }).detach();
  std::unique_lock<std::mutex> lock(call->mutex);
  if (!call->done_changed.wait_for(lock, std::chrono::duration<double>(std::max(0.0, timeout)),
                                   [&] { return call->done; }))
    return CallOutcome::kTimedOut;
  if (!call->answered)
    return CallOutcome::kFailed;
  service = call->service;
  return CallOutcome::kAnswered;
}

}  // namespace detail

/// Calls service `name` of `part` and waits at most part.timeout wall seconds in all for the
/// answer; a call that fails while the service is still offered is made again, up to
/// kServiceCallAttempts times. Throws PartFailure naming the node if no call answers in time,
/// the service is gone or every attempt failed.
template <typename Service>
void callService(const PartEndpoint& part, const std::string& name, Service& service) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(part.timeout);
  for (int attempt = 1;; ++attempt) {
    const double left =
        std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    const detail::CallOutcome outcome = detail::callOnce(name, service, left);
    if (outcome == detail::CallOutcome::kAnswered)
      return;
    if (outcome == detail::CallOutcome::kTimedOut) {
      throw PartFailure(part.node, "service " + name + " did not answer within " +
                                       std::to_string(static_cast<int>(part.timeout)) +
                                       " s (wall clock)");
    }
    if (!ros::service::exists(ros::NodeHandle().resolveName(name), false))
      throw PartFailure(part.node, "service " + name + " is gone (node down?)");
    if (attempt == kServiceCallAttempts) {
      throw PartFailure(part.node, "service " + name + " failed " + std::to_string(attempt) +
                                       " times (the node refused the request, or the connection "
                                       "to it broke)");
    }
    ROS_WARN("%s: service %s failed (attempt %d of %d); calling it again", part.node.c_str(),
             name.c_str(), attempt, kServiceCallAttempts);
    ros::WallDuration(0.1 * attempt).sleep();
  }
}

}  // namespace asr_state_machine::ros_interface
