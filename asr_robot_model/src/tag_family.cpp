#include "asr_robot_model/tag_family.hpp"

extern "C" {
#include <apriltag/apriltag.h>
#include <apriltag/common/image_u8.h>
#include <apriltag/tag16h5.h>
#include <apriltag/tag25h9.h>
#include <apriltag/tag36h11.h>
#include <apriltag/tagStandard41h12.h>
#include <apriltag/tagStandard52h13.h>
}

#include "asr_common/input_error.hpp"

namespace asr_robot_model {
namespace {

struct FamilyFunctions {
  const char* name;
  apriltag_family_t* (*create)();
  void (*destroy)(apriltag_family_t*);
};

const FamilyFunctions kFamilies[] = {
    {"tag36h11", tag36h11_create, tag36h11_destroy},
    {"tag25h9", tag25h9_create, tag25h9_destroy},
    {"tag16h5", tag16h5_create, tag16h5_destroy},
    {"tagStandard41h12", tagStandard41h12_create, tagStandard41h12_destroy},
    {"tagStandard52h13", tagStandard52h13_create, tagStandard52h13_destroy},
};

}  // namespace

bool isKnownTagFamily(const std::string& family) {
  for (const FamilyFunctions& known : kFamilies)
    if (family == known.name)
      return true;
  return false;
}

TagFamily::TagFamily(const std::string& name) : name_(name) {
  for (const FamilyFunctions& known : kFamilies)
    if (name == known.name) {
      family_ = known.create();
      destroy_ = known.destroy;
    }
  if (family_ == nullptr)
    throw asr_common::InputError("tag family '" + name + "' is not known");
}

TagFamily::~TagFamily() {
  destroy_(family_);
}

int TagFamily::codeCount() const {
  return static_cast<int>(family_->ncodes);
}

int TagFamily::totalWidth() const {
  return family_->total_width;
}

int TagFamily::widthAtBorder() const {
  return family_->width_at_border;
}

GreyImage TagFamily::bitmap(int id) const {
  if (id < 0 || id >= codeCount())
    throw asr_common::InputError("tag " + std::to_string(id) + ": " + name_ + " has ids 0 to " +
                                 std::to_string(codeCount() - 1));
  // libapriltag draws the code's bits and borders itself; its image has padded rows.
  image_u8_t* drawn = apriltag_to_image(family_, id);
  GreyImage image(drawn->width, drawn->height);
  for (int y = 0; y < drawn->height; ++y)
    for (int x = 0; x < drawn->width; ++x)
      image.at(x, y) = drawn->buf[y * drawn->stride + x];
  image_u8_destroy(drawn);
  return image;
}

}  // namespace asr_robot_model
