#pragma once
// SamplePlan: which of a database's samples the design's .prm asks for now,
// `<database>.plan`, one sample id per line, sorted. The database keeps every
// sample it ever stored (a cache: a sample taken out of the .prm and put back
// is not solved again), so without a plan a reader would also see samples the
// .prm no longer lists -- a validation sample removed, a force magnitude
// replaced -- and the reduction and the chain would go on using them. Each
// sweep that completes writes its plan (atomically, atomic_file.h), and the
// readers take the stored samples it lists (ActuationDatabase::sample_ids).
#include <optional>
#include <string>
#include <vector>

namespace softchain::data
{
  class SamplePlan
  {
  public:
    explicit SamplePlan(const std::string &database_path);

    // The listed ids, sorted; nullopt if there is no plan file (a database
    // whose first sweep has not completed, or of an earlier version). An
    // InputError naming the file for a line that is not a sample id.
    std::optional<std::vector<std::string>> read() const;
    // Replaces the plan by `ids` (any order, duplicates allowed), unless the
    // file already lists exactly these, and returns the plan (as read()
    // would); only the database's writer may call this.
    std::vector<std::string> write(std::vector<std::string> ids) const;
    // Removes temporaries of interrupted writes (the writer only).
    void remove_leftovers() const;
    // Renames the plan to the plan of `database_path`, if there is one.
    void move_to(const std::string &database_path) const;

  private:
    std::string path_;
  };
} // namespace softchain::data
