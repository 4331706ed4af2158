#pragma once
// PaperClaims: the paper's qualitative claims (Sec. IV-A, V; the report lists
// six) checked on one design's outputs, each with a verdict and the numbers
// behind it. Everything is computed from the CSV files of the reduction and
// chain tiers:
//   <output>/stiffness/<M>_b<f>a.csv, _kphi_vs_pressure.csv, _samples.csv
//   <output>/chain/validation_summary.csv
// Claims about other designs (the parallelepiped; P13 against P10) read the
// sibling directories <output>/../<design>/stiffness/ when they exist.
// The thresholds that turn a number into a verdict are stated in the
// claim's text, so that the report's reader can judge them.
#include <softchain/data/rotation_method.h>

#include <string>
#include <vector>

namespace softchain::report
{
  enum class Verdict
  {
    holds,
    does_not_hold,
    not_measurable
  };

  // "holds", "does not hold", "not measurable here".
  std::string verdict_text(Verdict verdict);

  struct Claim
  {
    std::string number;    // "1a", "1b", "2a", ...
    std::string statement; // the paper's claim and our criterion
    Verdict     verdict = Verdict::not_measurable;
    std::string measured; // the numbers, or why they cannot be measured
  };

  struct ClaimInputs
  {
    std::string design_name;      // /design name, e.g. "p10"
    std::string output_directory; // output/<design>
    std::string chain_method = "M2";
    double      half_width_fraction = 0.5; // b / a of the chain's tables
    int         extraction_samples = 0;    // converged non-validation samples
  };

  class PaperClaims
  {
  public:
    explicit PaperClaims(const ClaimInputs &inputs);

    const std::vector<Claim> &claims() const { return claims_; }

  private:
    Claim constant_for_regular_shape() const;  // 1a
    Claim thicker_walls_stiffer() const;       // 1b
    Claim decreases_along_taper() const;       // 2a
    Claim decreases_with_pressure() const;     // 2b
    Claim m1_more_sensitive_to_b() const;      // 3
    Claim lateral_fails_past_buckling() const; // 4a
    Claim lateral_unreliable_small() const;    // 4b
    Claim kpsi_higher_near_base() const;       // 5
    Claim few_samples_suffice() const;         // 6

    // <output>/stiffness of `design` (this one, or a sibling directory).
    std::string stiffness_directory(const std::string &design) const;
    // "<M>_b<f>a" of `method` at the chain's slab half-width.
    std::string label(data::RotationMethod method) const;

    ClaimInputs        in_;
    std::vector<Claim> claims_;
  };
} // namespace softchain::report
