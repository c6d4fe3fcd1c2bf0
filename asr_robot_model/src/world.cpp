#include "asr_robot_model/world.hpp"

#include <set>

#include "asr_common/input_error.hpp"
#include "asr_robot_model/document.hpp"
#include "asr_robot_model/shipped_files.hpp"

namespace asr_robot_model {
namespace {

// An absent optional list reads as an empty one.
const nlohmann::json kAbsent;

Eigen::Vector3d positiveSize(const Field& field) {
  const Eigen::Vector3d size = field.vector3();
  if ((size.array() <= 0.0).any())
    field.fail("every edge length must be positive");
  return size;
}

std::vector<Eigen::Vector3d> unitNormals(const Field& field) {
  std::vector<Eigen::Vector3d> normals;
  for (std::size_t i = 0; i < field.size(); ++i) {
    const Eigen::Vector3d normal = field[i].vector3();
    if (normal.norm() < 1e-9)
      field[i].fail("a normal must not be zero");
    normals.push_back(normal.normalized());
  }
  return normals;
}

Box boxAt(const Field& pose, const Eigen::Vector3d& size) {
  Box box;
  box.pose = asr_common::Pose(pose["position"].position(), pose["orientation"].orientation());
  box.size = size;
  return box;
}

void checkVersion(const Field& document) {
  if (document["version"].number() != 1.0)
    document["version"].fail("only version 1 is known");
}

WorldObject readObject(const Field& field, const ObjectCatalogue& catalogue) {
  WorldObject object;
  object.key = {field["type"].text(), field["id"].text()};
  const auto type = catalogue.find(object.key.type);
  if (!field.has("size") && type == catalogue.end())
    field["type"].fail("'" + object.key.type +
                       "' is not in the catalogue and the object has no size");
  const Eigen::Vector3d size = field.has("size") ? positiveSize(field["size"]) : type->second.size;
  object.box = boxAt(field["pose"], size);
  if (field.has("normals"))
    object.normals = unitNormals(field["normals"]);
  else if (type != catalogue.end())
    object.normals = type->second.normals;
  return object;
}

void readRoom(const Field& room, World& world) {
  const Field min = room["min"], max = room["max"];
  if (min.size() != 2 || max.size() != 2)
    room.fail("min and max must be [x, y]");
  world.room_min = {min[0].number(), min[1].number()};
  world.room_max = {max[0].number(), max[1].number()};
  if ((world.room_max.array() <= world.room_min.array()).any())
    room.fail("max must exceed min in x and y");
}

// Objects stand on furniture, never in it; two objects may not share type and id.
void checkObjects(const World& world, const Field& objects) {
  std::set<asr_common::ObjectKey> seen;
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const WorldObject& object = world.objects[i];
    if (!seen.insert(object.key).second)
      objects[i].fail("a second object " + object.key.toString());
    for (const Furniture& furniture : world.furniture) {
      if (furniture.box.contains(object.box.pose.position))
        objects[i].fail(object.key.toString() + " lies inside furniture '" + furniture.name + "'");
    }
  }
}

}  // namespace

bool Box::contains(const Eigen::Vector3d& point, double margin) const {
  const Eigen::Vector3d local = pose.orientation.conjugate() * (point - pose.position);
  return (local.cwiseAbs().array() <= (size / 2.0).array() + margin).all();
}

std::vector<Eigen::Vector3d> Box::corners() const {
  std::vector<Eigen::Vector3d> result;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d signs(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
    result.push_back(pose.position + pose.orientation * (signs.cwiseProduct(size) / 2.0));
  }
  return result;
}

ObjectCatalogue loadObjectCatalogue(const std::string& path) {
  const nlohmann::json document = readDocument(path);
  const Field root(document, path, "");
  checkVersion(root);
  ObjectCatalogue catalogue;
  const Field types = root["types"];
  for (const std::string& name : types.keys()) {
    const Field entry = types[name];
    ObjectType type;
    type.size = positiveSize(entry["size"]);
    if (entry.has("normals"))
      type.normals = unitNormals(entry["normals"]);
    if (entry.has("mesh"))
      type.mesh = entry["mesh"].text();
    catalogue[name] = type;
  }
  return catalogue;
}

std::string defaultObjectCatalogue() {
  return shippedFile("config/object_types.yaml");
}

World loadWorld(const std::string& path, const ObjectCatalogue& catalogue) {
  const nlohmann::json document = readDocument(path);
  const Field root(document, path, "");
  checkVersion(root);
  World world;
  world.frame = root["frame"].text();
  if (world.frame != "map")
    root["frame"].fail("must be map");
  readRoom(root["room"], world);
  const Field furniture = root.has("furniture") ? root["furniture"] : Field(kAbsent, path, "");
  for (std::size_t i = 0; i < furniture.size(); ++i)
    world.furniture.push_back({furniture[i]["name"].text(),
                               boxAt(furniture[i]["pose"], positiveSize(furniture[i]["size"]))});
  const Field objects = root.has("objects") ? root["objects"] : Field(kAbsent, path, "");
  for (std::size_t i = 0; i < objects.size(); ++i)
    world.objects.push_back(readObject(objects[i], catalogue));
  checkObjects(world, objects);
  if (root.has("robot")) {
    const Field robot = root["robot"];
    world.robot = {robot["x"].number(), robot["y"].number(), robot["yaw"].number(),
                   robot["pan"].number(), robot["tilt"].number()};
  }
  return world;
}

}  // namespace asr_robot_model
