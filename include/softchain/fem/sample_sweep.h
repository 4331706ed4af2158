#pragma once
// SampleSweep: `softchain sweep FILE.prm` -- the paper's database generation
// (Sec. III-A). Meshes the design, and for every sample of subsection Samples
// (SampleSet) that <output dir>/database.h5 does not hold yet (the cache, keyed
// by design hash and actuation) solves the quasi-static problem, continuing
// from the nearest converged sample of its chain, and stores the sample
// atomically (converged or failed). The pressure-only samples come first:
// a chain of forces at pressure p then starts from the converged one at the
// highest pressure not above p instead of from rest; the chains that cannot
// start from an inflation are solved beside the inflations. Samples are
// spread over MPI sample groups (whole chains per group, so the results do
// not depend on the rank count), which solve on their own; world rank 0
// writes each record to the database as it arrives and prints one progress
// line per sample.
// Then, if subsection Protocol asks for it, the samples of the paper's
// validation experiment (TipMotionProtocol): the inflation to a tip angle,
// found by trial samples, and the tip motions from that state, listed in
// <output>/protocol_samples.csv (sample, motion, amount, unit; the first row
// the inflated state, motion "inflation", amount the tip angle in deg) for
// the chain tier; the file is removed when the .prm has no protocol.
#include <softchain/data/prm_file.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/fem/finger_mesh.h>
#include <softchain/fem/parameters.h>
#include <softchain/fem/sample_set.h>
#include <softchain/fem/tip_motion_protocol.h>

#include <Eigen/Core>

#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace softchain::fem
{
  class SampleGroup;
  class SweepProgress;

  class SampleSweep
  {
  public:
    // Reads the .prm and builds the mesh (collective on MPI_COMM_WORLD).
    explicit SampleSweep(const data::PrmFile &prm_file);

    struct Summary
    {
      std::size_t              n_samples = 0, n_cached = 0, n_solved = 0;
      std::vector<std::string> failed; // "label (id): reason", on every rank
      std::string              database;

      // Prints the counts to `out` and the failed samples to `err`; returns
      // the exit status (0, or 2 if some sample failed).
      int report(std::ostream &out, std::ostream &err) const;
    };
    // Throws data::InputError (bad input, force point outside the body)
    // before any solve.
    Summary run();

  private:
    Parameters    prm;
    data::PrmFile prm_file;
    FingerMesh    mesh;
    std::string   hash;
    SampleSet         set; // the listed samples, then the protocol's
    TipMotionProtocol protocol;
    std::string       database_path;
    data::MeshRecord                tip_mesh; // rank 0, database_mesh()
    std::optional<data::TipPoseFit> tip_fit;

    using Records = std::map<std::size_t, data::SampleRecord>; // by sample index

    void read_cached(const std::vector<std::size_t> &indices, Records &known) const;
    // Rank 0: makes the ids of `known` the database's plan.
    void write_plan(const Records &known) const;
    void solve_missing(const std::vector<std::size_t> &indices, Records &known, Summary &summary,
                       bool inflations_first = false);
    void start_chains_from_inflations(const std::vector<std::size_t> &indices, Records &known);
    static bool                may_start_inflated(const data::Actuation &first);
    std::optional<std::size_t> inflated_start(const std::vector<std::size_t> &chain,
                                              const std::vector<std::size_t> &indices,
                                              const Records                  &known) const;
    // The chains of the chord and skin samples, by role, pressure and points.
    using MeasuredChains = std::map<std::string, std::size_t>;
    void solve_measured_samples(Records &known, Summary &summary);
    std::optional<std::vector<data::Point3>>
         measured_directions(const SampleSet::MeasuredForceRequest &request,
                             const std::optional<std::size_t> &inflation, const Records &known);
    void chain_measured_sample(std::size_t index, const SampleSet::MeasuredForceRequest &request,
                               const std::optional<std::size_t> &inflation, Records &known,
                               MeasuredChains &chains);
    data::Point3 chord_direction(const data::SampleRecord *record);
    data::Point3 palm_normal(const data::SampleRecord *record, const data::Point3 &X);
    data::Point3 palm_tangent(const data::SampleRecord *record, const data::Point3 &X);
    Eigen::Matrix3d palm_deformation(const data::SampleRecord &record, const data::Point3 &X);
    std::string                         run_protocol(Records &known, Summary &summary);
    std::pair<std::size_t, std::string> inflate_to_tip_angle(Records &known, Summary &summary);
    // The database's mesh (and the tip's fit to it), read once; rank 0.
    const data::MeshRecord             &database_mesh();
    data::TipPose                       tip_pose(const data::SampleRecord &record);
    std::string                         protocol_listing() const;
    void share_record(std::size_t i, Records &known) const;
    void                     solve_pending(const std::vector<std::size_t> &pending, Records &known,
                                           SweepProgress &progress, unsigned int n_groups) const;
    void solve_share(SampleGroup &group, const std::vector<std::size_t> &mine, std::size_t n_records,
                     std::optional<data::ActuationDatabase> &database, Records &known,
                     SweepProgress &progress) const;
    static constexpr int              record_tag = 1; // a solved record on its way to rank 0
    std::optional<data::SampleRecord> receive_record(bool wait) const;
    // Each group's samples of `pending`: whole chains, in chain order.
    std::vector<std::vector<std::size_t>> shares(const std::vector<std::size_t> &pending,
                                                 unsigned int n_groups) const;
    std::vector<const data::SampleRecord *> known_before(std::size_t sample, const Records &known) const;
    const data::SampleRecord *start_of(std::size_t sample, const Records &known) const;
    const data::SampleRecord *anchor_of(std::size_t sample, const Records &known) const;
    const data::SampleRecord *stopped_before(std::size_t sample, const Records &known) const;
    data::SampleRecord        beyond_limit_point(std::size_t sample, const data::SampleRecord &stop) const;
    void                      write_series() const;
  };
} // namespace softchain::fem
