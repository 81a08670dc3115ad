// `flume validate`: runs validation cases, compares their probes with the references they
// declare, and writes results.json, report.md and the plots (spec/contract.md). A case plugs in
// by declaring [[validation.curves]] in its case file; nothing here is case-specific.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace flume {

struct ValidateOptions {
  std::vector<std::string> names;  // bundled case names; empty = every case with references
  bool quick = false;              // the reduced-resolution set (each case's validation.quick)
  std::vector<std::string> sets;   // --set KEY=VALUE, applied to every run after the quick set
  std::filesystem::path out_dir = "validation";
  int threads = 0;
  // Cases validated at once, each in a process of its own (with threads = cores / jobs unless
  // `threads` is given); results.json and report.md keep the order of the cases.
  int jobs = 1;
  bool quiet = false;
};

// Returns the exit status: 0 when every metric passes, 1 otherwise.
int validate(const ValidateOptions& options);

}  // namespace flume
