// How far a liquid's density strays from rho0 over a run (diagnostics.csv's rho_min and rho_max
// columns): the weakly compressible model's measure of how incompressible the flow stayed.
#pragma once

#include "flume/io/csv_table.hpp"

namespace flume {

struct DensityRange {
  double above = 0.0;  // max over the rows of (rho_max - rho0) / rho0
  double below = 0.0;  // min over the rows of (rho_min - rho0) / rho0 (negative: below rho0)
};

// Over every row of diagnostics.csv; throws std::out_of_range if a column is missing and
// std::invalid_argument if there are no rows or rho0 is not positive.
DensityRange density_range(const io::CsvData& diagnostics, double rho0);

}  // namespace flume
