// Every bundled case file reads as flume validate reads it: as written, with its quick
// overrides, with each variant's overrides on top of the case (and of the quick set when
// validate --quick runs the variants: quick_variants), and with each companion's on top
// of every configuration (a variant whose key or value is
// wrong would otherwise surface only when the full validation reaches it, an hour in).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "flume/case/case_reader.hpp"
#include "flume/validation/bundled_cases.hpp"
#include "flume/validation/variant.hpp"

namespace flume {
namespace {

TEST(BundledCases, EveryCaseQuickSetAndVariantReads) {
  const auto files = bundled_case_files();
  ASSERT_GE(files.size(), 20u);  // the cases/ folder was found
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    CaseSpec spec;
    ASSERT_NO_THROW(spec = read_case(file, {}));
    ASSERT_NO_THROW(read_case(file, spec.quick));
    std::set<std::string> labels{spec.preset};
    for (const auto& text : spec.variants) {
      const Variant v = parse_variant(text);
      EXPECT_TRUE(labels.insert(v.label).second) << "variant label repeated: " << v.label;
      EXPECT_NO_THROW(read_case(file, v.overrides)) << text;
      if (!spec.quick_variants) continue;  // validate --quick runs the case alone
      auto quick = spec.quick;
      quick.insert(quick.end(), v.overrides.begin(), v.overrides.end());
      EXPECT_NO_THROW(read_case(file, quick)) << text;
    }
    // Each companion on top of the case, its quick set and every variant (validate runs each
    // configuration's companions).
    for (const auto& text : spec.companions) {
      const Variant c = parse_variant(text);
      std::vector<std::vector<std::string>> configs{{}, spec.quick};
      for (const auto& v : spec.variants) {
        const auto overrides = parse_variant(v).overrides;
        configs.push_back(overrides);
        if (!spec.quick_variants) continue;
        configs.push_back(spec.quick);
        configs.back().insert(configs.back().end(), overrides.begin(), overrides.end());
      }
      for (auto sets : configs) {
        sets.insert(sets.end(), c.overrides.begin(), c.overrides.end());
        EXPECT_NO_THROW(read_case(file, sets)) << text;
      }
    }
  }
}

}  // namespace
}  // namespace flume
