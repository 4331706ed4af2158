#pragma once
// ActuationDatabase: the paper's data exchange layer (Sec. II, III-A). One
// database per finger design holding the reference mesh and, per actuation
// sample S = (p, force points, forces), the deformed node positions x.
//
// Layout (documented in data/README.md): the database file PATH
// (e.g. out/database.h5) and, beside it, the sample directory PATH.samples/
// with one HDF5 file per sample.
//   PATH
//   /design               attributes: name, design_hash, element_type,
//                         code_version, parameters (the design's .prm text)
//   /mesh/X               (N,3) float64 reference node positions
//   /mesh/cavity_triangles(F,3) int64 node indices, each triangle oriented so
//                         that (x1-x0)x(x2-x0) points out of the body, i.e.
//                         into the cavity
//   /mesh/tip_nodes       (T)   int64 nodes on the tip face
//   /mesh/base_nodes      (B)   int64 nodes on the clamped base face
//   /mesh/cells           (C,k) int64 corner nodes of each element, k = 4
//                         (tetrahedron) or 8 (hexahedron, deal.II's
//                         lexicographic vertex order: x fastest, then y, z)
//   PATH.samples/<id>.h5  root attributes: design_hash, pressure, role,
//                         status, reason, load_factor_reached,
//                         newton_iterations, load_steps, wall_time
//                         datasets: force_points (m,3), forces (m,3),
//                         tip_motion (2,3), only if the tip is moved: the
//                         translation [m] and rotation vector [rad] of the
//                         tip face (Actuation::tip_motion), with the root
//                         attribute tip_contact = "point" for a point
//                         contact (absent: the face is held),
//                         force_points_deformed (m,3), x (N,3),
//                         base_wrench (2,3): the force and the moment the
//                         finger exerts on its base (about the base face's
//                         centroid); absent in older databases (read as NaN)
//                         only in contact samples: the root attribute
//                         contact_law (the contact constants' canonical text)
//                         and a group obstacles/<name> per obstacle with the
//                         attributes shape, order (its place in the sample's
//                         list), radius, friction and the (1,3) datasets
//                         position, direction, half_sizes, rotation (absent
//                         in older databases: zero), motion (ObstacleRecord) and wrench (2,3): the force and the
//                         moment about the origin the obstacle receives
//   PATH.plan             the sample ids the design's .prm asks for now, one
//                         per line (SamplePlan): the last completed sweep's;
//                         the samples it does not list stay stored, as a
//                         cache, but readers do not see them (sample_ids)
//   PATH.lock             empty; a writer holds an advisory lock on it
// The database file is written once (atomically) when the database is
// created; each sample file is written to a temporary, fsync'ed and renamed
// into place. So storing a sample costs the same however many are stored, a
// crash (even SIGKILL or power loss) leaves every stored sample intact, and
// a second writer is refused with an InputError while one has it open.
// Databases of earlier versions, with their samples inside the database
// file as /samples/<id>/ (same attributes and datasets), open as before;
// samples stored into them go to the sample directory, whose files take
// precedence over /samples for the same id.
//
// Test hook: if the environment variable SOFTCHAIN_TEST_KILL_IN_STORE is k,
// store_sample raises SIGKILL when it stores a sample into a database that
// holds k samples (so, storing samples 0, 1, ... in order, in the middle of
// writing sample k), after the sample's datasets are written to the
// temporary file and before it is closed and renamed: a deterministic crash
// inside a store for the crash tests (tests/data, tests/reduction). Never
// set it otherwise.
#include <softchain/data/obstacle_record.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace softchain::data
{
  using Point3 = std::array<double, 3>;

  struct DesignRecord
  {
    std::string name;
    std::string design_hash;  // hash of everything that changes the solution
    std::string element_type; // "Q1", "Q2", "P1", "P2"
    std::string code_version;
    std::string parameters;   // the design's .prm text, for provenance
  };

  struct MeshRecord
  {
    std::vector<Point3>                      X;
    std::vector<std::array<std::int64_t, 3>> cavity_triangles;
    std::vector<std::int64_t>                tip_nodes;
    std::vector<std::int64_t>                base_nodes;
    int                       nodes_per_cell = 4; // 4 or 8
    std::vector<std::int64_t> cells;              // C * nodes_per_cell
  };

  struct PointForce
  {
    Point3 point; // reference position, inside the body
    Point3 force; // dead load, world axes
  };

  // A motion prescribed to the tip (the paper's validation, Sec. IV-B),
  // relative to the equilibrium at the same pressure without it, world axes.
  // Face held (the default): the tip face moves rigidly, turned by the
  // rotation vector `rotation` (axis times angle) about its centre and moved
  // by `translation`. Point contact: only the mean of the tip face's nodes
  // moves by `translation` (a chopstick's contact); the face is free to turn
  // and deform, and `rotation` is zero.
  struct TipMotion
  {
    Point3 translation{}; // m
    Point3 rotation{};    // rad
    bool   point_contact = false;
  };

  struct Actuation
  {
    double                  pressure = 0.0; // Pa
    std::vector<PointForce> point_forces;
    // What the sample is for: "pressure" (k_phi), "lateral" (k_theta),
    // "torsion" (k_psi), "bending" (k_phi of the joints the pressure does not
    // load), "chord" (the links' compliance), "skin" (the sections'
    // compliance under a force on the palm), "validation" (never used for
    // extraction),
    // "protocol inflation" and "protocol" (the prescribed-motion protocol:
    // its inflated state and its tip motions), "contact" (a finger pressed
    // on obstacles: blocked force, grasp; never used for extraction), or a
    // user's name.
    std::string role;
    std::optional<TipMotion> tip_motion; // none: the tip is free
    // Volume control: the cavity inflated to this multiple of its volume at
    // rest; `pressure` is then an outcome, the pressure that holds it there
    // (none: pressure control, `pressure` is prescribed).
    std::optional<double> cavity_volume_ratio;
    // A contact sample: the rigid obstacles the finger may touch (role
    // "contact"), each at its final pose, and the canonical text of the
    // contact constants it was solved with (surfaces, penalty factor,
    // penetration tolerance); none: a free finger.
    std::vector<ObstacleRecord> obstacles;
    std::string                 contact_law;

    // Canonical text of the actuation (pressure or, under volume control,
    // the volume ratio instead; points, forces, tip motion, obstacles and
    // contact law; not role).
    std::string canonical_text() const;
  };

  // What became of a sample's solve; stored as the text of status_name().
  enum class SampleStatus
  {
    converged,
    failed,     // the solver did not reach the sample's load (reason: why)
    limit_point // pressure control stopped at a physical limit point (dp/dV -> 0),
                // or the sample lies beyond one on its load path
  };

  // "converged", "failed" or "limit point".
  std::string status_name(SampleStatus status);

  struct SampleRecord
  {
    std::string id; // sample_id(design_hash, actuation)
    Actuation   actuation;
    SampleStatus status = SampleStatus::converged;
    // Why it failed; for a converged sample, how it was reached where that
    // matters (a limit point of the forces passed by displacement control),
    // else empty.
    std::string  reason;
    double      load_factor_reached = 1.0;
    int         newton_iterations   = 0;
    int         load_steps          = 0;
    double      wall_time           = 0.0; // s
    std::vector<Point3> x; // deformed nodes (last converged state if failed)
    std::vector<Point3> force_points_deformed;
    // The force [N] and moment [N m] the finger exerts on its clamped base,
    // about the base face's centroid, world axes (NaN in databases written
    // before it was stored).
    Point3 base_force  = {{NAN, NAN, NAN}};
    Point3 base_moment = {{NAN, NAN, NAN}};
    // What each obstacle of the actuation receives, in its order.
    std::vector<ObstacleWrench> obstacle_wrenches;
    // A force sample that passed a limit point of its forces on the way (a
    // sideways buckling, followed by displacement control): the forces'
    // magnitude at the limit [N], the root sum of squares over the points.
    // NaN for a sample without one: it lies on the branch from the start.
    double force_limit = NAN;

    bool converged() const { return status == SampleStatus::converged; }
  };

  // Key of a sample: hash of the design hash and the actuation's canonical text.
  std::string sample_id(const std::string &design_hash, const Actuation &actuation);

  class WriterLock;

  class ActuationDatabase
  {
  public:
    // Opens `path` for reading. Throws InputError naming the file if it is
    // missing or not a SoftChain database.
    static ActuationDatabase open(const std::string &path);

    // Opens `path` for a sweep, as its one writer (an InputError naming the
    // file if another writer has it open). If it holds the same design_hash
    // it is reused (its samples are a cache); otherwise the existing
    // database (file and sample directory) is moved aside to
    // `path.<old hash>.stale` (and `path.<old hash>.stale.samples`) and a new
    // database with `design` and `mesh` is written.
    static ActuationDatabase open_or_create(const std::string  &path,
                                            const DesignRecord &design,
                                            const MeshRecord   &mesh);

    const std::string  &path() const { return path_; }
    const DesignRecord &design() const { return design_; }
    const MeshRecord   &mesh() const { return mesh_; }

    // Whether sample `id` is stored (the sweep's cache).
    bool has_sample(const std::string &id) const;
    // The samples the design's .prm asks for now, sorted: the stored ones
    // of the plan (PATH.plan) the last completed sweep wrote, or every
    // stored sample if there is no plan. A sample the .prm no longer lists
    // stays stored, as a cache, but leaves the readers' view.
    std::vector<std::string> sample_ids() const;
    // Every stored sample, sorted.
    const std::vector<std::string> &stored_sample_ids() const { return sample_ids_; }
    SampleRecord             read_sample(const std::string &id) const;

    // Writes (or replaces) one sample atomically (its own file: write a
    // temporary, fsync, rename). A database from open() becomes the writer
    // here (an InputError naming the file if another writer has it open).
    void store_sample(const SampleRecord &sample);
    // Makes `ids` the plan (a sweep, when it completes: every sample its
    // .prm lists, stored or failed). Written atomically, and only if it
    // changes. A database from open() becomes the writer here.
    void set_plan(const std::vector<std::string> &ids);

  private:
    // Takes the writer's lock and removes temporaries of interrupted stores.
    void become_writer(std::shared_ptr<WriterLock> lock);

    std::string              path_;
    DesignRecord             design_;
    MeshRecord               mesh_;
    std::vector<std::string> sample_ids_; // stored
    std::optional<std::vector<std::string>> plan_; // sorted; none: no plan file
    std::shared_ptr<WriterLock> writer_lock_; // shared by copies; none if only read
  };
} // namespace softchain::data
