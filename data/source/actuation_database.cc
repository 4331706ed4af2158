// ActuationDatabase on the HDF5 C API (layout in actuation_database.h and
// reduction/README.md). Every change is written to a copy of the file in the
// same directory, which is closed, fsync'ed and renamed over the original, so
// the database on disk is always either the old or the new complete file.
#include <softchain/data/actuation_database.h>
#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>

#include <hdf5.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace softchain::data
{
  namespace
  {
    namespace fs = std::filesystem;

    static_assert(sizeof(Point3) == 3 * sizeof(double), "Point3 must be three packed doubles");
    static_assert(sizeof(std::array<std::int64_t, 3>) == 3 * sizeof(std::int64_t),
                  "triangles must be three packed int64");

    // Owns one HDF5 identifier and closes it with the matching H5?close.
    class Handle
    {
    public:
      Handle(hid_t id, herr_t (*close)(hid_t))
        : id_(id), close_(close)
      {}
      Handle(Handle &&other)
        : id_(other.id_), close_(other.close_)
      {
        other.id_ = -1;
      }
      Handle(const Handle &)            = delete;
      Handle &operator=(const Handle &) = delete;
      ~Handle()
      {
        if (id_ >= 0)
          close_(id_);
      }
      operator hid_t() const { return id_; }
      bool valid() const { return id_ >= 0; }

    private:
      hid_t id_;
      herr_t (*close_)(hid_t);
    };

    // HDF5 prints its own error stack by default; SoftChain reports instead.
    void silence_hdf5()
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

    // ---- attributes ------------------------------------------------------
    void write_string_attribute(hid_t object, const char *name, const std::string &value,
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

    template <typename T>
    void write_number_attribute(hid_t object, const char *name, T value, hid_t type,
                                const std::string &path)
    {
      Handle space(H5Screate(H5S_SCALAR), H5Sclose);
      Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
      require_written(attribute.valid() ? H5Awrite(attribute, type, &value) : -1, path,
                      std::string("attribute ") + name);
    }

    Handle open_attribute(hid_t object, const char *name, const std::string &path)
    {
      require(H5Aexists(object, name) > 0, path, std::string("missing attribute '") + name + "'");
      return Handle(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
    }

    // Reads fixed-length and variable-length (e.g. h5py's) string attributes.
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

    template <typename T>
    T read_number_attribute(hid_t object, const char *name, hid_t type, const std::string &path)
    {
      Handle attribute = open_attribute(object, name, path);
      T      value{};
      require(H5Aread(attribute, type, &value) >= 0, path,
              std::string("attribute '") + name + "' is not a number");
      return value;
    }

    // ---- datasets: (rows, cols) arrays, or (rows) when cols == 0 --------
    template <typename T>
    void write_array(hid_t group, const char *name, const T *data, std::size_t rows,
                     std::size_t cols, hid_t type, const std::string &path)
    {
      const hsize_t dims[2] = {rows, cols};
      Handle        space(H5Screate_simple(cols ? 2 : 1, dims, nullptr), H5Sclose);
      Handle        dataset(H5Dcreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT,
                                H5P_DEFAULT),
                     H5Dclose);
      const herr_t  status = !dataset.valid() ? -1 :
                             rows * std::max<std::size_t>(cols, 1) == 0 ?
                                                0 :
                                                H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
      require_written(status, path, std::string("dataset ") + name);
    }

    void write_points(hid_t group, const char *name, const std::vector<Point3> &points,
                      const std::string &path)
    {
      write_array(group, name, points.empty() ? nullptr : points[0].data(), points.size(), 3,
                  H5T_NATIVE_DOUBLE, path);
    }

    // Reads a dataset of rank 1 (cols == 0) or rank 2 with `cols` columns
    // (cols < 0: any); returns the values row by row and sets rows/cols.
    template <typename T>
    std::vector<T> read_array(hid_t group, const std::string &name, hid_t type, int &cols,
                              const std::string &path)
    {
      require(H5Lexists(group, name.c_str(), H5P_DEFAULT) > 0, path,
              "missing dataset '" + name + "'");
      Handle    dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
      Handle    space(H5Dget_space(dataset), H5Sclose);
      const int rank = H5Sget_simple_extent_ndims(space);
      hsize_t   dims[2] = {0, 0};
      const int wanted_rank = cols == 0 ? 1 : 2;
      require(rank == wanted_rank, path,
              "dataset '" + name + "' must have rank " + std::to_string(wanted_rank));
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

    std::vector<Point3> read_points(hid_t group, const std::string &name, const std::string &path)
    {
      int                 cols   = 3;
      std::vector<double> values = read_array<double>(group, name, H5T_NATIVE_DOUBLE, cols, path);
      std::vector<Point3> points(values.size() / 3);
      std::copy(values.begin(), values.end(), points.empty() ? nullptr : points[0].data());
      return points;
    }

    std::vector<std::int64_t> read_indices(hid_t group, const std::string &name, int &cols,
                                           const std::string &path)
    {
      return read_array<std::int64_t>(group, name, H5T_NATIVE_INT64, cols, path);
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
      require(H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0, path,
              "missing group '" + name + "'");
      return Handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose);
    }

    // ---- whole records ---------------------------------------------------
    void write_design(hid_t file, const DesignRecord &design, const std::string &path)
    {
      Handle group = create_group(file, "design", path);
      write_string_attribute(group, "name", design.name, path);
      write_string_attribute(group, "design_hash", design.design_hash, path);
      write_string_attribute(group, "element_type", design.element_type, path);
      write_string_attribute(group, "code_version", design.code_version, path);
      write_string_attribute(group, "parameters", design.parameters, path);
    }

    DesignRecord read_design(hid_t file, const std::string &path)
    {
      Handle       group = open_group(file, "design", path);
      DesignRecord design;
      design.name         = read_string_attribute(group, "name", path);
      design.design_hash  = read_string_attribute(group, "design_hash", path);
      design.element_type = read_string_attribute(group, "element_type", path);
      design.code_version = read_string_attribute(group, "code_version", path);
      design.parameters   = read_string_attribute(group, "parameters", path);
      return design;
    }

    void write_mesh(hid_t file, const MeshRecord &mesh, const std::string &path)
    {
      Handle group = create_group(file, "mesh", path);
      write_points(group, "X", mesh.X, path);
      write_array(group, "cavity_triangles",
                  mesh.cavity_triangles.empty() ? nullptr : mesh.cavity_triangles[0].data(),
                  mesh.cavity_triangles.size(), 3, H5T_NATIVE_INT64, path);
      write_array(group, "tip_nodes", mesh.tip_nodes.data(), mesh.tip_nodes.size(), 0,
                  H5T_NATIVE_INT64, path);
      write_array(group, "base_nodes", mesh.base_nodes.data(), mesh.base_nodes.size(), 0,
                  H5T_NATIVE_INT64, path);
      write_array(group, "cells", mesh.cells.data(), mesh.cells.size() / mesh.nodes_per_cell,
                  mesh.nodes_per_cell, H5T_NATIVE_INT64, path);
    }

    void check_indices(const std::vector<std::int64_t> &indices, std::size_t n_nodes,
                       const std::string &name, const std::string &path)
    {
      for (const auto i : indices)
        require(i >= 0 && static_cast<std::size_t>(i) < n_nodes, path,
                "dataset '/mesh/" + name + "' holds node index " + std::to_string(i) +
                  " outside 0.." + std::to_string(n_nodes - 1));
    }

    MeshRecord read_mesh(hid_t file, const std::string &path)
    {
      Handle     group = open_group(file, "mesh", path);
      MeshRecord mesh;
      mesh.X        = read_points(group, "X", path);
      int  cols     = 3;
      auto triangles = read_indices(group, "cavity_triangles", cols, path);
      check_indices(triangles, mesh.X.size(), "cavity_triangles", path);
      mesh.cavity_triangles.resize(triangles.size() / 3);
      std::copy(triangles.begin(), triangles.end(),
                mesh.cavity_triangles.empty() ? nullptr : mesh.cavity_triangles[0].data());
      cols           = 0;
      mesh.tip_nodes = read_indices(group, "tip_nodes", cols, path);
      mesh.base_nodes = read_indices(group, "base_nodes", cols, path);
      cols            = -1;
      mesh.cells      = read_indices(group, "cells", cols, path);
      require(cols == 4 || cols == 8, path, "dataset '/mesh/cells' must have 4 or 8 columns");
      mesh.nodes_per_cell = cols;
      check_indices(mesh.tip_nodes, mesh.X.size(), "tip_nodes", path);
      check_indices(mesh.base_nodes, mesh.X.size(), "base_nodes", path);
      check_indices(mesh.cells, mesh.X.size(), "cells", path);
      return mesh;
    }

    void write_sample(hid_t samples, const SampleRecord &sample, const std::string &path)
    {
      Handle group = create_group(samples, sample.id, path);
      write_number_attribute(group, "pressure", sample.actuation.pressure, H5T_NATIVE_DOUBLE, path);
      write_string_attribute(group, "role", sample.actuation.role, path);
      write_string_attribute(group, "status", sample.status, path);
      write_string_attribute(group, "reason", sample.reason, path);
      write_number_attribute(group, "load_factor_reached", sample.load_factor_reached,
                             H5T_NATIVE_DOUBLE, path);
      write_number_attribute(group, "newton_iterations", sample.newton_iterations,
                             H5T_NATIVE_INT, path);
      write_number_attribute(group, "load_steps", sample.load_steps, H5T_NATIVE_INT, path);
      write_number_attribute(group, "wall_time", sample.wall_time, H5T_NATIVE_DOUBLE, path);
      std::vector<Point3> points, forces;
      for (const auto &f : sample.actuation.point_forces)
        {
          points.push_back(f.point);
          forces.push_back(f.force);
        }
      write_points(group, "force_points", points, path);
      write_points(group, "forces", forces, path);
      write_points(group, "force_points_deformed", sample.force_points_deformed, path);
      write_points(group, "x", sample.x, path);
    }

    SampleRecord read_sample_group(hid_t group, const std::string &id, std::size_t n_nodes,
                                   const std::string &path)
    {
      SampleRecord sample;
      sample.id                  = id;
      sample.actuation.pressure  = read_number_attribute<double>(group, "pressure", H5T_NATIVE_DOUBLE, path);
      sample.actuation.role      = read_string_attribute(group, "role", path);
      sample.status              = read_string_attribute(group, "status", path);
      sample.reason              = read_string_attribute(group, "reason", path);
      sample.load_factor_reached = read_number_attribute<double>(group, "load_factor_reached", H5T_NATIVE_DOUBLE, path);
      sample.newton_iterations   = read_number_attribute<int>(group, "newton_iterations", H5T_NATIVE_INT, path);
      sample.load_steps          = read_number_attribute<int>(group, "load_steps", H5T_NATIVE_INT, path);
      sample.wall_time           = read_number_attribute<double>(group, "wall_time", H5T_NATIVE_DOUBLE, path);
      const auto points          = read_points(group, "force_points", path);
      const auto forces          = read_points(group, "forces", path);
      require(points.size() == forces.size(), path,
              "sample '" + id + "': force_points and forces differ in length");
      for (std::size_t k = 0; k < points.size(); ++k)
        sample.actuation.point_forces.push_back({points[k], forces[k]});
      sample.force_points_deformed = read_points(group, "force_points_deformed", path);
      sample.x                     = read_points(group, "x", path);
      require(sample.x.size() == n_nodes, path,
              "sample '" + id + "': x has " + std::to_string(sample.x.size()) +
                " rows, the mesh has " + std::to_string(n_nodes) + " nodes");
      return sample;
    }

    std::vector<std::string> group_members(hid_t group)
    {
      H5G_info_t info;
      H5Gget_info(group, &info);
      std::vector<std::string> names;
      for (hsize_t i = 0; i < info.nlinks; ++i)
        {
          const ssize_t     length = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                                    nullptr, 0, H5P_DEFAULT);
          std::vector<char> name(length + 1, '\0');
          H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                             H5P_DEFAULT);
          names.emplace_back(name.data());
        }
      std::sort(names.begin(), names.end());
      return names;
    }

    Handle open_file(const std::string &path, unsigned flags)
    {
      require(fs::exists(path), path, "file does not exist");
      require(H5Fis_hdf5(path.c_str()) > 0, path, "not an HDF5 file");
      Handle file(H5Fopen(path.c_str(), flags, H5P_DEFAULT), H5Fclose);
      require(file.valid(), path, "cannot open the HDF5 file");
      return file;
    }

    // Makes `temporary` durable and puts it in place of `path` atomically.
    void commit(const std::string &temporary, const std::string &path)
    {
      const int fd = ::open(temporary.c_str(), O_RDONLY);
      const bool synced = fd >= 0 && ::fsync(fd) == 0;
      if (fd >= 0)
        ::close(fd);
      if (!synced || std::rename(temporary.c_str(), path.c_str()) != 0)
        throw std::runtime_error("database '" + path + "': cannot sync and rename " + temporary);
      const std::string directory = fs::absolute(path).parent_path().string();
      const int dir_fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY);
      if (dir_fd >= 0)
        {
          ::fsync(dir_fd); // makes the rename itself durable
          ::close(dir_fd);
        }
    }

    std::string temporary_name(const std::string &path)
    {
      return path + ".tmp" + std::to_string(::getpid());
    }

    // Runs `write(temporary)` on a temporary file, then commits it over
    // `path`; the temporary file is removed if anything fails.
    template <typename Writer>
    void write_atomically(const std::string &path, const Writer &write)
    {
      const std::string temporary = temporary_name(path);
      try
        {
          write(temporary);
          commit(temporary, path);
        }
      catch (...)
        {
          fs::remove(temporary);
          throw;
        }
    }
  } // namespace

  std::string Actuation::canonical_text() const
  {
    std::string text = "pressure " + canonical(pressure) + "\n";
    for (const auto &f : point_forces)
      {
        text += "force";
        for (const double v : f.point)
          text += " " + canonical(v);
        for (const double v : f.force)
          text += " " + canonical(v);
        text += "\n";
      }
    return text;
  }

  std::string sample_id(const std::string &design_hash, const Actuation &actuation)
  {
    return content_hash("design " + design_hash + "\n" + actuation.canonical_text());
  }

  ActuationDatabase ActuationDatabase::open(const std::string &path)
  {
    silence_hdf5();
    Handle file = open_file(path, H5F_ACC_RDONLY);
    require(H5Lexists(file, "design", H5P_DEFAULT) > 0, path,
            "not a SoftChain database (no /design group)");
    ActuationDatabase database;
    database.path_   = path;
    database.design_ = read_design(file, path);
    database.mesh_   = read_mesh(file, path);
    Handle samples   = open_group(file, "samples", path);
    database.sample_ids_ = group_members(samples);
    return database;
  }

  ActuationDatabase ActuationDatabase::open_or_create(const std::string  &path,
                                                      const DesignRecord &design,
                                                      const MeshRecord   &mesh)
  {
    if (fs::exists(path))
      {
        ActuationDatabase existing = open(path);
        if (existing.design_.design_hash == design.design_hash)
          return existing;
        fs::rename(path, path + "." + existing.design_.design_hash + ".stale");
      }
    write_atomically(path, [&](const std::string &temporary) {
      Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      require_written(file.valid() ? 0 : -1, path, "file " + temporary);
      write_design(file, design, path);
      write_mesh(file, mesh, path);
      create_group(file, "samples", path);
    });
    return open(path);
  }

  bool ActuationDatabase::has_sample(const std::string &id) const
  {
    return std::binary_search(sample_ids_.begin(), sample_ids_.end(), id);
  }

  std::vector<std::string> ActuationDatabase::sample_ids() const
  {
    return sample_ids_;
  }

  SampleRecord ActuationDatabase::read_sample(const std::string &id) const
  {
    require(has_sample(id), path_, "no sample '" + id + "'");
    silence_hdf5();
    Handle file    = open_file(path_, H5F_ACC_RDONLY);
    Handle samples = open_group(file, "samples", path_);
    Handle group   = open_group(samples, id, path_);
    return read_sample_group(group, id, mesh_.X.size(), path_);
  }

  void ActuationDatabase::store_sample(const SampleRecord &sample)
  {
    if (sample.id.empty() || sample.id.find('/') != std::string::npos || sample.id == ".")
      throw std::invalid_argument("store_sample: invalid sample id '" + sample.id + "'");
    if (sample.x.size() != mesh_.X.size())
      throw std::invalid_argument("store_sample: sample '" + sample.id + "' has " +
                                  std::to_string(sample.x.size()) + " positions for " +
                                  std::to_string(mesh_.X.size()) + " nodes");
    silence_hdf5();
    write_atomically(path_, [&](const std::string &temporary) {
      fs::copy_file(path_, temporary, fs::copy_options::overwrite_existing);
      Handle file    = open_file(temporary, H5F_ACC_RDWR);
      Handle samples = open_group(file, "samples", path_);
      if (H5Lexists(samples, sample.id.c_str(), H5P_DEFAULT) > 0)
        require_written(H5Ldelete(samples, sample.id.c_str(), H5P_DEFAULT), path_,
                        "(replace) sample " + sample.id);
      write_sample(samples, sample, path_);
    });
    if (!has_sample(sample.id))
      sample_ids_.insert(std::lower_bound(sample_ids_.begin(), sample_ids_.end(), sample.id),
                         sample.id);
  }
} // namespace softchain::data
