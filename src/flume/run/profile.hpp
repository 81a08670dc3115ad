// profile.csv of a run (case key output.profile): the state along a line at the end time, for
// comparison with a one-dimensional solution (the shock tube's exact Riemann solution). The
// particles within a band of the line x[axis] = at, sorted by their first coordinate; columns
// x, y (, z), rho, p, u, v (, w), e (e = 0 for a liquid, which carries no internal energy).
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/io/csv_table.hpp"

namespace flume {

template <int D>
void write_profile(const std::filesystem::path& file, const ParticleSet<D>& ps, int axis, double at,
                   double half_width) {
  const char* names[] = {"x", "y", "z"};
  const char* velocity[] = {"u", "v", "w"};
  std::vector<std::string> columns;
  for (int k = 0; k < D; ++k)
    columns.emplace_back(names[k]);
  columns.insert(columns.end(), {"rho", "p"});
  for (int k = 0; k < D; ++k)
    columns.emplace_back(velocity[k]);
  columns.emplace_back("e");
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    if (std::abs(ps.x[i][axis] - at) <= half_width) rows.push_back(i);
  std::stable_sort(rows.begin(), rows.end(),
                   [&](std::size_t a, std::size_t b) { return ps.x[a][0] < ps.x[b][0]; });
  io::CsvTable table(file, columns);
  for (const std::size_t i : rows) {
    std::vector<double> row;
    for (int k = 0; k < D; ++k)
      row.push_back(ps.x[i][k]);
    row.insert(row.end(), {ps.rho[i], ps.p[i]});
    for (int k = 0; k < D; ++k)
      row.push_back(ps.v[i][k]);
    row.push_back(ps.uses(kFieldEnergy) ? ps.e[i] : 0.0);
    table.add_row(row);
  }
  table.flush();
}

}  // namespace flume
