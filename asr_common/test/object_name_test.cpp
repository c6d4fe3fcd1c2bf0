#include "asr_common/object_name.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "asr_common/testing/input_error_of.hpp"

namespace asr_common {
namespace {

using testing::inputErrorOf;

const std::vector<ObjectKey> kCupAndSecondCup = {{"Plate", "1"}, {"Cup", ""}, {"Cup", "2"}};

TEST(ObjectName, AWrittenNameWinsOverAnAmbiguousType) {
  // `Cup` is the written name of the cup with an empty id, though two objects have type Cup.
  EXPECT_EQ(resolveObjectName("Cup", kCupAndSecondCup, "--star-center"), 1u);
  EXPECT_EQ(resolveObjectName("Cup:2", kCupAndSecondCup, "--star-center"), 2u);
}

TEST(ObjectName, AUniqueTypeNamesItsObject) {
  EXPECT_EQ(resolveObjectName("Plate", kCupAndSecondCup, "file:3"), 0u);
  EXPECT_EQ(resolveObjectName("Plate:1", kCupAndSecondCup, "file:3"), 0u);
}

TEST(ObjectName, AnAmbiguousTypeListsTheObjectsItCouldMean) {
  const std::vector<ObjectKey> two_cups = {{"Cup", "1"}, {"Cup", "2"}, {"Plate", ""}};
  EXPECT_EQ(inputErrorOf([&] { resolveObjectName("Cup", two_cups, "--object"); }),
            "--object: object type 'Cup' is ambiguous; write one of Cup:1, Cup:2");
}

TEST(ObjectName, AnUnknownNameListsTheScenesObjects) {
  EXPECT_EQ(inputErrorOf([&] { resolveObjectName("Cup:3", kCupAndSecondCup, "t.txt:2"); }),
            "t.txt:2: unknown object 'Cup:3' (the scene has: Plate:1, Cup, Cup:2)");
  EXPECT_EQ(inputErrorOf([&] { resolveObjectName("Cup", {}, "--star-center"); }),
            "--star-center: unknown object 'Cup' (the scene has: )");
}

TEST(ObjectName, ATypeWithAColonIsFoundByItsWrittenName) {
  // Splitting at the colon would look for type `a`, id `b` and find nothing.
  const std::vector<ObjectKey> objects = {{"a:b", ""}, {"a", "c"}};
  EXPECT_EQ(resolveObjectName("a:b", objects, "x"), 0u);
  EXPECT_EQ(resolveObjectName("a:c", objects, "x"), 1u);
}

TEST(ObjectName, TwoObjectsWrittenAlikeAreAmbiguous) {
  const std::vector<ObjectKey> objects = {{"a:b", ""}, {"a", "b"}};
  EXPECT_EQ(inputErrorOf([&] { resolveObjectName("a:b", objects, "x"); }),
            "x: object 'a:b' is ambiguous (a:b, a:b)");
}

// Property: in random scenes with distinct keys, every object is found by its written name, and
// by its plain type exactly when no other object has that type.
TEST(ObjectName, EveryObjectIsFoundByTheNameTheToolsPrint) {
  std::mt19937 random(7);
  for (int scene = 0; scene < 200; ++scene) {
    std::vector<ObjectKey> objects;
    const int count = 1 + static_cast<int>(random() % 8);
    for (int i = 0; i < count; ++i) {
      ObjectKey key{"T" + std::to_string(random() % 4), std::to_string(random() % 3)};
      if (key.id == "0")
        key.id.clear();
      bool duplicate = false;
      for (const ObjectKey& other : objects)
        duplicate = duplicate || other == key;
      if (!duplicate)
        objects.push_back(key);
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
      ASSERT_EQ(resolveObjectName(objects[i].toString(), objects, "x"), i);
      std::size_t same_type = 0;
      for (const ObjectKey& other : objects)
        same_type += other.type == objects[i].type ? 1 : 0;
      if (same_type == 1)
        ASSERT_EQ(resolveObjectName(objects[i].type, objects, "x"), i);
    }
  }
}

}  // namespace
}  // namespace asr_common
