#include "asr_ism_tree/topology_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"

namespace asr_ism_tree {
namespace {

namespace fs = std::filesystem;
using asr_common::testing::fileBytes;
using asr_common::testing::inputErrorOf;
using asr_common::testing::TempDir;

// Two instances of one type, an object without id and a unique type with an id.
const std::vector<ObjectKey> kObjects = {
    {"Cup", ""}, {"PlateDeep", "018054024100"}, {"PlateDeep", "054042013100"}, {"marker_1", "7"}};

RelationTopology sampleTopology() {
  RelationTopology topology(kObjects);
  topology.addRelation(0, 1);
  topology.addRelation(1, 2);
  topology.addRelation(1, 3);
  topology.addRelation(0, 3);
  return topology;
}

TEST(TopologyFile, RoundTrip) {
  TempDir dir("asr_topology");
  const std::string path = dir.file("topology.txt");
  const RelationTopology written = sampleTopology();
  writeTopologyFile(path, written);
  EXPECT_EQ(readTopologyFile(path, kObjects), written);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"topology.txt"}) << "no temporary file left";
}

TEST(TopologyFile, RoundTripOfStarAndCompleteOnARecording) {
  REQUIRE_RECORDINGS();
  const auto objects = asr_ism::sqlite::readDemonstration(
                           asr_common::testing::recording("story_1.sqlite"), "Spuelkorb_3")
                           .objects();
  TempDir dir("asr_topology");
  const std::string path = dir.file("topology.txt");
  for (const RelationTopology& topology :
       {RelationTopology::star(objects, 2), RelationTopology::complete(objects)}) {
    writeTopologyFile(path, topology);
    EXPECT_EQ(readTopologyFile(path, objects), topology);
  }
}

TEST(TopologyFile, WriterUsesTypeAndIdAndAHeader) {
  TempDir dir("asr_topology");
  const std::string path = dir.file("topology.txt");
  writeTopologyFile(path, sampleTopology());
  const std::string text = fileBytes(path);
  EXPECT_EQ(text.front(), '#') << "the file starts with a header comment";
  // Relations in index order; a plain type only where the id is empty.
  EXPECT_NE(text.find("\nCup PlateDeep:018054024100\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nCup marker_1:7\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nPlateDeep:018054024100 PlateDeep:054042013100\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("\nPlateDeep:018054024100 marker_1:7\n"), std::string::npos) << text;
}

TEST(TopologyFile, ReaderAcceptsUniqueTypesCommentsAndBlankLines) {
  TempDir dir("asr_topology");
  const std::string path = dir.write("topology.txt",
                                     "# hand-written\n"
                                     "\n"
                                     "   Cup   PlateDeep:018054024100   # plate on the left\n"
                                     "PlateDeep:054042013100\tPlateDeep:018054024100\n"
                                     "marker_1 PlateDeep:018054024100\n"
                                     "Cup marker_1:7\n"
                                     "marker_1:7 Cup\n"  // the same relation again
                                     "   \n");
  EXPECT_EQ(readTopologyFile(path, kObjects), sampleTopology());
}

TEST(TopologyFile, FileWithoutTrailingNewline) {
  TempDir dir("asr_topology");
  const std::string path = dir.write("topology.txt",
                                     "Cup marker_1\nmarker_1 PlateDeep:054042013100\n"
                                     "PlateDeep:054042013100 PlateDeep:018054024100");
  EXPECT_EQ(readTopologyFile(path, kObjects).relationCount(), 3u);
}

TEST(TopologyFile, SingleObjectNeedsNoRelation) {
  TempDir dir("asr_topology");
  const std::vector<ObjectKey> single = {{"Cup", "1"}};
  const std::string path = dir.file("topology.txt");
  writeTopologyFile(path, RelationTopology(single));
  EXPECT_EQ(readTopologyFile(path, single), RelationTopology(single));
}

// ---- read errors: each names the file, and the line where there is one ----

void expectReadError(const std::string& text, const std::string& line_reference,
                     const std::string& detail) {
  TempDir dir("asr_topology");
  const std::string path = dir.write("topology.txt", text);
  const std::string message = inputErrorOf([&] { readTopologyFile(path, kObjects); });
  EXPECT_NE(message.find(path + line_reference), std::string::npos) << message;
  EXPECT_NE(message.find(detail), std::string::npos) << message;
}

TEST(TopologyFileErrors, MissingFile) {
  TempDir dir("asr_topology");
  const std::string path = dir.file("absent.txt");
  const std::string message = inputErrorOf([&] { readTopologyFile(path, kObjects); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("no such"), std::string::npos) << message;
}

TEST(TopologyFileErrors, FolderInsteadOfFile) {
  TempDir dir("asr_topology");
  const std::string message = inputErrorOf([&] { readTopologyFile(dir.file(""), kObjects); });
  EXPECT_NE(message.find(dir.file("")), std::string::npos) << message;
}

TEST(TopologyFileErrors, MalformedLines) {
  expectReadError("Cup marker_1\nCup\n", ":2:", "two objects");
  expectReadError("# header\nCup marker_1 PlateDeep:018054024100\n", ":2:", "two objects");
  expectReadError("Cup-marker_1\n", ":1:", "two objects");
}

TEST(TopologyFileErrors, UnknownObjectListsTheKnownOnes) {
  expectReadError("Cup marker_1\n\nTeapot Cup\n", ":3:", "unknown object 'Teapot'");
  expectReadError("Cup marker_1\n\nTeapot Cup\n", ":3:", "PlateDeep:054042013100");
  expectReadError("Cup marker_1:8\n", ":1:", "unknown object 'marker_1:8'");
}

TEST(TopologyFileErrors, AmbiguousTypeListsTheCandidates) {
  expectReadError("Cup marker_1\nPlateDeep Cup\n", ":2:",
                  "'PlateDeep' is ambiguous; write one of PlateDeep:018054024100, "
                  "PlateDeep:054042013100");
}

TEST(TopologyFileErrors, RelationOfAnObjectWithItself) {
  expectReadError("Cup marker_1\nmarker_1 marker_1:7\n", ":2:", "related to itself");
}

TEST(TopologyFileErrors, DisconnectedTopology) {
  TempDir dir("asr_topology");
  const std::string path =
      dir.write("topology.txt", "Cup marker_1\nPlateDeep:018054024100 PlateDeep:054042013100\n");
  const std::string message = inputErrorOf([&] { readTopologyFile(path, kObjects); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("not connected"), std::string::npos) << message;
  EXPECT_NE(message.find("PlateDeep:018054024100"), std::string::npos) << message;

  // An empty file relates nothing: not connected either.
  const std::string empty = dir.write("empty.txt", "# nothing\n");
  EXPECT_NE(inputErrorOf([&] { readTopologyFile(empty, kObjects); }).find("not connected"),
            std::string::npos);
}

// ---- writing: atomic, never half a file ----

TEST(TopologyFile, OverwritingReplacesTheWholeFile) {
  TempDir dir("asr_topology");
  const std::string path = dir.write("topology.txt", std::string(10000, 'x') + "\n");
  writeTopologyFile(path, sampleTopology());
  EXPECT_EQ(readTopologyFile(path, kObjects), sampleTopology());
  EXPECT_EQ(fileBytes(path).find('x'), std::string::npos);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"topology.txt"});
}

TEST(TopologyFile, RefusedWritesLeaveTheOldFile) {
  TempDir dir("asr_topology");
  const std::string path = dir.file("topology.txt");
  writeTopologyFile(path, sampleTopology());
  const std::string before = fileBytes(path);

  RelationTopology disconnected(kObjects);
  disconnected.addRelation(0, 1);
  std::string message = inputErrorOf([&] { writeTopologyFile(path, disconnected); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("not connected"), std::string::npos) << message;

  // A name that would not read back as one object.
  const std::vector<ObjectKey> spaced = {{"Coffee Box", ""}, {"Cup", ""}};
  message = inputErrorOf([&] { writeTopologyFile(path, RelationTopology::complete(spaced)); });
  EXPECT_NE(message.find("Coffee Box"), std::string::npos) << message;

  // Two objects that would be written alike.
  const std::vector<ObjectKey> alike = {{"a:b", ""}, {"a", "b"}};
  message = inputErrorOf([&] { writeTopologyFile(path, RelationTopology::complete(alike)); });
  EXPECT_NE(message.find("'a:b'"), std::string::npos) << message;

  EXPECT_EQ(fileBytes(path), before);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"topology.txt"});
}

TEST(TopologyFile, UnwritableFolderIsNamedAndNothingIsCreated) {
  TempDir dir("asr_topology");
  const std::string path = dir.file("missing_folder/topology.txt");
  const std::string message = inputErrorOf([&] { writeTopologyFile(path, sampleTopology()); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(TopologyFile, TargetThatCannotBeReplacedKeepsItsContent) {
  TempDir dir("asr_topology");
  // A non-empty folder under the target name: rename fails after the temporary file is written.
  const std::string path = dir.file("topology.txt");
  fs::create_directories(path + "/inside");
  const std::string message = inputErrorOf([&] { writeTopologyFile(path, sampleTopology()); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_TRUE(fs::is_directory(path + "/inside"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"topology.txt"}) << "temporary file removed";
}

TEST(TopologyFile, ExistingFileKeepsItsPermissions) {
  TempDir dir("asr_topology");
  const std::string path = dir.write("topology.txt", "old\n");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  writeTopologyFile(path, sampleTopology());
  EXPECT_EQ(fs::status(path).permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

}  // namespace
}  // namespace asr_ism_tree
