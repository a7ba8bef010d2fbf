// vtp_distance_matrix: the HDF5 layout of the output file (see hdf5_layout.h).

#include "hdf5_layout.h"
#include "tool_error.h"

#include <hdf5.h>

#include <utility>

namespace vtp_matrix {
namespace {

// An HDF5 identifier closed by the right function at the end of its scope.
class Handle
{
public:
  typedef herr_t (*Closer)(hid_t);
  Handle(hid_t id, Closer closer) : m_id(id), m_closer(closer) {}
  Handle(Handle&& other) noexcept : m_id(other.m_id), m_closer(other.m_closer) { other.m_id = -1; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  ~Handle() { reset(); }
  hid_t get() const { return m_id; }
  bool valid() const { return m_id >= 0; }
  // closes now; false if closing failed (for the file: data not written)
  bool reset()
  {
    bool ok = true;
    if(m_id >= 0)
      ok = m_closer(m_id) >= 0;
    m_id = -1;
    return ok;
  }

private:
  hid_t m_id;
  Closer m_closer;
};

// HDF5 prints its error stack on stderr by default: the tool reports its own one-line errors.
// HDF5's clean-up at exit is turned off (every file is closed explicitly before): after a failed
// H5Fclose (a full disk), HDF5 1.10.8 crashes in that clean-up.
void silence_hdf5()
{
  static bool done = false;
  if(!done)
  {
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    done = true;
  }
}

void check(bool ok, const std::string& path, const std::string& what)
{
  if(!ok)
    throw Tool_error("cannot write the HDF5 file '" + path + "' (" + what + ")");
}

hid_t value_type(bool float32)
{
  return float32 ? H5T_IEEE_F32LE : H5T_IEEE_F64LE;
}

// Dataset creation: contiguous, space reserved at creation, never filled, no modification time.
Handle reserved_dataset_properties()
{
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_layout(dcpl.get(), H5D_CONTIGUOUS);
  H5Pset_alloc_time(dcpl.get(), H5D_ALLOC_TIME_EARLY);
  H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER);
  H5Pset_obj_track_times(dcpl.get(), 0);
  return dcpl;
}

void write_text_attribute(hid_t object, const std::string& name, const std::string& value, const std::string& path)
{
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const char* text = value.c_str();
  check(attribute.valid() && H5Awrite(attribute.get(), type.get(), &text) >= 0, path, "attribute " + name);
}

template <class T>
void write_number_attribute(hid_t object, const std::string& name, const T* values, hsize_t n, hid_t file_type,
                            hid_t memory_type, const std::string& path)
{
  Handle space(n == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose);
  Handle attribute(H5Acreate2(object, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  check(attribute.valid() && H5Awrite(attribute.get(), memory_type, values) >= 0, path, "attribute " + name);
}

// A new file with the root attributes and /sources.
Handle create_file(const std::string& path, const File_description& d)
{
  silence_hdf5();
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  H5Pset_obj_track_times(fcpl.get(), 0);
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), H5Fclose);
  if(!file.valid())
    throw Tool_error("cannot create the HDF5 file '" + path + "'");
  write_text_attribute(file.get(), "signature", d.signature, path);
  for(const auto& a : d.text_attributes)
    write_text_attribute(file.get(), a.first, a.second, path);
  for(const auto& a : d.number_attributes)
    write_number_attribute(file.get(), a.first, &a.second, 1, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, path);
  for(const auto& a : d.integer_attributes)
    write_number_attribute(file.get(), a.first, &a.second, 1, H5T_STD_I64LE, H5T_NATIVE_INT64, path);

  const hsize_t rows = static_cast<hsize_t>(d.sources.size());
  Handle space(H5Screate_simple(1, &rows, nullptr), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_obj_track_times(dcpl.get(), 0);
  Handle sources(H5Dcreate2(file.get(), "sources", H5T_STD_I64LE, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                 H5Dclose);
  check(sources.valid() && H5Dwrite(sources.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.sources.data()) >= 0,
        path, "/sources");
  return file;
}

// A reserved dataset of `n` elements (1-d) or rows x columns (2-d); returns its file offset.
std::uint64_t reserve_dataset(hid_t parent, const std::string& name, int rank, const hsize_t* dims, hid_t type,
                              const std::string& path)
{
  Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  Handle dcpl = reserved_dataset_properties();
  Handle dataset(H5Dcreate2(parent, name.c_str(), type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT), H5Dclose);
  check(dataset.valid(), path, name);
  hsize_t elements = 1;
  for(int i = 0; i < rank; ++i)
    elements *= dims[i];
  if(elements == 0)
    return 0;
  const haddr_t offset = H5Dget_offset(dataset.get());
  check(offset != HADDR_UNDEF, path, "no file offset for " + name);
  return static_cast<std::uint64_t>(offset);
}

void close_file(Handle& file, const std::string& path)
{
  check(file.reset(), path, "closing");
}

} // namespace

std::uint64_t create_dense_file(const std::string& path, const File_description& d)
{
  Handle file = create_file(path, d);
  const hsize_t dims[2] = { static_cast<hsize_t>(d.sources.size()), static_cast<hsize_t>(d.columns) };
  const std::uint64_t offset = reserve_dataset(file.get(), "distances", 2, dims, value_type(d.float32), path);
  close_file(file, path);
  return offset;
}

Sparse_offsets create_sparse_file(const std::string& path, const File_description& d,
                                  const std::vector<std::int64_t>& indptr)
{
  Handle file = create_file(path, d);
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  H5Pset_obj_track_times(gcpl.get(), 0);
  Handle group(H5Gcreate2(file.get(), "distances", H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
  check(group.valid(), path, "/distances");
  const std::int64_t shape[2] = { static_cast<std::int64_t>(d.sources.size()), d.columns };
  write_number_attribute(group.get(), "shape", shape, 2, H5T_STD_I64LE, H5T_NATIVE_INT64, path);

  const hsize_t nnz = static_cast<hsize_t>(indptr.back());
  Sparse_offsets offsets;
  offsets.data = reserve_dataset(group.get(), "data", 1, &nnz, value_type(d.float32), path);
  offsets.indices = reserve_dataset(group.get(), "indices", 1, &nnz, H5T_STD_I64LE, path);
  const hsize_t n = static_cast<hsize_t>(indptr.size());
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_obj_track_times(dcpl.get(), 0);
  Handle pointers(H5Dcreate2(group.get(), "indptr", H5T_STD_I64LE, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                  H5Dclose);
  check(pointers.valid() && H5Dwrite(pointers.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, indptr.data()) >= 0,
        path, "/distances/indptr");
  pointers.reset();
  group.reset();
  if(d.polar)
  {
    Handle angles(H5Gcreate2(file.get(), "angles", H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
    check(angles.valid(), path, "/angles");
    write_number_attribute(angles.get(), "shape", shape, 2, H5T_STD_I64LE, H5T_NATIVE_INT64, path);
    offsets.angles = reserve_dataset(angles.get(), "data", 1, &nnz, value_type(d.float32), path);
    check(H5Lcreate_hard(file.get(), "/distances/indices", angles.get(), "indices", H5P_DEFAULT, H5P_DEFAULT) >= 0
            && H5Lcreate_hard(file.get(), "/distances/indptr", angles.get(), "indptr", H5P_DEFAULT, H5P_DEFAULT) >= 0,
          path, "/angles/indices");
  }
  close_file(file, path);
  return offsets;
}

bool read_signature(const std::string& path, std::string& signature)
{
  silence_hdf5();
  if(H5Fis_hdf5(path.c_str()) <= 0)
    return false;
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if(!file.valid() || H5Aexists(file.get(), "signature") <= 0)
    return false;
  Handle attribute(H5Aopen(file.get(), "signature", H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if(!attribute.valid() || !type.valid() || H5Tget_class(type.get()) != H5T_STRING || !H5Tis_variable_str(type.get()))
    return false;
  Handle memory_type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(memory_type.get(), H5T_VARIABLE);
  H5Tset_cset(memory_type.get(), H5T_CSET_UTF8);
  char* text = nullptr;
  if(H5Aread(attribute.get(), memory_type.get(), &text) < 0 || text == nullptr)
    return false;
  signature = text;
  H5free_memory(text);
  return true;
}

bool dense_data_offset(const std::string& path, const File_description& d, std::uint64_t& offset)
{
  std::string signature;
  if(!read_signature(path, signature) || signature != d.signature)
    return false;
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if(!file.valid() || H5Lexists(file.get(), "distances", H5P_DEFAULT) <= 0)
    return false;
  Handle dataset(H5Dopen2(file.get(), "distances", H5P_DEFAULT), H5Dclose);
  if(!dataset.valid())
    return false;
  Handle space(H5Dget_space(dataset.get()), H5Sclose);
  Handle type(H5Dget_type(dataset.get()), H5Tclose);
  hsize_t dims[2] = { 0, 0 };
  if(!space.valid() || !type.valid() || H5Sget_simple_extent_ndims(space.get()) != 2
     || H5Sget_simple_extent_dims(space.get(), dims, nullptr) != 2
     || dims[0] != static_cast<hsize_t>(d.sources.size()) || dims[1] != static_cast<hsize_t>(d.columns)
     || H5Tequal(type.get(), value_type(d.float32)) <= 0)
    return false;
  Handle dcpl(H5Dget_create_plist(dataset.get()), H5Pclose);
  if(!dcpl.valid() || H5Pget_layout(dcpl.get()) != H5D_CONTIGUOUS)
    return false;
  if(dims[0] * dims[1] == 0)
  {
    offset = 0;
    return true;
  }
  const haddr_t a = H5Dget_offset(dataset.get());
  if(a == HADDR_UNDEF)
    return false;
  offset = static_cast<std::uint64_t>(a);
  return true;
}

} // namespace vtp_matrix
