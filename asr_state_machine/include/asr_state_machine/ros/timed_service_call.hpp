#pragma once

#include <ros/ros.h>

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

/// Calls service `name` of `part` and waits at most part.timeout wall seconds for the answer.
/// roscpp's call() has no timeout and blocks for as long as a node stalls, so the call runs in a
/// thread of its own that is left behind if the node never answers. Throws PartFailure naming
/// the node if the call does not answer in time, the service is gone or the node refused.
template <typename Service>
void callService(const PartEndpoint& part, const std::string& name, Service& service) {
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
  if (!call->done_changed.wait_for(lock, std::chrono::duration<double>(part.timeout),
                                   [&] { return call->done; })) {
    throw PartFailure(part.node, "service " + name + " did not answer within " +
                                     std::to_string(static_cast<int>(part.timeout)) +
                                     " s (wall clock)");
  }
  if (!call->answered) {
    const bool exists = ros::service::exists(ros::NodeHandle().resolveName(name), false);
    throw PartFailure(
        part.node, "service " + name + (exists ? " refused the request" : " is gone (node down?)"));
  }
  service = call->service;
}

}  // namespace asr_state_machine::ros_interface
