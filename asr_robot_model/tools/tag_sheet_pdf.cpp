#include "tag_sheet_pdf.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "asr_common/input_error.hpp"

namespace asr_robot_model::tools {
namespace {

constexpr double kPageWidthMm = 210.0, kPageHeightMm = 297.0, kMarginMm = 15.0;
constexpr double kCaptionMm = 8.0, kGapMm = 6.0;
constexpr double kPointsPerMm = 72.0 / 25.4;

std::string number(double millimetres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", millimetres * kPointsPerMm);
  return text;
}

/// Drawing commands for one tag whose printed square (with margin) has its top left corner at
/// (left, top) mm from the page's top left.
std::string drawTag(const TagFamily& family, const PrintedTag& tag, double left, double top) {
  const GreyImage bitmap = family.bitmap(tag.id);
  const double cell = tag.edge_mm / family.widthAtBorder();
  const double side = cell * family.totalWidth();
  std::ostringstream out;
  out << "0.75 G 0.2 w " << number(left) << " " << number(kPageHeightMm - top - side) << " "
      << number(side) << " " << number(side) << " re S\n0 g\n";
  // One rectangle per run of black cells in a row.
  for (int y = 0; y < bitmap.height; ++y)
    for (int x = 0; x < bitmap.width;) {
      if (bitmap.at(x, y) >= 128) {
        ++x;
        continue;
      }
      const int start = x;
      while (x < bitmap.width && bitmap.at(x, y) < 128)
        ++x;
      out << number(left + start * cell) << " " << number(kPageHeightMm - top - (y + 1) * cell)
          << " " << number((x - start) * cell) << " " << number(cell) << " re\n";
    }
  char caption[128];
  std::snprintf(caption, sizeof caption, "%s id %d, edge %.1f mm", family.name().c_str(), tag.id,
                tag.edge_mm);
  out << "f\nBT /F1 9 Tf " << number(left) << " "
      << number(kPageHeightMm - top - side - 0.6 * kCaptionMm) << " Td (" << caption << ") Tj ET\n";
  return out.str();
}

/// The content stream of each page: tags in rows, left to right, top to bottom.
std::vector<std::string> layOut(const TagFamily& family, const std::vector<PrintedTag>& tags) {
  std::vector<std::string> pages(1);
  double x = kMarginMm, y = kMarginMm, row_height = 0.0;
  for (const PrintedTag& tag : tags) {
    const double side = tag.edge_mm / family.widthAtBorder() * family.totalWidth();
    if (side > kPageWidthMm - 2 * kMarginMm || side + kCaptionMm > kPageHeightMm - 2 * kMarginMm)
      throw asr_common::InputError("tag " + std::to_string(tag.id) + ": " +
                                   std::to_string(tag.edge_mm) + " mm is too large for an A4 page");
    if (x + side > kPageWidthMm - kMarginMm) {
      x = kMarginMm;
      y += row_height + kGapMm;
      row_height = 0.0;
    }
    if (y + side + kCaptionMm > kPageHeightMm - kMarginMm) {
      pages.emplace_back();
      x = y = kMarginMm;
      row_height = 0.0;
    }
    pages.back() += drawTag(family, tag, x, y);
    x += side + kGapMm;
    row_height = std::max(row_height, side + kCaptionMm);
  }
  return pages;
}

}  // namespace

void writeTagSheetPdf(const std::string& path, const TagFamily& family,
                      const std::vector<PrintedTag>& tags) {
  const std::vector<std::string> pages = layOut(family, tags);
  // Objects: 1 catalog, 2 page tree, 3 font, then per page its page object and content stream.
  std::vector<std::string> objects = {"<< /Type /Catalog /Pages 2 0 R >>", "",
                                      "<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica >>"};
  std::string kids;
  for (std::size_t page = 0; page < pages.size(); ++page) {
    const std::size_t page_object = objects.size() + 1;
    kids += std::to_string(page_object) + " 0 R ";
    objects.push_back("<< /Type /Page /Parent 2 0 R /MediaBox [0 0 " + number(kPageWidthMm) + " " +
                      number(kPageHeightMm) +
                      "] /Resources << /Font << /F1 3 0 R >> >> /Contents " +
                      std::to_string(page_object + 1) + " 0 R >>");
    objects.push_back("<< /Length " + std::to_string(pages[page].size()) + " >>\nstream\n" +
                      pages[page] + "endstream");
  }
  objects[1] =
      "<< /Type /Pages /Kids [" + kids + "] /Count " + std::to_string(pages.size()) + " >>";

  std::string pdf = "%PDF-1.4\n";
  std::vector<std::size_t> offsets;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    offsets.push_back(pdf.size());
    pdf += std::to_string(i + 1) + " 0 obj\n" + objects[i] + "\nendobj\n";
  }
  const std::size_t xref = pdf.size();
  pdf += "xref\n0 " + std::to_string(objects.size() + 1) + "\n0000000000 65535 f \n";
  for (const std::size_t offset : offsets) {
    char entry[32];
    std::snprintf(entry, sizeof entry, "%010zu 00000 n \n", offset);
    pdf += entry;
  }
  pdf += "trailer\n<< /Size " + std::to_string(objects.size() + 1) +
         " /Root 1 0 R >>\nstartxref\n" + std::to_string(xref) + "\n%%EOF\n";
  std::ofstream file(path, std::ios::binary);
  file << pdf;
  if (!file.flush())
    throw asr_common::InputError(path + ": cannot write the PDF");
}

}  // namespace asr_robot_model::tools
