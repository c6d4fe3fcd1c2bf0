#pragma once

#include <vector>

#include "asr_ism/demonstration.hpp"
#include "asr_ism_tree/ism_tree.hpp"
#include "asr_ism_tree/relation_topology.hpp"
#include "asr_ism_tree/scene_instance.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "benchmark_settings.hpp"

namespace asr_ism_tree::bench {

struct LearnedTree {
  IsmTree tree;
  /// Fastest of the repetitions of tree generation plus storing the tree in a fresh SQLite file.
  double learn_ms = 0.0;
};

/// Learns the tree of `demonstration` over `topology` (default parameters) and stores it in a
/// fresh temporary file, which is deleted afterwards; repeated as the settings say.
LearnedTree learnAndStore(const asr_ism::Demonstration& demonstration,
                          const RelationTopology& topology, const BenchmarkSettings& settings);

struct RecognitionTiming {
  /// Per configuration, the fastest of the passes, in milliseconds.
  std::vector<double> milliseconds;
  /// Per configuration, the confidence of the best instance (0 if none).
  std::vector<double> best_confidence;
  int passes = 0;
};

/// Recognises every configuration, in passes, as the settings say.
RecognitionTiming timeRecognition(const TreeRecognizer& recognizer,
                                  const std::vector<asr_common::Configuration>& configurations,
                                  const BenchmarkSettings& settings);

/// Confidence of the best instance, 0 if there is none.
double bestConfidence(const std::vector<SceneInstance>& instances);

/// Share of the confidences that are >= 0.99, the threshold for "recognised".
double recognisedFraction(const std::vector<double>& confidences);

/// Mean over the sampled configurations and over every object in them of the best confidence
/// with that object left out.
double meanConfidenceWithOneLeftOut(const TreeRecognizer& recognizer,
                                    const std::vector<asr_common::Configuration>& configurations);

}  // namespace asr_ism_tree::bench
