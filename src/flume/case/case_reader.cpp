#include "flume/case/case_reader.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "flume/case/case_checks.hpp"
#include "flume/core/error.hpp"
#include "flume/kernels/kernel.hpp"
#include "flume/schemes/registry.hpp"

namespace flume {

const std::string& fluid_block_defaults(int dimension);
const std::string& curve_defaults();
const std::string& profile_defaults();
const std::string& moving_wall_defaults();
const std::string& repulsive_wall_defaults();

namespace {

// Arrays of tables are not in the defaults table itself; each element has its own defaults.
constexpr const char* kTableArrays[] = {"fluid_blocks", "moving_walls", "repulsive_walls",
                                        "validation.curves", "validation.profiles"};

bool is_table_array_key(const std::string& path) {
  return std::find(std::begin(kTableArrays), std::end(kTableArrays), path) !=
         std::end(kTableArrays);
}

const std::string& element_defaults(const std::string& path, int dim) {
  if (path == "fluid_blocks") return fluid_block_defaults(dim);
  if (path == "moving_walls") return moving_wall_defaults();
  if (path == "repulsive_walls") return repulsive_wall_defaults();
  if (path == "validation.profiles") return profile_defaults();
  return curve_defaults();
}

toml::table parse_defaults(const std::string& text) {
  return toml::parse(text);
}

// Splits "a.b[2].c" or "a.b.2.c" into segments; numeric segments index arrays.
std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> out;
  std::string cur;
  for (char ch : path) {
    if (ch == '.' || ch == '[' || ch == ']') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += ch;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

bool is_index(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The value text of --set KEY=VALUE as a TOML value; bare words are strings, so
// `--set scheme.preset=standard` works without quotes.
toml::table parse_override_value(const std::string& value) {
  try {
    return toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    toml::table t;
    t.insert("v", value);
    return t;
  }
}

class Checker {
 public:
  Checker(std::string file, int dimension) : file_(std::move(file)), dim_(dimension) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(fmt::format("{}: {}: {}", file_, key, what));
  }

  // Checks that every key of `user` exists in `defaults` with a compatible type; recurses into
  // sub-tables and into the arrays of tables.
  void check_known(const toml::table& user, const toml::table& defaults,
                   const std::string& prefix) const {
    for (const auto& [k, node] : user) {
      const std::string key =
          prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
      if (is_table_array_key(key)) {
        const auto* arr = node.as_array();
        if (!arr || !arr->is_array_of_tables())
          fail(key, "must be an array of tables ([[" + key + "]])");
        const toml::table elem_defaults = parse_defaults(element_defaults(key, dim_));
        for (std::size_t i = 0; i < arr->size(); ++i)
          check_known(*arr->get(i)->as_table(), elem_defaults, fmt::format("{}[{}]", key, i));
        continue;
      }
      const toml::node* def = defaults.get(k.str());
      if (!def)
        fail(key, fmt::format("unknown key (known here: {})", known_keys(defaults, prefix)));
      check_type(key, node, *def);
      if (def->is_table()) check_known(*node.as_table(), *def->as_table(), key);
    }
  }

  void check_type(const std::string& key, const toml::node& value, const toml::node& def) const {
    if (def.is_table()) {
      if (!value.is_table()) fail(key, "must be a table");
      return;
    }
    if (def.is_floating_point()) {
      if (!value.is_number()) fail(key, "must be a number");
      return;
    }
    if (def.is_integer()) {
      if (!value.is_integer()) fail(key, "must be an integer");
      return;
    }
    if (def.is_boolean()) {
      if (!value.is_boolean()) fail(key, "must be true or false");
      return;
    }
    if (def.is_string()) {
      if (!value.is_string()) fail(key, "must be a string");
      return;
    }
    if (def.is_array()) {
      const auto* arr = value.as_array();
      if (!arr) fail(key, "must be an array");
      const auto* darr = def.as_array();
      const bool numeric = !darr->empty() && darr->get(0)->is_number();
      if (numeric) {
        // A default of D x D numbers is a matrix (row-major), of D a vector.
        const std::size_t want = darr->size() == static_cast<std::size_t>(dim_ * dim_) && dim_ > 1
                                     ? static_cast<std::size_t>(dim_ * dim_)
                                     : static_cast<std::size_t>(dim_);
        if (arr->size() != want || !all_numbers(*arr))
          fail(key, want == static_cast<std::size_t>(dim_)
                        ? fmt::format("must be an array of {} numbers (one per dimension)", dim_)
                        : fmt::format("must be an array of {} numbers (a {} x {} matrix, "
                                      "row-major)",
                                      want, dim_, dim_));
      } else if (!darr->empty() && !all_strings(*arr)) {
        fail(key, "must be an array of strings");
      } else if (darr->empty() && !all_strings(*arr) && !all_numbers(*arr)) {
        // An empty default holds either kind; build_spec says which the key wants.
        fail(key, "must be an array of numbers or of strings");
      }
    }
  }

  static bool all_numbers(const toml::array& a) {
    for (const auto& n : a)
      if (!n.is_number()) return false;
    return true;
  }
  static bool all_strings(const toml::array& a) {
    for (const auto& n : a)
      if (!n.is_string()) return false;
    return true;
  }

  static std::string known_keys(const toml::table& defaults, const std::string& prefix) {
    std::vector<std::string> keys;
    for (const auto& [k, v] : defaults)
      keys.emplace_back(k.str());
    if (prefix.empty())
      keys.insert(keys.end(), {"fluid_blocks", "moving_walls", "repulsive_walls"});
    if (prefix == "validation") keys.insert(keys.end(), {"curves", "profiles"});
    return fmt::format("{}", fmt::join(keys, ", "));
  }

 private:
  std::string file_;
  int dim_;
};

// Copies every value of `user` over `out` (recursively for tables).
void merge_into(toml::table& out, const toml::table& user) {
  for (const auto& [k, node] : user) {
    if (node.is_table() && out.get(k.str()) && out.get(k.str())->is_table()) {
      merge_into(*out.get(k.str())->as_table(), *node.as_table());
    } else {
      out.insert_or_assign(k, node);
    }
  }
}

// Applies one --set KEY=VALUE to the user's table; the key must exist in the schema.
void apply_override(toml::table& user, const toml::table& defaults, const std::string& item,
                    const std::string& file, int dim) {
  const auto eq = item.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(fmt::format("{}: --set '{}': expected KEY=VALUE, e.g. particles.spacing=0.001",
                                 file, item));
  const std::string key = item.substr(0, eq);
  const toml::table parsed = parse_override_value(item.substr(eq + 1));
  const toml::node& value = *parsed.get("v");
  const auto segs = split_path(key);

  toml::table* tbl = &user;
  const toml::table* def = &defaults;
  toml::table elem_defaults;  // an array-of-tables element's schema, once the path enters one
  std::string walked;
  for (std::size_t s = 0; s + 1 < segs.size(); ++s) {
    walked += (walked.empty() ? "" : ".") + segs[s];
    if (is_table_array_key(walked)) {
      auto* arr = tbl->get(segs[s]) ? tbl->get(segs[s])->as_array() : nullptr;
      if (s + 2 >= segs.size() || !is_index(segs[s + 1]) || !arr ||
          std::stoul(segs[s + 1]) >= arr->size())
        throw InputError(
            fmt::format("{}: --set {}: unknown key (index an existing [[{}]] entry, "
                        "e.g. {}[0].KEY)",
                        file, key, walked, walked));
      tbl = arr->get(std::stoul(segs[s + 1]))->as_table();
      elem_defaults = parse_defaults(element_defaults(walked, dim));
      def = &elem_defaults;
      ++s;
      continue;
    }
    const toml::node* dnode = def->get(segs[s]);
    if (!dnode || !dnode->is_table())
      throw InputError(fmt::format("{}: --set {}: unknown key", file, key));
    def = dnode->as_table();
    if (!tbl->get(segs[s])) tbl->insert(segs[s], toml::table{});
    tbl = tbl->get(segs[s])->as_table();
    if (!tbl) throw InputError(fmt::format("{}: --set {}: '{}' is not a table", file, key, walked));
  }
  if (segs.empty() || !def->get(segs.back()) || def->get(segs.back())->is_table())
    throw InputError(fmt::format("{}: --set {}: unknown key", file, key));
  tbl->insert_or_assign(segs.back(), value);
}

}  // namespace

CaseSpec read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw InputError(
        fmt::format("{}: is a directory; give a case file (.toml): flume cases lists the bundled "
                    "ones",
                    file.string()));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the case file", file.string()));
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  // A NUL byte never occurs in a TOML file (toml++ would report a confusing syntax error).
  if (text.find('\0') != std::string::npos)
    throw InputError(
        fmt::format("{}: is a binary file, not a case file (TOML text)", file.string()));
  return read_case_string(text, file, overrides);
}

CaseSpec read_case_string(const std::string& text, const std::filesystem::path& file,
                          const std::vector<std::string>& overrides) {
  const std::string fname = file.string();
  toml::table user;
  try {
    user = toml::parse(text, fname);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", fname, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }

  // The dimension decides the shape of the defaults; an override may change it.
  int dim = 2;
  if (auto d = user["case"]["dimension"].value<int64_t>()) dim = static_cast<int>(*d);
  for (const auto& o : overrides)
    if (o.rfind("case.dimension=", 0) == 0) dim = std::atoi(o.c_str() + 15);
  if (dim != 2 && dim != 3)
    throw InputError(fmt::format("{}: case.dimension = {}: must be 2 or 3", fname, dim));

  const toml::table defaults = parse_defaults(case_defaults_toml(dim));
  for (const auto& o : overrides)
    apply_override(user, defaults, o, fname, dim);

  Checker checker(fname, dim);
  checker.check_known(user, defaults, "");

  toml::table resolved = defaults;
  merge_into(resolved, user);
  // Each array-of-tables element gets its own defaults.
  for (const char* key : kTableArrays) {
    toml::array* arr = resolved.at_path(key).as_array();
    if (!arr) continue;
    const toml::table elem_defaults = parse_defaults(element_defaults(key, dim));
    toml::array filled;
    for (const auto& node : *arr) {
      toml::table full = elem_defaults;
      merge_into(full, *node.as_table());
      filled.push_back(std::move(full));
    }
    *arr = std::move(filled);
  }

  CaseSpec spec = build_spec(resolved, file, dim);
  std::ostringstream os;
  os << "# flume: fully resolved case (every default written out); run it again with\n"
     << "# `flume run case.toml` to repeat this run exactly.\n"
     << spec_to_table(spec, resolved) << "\n";
  spec.resolved_toml = os.str();
  return spec;
}

}  // namespace flume
