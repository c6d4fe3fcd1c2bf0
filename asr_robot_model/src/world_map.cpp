#include "asr_robot_model/world_map.hpp"

#include <octomap/OcTree.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "asr_common/input_error.hpp"

namespace asr_robot_model {

struct WorldMap::Octree {
  explicit Octree(double resolution) : tree(resolution) {}
  octomap::OcTree tree;
  std::vector<Box> solids;  // the boxes whose surfaces the tree holds
  // The tree's occupied voxels as a grid of the finest keys over their bounding box, so a ray
  // cast looks each voxel up instead of descending the tree (empty if it would be too large).
  octomap::OcTreeKey low;
  std::array<long, 3> extent{0, 0, 0};
  std::vector<bool> occupied;  // x fastest

  void gridOccupied();
  // tree.search(key) is an occupied node, by the grid.
  bool occupiedAt(const octomap::OcTreeKey& key) const {
    const long x = static_cast<long>(key[0]) - low[0], y = static_cast<long>(key[1]) - low[1],
               z = static_cast<long>(key[2]) - low[2];
    if (x < 0 || y < 0 || z < 0 || x >= extent[0] || y >= extent[1] || z >= extent[2])
      return false;
    return occupied[static_cast<std::size_t>((z * extent[1] + y) * extent[0] + x)];
  }
};

void WorldMap::Octree::gridOccupied() {
  // Up to 2^26 cells (8 MB): every world of the suite at its resolutions fits.
  constexpr double kMostCells = 67108864.0;
  std::array<long, 3> first{65536, 65536, 65536}, last{-1, -1, -1};
  const unsigned depth = tree.getTreeDepth();
  for (auto leaf = tree.begin_leafs(), end = tree.end_leafs(); leaf != end; ++leaf) {
    if (!tree.isNodeOccupied(*leaf))
      continue;
    const octomap::OcTreeKey key = leaf.getIndexKey();
    const long span = 1L << (depth - leaf.getDepth());
    for (int axis = 0; axis < 3; ++axis) {
      first[axis] = std::min<long>(first[axis], key[axis]);
      last[axis] = std::max<long>(last[axis], key[axis] + span - 1);
    }
  }
  if (last[0] < 0 || static_cast<double>(last[0] - first[0] + 1) *
                             static_cast<double>(last[1] - first[1] + 1) *
                             static_cast<double>(last[2] - first[2] + 1) >
                         kMostCells)
    return;
  for (int axis = 0; axis < 3; ++axis) {
    low[axis] = static_cast<octomap::key_type>(first[axis]);
    extent[axis] = last[axis] - first[axis] + 1;
  }
  occupied.assign(static_cast<std::size_t>(extent[0] * extent[1] * extent[2]), false);
  for (auto leaf = tree.begin_leafs(), end = tree.end_leafs(); leaf != end; ++leaf) {
    if (!tree.isNodeOccupied(*leaf))
      continue;
    const octomap::OcTreeKey key = leaf.getIndexKey();
    const long span = 1L << (depth - leaf.getDepth());
    for (long z = key[2] - first[2]; z < key[2] - first[2] + span; ++z)
      for (long y = key[1] - first[1]; y < key[1] - first[1] + span; ++y)
        for (long x = key[0] - first[0]; x < key[0] - first[0] + span; ++x)
          occupied[static_cast<std::size_t>((z * extent[1] + y) * extent[0] + x)] = true;
  }
}

namespace {

octomap::point3d toPoint(const Eigen::Vector3d& v) {
  return octomap::point3d(static_cast<float>(v.x()), static_cast<float>(v.y()),
                          static_cast<float>(v.z()));
}

// Marks the voxels of the box's six faces, sampled at half the voxel edge so no voxel a face
// passes through is missed.
void insertBoxSurface(octomap::OcTree& tree, const Box& box) {
  const double step = tree.getResolution() / 2.0;
  const Eigen::Vector3d half = box.size / 2.0;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const int nu = static_cast<int>(std::ceil(box.size[u] / step));
    const int nv = static_cast<int>(std::ceil(box.size[v] / step));
    for (double side : {-1.0, 1.0}) {
      for (int i = 0; i <= nu; ++i) {
        for (int j = 0; j <= nv; ++j) {
          Eigen::Vector3d local;
          local[axis] = side * half[axis];
          local[u] = -half[u] + box.size[u] * i / nu;
          local[v] = -half[v] + box.size[v] * j / nv;
          const Eigen::Vector3d point = box.pose.position + box.pose.orientation * local;
          tree.updateNode(toPoint(point), true, true);
        }
      }
    }
  }
}

// The ray cast of WorldMap::lineOfSight: the voxels the segment from `eye` to the target's
// centre crosses, blocked by any `occupied` one but the target's own.
template <typename Occupied>
bool rayIsFree(const octomap::OcTree& tree, const Eigen::Vector3d& eye, const Box& target,
               const Occupied& occupied) {
  const double own_margin = tree.getResolution() * std::sqrt(3.0) / 2.0;
  octomap::KeyRay ray;
  if (!tree.computeRayKeys(toPoint(eye), toPoint(target.pose.position), ray))
    return false;
  for (const octomap::OcTreeKey& key : ray) {
    if (!occupied(key))
      continue;
    const octomap::point3d centre = tree.keyToCoord(key);
    if (!target.contains(Eigen::Vector3d(centre.x(), centre.y(), centre.z()), own_margin))
      return false;
  }
  return true;
}

// True if the segment from a to b comes within `margin` of the box (slab test in its frame).
bool segmentNearBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Box& box,
                    double margin) {
  const Eigen::Quaterniond to_box = box.pose.orientation.conjugate();
  const Eigen::Vector3d start = to_box * (a - box.pose.position);
  const Eigen::Vector3d direction = to_box * (b - a);
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double half = box.size[axis] / 2.0 + margin;
    if (std::abs(direction[axis]) < 1e-12) {
      if (std::abs(start[axis]) > half)
        return false;
      continue;
    }
    double t0 = (-half - start[axis]) / direction[axis];
    double t1 = (half - start[axis]) / direction[axis];
    if (t0 > t1)
      std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave)
      return false;
  }
  return true;
}

}  // namespace

WorldMap::WorldMap(const World& world, double resolution, double base_radius, double base_height)
    : room_min_(world.room_min),
      room_max_(world.room_max),
      base_radius_(base_radius),
      base_height_(base_height) {
  if (!(std::isfinite(resolution) && resolution >= 0.001 && resolution <= 1.0))
    throw asr_common::InputError("world map: resolution must lie in 0.001..1 m");
  if (!(std::isfinite(base_radius) && base_radius > 0.0))
    throw asr_common::InputError("world map: base radius must be positive");
  octree_ = std::make_unique<Octree>(resolution);
  for (const Furniture& furniture : world.furniture)
    octree_->solids.push_back(furniture.box);
  for (const WorldObject& object : world.objects)
    octree_->solids.push_back(object.box);
  for (const Box& box : octree_->solids)
    insertBoxSurface(octree_->tree, box);
  octree_->tree.updateInnerOccupancy();
  octree_->gridOccupied();
  computeBaseFootprintGrid();
}

// Blocks every cell that has a point within the base radius of an occupied voxel's footprint
// (voxels from the floor to base_height): the distance between the cell's and the voxel's
// squares is at most the radius.
void WorldMap::computeBaseFootprintGrid() {
  const double cell = resolution();
  cells_x_ = static_cast<int>(std::ceil((room_max_.x() - room_min_.x()) / cell));
  cells_y_ = static_cast<int>(std::ceil((room_max_.y() - room_min_.y()) / cell));
  base_blocked_.assign(static_cast<std::size_t>(cells_x_) * cells_y_, false);
  const octomap::OcTree& tree = octree_->tree;
  const octomap::point3d low(room_min_.x() - base_radius_, room_min_.y() - base_radius_, 0.0);
  const octomap::point3d high(room_max_.x() + base_radius_, room_max_.y() + base_radius_,
                              base_height_);
  for (auto leaf = tree.begin_leafs_bbx(low, high), end = tree.end_leafs_bbx(); leaf != end;
       ++leaf) {
    if (!tree.isNodeOccupied(*leaf))
      continue;
    const double half = leaf.getSize() / 2.0;
    const int first_i = std::max(
        0,
        static_cast<int>(std::floor((leaf.getX() - half - base_radius_ - room_min_.x()) / cell)));
    const int last_i = std::min(
        cells_x_ - 1,
        static_cast<int>(std::floor((leaf.getX() + half + base_radius_ - room_min_.x()) / cell)));
    const int first_j = std::max(
        0,
        static_cast<int>(std::floor((leaf.getY() - half - base_radius_ - room_min_.y()) / cell)));
    const int last_j = std::min(
        cells_y_ - 1,
        static_cast<int>(std::floor((leaf.getY() + half + base_radius_ - room_min_.y()) / cell)));
    for (int i = first_i; i <= last_i; ++i) {
      // Gap between the cell's and the voxel's squares along x, then y.
      const double cell_x = room_min_.x() + (i + 0.5) * cell;
      const double dx = std::max(std::abs(cell_x - leaf.getX()) - half - cell / 2.0, 0.0);
      for (int j = first_j; j <= last_j; ++j) {
        const double cell_y = room_min_.y() + (j + 0.5) * cell;
        const double dy = std::max(std::abs(cell_y - leaf.getY()) - half - cell / 2.0, 0.0);
        if (std::hypot(dx, dy) <= base_radius_)
          base_blocked_[static_cast<std::size_t>(j) * cells_x_ + i] = true;
      }
    }
  }
}

WorldMap::~WorldMap() = default;
WorldMap::WorldMap(WorldMap&&) noexcept = default;
WorldMap& WorldMap::operator=(WorldMap&&) noexcept = default;

double WorldMap::resolution() const {
  return octree_->tree.getResolution();
}

bool WorldMap::baseIsFree(double x, double y) const {
  if (!(std::isfinite(x) && std::isfinite(y)))
    return false;
  if (x - base_radius_ < room_min_.x() || x + base_radius_ > room_max_.x() ||
      y - base_radius_ < room_min_.y() || y + base_radius_ > room_max_.y())
    return false;
  const int i = std::min(cells_x_ - 1, static_cast<int>((x - room_min_.x()) / resolution()));
  const int j = std::min(cells_y_ - 1, static_cast<int>((y - room_min_.y()) / resolution()));
  return !base_blocked_[static_cast<std::size_t>(j) * cells_x_ + i];
}

bool WorldMap::lineOfSight(const Eigen::Vector3d& eye, const Box& target) const {
  const octomap::OcTree& tree = octree_->tree;
  // Every occupied voxel meets a box's surface, and the ray passes through the voxels it
  // crosses: a segment farther than a voxel's diagonal from every box crosses none, and the
  // ray cast is skipped (same answer, a fraction of the time).
  const double clearance = tree.getResolution() * std::sqrt(3.0) + 1e-3;
  // The ray cast refuses coordinates beyond its 16-bit keys (about 32,768 voxels from 0).
  const double sane = tree.getResolution() * 30000.0;
  if (eye.allFinite() && target.pose.position.allFinite() && eye.cwiseAbs().maxCoeff() < sane &&
      target.pose.position.cwiseAbs().maxCoeff() < sane &&
      std::none_of(octree_->solids.begin(), octree_->solids.end(), [&](const Box& box) {
        return segmentNearBox(eye, target.pose.position, box, clearance);
      }))
    return true;
  if (octree_->occupied.empty())
    return lineOfSightByRayCast(eye, target);
  return rayIsFree(tree, eye, target,
                   [this](const octomap::OcTreeKey& key) { return octree_->occupiedAt(key); });
}

bool WorldMap::lineOfSightByRayCast(const Eigen::Vector3d& eye, const Box& target) const {
  const octomap::OcTree& tree = octree_->tree;
  return rayIsFree(tree, eye, target, [&tree](const octomap::OcTreeKey& key) {
    const octomap::OcTreeNode* node = tree.search(key);
    return node != nullptr && tree.isNodeOccupied(node);
  });
}

std::vector<Eigen::Vector3d> WorldMap::occupiedVoxels() const {
  std::vector<Eigen::Vector3d> centres;
  const octomap::OcTree& tree = octree_->tree;
  for (auto leaf = tree.begin_leafs(), end = tree.end_leafs(); leaf != end; ++leaf) {
    if (tree.isNodeOccupied(*leaf))
      centres.emplace_back(leaf.getX(), leaf.getY(), leaf.getZ());
  }
  return centres;
}

}  // namespace asr_robot_model
