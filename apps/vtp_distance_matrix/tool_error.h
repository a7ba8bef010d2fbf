// vtp_distance_matrix: the one error type of the tool (that of the support layer's command-line helper).
//
// Every error the tool reports (bad arguments, unreadable mesh, bad source list, output that cannot
// be written, a resume against another run, a full disk) is a Tool_error: main() prints its message as
// one line "vtp_distance_matrix: error: ..." and exits with code 2.

#ifndef VTP_DISTANCE_MATRIX_TOOL_ERROR_H
#define VTP_DISTANCE_MATRIX_TOOL_ERROR_H

#include <vtp_support/command_line.h>

namespace vtp_matrix {

constexpr const char* program_name = "vtp_distance_matrix";

using vtp_support::Tool_error;

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_TOOL_ERROR_H
