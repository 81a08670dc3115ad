// The end-time profile of a shock tube (profile.csv) against the exact Riemann solution of its
// two fluid blocks (theory/riemann_exact.hpp): W 4.2's comparison, as relative L1 errors.
#pragma once

#include <filesystem>
#include <string>

#include "flume/case/case_spec.hpp"
#include "flume/io/csv_table.hpp"
#include "flume/theory/riemann_exact.hpp"

namespace flume {

// The Riemann problem of the case: left state the first block's (rho, u_x, p = (gamma - 1) rho
// e), right the second's, the diaphragm at the first block's x max.
struct ShockTube {
  RiemannSolution solution;
  double diaphragm = 0.0;  // m
  double time = 0.0;       // s, the case's end time
  GasState at(double x) const { return solution.sample((x - diaphragm) / time); }
};
ShockTube shock_tube(const CaseSpec& spec);

// sum_k |f_k - f(x_k)| / sum_k |f(x_k)| over the rows of profile.csv, for field "rho", "p" or
// "u" (f the exact solution at the particle's x).
double profile_l1_error(const ShockTube& tube, const io::CsvData& profile,
                        const std::string& field);

// The exact solution at n points across [x0, x1], columns x, rho, p, u (for the plots).
void write_exact_profile(const ShockTube& tube, double x0, double x1, int n,
                         const std::filesystem::path& file);

}  // namespace flume
