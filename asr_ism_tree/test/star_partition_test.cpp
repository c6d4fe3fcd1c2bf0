#include "asr_ism_tree/star_partition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "asr_common/input_error.hpp"
#include "golden_graphs.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::InputError;

// Stars as comparable tuples, so a failure prints the whole partition.
std::string describe(const std::vector<Star>& stars) {
  std::string text;
  for (const Star& star : stars) {
    text += "{centre " + std::to_string(star.center) + ", neighbours";
    for (int n : star.neighbours)
      text += " " + std::to_string(n);
    text += ", height " + std::to_string(star.height) + ", parent " + std::to_string(star.parent) +
            "} ";
  }
  return text;
}

void expectStars(const std::vector<Star>& actual, const std::vector<Star>& expected) {
  ASSERT_EQ(actual.size(), expected.size()) << describe(actual);
  for (std::size_t s = 0; s < expected.size(); ++s) {
    EXPECT_EQ(actual[s].center, expected[s].center) << "star " << s << ": " << describe(actual);
    EXPECT_EQ(actual[s].neighbours, expected[s].neighbours)
        << "star " << s << ": " << describe(actual);
    EXPECT_EQ(actual[s].height, expected[s].height) << "star " << s << ": " << describe(actual);
    EXPECT_EQ(actual[s].parent, expected[s].parent) << "star " << s << ": " << describe(actual);
  }
}

TEST(StarPartition, Chain) {
  // Root: B (degree 2, lower index than C). B takes A and C; C has D left, so C is next.
  expectStars(partitionIntoStars(golden::chain()), {{1, {0, 2}, 0, -1}, {2, {3}, 1, 0}});
}

TEST(StarPartition, ChainFromAGivenRoot) {
  // Starting at A, every star holds one relation and each hangs below the previous one.
  expectStars(partitionIntoStars(golden::chain(), 0),
              {{0, {1}, 0, -1}, {1, {2}, 1, 0}, {2, {3}, 2, 1}});
}

TEST(StarPartition, Triangle) {
  // All degrees 2: A is the root and takes B and C; B (first of the tie) keeps B - C.
  expectStars(partitionIntoStars(golden::triangle()), {{0, {1, 2}, 0, -1}, {1, {2}, 1, 0}});
}

TEST(StarPartition, CompleteGraphOfFour) {
  // A takes B, C, D. The depth-first search goes on to B (B - C, B - D left), then from B to C
  // (C - D left). C is also A's neighbour, so C's star hangs below the root, not below B.
  expectStars(partitionIntoStars(golden::complete4()),
              {{0, {1, 2, 3}, 0, -1}, {1, {2, 3}, 1, 0}, {2, {3}, 1, 0}});
}

TEST(StarPartition, CompleteGraphOfFourFromAGivenRoot) {
  expectStars(partitionIntoStars(golden::complete4(), 3),
              {{3, {0, 1, 2}, 0, -1}, {0, {1, 2}, 1, 0}, {1, {2}, 1, 0}});
}

TEST(StarPartition, StarIsOneStar) {
  expectStars(partitionIntoStars(golden::starAroundC()), {{2, {0, 1, 3}, 0, -1}});
}

TEST(StarPartition, BranchingGraph) {
  // C (degree 4) takes A, D, E, F. A and D have one relation left each; A comes first and takes
  // B; from A the search continues to B, which takes D. B is no neighbour of the root star, so
  // its star sits two levels down, below A's.
  expectStars(partitionIntoStars(golden::branching()),
              {{2, {0, 3, 4, 5}, 0, -1}, {0, {1}, 1, 0}, {1, {3}, 2, 1}});
}

TEST(StarPartition, SingleObjectIsOneEmptyStar) {
  expectStars(partitionIntoStars(RelationTopology(golden::lettered(1))), {{0, {}, 0, -1}});
}

TEST(StarPartition, DisconnectedTopologyIsAnError) {
  RelationTopology topology = golden::chain();
  topology.removeRelation(1, 2);
  EXPECT_THROW(partitionIntoStars(topology), InputError);
  EXPECT_THROW(partitionIntoStars(RelationTopology(golden::lettered(3))), InputError);
}

TEST(StarPartition, RootCentreOutOfRangeIsAnError) {
  EXPECT_THROW(partitionIntoStars(golden::chain(), 4), std::out_of_range);
}

// A random connected topology of `count` objects: a random spanning tree, then random extra
// relations.
RelationTopology randomConnectedTopology(int count, std::mt19937& random) {
  RelationTopology topology(golden::lettered(count));
  for (int object = 1; object < count; ++object)
    topology.addRelation(object, std::uniform_int_distribution<int>(0, object - 1)(random));
  const int extra = std::uniform_int_distribution<int>(0, count * (count - 1) / 2)(random);
  for (int e = 0; e < extra; ++e) {
    const int a = std::uniform_int_distribution<int>(0, count - 1)(random);
    const int b = std::uniform_int_distribution<int>(0, count - 1)(random);
    if (a != b)
      topology.addRelation(a, b);
  }
  return topology;
}

// Every relation in exactly one star; stars hold only relations of the topology.
void expectRelationsCoveredOnce(const RelationTopology& topology, const std::vector<Star>& stars) {
  std::multiset<std::pair<int, int>> covered;
  std::set<int> centres;
  for (const Star& star : stars) {
    EXPECT_FALSE(star.neighbours.empty());
    EXPECT_TRUE(std::is_sorted(star.neighbours.begin(), star.neighbours.end()));
    EXPECT_TRUE(centres.insert(star.center).second) << "centre used twice";
    for (int n : star.neighbours) {
      EXPECT_TRUE(topology.hasRelation(star.center, n));
      covered.insert({std::min(star.center, n), std::max(star.center, n)});
    }
  }
  const auto relations = topology.relations();
  EXPECT_EQ((std::vector<std::pair<int, int>>(covered.begin(), covered.end())), relations);
  EXPECT_EQ(covered.size(), relations.size());
}

// The root: highest degree, lowest index among ties.
void expectRootStar(const RelationTopology& topology, const std::vector<Star>& stars) {
  std::size_t best_degree = 0;
  int root = -1;
  for (int object = 0; object < static_cast<int>(topology.objectCount()); ++object) {
    if (topology.degree(object) > best_degree) {
      best_degree = topology.degree(object);
      root = object;
    }
  }
  EXPECT_EQ(stars[0].center, root);
  EXPECT_EQ(stars[0].height, 0);
  EXPECT_EQ(stars[0].parent, -1);
}

bool hasNeighbour(const Star& star, int object) {
  return std::binary_search(star.neighbours.begin(), star.neighbours.end(), object);
}

// Parent: the first star (extraction order) one height closer that has the centre. Height is the
// distance from the root star: no star higher up than the parent has the centre.
void expectParentsAndHeights(const std::vector<Star>& stars) {
  for (std::size_t j = 1; j < stars.size(); ++j) {
    int expected_parent = -1;
    for (std::size_t k = 0; k < stars.size() && expected_parent < 0; ++k) {
      if (stars[k].height == stars[j].height - 1 && hasNeighbour(stars[k], stars[j].center))
        expected_parent = static_cast<int>(k);
    }
    EXPECT_GE(stars[j].height, 1) << "star " << j;
    EXPECT_EQ(stars[j].parent, expected_parent) << "star " << j;
    for (std::size_t k = 0; k < stars.size(); ++k) {
      if (stars[k].height < stars[j].height - 1) {
        EXPECT_FALSE(hasNeighbour(stars[k], stars[j].center))
            << "star " << j << " could hang below star " << k;
      }
    }
  }
}

// The documented invariants, on many random connected topologies.
TEST(StarPartition, InvariantsOnRandomConnectedTopologies) {
  std::mt19937 random(20240611);
  for (int trial = 0; trial < 300; ++trial) {
    const RelationTopology topology = randomConnectedTopology(2 + trial % 9, random);
    const std::vector<Star> stars = partitionIntoStars(topology);
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + describe(stars));
    expectRelationsCoveredOnce(topology, stars);
    expectRootStar(topology, stars);
    expectParentsAndHeights(stars);
  }
}

}  // namespace
}  // namespace asr_ism_tree
