// File: label_color.h
// -----------------------------------------------------------------------------
// The colour of each region label in everything meshseg draws: the coloured
// PLY files (WriteColoredPly, WriteColoredPointPly) and the HTML report.
#ifndef MESHSEG_LABEL_COLOR_H_
#define MESHSEG_LABEL_COLOR_H_

#include <array>
#include <cstdint>

namespace meshseg {

// Returns the RGB colour of region label `label`: hues spaced by the golden
// angle, three brightness levels; grey for -1.
std::array<uint8_t, 3> LabelColor(int label);

}  // namespace meshseg

#endif  // MESHSEG_LABEL_COLOR_H_
