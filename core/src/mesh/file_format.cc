#include "mesh/file_format.h"

#include <cctype>
#include <cstdio>
#include <cstring>
#include <memory>

#include <sys/stat.h>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/ply_header.h"
#include "mesh/source.h"
#include "mesh/text_cursor.h"

namespace meshseg {
namespace mesh_internal {
namespace {

FileFormat FormatOfExtension(const std::string& path) {
  const std::string name = FileName(path);
  const size_t dot = name.find_last_of('.');
  if (dot == std::string::npos) return FileFormat::kUnknown;
  std::string ext = name.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "stl") return FileFormat::kStl;
  if (ext == "obj") return FileFormat::kObj;
  if (ext == "off") return FileFormat::kOff;
  if (ext == "ply") return FileFormat::kPly;
  if (ext == "xyz") return FileFormat::kXyz;
  if (ext == "pwn") return FileFormat::kPwn;
  if (ext == "nrrd" || ext == "nhdr") return FileFormat::kNrrd;
  if (ext == "mha") return FileFormat::kMha;
  if (ext == "mhd") return FileFormat::kMhd;
  if (ext == "raw") return FileFormat::kRaw;
  return FileFormat::kUnknown;
}

// Number of values on the first non-empty lines of text: {first, second}.
std::pair<int, int> ValuesPerLine(std::string_view head) {
  TextCursor cursor(head, /*comma_is_space=*/true);
  int counts[2] = {0, 0};
  for (int line = 0; line < 2 && cursor.SkipEmptyLines(); ++line) {
    for (std::string_view t = cursor.Token(); !t.empty(); t = cursor.Token()) {
      if (!ParseDouble(t)) return {-1, -1};
      ++counts[line];
    }
    cursor.NextLine();
  }
  return {counts[0], counts[1]};
}

FileFormat FormatOfContent(std::string_view head, int64_t size) {
  if (size >= 84) {
    uint32_t n;
    std::memcpy(&n, head.data() + 80, sizeof(n));
    if (84 + 50 * static_cast<int64_t>(n) == size) return FileFormat::kStl;
  }
  const std::string_view text = StripLeadingSpace(head);
  if (text.starts_with("ply")) return FileFormat::kPly;
  if (head.starts_with("NRRD000")) return FileFormat::kNrrd;
  if (text.starts_with("ObjectType") || text.starts_with("NDims")) return FileFormat::kMha;
  if (text.starts_with("solid")) return FileFormat::kStl;
  for (const char* magic : {"OFF", "COFF", "NOFF", "CNOFF"}) {
    if (text.starts_with(magic)) return FileFormat::kOff;
  }
  if (text.starts_with("v ") || head.find("\nv ") != std::string_view::npos) return FileFormat::kObj;
  const auto [first, second] = ValuesPerLine(head);
  if (first == 1 && second == 3) return FileFormat::kPwn;
  if (first == 3 || first == 6) return FileFormat::kXyz;
  return FileFormat::kUnknown;
}

}  // namespace

FileFormat FormatOf(const std::string& path, std::string_view head, int64_t size) {
  const FileFormat by_name = FormatOfExtension(path);
  if (by_name != FileFormat::kUnknown) return by_name;
  return FormatOfContent(head.substr(0, 4096), size);
}

absl::StatusOr<InputFile> OpenInput(const std::string& path, const ReadMeshOptions& options,
                                    const Source& src) {
  if (options.max_elements <= 0) {
    return BadInput(src, absl::StrCat("max_elements must be positive, got ",
                                      options.max_elements));
  }
  InputFile input;
  MESHSEG_ASSIGN_OR_RETURN(input.file, ReadFileBytes(path, src));
  const std::string_view bytes = input.bytes();
  if (bytes.empty()) return BadInput(src, "empty file");
  input.format = options.format.value_or(
      FormatOf(path, bytes.substr(0, 4096), static_cast<int64_t>(bytes.size())));
  return input;
}

}  // namespace mesh_internal

const char* FileFormatName(FileFormat format) {
  switch (format) {
    case FileFormat::kStl: return "stl";
    case FileFormat::kObj: return "obj";
    case FileFormat::kOff: return "off";
    case FileFormat::kPly: return "ply";
    case FileFormat::kXyz: return "xyz";
    case FileFormat::kPwn: return "pwn";
    case FileFormat::kNrrd: return "nrrd";
    case FileFormat::kMha: return "mha";
    case FileFormat::kMhd: return "mhd";
    case FileFormat::kRaw: return "raw";
    case FileFormat::kUnknown: break;
  }
  return "unknown";
}

absl::StatusOr<FileFormat> DetectFileFormat(const std::string& path) {
  const mesh_internal::Source src{"detect_format", mesh_internal::FileName(path)};
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  struct stat info;
  if (file == nullptr || stat(path.c_str(), &info) != 0) {
    return absl::NotFoundError(absl::StrCat("detect_format: \"", src.name, "\": cannot open"));
  }
  std::string head(4096, '\0');
  head.resize(std::fread(head.data(), 1, head.size(), file.get()));
  const FileFormat format = mesh_internal::FormatOf(path, head, info.st_size);
  if (format == FileFormat::kUnknown) {
    return mesh_internal::BadInput(
        src, "unknown format (extension and content match none of stl, obj, off, ply, xyz, pwn, "
             "nrrd, mha, mhd, raw)");
  }
  return format;
}

absl::StatusOr<bool> IsPointCloudFile(const std::string& path) {
  MESHSEG_ASSIGN_OR_RETURN(const FileFormat format, DetectFileFormat(path));
  if (format == FileFormat::kXyz || format == FileFormat::kPwn) return true;
  if (format != FileFormat::kPly) return false;
  const mesh_internal::Source src{"detect_format", mesh_internal::FileName(path)};
  MESHSEG_ASSIGN_OR_RETURN(const mesh_internal::FileBytes file,
                           mesh_internal::ReadFileBytes(path, src));
  MESHSEG_ASSIGN_OR_RETURN(const mesh_internal::PlyHeader header,
                           mesh_internal::ParsePlyHeader(file.view(), src));
  for (const mesh_internal::PlyElement& element : header.elements) {
    if (element.name == "face" && element.count > 0) return false;
  }
  return true;
}

}  // namespace meshseg
