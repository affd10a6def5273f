#include "mesh/ply_body.h"

#include <atomic>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/ply_header.h"
#include "mesh/text_cursor.h"

namespace meshseg::mesh_internal {
namespace {

// Corners a face may have: a polygon with more is taken as a corrupt list
// length, not a face.
constexpr double kMaxFaceCorners = 1'000'000;

template <typename T>
double Read(const unsigned char* raw) {
  T value;
  std::memcpy(&value, raw, sizeof(T));
  return static_cast<double>(value);
}

// The value of `type` whose bytes (in the host's order) start at raw.
double Decode(PlyType type, const unsigned char* raw) {
  switch (type) {
    case PlyType::kInt8: return Read<int8_t>(raw);
    case PlyType::kUint8: return Read<uint8_t>(raw);
    case PlyType::kInt16: return Read<int16_t>(raw);
    case PlyType::kUint16: return Read<uint16_t>(raw);
    case PlyType::kInt32: return Read<int32_t>(raw);
    case PlyType::kUint32: return Read<uint32_t>(raw);
    case PlyType::kFloat32: return Read<float>(raw);
    case PlyType::kFloat64: return Read<double>(raw);
  }
  return 0.0;
}

// The binary value of `type` (`size` bytes) at `at`, in the file's order.
double DecodeAt(PlyType type, int size, const char* at, bool big_endian) {
  unsigned char raw[8];
  std::memcpy(raw, at, size);
  if (big_endian) {
    for (int i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
  }
  return Decode(type, raw);
}

// Reads the values of the body one at a time, ascii or binary, and names the
// place of an error.
class ValueReader {
 public:
  ValueReader(std::string_view bytes, const PlyHeader& header, const Source& src)
      : bytes_(bytes), pos_(header.body_offset), body_offset_(header.body_offset),
        encoding_(header.encoding), src_(src), cursor_(bytes.substr(header.body_offset)) {
    cursor_.set_comments(false);
    line_offset_ = header.body_line - 1;
  }

  absl::StatusOr<double> Next(PlyType type, const std::string& what) {
    if (encoding_ == PlyEncoding::kAscii) return NextAscii(what);
    const int size = PlyTypeSize(type);
    if (pos_ + size > bytes_.size()) {
      return BadInput(src_, absl::StrCat("truncated at byte offset ", pos_, " reading ", what,
                                         " (file is ", bytes_.size(), " bytes)"));
    }
    const double value = DecodeAt(type, size, bytes_.data() + pos_,
                                  encoding_ == PlyEncoding::kBinaryBigEndian);
    pos_ += size;
    return value;
  }

  // Ends one element instance (one line in ascii).
  absl::Status EndElement(const std::string& what) {
    if (encoding_ != PlyEncoding::kAscii) return absl::OkStatus();
    if (!cursor_.AtLineEnd()) {
      return Error(absl::StrCat("extra values after ", what));
    }
    cursor_.NextLine();
    return absl::OkStatus();
  }

  absl::Status Error(const std::string& what) const {
    if (encoding_ == PlyEncoding::kAscii) {
      return BadInput(src_, absl::StrCat("line ", cursor_.line() + line_offset_, ": ", what));
    }
    return BadInput(src_, absl::StrCat("byte offset ", pos_, ": ", what));
  }

  // Starts one element instance; ascii files may have blank lines between.
  void BeginElement() {
    if (encoding_ == PlyEncoding::kAscii) cursor_.SkipEmptyLines();
  }

  bool ascii() const { return encoding_ == PlyEncoding::kAscii; }
  bool big_endian() const { return encoding_ == PlyEncoding::kBinaryBigEndian; }

  // The whole file and the binary read position (for ReadBinaryElement).
  std::string_view bytes() const { return bytes_; }
  size_t position() const { return pos_; }
  void set_position(size_t pos) { pos_ = pos; }

  // Bytes of the file not read yet.
  int64_t BytesLeft() const {
    const size_t at = ascii() ? body_offset_ + cursor_.offset() : pos_;
    return at < bytes_.size() ? static_cast<int64_t>(bytes_.size() - at) : 0;
  }

 private:
  absl::StatusOr<double> NextAscii(const std::string& what) {
    if (cursor_.AtEnd()) return Error(absl::StrCat("file ends while reading ", what));
    const std::string_view token = cursor_.Token();
    const std::optional<double> value = ParseDouble(token);
    if (!value) {
      return Error(absl::StrCat("expected a number for ", what, ", got \"", Shorten(token),
                                "\""));
    }
    return *value;
  }

  std::string_view bytes_;
  size_t pos_;
  size_t body_offset_;
  PlyEncoding encoding_;
  const Source& src_;
  TextCursor cursor_;
  int64_t line_offset_ = 0;
};

// Smallest number of bytes one instance of `element` can take.
int64_t MinElementBytes(const PlyElement& element, bool ascii) {
  int64_t bytes = 0;
  for (const PlyProperty& p : element.properties) {
    if (ascii) {
      bytes += 2;  // a digit and a separator
    } else {
      bytes += p.is_list ? PlyTypeSize(p.count_type) : PlyTypeSize(p.type);
    }
  }
  return bytes;
}

// What a property of the vertex or face element is read into.
struct PropertyRoles {
  int xyz[3] = {-1, -1, -1};   // property index of each coordinate
  int nxyz[3] = {-1, -1, -1};  // of each normal component, if `normals`
  bool normals = false;
  int corners = -1;  // the face element's list of vertex indices
};

// A binary face element whose one property is its corner list, all of
// triangles, read side by side; false (nothing written) if it is not that
// or a value fails a check, for ReadBinaryElement to read as before. The
// count at byte pos + i * (one triangle's bytes) being 3 for every i proves
// face i starts there (by induction from face 0), so each face is decoded
// alone into its own slots: the values and checks ReadBinaryElement's.
bool ReadBinaryTriangles(const PlyElement& element, const PropertyRoles& roles,
                         ValueReader& reader, PlyData* data) {
  if (element.properties.size() != 1 || roles.corners != 0) return false;
  const PlyProperty& p = element.properties[0];
  const int count_size = PlyTypeSize(p.count_type);
  const int size = PlyTypeSize(p.type);
  const int64_t record = count_size + 3 * size;
  const std::string_view bytes = reader.bytes();
  const size_t begin = reader.position();
  if (element.count <= 0 || (bytes.size() - begin) / record < static_cast<size_t>(element.count)) {
    return false;
  }
  const bool big_endian = reader.big_endian();
  const double nv = static_cast<double>(data->vertices.size());
  const size_t first = data->corners.size();  // = data->face_start.back()
  data->corners.resize(first + 3 * element.count);
  data->face_start.resize(data->face_start.size() + element.count);
  int64_t* starts = data->face_start.data() + data->face_start.size() - element.count;
  std::atomic<bool> failed{false};
  tbb::parallel_for(tbb::blocked_range<int64_t>(0, element.count, 1 << 14),
                    [&](const tbb::blocked_range<int64_t>& range) {
    for (int64_t i = range.begin(); i < range.end() && !failed; ++i) {
      const char* at = bytes.data() + begin + i * record;
      bool ok = DecodeAt(p.count_type, count_size, at, big_endian) == 3.0;
      for (int c = 0; c < 3 && ok; ++c) {
        const double v = DecodeAt(p.type, size, at + count_size + c * size, big_endian);
        ok = v >= 0 && v < nv && v == std::floor(v);
        if (ok) data->corners[first + 3 * i + c] = static_cast<int>(v);
      }
      if (!ok) failed = true;
      starts[i] = static_cast<int64_t>(first + 3 * (i + 1));
    }
  });
  if (failed) {
    data->corners.resize(first);
    data->face_start.resize(data->face_start.size() - element.count);
    return false;
  }
  reader.set_position(begin + element.count * record);
  return true;
}

// Reads the binary `element` in one pass, with the checks ReadElement makes
// value by value. True if every value passed; false where one did not (or
// the file ends), with the reader not moved, so that ReadElement reads the
// element again value by value and names the error as before. On false,
// `data`'s corners / face_start may hold a partial element: the caller cuts
// them back.
bool ReadBinaryElement(const PlyElement& element, const PropertyRoles& roles,
                       ValueReader& reader, PlyData* data) {
  const std::string_view bytes = reader.bytes();
  const bool big_endian = reader.big_endian();
  const int64_t nv = static_cast<int64_t>(data->vertices.size());
  const bool is_vertex = roles.xyz[0] >= 0;
  if (!is_vertex && ReadBinaryTriangles(element, roles, reader, data)) return true;
  size_t pos = reader.position();
  for (int64_t i = 0; i < element.count; ++i) {
    for (int k = 0; k < static_cast<int>(element.properties.size()); ++k) {
      const PlyProperty& p = element.properties[k];
      const int size = PlyTypeSize(p.type);
      if (p.is_list) {
        const int count_size = PlyTypeSize(p.count_type);
        if (pos + count_size > bytes.size()) return false;
        const double n = DecodeAt(p.count_type, count_size, bytes.data() + pos, big_endian);
        pos += count_size;
        const bool corners = k == roles.corners;
        if (corners && (n < 3 || n > kMaxFaceCorners)) return false;
        if (!(n >= 0) || n != std::floor(n) || n > static_cast<double>(bytes.size() - pos)) {
          return false;
        }
        const int64_t count = static_cast<int64_t>(n);
        if (pos + count * size > bytes.size()) return false;
        for (int64_t c = 0; c < count; ++c, pos += size) {
          if (!corners) continue;
          const double v = DecodeAt(p.type, size, bytes.data() + pos, big_endian);
          if (!(v >= 0 && v < static_cast<double>(nv)) || v != std::floor(v)) return false;
          data->corners.push_back(static_cast<int>(v));
        }
        if (corners) data->face_start.push_back(static_cast<int64_t>(data->corners.size()));
        continue;
      }
      if (pos + size > bytes.size()) return false;
      const double v = DecodeAt(p.type, size, bytes.data() + pos, big_endian);
      pos += size;
      for (int c = 0; c < 3 && is_vertex; ++c) {
        if (k == roles.xyz[c]) {
          if (!std::isfinite(v)) return false;
          data->vertices[i][c] = v;
        }
        if (k == roles.nxyz[c] && roles.normals) data->normals[i][c] = v;
      }
    }
  }
  reader.set_position(pos);
  return true;
}

absl::Status ReadElement(const PlyElement& element, ValueReader& reader, PlyData* data) {
  const bool is_vertex = element.name == "vertex";
  const bool is_face = element.name == "face";
  int xyz[3] = {-1, -1, -1};
  int nxyz[3] = {-1, -1, -1};
  int indices = -1;
  bool normals = false;  // all of nx ny nz present
  if (is_vertex) {
    const char* names[3] = {"x", "y", "z"};
    const char* normal_names[3] = {"nx", "ny", "nz"};
    for (int c = 0; c < 3; ++c) {
      xyz[c] = element.Find(names[c]);
      nxyz[c] = element.Find(normal_names[c]);
      if (xyz[c] < 0 || element.properties[xyz[c]].is_list) {
        return reader.Error(absl::StrCat("element vertex has no scalar property ", names[c]));
      }
    }
    normals = nxyz[0] >= 0 && nxyz[1] >= 0 && nxyz[2] >= 0;
    data->vertices.resize(element.count);
    if (normals) data->normals.resize(element.count);
  }
  if (is_face) {
    indices = element.Find("vertex_indices");
    if (indices < 0) indices = element.Find("vertex_index");
    if (indices < 0 || !element.properties[indices].is_list) {
      return reader.Error("element face has no list property vertex_indices");
    }
    data->has_face_element = true;
    data->face_start.assign(1, 0);
    data->face_start.reserve(element.count + 1);
    data->corners.reserve(3 * element.count);
  }
  // Binary: the element in one pass; value by value only to name an error.
  if (!reader.ascii()) {
    PropertyRoles roles;
    for (int c = 0; c < 3 && is_vertex; ++c) {
      roles.xyz[c] = xyz[c];
      roles.nxyz[c] = nxyz[c];
    }
    roles.normals = normals;
    roles.corners = indices;
    const size_t corner_count = data->corners.size();
    const size_t face_start_count = data->face_start.size();
    if (ReadBinaryElement(element, roles, reader, data)) return absl::OkStatus();
    data->corners.resize(corner_count);
    data->face_start.resize(face_start_count);
  }
  const int64_t nv = static_cast<int64_t>(data->vertices.size());
  for (int64_t i = 0; i < element.count; ++i) {
    reader.BeginElement();
    for (size_t k = 0; k < element.properties.size(); ++k) {
      const PlyProperty& p = element.properties[k];
      if (p.is_list) {
        MESHSEG_ASSIGN_OR_RETURN(const double n, reader.Next(p.count_type, "a list length"));
        const bool corners = is_face && static_cast<int>(k) == indices;
        if (corners && (n < 3 || n > kMaxFaceCorners)) {
          return reader.Error(
              absl::StrCat("face ", i, " has ", n, " corners, expected 3 to ",
                                         static_cast<int64_t>(kMaxFaceCorners)));
        }
        if (n < 0) return reader.Error(absl::StrCat("negative list length ", n));
        // A length counts the values that follow, each at least one byte
        // (text or binary): a whole number no larger than the bytes left.
        if (n != std::floor(n) || n > static_cast<double>(reader.BytesLeft())) {
          // Whole lengths are shown as integers ("4000000000", not "4e+09").
          const std::string shown = n == std::floor(n) && std::abs(n) < 9e15
                                        ? absl::StrCat(static_cast<int64_t>(n))
                                        : absl::StrCat(n);
          return reader.Error(absl::StrCat("list length ", shown, " of ", p.name,
                                           " is not a whole number of values the ",
                                           reader.BytesLeft(), " bytes left can hold"));
        }
        for (int64_t c = 0; c < static_cast<int64_t>(n); ++c) {
          MESHSEG_ASSIGN_OR_RETURN(const double v, reader.Next(p.type, p.name));
          if (!corners) continue;
          if (!(v >= 0 && v < static_cast<double>(nv)) || v != std::floor(v)) {
            return reader.Error(absl::StrCat("face ", i, ": vertex index ", v,
                                             " out of range [0, ", nv, ")"));
          }
          data->corners.push_back(static_cast<int>(v));
        }
        if (corners) data->face_start.push_back(static_cast<int64_t>(data->corners.size()));
        continue;
      }
      MESHSEG_ASSIGN_OR_RETURN(const double v, reader.Next(p.type, p.name));
      for (int c = 0; c < 3 && is_vertex; ++c) {
        if (static_cast<int>(k) == xyz[c]) {
          if (!std::isfinite(v)) {
            return reader.Error(absl::StrCat("vertex ", i, ": non-finite coordinate ", v));
          }
          data->vertices[i][c] = v;
        }
        if (static_cast<int>(k) == nxyz[c] && normals) data->normals[i][c] = v;
      }
    }
    MESHSEG_RETURN_IF_ERROR(reader.EndElement(element.name));
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<PlyData> ReadPlyData(std::string_view bytes, const Source& src,
                                    int64_t max_elements) {
  MESHSEG_ASSIGN_OR_RETURN(const PlyHeader header, ParsePlyHeader(bytes, src));
  ValueReader reader(bytes, header, src);
  int64_t declared_bytes = 0;
  bool vertex_seen = false;
  bool face_seen = false;
  for (const PlyElement& element : header.elements) {
    if (element.name == "face" && !vertex_seen) {
      return BadInput(src, "element face comes before element vertex");
    }
    // Indices refer to THE vertex list: a second one (or a second face
    // list) leaves the file ambiguous, so it is refused, not merged.
    if ((element.name == "vertex" && vertex_seen) || (element.name == "face" && face_seen)) {
      return BadInput(src, absl::StrCat("element ", element.name, " declared twice"));
    }
    vertex_seen |= element.name == "vertex";
    face_seen |= element.name == "face";
    const int64_t min_bytes = MinElementBytes(element, reader.ascii());
    MESHSEG_RETURN_IF_ERROR(CheckDeclaredCount(
        src, absl::StrCat("\"", element.name, "\" elements"), element.count, min_bytes,
        static_cast<int64_t>(bytes.size() - header.body_offset) - declared_bytes, max_elements));
    declared_bytes += element.count * min_bytes;
  }
  if (!vertex_seen) return BadInput(src, "no element vertex");
  PlyData data;
  for (const PlyElement& element : header.elements) {
    MESHSEG_RETURN_IF_ERROR(ReadElement(element, reader, &data));
  }
  return data;
}

}  // namespace meshseg::mesh_internal
