#pragma once

#include <optional>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_robot_model/frustum.hpp"
#include "asr_robot_model/motion_model.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"
#include "asr_state_machine/parts.hpp"

namespace asr_state_machine {

/// A view the robot can take that shows `target` near the middle of the camera's depth range,
/// from a camera whose direction seen from the target has an azimuth within `half_range` of
/// `approach` (radians): base free, head within its limits, line of sight free. Of the views
/// that work, the one with the target nearest the middle of the clipping range.
std::optional<SearchView> viewLookingAt(const Eigen::Vector3d& target, double approach,
                                        double half_range,
                                        const asr_robot_model::RobotDescription& robot,
                                        const asr_robot_model::WorldMap& map,
                                        const asr_robot_model::Frustum& frustum);

/// When a view counts as one already visited.
struct VisitedViewTolerance {
  double distance = 0.225;             // metres between camera positions
  double angle = 15.0 * M_PI / 180.0;  // between optical axes
};

/// The in-process direct search: views of demonstrated object poses (for the searched types
/// only) first, then a sweep that covers points over the top of every piece of furniture, each
/// from the four sides (objects are often recognisable from some sides only); each
/// time the view cheapest to reach from where the robot is, and never one close to a view
/// already visited that searched every type still searched.
class FurnitureSweep : public DirectSearch {
 public:
  /// `demonstrated`: where objects were seen in the demonstrations (in map; may be empty).
  /// `spacing`: metres between the sweep's points on a top.
  FurnitureSweep(const asr_robot_model::RobotDescription& robot,
                 const asr_robot_model::World& world, const asr_robot_model::WorldMap& map,
                 const asr_robot_model::Frustum& frustum,
                 const std::vector<asr_common::ObjectEstimate>& demonstrated, double spacing = 0.35,
                 VisitedViewTolerance tolerance = {});

  std::optional<SearchView> next(const RobotState& current, const std::vector<std::string>& types,
                                 const std::vector<VisitedView>& visited) override;

  std::size_t sweepViewCount() const { return sweep_.size(); }
  std::size_t demonstratedViewCount() const { return informed_.size(); }

 private:
  struct TypedView {
    SearchView view;
    std::vector<std::string> types;  // of the demonstrated objects it shows
  };
  // Whether a view near `view` already searched every one of `types`.
  bool nearVisited(const SearchView& view, const std::vector<std::string>& types,
                   const std::vector<VisitedView>& visited) const;

  asr_robot_model::MotionSpeeds speeds_;
  VisitedViewTolerance tolerance_;
  std::vector<TypedView> informed_;
  std::vector<SearchView> sweep_;
};

}  // namespace asr_state_machine
