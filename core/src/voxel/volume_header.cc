#include "voxel/volume_header.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"

namespace meshseg::voxel_internal {
namespace {

std::string FileNameOf(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

std::string Clip(std::string_view s) { return std::string(s.substr(0, 64)); }

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view Strip(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// Numbers of `value`, separated by spaces, commas or parentheses.
std::optional<std::vector<double>> Numbers(std::string_view value) {
  std::vector<double> out;
  for (absl::string_view t : absl::StrSplit(absl::string_view(value.data(), value.size()),
                                            absl::ByAnyChar(" \t,()"), absl::SkipEmpty())) {
    double v;
    if (!absl::SimpleAtod(t, &v)) return std::nullopt;
    out.push_back(v);
  }
  return out;
}

struct Fields {
  std::optional<std::array<int64_t, 3>> dims;
  std::optional<VoxelType> type;
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();
  std::optional<std::array<Eigen::Vector3d, 3>> directions;
  // NRRD's space directions carry the spacing; MetaImage's TransformMatrix
  // holds direction cosines and ElementSpacing the spacing.
  bool directions_carry_spacing = true;
};

absl::Status ParseDims(std::string_view name, std::string_view key, std::string_view value,
                       Fields* f) {
  std::array<int64_t, 3> dims;
  std::vector<absl::string_view> parts =
      absl::StrSplit(absl::string_view(value.data(), value.size()), ' ', absl::SkipWhitespace());
  if (parts.size() != 3) {
    return BadVolume(name,
                     absl::StrCat(std::string(key), " \"", Clip(value), "\" must give 3 sizes"));
  }
  for (int a = 0; a < 3; ++a) {
    if (!absl::SimpleAtoi(parts[a], &dims[a]) || dims[a] <= 0) {
      return BadVolume(name, absl::StrCat(std::string(key), " \"", Clip(value), "\": size ", a,
                                          " must be a positive integer"));
    }
  }
  f->dims = dims;
  return absl::OkStatus();
}

// See CheckAxisLength (volume_header.h).
const double kMinAxisLength = std::sqrt(std::numeric_limits<double>::min());
const double kMaxAxisLength =
    std::sqrt(std::numeric_limits<double>::max()) / double(int64_t{1} << 33);

absl::Status ParseSpacing(std::string_view name, std::string_view key, std::string_view value,
                          Fields* f) {
  const std::optional<std::vector<double>> v = Numbers(value);
  if (!v || v->size() != 3) {
    return BadVolume(name,
                     absl::StrCat(std::string(key), " \"", Clip(value), "\" must give 3 numbers"));
  }
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite((*v)[a]) || (*v)[a] <= 0.0) {
      return BadVolume(name, absl::StrCat(std::string(key), " \"", Clip(value), "\": spacing ", a,
                                          " must be positive and finite"));
    }
    if (absl::Status s = CheckAxisLength(name, absl::StrCat(std::string(key), " ", a), (*v)[a]);
        !s.ok()) {
      return s;
    }
    f->spacing[a] = (*v)[a];
  }
  return absl::OkStatus();
}

absl::StatusOr<Eigen::Vector3d> ParseVector(std::string_view name, std::string_view key,
                                            std::string_view value) {
  const std::optional<std::vector<double>> v = Numbers(value);
  if (!v || v->size() != 3 || !std::isfinite((*v)[0]) || !std::isfinite((*v)[1]) ||
      !std::isfinite((*v)[2])) {
    return BadVolume(
        name, absl::StrCat(std::string(key), " \"", Clip(value), "\" must give 3 finite numbers"));
  }
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

// Three axis vectors (NRRD "space directions", MetaImage "TransformMatrix").
absl::Status ParseDirections(std::string_view name, std::string_view key, std::string_view value,
                             Fields* f) {
  const std::optional<std::vector<double>> v = Numbers(value);
  if (!v || v->size() != 9) {
    return BadVolume(
        name, absl::StrCat(std::string(key), " \"", Clip(value), "\" must give 3 vectors of 3"));
  }
  std::array<Eigen::Vector3d, 3> d;
  for (int a = 0; a < 3; ++a) {
    d[a] = Eigen::Vector3d((*v)[3 * a], (*v)[3 * a + 1], (*v)[3 * a + 2]);
    if (!d[a].allFinite() || d[a].norm() == 0.0) {
      return BadVolume(name, absl::StrCat(std::string(key), " \"", Clip(value), "\": axis ", a,
                                          " must be a finite non-zero vector"));
    }
    // MetaImage's directions are normalised (ElementSpacing gives the length).
    if (f->directions_carry_spacing) {
      if (absl::Status s =
              CheckAxisLength(name, absl::StrCat(std::string(key), " axis ", a), d[a].norm());
          !s.ok()) {
        return s;
      }
    }
  }
  f->directions = d;
  return absl::OkStatus();
}

std::optional<VoxelType> NrrdType(std::string value) {
  value = Lower(value);
  for (const char* s : {"uchar", "unsigned char", "uint8", "uint8_t"}) {
    if (value == s) return VoxelType::kUint8;
  }
  for (const char* s :
       {"short", "short int", "signed short", "signed short int", "int16", "int16_t"}) {
    if (value == s) return VoxelType::kInt16;
  }
  for (const char* s : {"ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t"}) {
    if (value == s) return VoxelType::kUint16;
  }
  if (value == "float") return VoxelType::kFloat32;
  return std::nullopt;
}

std::optional<VoxelType> MetaType(std::string_view value) {
  if (value == "MET_UCHAR") return VoxelType::kUint8;
  if (value == "MET_SHORT") return VoxelType::kInt16;
  if (value == "MET_USHORT") return VoxelType::kUint16;
  if (value == "MET_FLOAT") return VoxelType::kFloat32;
  return std::nullopt;
}

// The geometry from the parsed fields; `origin` already set.
absl::Status Finish(std::string_view name, const Fields& f, VolumeInfo* info) {
  if (!f.dims) return BadVolume(name, "header gives no sizes");
  if (!f.type) return BadVolume(name, "header gives no sample type");
  info->geometry.dims = *f.dims;
  info->type = *f.type;
  for (int a = 0; a < 3; ++a) {
    if (!f.directions) {
      info->geometry.axes[a] = f.spacing[a] * Eigen::Vector3d::Unit(a);
    } else if (f.directions_carry_spacing) {
      info->geometry.axes[a] = (*f.directions)[a];
    } else {
      info->geometry.axes[a] = f.spacing[a] * (*f.directions)[a].normalized();
    }
  }
  return absl::OkStatus();
}

std::string DataPathBeside(const std::string& header_path, std::string_view file) {
  const std::filesystem::path p(file);
  if (p.is_absolute()) return p.string();
  return (std::filesystem::path(header_path).parent_path() / p).string();
}

}  // namespace

absl::Status BadVolume(std::string_view name, std::string_view problem) {
  return absl::InvalidArgumentError(
      absl::StrCat("read_volume: \"", std::string(name), "\": ", std::string(problem)));
}

absl::StatusOr<VolumeInfo> ParseNrrdHeader(std::string_view text, const std::string& path) {
  VolumeInfo info;
  info.name = FileNameOf(path);
  info.format = FileFormat::kNrrd;
  info.data_path = path;
  const std::string_view name = info.name;
  if (!text.starts_with("NRRD000")) return BadVolume(name, "no NRRD000x magic on the first line");
  Fields f;
  bool ended = false;
  size_t at = text.find('\n');
  int line_no = 1;
  while (at != std::string_view::npos && at + 1 <= text.size()) {
    const size_t start = at + 1;
    const size_t end = text.find('\n', start);
    if (end == std::string_view::npos) break;
    ++line_no;
    std::string_view line = text.substr(start, end - start);
    if (line.ends_with('\r')) line.remove_suffix(1);
    at = end;
    if (line.empty()) {
      ended = true;
      info.data_offset = static_cast<int64_t>(end + 1);
      break;
    }
    if (line.starts_with('#') || line.find(":=") != std::string_view::npos) continue;
    const size_t colon = line.find(": ");
    if (colon == std::string_view::npos) {
      return BadVolume(name, absl::StrCat("header line ", line_no, " \"", Clip(line),
                                          "\" is not \"field: value\""));
    }
    const std::string key = Lower(line.substr(0, colon));
    const std::string_view value = Strip(line.substr(colon + 2));
    absl::Status s;
    if (key == "type") {
      f.type = NrrdType(std::string(value));
      if (!f.type) {
        return BadVolume(name, absl::StrCat("unsupported type \"", Clip(value),
                                            "\" (uint8, uint16, int16, float)"));
      }
    } else if (key == "dimension") {
      if (value != "3")
        return BadVolume(name, absl::StrCat("dimension ", Clip(value), " is not 3"));
    } else if (key == "sizes") {
      s = ParseDims(name, key, value, &f);
    } else if (key == "spacings") {
      s = ParseSpacing(name, key, value, &f);
    } else if (key == "space directions") {
      s = ParseDirections(name, key, value, &f);
    } else if (key == "space origin") {
      absl::StatusOr<Eigen::Vector3d> o = ParseVector(name, key, value);
      if (!o.ok()) return o.status();
      info.geometry.origin = *o;
    } else if (key == "encoding") {
      const std::string e = Lower(value);
      if (e == "gzip" || e == "gz") {
        info.gzip = true;
      } else if (e != "raw") {
        return BadVolume(name, absl::StrCat("unknown encoding \"", Clip(value), "\" (raw, gzip)"));
      }
    } else if (key == "endian") {
      info.big_endian = value == "big";
    } else if (key == "data file" || key == "datafile") {
      if (value.starts_with("LIST") || value.find('%') != std::string_view::npos) {
        return BadVolume(name, "data file lists are not supported (one data file)");
      }
      info.data_path = DataPathBeside(path, value);
      info.data_offset = 0;
    } else if (key == "byte skip" || key == "byteskip" || key == "line skip" || key == "lineskip") {
      if (value != "0")
        return BadVolume(name,
                         absl::StrCat(std::string(key), " ", Clip(value), " is not supported"));
    }
    if (!s.ok()) return s;
  }
  if (!ended && info.data_path == path) {
    return BadVolume(name, "header has no blank line before the data");
  }
  if (info.data_path != path) info.data_offset = 0;
  if (absl::Status s = Finish(name, f, &info); !s.ok()) return s;
  return info;
}

absl::StatusOr<VolumeInfo> ParseMetaImageHeader(std::string_view text, const std::string& path) {
  VolumeInfo info;
  info.name = FileNameOf(path);
  info.format = Lower(path).ends_with(".mhd") ? FileFormat::kMhd : FileFormat::kMha;
  const std::string_view name = info.name;
  Fields f;
  f.directions_carry_spacing = false;
  bool ended = false;
  size_t start = 0;
  int line_no = 0;
  while (start < text.size()) {
    const size_t end = text.find('\n', start);
    if (end == std::string_view::npos) break;
    ++line_no;
    std::string_view line = Strip(text.substr(start, end - start));
    start = end + 1;
    if (line.empty()) continue;
    const size_t eq = line.find('=');
    if (eq == std::string_view::npos) {
      return BadVolume(name, absl::StrCat("header line ", line_no, " \"", Clip(line),
                                          "\" is not \"Key = Value\""));
    }
    const std::string_view key = Strip(line.substr(0, eq));
    const std::string_view value = Strip(line.substr(eq + 1));
    absl::Status s;
    if (key == "NDims") {
      if (value != "3") return BadVolume(name, absl::StrCat("NDims ", Clip(value), " is not 3"));
    } else if (key == "DimSize") {
      s = ParseDims(name, key, value, &f);
    } else if (key == "ElementSpacing" || key == "ElementSize") {
      s = ParseSpacing(name, key, value, &f);
    } else if (key == "Offset" || key == "Position" || key == "Origin") {
      absl::StatusOr<Eigen::Vector3d> o = ParseVector(name, key, value);
      if (!o.ok()) return o.status();
      info.geometry.origin = *o;
    } else if (key == "TransformMatrix" || key == "Rotation" || key == "Orientation") {
      s = ParseDirections(name, key, value, &f);
    } else if (key == "ElementType") {
      f.type = MetaType(value);
      if (!f.type) {
        return BadVolume(name, absl::StrCat("unsupported ElementType \"", Clip(value),
                                            "\" (MET_UCHAR, MET_USHORT, MET_SHORT, MET_FLOAT)"));
      }
    } else if (key == "ElementByteOrderMSB" || key == "BinaryDataByteOrderMSB") {
      info.big_endian = Lower(value) == "true";
    } else if (key == "CompressedData") {
      if (Lower(value) != "false") {
        return BadVolume(name, absl::StrCat("unknown encoding: CompressedData = ", Clip(value),
                                            " is not supported (uncompressed data only)"));
      }
    } else if (key == "ElementNumberOfChannels") {
      if (value != "1") {
        return BadVolume(name, absl::StrCat("ElementNumberOfChannels ", Clip(value), " is not 1"));
      }
    } else if (key == "HeaderSize") {
      if (value != "0")
        return BadVolume(name, absl::StrCat("HeaderSize ", Clip(value), " is not supported"));
    } else if (key == "ElementDataFile") {
      if (value == "LOCAL") {
        info.data_path = path;
        info.data_offset = static_cast<int64_t>(start);
      } else if (value.starts_with("LIST") || value.find('%') != std::string_view::npos) {
        return BadVolume(name, "data file lists are not supported (one data file)");
      } else {
        info.data_path = DataPathBeside(path, value);
        info.data_offset = 0;
      }
      ended = true;
      break;
    }
    if (!s.ok()) return s;
  }
  if (!ended) return BadVolume(name, "header has no ElementDataFile line");
  if (absl::Status s = Finish(name, f, &info); !s.ok()) return s;
  return info;
}

absl::Status CheckAxisLength(std::string_view name, std::string_view what, double length) {
  if (length >= kMinAxisLength && length <= kMaxAxisLength) return absl::OkStatus();
  return BadVolume(name, absl::StrCat(std::string(what), " is ", length, ", outside [",
                                      kMinAxisLength, ", ", kMaxAxisLength,
                                      "]: its square underflows or the squared extent overflows"));
}

absl::Status CheckDims(const VolumeInfo& info, const VolumeReadOptions& options) {
  const auto& d = info.geometry.dims;
  for (int a = 0; a < 3; ++a) {
    if (d[a] <= 0)
      return BadVolume(info.name, absl::StrCat("size ", a, " is ", d[a], ", not positive"));
  }
  const double voxels = static_cast<double>(d[0]) * d[1] * d[2];
  if (voxels > static_cast<double>(options.max_voxels)) {
    return BadVolume(info.name,
                     absl::StrCat("sizes ", d[0], " x ", d[1], " x ", d[2], " = ", voxels,
                                  " voxels, over the limit of ", options.max_voxels));
  }
  if (d[0] * d[1] > options.max_slice_voxels) {
    return BadVolume(info.name,
                     absl::StrCat("a slice of ", d[0], " x ", d[1], " voxels is over the limit of ",
                                  options.max_slice_voxels));
  }
  if (d[0] < 2 || d[1] < 2 || d[2] < 2) {
    return BadVolume(info.name, absl::StrCat("sizes ", d[0], " x ", d[1], " x ", d[2],
                                             " hold no cube of 8 samples"));
  }
  return absl::OkStatus();
}

}  // namespace meshseg::voxel_internal
