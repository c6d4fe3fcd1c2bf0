#include "asr_state_machine/search_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "asr_common/atomic_file.hpp"
#include "asr_common/input_error.hpp"

namespace asr_state_machine {

using asr_robot_model::World;
using asr_robot_model::WorldObject;

TopDownFrame::TopDownFrame(const World& world, double pixels_per_metre)
    : room_min_(world.room_min), room_max_y_(world.room_max.y()), scale_(pixels_per_metre) {
  const Eigen::Vector2d extent = world.room_max - world.room_min;
  map_width_ = static_cast<int>(std::ceil(extent.x() * scale_)) + 2 * kMargin;
  // The key needs room for its lines (a few on the search, one per object) even in a small room.
  height_ = std::max(static_cast<int>(std::ceil(extent.y() * scale_)) + 2 * kMargin,
                     240 + 16 * static_cast<int>(world.objects.size()));
}

Eigen::Vector2i TopDownFrame::pixel(const Eigen::Vector2d& floor) const {
  return {kMargin + static_cast<int>(std::lround((floor.x() - room_min_.x()) * scale_)),
          kMargin + static_cast<int>(std::lround((room_max_y_ - floor.y()) * scale_))};
}

namespace {

// OpenCV draws in BGR.
cv::Scalar colour(const Rgb& rgb) {
  return cv::Scalar(rgb[2], rgb[1], rgb[0]);
}

const cv::Scalar kInk(40, 40, 40);
const cv::Scalar kFurnitureFill(200, 200, 200);
const cv::Scalar kWedgeColour(0, 150, 255);
const cv::Scalar kClutterColour(150, 150, 150);
// One colour per scene, in the order of the scene names.
const Rgb kSceneColours[] = {{0, 150, 70},  {200, 30, 120}, {230, 120, 0},
                             {0, 150, 190}, {130, 70, 200}, {160, 110, 40}};

cv::Point point(const TopDownFrame& frame, const Eigen::Vector2d& floor) {
  const Eigen::Vector2i p = frame.pixel(floor);
  return {p.x(), p.y()};
}

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

// Writes `line` from `at`; a line too long for the room left to the right edge is written
// smaller so that it ends inside the picture (long object names with their scenes).
void text(cv::Mat& image, const std::string& line, cv::Point at, const cv::Scalar& ink,
          double size = 0.45) {
  const int room = image.cols - 4 - at.x;
  int baseline = 0;
  const int width = cv::getTextSize(line, cv::FONT_HERSHEY_SIMPLEX, size, 1, &baseline).width;
  if (room > 0 && width > room)
    size *= static_cast<double>(room) / width;
  cv::putText(image, line, at, cv::FONT_HERSHEY_SIMPLEX, size, ink, 1, cv::LINE_AA);
}

// The outline of a box seen from above: the convex hull of its corners on the floor.
std::vector<cv::Point> footprint(const TopDownFrame& frame, const asr_robot_model::Box& box) {
  std::vector<cv::Point> corners;
  for (const Eigen::Vector3d& corner : box.corners())
    corners.push_back(point(frame, corner.head<2>()));
  std::vector<cv::Point> hull;
  cv::convexHull(corners, hull);
  return hull;
}

void drawFurniture(cv::Mat& image, const TopDownFrame& frame, const World& world) {
  const cv::Point low = point(frame, world.room_min);
  const cv::Point high = point(frame, world.room_max);
  cv::rectangle(image, low, high, kInk, 2);
  for (const asr_robot_model::Furniture& piece : world.furniture) {
    const std::vector<cv::Point> outline = footprint(frame, piece.box);
    cv::fillConvexPoly(image, outline, kFurnitureFill, cv::LINE_AA);
    cv::polylines(image, outline, true, cv::Scalar(120, 120, 120), 1, cv::LINE_AA);
  }
  // Names on top of every box, so overlapping boards do not hide them.
  for (const asr_robot_model::Furniture& piece : world.furniture) {
    if (piece.name.rfind("shelf_board", 0) == 0)
      continue;  // the shelf's boards lie under one another; the back panel names the shelf
    const cv::Point centre = point(frame, piece.box.pose.position.head<2>());
    text(image, piece.name, centre + cv::Point(-4 * static_cast<int>(piece.name.size()), 4),
         cv::Scalar(90, 90, 90), 0.4);
  }
}

// The camera's horizontal opening on the floor: from the camera along its optical axis
// (projected onto the floor) out to the far plane.
void drawView(cv::Mat& image, const TopDownFrame& frame, const VisitedView& view, int number,
              const asr_robot_model::Frustum& frustum) {
  const Eigen::Vector3d axis = view.camera.orientation * Eigen::Vector3d::UnitZ();
  const Eigen::Vector2d flat = axis.head<2>();
  const Eigen::Vector2d camera = view.camera.position.head<2>();
  const cv::Point apex = point(frame, camera);
  if (flat.norm() > 1e-6) {
    const double heading = std::atan2(flat.y(), flat.x());
    const double reach = frustum.far() * flat.norm();
    std::vector<cv::Point> wedge{apex};
    for (double side : {-0.5, 0.5}) {
      const double angle = heading + side * frustum.fovx();
      wedge.push_back(
          point(frame, camera + reach * Eigen::Vector2d(std::cos(angle), std::sin(angle))));
    }
    cv::Mat overlay = image.clone();
    cv::fillConvexPoly(overlay, wedge, kWedgeColour, cv::LINE_AA);
    cv::addWeighted(overlay, 0.18, image, 0.82, 0.0, image);
    cv::polylines(image, wedge, true, kWedgeColour, 1, cv::LINE_AA);
  }
  cv::circle(image, apex, 3, kWedgeColour, cv::FILLED, cv::LINE_AA);
  text(image, std::to_string(number), apex + cv::Point(5, -5), cv::Scalar(0, 90, 180), 0.4);
}

void drawPath(cv::Mat& image, const TopDownFrame& frame, const SearchResult& result) {
  std::vector<cv::Point> path{point(frame, {result.start.x, result.start.y})};
  for (const VisitedView& view : result.world.visitedViews())
    path.push_back(point(frame, {view.base.x, view.base.y}));
  cv::polylines(image, path, false, colour(kPathColour), 2, cv::LINE_AA);
  for (std::size_t i = 1; i < path.size(); ++i)
    cv::circle(image, path[i], 3, colour(kPathColour), cv::FILLED, cv::LINE_AA);
  cv::circle(image, path.front(), 7, colour(kPathColour), 2, cv::LINE_AA);
  text(image, "start", path.front() + cv::Point(9, 14), colour(kPathColour));
}

// The scenes an object belongs to (indices in the order of the scene names) and their names.
struct Membership {
  std::vector<std::size_t> scenes;
  std::string names;
};
Membership scenesOf(const SearchResult& result, const asr_common::ObjectKey& key) {
  Membership membership;
  std::size_t index = 0;
  for (const auto& [scene, objects] : result.world.sceneObjects()) {
    if (std::count(objects.begin(), objects.end(), key)) {
      membership.scenes.push_back(index);
      membership.names += (membership.names.empty() ? "" : ", ") + scene;
    }
    ++index;
  }
  return membership;
}

// The found object that stands for a world object: by key, else the nearest of its type.
const FoundObject* foundFor(const SearchResult& result, const WorldObject& object) {
  const FoundObject* nearest = nullptr;
  double best = 0.3;  // beyond this, an estimate of the type is another object
  for (const FoundObject& found : result.world.foundObjects()) {
    if (found.key == object.key)
      return &found;
    const double distance = (found.pose.position - object.box.pose.position).norm();
    if (found.key.type == object.key.type && distance < best) {
      best = distance;
      nearest = &found;
    }
  }
  return nearest;
}

std::string label(std::size_t index) {
  std::string name;
  for (std::size_t n = index + 1; n > 0; n = (n - 1) / 26)
    name.insert(name.begin(), static_cast<char>('A' + (n - 1) % 26));
  return name;
}

struct KeyWriter {
  cv::Mat& image;
  int x;
  int y = 26;
  void line(const std::string& words, const cv::Scalar& ink = kInk, double size = 0.45) {
    text(image, words, {x, y}, ink, size);
    y += static_cast<int>(40 * size);
  }
};

void drawObjects(cv::Mat& image, const TopDownFrame& frame, const World& world,
                 const SearchResult& result, KeyWriter& key) {
  key.line("objects: filled found, crossed never found, grey not searched");
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const WorldObject& object = world.objects[i];
    const Membership membership = scenesOf(result, object.key);
    const bool searched = !membership.scenes.empty();
    const FoundObject* found = foundFor(result, object);
    // An object of several scenes takes the colour of the first.
    const cv::Scalar ink =
        searched ? colour(kSceneColours[membership.scenes.front() % std::size(kSceneColours)])
                 : kClutterColour;
    const cv::Point at = point(frame, object.box.pose.position.head<2>());
    std::string status = "not searched";
    if (found) {
      cv::circle(image, at, 6, ink, cv::FILLED, cv::LINE_AA);
      status =
          "found at " + fixed(found->found_at_s, 0) + " s from view " + std::to_string(found->view);
    } else if (searched) {
      cv::circle(image, at, 6, ink, 2, cv::LINE_AA);
      cv::line(image, at + cv::Point(-5, -5), at + cv::Point(5, 5), ink, 2, cv::LINE_AA);
      cv::line(image, at + cv::Point(-5, 5), at + cv::Point(5, -5), ink, 2, cv::LINE_AA);
      status = "never found";
    } else {
      cv::rectangle(image, at + cv::Point(-4, -4), at + cv::Point(4, 4), ink, 1, cv::LINE_AA);
    }
    text(image, label(i), at + cv::Point(7, 4), ink, 0.4);
    key.line(label(i) + "  " + object.key.toString() + ": " + status +
                 (membership.scenes.size() > 1 ? " (" + membership.names + ")" : ""),
             ink, 0.4);
  }
}

void drawKey(cv::Mat& image, const World& world, const SearchResult& result,
             const TopDownFrame& frame) {
  KeyWriter key{image, frame.mapWidth() + 10};
  key.line(outcomeName(result.outcome), kInk, 0.6);
  if (!result.reason.empty())
    key.line(result.reason.substr(0, 70), kInk, 0.4);
  key.line(fixed(result.sim_seconds / 60.0, 2) + " simulated min, " +
           std::to_string(result.world.visitedViews().size()) + " views, " +
           std::to_string(result.world.foundObjects().size()) + " objects found");
  key.line("blue: the robot's path; orange: the views, numbered from 0");
  std::size_t index = 0;
  for (const auto& [scene, objects] : result.world.sceneObjects()) {
    const cv::Scalar ink = colour(kSceneColours[index++ % std::size(kSceneColours)]);
    key.line("scene " + scene + ": confidence " + fixed(result.world.sceneConfidence(scene), 2) +
                 ", " + std::to_string(objects.size() - result.world.missingObjects(scene).size()) +
                 " of " + std::to_string(objects.size()) + " found",
             ink);
  }
  key.y += 6;
  drawObjects(image, frame, world, result, key);
}

}  // namespace

void checkPictureFile(const std::string& png) {
  namespace fs = std::filesystem;
  const fs::path path(png);
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code error;
  if (png.empty() || fs::is_directory(path, error))
    throw asr_common::InputError("'" + png + "': the picture needs a file name");
  if (!fs::is_directory(folder, error))
    throw asr_common::InputError(png + ": the folder " + folder.string() + " does not exist");
}

void writeSearchPicture(const World& world, const SearchResult& result, const std::string& png,
                        const asr_robot_model::Frustum& frustum) {
  checkPictureFile(png);
  const TopDownFrame frame(world);
  cv::Mat image(frame.height(), frame.width(), CV_8UC3, colour(kFloorColour));
  drawFurniture(image, frame, world);
  const std::vector<VisitedView>& views = result.world.visitedViews();
  for (std::size_t i = 0; i < views.size(); ++i)
    drawView(image, frame, views[i], static_cast<int>(i), frustum);
  drawPath(image, frame, result);
  drawKey(image, world, result, frame);
  std::vector<unsigned char> encoded;
  if (!cv::imencode(".png", image, encoded))
    throw asr_common::InputError(png + ": cannot encode the picture as PNG");
  asr_common::writeFileAtomically(png, std::string(encoded.begin(), encoded.end()));
}

}  // namespace asr_state_machine
