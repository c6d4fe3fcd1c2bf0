#include "asr_common/cli/line_plot.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "asr_common/atomic_file.hpp"
#include "asr_common/input_error.hpp"

namespace asr_common::cli {
namespace {

// A gnuplot string literal: single quotes, a quote inside doubled.
std::string gnuplotQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text)
    quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

// The script: one inline data block per curve.
std::string plotScript(const LinePlot& plot, const std::string& output) {
  std::ostringstream script;
  script << "set terminal pngcairo size 900,600 enhanced font 'sans,11'\n"
         << "set output " << gnuplotQuoted(output) << "\n"
         << "set title " << gnuplotQuoted(plot.title) << "\n"
         << "set xlabel " << gnuplotQuoted(plot.x_label) << "\nset ylabel "
         << gnuplotQuoted(plot.y_label) << "\n"
         << "set key top left\nset grid\nset xtics 1\nset yrange [0:*]\n";
  if (!plot.x_tic_labels.empty()) {
    script << "set xrange [0.5:" << plot.x_tic_labels.size() + 0.5 << "]\nset xtics (";
    for (std::size_t i = 0; i < plot.x_tic_labels.size(); ++i)
      script << (i ? ", " : "") << gnuplotQuoted(plot.x_tic_labels[i]) << " " << i + 1;
    // Categories fall from left to right in the suite's plots: the key goes where they do not.
    script << ")\nset key top right\n";
  }
  std::string command = "plot ";
  for (std::size_t i = 0; i < plot.curves.size(); ++i) {
    const PlotCurve& curve = plot.curves[i];
    const std::string block = "$curve" + std::to_string(i);
    script << block << " << EOD\n";
    for (const auto& [x, y] : curve.points)
      script << x << " " << y << "\n";
    script << "EOD\n";
    command += (i == 0 ? "" : ", ") + block + " using 1:2 with linespoints lw 2 pt 7 lc " +
               std::to_string(curve.colour) + (curve.dashed ? " dt 2" : " dt 1") + " title " +
               gnuplotQuoted(curve.title);
  }
  script << command << "\n";
  return script.str();
}

}  // namespace

void drawLinePlot(const LinePlot& plot, const std::string& path) {
  if (plot.curves.empty())
    throw InputError(path + ": nothing to plot");
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  FILE* gnuplot = ::popen("gnuplot", "w");
  if (gnuplot == nullptr)
    throw InputError(path + ": cannot start gnuplot (install gnuplot-nox)");
  const std::string script = plotScript(plot, temporary);
  std::fwrite(script.data(), 1, script.size(), gnuplot);
  const int status = ::pclose(gnuplot);
  std::error_code error;
  if (status != 0 || !std::filesystem::exists(temporary, error)) {
    std::filesystem::remove(temporary, error);
    throw InputError(path + ": gnuplot failed to draw the plot (is gnuplot-nox installed?)");
  }
  // gnuplot wrote a file of its own; the plot replaces `path` whole, like every file the suite
  // writes.
  std::ifstream drawn(temporary, std::ios::binary);
  const std::string png((std::istreambuf_iterator<char>(drawn)), std::istreambuf_iterator<char>());
  drawn.close();
  std::filesystem::remove(temporary, error);
  writeFileAtomically(path, png);
}

}  // namespace asr_common::cli
