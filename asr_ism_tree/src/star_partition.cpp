#include "asr_ism_tree/star_partition.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>

namespace asr_ism_tree {
namespace {

class DepthFirstPartition {
 public:
  explicit DepthFirstPartition(const RelationTopology& topology) : remaining_(topology) {}

  void visit(int center) {
    const std::vector<int> neighbours = remaining_.neighbours(center);
    if (neighbours.empty())
      return;
    for (int neighbour : neighbours)
      remaining_.removeRelation(center, neighbour);
    stars_.push_back({center, neighbours, 0, -1});
    while (true) {
      int next = -1;
      std::size_t next_degree = 0;
      for (int neighbour : neighbours) {
        const std::size_t degree = remaining_.degree(neighbour);
        if (degree > next_degree) {
          next = neighbour;
          next_degree = degree;
        }
      }
      if (next < 0)
        return;
      visit(next);
    }
  }

  std::vector<Star>& stars() { return stars_; }

 private:
  RelationTopology remaining_;
  std::vector<Star> stars_;
};

// Breadth-first over the stars from the root: heights and parents.
void assignHeights(std::vector<Star>& stars) {
  std::vector<char> reached(stars.size(), 0);
  std::deque<int> queue = {0};
  reached[0] = 1;
  while (!queue.empty()) {
    const int current = queue.front();
    queue.pop_front();
    const auto& neighbours = stars[current].neighbours;
    for (std::size_t j = 0; j < stars.size(); ++j) {
      if (reached[j])
        continue;
      if (std::binary_search(neighbours.begin(), neighbours.end(), stars[j].center)) {
        reached[j] = 1;
        stars[j].height = stars[current].height + 1;
        stars[j].parent = current;
        queue.push_back(static_cast<int>(j));
      }
    }
  }
}

}  // namespace

std::vector<Star> partitionIntoStars(const RelationTopology& topology, int root_center) {
  topology.requireConnected("star partition");
  if (root_center >= static_cast<int>(topology.objectCount())) {
    throw std::out_of_range("root centre index out of range");
  }
  if (topology.objectCount() == 1) {
    return {Star{0, {}, 0, -1}};
  }
  if (root_center < 0) {
    std::size_t best_degree = 0;
    for (std::size_t object = 0; object < topology.objectCount(); ++object) {
      if (topology.degree(object) > best_degree) {
        best_degree = topology.degree(object);
        root_center = static_cast<int>(object);
      }
    }
  }
  DepthFirstPartition partition(topology);
  partition.visit(root_center);
  std::vector<Star> stars = std::move(partition.stars());
  assignHeights(stars);
  return stars;
}

}  // namespace asr_ism_tree
