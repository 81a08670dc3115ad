#include "flume/validation/validate.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "flume/case/case_reader.hpp"
#include "flume/core/error.hpp"
#include "flume/io/atomic_file.hpp"
#include "flume/io/csv_table.hpp"
#include "flume/run/runner.hpp"
#include "flume/validation/bundled_cases.hpp"
#include "flume/validation/curve_compare.hpp"

namespace flume {

namespace {

// Debian's python3 has matplotlib (python3-matplotlib); a python3 earlier on PATH may not.
std::string python() {
  if (const char* env = std::getenv("FLUME_PYTHON")) return env;
  if (std::filesystem::exists("/usr/bin/python3")) return "/usr/bin/python3";
  return "python3";
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s)
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct CurveResult {
  CurveCheck check;
  std::vector<CurvePoint> points;
  double tolerance = 0.0;
  std::string plot;  // PNG file name in the output folder, empty if plotting failed
};

struct CaseResult {
  CaseSpec spec;
  RunResult run;
  std::vector<CurveResult> curves;
};

// Plots flume's curve against the reference with scripts/plot_curve.py.
std::string plot_curve(const std::filesystem::path& out_dir, const CaseResult& cr,
                       const CurveResult& c, const std::vector<double>& t,
                       const std::vector<double>& y, const std::vector<double>& rx,
                       const std::vector<double>& ry) {
  const std::string stem = cr.spec.name + "_" + c.check.probe;
  io::CsvTable sim(out_dir / (stem + "_flume.csv"), {"x", "y"});
  for (std::size_t k = 0; k < t.size(); ++k)
    sim.add_row(std::vector<double>{t[k] / cr.spec.time_scale, y[k] / c.check.value_scale});
  sim.flush();
  io::CsvTable ref(out_dir / (stem + "_reference.csv"), {"x", "y"});
  for (std::size_t k = 0; k < rx.size(); ++k)
    ref.add_row(std::vector<double>{rx[k], ry[k]});
  ref.flush();
  const auto script = std::filesystem::path(FLUME_SOURCE_DIR) / "scripts" / "plot_curve.py";
  const std::string png = stem + ".png";
  const std::string cmd = fmt::format(
      "{} {} --flume {} --reference {} --out {} --title {} --xlabel {} --ylabel {} "
      "--reference-label {} > /dev/null 2>&1",
      python(), shell_quote(script.string()),
      shell_quote((out_dir / (stem + "_flume.csv")).string()),
      shell_quote((out_dir / (stem + "_reference.csv")).string()),
      shell_quote((out_dir / png).string()),
      shell_quote(fmt::format("{}: {} ({} particles, {})", cr.spec.name, c.check.label,
                              cr.run.particles, cr.spec.preset)),
      shell_quote(c.check.reference_x), shell_quote(c.check.reference_y),
      shell_quote(c.check.source.empty() ? "reference" : c.check.source));
  if (std::system(cmd.c_str()) != 0) return {};
  return png;
}

CaseResult validate_case(const std::string& name, const ValidateOptions& opt) {
  CaseResult cr;
  const auto file = bundled_case(name);
  std::vector<std::string> overrides;
  if (opt.quick) overrides = read_case(file, {}).quick;
  cr.spec = read_case(file, overrides);
  const auto run_dir = opt.out_dir / name;
  RunOptions ro{run_dir, opt.threads, true};
  if (!opt.quiet)
    std::cout << fmt::format("validate {}: running into {} ...", name, run_dir.string())
              << std::endl;
  cr.run = run_case(cr.spec, ro);
  if (!cr.run.completed) return cr;
  const auto probes = io::read_csv(run_dir / "probes.csv");
  const auto t = probes.column("time");
  for (const auto& check : cr.spec.curves) {
    CurveResult c;
    c.check = check;
    c.tolerance = opt.quick ? check.quick_tolerance : check.tolerance;
    const auto ref = io::read_csv(check.reference);
    const auto rx = ref.column(check.reference_x), ry = ref.column(check.reference_y);
    const auto y = probes.column(check.probe);
    c.points = compare_curve(t, y, rx, ry, cr.spec.time_scale, check.value_scale);
    c.plot = plot_curve(opt.out_dir, cr, c, t, y, rx, ry);
    cr.curves.push_back(std::move(c));
  }
  return cr;
}

std::string report_markdown(const std::vector<CaseResult>& results, const ValidateOptions& opt) {
  std::string md = fmt::format(
      "# flume validation report\n\nflume {}{}. Errors are relative: "
      "|flume - reference| / |reference|.\n",
      FLUME_VERSION, opt.quick ? ", quick (reduced-resolution) set" : "");
  for (const auto& cr : results) {
    md += fmt::format("\n## {}\n\n{}\n\n", cr.spec.name, cr.spec.description);
    md += fmt::format(
        "Scheme `{}` ({} density + {} force), kernel `{}`, h/dx = {}, spacing {} m, "
        "{} particles, {} steps, {:.1f} s wall time ({:.3g} particle-steps/s, {} "
        "threads).\n",
        cr.spec.preset, cr.spec.density, cr.spec.force, cr.spec.kernel, cr.spec.h_over_dx,
        cr.spec.spacing, cr.run.particles, cr.run.steps, cr.run.wall_seconds,
        cr.run.particle_steps_per_second, cr.run.threads);
    if (!cr.run.completed) {
      md += fmt::format("\n**The run failed:** {}\n", cr.run.error);
      continue;
    }
    if (!cr.spec.notes.empty()) {
      md += "\nWhat the papers report:\n\n";
      for (const auto& n : cr.spec.notes)
        md += "- " + n + "\n";
    }
    for (const auto& c : cr.curves) {
      double max_err = 0.0, sum = 0.0;
      for (const auto& p : c.points) {
        max_err = std::max(max_err, p.error);
        sum += p.error;
      }
      const double mean = c.points.empty() ? 0.0 : sum / static_cast<double>(c.points.size());
      md += fmt::format(
          "\n### {}\n\nReference: {} (`{}`). {} points compared; max error {:.1f} %, "
          "mean {:.1f} %, tolerance {:.0f} %: **{}**.\n\n",
          c.check.label, c.check.source, c.check.reference.filename().string(), c.points.size(),
          100 * max_err, 100 * mean, 100 * c.tolerance,
          !c.points.empty() && max_err <= c.tolerance ? "pass" : "FAIL");
      md += fmt::format("| {} | reference {} | flume | error |\n|---|---|---|---|\n",
                        c.check.reference_x, c.check.reference_y);
      for (const auto& p : c.points)
        md += fmt::format("| {:.3g} | {:.3g} | {:.3f} | {:.1f} % |\n", p.x, p.reference, p.value,
                          100 * p.error);
      md += c.plot.empty() ? "\n(plot unavailable: python3 with matplotlib not found)\n"
                           : fmt::format("\n![{}]({})\n", c.check.label, c.plot);
    }
  }
  return md;
}

}  // namespace

int validate(const ValidateOptions& opt) {
  std::vector<std::string> names = opt.names;
  if (names.empty()) {
    for (const auto& f : bundled_case_files()) {
      const auto spec = read_case(f, {});
      if (!spec.curves.empty()) names.push_back(spec.name);
    }
  }
  std::filesystem::create_directories(opt.out_dir);
  std::vector<CaseResult> results;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  bool all_pass = true;
  for (const auto& name : names) {
    results.push_back(validate_case(name, opt));
    const auto& cr = results.back();
    if (!cr.run.completed) {
      all_pass = false;
      rows.push_back({{"case", name},
                      {"metric", "run"},
                      {"value", nullptr},
                      {"reference", nullptr},
                      {"error", cr.run.error},
                      {"tolerance", nullptr},
                      {"pass", false}});
      continue;
    }
    for (const auto& c : cr.curves) {
      if (c.points.empty()) all_pass = false;
      for (const auto& p : c.points) {
        const bool pass = p.error <= c.tolerance;
        all_pass = all_pass && pass;
        rows.push_back(
            {{"case", name},
             {"metric", fmt::format("{} at {}={:.3g}", c.check.probe, c.check.reference_x, p.x)},
             {"value", p.value},
             {"reference", p.reference},
             {"error", p.error},
             {"tolerance", c.tolerance},
             {"pass", pass}});
      }
    }
  }
  io::write_file_atomic(opt.out_dir / "results.json", rows.dump(2) + "\n");
  io::write_file_atomic(opt.out_dir / "report.md", report_markdown(results, opt));
  if (!opt.quiet) {
    std::cout << fmt::format("validation {}: report {}", all_pass ? "passed" : "FAILED",
                             (opt.out_dir / "report.md").string())
              << std::endl;
  }
  return all_pass ? 0 : 1;
}

}  // namespace flume
