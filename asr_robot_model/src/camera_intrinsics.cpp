#include "asr_robot_model/camera_intrinsics.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>

#include "asr_common/input_error.hpp"
#include "asr_robot_model/document.hpp"

namespace asr_robot_model {
namespace {

std::vector<double> numbers(const Field& list) {
  std::vector<double> values;
  for (std::size_t i = 0; i < list.size(); ++i)
    values.push_back(list[i].number());
  return values;
}

int imageSide(const Field& field) {
  const double side = field.number();
  if (side < 1 || side > 100000 || side != std::floor(side))
    field.fail("must be a whole number of pixels from 1 to 100000");
  return static_cast<int>(side);
}

void writeList(std::ofstream& out, const std::vector<double>& values) {
  out << "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    out << (i ? ", " : "") << std::setprecision(17) << values[i];
  out << "]";
}

}  // namespace

CameraIntrinsics CameraIntrinsics::fromHorizontalFov(int width, int height, double horizontal_fov) {
  if (width < 1 || height < 1)
    throw asr_common::InputError("camera: the image size must be positive");
  if (!(horizontal_fov > 0.0 && horizontal_fov < M_PI))
    throw asr_common::InputError("camera: the horizontal field of view must lie in (0, pi)");
  CameraIntrinsics camera;
  camera.width = width;
  camera.height = height;
  camera.fx = camera.fy = (width / 2.0) / std::tan(horizontal_fov / 2.0);
  camera.cx = (width - 1) / 2.0;
  camera.cy = (height - 1) / 2.0;
  return camera;
}

CameraIntrinsics CameraIntrinsics::defaults() {
  return fromHorizontalFov(640, 480, M_PI / 3.0);
}

Eigen::Matrix3d CameraIntrinsics::matrix() const {
  Eigen::Matrix3d k;
  k << fx, 0, cx, 0, fy, cy, 0, 0, 1;
  return k;
}

void CameraIntrinsics::check(const std::string& what) const {
  auto fail = [&](const std::string& field, const std::string& problem) {
    throw asr_common::InputError(what + ": " + field + ": " + problem);
  };
  if (width < 1 || height < 1)
    fail("image_width/image_height", "must be positive");
  if (!(std::isfinite(fx) && fx > 0 && std::isfinite(fy) && fy > 0))
    fail("camera_matrix", "the focal lengths must be positive and finite");
  if (!(std::isfinite(cx) && std::isfinite(cy)))
    fail("camera_matrix", "the principal point must be finite");
  if (!(distortion.empty() || distortion.size() == 4 || distortion.size() == 5 ||
        distortion.size() == 8))
    fail("distortion_coefficients", "must hold 4, 5 or 8 plumb-bob coefficients");
  for (const double d : distortion)
    if (!std::isfinite(d))
      fail("distortion_coefficients", "must be finite");
}

CameraIntrinsics loadCameraInfo(const std::string& path) {
  const nlohmann::json document = readDocument(path);
  const Field root(document, path, "");
  CameraIntrinsics camera;
  camera.width = imageSide(root["image_width"]);
  camera.height = imageSide(root["image_height"]);
  const Field matrix = root["camera_matrix"]["data"];
  const std::vector<double> k = numbers(matrix);
  if (k.size() != 9)
    matrix.fail("must hold the 9 entries of the 3x3 camera matrix");
  if (!(k[0] > 0 && k[4] > 0) || k[1] != 0 || k[3] != 0 || k[6] != 0 || k[7] != 0 || k[8] != 1)
    matrix.fail("must be [fx, 0, cx, 0, fy, cy, 0, 0, 1] with positive focal lengths");
  camera.fx = k[0];
  camera.cx = k[2];
  camera.fy = k[4];
  camera.cy = k[5];
  if (root.has("distortion_model")) {
    const std::string model = root["distortion_model"].text();
    if (model != "plumb_bob" && model != "rational_polynomial")
      root["distortion_model"].fail("'" + model + "' is not plumb_bob or rational_polynomial");
  }
  if (root.has("distortion_coefficients"))
    camera.distortion = numbers(root["distortion_coefficients"]["data"]);
  camera.check(path);
  return camera;
}

void saveCameraInfo(const std::string& path, const CameraIntrinsics& camera,
                    const std::string& camera_name) {
  std::ofstream out(path);
  if (!out)
    throw asr_common::InputError(path + ": cannot write the file");
  std::vector<double> distortion = camera.distortion;
  distortion.resize(std::max<std::size_t>(distortion.size(), 5), 0.0);
  out << "image_width: " << camera.width << "\nimage_height: " << camera.height
      << "\ncamera_name: " << camera_name << "\ncamera_matrix: {rows: 3, cols: 3, data: ";
  writeList(out, {camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1});
  out << "}\ndistortion_model: plumb_bob\ndistortion_coefficients: {rows: 1, cols: "
      << distortion.size() << ", data: ";
  writeList(out, distortion);
  out << "}\nrectification_matrix: {rows: 3, cols: 3, data: [1, 0, 0, 0, 1, 0, 0, 0, 1]}\n"
      << "projection_matrix: {rows: 3, cols: 4, data: ";
  writeList(out, {camera.fx, 0, camera.cx, 0, 0, camera.fy, camera.cy, 0, 0, 0, 1, 0});
  out << "}\n";
  if (!out)
    throw asr_common::InputError(path + ": cannot write the file");
}

}  // namespace asr_robot_model
