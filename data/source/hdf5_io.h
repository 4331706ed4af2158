#pragma once
// Thin helpers over the HDF5 C API for ActuationDatabase: owned identifiers,
// groups, scalar attributes and (rows, cols) datasets. Reading problems are
// InputErrors naming the database file; writing problems runtime_errors.
#include <softchain/data/actuation_database.h>

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace softchain::data::hdf5
{
  // Owns one HDF5 identifier and closes it with the matching H5?close.
  class Handle
  {
  public:
    Handle(hid_t id, herr_t (*close)(hid_t));
    Handle(Handle &&other);
    Handle(const Handle &)            = delete;
    Handle &operator=(const Handle &) = delete;
    ~Handle();
    operator hid_t() const { return id_; }
    bool valid() const { return id_ >= 0; }

  private:
    hid_t id_;
    herr_t (*close_)(hid_t);
  };

  // HDF5 prints its own error stack by default; SoftChain reports instead.
  void silence_errors();

  // Throws InputError "database 'PATH': WHAT" unless ok.
  void require(bool ok, const std::string &path, const std::string &what);
  // Throws runtime_error "database 'PATH': cannot write WHAT" if status < 0.
  void require_written(herr_t status, const std::string &path, const std::string &what);

  Handle open_file(const std::string &path, unsigned flags);
  Handle create_group(hid_t parent, const std::string &name, const std::string &path);
  Handle open_group(hid_t parent, const std::string &name, const std::string &path);
  // Names of the links in a group, sorted.
  std::vector<std::string> group_members(hid_t group);

  void write_attribute(hid_t object, const char *name, const std::string &value,
                       const std::string &path);
  void write_attribute(hid_t object, const char *name, double value, const std::string &path);
  void write_attribute(hid_t object, const char *name, int value, const std::string &path);
  // Fixed-length and variable-length (e.g. h5py's) strings.
  std::string read_string_attribute(hid_t object, const char *name, const std::string &path);
  double      read_double_attribute(hid_t object, const char *name, const std::string &path);
  int         read_int_attribute(hid_t object, const char *name, const std::string &path);

  // (rows, 3) float64.
  void write_points(hid_t group, const char *name, const std::vector<Point3> &points,
                    const std::string &path);
  std::vector<Point3> read_points(hid_t group, const std::string &name, const std::string &path);
  // (rows, cols) int64, or (rows) when cols == 0.
  void write_indices(hid_t group, const char *name, const std::int64_t *values, std::size_t rows,
                     std::size_t cols, const std::string &path);
  // Reads rank 1 (cols == 0) or rank 2 with `cols` columns (cols < 0: any,
  // set to the number found); values row by row.
  std::vector<std::int64_t> read_indices(hid_t group, const std::string &name, int &cols,
                                         const std::string &path);
} // namespace softchain::data::hdf5
