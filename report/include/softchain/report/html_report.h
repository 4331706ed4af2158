#pragma once
// HtmlReport: output/<design>/report.html, what a user reads after
// `softchain run`: the design, pictures of the deformed finger at 0, 40 and
// 80 kPa, the stiffness profiles (the paper's Fig. 5-7 equivalents), the
// chain-vs-FEM validation and the baseline comparison, the base torques of
// the prescribed tip motions (the paper's Sec. IV-B), the contact samples
// (force against pressure per obstacle, the finger on each obstacle), the
// run times and the paper's claims with verdicts. One HTML file: every image
// is a data: URI. It reads what the other tiers wrote (database.h5,
// stiffness/, chain/, contact/) and nothing else.
#include <softchain/chain/chain_parameters.h>
#include <softchain/data/actuation_database.h>
#include <softchain/report/html_document.h>

#include <optional>
#include <string>
#include <vector>

namespace softchain::report
{
  // The wall time of one stage of `softchain run`.
  struct StageTime
  {
    std::string name;
    double      seconds = 0;
  };

  class HtmlReport
  {
  public:
    // Reads the database, the chain's subsection of `prm` and the
    // outputs under `output_directory`. Throws data::InputError naming the
    // file when the database, the chain's stiffness table or the validation
    // summary is missing (plots are optional: gnuplot may be absent).
    HtmlReport(const data::PrmFile &prm, const std::string &database_path,
               const std::string &output_directory);

    // The stage times of `softchain run`; without them the report says
    // "not measured in this run".
    void set_stage_times(const std::vector<StageTime> &times) { stage_times_ = times; }

    std::string html() const;

  private:
    void summary_section(HtmlDocument &page) const;
    void fem_accuracy_paragraph(HtmlDocument &page) const;
    void design_section(HtmlDocument &page) const;
    void finger_section(HtmlDocument &page) const;
    void stiffness_section(HtmlDocument &page) const;
    void validation_section(HtmlDocument &page) const;
    void chain_pictures(HtmlDocument &page) const;
    // The paper's validation experiment: each chain model's base torque
    // errors over the prescribed tip motions (chain/protocol_summary.csv),
    // or a paragraph saying the design has none.
    void protocol_section(HtmlDocument &page) const;
    void contact_section(HtmlDocument &page) const;
    void chain_contact(HtmlDocument &page) const;
    void contact_pictures(HtmlDocument &page, const std::vector<std::string> &obstacles) const;
    void timing_section(HtmlDocument &page) const;
    void claims_section(HtmlDocument &page) const;

    // An output file by its path under the output directory.
    std::string output(const std::string &relative) const;
    // The PNG `relative` as a figure, or a line saying it was not drawn.
    void png_figure(HtmlDocument &page, const std::string &relative, const std::string &caption) const;
    // "<M>_b<f>a" of the chain's stiffness tables.
    std::string chain_label() const;

    std::string                      output_directory_;
    chain::ChainParameters           chain_;
    data::DesignRecord               design_;
    data::MeshRecord                 mesh_;
    std::vector<data::SampleRecord>  samples_;
    std::optional<std::vector<StageTime>> stage_times_;
  };
} // namespace softchain::report
