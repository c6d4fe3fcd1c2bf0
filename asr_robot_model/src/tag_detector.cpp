#include "asr_robot_model/tag_detector.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

extern "C" {
#include <apriltag/apriltag.h>
}

#include "asr_common/input_error.hpp"
#include "asr_robot_model/tag_family.hpp"

namespace asr_robot_model {
namespace {

// The corner noise assumed at least (pixels): a perfect fit must not claim certainty.
constexpr double kMinCornerSigma = 0.1;

using Pixels = std::vector<Eigen::Vector2d>;
using Points = std::vector<Eigen::Vector3d>;

/// The printed tag's outer black corners in its own frame, in TagEstimate::corners' order
/// (the order SOLVEPNP_IPPE_SQUARE wants).
Points tagCorners(double edge_length) {
  const double h = edge_length / 2.0;
  return {{-h, h, 0}, {h, h, 0}, {h, -h, 0}, {-h, -h, 0}};
}

Pixels undistorted(const Pixels& raw, const CameraIntrinsics& camera) {
  if (std::all_of(camera.distortion.begin(), camera.distortion.end(),
                  [](double d) { return d == 0.0; }))
    return raw;
  std::vector<cv::Point2d> in, out;
  for (const Eigen::Vector2d& p : raw)
    in.emplace_back(p.x(), p.y());
  cv::Mat k;
  cv::eigen2cv(camera.matrix(), k);
  cv::undistortPoints(in, out, k, camera.distortion, cv::noArray(), k);
  Pixels result;
  for (const cv::Point2d& p : out)
    result.emplace_back(p.x, p.y);
  return result;
}

asr_common::Pose poseOf(const cv::Mat& rvec, const cv::Mat& tvec) {
  cv::Mat rotation;
  cv::Rodrigues(rvec, rotation);
  Eigen::Matrix3d r;
  cv::cv2eigen(rotation, r);
  return asr_common::Pose(
      Eigen::Vector3d(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2)),
      asr_common::canonicalQuaternion(Eigen::Quaterniond(r)));
}

void toRodrigues(const asr_common::Pose& pose, cv::Mat& rvec, cv::Mat& tvec) {
  cv::Mat rotation;
  cv::eigen2cv(Eigen::Matrix3d(pose.orientation.toRotationMatrix()), rotation);
  cv::Rodrigues(rotation, rvec);
  tvec = (cv::Mat_<double>(3, 1) << pose.position.x(), pose.position.y(), pose.position.z());
}

/// RMS pixel distance between `pixels` and `points` (model frame) projected at `pose`.
double reprojectionRms(const Points& points, const Pixels& pixels, const asr_common::Pose& pose,
                       const CameraIntrinsics& camera) {
  double sum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = pose.orientation * points[i] + pose.position;
    const Eigen::Vector2d projected(camera.fx * p.x() / p.z() + camera.cx,
                                    camera.fy * p.y() / p.z() + camera.cy);
    sum += (projected - pixels[i]).squaredNorm();
  }
  return std::sqrt(sum / points.size());
}

/// Covariance of the pose over (x, y, z, rotation about the camera's x, y, z): the Gauss-Newton
/// inverse of JᵀJ of the projections, scaled by the corner variance the residual shows.
Eigen::Matrix<double, 6, 6> poseCovariance(const Points& points, const asr_common::Pose& pose,
                                           const CameraIntrinsics& camera, double rms) {
  Eigen::MatrixXd jacobian(2 * points.size(), 6);  // columns: translation, rotation
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d rotated = pose.orientation * points[i];
    const Eigen::Vector3d p = rotated + pose.position;
    Eigen::Matrix<double, 2, 3> projection;
    projection << camera.fx / p.z(), 0, -camera.fx * p.x() / (p.z() * p.z()), 0, camera.fy / p.z(),
        -camera.fy * p.y() / (p.z() * p.z());
    Eigen::Matrix3d rotation_effect;  // d p / d(small rotation about the object's origin)
    rotation_effect << 0, rotated.z(), -rotated.y(), -rotated.z(), 0, rotated.x(), rotated.y(),
        -rotated.x(), 0;
    jacobian.block<2, 3>(2 * i, 0) = projection;
    jacobian.block<2, 3>(2 * i, 3) = projection * rotation_effect;
  }
  const double dof = std::max<double>(2.0 * points.size() - 6.0, 1.0);
  const double variance =
      std::max(rms * rms * points.size() / dof, kMinCornerSigma * kMinCornerSigma);
  const Eigen::Matrix<double, 6, 6> information = jacobian.transpose() * jacobian;
  return variance * information.ldlt().solve(Eigen::Matrix<double, 6, 6>::Identity());
}

cv::Mat cvPoints(const Points& points) {
  cv::Mat mat(static_cast<int>(points.size()), 1, CV_64FC3);
  for (std::size_t i = 0; i < points.size(); ++i)
    mat.at<cv::Vec3d>(int(i)) = {points[i].x(), points[i].y(), points[i].z()};
  return mat;
}

cv::Mat cvPixels(const Pixels& pixels) {
  cv::Mat mat(static_cast<int>(pixels.size()), 1, CV_64FC2);
  for (std::size_t i = 0; i < pixels.size(); ++i)
    mat.at<cv::Vec2d>(int(i)) = {pixels[i].x(), pixels[i].y()};
  return mat;
}

/// The pose of a tag of edge `edge_length` seen at the undistorted `corners`: the better of
/// IPPE's two solutions (a square seen nearly head-on has two that fit almost equally).
asr_common::Pose tagPose(const Pixels& corners, double edge_length,
                         const CameraIntrinsics& camera) {
  cv::Mat k;
  cv::eigen2cv(camera.matrix(), k);
  std::vector<cv::Mat> rvecs, tvecs;
  cv::solvePnPGeneric(cvPoints(tagCorners(edge_length)), cvPixels(corners), k, cv::noArray(), rvecs,
                      tvecs, false, cv::SOLVEPNP_IPPE_SQUARE);
  asr_common::Pose best;
  double best_error = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < rvecs.size(); ++i) {
    const asr_common::Pose pose = poseOf(rvecs[i], tvecs[i]);
    const double error = reprojectionRms(tagCorners(edge_length), corners, pose, camera);
    if (error < best_error)
      best = pose, best_error = error;
  }
  return best;
}

}  // namespace

void TagDetectorSettings::check() const {
  auto fail = [](const std::string& problem) {
    throw asr_common::InputError("tag detector: " + problem);
  };
  if (!(decimate >= 1.0 && decimate <= 8.0))
    fail("decimate must lie in [1, 8]");
  if (threads < 1 || threads > 64)
    fail("threads must lie in [1, 64]");
  if (max_hamming < 0 || max_hamming > 2)
    fail("max_hamming must be 0, 1 or 2");
  if (!(min_decision_margin >= 0.0))
    fail("min_decision_margin must not be negative");
  if (!(max_reprojection_px > 0.0))
    fail("max_reprojection_px must be positive");
}

struct TagDetector::Library {
  explicit Library(const std::string& family_name) : family(family_name) {}
  ~Library() {
    if (detector != nullptr)
      apriltag_detector_destroy(detector);
  }
  TagFamily family;
  apriltag_detector_t* detector = nullptr;
};

TagDetector::TagDetector(TagMap map, TagDetectorSettings settings)
    : map_(std::move(map)), settings_(settings) {
  settings_.check();
  library_ = std::make_unique<Library>(map_.family);
  library_->detector = apriltag_detector_create();
  apriltag_detector_add_family_bits(library_->detector, library_->family.raw(),
                                    settings_.max_hamming);
  library_->detector->quad_decimate = static_cast<float>(settings_.decimate);
  library_->detector->nthreads = settings_.threads;
  library_->detector->refine_edges = 1;
}

TagDetector::~TagDetector() = default;

TagDetections TagDetector::detect(const GreyImage& image, const CameraIntrinsics& camera) const {
  if (image.width < 1 || image.height < 1 ||
      image.pixels.size() != std::size_t(image.width) * image.height)
    throw asr_common::InputError("tag detector: the image is empty or its size is inconsistent");
  camera.check("camera info");
  image_u8_t view{image.width, image.height, image.width,
                  const_cast<std::uint8_t*>(image.pixels.data())};
  zarray_t* found = apriltag_detector_detect(library_->detector, &view);
  TagDetections result;
  std::vector<Pixels> tag_pixels;  // undistorted corners, parallel to result.tags
  for (int i = 0; i < zarray_size(found); ++i) {
    apriltag_detection_t* detection = nullptr;
    zarray_get(found, i, &detection);
    if (detection->hamming > settings_.max_hamming ||
        detection->decision_margin < settings_.min_decision_margin) {
      ++result.refused;
      continue;
    }
    const TagPlacement* placement = map_.find(detection->id);
    if (placement == nullptr) {
      result.unknown_ids.push_back(detection->id);
      continue;
    }
    TagEstimate tag;
    tag.id = detection->id;
    // libapriltag's corners run bottom-left, bottom-right, top-right, top-left of the tag.
    for (int corner = 0; corner < 4; ++corner)
      tag.corners[corner] = {detection->p[3 - corner][0], detection->p[3 - corner][1]};
    const Pixels corners = undistorted(Pixels(tag.corners.begin(), tag.corners.end()), camera);
    tag.pose = tagPose(corners, placement->edge_length, camera);
    tag.reprojection_px =
        reprojectionRms(tagCorners(placement->edge_length), corners, tag.pose, camera);
    if (!(tag.reprojection_px <= settings_.max_reprojection_px)) {
      ++result.refused;
      continue;
    }
    result.tags.push_back(tag);
    tag_pixels.push_back(corners);
  }
  apriltag_detections_destroy(found);

  std::map<asr_common::ObjectKey, std::vector<std::size_t>> tags_of_object;
  for (std::size_t i = 0; i < result.tags.size(); ++i)
    tags_of_object[map_.find(result.tags[i].id)->object].push_back(i);
  for (const auto& [key, indices] : tags_of_object)
    result.objects.push_back(combineTags(key, indices, result.tags, tag_pixels, camera));
  return result;
}

ObjectDetection TagDetector::combineTags(const asr_common::ObjectKey& key,
                                         const std::vector<std::size_t>& indices,
                                         const std::vector<TagEstimate>& tags,
                                         const std::vector<std::vector<Eigen::Vector2d>>& pixels,
                                         const CameraIntrinsics& camera) const {
  const std::size_t best =
      *std::min_element(indices.begin(), indices.end(), [&](std::size_t a, std::size_t b) {
        return tags[a].reprojection_px < tags[b].reprojection_px;
      });
  auto objectFrom = [&](std::size_t i) {
    return asr_common::compose(tags[i].pose, asr_common::inverse(map_.find(tags[i].id)->pose));
  };
  auto cornersOf = [&](const std::vector<std::size_t>& chosen, Points& points, Pixels& seen) {
    points.clear(), seen.clear();
    for (const std::size_t i : chosen) {
      const TagPlacement& placement = *map_.find(tags[i].id);
      for (const Eigen::Vector3d& corner : tagCorners(placement.edge_length))
        points.push_back(placement.pose.orientation * corner + placement.pose.position);
      seen.insert(seen.end(), pixels[i].begin(), pixels[i].end());
    }
  };
  ObjectDetection object;
  object.key = key;
  object.pose = objectFrom(best);
  object.tags = {tags[best].id};
  Points points;
  Pixels seen;
  cornersOf({best}, points, seen);
  if (indices.size() > 1) {
    Points all_points;
    Pixels all_seen;
    cornersOf(indices, all_points, all_seen);
    cv::Mat k, rvec, tvec;
    cv::eigen2cv(camera.matrix(), k);
    toRodrigues(object.pose, rvec, tvec);
    cv::solvePnP(cvPoints(all_points), cvPixels(all_seen), k, cv::noArray(), rvec, tvec, true,
                 cv::SOLVEPNP_ITERATIVE);
    const asr_common::Pose joint = poseOf(rvec, tvec);
    // Tags that disagree (a misplaced tag, a wrong offset in the map) fall back to the best.
    if (reprojectionRms(all_points, all_seen, joint, camera) <= settings_.max_reprojection_px) {
      object.pose = joint;
      object.tags.clear();
      for (const std::size_t i : indices)
        object.tags.push_back(tags[i].id);
      points = all_points, seen = all_seen;
    }
  }
  object.reprojection_px = reprojectionRms(points, seen, object.pose, camera);
  object.covariance = poseCovariance(points, object.pose, camera, object.reprojection_px);
  return object;
}

}  // namespace asr_robot_model
