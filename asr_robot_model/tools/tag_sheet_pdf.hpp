// `asr tags print --out tags.pdf`: tags as vector graphics at their true printed size.
#pragma once

#include <string>
#include <vector>

#include "asr_robot_model/tag_family.hpp"

namespace asr_robot_model::tools {

/// One tag to print: its id and the edge of its black square in millimetres.
struct PrintedTag {
  int id = 0;
  double edge_mm = 0.0;
};

/// Writes the tags on A4 pages (15 mm margins, as many per row and page as fit), each cell of
/// the family's bitmap a filled square, so the black square measures exactly `edge_mm` when
/// printed at 100 % ("actual size"); a light grey line marks the white margin for cutting and
/// a caption gives family, id and edge length. A PDF written by hand (uncompressed, one font
/// of the standard 14) keeps the suite free of a PDF library. Throws asr_common::InputError
/// naming the tag if it does not fit on a page, and naming the file if it cannot be written.
void writeTagSheetPdf(const std::string& path, const TagFamily& family,
                      const std::vector<PrintedTag>& tags);

}  // namespace asr_robot_model::tools
