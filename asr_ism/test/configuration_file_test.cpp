#include "asr_ism/configuration_file.hpp"
#include "asr_ism/input_limits.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"

namespace asr_ism {
namespace {

namespace fs = std::filesystem;
using asr_common::testing::fileBytes;
using asr_common::testing::inputErrorOf;
using asr_common::testing::TempDir;

constexpr char kPrefix[] = "asr_configuration_file";

// Two objects of one type, one without an id; the second quaternion is a quarter turn about z.
const char kYaml[] =
    "# a hand-written configuration\n"
    "objects:\n"
    "  - type: Cup\n"
    "    id: \"1\"\n"
    "    pose:\n"
    "      position: {x: 1.0, y: 2.0, z: 0.75}\n"
    "      orientation: {x: 0, y: 0, z: 0, w: 1}\n"
    "  - type: Cup\n"
    "    id: 2\n"
    "    pose:\n"
    "      orientation:\n"
    "        w: 0.70710678118654757\n"
    "        x: 0.0\n"
    "        y: 0.0\n"
    "        z: 0.70710678118654757\n"
    "      position:\n"
    "        x: -0.25\n"
    "        y: 1.5e-1\n"
    "        z: 0.8\n"
    "  - type: PlateDeep\n"
    "    pose:\n"
    "      position: {x: 0, y: 0, z: 0.7}\n"
    "      orientation: {x: 0, y: 0, z: 0, w: 1}\n";

const char kJson[] = R"({
  "objects": [
    {"type": "Cup", "id": "1",
     "pose": {"position": {"x": 1.0, "y": 2.0, "z": 0.75},
              "orientation": {"x": 0, "y": 0, "z": 0, "w": 1}}},
    {"type": "Cup", "id": 2,
     "pose": {"position": {"x": -0.25, "y": 0.15, "z": 0.8},
              "orientation": {"w": 0.70710678118654757, "x": 0.0, "y": 0.0,
                              "z": 0.70710678118654757}}},
    {"type": "PlateDeep",
     "pose": {"position": {"x": 0, "y": 0, "z": 0.7},
              "orientation": {"x": 0, "y": 0, "z": 0, "w": 1}}}
  ]
})";

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Keys equal, positions and quaternion coefficients equal bit for bit.
void expectSameConfiguration(const Configuration& actual, const Configuration& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE("object " + std::to_string(i) + " (" + expected[i].key.toString() + ")");
    EXPECT_EQ(actual[i].key, expected[i].key);
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(sameBits(actual[i].pose.position[c], expected[i].pose.position[c]))
          << "position " << c << ": " << actual[i].pose.position[c] << " vs "
          << expected[i].pose.position[c];
    }
    for (int c = 0; c < 4; ++c) {
      EXPECT_TRUE(sameBits(actual[i].pose.orientation.coeffs()[c],
                           expected[i].pose.orientation.coeffs()[c]))
          << "orientation " << c << ": " << actual[i].pose.orientation.coeffs()[c] << " vs "
          << expected[i].pose.orientation.coeffs()[c];
    }
  }
}

TEST(ConfigurationFile, YamlFileIsRead) {
  TempDir dir(kPrefix);
  const Configuration configuration = readConfigurationFile(dir.write("objects.yaml", kYaml));
  ASSERT_EQ(configuration.size(), 3u);
  EXPECT_EQ(configuration[0].key, (ObjectKey{"Cup", "1"}));
  EXPECT_EQ(configuration[1].key, (ObjectKey{"Cup", "2"}));
  EXPECT_EQ(configuration[2].key, (ObjectKey{"PlateDeep", ""})) << "id is optional";
  EXPECT_EQ(configuration[0].pose.position, Eigen::Vector3d(1.0, 2.0, 0.75));
  EXPECT_EQ(configuration[1].pose.position, Eigen::Vector3d(-0.25, 0.15, 0.8));
  EXPECT_NEAR(configuration[1].pose.orientation.angularDistance(
                  Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()))),
              0.0, 1e-12);
}

TEST(ConfigurationFile, JsonFileReadsAsTheEquivalentYaml) {
  TempDir dir(kPrefix);
  const Configuration from_yaml = readConfigurationFile(dir.write("objects.yaml", kYaml));
  const Configuration from_json = readConfigurationFile(dir.write("objects.json", kJson));
  expectSameConfiguration(from_json, from_yaml);
}

Configuration randomConfiguration(std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-3.0, 3.0);
  // Text that YAML would otherwise read as syntax, or not as a string at all.
  const std::vector<ObjectKey> keys = {
      {"Cup", "1"},
      {"Plate \"deep\"", "it's: 2"},
      {"  spaced type  ", "a b"},
      {"colon:type", ":"},
      {"back\\slash", "#not a comment"},
      {"- dash", "[1, 2]"},
      {"{braces}", "null"},
      {"true", "007"},
      {"Tasse", "ümlaut"},
      {"tab\there", ""},
      {"two\nlines\r\n", "bell\a\x7f"},
  };
  Configuration configuration;
  for (const ObjectKey& key : keys) {
    const Eigen::Vector3d axis(uniform(random), uniform(random), uniform(random));
    const Pose pose(Eigen::Vector3d(uniform(random), uniform(random), uniform(random)),
                    Eigen::Quaterniond(Eigen::AngleAxisd(uniform(random), axis.normalized())));
    configuration.push_back({key, pose});
  }
  // Values whose shortest decimal form is long, tiny, the largest accepted or signed zero.
  configuration[0].pose.position = Eigen::Vector3d(0.1 + 0.2, 1e-300, -0.0);
  configuration[1].pose.position =
      Eigen::Vector3d(std::nextafter(kMaxCoordinate, 0.0), -123.456789123456789, 5e-324);
  return configuration;
}

TEST(ConfigurationFile, RoundTripKeepsPosesBitForBitAndKeysVerbatim) {
  TempDir dir(kPrefix);
  for (std::uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::string path = dir.file("objects_" + std::to_string(seed) + ".yaml");
    const Configuration written = randomConfiguration(seed);
    writeConfigurationFile(path, written);
    expectSameConfiguration(readConfigurationFile(path), written);
  }
}

TEST(ConfigurationFile, EmptyConfigurationRoundTrips) {
  TempDir dir(kPrefix);
  const std::string path = dir.file("empty.yaml");
  writeConfigurationFile(path, {});
  EXPECT_TRUE(readConfigurationFile(path).empty());
  EXPECT_TRUE(readConfigurationFile(dir.write("empty.json", R"({"objects": []})")).empty());
}

std::string singleObject(const std::string& orientation) {
  return "objects:\n  - type: Cup\n    id: \"1\"\n    pose:\n      position: {x: 1, y: 2, z: 3}\n"
         "      orientation: " +
         orientation + "\n";
}

TEST(ConfigurationFile, NearlyUnitQuaternionIsNormalisedAndCanonical) {
  TempDir dir(kPrefix);
  const Configuration read = readConfigurationFile(
      dir.write("objects.yaml", singleObject("{x: 0.0002, y: 0, z: 0, w: -1.0004}")));
  ASSERT_EQ(read.size(), 1u);
  EXPECT_NEAR(read[0].pose.orientation.norm(), 1.0, 1e-15);
  EXPECT_GE(read[0].pose.orientation.w(), 0.0) << "q and -q are one rotation; w >= 0 is kept";
  const double norm = std::sqrt(0.0002 * 0.0002 + 1.0004 * 1.0004);
  EXPECT_NEAR(read[0].pose.orientation.x(), -0.0002 / norm, 1e-15);
  EXPECT_NEAR(read[0].pose.orientation.w(), 1.0004 / norm, 1e-15);
}

TEST(ConfigurationFile, OmittedQuaternionComponentsAreZeroAsInRosMessages) {
  TempDir dir(kPrefix);
  const Configuration identity =
      readConfigurationFile(dir.write("identity.yaml", singleObject("{w: 1}")));
  ASSERT_EQ(identity.size(), 1u);
  EXPECT_TRUE(identity[0].pose.orientation.isApprox(Eigen::Quaterniond::Identity(), 1e-15));
  const Configuration turned =
      readConfigurationFile(dir.write("turned.yaml", singleObject("{z: 0.6, w: 0.8}")));
  ASSERT_EQ(turned.size(), 1u);
  EXPECT_TRUE(turned[0].pose.orientation.isApprox(Eigen::Quaterniond(0.8, 0, 0, 0.6), 1e-15));
  // Left out is 0, never "whatever makes it a unit quaternion": {z: 0.6} has norm 0.6.
  const std::string path = dir.write("short.yaml", singleObject("{z: 0.6}"));
  const std::string message = inputErrorOf([&] { readConfigurationFile(path); });
  EXPECT_NE(message.find("not normalised"), std::string::npos) << message;
  EXPECT_NE(message.find("Cup:1"), std::string::npos) << message;
}

// ---- errors: each names the file, and the object where there is one ----

// The message of reading `text` as a configuration file; checks that it names the file.
std::string readError(const TempDir& dir, const std::string& text,
                      const std::string& name = "objects.yaml") {
  const std::string path = dir.write(name, text);
  const std::string message = inputErrorOf([&] { readConfigurationFile(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  return message;
}

TEST(ConfigurationFileErrors, MissingFile) {
  TempDir dir(kPrefix);
  const std::string path = dir.file("absent.yaml");
  EXPECT_NE(inputErrorOf([&] { readConfigurationFile(path); }).find(path), std::string::npos);
  EXPECT_FALSE(fs::exists(path));
}

TEST(ConfigurationFileErrors, FolderInsteadOfAFile) {
  TempDir dir(kPrefix);
  const std::string message = inputErrorOf([&] { readConfigurationFile(dir.path()); });
  EXPECT_NE(message.find(dir.path()), std::string::npos) << message;
}

TEST(ConfigurationFileErrors, MalformedYamlNamesTheLine) {
  TempDir dir(kPrefix);
  const std::string message = readError(dir, "objects:\n  - type: Cup\n    pose: {position: [\n");
  EXPECT_NE(message.find("malformed"), std::string::npos) << message;
  EXPECT_NE(message.find("line"), std::string::npos) << message;
}

TEST(ConfigurationFileErrors, MalformedJson) {
  TempDir dir(kPrefix);
  const std::string message = readError(
      dir, R"({"objects": [{"type": "Cup", "pose": {"position": {"x": 1,}})", "objects.json");
  EXPECT_NE(message.find("malformed"), std::string::npos) << message;
}

TEST(ConfigurationFileErrors, NoObjectsList) {
  TempDir dir(kPrefix);
  EXPECT_NE(readError(dir, "").find("'objects'"), std::string::npos);
  EXPECT_NE(readError(dir, "# only a comment\n").find("'objects'"), std::string::npos);
  EXPECT_NE(readError(dir, "things: []\n").find("'objects'"), std::string::npos);
  EXPECT_NE(readError(dir, "- type: Cup\n").find("'objects'"), std::string::npos);
  EXPECT_NE(readError(dir, R"({"object": []})", "objects.json").find("'objects'"),
            std::string::npos);
}

TEST(ConfigurationFileErrors, ObjectsIsNotAList) {
  TempDir dir(kPrefix);
  EXPECT_NE(readError(dir, "objects: {type: Cup}\n").find("not a list"), std::string::npos);
  EXPECT_NE(readError(dir, "objects: 3\n").find("not a list"), std::string::npos);
  EXPECT_NE(readError(dir, R"({"objects": "Cup"})", "objects.json").find("not a list"),
            std::string::npos);
}

// A second object (index 1) after a valid first one, with `pose_text` as its pose mapping.
std::string secondObject(const std::string& type_and_id, const std::string& pose_text) {
  return "objects:\n"
         "  - {type: Plate, id: '1', pose: {position: {x: 0, y: 0, z: 0}, "
         "orientation: {x: 0, y: 0, z: 0, w: 1}}}\n"
         "  - {" +
         type_and_id + (type_and_id.empty() ? "" : ", ") + pose_text + "}\n";
}

const std::string kGoodPose =
    "pose: {position: {x: 1, y: 2, z: 3}, orientation: {x: 0, y: 0, "
    "z: 0, w: 1}}";

TEST(ConfigurationFileErrors, MissingOrEmptyType) {
  TempDir dir(kPrefix);
  for (const std::string& type :
       {std::string(""), std::string("id: '7'"), std::string("type: '', id: '7'"),
        std::string("type: ~"), std::string("type: [a, b]")}) {
    SCOPED_TRACE(type);
    const std::string message = readError(dir, secondObject(type, kGoodPose));
    EXPECT_NE(message.find("object 1"), std::string::npos) << message;
    EXPECT_NE(message.find("'type'"), std::string::npos) << message;
  }
}

TEST(ConfigurationFileErrors, ObjectThatIsNotAMapping) {
  TempDir dir(kPrefix);
  const std::string message = readError(dir, "objects:\n  - Cup\n");
  EXPECT_NE(message.find("object 0"), std::string::npos) << message;
}

TEST(ConfigurationFileErrors, MissingPoseFields) {
  TempDir dir(kPrefix);
  struct Case {
    std::string pose;
    std::string field;
  };
  const std::vector<Case> cases = {
      {"", "'pose'"},
      {"pose: {orientation: {x: 0, y: 0, z: 0, w: 1}}", "'position'"},
      {"pose: {position: {x: 1, y: 2, z: 3}}", "'orientation'"},
      {"pose: {position: {x: 1, z: 3}, orientation: {x: 0, y: 0, z: 0, w: 1}}", "'y'"},
      // Omitted quaternion components are 0, as in ROS messages: this one is all zero.
      {"pose: {position: {x: 1, y: 2, z: 3}, orientation: {x: 0, y: 0, z: 0}}", "zero quaternion"},
      {"pose: {position: {x: 1, y: 2, z: 3}, orientation: {}}", "zero quaternion"},
      {"pose: [1, 2, 3]", "'pose'"},
      {"pose: {position: 3, orientation: {x: 0, y: 0, z: 0, w: 1}}", "'position'"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.pose);
    const std::string message = readError(dir, secondObject("type: Cup, id: '7'", c.pose));
    EXPECT_NE(message.find("object 1 (Cup:7)"), std::string::npos) << message;
    EXPECT_NE(message.find(c.field), std::string::npos) << message;
  }
}

TEST(ConfigurationFileErrors, NonNumberField) {
  TempDir dir(kPrefix);
  for (const std::string& value : {std::string("abc"), std::string("'1.0.0'"), std::string("[1]"),
                                   std::string("{a: 1}"), std::string("~")}) {
    SCOPED_TRACE(value);
    const std::string message =
        readError(dir, secondObject("type: Cup, id: '7'", "pose: {position: {x: 1, y: " + value +
                                                              ", z: 3}, orientation: {x: 0, y: 0, "
                                                              "z: 0, w: 1}}"));
    EXPECT_NE(message.find("object 1 (Cup:7)"), std::string::npos) << message;
    EXPECT_NE(message.find("'y'"), std::string::npos) << message;
    EXPECT_NE(message.find("not a number"), std::string::npos) << message;
  }
  const std::string json = readError(dir,
                                     R"({"objects": [{"type": "Cup", "pose": {
                                       "position": {"x": 1, "y": true, "z": 3},
                                       "orientation": {"x": 0, "y": 0, "z": 0, "w": 1}}}]})",
                                     "objects.json");
  EXPECT_NE(json.find("object 0 (Cup)"), std::string::npos) << json;
  EXPECT_NE(json.find("not a number"), std::string::npos) << json;
}

TEST(ConfigurationFileErrors, NotFiniteValues) {
  TempDir dir(kPrefix);
  for (const char* pose : {"pose: {position: {x: 1, y: .nan, z: 3}, "
                           "orientation: {x: 0, y: 0, z: 0, w: 1}}",
                           "pose: {position: {x: 1, y: 2, z: 3}, "
                           "orientation: {x: 0, y: 0, z: 0, w: .NaN}}",
                           "pose: {position: {x: -.inf, y: 2, z: 3}, "
                           "orientation: {x: 0, y: 0, z: 0, w: 1}}"}) {
    SCOPED_TRACE(pose);
    const std::string message = readError(dir, secondObject("type: Cup, id: '7'", pose));
    EXPECT_NE(message.find("object 1 (Cup:7)"), std::string::npos) << message;
    EXPECT_NE(message.find("not finite"), std::string::npos) << message;
  }
}

TEST(ConfigurationFileErrors, ZeroQuaternion) {
  TempDir dir(kPrefix);
  const std::string message = readError(dir, singleObject("{x: 0, y: 0, z: 0, w: 0}"));
  EXPECT_NE(message.find("object 0 (Cup:1)"), std::string::npos) << message;
  EXPECT_NE(message.find("zero quaternion"), std::string::npos) << message;
}

TEST(ConfigurationFileErrors, QuaternionFarFromUnitLength) {
  TempDir dir(kPrefix);
  for (const char* orientation : {"{x: 0, y: 0, z: 0, w: 1.01}", "{x: 0.5, y: 0.5, z: 0, w: 0}",
                                  "{x: 0, y: 0, z: 0, w: 1e-9}"}) {
    SCOPED_TRACE(orientation);
    const std::string message = readError(dir, singleObject(orientation));
    EXPECT_NE(message.find("object 0 (Cup:1)"), std::string::npos) << message;
    EXPECT_NE(message.find("normalised"), std::string::npos) << message;
  }
}

// ---- writing: never over an existing file unless told, never half a file ----

TEST(ConfigurationFileWriting, ExistingFileIsKeptUnlessOverwriteIsAsked) {
  TempDir dir(kPrefix);
  const std::string path = dir.write("objects.yaml", kYaml);
  const Configuration replacement = randomConfiguration(9);
  const std::string message = inputErrorOf([&] { writeConfigurationFile(path, replacement); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_EQ(fileBytes(path), kYaml);

  writeConfigurationFile(path, replacement, true);
  expectSameConfiguration(readConfigurationFile(path), replacement);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"objects.yaml"}) << "no temporary file left";
}

TEST(ConfigurationFileWriting, MissingFolderIsNamedAndNothingIsCreated) {
  TempDir dir(kPrefix);
  const std::string path = dir.file("missing_folder/objects.yaml");
  const std::string message = inputErrorOf([&] { writeConfigurationFile(path, {}); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ConfigurationFileWriting, TargetThatCannotBeReplacedIsLeftAsItWas) {
  TempDir dir(kPrefix);
  // A non-empty folder under the target name: the rename fails after the text is written.
  const std::string path = dir.file("objects.yaml");
  fs::create_directories(path + "/inside");
  const std::string message =
      inputErrorOf([&] { writeConfigurationFile(path, randomConfiguration(3), true); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_TRUE(fs::is_directory(path + "/inside"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"objects.yaml"}) << "temporary file removed";
}

// Limits the size of files this process writes (as a full disk would) while it lives.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);  // a failing write, not a killed test
    getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit limit = previous_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previous_handler_);
  }

 private:
  rlimit previous_{};
  void (*previous_handler_)(int) = nullptr;
};

TEST(ConfigurationFileWriting, FailedWriteLeavesTheOldFileWhole) {
  TempDir dir(kPrefix);
  const std::string path = dir.write("objects.yaml", kYaml);
  Configuration large;
  for (std::uint32_t seed = 0; seed < 100; ++seed) {
    for (const ObjectEstimate& estimate : randomConfiguration(seed))
      large.push_back(estimate);
  }
  std::string message;
  {
    const FileSizeLimit limit(4096);
    message = inputErrorOf([&] { writeConfigurationFile(path, large, true); });
  }
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_EQ(fileBytes(path), kYaml);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"objects.yaml"}) << "temporary file removed";
}

}  // namespace
}  // namespace asr_ism
