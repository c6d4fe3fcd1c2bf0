#include "runtime_plot.hpp"

#include "asr_common/cli/line_plot.hpp"
#include "asr_common/input_error.hpp"

namespace asr_pose_prediction::bench {

void plotSyntheticRuntime(const std::vector<RuntimeRow>& rows, const std::string& path) {
  if (rows.empty())
    throw asr_common::InputError(path + ": no synthetic runtimes to plot (--no-synthetic?)");
  asr_common::cli::LinePlot plot;
  plot.title = "Pose prediction with ISM trees: " + std::to_string(rows.front().samples) +
               " poses of every object of a synthetic scene";
  plot.x_label = "objects in the scene";
  plot.y_label = "runtime [ms] (median)";
  int colour = 1;
  for (std::size_t steps : syntheticStepCounts()) {
    for (const char* topology : {"complete", "star"}) {
      asr_common::cli::PlotCurve curve;
      curve.title = std::to_string(steps) + " steps, " + topology;
      curve.colour = colour;
      curve.dashed = std::string(topology) == "star";
      for (const RuntimeRow& row : rows) {
        if (row.steps == steps && row.topology == topology)
          curve.points.push_back({static_cast<double>(row.objects), row.median_ms});
      }
      plot.curves.push_back(std::move(curve));
    }
    ++colour;
  }
  asr_common::cli::drawLinePlot(plot, path);
}

}  // namespace asr_pose_prediction::bench
