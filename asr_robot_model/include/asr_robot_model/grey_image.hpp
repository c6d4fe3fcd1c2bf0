#pragma once

#include <cstdint>
#include <vector>

namespace asr_robot_model {

/// An 8-bit greyscale image, rows top to bottom, no padding: what the tag detector reads and the
/// simulated camera renders, kept free of OpenCV and ROS types.
struct GreyImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height

  GreyImage() = default;
  GreyImage(int width_in, int height_in, std::uint8_t value = 0)
      : width(width_in), height(height_in), pixels(std::size_t(width_in) * height_in, value) {}

  std::uint8_t& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  std::uint8_t at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

}  // namespace asr_robot_model
