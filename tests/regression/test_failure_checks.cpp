// Failure detection after every step (sim/simulation.hpp, [checks] of the case file): each
// check, when it fires, ends the run with exit 1, summary.json's status "failed" and an error
// that names the check, the step, the time and the worst particle (its id and position); what
// was written before is kept and the failing state is the last snapshot.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "flume/case/build_simulation.hpp"
#include "flume/core/error.hpp"
#include "flume/io/csv_table.hpp"
#include "support/flume_binary.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

using test::slurp;
namespace fs = std::filesystem;

class FailureChecks : public test::FlumeBinaryTest {
 protected:
  // Runs the small dam break (rows every 0.001 s, no snapshots asked) with the overrides;
  // expects the failure and returns summary.json's error.
  std::string failed_run(const std::string& sets, const std::string& check,
                         std::size_t rows_before = 2) {
    const auto file = dir_ / "case.toml";
    std::ofstream(file) << test::dam_break_toml("continuity", 8, 0.1);
    const auto out = dir_ / "run";
    const auto r = flume("run " + file.string() + " --quiet --out " + out.string() +
                         " --set output.interval=0.001 --set output.snapshot_interval=0 " + sets);
    EXPECT_EQ(r.status, 1) << r.err;
    const auto summary = nlohmann::json::parse(slurp(out / "summary.json"));
    EXPECT_EQ(summary["status"], "failed");
    const std::string error = summary["error"].get<std::string>();
    for (const std::string& part : std::vector<std::string>{"check " + check + " failed", "step ",
                                                            "t = ", "particle ", ") m"})
      EXPECT_NE(error.find(part), std::string::npos) << part << " in: " << error;
    EXPECT_NE(r.err.find(error), std::string::npos) << r.err;
    // Nothing written before is lost; the failed state is the last (only) snapshot.
    EXPECT_GE(io::read_csv(out / "diagnostics.csv").rows.size(), rows_before);
    EXPECT_TRUE(fs::exists(out / "snapshots" / "snapshot_00000.vtu"));
    EXPECT_NE(slurp(out / "log.txt").find("failed state"), std::string::npos);
    return error;
  }
};

TEST_F(FailureChecks, AFixedStepFarAboveTheCflStepBlowsUp) {
  // 0.005 s is about 20 CFL steps: the density leaves the band within a few steps.
  const auto error = failed_run("--set case.dt=0.005", "density_band");
  EXPECT_NE(error.find("blew up"), std::string::npos) << error;
}

TEST_F(FailureChecks, ADensityBandTighterThanTheFlowNamesTheWorstParticle) {
  // The collapsing column compresses the water by more than 0.1 % within a few hundredths of a
  // second (c0 = 10 u_max: density changes of order (u/c0)^2 = 1 %).
  const auto error = failed_run("--set checks.density_band=[0.999,1.001]", "density_band");
  EXPECT_NE(error.find("outside [999"), std::string::npos) << error;
  EXPECT_NE(error.find("checks.density_band"), std::string::npos) << error;
}

TEST_F(FailureChecks, ACompressionAboveTheBandIsCaught) {
  // Only the band's upper side can trip here: the column's foot compresses by more than 0.1 %
  // while no density falls to half the starting one (the test above may trip on either side).
  const auto error = failed_run("--set checks.density_band=[0.5,1.001]", "density_band");
  const auto at = error.find("has density ");
  ASSERT_NE(at, std::string::npos) << error;
  EXPECT_GT(std::stod(error.substr(at + 12)), 1001.0) << error;
}

TEST_F(FailureChecks, AStepBelowTheFloorNamesTheFastestParticle) {
  // The CFL step shrinks as the water accelerates: a floor at 99.9 % of the first step trips.
  // It trips within the first steps: the row at t = 0 is what was written before.
  const auto error = failed_run("--set checks.min_dt_ratio=0.999", "time_step", 1);
  EXPECT_NE(error.find("checks.min_dt_ratio"), std::string::npos) << error;
  EXPECT_NE(error.find("largest acceleration"), std::string::npos) << error;
}

TEST_F(FailureChecks, AParticleFallingThroughAnOpenFloorIsLost) {
  // The floor open: the bottom row falls below y = 0 within about 0.03 s. With `standard` the
  // checks ride in the leap-frog's kick-and-drift pass (the schemes that evolve the density,
  // as the tests above, in the pass that advances it).
  const auto error =
      failed_run("--set boundaries.y_min=open --set scheme.preset=standard", "inside");
  EXPECT_NE(error.find("left the domain (particle lost)"), std::string::npos) << error;
}

// At the level of the simulation: a state restored with a NaN, or with densities outside the
// band, is refused by the same checks, naming the particle (the worst of the band's offenders:
// the largest factor outside it, here 3 against 1.5).
TEST(FailureCheckState, NonFiniteAndOutOfBandParticlesAreNamed) {
  const auto spec = test::spec_from(test::dam_break_toml("continuity", 8, 0.1));
  auto sim = build_simulation<2>(spec);
  const auto state = sim.state();
  auto ps = sim.particles();
  ps.v[5][0] = std::nan("");
  try {
    sim.restore(ps, state);
    FAIL() << "a NaN was accepted";
  } catch (const SimulationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("check finite failed"), std::string::npos) << what;
    EXPECT_NE(what.find(fmt::format("particle {} at (", ps.id[5])), std::string::npos) << what;
  }
  ps = sim.particles();
  const double lo = spec.density_band_lo, hi = spec.density_band_hi;  // 0.2, 5
  double rho_min = ps.rho[0], rho_max = ps.rho[0];
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    rho_min = std::min(rho_min, ps.rho[i]);
    rho_max = std::max(rho_max, ps.rho[i]);
  }
  ps.rho[3] = 1.5 * hi * rho_max;  // 1.5 times above the band
  ps.rho[9] = lo * rho_min / 3.0;  // 3 times below it: the worst
  try {
    sim.restore(ps, state);
    FAIL() << "densities outside the band were accepted";
  } catch (const SimulationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("check density_band failed"), std::string::npos) << what;
    EXPECT_NE(what.find(fmt::format("particle {} at (", ps.id[9])), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace flume
