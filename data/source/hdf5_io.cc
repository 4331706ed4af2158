// HDF5 helpers of ActuationDatabase (hdf5_io.h).
#include "hdf5_io.h"

#include <softchain/data/input_error.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace softchain::data::hdf5
{
  namespace
  {
    static_assert(sizeof(Point3) == 3 * sizeof(double), "Point3 must be three packed doubles");

    Handle open_attribute(hid_t object, const char *name, const std::string &path)
    {
      require(H5Aexists(object, name) > 0, path, std::string("missing attribute '") + name + "'");
      return Handle(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
    }

    template <typename T>
    void write_scalar(hid_t object, const char *name, const T &value, hid_t type,
                      const std::string &path)
    {
      Handle space(H5Screate(H5S_SCALAR), H5Sclose);
      Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
      require_written(attribute.valid() ? H5Awrite(attribute, type, &value) : -1, path,
                      std::string("attribute ") + name);
    }

    template <typename T>
    T read_scalar(hid_t object, const char *name, hid_t type, const std::string &path)
    {
      Handle attribute = open_attribute(object, name, path);
      T      value{};
      require(H5Aread(attribute, type, &value) >= 0, path,
              std::string("attribute '") + name + "' is not a number");
      return value;
    }

    void write_array(hid_t group, const char *name, const void *data, std::size_t rows,
                     std::size_t cols, hid_t type, const std::string &path)
    {
      const hsize_t dims[2] = {rows, cols};
      Handle        space(H5Screate_simple(cols ? 2 : 1, dims, nullptr), H5Sclose);
      Handle        dataset(
        H5Dcreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
      require_written(dataset.valid() ? 0 : -1, path, std::string("dataset ") + name);
      if (rows * std::max<std::size_t>(cols, 1) > 0) // HDF5 has nothing to write otherwise
        require_written(H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), path,
                        std::string("dataset ") + name);
    }

    template <typename T>
    std::vector<T> read_array(hid_t group, const std::string &name, hid_t type, int &cols,
                              const std::string &path)
    {
      require(H5Lexists(group, name.c_str(), H5P_DEFAULT) > 0, path,
              "missing dataset '" + name + "'");
      Handle    dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
      Handle    space(H5Dget_space(dataset), H5Sclose);
      const int wanted_rank = cols == 0 ? 1 : 2;
      require(H5Sget_simple_extent_ndims(space) == wanted_rank, path,
              "dataset '" + name + "' must have rank " + std::to_string(wanted_rank));
      hsize_t dims[2] = {0, 0};
      H5Sget_simple_extent_dims(space, dims, nullptr);
      require(cols <= 0 || dims[1] == static_cast<hsize_t>(cols), path,
              "dataset '" + name + "' must have " + std::to_string(cols) + " columns");
      cols = static_cast<int>(dims[1]);
      std::vector<T> values(dims[0] * std::max<hsize_t>(dims[1], 1));
      require(values.empty() ||
                H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0,
              path, "cannot read dataset '" + name + "'");
      return values;
    }
  } // namespace

  Handle::Handle(hid_t id, herr_t (*close)(hid_t))
    : id_(id)
    , close_(close)
  {}

  Handle::Handle(Handle &&other)
    : id_(other.id_)
    , close_(other.close_)
  {
    other.id_ = -1;
  }

  Handle::~Handle()
  {
    if (id_ >= 0)
      close_(id_);
  }

  void silence_errors()
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }

  void require(bool ok, const std::string &path, const std::string &what)
  {
    if (!ok)
      throw InputError("database '" + path + "': " + what);
  }

  void require_written(herr_t status, const std::string &path, const std::string &what)
  {
    if (status < 0)
      throw std::runtime_error("database '" + path + "': cannot write " + what);
  }

  Handle open_file(const std::string &path, unsigned flags)
  {
    require(std::filesystem::exists(path), path, "file does not exist");
    require(H5Fis_hdf5(path.c_str()) > 0, path, "not an HDF5 file");
    Handle file(H5Fopen(path.c_str(), flags, H5P_DEFAULT), H5Fclose);
    require(file.valid(), path, "cannot open the HDF5 file");
    return file;
  }

  Handle create_group(hid_t parent, const std::string &name, const std::string &path)
  {
    Handle group(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 H5Gclose);
    require_written(group.valid() ? 0 : -1, path, "group " + name);
    return group;
  }

  Handle open_group(hid_t parent, const std::string &name, const std::string &path)
  {
    require(H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0, path, "missing group '" + name + "'");
    return Handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose);
  }

  std::vector<std::string> group_members(hid_t group)
  {
    H5G_info_t info;
    H5Gget_info(group, &info);
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i)
      {
        const ssize_t length =
          H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
        std::vector<char> name(length + 1, '\0');
        H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                           H5P_DEFAULT);
        names.emplace_back(name.data());
      }
    std::sort(names.begin(), names.end());
    return names;
  }

  void write_attribute(hid_t object, const char *name, const std::string &value,
                       const std::string &path)
  {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type, value.size() + 1);
    H5Tset_strpad(type, H5T_STR_NULLTERM);
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    require_written(attribute.valid() ? H5Awrite(attribute, type, value.c_str()) : -1, path,
                    std::string("attribute ") + name);
  }

  void write_attribute(hid_t object, const char *name, double value, const std::string &path)
  {
    write_scalar(object, name, value, H5T_NATIVE_DOUBLE, path);
  }

  void write_attribute(hid_t object, const char *name, int value, const std::string &path)
  {
    write_scalar(object, name, value, H5T_NATIVE_INT, path);
  }

  std::string read_string_attribute(hid_t object, const char *name, const std::string &path)
  {
    Handle attribute = open_attribute(object, name, path);
    Handle file_type(H5Aget_type(attribute), H5Tclose);
    require(H5Tget_class(file_type) == H5T_STRING, path,
            std::string("attribute '") + name + "' is not a string");
    Handle memory_type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (H5Tis_variable_str(file_type) > 0)
      {
        H5Tset_size(memory_type, H5T_VARIABLE);
        char *text = nullptr;
        require(H5Aread(attribute, memory_type, &text) >= 0, path,
                std::string("cannot read attribute '") + name + "'");
        const std::string value = text ? text : "";
        H5free_memory(text);
        return value;
      }
    const std::size_t size = H5Tget_size(file_type);
    H5Tset_size(memory_type, size);
    std::vector<char> text(size + 1, '\0');
    require(H5Aread(attribute, memory_type, text.data()) >= 0, path,
            std::string("cannot read attribute '") + name + "'");
    return std::string(text.data());
  }

  double read_double_attribute(hid_t object, const char *name, const std::string &path)
  {
    return read_scalar<double>(object, name, H5T_NATIVE_DOUBLE, path);
  }

  int read_int_attribute(hid_t object, const char *name, const std::string &path)
  {
    return read_scalar<int>(object, name, H5T_NATIVE_INT, path);
  }

  void write_points(hid_t group, const char *name, const std::vector<Point3> &points,
                    const std::string &path)
  {
    write_array(group, name, points.data(), points.size(), 3, H5T_NATIVE_DOUBLE, path);
  }

  std::vector<Point3> read_points(hid_t group, const std::string &name, const std::string &path)
  {
    int                 cols   = 3;
    std::vector<double> values = read_array<double>(group, name, H5T_NATIVE_DOUBLE, cols, path);
    std::vector<Point3> points(values.size() / 3);
    for (std::size_t i = 0; i < points.size(); ++i)
      points[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
    return points;
  }

  void write_indices(hid_t group, const char *name, const std::int64_t *values, std::size_t rows,
                     std::size_t cols, const std::string &path)
  {
    write_array(group, name, values, rows, cols, H5T_NATIVE_INT64, path);
  }

  std::vector<std::int64_t> read_indices(hid_t group, const std::string &name, int &cols,
                                         const std::string &path)
  {
    return read_array<std::int64_t>(group, name, H5T_NATIVE_INT64, cols, path);
  }
} // namespace softchain::data::hdf5
