#include "asr_pose_prediction/prediction_path.hpp"

#include <deque>

#include "asr_common/input_error.hpp"

namespace asr_pose_prediction {

std::vector<PredictionPath> shortestPredictionPaths(const IsmTree& tree) {
  tree.validate("pose prediction");
  const std::vector<ObjectKey>& objects = tree.objects();
  std::vector<PredictionPath> paths(objects.size());
  std::vector<char> found(objects.size(), 0);

  // Breadth-first from the root; `reached_by[ism]` is the step in its parent that leads to it.
  std::vector<PredictionStep> reached_by(tree.isms.size());
  std::deque<int> queue = {0};
  while (!queue.empty()) {
    const int ism = queue.front();
    queue.pop_front();
    const auto& members = tree.isms[ism].members;
    for (std::size_t m = 0; m < members.size(); ++m) {
      const asr_ism::IsmMember& member = members[m];
      if (member.isPlaceholder()) {
        reached_by[member.child_ism] = {ism, static_cast<int>(m)};
        queue.push_back(member.child_ism);
        continue;
      }
      const int object = tree.topology.indexOf(member.object);
      if (found[object])
        continue;
      found[object] = 1;
      PredictionPath& path = paths[object];
      path.object = member.object;
      path.steps.push_back({ism, static_cast<int>(m)});
      for (int above = ism; above != 0; above = reached_by[above].ism)
        path.steps.insert(path.steps.begin(), reached_by[above]);
    }
  }
  for (std::size_t object = 0; object < objects.size(); ++object) {
    if (!found[object]) {
      throw asr_common::InputError("scene '" + tree.scene + "': object " +
                                   objects[object].toString() + " is not a leaf of any ISM");
    }
  }
  return paths;
}

std::vector<std::string> ismNames(const IsmTree& tree, const PredictionPath& path) {
  std::vector<std::string> names;
  for (const PredictionStep& step : path.steps)
    names.push_back(tree.isms.at(step.ism).name);
  return names;
}

}  // namespace asr_pose_prediction
