// vtp_distance_matrix: the --sources argument.

#ifndef VTP_DISTANCE_MATRIX_SOURCE_LIST_H
#define VTP_DISTANCE_MATRIX_SOURCE_LIST_H

#include <cstdint>
#include <string>
#include <vector>

namespace vtp_matrix {

// The source vertices (0-based, file order of the mesh) of `spec`:
//   "all"        0, 1, ..., n-1
//   "A:B"        A, A+1, ..., B-1 (A < B <= n; half-open, as Python's slices)
//   "V,V,..."    the listed indices, in this order (repetitions allowed)
//   otherwise    the name of a text file of indices separated by blanks, commas or new lines,
//                '#' starting a comment to the end of the line.
// A spec made only of digits, commas and colons (and a leading '-') is always read as a list or a
// range, never as a file name. Throws Tool_error on an empty list, an index out of range, a bad item,
// or a file that cannot be read.
std::vector<std::int64_t> parse_sources(const std::string& spec, std::int64_t number_of_vertices);

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_SOURCE_LIST_H
