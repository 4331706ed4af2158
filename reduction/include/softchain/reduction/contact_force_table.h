#pragma once
// ContactForceTable: the database's contact samples (role contact: the
// finger inflated against rigid obstacles, data::ObstacleRecord) as one CSV
// row per sample and obstacle, ordered by obstacle and pressure: what the
// obstacle receives and where the tip went. For a table under the tip the
// rows are the actuator's blocked-force curve F(p); for a cylinder under the
// finger, the grasp force and the finger's pose per pressure.
//   contact/contact_forces.csv: sample, obstacle, shape, pressure, status,
//     force_x, force_y, force_z, force_norm [N],
//     moment_x, moment_y, moment_z [N m, about the origin],
//     tip_x, tip_y, tip_z [m, centroid of the tip face],
//     tip_angle_deg (the tip face's rotation from rest)
// The reduction leaves contact samples out of the extraction: their joint
// torques would need the contact forces, which act all along the finger.
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>

#include <string>
#include <vector>

namespace softchain::reduction
{
  class ContactForceTable
  {
  public:
    // The contact samples of `samples` (any status) on `mesh`; `source`
    // names the database in messages.
    ContactForceTable(const std::vector<data::SampleRecord> &samples, const data::MeshRecord &mesh,
                      const std::string &source);

    bool           empty() const { return table_.n_rows() == 0; }
    const data::CsvTable &table() const { return table_; }

    // Writes `file` (data::contact_forces_file), or removes a stale one
    // when the database holds no contact sample.
    void write(const std::string &file) const;

    static bool is_contact(const data::SampleRecord &sample) { return !sample.actuation.obstacles.empty(); }

  private:
    data::CsvTable table_;
  };
} // namespace softchain::reduction
