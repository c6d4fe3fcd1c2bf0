#include "tag_commands.hpp"

#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/input_error.hpp"
#include "asr_robot_model/tag_camera_sim.hpp"
#include "asr_robot_model/tag_detector.hpp"
#include "asr_robot_model/tag_family.hpp"
#include "robot_json.hpp"
#include "tag_sheet_pdf.hpp"

namespace asr_robot_model::tools {

using asr_common::InputError;
using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;

namespace {

void print(const CommandLine& options, const nlohmann::json& result) {
  std::cout << (options.flag("json") ? result.dump() : result.dump(2)) << "\n";
}

TagMap tagMapOf(const CommandLine& options) {
  return loadTagMap(options.optional("tag-map", defaultTagMap()));
}

/// An 8-bit image as grey: colour is converted (and said so), other depths are refused.
GreyImage readGrey(const std::string& path) {
  const cv::Mat read = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (read.empty())
    throw InputError(path + ": cannot read the image");
  if (read.depth() != CV_8U)
    throw InputError(path + ": an 8-bit image is needed (this one has " +
                     std::to_string(8 * read.elemSize1()) + "-bit channels)");
  cv::Mat grey = read;
  if (read.channels() == 3 || read.channels() == 4) {
    cv::cvtColor(read, grey, read.channels() == 3 ? cv::COLOR_BGR2GRAY : cv::COLOR_BGRA2GRAY);
    std::cerr << "tags detect: " << path << ": colour image converted to grey\n";
  } else if (read.channels() != 1) {
    throw InputError(path + ": " + std::to_string(read.channels()) +
                     " channels; grey or colour is needed");
  }
  GreyImage image(grey.cols, grey.rows);
  for (int y = 0; y < grey.rows; ++y)
    for (int x = 0; x < grey.cols; ++x)
      image.at(x, y) = grey.at<std::uint8_t>(y, x);
  return image;
}

void writePng(const std::string& path, const cv::Mat& image) {
  if (path.size() < 4 || path.compare(path.size() - 4, 4, ".png") != 0)
    throw UsageError{"--out must name a .png file (" + path + ")"};
  bool written = false;
  try {
    written = cv::imwrite(path, image);
  } catch (const cv::Exception&) {
  }
  if (!written)
    throw InputError(path + ": cannot write the image");
}

nlohmann::json covarianceJson(const Eigen::Matrix<double, 6, 6>& covariance) {
  nlohmann::json values = nlohmann::json::array();
  for (int row = 0; row < 6; ++row)
    for (int column = 0; column < 6; ++column)
      values.push_back(covariance(row, column));
  return values;
}

}  // namespace

std::vector<int> idList(const std::string& text) {
  std::vector<int> ids;
  std::istringstream list(text);
  for (std::string part; std::getline(list, part, ',');) {
    int first = -1, last = -1;
    char dash = 0, rest = 0;
    std::istringstream range(part);
    range >> first;
    if (range >> dash) {
      if (dash != '-' || !(range >> last) || range >> rest)
        throw UsageError{"--ids: '" + part + "' is not an id or a range such as 0-11"};
    } else {
      last = first;
    }
    if (first < 0 || last < first || last - first > 10000)
      throw UsageError{"--ids: '" + part + "' is not an id or a range such as 0-11"};
    for (int id = first; id <= last; ++id)
      ids.push_back(id);
  }
  if (ids.empty())
    throw UsageError{"--ids: no ids given"};
  return ids;
}

int runTagsDetect(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments, {"image", "camera-info", "tag-map", "decimate"}, {"json"});
  const GreyImage image = readGrey(options.required("image"));
  const CameraIntrinsics camera = loadCameraInfo(options.required("camera-info"));
  if (camera.width != image.width || camera.height != image.height)
    throw InputError(options.required("camera-info") +
                     ": image_width/image_height: " + std::to_string(camera.width) + " x " +
                     std::to_string(camera.height) + " but the image is " +
                     std::to_string(image.width) + " x " + std::to_string(image.height));
  TagDetectorSettings settings;
  settings.decimate = options.number("decimate", settings.decimate);
  const TagDetector detector(tagMapOf(options), settings);
  const TagDetections found = detector.detect(image, camera);
  nlohmann::json tags = nlohmann::json::array(), objects = nlohmann::json::array();
  for (const TagEstimate& tag : found.tags)
    tags.push_back(
        {{"id", tag.id}, {"pose", poseJson(tag.pose)}, {"reprojection_px", tag.reprojection_px}});
  for (const ObjectDetection& object : found.objects)
    objects.push_back({{"type", object.key.type},
                       {"id", object.key.id},
                       {"pose", poseJson(object.pose)},
                       {"covariance", covarianceJson(object.covariance)},
                       {"tags", object.tags},
                       {"reprojection_px", object.reprojection_px}});
  print(options, {{"tags", tags},
                  {"objects", objects},
                  {"unknown_ids", found.unknown_ids},
                  {"refused", found.refused}});
  return 0;
}

int runTagsRender(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments,
                            {"world", "catalogue", "camera", "out", "tag-map", "camera-info",
                             "save-camera-info", "seed", "noise", "blur"},
                            {"no-occlusion"});
  const World world =
      loadWorld(options.required("world"),
                loadObjectCatalogue(options.optional("catalogue", defaultObjectCatalogue())));
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
  poseOption(options, "camera", position, orientation);
  const asr_common::Pose camera = asr_common::validatedPose(position, orientation, "--camera");
  const std::string out = options.required("out");
  CameraSimSettings settings;
  if (options.has("camera-info"))
    settings.camera = loadCameraInfo(options.required("camera-info"));
  settings.noise_sigma = options.number("noise", settings.noise_sigma);
  settings.blur_sigma = options.number("blur", settings.blur_sigma);
  settings.occlusion = !options.flag("no-occlusion");
  const TagCameraSim simulator(world, tagMapOf(options), settings);
  const GreyImage image =
      simulator.render(camera, static_cast<unsigned>(options.integer("seed", 0, 0, 4294967295LL)));
  writePng(out, cv::Mat(image.height, image.width, CV_8U,
                        const_cast<std::uint8_t*>(image.pixels.data())));
  if (options.has("save-camera-info"))
    saveCameraInfo(options.required("save-camera-info"), settings.camera);
  return 0;
}

namespace {

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

/// A PNG sheet, `cell` pixels per cell of the family's bitmap, four tags a row.
void printPng(const std::string& out, const TagFamily& family, const std::vector<int>& ids,
              int cell) {
  const int side = family.totalWidth() * cell, label = 3 * cell, gap = cell;
  const int columns = std::min<int>(4, static_cast<int>(ids.size()));
  const int rows = (static_cast<int>(ids.size()) + columns - 1) / columns;
  cv::Mat sheet(rows * (side + label) + gap, columns * (side + gap) + gap, CV_8U, cv::Scalar(255));
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const GreyImage bitmap = family.bitmap(ids[i]);
    const int left = gap + static_cast<int>(i % columns) * (side + gap);
    const int top = gap + static_cast<int>(i / columns) * (side + label);
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        sheet.at<std::uint8_t>(top + y, left + x) = bitmap.at(x / cell, y / cell);
    cv::putText(sheet, family.name() + " id " + std::to_string(ids[i]),
                {left + cell, top + side + label / 2}, cv::FONT_HERSHEY_SIMPLEX, cell / 24.0,
                cv::Scalar(0), std::max(1, cell / 12));
  }
  writePng(out, sheet);
}

}  // namespace

int runTagsPrint(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments, {"ids", "out", "family", "tag-map", "cell-px", "edge-mm"},
                            {});
  const std::vector<int> ids = idList(options.required("ids"));
  const std::string out = options.required("out");
  const TagMap map = tagMapOf(options);
  const TagFamily family(options.has("family") ? options.required("family") : map.family);
  if (!endsWith(out, ".pdf")) {
    printPng(out, family, ids, static_cast<int>(options.integer("cell-px", 24, 2, 200)));
    return 0;
  }
  // True size: the tag map's edge length for the tags it places (in its family), else --edge-mm.
  const double edge_mm = options.number("edge-mm", 50.0);
  if (!(edge_mm >= 5.0 && edge_mm <= 1000.0))
    throw UsageError{"--edge-mm must be 5 to 1000 (millimetres)"};
  std::vector<PrintedTag> tags;
  for (const int id : ids) {
    const TagPlacement* placement = family.name() == map.family ? map.find(id) : nullptr;
    tags.push_back({id, placement ? 1000.0 * placement->edge_length : edge_mm});
  }
  writeTagSheetPdf(out, family, tags);
  return 0;
}

}  // namespace asr_robot_model::tools
