// `asr_node_bench` (`./asr bench node`, which starts a ROS master for it): the scene_recognizer
// node against the library. (1) End-to-end latency of the recognize_scenes service for every
// recorded set of gedeck with a complete topology, against the library's own recognition of the
// same sets; target: within 2x. (2) The rate at which scene_instances are published in
// continuous mode with the trees of all ten kitchen scenes loaded; target: >= 10 Hz. (3) The
// longest gap between two lists on scene_instances while a heavy recognize_scenes call (every
// scene on the kitchen estimates and gedeck set 5 repeated with jitter to 200 estimates, about
// half a second of work) runs; target: at most two periods (the call delays the continuous output
// by at most one period). (4) With every object seen anew (moved up to 1 cm) every period, so
// that every scene is recognised anew, the badly seen ones taking longer than a period: the rate
// of lists, of fresh ones, and how old each scene's content is; target: >= 10 Hz, gaps <= two
// periods.
#include <asr_msgs/ObjectEstimateList.h>
#include <asr_msgs/RecognizeScenes.h>
#include <asr_msgs/SceneInstanceList.h>
#include <ros/ros.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "asr_common/child_process.hpp"
#include "asr_common/cli/recordings_folder.hpp"
#include "asr_common/cli/targets.hpp"
#include "asr_common/cli/timing.hpp"
#include "asr_common/recordings.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/continuous_recognition.hpp"
#include "asr_ism_tree/scene_models.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "clutter_series.hpp"

namespace {

using namespace asr_ism_tree;

constexpr int kRepetitions = 5;       // per set; the fastest counts, as in asr_bench
constexpr double kRateWindow = 10.0;  // s of publishing to average the rate over
constexpr int kAskedHz = 20;          // the node's rate: twice the target, to show the headroom

std::vector<asr_msgs::ObjectEstimate> messagesOf(const asr_common::Configuration& configuration) {
  std_msgs::Header header;
  header.frame_id = "map";
  header.stamp = ros::Time::now();
  std::vector<asr_msgs::ObjectEstimate> messages;
  for (const asr_common::ObjectEstimate& estimate : configuration)
    messages.push_back(asr_common::ros_interface::toEstimateMessage(estimate, header));
  return messages;
}

// Gedeck's recorded set 5 repeated with 2 cm / 3 deg jitter up to `count` estimates.
asr_common::Configuration clutteredGedeck(const std::string& recordings, std::size_t count) {
  const auto recorded =
      bench::clutterDemonstration(recordings).configuration(bench::kClutterRecordedSet);
  return bench::clutteredCopies(recorded, count, 1);
}

// A failure that ends the benchmark: the node did not start or did not answer.
struct BenchmarkFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Latency {
  std::vector<double> library_ms;  // fastest of kRepetitions per recorded set
  std::vector<double> node_ms;
};

// (1) The recognize_scenes service of a scene_recognizer loaded with `model` against the
// library's recognition with the same tree, for every recorded set of `demonstration`.
Latency measureLatency(const std::string& nodes, const asr_ism::Demonstration& demonstration,
                       const IsmTree& tree, const std::string& model, ros::NodeHandle& handle) {
  const TreeRecognizer recognizer(tree);
  asr_common::ChildProcess node(
      nodes + "/scene_recognizer",
      {"__name:=bench_recognizer", "_model_files:=" + model, "_continuous:=false"});
  if (!ros::service::waitForService("recognize_scenes", ros::Duration(30)))
    throw BenchmarkFailure("the scene_recognizer did not start");
  // Persistent: one connection, as a node that asks often.
  ros::ServiceClient client =
      handle.serviceClient<asr_msgs::RecognizeScenes>("recognize_scenes", true);
  Latency latency;
  for (std::size_t set = 0; set < demonstration.stepCount(); ++set) {
    const asr_common::Configuration configuration = demonstration.configuration(set);
    double best_library = 1e9;
    double best_node = 1e9;
    for (int repetition = 0; repetition < kRepetitions; ++repetition) {
      best_library =
          std::min(best_library,
                   asr_common::cli::millisecondsOf([&] { recognizer.recognize(configuration); }));
      asr_msgs::RecognizeScenes service;
      service.request.objects = messagesOf(configuration);
      bool answered = false;
      best_node = std::min(
          best_node, asr_common::cli::millisecondsOf([&] { answered = client.call(service); }));
      if (!answered || service.response.instances.empty())
        throw BenchmarkFailure("the service call for set " + std::to_string(set) + " failed");
    }
    latency.library_ms.push_back(best_library);
    latency.node_ms.push_back(best_node);
  }
  return latency;
}

// The complete trees of the ten kitchen scenes, stored in `work`; their model files.
std::vector<std::string> saveKitchenModels(const std::string& recordings,
                                           const std::filesystem::path& work) {
  std::vector<std::string> model_files;
  for (const asr_common::cli::KitchenScene& kitchen : asr_common::cli::kitchenScenes()) {
    const asr_ism::Demonstration demonstration =
        asr_ism::sqlite::readDemonstration(recordings + "/" + kitchen.file, kitchen.scene);
    const std::string model = (work / (std::string(kitchen.scene) + ".sqlite")).string();
    sqlite::saveIsmTree(
        model,
        generateIsmTree(demonstration, RelationTopology::complete(demonstration.objects()), {}),
        "asr_node_bench");
    model_files.push_back(model);
  }
  return model_files;
}

// Every estimate of every kitchen scene's first set, in scene order: all ten trees have work.
asr_common::Configuration kitchenFirstSets(const std::string& recordings) {
  asr_common::Configuration all;
  for (const asr_common::cli::KitchenScene& kitchen : asr_common::cli::kitchenScenes()) {
    const asr_common::Configuration configuration =
        asr_ism::sqlite::readDemonstration(recordings + "/" + kitchen.file, kitchen.scene)
            .configuration(0);
    all.insert(all.end(), configuration.begin(), configuration.end());
  }
  return all;
}

// One estimate per object, as the node keeps: scenes share objects.
asr_common::Configuration onePerObject(const asr_common::Configuration& estimates) {
  asr_common::Configuration kept;
  for (const asr_common::ObjectEstimate& estimate : estimates) {
    if (std::none_of(kept.begin(), kept.end(),
                     [&](const auto& other) { return other.key == estimate.key; }))
      kept.push_back(estimate);
  }
  return kept;
}

struct Tick {
  double serial_ms = 0.0;    // every scene anew, one thread
  double parallel_ms = 0.0;  // every scene anew, one thread per core (the node's default)
  unsigned threads = 0;
  // One object seen 1 cm elsewhere (each of `objects` in turn): the scenes with its type are
  // recognised anew, each on its thread (ContinuousRecognition).
  std::size_t objects = 0;
  double moved_mean_scenes = 0.0;
  double moved_mean_ms = 0.0;
  double moved_max_ms = 0.0;
};

// The fastest of kRepetitions of `tick` after `prepare` (untimed).
template <typename Prepare, typename Run>
double fastestMs(Prepare prepare, Run tick) {
  double fastest = 1e9;
  for (int repetition = 0; repetition < kRepetitions; ++repetition) {
    prepare();
    fastest = std::min(fastest, asr_common::cli::millisecondsOf(tick));
  }
  return fastest;
}

// What one tick of the continuous mode costs in the library: every tree on every estimate, on
// one thread and on the pool, and where one object moved (IncrementalRecognition).
Tick measureTick(const std::vector<std::string>& model_files,
                 const asr_common::Configuration& estimates) {
  const asr_common::Configuration everything = onePerObject(estimates);
  Tick tick;
  const SceneModels serial = SceneModels::load(model_files, {}, {}, 1);
  tick.serial_ms = fastestMs([] {}, [&] { serial.recognize(everything); });
  const auto models = std::make_shared<const SceneModels>(SceneModels::load(model_files));
  tick.threads = asr_ism::ThreadPool().threadCount();
  tick.parallel_ms = fastestMs([] {}, [&] { models->recognize(everything); });
  // A detector that sees one object anew: each object in turn moved 1 cm, after the estimates
  // before were recognised (one run each; the scenes with its type are recognised anew).
  std::atomic<bool> failed{false};  // set on the scenes' threads
  ContinuousRecognition continuous([&failed](std::exception_ptr) { failed = true; },
                                   ContinuousPace{0, 1.0 / kAskedHz});  // as the node paces it
  // Offered again every millisecond, as the node's ticks would, until every scene's result is
  // of `configuration` (a slow scene may wait for a slot); how many scenes were recognised.
  const auto recognizeAll = [&](const asr_common::Configuration& configuration) {
    const auto offered = std::make_shared<const asr_common::Configuration>(configuration);
    do {
      continuous.offer(models, offered, 0);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    } while (!continuous.settled() && !failed);
    return continuous.latest().fresh;
  };
  for (std::size_t object = 0; object < everything.size(); ++object) {
    asr_common::Configuration moved = everything;
    moved[object].pose.position.x() += 0.01;
    recognizeAll(everything);
    std::size_t scenes = 0;
    const double ms = asr_common::cli::millisecondsOf([&] { scenes = recognizeAll(moved); });
    tick.moved_mean_ms += ms / static_cast<double>(everything.size());
    tick.moved_max_ms = std::max(tick.moved_max_ms, ms);
    tick.moved_mean_scenes += static_cast<double>(scenes) / everything.size();
  }
  if (failed)
    throw BenchmarkFailure("a continuous recognition failed");
  tick.objects = everything.size();
  return tick;
}

struct Rate {
  double achieved_hz = 0.0;
  std::size_t instances_seen = 0;  // most instances in one list
  // (3) A heavy recognize_scenes call while the timer publishes.
  double heavy_call_s = 0.0;
  double longest_gap_s = 0.0;
  std::string heavy_message;
  std::size_t heavy_instances = 0;
  // (4) Every object moved every period. A scene's age in a list: its arrival minus the stamp
  // of that scene's instances (the time of the estimates they were recognised from).
  double moving_hz = 0.0;
  double moving_fresh_hz = 0.0;  // lists where some scene is newer than in the one before
  double moving_longest_gap_s = 0.0;
  double moving_median_age_s = 0.0;         // over lists and scenes
  double moving_median_oldest_age_s = 0.0;  // over lists, of each list's oldest scene
  double moving_max_age_s = 0.0;
  double moving_first_fresh_s = 0.0;  // the first scene recognised from moved estimates: its age
  double moving_all_fresh_s = 0.0;    // until every scene had been (from the first moved ones)
  std::map<std::string, double> moving_median_age_of_scene;
};

// A list with instances as it arrived: the stamp of each scene's instances.
struct Arrival {
  ros::WallTime at;
  std::map<std::string, ros::Time> scene_stamps;
};

// The stamp of each scene's instances in `list`.
std::map<std::string, ros::Time> sceneStamps(const asr_msgs::SceneInstanceList& list) {
  std::map<std::string, ros::Time> stamps;
  for (const asr_msgs::SceneInstance& instance : list.instances)
    stamps[instance.scene] = instance.header.stamp;
  return stamps;
}

// Whether some scene's instances in `later` are of newer estimates than in `earlier`.
bool someSceneNewer(const Arrival& earlier, const Arrival& later) {
  return std::any_of(later.scene_stamps.begin(), later.scene_stamps.end(), [&](const auto& entry) {
    const auto before = earlier.scene_stamps.find(entry.first);
    return before == earlier.scene_stamps.end() || entry.second > before->second;
  });
}

double longestGap(const std::vector<Arrival>& arrivals, std::size_t from, ros::WallTime end) {
  double longest = 0.0;
  for (std::size_t i = from + 1; i < arrivals.size(); ++i)
    longest = std::max(longest, (arrivals[i].at - arrivals[i - 1].at).toSec());
  return std::max(longest, (end - arrivals.back().at).toSec());
}

// Rate over the steady part: lists with instances within kRateWindow of the first.
double steadyRate(const std::vector<Arrival>& arrivals) {
  std::size_t last = 0;
  while (last + 1 < arrivals.size() &&
         (arrivals[last + 1].at - arrivals.front().at).toSec() <= kRateWindow)
    ++last;
  return last > 0 ? last / (arrivals[last].at - arrivals.front().at).toSec() : 0.0;
}

// (3) Runs a heavy recognize_scenes call on the node's other thread while the timer keeps
// publishing; records the call and the longest gap between lists arriving in `arrivals`.
void measureHeavyCallGap(const std::string& recordings, const asr_common::Configuration& estimates,
                         const std::vector<Arrival>& arrivals, ros::NodeHandle& handle,
                         Rate& rate) {
  asr_msgs::RecognizeScenes heavy;  // every scene: repeated detections alone are merged quickly
  asr_common::Configuration objects = estimates;
  const asr_common::Configuration clutter = clutteredGedeck(recordings, 200);
  objects.insert(objects.end(), clutter.begin(), clutter.end());
  heavy.request.objects = messagesOf(objects);
  ros::ServiceClient client = handle.serviceClient<asr_msgs::RecognizeScenes>("recognize_scenes");
  if (!client.waitForExistence(ros::Duration(10)) || arrivals.empty())
    throw BenchmarkFailure("the continuous scene_recognizer did not answer or publish");
  bool heavy_done = false;
  const std::size_t before = arrivals.size();
  const ros::WallTime call_start = ros::WallTime::now();
  std::thread caller([&] {
    client.call(heavy);
    rate.heavy_call_s = (ros::WallTime::now() - call_start).toSec();
    heavy_done = true;
  });
  while (!heavy_done) {
    ros::spinOnce();
    ros::WallDuration(0.002).sleep();
  }
  caller.join();
  rate.heavy_message = heavy.response.message;
  rate.heavy_instances = heavy.response.instances.size();
  rate.longest_gap_s = longestGap(arrivals, before - 1, ros::WallTime::now());
}

// (4) Publishes `estimates` every period for kRateWindow seconds, each object moved up to 1 cm
// (a fixed seed), and measures the lists that arrive meanwhile.
void measureEverythingMoving(const asr_common::Configuration& estimates, ros::Publisher& objects,
                             const std::vector<Arrival>& arrivals, Rate& rate) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-0.01, 0.01);
  const std::size_t before = arrivals.size();
  const ros::WallTime start = ros::WallTime::now();
  while (ros::WallTime::now() - start < ros::WallDuration(kRateWindow)) {
    asr_common::Configuration moved = estimates;
    for (asr_common::ObjectEstimate& estimate : moved)
      estimate.pose.position += Eigen::Vector3d(shift(random), shift(random), shift(random));
    asr_msgs::ObjectEstimateList list;
    list.objects = messagesOf(moved);
    objects.publish(list);
    const ros::WallTime next = ros::WallTime::now() + ros::WallDuration(1.0 / kAskedHz);
    while (ros::WallTime::now() < next) {
      ros::spinOnce();
      ros::WallDuration(0.002).sleep();
    }
  }
  const ros::WallTime end = ros::WallTime::now();
  if (arrivals.size() <= before)
    throw BenchmarkFailure("no list arrived while every object moved");
  const double seconds = (end - start).toSec();
  // Ages count from the first results recognised on moved estimates (those before repeat a
  // result of estimates published long before).
  const ros::Time moved_since(start.toSec());
  std::vector<double> ages;
  std::vector<double> oldest_ages;
  std::map<std::string, std::vector<double>> ages_of_scene;
  std::size_t fresh = 0;
  bool all_fresh = false;
  for (std::size_t i = before; i < arrivals.size(); ++i) {
    const Arrival& arrival = arrivals[i];
    double oldest = 0.0;
    bool every_scene_moved = true;
    for (const auto& [scene, stamp] : arrival.scene_stamps) {
      every_scene_moved = every_scene_moved && stamp >= moved_since;
      if (stamp < moved_since)
        continue;
      const double age = arrival.at.toSec() - stamp.toSec();
      if (ages.empty())
        rate.moving_first_fresh_s = age;
      ages.push_back(age);
      ages_of_scene[scene].push_back(age);
      oldest = std::max(oldest, age);
    }
    if (every_scene_moved) {
      oldest_ages.push_back(oldest);
      if (!all_fresh)
        rate.moving_all_fresh_s = (arrival.at - start).toSec();
      all_fresh = true;
    }
    fresh += someSceneNewer(arrivals[i - 1], arrival) ? 1 : 0;
  }
  if (oldest_ages.empty())
    throw BenchmarkFailure("no list with every scene of moved estimates arrived");
  rate.moving_hz = static_cast<double>(arrivals.size() - before) / seconds;
  rate.moving_fresh_hz = static_cast<double>(fresh) / seconds;
  rate.moving_longest_gap_s =
      std::max((arrivals[before].at - start).toSec(), longestGap(arrivals, before, end));
  rate.moving_median_age_s = asr_common::cli::median(ages);
  rate.moving_median_oldest_age_s = asr_common::cli::median(oldest_ages);
  rate.moving_max_age_s = *std::max_element(ages.begin(), ages.end());
  for (const auto& [scene, scene_ages] : ages_of_scene)
    rate.moving_median_age_of_scene[scene] = asr_common::cli::median(scene_ages);
}

// (2) The rate at which a continuous scene_recognizer with `model_files` publishes instances
// once it has `estimates`.
Rate measureRate(const std::string& nodes, const std::string& recordings,
                 const std::vector<std::string>& model_files,
                 const asr_common::Configuration& estimates, ros::NodeHandle& handle) {
  // A list parameter cannot be given on a command line: set it before the node starts.
  handle.setParam("/bench_continuous/model_files", model_files);
  asr_common::ChildProcess node(
      nodes + "/scene_recognizer",
      {"__name:=bench_continuous", "_rate:=" + std::to_string(kAskedHz), "_estimate_timeout:=0"});
  ros::Publisher objects = handle.advertise<asr_msgs::ObjectEstimateList>("objects", 10);
  Rate rate;
  std::vector<Arrival> arrivals;
  ros::Subscriber subscriber = handle.subscribe<asr_msgs::SceneInstanceList>(
      "scene_instances", 100, [&](const asr_msgs::SceneInstanceList::ConstPtr& list) {
        if (!list->instances.empty()) {
          arrivals.push_back({ros::WallTime::now(), sceneStamps(*list)});
          rate.instances_seen = std::max(rate.instances_seen, list->instances.size());
        }
      });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30);
  while ((objects.getNumSubscribers() == 0 || subscriber.getNumPublishers() == 0) &&
         ros::WallTime::now() < deadline) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  asr_msgs::ObjectEstimateList list;
  list.objects = messagesOf(estimates);  // the node keeps the newest estimate per object
  objects.publish(list);
  const ros::WallTime start = ros::WallTime::now();
  while (ros::WallTime::now() - start < ros::WallDuration(kRateWindow + 2.0)) {
    ros::spinOnce();
    ros::WallDuration(0.002).sleep();
  }
  rate.achieved_hz = steadyRate(arrivals);
  measureHeavyCallGap(recordings, estimates, arrivals, handle, rate);
  measureEverythingMoving(estimates, objects, arrivals, rate);
  return rate;
}

void printReport(const Latency& latency, const Tick& tick, const Rate& rate) {
  const double library_median = asr_common::cli::median(latency.library_ms);
  const double node_median = asr_common::cli::median(latency.node_ms);
  std::printf(
      "scene_recognizer node vs library (gedeck, complete topology, %zu recorded sets, "
      "fastest of %d per set)\n",
      latency.library_ms.size(), kRepetitions);
  std::printf("  library recognition: median %.3f ms\n", library_median);
  std::printf("  node service call:   median %.3f ms (%.2fx the library)\n", node_median,
              node_median / library_median);
  std::printf("continuous mode, ten kitchen scenes loaded (complete topologies), ~rate %d Hz:\n",
              kAskedHz);
  std::printf("  scene_instances published at %.2f Hz (up to %zu instances per list)\n",
              rate.achieved_hz, rate.instances_seen);
  std::printf(
      "  a tick recognising every scene anew (all ten trees on every estimate) takes %.1f ms in "
      "the library on one thread, %.1f ms on %u\n",
      tick.serial_ms, tick.parallel_ms, tick.threads);
  std::printf(
      "  a tick after one object moved 1 cm (each of the %zu in turn) recognises %.1f scenes anew "
      "on average: mean %.1f ms, max %.1f ms\n",
      tick.objects, tick.moved_mean_scenes, tick.moved_mean_ms, tick.moved_max_ms);
  std::printf(
      "  during a %.2f s recognize_scenes call of every scene on the kitchen estimates and 200 "
      "cluttered ones (%zu instances%s%s), the longest "
      "gap between two lists was %.3f s\n",
      rate.heavy_call_s, rate.heavy_instances, rate.heavy_message.empty() ? "" : ", ",
      rate.heavy_message.c_str(), rate.longest_gap_s);
  std::printf(
      "  with every object moved up to 1 cm every period (every scene recognised anew, each at "
      "its own pace): lists at %.2f Hz, %.2f Hz of them with some scene fresh; longest gap %.3f "
      "s; the first scene of moved estimates came %.3f s after them, every scene %.3f s after "
      "the first moved estimates; a scene's estimates were %.3f s old (median over lists and "
      "scenes) when its list arrived, the oldest scene's %.3f s (median over lists), %.3f s at "
      "most\n",
      rate.moving_hz, rate.moving_fresh_hz, rate.moving_longest_gap_s, rate.moving_first_fresh_s,
      rate.moving_all_fresh_s, rate.moving_median_age_s, rate.moving_median_oldest_age_s,
      rate.moving_max_age_s);
  std::printf("    median age per scene:");
  for (const auto& [scene, age] : rate.moving_median_age_of_scene)
    std::printf(" %s %.3f s,", scene.c_str(), age);
  std::printf("\n\n");
  char library[64], node[64], hz[64], gap[64], moving_hz[64], moving_gap[64];
  std::snprintf(library, sizeof library, "%.3f ms", library_median);
  std::snprintf(node, sizeof node, "%.3f ms", node_median);
  std::snprintf(hz, sizeof hz, "%.2f Hz", rate.achieved_hz);
  std::snprintf(gap, sizeof gap, "%.3f s", rate.longest_gap_s);
  std::snprintf(moving_hz, sizeof moving_hz, "%.2f Hz", rate.moving_hz);
  std::snprintf(moving_gap, sizeof moving_gap, "%.3f s", rate.moving_longest_gap_s);
  const double period_s = 1.0 / kAskedHz;
  std::ostringstream report;
  asr_common::cli::printTargets(
      report,
      {{std::string("service latency <= 2x the library's ") + library, node,
        node_median <= 2.0 * library_median},
       {"publishing rate >= 10 Hz with ten scenes loaded", hz, rate.achieved_hz >= 10.0},
       {"longest gap during a heavy service call <= 2 periods", gap,
        rate.longest_gap_s <= 2.0 * period_s},
       {"publishing rate >= 10 Hz with every object moving", moving_hz, rate.moving_hz >= 10.0},
       {"longest gap with every object moving <= 2 periods", moving_gap,
        rate.moving_longest_gap_s <= 2.0 * period_s}});
  std::fputs(report.str().c_str(), stdout);
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "asr_node_bench", ros::init_options::AnonymousName);
  const std::string recordings = asr_common::recordingsDirectory(ASR_RECORDINGS_DIR);
  if (recordings.empty()) {
    std::fprintf(
        stderr,
        "asr_node_bench: recordings not found (set ASR_RECORDINGS_DIR); nothing to measure\n");
    return 0;
  }
  const std::string nodes = argc > 1 ? argv[1] : ASR_NODE_DIR;
  const std::filesystem::path work =
      std::filesystem::temp_directory_path() / ("asr_node_bench_" + std::to_string(::getpid()));
  std::filesystem::create_directories(work);
  ros::NodeHandle handle;
  try {
    const asr_ism::Demonstration gedeck =
        asr_ism::sqlite::readDemonstration(recordings + "/story_1.sqlite", "gedeck");
    const IsmTree tree = generateIsmTree(gedeck, RelationTopology::complete(gedeck.objects()), {});
    const std::string gedeck_model = (work / "gedeck.sqlite").string();
    sqlite::saveIsmTree(gedeck_model, tree, "asr_node_bench");
    const Latency latency = measureLatency(nodes, gedeck, tree, gedeck_model, handle);

    const std::vector<std::string> model_files = saveKitchenModels(recordings, work);
    const asr_common::Configuration estimates = kitchenFirstSets(recordings);
    const Tick tick = measureTick(model_files, estimates);
    const Rate rate = measureRate(nodes, recordings, model_files, estimates, handle);
    std::filesystem::remove_all(work);
    printReport(latency, tick, rate);
  } catch (const std::exception& error) {
    std::filesystem::remove_all(work);
    std::fprintf(stderr, "asr_node_bench: %s\n", error.what());
    return 1;
  }
  return 0;
}
