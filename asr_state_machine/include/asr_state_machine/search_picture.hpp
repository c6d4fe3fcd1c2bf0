#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>

#include "asr_robot_model/frustum.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_state_machine/search_executive.hpp"

namespace asr_state_machine {

using Rgb = std::array<std::uint8_t, 3>;

/// Colours of the picture that a reader (and the tests) can look for.
inline constexpr Rgb kPathColour{20, 60, 200};
inline constexpr Rgb kFloorColour{255, 255, 255};

/// Where the floor lies in the picture: north (+y) is up, the room fills the left part with a
/// margin, the key (outcome, scenes, objects) stands to its right.
class TopDownFrame {
 public:
  explicit TopDownFrame(const asr_robot_model::World& world, double pixels_per_metre = 120.0);

  /// The pixel (column, row) of a point on the floor, rounded.
  Eigen::Vector2i pixel(const Eigen::Vector2d& floor) const;
  int width() const { return map_width_ + kKeyWidth; }
  int height() const { return height_; }
  int mapWidth() const { return map_width_; }
  double pixelsPerMetre() const { return scale_; }

  static constexpr int kMargin = 40;
  static constexpr int kKeyWidth = 600;

 private:
  Eigen::Vector2d room_min_;
  double room_max_y_;
  double scale_;
  int map_width_;
  int height_;
};

/// A top-down picture of a search in its world: the room and the furniture boxes, the robot's
/// path from its start through every view, the views (camera position and a wedge of the
/// camera's horizontal opening, numbered in order), the objects found (filled, coloured by
/// scene, lettered) and those of the scenes never found (hollow, crossed); the key lists the
/// outcome, the scenes with their confidence and every object with when and from which view it
/// was found. PNG, written whole or not at all; throws asr_common::InputError naming `png` if it
/// cannot be written.
void writeSearchPicture(
    const asr_robot_model::World& world, const SearchResult& result, const std::string& png,
    const asr_robot_model::Frustum& frustum = asr_robot_model::Frustum::defaults());

/// Throws asr_common::InputError naming `png` if a picture cannot go there (its folder does not
/// exist, or it is a folder): checked before a search, so a typo does not cost the search.
void checkPictureFile(const std::string& png);

}  // namespace asr_state_machine
