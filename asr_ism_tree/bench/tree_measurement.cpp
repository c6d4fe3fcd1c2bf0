#include "tree_measurement.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>

#include "asr_common/cli/timing.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_generation.hpp"

namespace asr_ism_tree::bench {

using asr_common::cli::millisecondsOf;
namespace {

constexpr double kRecognisedConfidence = 0.99;

// A path for a model file that does not exist yet; removed, with SQLite's side files, on exit.
class TemporaryModelFile {
 public:
  TemporaryModelFile() {
    static int counter = 0;
    path_ = (std::filesystem::temp_directory_path() / ("asr_bench_" + std::to_string(::getpid()) +
                                                       "_" + std::to_string(counter++) + ".sqlite"))
                .string();
    remove();
  }
  ~TemporaryModelFile() { remove(); }
  TemporaryModelFile(const TemporaryModelFile&) = delete;
  TemporaryModelFile& operator=(const TemporaryModelFile&) = delete;

  const std::string& path() const { return path_; }

 private:
  void remove() const {
    std::error_code ignored;
    for (const char* suffix : {"", "-journal", "-wal", "-shm"})
      std::filesystem::remove(path_ + suffix, ignored);
  }

  std::string path_;
};

}  // namespace

LearnedTree learnAndStore(const asr_ism::Demonstration& demonstration,
                          const RelationTopology& topology, const BenchmarkSettings& settings) {
  LearnedTree learned;
  learned.learn_ms = std::numeric_limits<double>::infinity();
  for (int repetition = 0; repetition < std::max(1, settings.learn_repetitions); ++repetition) {
    const TemporaryModelFile model_file;
    const double milliseconds = millisecondsOf([&] {
      learned.tree = generateIsmTree(demonstration, topology, asr_ism::IsmRecognitionParameters{});
      sqlite::saveIsmTree(model_file.path(), learned.tree, "asr_bench");
    });
    learned.learn_ms = std::min(learned.learn_ms, milliseconds);
  }
  return learned;
}

RecognitionTiming timeRecognition(const TreeRecognizer& recognizer,
                                  const std::vector<asr_common::Configuration>& configurations,
                                  const BenchmarkSettings& settings) {
  RecognitionTiming timing;
  timing.milliseconds.assign(configurations.size(), std::numeric_limits<double>::infinity());
  timing.best_confidence.assign(configurations.size(), 0.0);
  double spent_ms = 0.0;
  while (timing.passes < std::max(1, settings.max_passes) &&
         (timing.passes == 0 || spent_ms < settings.pass_budget_ms)) {
    for (std::size_t i = 0; i < configurations.size(); ++i) {
      std::vector<SceneInstance> instances;
      const double milliseconds =
          millisecondsOf([&] { instances = recognizer.recognize(configurations[i]); });
      timing.milliseconds[i] = std::min(timing.milliseconds[i], milliseconds);
      timing.best_confidence[i] = bestConfidence(instances);
      spent_ms += milliseconds;
    }
    ++timing.passes;
  }
  return timing;
}

double bestConfidence(const std::vector<SceneInstance>& instances) {
  double best = 0.0;
  for (const SceneInstance& instance : instances)
    best = std::max(best, instance.confidence);
  return best;
}

double recognisedFraction(const std::vector<double>& confidences) {
  if (confidences.empty())
    return 0.0;
  const auto recognised = std::count_if(confidences.begin(), confidences.end(),
                                        [](double c) { return c >= kRecognisedConfidence; });
  return static_cast<double>(recognised) / static_cast<double>(confidences.size());
}

double meanConfidenceWithOneLeftOut(const TreeRecognizer& recognizer,
                                    const std::vector<asr_common::Configuration>& configurations) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const asr_common::Configuration& configuration : configurations) {
    for (std::size_t left_out = 0; left_out < configuration.size(); ++left_out) {
      asr_common::Configuration rest = configuration;
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(left_out));
      sum += bestConfidence(recognizer.recognize(rest));
      ++count;
    }
  }
  return count == 0 ? 0.0 : sum / static_cast<double>(count);
}

}  // namespace asr_ism_tree::bench
