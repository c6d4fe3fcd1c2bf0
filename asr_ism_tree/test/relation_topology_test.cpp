#include "asr_ism_tree/relation_topology.hpp"

#include <gtest/gtest.h>

#include <string>

#include "asr_common/input_error.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::InputError;

std::vector<ObjectKey> objects(int count) {
  std::vector<ObjectKey> keys;
  for (int i = 0; i < count; ++i)
    keys.push_back({"Object" + std::to_string(i), "id" + std::to_string(i)});
  return keys;
}

TEST(RelationTopology, StarRelatesTheCentreToEveryOtherObject) {
  const RelationTopology star = RelationTopology::star(objects(5), 2);
  EXPECT_EQ(star.objectCount(), 5u);
  EXPECT_EQ(star.relationCount(), 4u);
  EXPECT_EQ(star.relations(), (std::vector<std::pair<int, int>>{{0, 2}, {1, 2}, {2, 3}, {2, 4}}));
  EXPECT_EQ(star.degree(2), 4u);
  for (std::size_t other : {0u, 1u, 3u, 4u}) {
    EXPECT_EQ(star.degree(other), 1u);
    EXPECT_EQ(star.neighbours(other), std::vector<int>{2});
    EXPECT_TRUE(star.hasRelation(2, other));
    EXPECT_TRUE(star.hasRelation(other, 2));
  }
  EXPECT_FALSE(star.hasRelation(0, 1));
  EXPECT_FALSE(star.hasRelation(2, 2));
  EXPECT_TRUE(star.isConnected());
  EXPECT_THROW(RelationTopology::star(objects(3), 3), std::out_of_range);
}

TEST(RelationTopology, CompleteRelatesEveryPair) {
  for (int n = 1; n <= 7; ++n) {
    const RelationTopology complete = RelationTopology::complete(objects(n));
    EXPECT_EQ(complete.relationCount(), static_cast<std::size_t>(n * (n - 1) / 2));
    for (int a = 0; a < n; ++a) {
      EXPECT_EQ(complete.degree(a), static_cast<std::size_t>(n - 1));
      for (int b = 0; b < n; ++b)
        EXPECT_EQ(complete.hasRelation(a, b), a != b);
    }
    EXPECT_TRUE(complete.isConnected());
  }
}

TEST(RelationTopology, AddingAndRemovingRelations) {
  RelationTopology topology(objects(4));
  EXPECT_EQ(topology.relationCount(), 0u);
  topology.addRelation(3, 1);
  topology.addRelation(1, 3);  // the same undirected relation
  EXPECT_EQ(topology.relationCount(), 1u);
  EXPECT_EQ(topology.relations(), (std::vector<std::pair<int, int>>{{1, 3}}));
  topology.addRelation(0, 1);
  EXPECT_EQ(topology.neighbours(1), (std::vector<int>{0, 3}));
  topology.removeRelation(1, 0);
  topology.removeRelation(1, 0);  // removing a missing relation changes nothing
  EXPECT_EQ(topology.relationCount(), 1u);
  EXPECT_FALSE(topology.hasRelation(0, 1));
  EXPECT_THROW(topology.addRelation(2, 2), std::out_of_range);
  EXPECT_THROW(topology.addRelation(0, 4), std::out_of_range);
  EXPECT_FALSE(topology.hasRelation(0, 9));
}

TEST(RelationTopology, IndexOfFindsObjectsByTypeAndId) {
  const RelationTopology topology(objects(3));
  EXPECT_EQ(topology.indexOf({"Object1", "id1"}), 1);
  EXPECT_EQ(topology.indexOf({"Object1", "id2"}), -1);
  EXPECT_EQ(topology.indexOf({"Object9", "id9"}), -1);
}

TEST(RelationTopology, Connectivity) {
  // A chain is connected; cutting it in the middle is not.
  RelationTopology chain(objects(4));
  chain.addRelation(0, 1);
  chain.addRelation(1, 2);
  chain.addRelation(2, 3);
  EXPECT_TRUE(chain.isConnected());
  EXPECT_NO_THROW(chain.requireConnected("chain"));
  chain.removeRelation(1, 2);
  EXPECT_FALSE(chain.isConnected());
  // A single object is connected; no object is not.
  EXPECT_TRUE(RelationTopology(objects(1)).isConnected());
  EXPECT_FALSE(RelationTopology().isConnected());
  EXPECT_THROW(RelationTopology().requireConnected("empty"), InputError);
  EXPECT_FALSE(RelationTopology(objects(2)).isConnected());
}

TEST(RelationTopology, RequireConnectedNamesTheUnreachableObjects) {
  RelationTopology topology(objects(5));
  topology.addRelation(0, 2);
  topology.addRelation(2, 4);
  topology.addRelation(1, 3);
  try {
    topology.requireConnected("scene 'breakfast'");
    FAIL() << "no InputError thrown";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("scene 'breakfast'"), std::string::npos) << message;
    EXPECT_NE(message.find("Object1:id1"), std::string::npos) << message;
    EXPECT_NE(message.find("Object3:id3"), std::string::npos) << message;
    // Reachable objects are not blamed (the first object is named as the start only once).
    EXPECT_EQ(message.find("Object2:id2"), std::string::npos) << message;
    EXPECT_EQ(message.find("Object4:id4"), std::string::npos) << message;
  }
}

TEST(RelationTopology, DuplicateObjectsAreRefused) {
  std::vector<ObjectKey> keys = objects(3);
  keys.push_back(keys[1]);
  EXPECT_THROW(RelationTopology{keys}, InputError);
  EXPECT_THROW(RelationTopology::complete(keys), InputError);
  EXPECT_THROW(RelationTopology::star(keys, 0), InputError);
  // Same type with different ids, or same id with different types, are different objects.
  EXPECT_NO_THROW(RelationTopology({{"Cup", "1"}, {"Cup", "2"}, {"Plate", "1"}}));
}

TEST(RelationTopology, ValueSemantics) {
  const RelationTopology a = RelationTopology::star(objects(4), 0);
  RelationTopology b = a;
  EXPECT_EQ(a, b);
  b.addRelation(1, 2);
  EXPECT_NE(a, b);
  EXPECT_EQ(a.relationCount(), 3u);
  b.removeRelation(1, 2);
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace asr_ism_tree
