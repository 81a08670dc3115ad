#include "flume/validation/validate.hpp"

#include <fmt/format.h>

#include <omp.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "flume/case/case_reader.hpp"
#include "flume/core/error.hpp"
#include "flume/io/atomic_file.hpp"
#include "flume/io/csv_table.hpp"
#include "flume/run/child_process.hpp"
#include "flume/validation/bundled_cases.hpp"
#include "flume/validation/case_result.hpp"
#include "flume/validation/convergence.hpp"
#include "flume/validation/convergence_rows.hpp"
#include "flume/validation/density_range.hpp"
#include "flume/validation/profile_compare.hpp"
#include "flume/validation/report.hpp"
#include "flume/validation/theory_reference.hpp"
#include "flume/validation/variant.hpp"

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

// The file stem of curve c's plot and data: case and probe, plus the curve's index when another
// curve of the case plots the same probe.
std::string curve_stem(const CaseSpec& spec, std::size_t c) {
  const auto& check = spec.curves[c];
  const auto same_probe =
      std::count_if(spec.curves.begin(), spec.curves.end(),
                    [&](const CurveCheck& o) { return o.probe == check.probe; });
  std::string stem = spec.name + "_" + check.probe;
  return same_probe > 1 ? fmt::format("{}_{}", stem, c) : stem;
}

// Plots every series of curve c against the reference with scripts/plot_curve.py; returns the
// PNG's file name, or "" when plotting is unavailable.
std::string plot_curve(const std::filesystem::path& out_dir, const CaseResult& cr, std::size_t c,
                       const std::vector<io::CsvData>& probes, const io::CsvData& ref) {
  const auto& check = cr.spec.curves[c];
  const std::string stem = curve_stem(cr.spec, c);
  std::string args;
  for (std::size_t s = 0; s < cr.series.size(); ++s) {
    if (!cr.series[s].run.completed) continue;
    const auto file = out_dir / fmt::format("{}_{}.csv", stem, cr.series[s].label);
    io::CsvTable table(file, {"x", "y"});
    const auto t = probes[s].column("time"), y = probes[s].column(check.probe);
    for (std::size_t k = 0; k < t.size(); ++k)
      table.add_row(std::vector<double>{t[k] / cr.spec.time_scale, y[k] / check.value_scale});
    table.flush();
    args += " --series " + shell_quote(cr.series[s].label + "=" + file.string());
  }
  const auto ref_file = out_dir / (stem + "_reference.csv");
  io::CsvTable table(ref_file, {"x", "y"});
  const auto rx = ref.column(check.reference_x), ry = ref.column(check.reference_y);
  for (std::size_t k = 0; k < rx.size(); ++k)
    table.add_row(std::vector<double>{rx[k], ry[k]});
  table.flush();
  const auto script = std::filesystem::path(FLUME_SOURCE_DIR) / "scripts" / "plot_curve.py";
  const std::string png = stem + ".png";
  const std::string cmd = fmt::format(
      "{} {}{} --reference {} --reference-label {} --out {} --title {} --xlabel {} --ylabel {} "
      "> /dev/null 2>&1",
      python(), shell_quote(script.string()), args, shell_quote(ref_file.string()),
      shell_quote(check.source.empty() ? "reference" : check.source),
      shell_quote((out_dir / png).string()),
      shell_quote(fmt::format("{}: {} ({} particles)", cr.spec.name, check.label,
                              cr.series.front().run.particles)),
      shell_quote(check.reference_x), shell_quote(check.reference_y));
  return std::system(cmd.c_str()) == 0 ? png : std::string();
}

// The particle pictures of every completed series near each of the case's picture times,
// coloured by spec.picture_field (scripts/plot_snapshot.py on the run's snapshots.pvd).
void draw_pictures(const std::filesystem::path& out_dir, CaseResult& cr) {
  const auto script = std::filesystem::path(FLUME_SOURCE_DIR) / "scripts" / "plot_snapshot.py";
  for (double t : cr.spec.pictures) {
    std::vector<std::string> row;
    for (const auto& s : cr.series) {
      const auto pvd = out_dir / cr.spec.name / s.label / "snapshots" / "snapshots.pvd";
      const std::string png = fmt::format("{}_{}_t{:.4g}.png", cr.spec.name, s.label, t);
      const std::string cmd =
          fmt::format("{} {} {} {} --time {} --field {} --title {} > /dev/null 2>&1", python(),
                      shell_quote(script.string()), shell_quote(pvd.string()),
                      shell_quote((out_dir / png).string()), t, shell_quote(cr.spec.picture_field),
                      shell_quote(fmt::format("{} `{}`, t = {:.4g} s, coloured by {}", cr.spec.name,
                                              s.label, t, cr.spec.picture_field)));
      row.push_back(s.run.completed && std::filesystem::exists(pvd) && std::system(cmd.c_str()) == 0
                        ? png
                        : std::string());
    }
    cr.pictures.push_back(row);
  }
}

// The surface near the highest crest of every completed series at each of the case's
// crest_pictures times, against KdV's A sech^2 of its height (scripts/plot_crest_profile.py).
void draw_crest_profiles(const std::filesystem::path& out_dir, CaseResult& cr) {
  const auto script = std::filesystem::path(FLUME_SOURCE_DIR) / "scripts" / "plot_crest_profile.py";
  const auto& spec = cr.spec;
  for (double t : spec.crest_pictures) {
    std::string args;
    for (const auto& s : cr.series) {
      const auto pvd = out_dir / spec.name / s.label / "snapshots" / "snapshots.pvd";
      if (s.run.completed && std::filesystem::exists(pvd))
        args += " --series " + shell_quote(s.label + "=" + pvd.string());
    }
    const std::string png = fmt::format("{}_crest_t{:.4g}.png", spec.name, t);
    const std::string cmd = fmt::format(
        "{} {}{} --time {} --depth {} --rho0 {} --dx {} --x-lo {} --x-hi {}{} --out {} --title {} "
        "> /dev/null 2>&1",
        python(), shell_quote(script.string()), args, t, spec.still_depth, spec.rho0, spec.spacing,
        spec.domain_min[0], spec.domain_max[0], spec.walls[0] == "periodic" ? " --periodic" : "",
        shell_quote((out_dir / png).string()),
        shell_quote(
            fmt::format("{}: the surface near the crest against KdV, t = {:.4g} s", spec.name, t)));
    cr.crest_pictures.push_back(!args.empty() && std::system(cmd.c_str()) == 0 ? png
                                                                               : std::string());
  }
}

// Each of the case's diagnostics columns against time, one line per completed series (BL Fig 6
// sets the schemes' momenta side by side); a column that diagnostics.csv does not have is
// taken from probes.csv (a wave gauge's time series).
void plot_diagnostics(const std::filesystem::path& out_dir, CaseResult& cr) {
  const auto script = std::filesystem::path(FLUME_SOURCE_DIR) / "scripts" / "plot_curve.py";
  for (const auto& column : cr.spec.diagnostics_plots) {
    std::string args;
    for (const auto& s : cr.series) {
      if (!s.run.completed) continue;
      const auto dir = out_dir / cr.spec.name / s.label;
      auto d = io::read_csv(dir / "diagnostics.csv");
      if (std::find(d.columns.begin(), d.columns.end(), column) == d.columns.end() &&
          std::filesystem::exists(dir / "probes.csv"))
        d = io::read_csv(dir / "probes.csv");
      const auto file = out_dir / fmt::format("{}_{}_{}.csv", cr.spec.name, column, s.label);
      io::CsvTable table(file, {"x", "y"});
      const auto t = d.column("time"), y = d.column(column);
      for (std::size_t k = 0; k < t.size(); ++k)
        table.add_row(std::vector<double>{t[k], y[k]});
      table.flush();
      args += " --series " + shell_quote(s.label + "=" + file.string());
    }
    const std::string png = fmt::format("{}_{}.png", cr.spec.name, column);
    const std::string cmd = fmt::format(
        "{} {}{} --out {} --title {} --xlabel {} --ylabel {} > /dev/null 2>&1", python(),
        shell_quote(script.string()), args, shell_quote((out_dir / png).string()),
        shell_quote(fmt::format("{}: {} of every scheme", cr.spec.name, column)),
        shell_quote("t (s)"), shell_quote(column));
    cr.diagnostics_plots.push_back(!args.empty() && std::system(cmd.c_str()) == 0 ? png
                                                                                  : std::string());
  }
}

// Each profile check's field along the profile line, every completed series against the
// exact solution (scripts/plot_curve.py).
void plot_profiles(const std::filesystem::path& out_dir, CaseResult& cr) {
  const auto script = std::filesystem::path(FLUME_SOURCE_DIR) / "scripts" / "plot_curve.py";
  const ShockTube tube = shock_tube(cr.spec);
  const auto exact = out_dir / fmt::format("{}_exact.csv", cr.spec.name);
  write_exact_profile(tube, cr.spec.domain_min[0], cr.spec.domain_max[0], 801, exact);
  const auto exact_data = io::read_csv(exact);
  for (const auto& check : cr.spec.profiles) {
    std::string args;
    for (const auto& s : cr.series) {
      if (!s.run.completed) continue;
      const auto d = io::read_csv(out_dir / cr.spec.name / s.label / "profile.csv");
      const auto file = out_dir / fmt::format("{}_{}_{}.csv", cr.spec.name, check.field, s.label);
      io::CsvTable table(file, {"x", "y"});
      const auto x = d.column("x"), y = d.column(check.field);
      for (std::size_t k = 0; k < x.size(); ++k)
        table.add_row(std::vector<double>{x[k], y[k]});
      table.flush();
      args += " --series " + shell_quote(s.label + "=" + file.string());
    }
    const auto ref = out_dir / fmt::format("{}_{}_exact.csv", cr.spec.name, check.field);
    io::CsvTable table(ref, {"x", "y"});
    const auto x = exact_data.column("x"), y = exact_data.column(check.field);
    for (std::size_t k = 0; k < x.size(); ++k)
      table.add_row(std::vector<double>{x[k], y[k]});
    table.flush();
    const std::string png = fmt::format("{}_profile_{}.png", cr.spec.name, check.field);
    const std::string cmd = fmt::format(
        "{} {}{} --reference {} --reference-label {} --out {} --title {} --xlabel {} --ylabel {} "
        "> /dev/null 2>&1",
        python(), shell_quote(script.string()), args, shell_quote(ref.string()),
        shell_quote("exact Riemann solution"), shell_quote((out_dir / png).string()),
        shell_quote(fmt::format("{}: {} at t = {} s", cr.spec.name, check.field, cr.spec.end_time)),
        shell_quote("x (m)"), shell_quote(check.field));
    cr.profile_plots.push_back(!args.empty() && std::system(cmd.c_str()) == 0 ? png
                                                                              : std::string());
  }
}

// The relative L1 error of each of the case's profile checks, from the run's profile.csv.
std::vector<double> profile_errors(const CaseSpec& spec, const std::filesystem::path& run_dir) {
  if (spec.profiles.empty()) return {};
  const ShockTube tube = shock_tube(spec);
  const auto profile = io::read_csv(run_dir / "profile.csv");
  std::vector<double> errors;
  for (const auto& check : spec.profiles)
    errors.push_back(profile_l1_error(tube, profile, check.field));
  return errors;
}

// The probes of a configuration's companion runs, by label (those that completed).
using CompanionProbes = std::map<std::string, io::CsvData>;

// The probes of companion `label` (nullptr when it did not run to the end).
const io::CsvData* companion_probes(const CompanionProbes& companions, const std::string& label) {
  const auto it = companions.find(label);
  return it == companions.end() ? nullptr : &it->second;
}

// The points of curve `check` of a run whose probes are `probes`.
std::vector<CurvePoint> compare_curve(const CaseSpec& spec, const CurveCheck& check,
                                      const io::CsvData& probes,
                                      const CompanionProbes& companions = {}) {
  const auto ref =
      curve_reference(spec, check, probes, companion_probes(companions, check.companion));
  const double to = check.window_to > 0.0 ? check.window_to : HUGE_VAL;
  return compare_over_window(probes.column("time"), probes.column(check.probe),
                             ref.column(check.reference_x), ref.column(check.reference_y),
                             spec.time_scale, check.value_scale, check.absolute, check.statistic,
                             check.window_from, to, check.at);
}

// The case's convergence study (CaseSpec::convergence_spacings, or the quick ones): the case as
// written, with the user's --set, the study's overrides and the level's spacing, at each level.
std::vector<StudyLevel> run_study(const std::filesystem::path& file, const std::string& name,
                                  const CaseSpec& spec, const ValidateOptions& opt) {
  std::vector<StudyLevel> study;
  for (double spacing : opt.quick ? spec.quick_convergence_spacings : spec.convergence_spacings) {
    auto sets = opt.sets;
    sets.insert(sets.end(), spec.convergence_sets.begin(), spec.convergence_sets.end());
    sets.push_back(spacing_override(spacing));
    const CaseSpec level_spec = read_case(file, sets);
    const auto dir = opt.out_dir / name / "convergence" / fmt::format("{}", spacing);
    if (!opt.quiet)
      std::cout << fmt::format("validate {}: convergence study at spacing {} m -> {}", name,
                               spacing, dir.string())
                << std::endl;
    StudyLevel level;
    level.spacing = spacing;
    level.run = run_case(level_spec, RunOptions{dir, opt.threads, true});
    if (level.run.completed) {
      const auto points =
          compare_curve(level_spec, level_spec.curves.at(level_spec.convergence_curve),
                        io::read_csv(dir / "probes.csv"));
      if (!points.empty()) level.max_error = summarize(points).max;
    }
    study.push_back(std::move(level));
  }
  return study;
}

CaseResult validate_case(const std::string& name, const ValidateOptions& opt) {
  CaseResult cr;
  const auto file = bundled_case(name);
  const CaseSpec as_written = read_case(file, {});
  std::vector<std::string> base = opt.quick ? as_written.quick : std::vector<std::string>{};
  base.insert(base.end(), opt.sets.begin(), opt.sets.end());
  cr.overrides = opt.sets;
  cr.spec = read_case(file, base);
  for (const auto& check : cr.spec.curves) {
    cr.tolerances.push_back(opt.quick ? check.quick_tolerance : check.tolerance);
    cr.mean_tolerances.push_back(opt.quick ? check.quick_mean_tolerance : check.mean_tolerance);
  }
  for (const auto& check : cr.spec.profiles)
    cr.profile_tolerances.push_back(opt.quick ? check.quick_tolerance : check.tolerance);

  std::vector<std::pair<std::string, std::vector<std::string>>> configs{{cr.spec.preset, base}};
  std::vector<std::vector<std::string>> own_overrides{{}};  // each variant's, for the report
  for (const auto& v :
       opt.quick && !cr.spec.quick_variants ? std::vector<std::string>{} : cr.spec.variants) {
    const Variant variant = parse_variant(v);
    auto overrides = base;
    overrides.insert(overrides.end(), variant.overrides.begin(), variant.overrides.end());
    configs.emplace_back(variant.label, overrides);
    own_overrides.push_back(variant.overrides);
  }
  // Profile cases also run every configuration at twice the spacing, to show convergence.
  const auto coarse =
      cr.spec.profiles.empty() ? std::vector<std::string>{} : coarser_overrides(cr.spec);
  std::vector<io::CsvData> probes;
  std::vector<CompanionProbes> companions;  // per configuration
  for (const auto& [label, overrides] : configs) {
    const CaseSpec spec = read_case(file, overrides);
    const auto run_dir = opt.out_dir / name / label;
    if (!opt.quiet)
      std::cout << fmt::format("validate {}: {} -> {}", name, label, run_dir.string()) << std::endl;
    SeriesResult s;
    s.label = label;
    s.overrides = own_overrides[cr.series.size()];
    s.run = run_case(spec, RunOptions{run_dir, opt.threads, true});
    // A case without curves (a shock tube) has no probes.csv.
    const bool curves = s.run.completed && !spec.curves.empty();
    probes.push_back(curves ? io::read_csv(run_dir / "probes.csv") : io::CsvData{});
    // The configuration's companions (its overrides, then the companion's), once it completed.
    companions.emplace_back();
    for (const auto& c : s.run.completed ? spec.companions : std::vector<std::string>{}) {
      const Variant companion = parse_variant(c);
      auto sets = overrides;
      sets.insert(sets.end(), companion.overrides.begin(), companion.overrides.end());
      const auto dir = opt.out_dir / name / "companions" / label / companion.label;
      if (!opt.quiet)
        std::cout << fmt::format("validate {}: {}, companion {} -> {}", name, label,
                                 companion.label, dir.string())
                  << std::endl;
      RunResult r = run_case(read_case(file, sets), RunOptions{dir, opt.threads, true});
      if (r.completed) companions.back().emplace(companion.label, io::read_csv(dir / "probes.csv"));
      s.companions.emplace_back(companion.label, std::move(r));
    }
    if (curves)
      for (const auto& check : spec.curves)
        s.curves.push_back(compare_curve(spec, check, probes.back(), companions.back()));
    if (s.run.completed) s.profile_errors = profile_errors(spec, run_dir);
    if (s.run.completed && spec.eos == "tait") {
      s.has_density_range = true;
      s.density = density_range(io::read_csv(run_dir / "diagnostics.csv"), spec.rho0);
    }
    if (!coarse.empty()) {
      auto coarse_sets = overrides;
      coarse_sets.insert(coarse_sets.end(), coarse.begin(), coarse.end());
      const CaseSpec coarse_spec = read_case(file, coarse_sets);
      cr.coarse_spacing = coarse_spec.spacing;
      const auto coarse_dir = opt.out_dir / name / "coarse" / label;
      if (!opt.quiet)
        std::cout << fmt::format("validate {}: {} at spacing {} m -> {}", name, label,
                                 coarse_spec.spacing, coarse_dir.string())
                  << std::endl;
      s.coarse_run = run_case(coarse_spec, RunOptions{coarse_dir, opt.threads, true});
      if (s.coarse_run.completed) s.coarse_profile_errors = profile_errors(coarse_spec, coarse_dir);
    }
    cr.series.push_back(std::move(s));
  }
  cr.study = run_study(file, name, cr.spec, opt);
  draw_pictures(opt.out_dir, cr);
  draw_crest_profiles(opt.out_dir, cr);
  plot_diagnostics(opt.out_dir, cr);
  if (!cr.spec.profiles.empty() && cr.series.front().run.completed) plot_profiles(opt.out_dir, cr);
  for (const auto& check : cr.spec.curves) {
    const std::size_t c = cr.plots.size();
    if (!cr.series.front().run.completed) {
      cr.plots.emplace_back();
      continue;
    }
    const auto ref = curve_reference(cr.spec, check, probes.front(),
                                     companion_probes(companions.front(), check.companion));
    cr.plots.push_back(plot_curve(opt.out_dir, cr, c, probes, ref));
  }
  return cr;
}

// results.json rows of the case as written (the variants are reported, not gated).
bool add_result_rows(const CaseResult& cr, nlohmann::ordered_json& rows) {
  const auto& main = cr.series.front();
  if (!main.run.completed) {
    rows.push_back({{"case", cr.spec.name},
                    {"metric", "run"},
                    {"value", nullptr},
                    {"reference", nullptr},
                    {"error", main.run.error},
                    {"tolerance", nullptr},
                    {"pass", false}});
    return false;
  }
  bool all_pass = true;
  for (std::size_t c = 0; c < cr.spec.profiles.size(); ++c) {
    const auto& check = cr.spec.profiles[c];
    const double error = main.profile_errors.at(c);
    const bool pass = error <= cr.profile_tolerances[c];
    if (check.gated) all_pass = all_pass && pass;
    rows.push_back({{"case", cr.spec.name},
                    {"metric", fmt::format("{} relative L1 error at t = {} s against the exact "
                                           "Riemann solution",
                                           check.field, cr.spec.end_time)},
                    {"value", error},
                    {"reference", nullptr},
                    {"error", error},
                    {"tolerance", cr.profile_tolerances[c]},
                    {"gated", check.gated},
                    {"pass", pass}});
  }
  for (std::size_t c = 0; c < cr.spec.curves.size(); ++c) {
    const auto& check = cr.spec.curves[c];
    if (main.curves[c].empty() && check.gated) all_pass = false;
    for (const auto& p : main.curves[c]) {
      const bool pass = p.error <= cr.tolerances[c];
      if (check.gated) all_pass = all_pass && pass;
      rows.push_back(
          {{"case", cr.spec.name},
           {"metric", check.statistic == CurveStatistic::pointwise
                          ? fmt::format("{} at {}={:.3g}", check.probe, check.reference_x, p.x)
                          : fmt::format("{} {} over {}=[{:.3g}, {:.3g}]", check.probe,
                                        statistic_name(check.statistic), check.reference_x,
                                        check.window_from, p.x)},
           {"value", p.value},
           {"reference", p.reference},
           {"error", p.error},
           {"tolerance", cr.tolerances[c]},
           {"gated", check.gated},
           {"pass", pass}});
    }
    if (cr.mean_tolerances[c] > 0.0 && !main.curves[c].empty()) {
      const double mean = summarize(main.curves[c]).mean;
      const bool pass = mean <= cr.mean_tolerances[c];
      if (check.gated) all_pass = all_pass && pass;
      rows.push_back({{"case", cr.spec.name},
                      {"metric", fmt::format("{} mean error", check.probe)},
                      {"value", mean},
                      {"reference", nullptr},
                      {"error", mean},
                      {"tolerance", cr.mean_tolerances[c]},
                      {"gated", check.gated},
                      {"pass", pass}});
    }
  }
  return all_pass;
}

// What validating one case gives: its rows of results.json, whether its gated metrics pass,
// and its section of report.md.
struct CaseOutcome {
  bool pass = false;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  std::string section;
};

CaseOutcome case_outcome(const std::string& name, const ValidateOptions& opt) {
  const CaseResult cr = validate_case(name, opt);
  CaseOutcome o;
  o.pass = add_result_rows(cr, o.rows);
  o.pass = add_convergence_rows(cr, o.rows) && o.pass;
  o.pass = add_study_rows(cr, o.rows) && o.pass;
  o.section = report_case_section(cr);
  return o;
}

// A case whose process died (a crash, or killed for memory): a failed run row and a section
// that says so.
CaseOutcome died(const std::string& name, const ChildResult& child) {
  const std::string why = how_it_ended(child);
  CaseOutcome o;
  o.rows.push_back({{"case", name},
                    {"metric", "run"},
                    {"value", nullptr},
                    {"reference", nullptr},
                    {"error", "the validation process of the case ended: " + why},
                    {"tolerance", nullptr},
                    {"pass", false}});
  o.section = fmt::format("\n## {}\n\nThe validation process of this case ended: {}.\n", name, why);
  return o;
}

// --jobs N: each case in a forked child, N at a time, with the cores shared among them unless
// --threads says otherwise (the quick set's coarse runs gain nothing from a second thread: two
// of them took 86 s on one thread each against 95 s on two). Every case's threads are then
// its own, so its results are those of `--threads` (results.json byte for byte).
std::vector<CaseOutcome> outcomes_in_children(const std::vector<std::string>& names,
                                              const ValidateOptions& opt) {
  ValidateOptions child = opt;
  if (child.threads == 0) child.threads = std::max(1, omp_get_num_procs() / opt.jobs);
  std::vector<std::function<std::string()>> bodies;
  for (const auto& name : names)
    bodies.emplace_back([&child, name] {
      try {
        const CaseOutcome o = case_outcome(name, child);
        return nlohmann::ordered_json{{"pass", o.pass}, {"rows", o.rows}, {"section", o.section}}
            .dump();
      } catch (const InputError& e) {
        return nlohmann::ordered_json{{"input_error", e.what()}}.dump();
      }
    });
  const auto children = run_in_children(bodies, opt.jobs);
  std::vector<CaseOutcome> outcomes;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const ChildResult& c = children[k];
    if (c.exited && c.exit_code == 1 && !c.output.empty())  // an exception: rethrown here
      throw std::runtime_error(c.output);
    if (!c.exited || c.exit_code != 0) {
      outcomes.push_back(died(names[k], c));
      continue;
    }
    const auto j = nlohmann::ordered_json::parse(c.output);
    if (j.contains("input_error")) throw InputError(j.at("input_error").get<std::string>());
    CaseOutcome o;
    o.pass = j.at("pass").get<bool>();
    o.rows = j.at("rows");
    o.section = j.at("section").get<std::string>();
    outcomes.push_back(std::move(o));
  }
  return outcomes;
}

}  // namespace

int validate(const ValidateOptions& opt) {
  if (opt.jobs < 1)
    throw InputError(fmt::format("validate: --jobs {}: must be positive", opt.jobs));
  std::vector<std::string> names = opt.names;
  if (names.empty()) {
    for (const auto& f : bundled_case_files()) {
      const auto spec = read_case(f, {});
      if (!spec.curves.empty() || !spec.profiles.empty()) names.push_back(spec.name);
    }
  }
  std::filesystem::create_directories(opt.out_dir);
  std::vector<CaseOutcome> outcomes;
  if (opt.jobs > 1) {
    outcomes = outcomes_in_children(names, opt);
  } else {
    for (const auto& name : names)
      outcomes.push_back(case_outcome(name, opt));
  }
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  std::string report = report_heading(opt.quick);
  bool all_pass = true;
  for (const auto& o : outcomes) {
    for (const auto& row : o.rows)
      rows.push_back(row);
    report += o.section;
    all_pass = all_pass && o.pass;
  }
  io::write_file_atomic(opt.out_dir / "results.json", rows.dump(2) + "\n");
  io::write_file_atomic(opt.out_dir / "report.md", report);
  if (!opt.quiet) {
    std::cout << fmt::format("validation {}: report {}", all_pass ? "passed" : "FAILED",
                             (opt.out_dir / "report.md").string())
              << std::endl;
  }
  return all_pass ? 0 : 1;
}

}  // namespace flume
