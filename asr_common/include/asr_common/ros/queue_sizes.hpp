#pragma once

#include <cstdint>

// The queue sizes of the suite's topics, by what the messages are for, so that every node sizes
// the same kind of topic alike.
namespace asr_common::ros_interface {

/// Where every message counts (recording or replaying a demonstration): a slow subscriber gets
/// every set rather than the latest only.
constexpr std::uint32_t kEveryMessageQueue = 1000;

/// Object estimates into a node that keeps the latest per object: a burst from several
/// detectors is buffered, not dropped.
constexpr std::uint32_t kEstimateQueue = 100;

/// Results published as a stream (scene instances, predicted poses): old ones lose their worth.
constexpr std::uint32_t kResultQueue = 10;

/// Latched state (markers, counters): only the latest matters.
constexpr std::uint32_t kLatchedQueue = 1;

}  // namespace asr_common::ros_interface
