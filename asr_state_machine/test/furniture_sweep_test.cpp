// The direct search's sweep on the shipped kitchen (no recordings needed).
#include <gtest/gtest.h>

#include "asr_nbv/nbv_parameters.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"
#include "asr_state_machine/furniture_sweep.hpp"

namespace asr_state_machine {
namespace {

const std::string kKitchen =
    std::string(ASR_STATE_MACHINE_SOURCE_DIR) + "/config/worlds/kitchen.yaml";

class KitchenSweep : public ::testing::Test {
 protected:
  KitchenSweep()
      : robot_(asr_robot_model::loadRobotDescription(asr_robot_model::defaultRobotUrdf())),
        world_(asr_robot_model::loadWorld(
            kKitchen,
            asr_robot_model::loadObjectCatalogue(asr_robot_model::defaultObjectCatalogue()))),
        nbv_(asr_nbv::loadNbvParameters(asr_nbv::defaultNbvParameters())),
        map_(world_, nbv_.occlusion_resolution, robot_.base_radius),
        sweep_(robot_, world_, map_, nbv_.frustum, {}) {}

  std::optional<SearchView> next(const std::vector<std::string>& types,
                                 const std::vector<VisitedView>& visited) {
    return sweep_.next(world_.robot, types, visited);
  }

  asr_robot_model::RobotDescription robot_;
  asr_robot_model::World world_;
  asr_nbv::NbvParameters nbv_;
  asr_robot_model::WorldMap map_;
  FurnitureSweep sweep_;
};

bool sameCamera(const SearchView& a, const SearchView& b) {
  return a.camera.position.isApprox(b.camera.position) &&
         a.camera.orientation.isApprox(b.camera.orientation);
}

VisitedView visitedAt(const SearchView& view, std::vector<std::string> types) {
  VisitedView visited;
  visited.camera = view.camera;
  visited.types = std::move(types);
  return visited;
}

// A next-best-view searches only the types worth it there; the bounding-box search's sweep once
// skipped such views for every type and missed the plate in half of its runs.
TEST_F(KitchenSweep, AViewThatSearchedSomeTypesIsTakenAgainForTheOthers) {
  const std::vector<std::string> types{"Cup", "PlateDeep"};
  const std::optional<SearchView> first = next(types, {});
  ASSERT_TRUE(first.has_value());

  const std::optional<SearchView> after_cup_only = next(types, {visitedAt(*first, {"Cup"})});
  ASSERT_TRUE(after_cup_only.has_value());
  EXPECT_TRUE(sameCamera(*after_cup_only, *first));

  const std::optional<SearchView> after_both = next(types, {visitedAt(*first, types)});
  ASSERT_TRUE(after_both.has_value());
  EXPECT_FALSE(sameCamera(*after_both, *first));

  // Once only the cup is searched, the view that searched the cup is done.
  const std::optional<SearchView> cup_after_cup = next({"Cup"}, {visitedAt(*first, {"Cup"})});
  ASSERT_TRUE(cup_after_cup.has_value());
  EXPECT_FALSE(sameCamera(*cup_after_cup, *first));
}

}  // namespace
}  // namespace asr_state_machine
