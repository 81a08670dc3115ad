#include "flume/bench/bench_table.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace flume {

namespace {

struct Column {
  std::string header;
  bool left = false;  // text, not a number
  std::vector<std::string> cells;
};

}  // namespace

std::string bench_table(const std::vector<BenchResult>& results) {
  std::vector<std::string> phase_names;
  for (const auto& r : results)
    for (const auto& [name, seconds] : r.phases)
      if (std::find(phase_names.begin(), phase_names.end(), name) == phase_names.end())
        phase_names.push_back(name);

  std::vector<Column> cols{
      {"preset", true, {}},     {"particles", false, {}},      {"neighbours", false, {}},
      {"steps", false, {}},     {"wall s", false, {}},         {"M p-steps/s", false, {}},
      {"M inter/s", false, {}}, {"bytes/particle", false, {}}, {"threads", false, {}}};
  for (const auto& name : phase_names)
    cols.push_back({name + " %", false, {}});

  for (const auto& r : results) {
    std::size_t c = 0;
    cols[c++].cells.push_back(r.preset);
    cols[c++].cells.push_back(fmt::format("{}", r.particles));
    cols[c++].cells.push_back(fmt::format("{:.1f}", r.neighbours));
    cols[c++].cells.push_back(fmt::format("{}", r.steps));
    cols[c++].cells.push_back(fmt::format("{:.3g}", r.wall_seconds));
    cols[c++].cells.push_back(fmt::format("{:.3g}", r.particle_steps_per_second / 1e6));
    cols[c++].cells.push_back(fmt::format("{:.3g}", r.interactions_per_second / 1e6));
    cols[c++].cells.push_back(fmt::format("{:.0f}", r.bytes_per_particle));
    cols[c++].cells.push_back(fmt::format("{}", r.threads));
    for (const auto& name : phase_names) {
      auto it = std::find_if(r.phases.begin(), r.phases.end(),
                             [&](const auto& p) { return p.first == name; });
      cols[c++].cells.push_back(it == r.phases.end() || r.wall_seconds <= 0.0
                                    ? std::string("-")
                                    : fmt::format("{:.1f}", 100.0 * it->second / r.wall_seconds));
    }
  }

  std::string out;
  auto add_line = [&](auto cell_of) {
    std::string line;
    for (std::size_t c = 0; c < cols.size(); ++c) {
      std::size_t width = cols[c].header.size();
      for (const auto& s : cols[c].cells)
        width = std::max(width, s.size());
      const std::string text = cell_of(cols[c]);
      line += (c ? "  " : "") + (cols[c].left ? fmt::format("{:<{}}", text, width)
                                              : fmt::format("{:>{}}", text, width));
    }
    while (!line.empty() && line.back() == ' ')
      line.pop_back();
    out += line + "\n";
  };
  add_line([](const Column& c) { return c.header; });
  for (std::size_t row = 0; row < results.size(); ++row)
    add_line([row](const Column& c) { return c.cells[row]; });
  out +=
      "each run: the median of its repeats (wall s, M p-steps/s and phases); phases in % of the "
      "measured wall time; neighbours: mean per particle within the kernel support\n";
  return out;
}

}  // namespace flume
