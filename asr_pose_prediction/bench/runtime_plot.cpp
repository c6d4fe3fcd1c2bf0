#include "runtime_plot.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "asr_ism/input_error.hpp"

namespace asr_pose_prediction::bench {
namespace {

// A gnuplot string literal: single quotes, a quote inside doubled.
std::string gnuplotQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text)
    quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

// The script: one inline data block per step count (objects, complete ms, star ms).
std::string plotScript(const std::vector<RuntimeRow>& rows, const std::string& output) {
  std::ostringstream script;
  script << "set terminal pngcairo size 900,600 enhanced font 'sans,11'\n"
         << "set output " << gnuplotQuoted(output) << "\n"
         << "set title 'Pose prediction with ISM trees: " << rows.front().samples
         << " poses of every object of a synthetic scene'\n"
         << "set xlabel 'objects in the scene'\nset ylabel 'runtime [ms] (median)'\n"
         << "set key top left\nset grid\nset xtics 1\nset yrange [0:*]\n";
  std::string plot = "plot ";
  int colour = 1;
  for (std::size_t steps : syntheticStepCounts()) {
    const std::string block = "$steps" + std::to_string(steps);
    script << block << " << EOD\n";
    for (std::size_t objects : syntheticObjectCounts()) {
      double complete_ms = -1.0;
      double star_ms = -1.0;
      for (const RuntimeRow& row : rows) {
        if (row.objects == objects && row.steps == steps)
          (row.topology == "complete" ? complete_ms : star_ms) = row.median_ms;
      }
      if (complete_ms >= 0.0 && star_ms >= 0.0)
        script << objects << " " << complete_ms << " " << star_ms << "\n";
    }
    script << "EOD\n";
    const std::string style = " with linespoints lw 2 pt 7 lc " + std::to_string(colour);
    plot += (colour == 1 ? "" : ", ") + block + " using 1:2" + style + " dt 1 title '" +
            std::to_string(steps) + " steps, complete', " + block + " using 1:3" + style +
            " dt 2 title '" + std::to_string(steps) + " steps, star'";
    ++colour;
  }
  script << plot << "\n";
  return script.str();
}

}  // namespace

void plotSyntheticRuntime(const std::vector<RuntimeRow>& rows, const std::string& path) {
  if (rows.empty())
    throw asr_ism::InputError(path + ": no synthetic runtimes to plot (--no-synthetic?)");
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  FILE* gnuplot = ::popen("gnuplot", "w");
  if (gnuplot == nullptr)
    throw asr_ism::InputError(path + ": cannot start gnuplot (install gnuplot-nox)");
  const std::string script = plotScript(rows, temporary);
  std::fwrite(script.data(), 1, script.size(), gnuplot);
  const int status = ::pclose(gnuplot);
  std::error_code error;
  if (status != 0 || !std::filesystem::exists(temporary, error)) {
    std::filesystem::remove(temporary, error);
    throw asr_ism::InputError(path + ": gnuplot failed to draw the plot (is gnuplot-nox installed?)");
  }
  std::filesystem::rename(temporary, path, error);
  if (error) {
    const std::string reason = error.message();
    std::filesystem::remove(temporary, error);
    throw asr_ism::InputError(path + ": cannot write the plot: " + reason);
  }
}

}  // namespace asr_pose_prediction::bench
