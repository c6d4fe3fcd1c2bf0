#include "asr_ism_tree/continuous_recognition.hpp"

#include <algorithm>
#include <ctime>
#include <limits>
#include <string>
#include <thread>
#include <tuple>
#include <utility>

#include "asr_common/input_error.hpp"
#include "matchable_estimates.hpp"

namespace asr_ism_tree {
namespace {

// The CPU time of the calling thread: what a recognition costs, which the load of other threads
// sharing the cores does not inflate as it does the wall time.
double threadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

ContinuousRecognition::ContinuousRecognition(std::function<void(std::exception_ptr)> on_error,
                                             ContinuousPace pace)
    : on_error_(std::move(on_error)),
      slots_(pace.slow_at_once > 0 ? pace.slow_at_once
                                   : std::max(1U, std::thread::hardware_concurrency())),
      period_seconds_(pace.period_seconds) {}

ContinuousRecognition::~ContinuousRecognition() {
  waitUntilIdle();
}

void ContinuousRecognition::dropEverything() {
  ++generation_;
  for (SceneState& state : scenes_)
    state = SceneState{};
  fresh_ = 0;
}

void ContinuousRecognition::offer(
    const std::shared_ptr<const SceneModels>& models,
    const std::shared_ptr<const asr_common::Configuration>& configuration, std::uint64_t stamp) {
  std::vector<Start> starts;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (models != models_) {
      dropEverything();
      models_ = models;
      scenes_.assign(models->scenes().size(), SceneState{});
    }
    try {
      refuseAsRecognitionWould(*models, *configuration);
    } catch (...) {
      dropEverything();
      throw;
    }
    while (workers_.size() < scenes_.size())
      workers_.push_back(std::make_unique<asr_ism::BackgroundWorker>(on_error_));
    starts = scenesToStart(*configuration, stamp);
  }
  for (Start& start : starts)
    startScene(start, configuration, stamp);
}

void ContinuousRecognition::refuseAsRecognitionWould(
    const SceneModels& models, const asr_common::Configuration& configuration) {
  // Every scene's recognition runs into too many estimates, whatever it can match.
  const std::size_t limit = models.parameters().max_estimates;
  if (configuration.size() > limit) {
    throw asr_common::InputError("continuous recognition: " + std::to_string(configuration.size()) +
                                 " object estimates, more than the configured maximum of " +
                                 std::to_string(limit) + " per recognition");
  }
  asr_common::validatedPoses(configuration);
}

// Under the lock. Marks the scenes behind; of those whose thread is free, every quick one and,
// while slots are free, the slow ones whose results are oldest (none yet: first).
std::vector<ContinuousRecognition::Start> ContinuousRecognition::scenesToStart(
    const asr_common::Configuration& configuration, std::uint64_t stamp) {
  std::vector<Start> candidates;
  for (std::size_t scene = 0; scene < scenes_.size(); ++scene) {
    SceneState& state = scenes_[scene];
    asr_common::Configuration estimates = matchableEstimates(models_->tree(scene), configuration);
    const bool running = workers_[scene]->busy();
    state.behind = !state.started || !sameEstimates(estimates, state.estimates);
    if (!state.behind) {
      if (state.result && !running)
        state.result->stamp = stamp;  // still the answer for the estimates as of now
      continue;
    }
    const bool quick = state.last_seconds * static_cast<double>(scenes_.size()) < period_seconds_;
    if (!running)
      candidates.push_back({scene, std::move(estimates), !quick});
  }
  const auto age = [&](const Start& start) {
    const auto& result = scenes_[start.scene].result;
    return std::make_tuple(result.has_value(), result ? result->stamp : 0, start.scene);
  };
  std::sort(candidates.begin(), candidates.end(),
            [&](const Start& a, const Start& b) { return age(a) < age(b); });
  std::vector<Start> starts;
  for (Start& candidate : candidates) {
    if (candidate.in_slot && slots_used_ >= slots_)
      continue;
    slots_used_ += candidate.in_slot ? 1 : 0;
    starts.push_back(std::move(candidate));
  }
  return starts;
}

// Outside the lock: where the worker has no thread of its own the recognition runs right here.
void ContinuousRecognition::startScene(
    Start& start, const std::shared_ptr<const asr_common::Configuration>& configuration,
    std::uint64_t stamp) {
  std::uint64_t generation;
  std::shared_ptr<const SceneModels> models;
  asr_ism::BackgroundWorker* worker;
  SceneState before;
  {
    // Marked started first: a recognition that fails at once marks it not started again.
    std::lock_guard<std::mutex> lock(mutex_);
    generation = generation_;
    models = models_;
    worker = workers_[start.scene].get();
    SceneState& state = scenes_[start.scene];
    before = state;
    state.started = true;
    state.estimates = std::move(start.estimates);
    state.behind = false;
  }
  const std::size_t scene = start.scene;
  const bool in_slot = start.in_slot;
  if (worker->tryStart([this, scene, in_slot, generation, models, configuration, stamp] {
        recognizeScene(scene, in_slot, generation, models, configuration, stamp);
      }))
    return;
  // Only offer() starts recognitions, and it saw the thread free: this cannot happen, but
  // leaves nothing inconsistent if it does.
  std::lock_guard<std::mutex> lock(mutex_);
  slots_used_ -= in_slot ? 1 : 0;
  if (generation == generation_) {
    SceneState& state = scenes_[scene];
    state.started = before.started;
    state.estimates = std::move(before.estimates);
    state.behind = true;
  }
}

// On the scene's thread.
void ContinuousRecognition::recognizeScene(
    std::size_t scene, bool in_slot, std::uint64_t generation,
    const std::shared_ptr<const SceneModels>& models,
    const std::shared_ptr<const asr_common::Configuration>& configuration, std::uint64_t stamp) {
  const double begin = threadCpuSeconds();
  std::vector<SceneInstance> instances;
  std::exception_ptr error;
  try {
    instances = std::move(models->recognizeEach({scene}, *configuration).front());
  } catch (...) {
    error = std::current_exception();
  }
  const double seconds = threadCpuSeconds() - begin;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    slots_used_ -= in_slot ? 1 : 0;
    if (generation == generation_) {
      SceneState& state = scenes_[scene];
      state.last_seconds = seconds;
      if (error) {
        state.result.reset();
        state.started = false;  // tried again at the next offer
      } else {
        state.result = SceneResult{std::move(instances), configuration, stamp};
        ++fresh_;
      }
    }
  }
  if (error)
    std::rethrow_exception(error);  // to on_error_
}

ContinuousRecognition::Latest ContinuousRecognition::latest() {
  std::lock_guard<std::mutex> lock(mutex_);
  Latest latest;
  latest.scenes.reserve(scenes_.size());
  for (const SceneState& state : scenes_)
    latest.scenes.push_back(state.result);
  latest.fresh = fresh_;
  fresh_ = 0;
  return latest;
}

bool ContinuousRecognition::settled() const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (std::size_t scene = 0; scene < scenes_.size(); ++scene) {
    const SceneState& state = scenes_[scene];
    if (state.behind || !state.started || !state.result || workers_[scene]->busy())
      return false;
  }
  return true;
}

void ContinuousRecognition::waitUntilIdle() {
  std::vector<asr_ism::BackgroundWorker*> workers;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& worker : workers_)
      workers.push_back(worker.get());
  }
  // Outside the lock: a recognition ending takes it to store its result.
  for (asr_ism::BackgroundWorker* worker : workers)
    worker->waitUntilIdle();
}

}  // namespace asr_ism_tree
