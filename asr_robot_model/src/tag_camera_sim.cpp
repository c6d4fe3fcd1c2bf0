#include "asr_robot_model/tag_camera_sim.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <random>

#include "asr_common/input_error.hpp"

namespace asr_robot_model {
namespace {

// Grey levels of the printed tag and of the room behind the furniture.
constexpr double kInk = 25.0;
constexpr double kPaper = 230.0;
constexpr double kFloor = 90.0;
constexpr double kWall = 170.0;
// Rays start this far in front of the camera (metres along the optical axis).
constexpr double kNear = 0.01;

}  // namespace

void CameraSimSettings::check() const {
  camera.check("camera_sim");
  auto fail = [](const std::string& problem) {
    throw asr_common::InputError("camera_sim: " + problem);
  };
  if (!(noise_sigma >= 0.0 && noise_sigma < 128.0))
    fail("noise_sigma must lie in [0, 128) grey levels");
  if (!(blur_sigma >= 0.0 && blur_sigma < 20.0))
    fail("blur_sigma must lie in [0, 20) pixels");
  if (supersampling < 1 || supersampling > 16)
    fail("supersampling must lie in [1, 16]");
}

TagCameraSim::TagCameraSim(const World& world, const TagMap& tags, CameraSimSettings settings)
    : settings_(std::move(settings)), family_(tags.family) {
  settings_.check();
  auto addBox = [this](const Box& box) {
    boxes_.push_back(
        {box.pose.orientation.toRotationMatrix().transpose(), box.pose.position, box.size / 2.0});
  };
  for (const Furniture& furniture : world.furniture)
    addBox(furniture.box);
  for (const WorldObject& object : world.objects)
    addBox(object.box);
  for (const auto& [id, placement] : tags.tags) {
    const auto object = std::find_if(
        world.objects.begin(), world.objects.end(),
        [&](const WorldObject& candidate) { return candidate.key == placement.object; });
    if (object == world.objects.end())
      continue;
    const asr_common::Pose pose = asr_common::compose(object->box.pose, placement.pose);
    const Eigen::Matrix3d axes = pose.orientation.toRotationMatrix();
    DrawnTag tag{id,
                 pose.position,
                 axes.col(0),
                 axes.col(1),
                 axes.col(2),
                 0.0,
                 0.0,
                 family_.bitmap(id),
                 static_cast<int>(world.furniture.size() + (object - world.objects.begin()))};
    tag.cell = placement.edge_length / family_.widthAtBorder();
    tag.half_width = tag.cell * family_.totalWidth() / 2.0;
    tags_.push_back(std::move(tag));
    tag_poses_.emplace_back(id, pose);
  }
}

Eigen::Vector3d TagCameraSim::rayDirection(const asr_common::Pose& camera, double x,
                                           double y) const {
  const CameraIntrinsics& k = settings_.camera;
  return camera.orientation * Eigen::Vector3d((x - k.cx) / k.fx, (y - k.cy) / k.fy, 1.0);
}

double TagCameraSim::nearestBox(const Eigen::Vector3d& eye, const Eigen::Vector3d& direction,
                                int skip, int& hit, double& shade) const {
  double nearest = std::numeric_limits<double>::infinity();
  hit = -1;
  for (std::size_t index = 0; index < boxes_.size(); ++index) {
    if (static_cast<int>(index) == skip)
      continue;
    const RayBox& box = boxes_[index];
    const Eigen::Vector3d origin = box.to_box * (eye - box.centre);
    const Eigen::Vector3d step = box.to_box * direction;
    double enter = -std::numeric_limits<double>::infinity();
    double leave = std::numeric_limits<double>::infinity();
    int enter_axis = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (std::abs(step[axis]) < 1e-12) {
        if (std::abs(origin[axis]) > box.half_size[axis])
          leave = -1.0;
        continue;
      }
      double near_side = (-box.half_size[axis] - origin[axis]) / step[axis];
      double far_side = (box.half_size[axis] - origin[axis]) / step[axis];
      if (near_side > far_side)
        std::swap(near_side, far_side);
      if (near_side > enter) {
        enter = near_side;
        enter_axis = axis;
      }
      leave = std::min(leave, far_side);
    }
    // A camera inside a box sees through it (enter behind the near plane).
    if (enter > leave || enter < kNear || enter >= nearest)
      continue;
    nearest = enter;
    hit = static_cast<int>(index);
    const Eigen::Vector3d face = box.to_box.row(enter_axis).transpose();
    shade = 60.0 + 150.0 * std::abs(face.dot(direction.normalized()));
  }
  return nearest;
}

bool TagCameraSim::facesCamera(const DrawnTag& tag, const Eigen::Vector3d& eye) const {
  return (eye - tag.centre).dot(tag.normal) > 0.0;
}

void TagCameraSim::drawTag(const DrawnTag& tag, const asr_common::Pose& camera,
                           std::vector<double>& image) const {
  const CameraIntrinsics& k = settings_.camera;
  const Eigen::Matrix3d to_camera = camera.orientation.toRotationMatrix().transpose();
  double min_x = k.width, min_y = k.height, max_x = -1.0, max_y = -1.0;
  for (const double sx : {-1.0, 1.0})
    for (const double sy : {-1.0, 1.0}) {
      const Eigen::Vector3d corner =
          to_camera *
          (tag.centre + tag.half_width * (sx * tag.x_axis + sy * tag.y_axis) - camera.position);
      if (corner.z() < kNear)
        return;  // partly behind the camera: not drawn
      const double x = k.fx * corner.x() / corner.z() + k.cx;
      const double y = k.fy * corner.y() / corner.z() + k.cy;
      min_x = std::min(min_x, x), max_x = std::max(max_x, x);
      min_y = std::min(min_y, y), max_y = std::max(max_y, y);
    }
  const int first_x = std::max(0, static_cast<int>(std::floor(min_x)) - 1);
  const int last_x = std::min(k.width - 1, static_cast<int>(std::ceil(max_x)) + 1);
  const int first_y = std::max(0, static_cast<int>(std::floor(min_y)) - 1);
  const int last_y = std::min(k.height - 1, static_cast<int>(std::ceil(max_y)) + 1);
  const int n = settings_.supersampling;
  const int cells = tag.bitmap.width;
  const double distance_to_plane = (tag.centre - camera.position).dot(tag.normal);
  for (int y = first_y; y <= last_y; ++y)
    for (int x = first_x; x <= last_x; ++x) {
      double sum = 0.0;
      bool touched = false;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const Eigen::Vector3d direction =
              rayDirection(camera, x + (j + 0.5) / n - 0.5, y + (i + 0.5) / n - 0.5);
          const double along = direction.dot(tag.normal);
          const double t = along < 0.0 ? distance_to_plane / along : -1.0;
          const Eigen::Vector3d on_plane = camera.position + t * direction - tag.centre;
          const double u = on_plane.dot(tag.x_axis), v = on_plane.dot(tag.y_axis);
          if (t <= 0.0 || std::abs(u) > tag.half_width || std::abs(v) > tag.half_width) {
            sum += image[std::size_t(y) * k.width + x];
            continue;
          }
          touched = true;
          int hit = -1;
          double shade = 0.0;
          if (settings_.occlusion &&
              nearestBox(camera.position, direction, tag.own_box, hit, shade) < t) {
            sum += shade;
            continue;
          }
          const int column = std::clamp(int((u + tag.half_width) / tag.cell), 0, cells - 1);
          const int row = std::clamp(int((tag.half_width - v) / tag.cell), 0, cells - 1);
          sum += kInk + (kPaper - kInk) * tag.bitmap.at(column, row) / 255.0;
        }
      if (touched)
        image[std::size_t(y) * k.width + x] = sum / (n * n);
    }
}

GreyImage TagCameraSim::render(const asr_common::Pose& camera, unsigned seed) const {
  const CameraIntrinsics& k = settings_.camera;
  std::vector<double> image(std::size_t(k.width) * k.height);
  for (int y = 0; y < k.height; ++y)
    for (int x = 0; x < k.width; ++x) {
      const Eigen::Vector3d direction = rayDirection(camera, x, y);
      int hit = -1;
      double shade = 0.0;
      nearestBox(camera.position, direction, -1, hit, shade);
      image[std::size_t(y) * k.width + x] = hit >= 0 ? shade : direction.z() < 0 ? kFloor : kWall;
    }
  for (const DrawnTag& tag : tags_)
    if (facesCamera(tag, camera.position))
      drawTag(tag, camera, image);
  cv::Mat picture(k.height, k.width, CV_64F, image.data());
  if (settings_.blur_sigma > 0.0)
    cv::GaussianBlur(picture, picture, cv::Size(0, 0), settings_.blur_sigma);
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, settings_.noise_sigma);
  GreyImage result(k.width, k.height);
  for (std::size_t i = 0; i < image.size(); ++i) {
    const double value = image[i] + (settings_.noise_sigma > 0.0 ? noise(random) : 0.0);
    result.pixels[i] = static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
  }
  return result;
}

std::vector<int> TagCameraSim::tagsInView(const asr_common::Pose& camera) const {
  const CameraIntrinsics& k = settings_.camera;
  const Eigen::Matrix3d to_camera = camera.orientation.toRotationMatrix().transpose();
  std::vector<int> ids;
  for (const DrawnTag& tag : tags_) {
    if (!facesCamera(tag, camera.position))
      continue;
    const double half_border = tag.cell * family_.widthAtBorder() / 2.0;
    bool inside = true;
    for (const double sx : {-1.0, 1.0})
      for (const double sy : {-1.0, 1.0}) {
        const Eigen::Vector3d corner =
            to_camera *
            (tag.centre + half_border * (sx * tag.x_axis + sy * tag.y_axis) - camera.position);
        const double x = k.fx * corner.x() / corner.z() + k.cx;
        const double y = k.fy * corner.y() / corner.z() + k.cy;
        inside = inside && corner.z() > kNear && x >= 0 && y >= 0 && x <= k.width - 1 &&
                 y <= k.height - 1;
      }
    if (inside)
      ids.push_back(tag.id);
  }
  return ids;
}

}  // namespace asr_robot_model
