#include "mesh/ply_header.h"

#include <optional>

#include "absl/strings/str_cat.h"
#include "mesh/text_cursor.h"

namespace meshseg::mesh_internal {
namespace {

std::optional<PlyType> TypeNamed(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::kInt8;
  if (name == "uchar" || name == "uint8") return PlyType::kUint8;
  if (name == "short" || name == "int16") return PlyType::kInt16;
  if (name == "ushort" || name == "uint16") return PlyType::kUint16;
  if (name == "int" || name == "int32") return PlyType::kInt32;
  if (name == "uint" || name == "uint32") return PlyType::kUint32;
  if (name == "float" || name == "float32") return PlyType::kFloat32;
  if (name == "double" || name == "float64") return PlyType::kFloat64;
  return std::nullopt;
}

}  // namespace

int PlyTypeSize(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 0;
}

int PlyElement::Find(std::string_view property_name) const {
  for (size_t i = 0; i < properties.size(); ++i) {
    if (properties[i].name == property_name) return static_cast<int>(i);
  }
  return -1;
}

absl::StatusOr<PlyHeader> ParsePlyHeader(std::string_view bytes, const Source& src) {
  // The header is text even in binary files; stop the cursor at end_header.
  // "end_header" at the start of a line (not inside a comment).
  size_t end = bytes.find("\nend_header");
  if (end != std::string_view::npos) ++end;
  if (bytes.substr(0, 3) != "ply") return BadInput(src, "missing \"ply\" magic at byte 0");
  if (end == std::string_view::npos) return BadInput(src, "no \"end_header\" line");
  TextCursor cursor(bytes.substr(0, end + 10));
  cursor.set_comments(false);
  auto at_line = [&](const std::string& what) {
    return BadInput(src, absl::StrCat("header line ", cursor.line(), ": ", what));
  };
  PlyHeader header;
  bool have_format = false;
  cursor.NextLine();
  while (cursor.SkipEmptyLines()) {
    const std::string_view word = cursor.Token();
    if (word == "format") {
      const std::string_view encoding = cursor.Token();
      if (encoding == "ascii") {
        header.encoding = PlyEncoding::kAscii;
      } else if (encoding == "binary_little_endian") {
        header.encoding = PlyEncoding::kBinaryLittleEndian;
      } else if (encoding == "binary_big_endian") {
        header.encoding = PlyEncoding::kBinaryBigEndian;
      } else {
        return at_line(absl::StrCat("unknown format \"", Shorten(encoding), "\""));
      }
      have_format = true;
    } else if (word == "element") {
      PlyElement element;
      element.name = std::string(cursor.Token());
      const std::optional<int64_t> count = ParseInt(cursor.Token());
      if (element.name.empty() || !count || *count < 0) {
        return at_line("expected \"element <name> <count>\"");
      }
      element.count = *count;
      header.elements.push_back(std::move(element));
    } else if (word == "property") {
      if (header.elements.empty()) return at_line("property before any element");
      PlyProperty property;
      std::string_view type_name = cursor.Token();
      if (type_name == "list") {
        property.is_list = true;
        const std::optional<PlyType> count_type = TypeNamed(cursor.Token());
        if (!count_type || *count_type == PlyType::kFloat32 ||
            *count_type == PlyType::kFloat64) {
          return at_line("bad list count type");
        }
        property.count_type = *count_type;
        type_name = cursor.Token();
      }
      const std::optional<PlyType> type = TypeNamed(type_name);
      if (!type) return at_line(absl::StrCat("unknown type \"", Shorten(type_name), "\""));
      property.type = *type;
      property.name = std::string(cursor.Token());
      if (property.name.empty()) return at_line("property without a name");
      header.elements.back().properties.push_back(std::move(property));
    } else if (word == "end_header") {
      if (!have_format) return at_line("end_header before a format line");
      // The cursor stops right after "end_header"; its newline may be \r\n.
      header.body_offset = end + 10;
      if (header.body_offset < bytes.size() && bytes[header.body_offset] == '\r') {
        ++header.body_offset;
      }
      if (header.body_offset < bytes.size() && bytes[header.body_offset] == '\n') {
        ++header.body_offset;
      }
      header.body_line = cursor.line() + 1;
      return header;
    } else if (word != "comment" && word != "obj_info") {
      return at_line(absl::StrCat("unexpected \"", Shorten(word), "\""));
    }
    cursor.NextLine();
  }
  return BadInput(src, "no \"end_header\" line");
}

}  // namespace meshseg::mesh_internal
