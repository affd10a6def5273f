// ProbeInput: the element counts a file declares, from its header (binary
// STL, PLY, OFF, PWN) or from one streamed pass over its lines (OBJ, ASCII
// STL, XYZ), without mapping or building anything: what admission control
// needs to estimate a job's memory before the job is read.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "absl/strings/str_cat.h"
#include "mesh/file_format.h"
#include "mesh/ply_header.h"
#include "mesh/source.h"
#include "mesh/text_cursor.h"
#include "meshseg/input_size.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

using mesh_internal::BadInput;
using mesh_internal::Source;

constexpr std::size_t kHeadBytes = 64 << 10;  // enough for any PLY header we accept
constexpr std::size_t kChunkBytes = 4 << 20;

// An open file descriptor, closed on scope exit.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

// Counts, per line of a text file, what ProbeInput needs: lines starting
// with the keywords below, and the corners on OBJ face lines.
struct LineCounts {
  int64_t lines = 0;    // non-empty lines not starting with '#'
  int64_t v = 0;        // "v" lines (OBJ vertices)
  int64_t f = 0;        // "f" lines (OBJ faces)
  int64_t corners = 0;  // tokens after "f"
  int64_t facet = 0;    // "facet" lines (ASCII STL triangles)

  void Add(std::string_view line) {
    line = mesh_internal::StripLeadingSpace(line);
    if (line.empty() || line[0] == '#') return;
    ++lines;
    const std::size_t end = line.find_first_of(" \t\r");
    const std::string_view keyword = line.substr(0, end);
    if (keyword == "v") {
      ++v;
    } else if (keyword == "facet") {
      ++facet;
    } else if (keyword == "f") {
      ++f;
      bool in_token = false;
      for (const char c : line.substr(1)) {
        const bool blank = c == ' ' || c == '\t' || c == '\r';
        if (!blank && !in_token) ++corners;
        in_token = !blank;
      }
    }
  }
};

// Returns the line counts of the whole file behind `fd`, read in chunks.
absl::StatusOr<LineCounts> CountLines(int fd, const Source& src) {
  LineCounts counts;
  std::vector<char> buffer(kChunkBytes);
  std::string carry;  // the unfinished last line of the previous chunk
  off_t offset = 0;
  while (true) {
    const ssize_t n = pread(fd, buffer.data(), buffer.size(), offset);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return BadInput(src, absl::StrCat("read failed: ", std::strerror(errno)));
    if (n == 0) break;
    offset += n;
    std::string_view chunk(buffer.data(), static_cast<std::size_t>(n));
    std::size_t newline;
    while ((newline = chunk.find('\n')) != std::string_view::npos) {
      if (carry.empty()) {
        counts.Add(chunk.substr(0, newline));
      } else {
        carry.append(chunk.substr(0, newline));
        counts.Add(carry);
        carry.clear();
      }
      chunk.remove_prefix(newline + 1);
    }
    // A line longer than a chunk only needs its start to be classified.
    if (carry.size() < 4096) carry.append(chunk.substr(0, 4096 - carry.size()));
  }
  if (!carry.empty()) counts.Add(carry);
  return counts;
}

// Returns the first integer tokens of the first non-comment lines of a
// text header (OFF: "OFF" then "nv nf ne"; PWN: "n").
std::vector<int64_t> HeaderInts(std::string_view head, std::size_t wanted) {
  std::vector<int64_t> values;
  mesh_internal::TextCursor cursor(head);
  while (values.size() < wanted && cursor.SkipEmptyLines()) {
    while (values.size() < wanted && !cursor.AtLineEnd()) {
      const std::string_view token = cursor.Token();
      if (const std::optional<int64_t> v = mesh_internal::ParseInt(token)) values.push_back(*v);
    }
    cursor.NextLine();
  }
  return values;
}

}  // namespace

absl::StatusOr<InputSize> ProbeInput(const std::string& path, std::optional<FileFormat> format) {
  const Source src{"probe_input", mesh_internal::FileName(path)};
  Fd file{open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) {
    return absl::NotFoundError(
        absl::StrCat("probe_input: \"", src.name, "\": cannot open: ", std::strerror(errno)));
  }
  struct stat info;
  if (fstat(file.fd, &info) != 0 || !S_ISREG(info.st_mode))
    return BadInput(src, "not a regular file");
  if (info.st_size == 0) return BadInput(src, "empty file");
  std::string head(std::min<std::size_t>(kHeadBytes, static_cast<std::size_t>(info.st_size)), '\0');
  if (pread(file.fd, head.data(), head.size(), 0) != static_cast<ssize_t>(head.size())) {
    return BadInput(src, "cannot read the header");
  }
  InputSize size;
  size.file_bytes = info.st_size;
  size.format = format.value_or(mesh_internal::FormatOf(path, head, info.st_size));
  switch (size.format) {
    case FileFormat::kStl: {
      const bool binary = info.st_size >= 84 && !head.starts_with("solid");
      uint32_t declared = 0;
      if (info.st_size >= 84) std::memcpy(&declared, head.data() + 80, sizeof(declared));
      if (binary || (info.st_size >= 84 && 84 + 50 * int64_t{declared} == info.st_size)) {
        size.face_count = declared;
      } else {
        MESHSEG_ASSIGN_OR_RETURN(const LineCounts counts, CountLines(file.fd, src));
        size.face_count = counts.facet;
      }
      size.vertex_count = 3 * size.face_count;  // corners, before welding
      break;
    }
    case FileFormat::kObj: {
      MESHSEG_ASSIGN_OR_RETURN(const LineCounts counts, CountLines(file.fd, src));
      size.vertex_count = counts.v;
      size.face_count = counts.corners - 2 * counts.f;  // fan triangles
      break;
    }
    case FileFormat::kOff: {
      // Skip the "OFF" keyword (possibly with the counts on its line).
      const std::size_t after = head.find("OFF");
      const std::vector<int64_t> n =
          HeaderInts(std::string_view(head).substr(after == std::string::npos ? 0 : after + 3), 2);
      if (n.size() < 2) return BadInput(src, "no vertex and face counts in the OFF header");
      size.vertex_count = n[0];
      size.face_count = n[1];
      break;
    }
    case FileFormat::kPly: {
      MESHSEG_ASSIGN_OR_RETURN(const mesh_internal::PlyHeader header,
                               mesh_internal::ParsePlyHeader(head, src));
      for (const mesh_internal::PlyElement& e : header.elements) {
        if (e.name == "vertex") size.vertex_count = e.count;
        if (e.name == "face") size.face_count = e.count;
      }
      size.point_cloud = size.face_count == 0;
      break;
    }
    case FileFormat::kPwn: {
      const std::vector<int64_t> n = HeaderInts(head, 1);
      if (n.empty()) return BadInput(src, "no point count in the PWN header");
      size.vertex_count = n[0];
      size.point_cloud = true;
      break;
    }
    case FileFormat::kXyz: {
      MESHSEG_ASSIGN_OR_RETURN(const LineCounts counts, CountLines(file.fd, src));
      size.vertex_count = counts.lines;
      size.point_cloud = true;
      break;
    }
    case FileFormat::kNrrd:
    case FileFormat::kMha:
    case FileFormat::kMhd:
    case FileFormat::kRaw:
      // A volume's size is its header's grid (meshseg/voxel.h); the memory
      // model costs volumes from that, never from mesh element counts.
      return BadInput(src, absl::StrCat("a ", FileFormatName(size.format),
                                        " volume has no mesh element counts; read its volume "
                                        "header (meshseg/voxel.h)"));
    case FileFormat::kUnknown:
      return BadInput(src,
                      "unknown format (extension and content match none of stl, obj, off, "
                      "ply, xyz, pwn)");
  }
  if (size.vertex_count < 0 || size.face_count < 0) {
    return BadInput(src, absl::StrCat("negative count in the header (", size.vertex_count,
                                      " vertices, ", size.face_count, " faces)"));
  }
  return size;
}

}  // namespace meshseg
