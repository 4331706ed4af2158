// ActuationDatabase on the HDF5 C API (layout in actuation_database.h and
// data/README.md). The database file holds the design and the
// mesh and is written once, atomically; every sample is a file of its own in
// the sample directory, written to a temporary, fsync'ed and renamed into
// place (atomic_file.h). So storing a sample costs the same however many are
// stored, and a crash leaves every stored sample intact. One writer at a
// time (WriterLock).
#include <softchain/data/actuation_database.h>
#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>

#include "atomic_file.h"
#include "hdf5_io.h"
#include "sample_directory.h"
#include "sample_plan.h"
#include "writer_lock.h"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <stdexcept>

namespace softchain::data
{
  namespace
  {
    namespace fs = std::filesystem;
    using namespace hdf5;

    static_assert(sizeof(std::array<std::int64_t, 3>) == 3 * sizeof(std::int64_t),
                  "triangles must be three packed int64");

    void write_design(hid_t file, const DesignRecord &design, const std::string &path)
    {
      Handle group = create_group(file, "design", path);
      write_attribute(group, "name", design.name, path);
      write_attribute(group, "design_hash", design.design_hash, path);
      write_attribute(group, "element_type", design.element_type, path);
      write_attribute(group, "code_version", design.code_version, path);
      write_attribute(group, "parameters", design.parameters, path);
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
      write_indices(group, "cavity_triangles",
                    mesh.cavity_triangles.empty() ? nullptr : mesh.cavity_triangles[0].data(),
                    mesh.cavity_triangles.size(), 3, path);
      write_indices(group, "tip_nodes", mesh.tip_nodes.data(), mesh.tip_nodes.size(), 0, path);
      write_indices(group, "base_nodes", mesh.base_nodes.data(), mesh.base_nodes.size(), 0, path);
      write_indices(group, "cells", mesh.cells.data(), mesh.cells.size() / mesh.nodes_per_cell,
                    mesh.nodes_per_cell, path);
    }

    // Reads /mesh/NAME (rank 1 if cols == 0) and checks its node indices.
    std::vector<std::int64_t> read_node_indices(hid_t group, const std::string &name, int &cols,
                                                std::size_t n_nodes, const std::string &path)
    {
      auto indices = read_indices(group, name, cols, path);
      for (const auto i : indices)
        require(i >= 0 && static_cast<std::size_t>(i) < n_nodes, path,
                "dataset '/mesh/" + name + "' holds node index " + std::to_string(i) +
                  " outside 0.." + std::to_string(n_nodes) + "-1");
      return indices;
    }

    MeshRecord read_mesh(hid_t file, const std::string &path)
    {
      Handle     group = open_group(file, "mesh", path);
      MeshRecord mesh;
      mesh.X             = read_points(group, "X", path);
      const std::size_t n = mesh.X.size();
      int        cols      = 3;
      const auto triangles = read_node_indices(group, "cavity_triangles", cols, n, path);
      for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
        mesh.cavity_triangles.push_back({triangles[t], triangles[t + 1], triangles[t + 2]});
      cols            = 0;
      mesh.tip_nodes  = read_node_indices(group, "tip_nodes", cols, n, path);
      mesh.base_nodes = read_node_indices(group, "base_nodes", cols, n, path);
      cols            = -1;
      mesh.cells      = read_node_indices(group, "cells", cols, n, path);
      require(cols == 4 || cols == 8, path, "dataset '/mesh/cells' must have 4 or 8 columns");
      mesh.nodes_per_cell = cols;
      return mesh;
    }

    // A contact sample's obstacles, each a group obstacles/<name> holding
    // its description and the wrench it receives.
    void write_obstacles(hid_t group, const SampleRecord &sample, const std::string &path)
    {
      const auto &obstacles = sample.actuation.obstacles;
      if (obstacles.empty())
        return;
      write_attribute(group, "contact_law", sample.actuation.contact_law, path);
      Handle all = create_group(group, "obstacles", path);
      for (std::size_t k = 0; k < obstacles.size(); ++k)
        {
          const ObstacleRecord &o = obstacles[k];
          Handle                g = create_group(all, o.name, path);
          write_attribute(g, "shape", o.shape, path);
          write_attribute(g, "order", static_cast<int>(k), path);
          write_attribute(g, "radius", o.radius, path);
          write_attribute(g, "friction", o.friction, path);
          write_points(g, "position", {o.position}, path);
          write_points(g, "direction", {o.direction}, path);
          write_points(g, "half_sizes", {o.half_sizes}, path);
          write_points(g, "rotation", {o.rotation}, path);
          write_points(g, "motion", {o.motion}, path);
          if (o.motion_rotation != Point3{})
            {
              write_points(g, "motion_rotation", {o.motion_rotation}, path);
              write_points(g, "motion_pivot", {o.motion_pivot}, path);
            }
          if (!o.vertices.empty())
            {
              write_points(g, "vertices", o.vertices, path);
              write_attribute(g, "file", o.file, path);
            }
          const ObstacleWrench w = k < sample.obstacle_wrenches.size() ?
                                     sample.obstacle_wrenches[k] :
                                     ObstacleWrench{{{NAN, NAN, NAN}}, {{NAN, NAN, NAN}}};
          write_points(g, "wrench", {w.force, w.moment}, path);
        }
    }

    // One (1,3) dataset of an obstacle's group.
    Point3 read_point(hid_t group, const std::string &name, const std::string &where,
                      const std::string &path)
    {
      const auto rows = read_points(group, name, path);
      require(rows.size() == 1, path, where + ": '" + name + "' needs 1 row");
      return rows.front();
    }

    // The obstacles of a contact sample, in their order, and their wrenches.
    void read_obstacles(hid_t group, const std::string &id, Actuation &actuation,
                        std::vector<ObstacleWrench> &wrenches, const std::string &path)
    {
      if (H5Lexists(group, "obstacles", H5P_DEFAULT) <= 0)
        return;
      actuation.contact_law = read_string_attribute(group, "contact_law", path);
      Handle     all   = open_group(group, "obstacles", path);
      const auto names = group_members(all);
      actuation.obstacles.resize(names.size());
      wrenches.resize(names.size());
      for (const auto &name : names)
        {
          Handle            g     = open_group(all, name, path);
          const std::string where = "sample '" + id + "', obstacle '" + name + "'";
          const int         k     = read_int_attribute(g, "order", path);
          require(k >= 0 && static_cast<std::size_t>(k) < names.size() &&
                    actuation.obstacles[k].name.empty(),
                  path, where + ": 'order' is not a free place in 0.." + std::to_string(names.size() - 1));
          ObstacleRecord &o = actuation.obstacles[k];
          o.name            = name;
          o.shape           = read_string_attribute(g, "shape", path);
          o.radius          = read_double_attribute(g, "radius", path);
          o.friction        = read_double_attribute(g, "friction", path);
          o.position        = read_point(g, "position", where, path);
          o.direction       = read_point(g, "direction", where, path);
          o.half_sizes      = read_point(g, "half_sizes", where, path);
          if (H5Lexists(g, "rotation", H5P_DEFAULT) > 0) // absent in older databases: zero
            o.rotation = read_point(g, "rotation", where, path);
          o.motion = read_point(g, "motion", where, path);
          if (H5Lexists(g, "motion_rotation", H5P_DEFAULT) > 0) // absent where the obstacle does not turn
            {
              o.motion_rotation = read_point(g, "motion_rotation", where, path);
              o.motion_pivot    = read_point(g, "motion_pivot", where, path);
            }
          if (H5Lexists(g, "vertices", H5P_DEFAULT) > 0) // stl only
            {
              o.vertices = read_points(g, "vertices", path);
              o.file     = read_string_attribute(g, "file", path);
              require(o.vertices.size() % 3 == 0, path, where + ": 'vertices' needs three rows per triangle");
            }
          const auto wrench = read_points(g, "wrench", path);
          require(wrench.size() == 2, path, where + ": 'wrench' needs 2 rows");
          wrenches[k] = {wrench[0], wrench[1]};
        }
    }

    // The sample's attributes and datasets in `group` (a sample file's root).
    void write_sample(hid_t group, const SampleRecord &sample, const std::string &path)
    {
      write_attribute(group, "pressure", sample.actuation.pressure, path);
      write_attribute(group, "role", sample.actuation.role, path);
      write_attribute(group, "status", status_name(sample.status), path);
      write_attribute(group, "reason", sample.reason, path);
      write_attribute(group, "load_factor_reached", sample.load_factor_reached, path);
      write_attribute(group, "newton_iterations", sample.newton_iterations, path);
      write_attribute(group, "load_steps", sample.load_steps, path);
      write_attribute(group, "wall_time", sample.wall_time, path);
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
      write_points(group, "base_wrench", {sample.base_force, sample.base_moment}, path);
      if (const auto &motion = sample.actuation.tip_motion)
        {
          write_points(group, "tip_motion", {motion->translation, motion->rotation}, path);
          if (motion->point_contact)
            write_attribute(group, "tip_contact", std::string("point"), path);
        }
      if (const auto &ratio = sample.actuation.cavity_volume_ratio)
        write_attribute(group, "cavity_volume_ratio", *ratio, path);
      if (std::isfinite(sample.force_limit))
        write_attribute(group, "force_limit", sample.force_limit, path);
      write_obstacles(group, sample, path);
    }

    Actuation read_actuation(hid_t group, const std::string &id, const std::string &path)
    {
      Actuation actuation;
      actuation.pressure = read_double_attribute(group, "pressure", path);
      actuation.role     = read_string_attribute(group, "role", path);
      const auto points  = read_points(group, "force_points", path);
      const auto forces  = read_points(group, "forces", path);
      require(points.size() == forces.size(), path,
              "sample '" + id + "': force_points and forces differ in length");
      for (std::size_t k = 0; k < points.size(); ++k)
        actuation.point_forces.push_back({points[k], forces[k]});
      if (H5Lexists(group, "tip_motion", H5P_DEFAULT) > 0)
        {
          const auto motion = read_points(group, "tip_motion", path);
          require(motion.size() == 2, path, "sample '" + id + "': tip_motion needs 2 rows");
          const bool point = H5Aexists(group, "tip_contact") > 0 &&
                             read_string_attribute(group, "tip_contact", path) == "point";
          actuation.tip_motion = TipMotion{motion[0], motion[1], point};
        }
      if (H5Aexists(group, "cavity_volume_ratio") > 0)
        actuation.cavity_volume_ratio = read_double_attribute(group, "cavity_volume_ratio", path);
      return actuation;
    }

    SampleStatus parse_status(const std::string &text, const std::string &id,
                              const std::string &path)
    {
      for (const auto status :
           {SampleStatus::converged, SampleStatus::failed, SampleStatus::limit_point})
        if (text == status_name(status))
          return status;
      throw InputError("database '" + path + "': sample '" + id + "' has the unknown status '" + text + "'");
    }

    SampleRecord read_sample_group(hid_t group, const std::string &id, std::size_t n_nodes,
                                   const std::string &path)
    {
      SampleRecord sample;
      sample.id                    = id;
      sample.actuation             = read_actuation(group, id, path);
      sample.status                = parse_status(read_string_attribute(group, "status", path),
                                                  id, path);
      sample.reason                = read_string_attribute(group, "reason", path);
      sample.load_factor_reached   = read_double_attribute(group, "load_factor_reached", path);
      sample.newton_iterations     = read_int_attribute(group, "newton_iterations", path);
      sample.load_steps            = read_int_attribute(group, "load_steps", path);
      sample.wall_time             = read_double_attribute(group, "wall_time", path);
      sample.force_points_deformed = read_points(group, "force_points_deformed", path);
      sample.x                     = read_points(group, "x", path);
      read_obstacles(group, id, sample.actuation, sample.obstacle_wrenches, path);
      if (H5Aexists(group, "force_limit") > 0)
        sample.force_limit = read_double_attribute(group, "force_limit", path);
      if (H5Lexists(group, "base_wrench", H5P_DEFAULT) > 0)
        {
          const auto wrench = read_points(group, "base_wrench", path);
          require(wrench.size() == 2, path, "sample '" + id + "': base_wrench needs 2 rows");
          sample.base_force  = wrench[0];
          sample.base_moment = wrench[1];
        }
      require(sample.x.size() == n_nodes, path,
              "sample '" + id + "': x has " + std::to_string(sample.x.size()) +
                " rows, the mesh has " + std::to_string(n_nodes) + " nodes");
      return sample;
    }

    // Test hook (actuation_database.h): SOFTCHAIN_TEST_KILL_IN_STORE=k kills
    // the process while it stores a sample into a database of k samples.
    void kill_if_requested(std::size_t samples_in_database)
    {
      const char *k = std::getenv("SOFTCHAIN_TEST_KILL_IN_STORE");
      if (k != nullptr && std::to_string(samples_in_database) == k)
        std::raise(SIGKILL);
    }

    void write_sample_file(const std::string &file, const SampleRecord &sample,
                           const std::string &design_hash, std::size_t samples_in_database,
                           const std::string &path)
    {
      Handle root(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      require_written(root.valid() ? 0 : -1, path, "file " + file);
      write_attribute(root, "design_hash", design_hash, path);
      write_sample(root, sample, path);
      kill_if_requested(samples_in_database); // datasets written, file not yet closed
    }

    // A sample file of another design would be a silent wrong answer.
    SampleRecord read_sample_file(const std::string &file, const std::string &id,
                                  const std::string &design_hash, std::size_t n_nodes)
    {
      Handle root = open_file(file, H5F_ACC_RDONLY);
      require(read_string_attribute(root, "design_hash", file) == design_hash, file,
              "sample file of another design (design_hash is not " + design_hash + ")");
      return read_sample_group(root, id, n_nodes, file);
    }

    // The sorted union of two sorted id lists.
    std::vector<std::string> merged(const std::vector<std::string> &a,
                                    const std::vector<std::string> &b)
    {
      std::vector<std::string> ids;
      std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(ids));
      return ids;
    }

    // Moves the database at `path` and its samples to `path.<hash>.stale`:
    // the sample directory first, so that a crash in between leaves the
    // database file without samples, which the next sweep moves aside too.
    void move_aside(const std::string &path, const std::string &hash)
    {
      const std::string stale = path + "." + hash + ".stale";
      const SampleDirectory samples(path);
      if (samples.exists())
        samples.move_to(stale);
      SamplePlan(path).move_to(stale);
      fs::rename(path, stale);
      sync_directory(fs::absolute(path).parent_path().string());
    }
  } // namespace

  std::string Actuation::canonical_text() const
  {
    // Under volume control the pressure is solved for: the ratio, not the
    // pressure, is what the sample asks for.
    std::string text = cavity_volume_ratio ? "cavity volume ratio " + canonical(*cavity_volume_ratio) + "\n" :
                                             "pressure " + canonical(pressure) + "\n";
    for (const auto &f : point_forces)
      {
        text += "force";
        for (const double v : f.point)
          text += " " + canonical(v);
        for (const double v : f.force)
          text += " " + canonical(v);
        text += "\n";
      }
    if (tip_motion) // absent: the text (and so the id) of a free-tip sample as before
      {
        text += tip_motion->point_contact ? "tip point motion" : "tip motion";
        for (const auto &v : {tip_motion->translation, tip_motion->rotation})
          for (const double c : v)
            text += " " + canonical(c);
        text += "\n";
      }
    if (!obstacles.empty()) // absent: the text (and so the id) of a free finger as before
      {
        text += "contact " + contact_law + "\n";
        for (const auto &o : obstacles)
          text += o.canonical_text();
      }
    return text;
  }

  std::string ObstacleRecord::canonical_text() const
  {
    std::string text = "obstacle " + name + " " + shape;
    for (const auto &v : {position, direction, half_sizes, motion})
      for (const double c : v)
        text += " " + canonical(c);
    text += " " + canonical(radius) + " " + canonical(friction);
    const auto words = [](const Point3 &v) {
      return " " + canonical(v[0]) + " " + canonical(v[1]) + " " + canonical(v[2]);
    };
    if (rotation != Point3{})
      text += " rotation" + words(rotation);
    if (motion_rotation != Point3{})
      text += " turn" + words(motion_rotation) + " about" + words(motion_pivot);
    if (!vertices.empty())
      {
        std::string mesh;
        for (const auto &v : vertices)
          mesh += words(v);
        text += " triangles " + content_hash(mesh);
      }
    return text + "\n";
  }

  std::string sample_id(const std::string &design_hash, const Actuation &actuation)
  {
    return content_hash("design " + design_hash + "\n" + actuation.canonical_text());
  }

  std::string status_name(const SampleStatus status)
  {
    switch (status)
      {
        case SampleStatus::converged:
          return "converged";
        case SampleStatus::failed:
          return "failed";
        case SampleStatus::limit_point:
          return "limit point";
      }
    return "";
  }

  ActuationDatabase ActuationDatabase::open(const std::string &path)
  {
    silence_errors();
    Handle file = open_file(path, H5F_ACC_RDONLY);
    require(H5Lexists(file, "design", H5P_DEFAULT) > 0, path,
            "not a SoftChain database (no /design group)");
    ActuationDatabase database;
    database.path_       = path;
    database.design_     = read_design(file, path);
    database.mesh_       = read_mesh(file, path);
    // Databases written by earlier versions hold their samples in /samples.
    std::vector<std::string> in_file;
    if (H5Lexists(file, "samples", H5P_DEFAULT) > 0)
      in_file = group_members(open_group(file, "samples", path));
    database.sample_ids_ = merged(in_file, SampleDirectory(path).ids());
    database.plan_       = SamplePlan(path).read();
    return database;
  }

  ActuationDatabase ActuationDatabase::open_or_create(const std::string  &path,
                                                      const DesignRecord &design,
                                                      const MeshRecord   &mesh)
  {
    auto lock = std::make_shared<WriterLock>(path);
    remove_temporaries_of(path);
    if (fs::exists(path))
      {
        ActuationDatabase existing = open(path);
        if (existing.design_.design_hash == design.design_hash)
          {
            existing.become_writer(lock);
            return existing;
          }
        move_aside(path, existing.design_.design_hash);
      }
    const SampleDirectory samples(path);
    require(samples.ids().empty(), path,
            "the file is missing but its sample directory '" + samples.path() +
              "' holds samples; restore the file or move the directory away");
    samples.create(); // before the file, so that a database file has its directory
    silence_errors();
    write_atomically(path, [&](const std::string &temporary) {
      Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      require_written(file.valid() ? 0 : -1, path, "file " + temporary);
      write_design(file, design, path);
      write_mesh(file, mesh, path);
    });
    ActuationDatabase created = open(path);
    created.become_writer(lock);
    return created;
  }

  void ActuationDatabase::become_writer(std::shared_ptr<WriterLock> lock)
  {
    writer_lock_ = std::move(lock);
    const SampleDirectory samples(path_);
    samples.create(); // a database of an earlier version has none yet
    samples.remove_leftovers();
    SamplePlan(path_).remove_leftovers();
  }

  bool ActuationDatabase::has_sample(const std::string &id) const
  {
    return std::binary_search(sample_ids_.begin(), sample_ids_.end(), id);
  }

  std::vector<std::string> ActuationDatabase::sample_ids() const
  {
    if (!plan_)
      return sample_ids_;
    std::vector<std::string> planned;
    std::set_intersection(plan_->begin(), plan_->end(), sample_ids_.begin(), sample_ids_.end(),
                          std::back_inserter(planned));
    return planned;
  }

  void ActuationDatabase::set_plan(const std::vector<std::string> &ids)
  {
    if (!writer_lock_)
      become_writer(std::make_shared<WriterLock>(path_));
    plan_ = SamplePlan(path_).write(ids);
  }

  SampleRecord ActuationDatabase::read_sample(const std::string &id) const
  {
    require(has_sample(id), path_, "no sample '" + id + "'");
    silence_errors();
    const std::string sample_file = SampleDirectory(path_).file_of(id);
    if (fs::exists(sample_file))
      return read_sample_file(sample_file, id, design_.design_hash, mesh_.X.size());
    Handle file    = open_file(path_, H5F_ACC_RDONLY);
    Handle samples = open_group(file, "samples", path_);
    Handle group   = open_group(samples, id, path_);
    return read_sample_group(group, id, mesh_.X.size(), path_);
  }

  void ActuationDatabase::store_sample(const SampleRecord &sample)
  {
    if (sample.id.empty() || sample.id.find('/') != std::string::npos || sample.id[0] == '.')
      throw std::invalid_argument("store_sample: invalid sample id '" + sample.id + "'");
    if (sample.x.size() != mesh_.X.size())
      throw std::invalid_argument("store_sample: sample '" + sample.id + "' has " +
                                  std::to_string(sample.x.size()) + " positions for " +
                                  std::to_string(mesh_.X.size()) + " nodes");
    if (!writer_lock_)
      become_writer(std::make_shared<WriterLock>(path_));
    silence_errors();
    const std::string sample_file = SampleDirectory(path_).file_of(sample.id);
    write_atomically(sample_file, [&](const std::string &temporary) {
      write_sample_file(temporary, sample, design_.design_hash, sample_ids_.size(), path_);
    });
    if (!has_sample(sample.id))
      sample_ids_.insert(std::lower_bound(sample_ids_.begin(), sample_ids_.end(), sample.id),
                         sample.id);
  }
} // namespace softchain::data
