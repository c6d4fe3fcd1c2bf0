#pragma once

#include <string>
#include <utility>
#include <vector>

namespace asr_common::cli {

/// One curve of a line plot: (x, y) points, a title for the key, a colour index (gnuplot's
/// line colours 1, 2, ...) and solid or dashed.
struct PlotCurve {
  std::string title;
  std::vector<std::pair<double, double>> points;
  int colour = 1;
  bool dashed = false;
};

struct LinePlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<PlotCurve> curves;
  /// Names of the x values 1, 2, ... (categories, e.g. search modes); empty: plain numbers.
  std::vector<std::string> x_tic_labels;
};

/// Draws the plot as a PNG at `path` with gnuplot (pngcairo). gnuplot draws into a temporary file
/// beside it, which is renamed into place, so an existing plot is replaced whole or not at all.
/// Throws InputError if there is nothing to plot, gnuplot is missing or fails, or the file
/// cannot be written.
void drawLinePlot(const LinePlot& plot, const std::string& path);

}  // namespace asr_common::cli
