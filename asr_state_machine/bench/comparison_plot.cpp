#include "comparison_plot.hpp"

#include <algorithm>

#include "asr_common/cli/line_plot.hpp"
#include "asr_common/cli/timing.hpp"

namespace asr_state_machine::bench {

void plotComparison(const std::vector<ModeMinutes>& modes, int seeds, const std::string& path) {
  using asr_common::cli::PlotCurve;
  asr_common::cli::LinePlot plot;
  plot.title =
      "Searching the kitchen until every object is found (" + std::to_string(seeds) + " seeds)";
  plot.x_label = "search mode";
  plot.y_label = "simulated minutes";
  PlotCurve median{"this suite: median", {}, 1, false};
  // Own colours: with one style, which dashed line is which could not be told.
  PlotCurve fastest{"this suite: fastest run", {}, 3, true};
  PlotCurve slowest{"this suite: slowest run", {}, 4, true};
  PlotCurve paper{"the paper", {}, 2, false};
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const double x = static_cast<double>(i + 1);
    const std::vector<double>& minutes = modes[i].minutes;
    plot.x_tic_labels.push_back(modes[i].name);
    median.points.push_back({x, asr_common::cli::median(minutes)});
    fastest.points.push_back({x, *std::min_element(minutes.begin(), minutes.end())});
    slowest.points.push_back({x, *std::max_element(minutes.begin(), minutes.end())});
    paper.points.push_back({x, modes[i].paper_minutes});
  }
  plot.curves = {median, fastest, slowest, paper};
  asr_common::cli::drawLinePlot(plot, path);
}

}  // namespace asr_state_machine::bench
