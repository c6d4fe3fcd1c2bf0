#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_ism/background_worker.hpp"
#include "asr_ism_tree/scene_instance.hpp"
#include "asr_ism_tree/scene_models.hpp"

namespace asr_ism_tree {

/// How ContinuousRecognition shares the cores among scenes.
struct ContinuousPace {
  /// Recognitions that are not quick running at once; 0: one per hardware thread.
  unsigned slow_at_once = 0;
  /// How often offer() is called (seconds; the node: its period). A scene whose last
  /// recognition took less than its share of it (the period over the number of scenes; CPU time
  /// of the scene's thread) is quick: the quick ones together keep at most about one core busy.
  /// 0: none is quick.
  double period_seconds = 0.0;
};

/// Recognition of the configurations a robot sees one after another, each scene at its own
/// pace (the scene_recognizer's continuous mode). Scenes take very different times: one seen
/// well a few milliseconds, one seen badly as long as its searches' limits allow (a second and
/// more). Each scene is therefore recognised on a thread of its own (asr_ism::BackgroundWorker),
/// anew only where the estimates of its objects' types changed since its last recognition
/// started, and none waits for another: a scene whose last recognition was quick starts again
/// whenever its estimates change, so it follows them every period; the slow ones share a few
/// slots (one per core), the one whose result is oldest first, so the quick ones cannot starve
/// them and they cannot hold each other up for longer than a round. A scene's latest result
/// stands, with the time of the estimates it came from, until its next one is done. Each result
/// is what SceneModels recognises for that scene in those estimates, bit for bit.
class ContinuousRecognition {
 public:
  /// One scene's latest result.
  struct SceneResult {
    std::vector<SceneInstance> instances;  // as the scene's tree ranks them
    /// The estimates recognised: the instances' `estimate` indices refer to them.
    std::shared_ptr<const asr_common::Configuration> configuration;
    /// The time of the estimates (the caller's units: the node gives nanoseconds), as offered
    /// with them or with a later offer whose estimates of the scene's types were the same (the
    /// answer is the same for those).
    std::uint64_t stamp = 0;
  };
  struct Latest {
    /// Per scene of the models last offered (their order), its latest result; none before its
    /// first recognition is done.
    std::vector<std::optional<SceneResult>> scenes;
    /// Results done since the last call of latest().
    std::size_t fresh = 0;
  };

  /// `on_error` gets, on the scene's thread, what a recognition threw; that scene then has no
  /// result until a later one succeeds.
  explicit ContinuousRecognition(std::function<void(std::exception_ptr)> on_error,
                                 ContinuousPace pace = {});
  /// Waits for the recognitions running.
  ~ContinuousRecognition();
  ContinuousRecognition(const ContinuousRecognition&) = delete;
  ContinuousRecognition& operator=(const ContinuousRecognition&) = delete;

  /// Starts recognising, each on its thread, the scenes whose estimates differ from those their
  /// last recognition started with, whose thread is free and that are quick or find a slot;
  /// the others are started at a later offer. Returns without waiting; call it from one thread
  /// at a time (a node's timer). Throws InputError where recognition refuses the
  /// configuration (more than `max_estimates` estimates, an invalid pose), and keeps no result
  /// then. New models drop every result; recognitions running with the old ones are discarded.
  void offer(const std::shared_ptr<const SceneModels>& models,
             const std::shared_ptr<const asr_common::Configuration>& configuration,
             std::uint64_t stamp);

  /// Each scene's latest result, and how many were done since the last call.
  Latest latest();

  /// Whether every scene has a result of the estimates last offered, and nothing runs.
  bool settled() const;
  /// Blocks until no recognition runs.
  void waitUntilIdle();

 private:
  struct SceneState {
    bool started = false;                 // since the models were set or the last refusal
    asr_common::Configuration estimates;  // the ones its last recognition started with
    bool behind = false;  // the last offer's estimates differ and have not been started
    std::optional<SceneResult> result;
    double last_seconds = std::numeric_limits<double>::infinity();  // CPU; unknown: slow
  };
  struct Start {
    std::size_t scene;
    asr_common::Configuration estimates;
    bool in_slot;  // not quick
  };
  void dropEverything();
  static void refuseAsRecognitionWould(const SceneModels& models,
                                       const asr_common::Configuration& configuration);
  std::vector<Start> scenesToStart(const asr_common::Configuration& configuration,
                                   std::uint64_t stamp);
  void startScene(Start& start,
                  const std::shared_ptr<const asr_common::Configuration>& configuration,
                  std::uint64_t stamp);
  void recognizeScene(std::size_t scene, bool in_slot, std::uint64_t generation,
                      const std::shared_ptr<const SceneModels>& models,
                      const std::shared_ptr<const asr_common::Configuration>& configuration,
                      std::uint64_t stamp);

  const std::function<void(std::exception_ptr)> on_error_;
  const unsigned slots_;
  const double period_seconds_;
  mutable std::mutex mutex_;  // everything below
  std::shared_ptr<const SceneModels> models_;
  std::uint64_t generation_ = 0;  // raised where results are dropped: late ones are discarded
  std::vector<SceneState> scenes_;
  std::size_t fresh_ = 0;
  unsigned slots_used_ = 0;  // by recognitions running, whatever their generation
  // Per scene, grown with the most scenes offered; only offer() starts them. Last: destroyed
  // first, so a running recognition ends while what it uses still exists.
  std::vector<std::unique_ptr<asr_ism::BackgroundWorker>> workers_;
};

}  // namespace asr_ism_tree
