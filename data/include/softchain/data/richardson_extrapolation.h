#pragma once
// RichardsonExtrapolation: the converged value of a quantity computed on
// three meshes, and how sure that value is, by the procedure of Celik et al.
// (2008, "Procedure for estimation and reporting of uncertainty due to
// discretization in CFD applications", J. Fluids Eng. 130, 078001), which
// allows unequal refinement ratios. With h1 < h2 < h3 the representative
// mesh sizes (h = N^(-1/3) for N unknowns in 3D), f1, f2, f3 the values,
// e21 = f2 - f1, e32 = f3 - f2, r21 = h2/h1, r32 = h3/h2 and s = sign(e32/e21),
// the observed order p solves
//     p = | ln|e32/e21| + ln((r21^p - s) / (r32^p - s)) | / ln r21
// (fixed-point iteration), and
//     f_ext = (r21^p f1 - f2) / (r21^p - 1),
//     uncertainty of f_ext = 1.25 |f1 - f_ext|   (the GCI's safety factor).
// Oscillating values (s < 0) or an order outside [0.5, 8] mean the meshes
// are not in the asymptotic range: then f_ext = f1 and its uncertainty is
// |f2 - f1|, and `asymptotic` says so.
#include <array>

namespace softchain::data
{
  struct RichardsonExtrapolation
  {
    double value;       // f_ext
    double uncertainty; // of f_ext, in the quantity's units
    double order;       // p (0 outside the asymptotic range)
    bool   asymptotic;

    // Sizes and values finest first.
    static RichardsonExtrapolation of(const std::array<double, 3> &h, const std::array<double, 3> &f);
  };
} // namespace softchain::data
