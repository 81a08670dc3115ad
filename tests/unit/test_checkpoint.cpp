// The checkpoint file (run/checkpoint.hpp): every state field a scheme carries comes back bit
// for bit in 2D and 3D, a changed byte or a cut file is refused with a reason, and the
// directory's checkpoints are listed by step and pruned to the newest K.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "flume/run/checkpoint.hpp"

namespace flume {
namespace {

namespace fs = std::filesystem;

// A particle set with every optional state field in use (a gas under Runge-Kutta), filled
// with values that differ in every field and particle (and include -0 and a denormal).
template <int D>
Checkpoint<D> sample(std::size_t n) {
  Checkpoint<D> c;
  c.case_toml = "[case]\nname = \"sample\"\n";
  c.case_name = "sample";
  c.state = {0.125, 77, 1.5e-4, 2.5e-4, 1.25e-4};
  c.output = {9, 4, 8, 8, {0.0, 0.05, 0.1}, {0.25, 0.5}};
  auto& ps = c.particles;
  ps.optional = kFieldEnergy | kFieldStepStart;
  ps.resize(n);
  ps.n_real = n;
  double v = 0.1;
  ps.for_each_state_field([&](auto& f) {
    for (auto& e : f) {
      if constexpr (std::is_same_v<std::decay_t<decltype(e)>, std::int64_t>) {
        e = static_cast<std::int64_t>(v * 1000);
      } else if constexpr (std::is_same_v<std::decay_t<decltype(e)>, double>) {
        e = v;
      } else {
        for (int k = 0; k < D; ++k)
          e[k] = v + k;
      }
      v += 0.37;
    }
  });
  ps.x[0][0] = -0.0;
  ps.rho[1] = 4.9e-324;
  return c;
}

template <int D>
void expect_equal_bits(ParticleSet<D>& a, ParticleSet<D>& b) {
  ASSERT_EQ(a.n_real, b.n_real);
  ASSERT_EQ(a.optional, b.optional);
  std::vector<std::string> got;
  std::vector<std::pair<const void*, std::size_t>> fields;
  a.for_each_named_state_field([&](const char* name, const char*, auto& f) {
    got.emplace_back(name);
    fields.emplace_back(f.data(), f.size() * sizeof(f[0]));
  });
  std::size_t k = 0;
  b.for_each_named_state_field([&](const char* name, const char*, auto& f) {
    ASSERT_LT(k, got.size());
    EXPECT_EQ(got[k], name);
    ASSERT_EQ(fields[k].second, f.size() * sizeof(f[0])) << name;
    EXPECT_EQ(std::memcmp(fields[k].first, f.data(), fields[k].second), 0) << name;
    ++k;
  });
  EXPECT_EQ(k, got.size());
  // Every state field of a gas under Runge-Kutta: id x v m rho h v_half e and the five starts.
  EXPECT_EQ(got.size(), 13u);
}

class CheckpointFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flume_checkpoint_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

template <int D>
void round_trip(const fs::path& dir) {
  auto c = sample<D>(5);
  const auto file = checkpoint_path(dir, 77);
  write_checkpoint<D>(file, c);
  EXPECT_EQ(checkpoint_dimension(file), D);
  auto back = read_checkpoint<D>(file);
  EXPECT_EQ(back.case_toml, c.case_toml);
  EXPECT_EQ(back.case_name, "sample");
  EXPECT_EQ(std::memcmp(&back.state, &c.state, sizeof c.state), 0);
  EXPECT_EQ(back.output.next_output, 9);
  EXPECT_EQ(back.output.next_snapshot, 4);
  EXPECT_EQ(back.output.diagnostics_rows, 8);
  EXPECT_EQ(back.output.snapshot_times, c.output.snapshot_times);
  EXPECT_EQ(back.output.probe_state, c.output.probe_state);
  expect_equal_bits(c.particles, back.particles);
  EXPECT_THROW(read_checkpoint<5 - D>(file), CheckpointError);  // the other dimension
}

TEST_F(CheckpointFile, EveryStateFieldComesBackBitForBit) {
  round_trip<2>(dir_);
  round_trip<3>(dir_ / "3d");
}

TEST_F(CheckpointFile, AChangedValueFailsTheChecksum) {
  auto c = sample<2>(5);
  c.particles.rho[3] = 1234.5678;  // a value to find in the file
  const auto file = checkpoint_path(dir_, 1);
  write_checkpoint<2>(file, c);
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    bytes = ss.str();
  }
  const double value = 1234.5678;
  const auto at = bytes.find(std::string(reinterpret_cast<const char*>(&value), sizeof value));
  ASSERT_NE(at, std::string::npos);
  bytes[at] = static_cast<char>(bytes[at] ^ 1);  // the last bit of the mantissa
  std::ofstream(file, std::ios::binary) << bytes;
  try {
    read_checkpoint<2>(file);
    FAIL() << "a changed value was read";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
  }
}

TEST_F(CheckpointFile, ACutOrForeignFileIsRefused) {
  const auto file = checkpoint_path(dir_, 1);
  write_checkpoint<2>(file, sample<2>(50));
  fs::resize_file(file, fs::file_size(file) / 2);
  EXPECT_THROW(read_checkpoint<2>(file), CheckpointError);
  std::ofstream(file) << "not HDF5 at all\n";
  EXPECT_THROW(read_checkpoint<2>(file), CheckpointError);
  EXPECT_THROW(checkpoint_dimension(file), CheckpointError);
}

TEST_F(CheckpointFile, ListedByStepAndPrunedToTheNewest) {
  for (long step : {300L, 20L, 1000L, 40L})
    write_checkpoint<2>(checkpoint_path(dir_, step), sample<2>(2));
  std::ofstream(dir_ / "checkpoints" / "notes.txt") << "not a checkpoint";
  auto all = list_checkpoints(dir_);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all.front().filename(), "checkpoint_0000000020.h5");
  EXPECT_EQ(all.back().filename(), "checkpoint_0000001000.h5");
  prune_checkpoints(dir_, 2);
  all = list_checkpoints(dir_);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all.front().filename(), "checkpoint_0000000300.h5");
  EXPECT_TRUE(fs::exists(dir_ / "checkpoints" / "notes.txt"));
  // No temporary file left by the atomic writes.
  for (const auto& e : fs::directory_iterator(dir_ / "checkpoints"))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos);
}

}  // namespace
}  // namespace flume
