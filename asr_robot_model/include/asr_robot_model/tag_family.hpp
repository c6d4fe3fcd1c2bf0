#pragma once

#include <memory>
#include <string>

#include "asr_robot_model/grey_image.hpp"

struct apriltag_family;

namespace asr_robot_model {

/// True for the families libapriltag ships with square tags: tag36h11, tag25h9, tag16h5,
/// tagStandard41h12, tagStandard52h13.
bool isKnownTagFamily(const std::string& family);

/// One of libapriltag's tag families (the codes the tags are drawn from and decoded against).
/// libapriltag wants one family instance per detector, so each user owns its own.
class TagFamily {
 public:
  /// Throws asr_common::InputError if `name` is not a known family (isKnownTagFamily).
  explicit TagFamily(const std::string& name);
  ~TagFamily();
  TagFamily(const TagFamily&) = delete;
  TagFamily& operator=(const TagFamily&) = delete;

  const std::string& name() const { return name_; }
  int codeCount() const;
  /// Cells across the whole printed tag (with its white margin) and across the part whose
  /// outer corners the detector finds (tag36h11: 10 and 8).
  int totalWidth() const;
  int widthAtBorder() const;
  /// The printed tag `id` from the family's code, one pixel per cell (totalWidth() square,
  /// black 0, white 255). Throws asr_common::InputError for an id outside the family.
  GreyImage bitmap(int id) const;

  apriltag_family* raw() const { return family_; }

 private:
  std::string name_;
  apriltag_family* family_ = nullptr;
  void (*destroy_)(apriltag_family*) = nullptr;
};

}  // namespace asr_robot_model
