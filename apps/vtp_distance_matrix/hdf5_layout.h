// vtp_distance_matrix: the HDF5 layout of the output file.
//
//   /sources                     int64 (rows)              source vertex of each row (file order)
//   dense:
//   /distances                   float64|float32 (rows, vertices), +inf where unreachable
//   sparse (--max-distance R), the arrays of scipy.sparse.csr_matrix((data, indices, indptr), shape):
//   /distances/data              float64|float32 (nnz)     the distances <= R, row by row
//   /distances/indices           int64 (nnz)               their vertices, ascending in each row
//   /distances/indptr            int64 (rows + 1)          row i is data[indptr[i]:indptr[i+1]]
//   /distances@shape             int64 (2)                 (rows, vertices)
//   polar patches (--max-distance R --polar): /distances as above holds rho, and
//   /angles/data                 float64|float32 (nnz)     theta in [0, 2 pi) of each entry of /distances
//   /angles/indices, /angles/indptr  hard links to /distances/indices and /distances/indptr (one dataset each)
//   /angles@shape                int64 (2)                 (rows, vertices)
//   root attributes: signature (the run's parameters, see main), method, lambda, max_distance,
//   mesh_vertices, format ("dense" or "csr").
//
// Every dataset written row by row (/distances, data, indices) is contiguous and allocated when it
// is created, without fill values (the space is reserved, nothing is written): its place in the file
// is then fixed, and rows are written there with plain writes (POSIX or MPI-IO) after the HDF5 file
// was closed. So the HDF5 metadata is complete and on disk before the first row is written, and a
// row write never touches it: a file killed at any moment is a valid HDF5 file with some rows missing.
// Object modification times are not recorded, so that two runs with the same arguments give the
// same bytes.

#ifndef VTP_DISTANCE_MATRIX_HDF5_LAYOUT_H
#define VTP_DISTANCE_MATRIX_HDF5_LAYOUT_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vtp_matrix {

struct File_description
{
  std::vector<std::int64_t> sources;
  std::int64_t columns = 0;            // vertices of the mesh file
  bool float32 = false;
  bool polar = false;                  // sparse: also /angles
  std::string signature;
  std::vector<std::pair<std::string, std::string> > text_attributes;
  std::vector<std::pair<std::string, double> > number_attributes;
  std::vector<std::pair<std::string, std::int64_t> > integer_attributes;
};

// Creates (truncates) `path` with the dense layout; returns the file offset of /distances.
std::uint64_t create_dense_file(const std::string& path, const File_description& d);

struct Sparse_offsets
{
  std::uint64_t data = 0, indices = 0;  // meaningless when there are no entries
  std::uint64_t angles = 0;             // /angles/data (polar)
};
// Creates (truncates) `path` with the sparse layout for the given row pointers (rows + 1 values).
Sparse_offsets create_sparse_file(const std::string& path, const File_description& d,
                                  const std::vector<std::int64_t>& indptr);

// The root attribute "signature" of `path`; false if `path` is not an HDF5 file or has none.
bool read_signature(const std::string& path, std::string& signature);

// The file offset of /distances in the dense file `path`, after checking that its signature, shape
// and value type are those of `d`; false if not.
bool dense_data_offset(const std::string& path, const File_description& d, std::uint64_t& offset);

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_HDF5_LAYOUT_H
