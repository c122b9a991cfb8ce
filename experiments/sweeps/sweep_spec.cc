#include "experiments/sweeps/sweep_spec.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "core/error.h"

namespace vigil::experiments {
namespace fs = std::filesystem;
namespace {

int LineOf(const YAML::Node& n) { return n.Mark().line >= 0 ? n.Mark().line + 1 : 0; }

[[noreturn]] void Fail(const std::string& path, const YAML::Node& n, const std::string& key,
                       const std::string& why) {
  throw InputError(Located(path, LineOf(n), key + ": " + why));
}

// A mapping key as text; a key that is not a plain scalar (a `? [a, b]` or `? {a: b}` complex key) is an
// error naming its line, not a yaml-cpp conversion failure.
std::string KeyText(const std::string& path, const YAML::Node& key, const std::string& where) {
  if (!key.IsScalar()) Fail(path, key, where, "a key must be a plain name, not a sequence or mapping");
  return key.Scalar();
}

// Labels and names become parts of run ids (joined by '-') and of file names.
bool IsLabel(const std::string& s) {
  if (s.empty()) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
  });
}

// Run ids name directories (plus a staging suffix of up to ~80 characters, core/staging.h): NAME_MAX is 255.
constexpr std::size_t kMaxLabelLength = 64;
constexpr std::size_t kMaxRunIdLength = 160;

void CheckLabelLength(const std::string& path, const YAML::Node& n, const std::string& key,
                      const std::string& label) {
  if (label.size() > kMaxLabelLength)
    Fail(path, n, key,
         "label of " + std::to_string(label.size()) + " characters (at most " +
             std::to_string(kMaxLabelLength) + ": labels become parts of run ids and directory names)");
}

std::string Sanitize(const std::string& s) {
  std::string out = s;
  for (char& c : out)
    if (!IsLabel(std::string(1, c))) c = '_';
  return out;
}

// "0.5" for a scalar, "ax_az" for a sequence of scalars.
std::string ValueLabel(const YAML::Node& v) {
  if (v.IsScalar()) return Sanitize(v.Scalar());
  if (v.IsSequence()) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "_" : "") + ValueLabel(v[i]);
    return s.empty() ? "empty" : s;
  }
  return "value";
}

std::string LastComponent(const std::string& key) {
  const auto dot = key.rfind('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

// Flattens a mapping of (possibly dotted) keys to values into overrides below `prefix`.
void CollectOverrides(const std::string& path, const YAML::Node& map, const std::string& prefix,
                      const std::string& what, std::vector<SweepOverride>* out) {
  if (!map.IsMap()) Fail(path, map, what, "expected a mapping of config keys to values");
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string key = KeyText(path, it->first, what);
    if (key.empty()) Fail(path, it->first, what, "empty key");
    out->push_back({prefix.empty() ? key : prefix + "." + key, it->second, LineOf(it->first)});
  }
}

// Applies one override with the run configuration's schema; errors name the sweep file line.
void Apply(const std::string& path, const SweepOverride& o, RunConfig* config) {
  config::Reader reader(config::NestKey(o.key, o.value), path + ":" + std::to_string(o.line),
                        /*has_lines=*/false);
  config->Visit(reader);
  reader.RejectUnknownKeys();
}

std::vector<uint64_t> ParseSeeds(const std::string& path, const YAML::Node& n) {
  std::vector<uint64_t> seeds;
  std::string why;
  if (n.IsSequence()) {
    if (!config::Decode(n, &seeds, &why)) Fail(path, n, "seeds", why);
  } else if (n.IsMap()) {
    uint64_t count = 0, first = 1;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const std::string key = KeyText(path, it->first, "seeds");
      uint64_t* field = key == "count" ? &count : key == "first" ? &first : nullptr;
      if (!field) Fail(path, it->first, "seeds." + key, "unknown key (expected count, first)");
      if (!config::Decode(it->second, field, &why)) Fail(path, it->second, "seeds." + key, why);
    }
    if (count > kMaxSweepSeeds)
      Fail(path, n, "seeds.count", "must be at most " + std::to_string(kMaxSweepSeeds));
    if (count > 0 && first > UINT64_MAX - (count - 1))
      Fail(path, n, "seeds.first", "first + count - 1 must be at most 2^64 - 1");
    for (uint64_t i = 0; i < count; ++i) seeds.push_back(first + i);
  } else {
    Fail(path, n, "seeds", "expected a list of seeds or {count: N, first: S}");
  }
  if (seeds.empty()) Fail(path, n, "seeds", "at least one seed is needed");
  if (seeds.size() > kMaxSweepSeeds)
    Fail(path, n, "seeds", "at most " + std::to_string(kMaxSweepSeeds) + " seeds");
  std::set<uint64_t> unique(seeds.begin(), seeds.end());
  if (unique.size() != seeds.size()) Fail(path, n, "seeds", "seeds must be distinct");
  return seeds;
}

SweepAxis ParseAxis(const std::string& path, const YAML::Node& key_node, const YAML::Node& n) {
  SweepAxis axis;
  axis.key = KeyText(path, key_node, "axes");
  const std::string where = "axes." + axis.key;
  if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i) {
      SweepSetting s;
      s.label = LastComponent(axis.key) + "_" + ValueLabel(n[i]);
      CheckLabelLength(path, n[i], where, s.label);
      s.overrides.push_back({axis.key, n[i], LineOf(n[i])});
      axis.settings.push_back(std::move(s));
    }
  } else if (n.IsMap()) {
    axis.named = true;
    for (auto it = n.begin(); it != n.end(); ++it) {
      SweepSetting s;
      s.label = KeyText(path, it->first, where);
      if (!IsLabel(s.label))
        Fail(path, it->first, where + "." + s.label,
             "setting names may use only letters, digits, '_' and '.'");
      CheckLabelLength(path, it->first, where + "." + s.label, s.label);
      CollectOverrides(path, it->second, axis.key, where + "." + s.label, &s.overrides);
      axis.settings.push_back(std::move(s));
    }
  } else {
    Fail(path, n, where, "expected a list of values or a mapping of named settings");
  }
  if (axis.settings.empty()) Fail(path, n, where, "an axis needs at least one setting");
  std::set<std::string> labels;
  for (const auto& s : axis.settings)
    if (!labels.insert(s.label).second)
      Fail(path, n, where, "two settings have the label '" + s.label + "' (use named settings)");
  return axis;
}

std::vector<SweepSetting> ParseMethods(const std::string& path, const YAML::Node& n) {
  if (!n.IsMap() || n.size() == 0) Fail(path, n, "methods", "expected a mapping: name -> detector settings");
  std::vector<SweepSetting> methods;
  for (auto it = n.begin(); it != n.end(); ++it) {
    SweepSetting m;
    m.label = KeyText(path, it->first, "methods");
    const std::string where = "methods." + m.label;
    if (!IsLabel(m.label))
      Fail(path, it->first, where, "method names may use only letters, digits, '_' and '.'");
    CheckLabelLength(path, it->first, where, m.label);
    if (it->second.IsScalar()) {
      m.overrides.push_back({"detector.type", it->second, LineOf(it->second)});
    } else {
      CollectOverrides(path, it->second, "detector", where, &m.overrides);
      // Keys under `estimator.` set the estimator (in-estimator mitigation per method).
      for (SweepOverride& o : m.overrides)
        if (o.key.rfind("detector.estimator.", 0) == 0) o.key = o.key.substr(std::string("detector.").size());
    }
    methods.push_back(std::move(m));
  }
  return methods;
}

}  // namespace

std::size_t SweepSpec::cell_count() const {
  std::size_t n = methods.size();
  for (const auto& a : axes) n *= a.settings.size();
  return n;
}

SweepSpec LoadSweepSpec(const std::string& path) {
  const YAML::Node root = config::LoadYamlFile(path);
  if (!root.IsMap()) Fail(path, root, "(top level)", "expected a mapping of keys");
  SweepSpec spec;
  spec.path = path;
  YAML::Node base_node, methods_node, seeds_node, table_methods_node, template_seed_node, axes_node;
  for (const auto& kv : root) {
    const std::string key = KeyText(path, kv.first, "(top level)");
    const YAML::Node v = kv.second;
    std::string why;
    if (key == "base") {
      base_node.reset(v);
    } else if (key == "set") {
      if (!v.IsNull()) CollectOverrides(path, v, "", "set", &spec.set);
    } else if (key == "axes") {
      if (v.IsNull()) continue;
      axes_node.reset(v);
      if (!v.IsMap()) Fail(path, v, "axes", "expected a mapping: config key -> values or named settings");
      for (auto a = v.begin(); a != v.end(); ++a) spec.axes.push_back(ParseAxis(path, a->first, a->second));
    } else if (key == "methods") {
      methods_node.reset(v);
    } else if (key == "seeds") {
      seeds_node.reset(v);
    } else if (key == "template_seed") {
      template_seed_node.reset(v);
      if (!config::Decode(v, &spec.template_seed, &why)) Fail(path, v, key, why);
    } else if (key == "write_trajectories") {
      if (!config::Decode(v, &spec.write_trajectories, &why)) Fail(path, v, key, why);
    } else if (key == "write_figure_data") {
      if (!config::Decode(v, &spec.write_figure_data, &why)) Fail(path, v, key, why);
    } else if (key == "table_methods") {
      table_methods_node.reset(v);
    } else {
      Fail(path, kv.first, key, "unknown key");
    }
  }
  if (!base_node.IsScalar())
    Fail(path, base_node.IsNull() ? root : base_node, "base",
         "the base run configuration (a path) is required");
  if (methods_node.IsNull()) Fail(path, root, "methods", "required (name -> detector settings)");
  if (seeds_node.IsNull()) Fail(path, root, "seeds", "required (a list, or {count: N, first: S})");
  spec.methods = ParseMethods(path, methods_node);
  spec.seeds = ParseSeeds(path, seeds_node);
  if (std::find(spec.seeds.begin(), spec.seeds.end(), spec.template_seed) != spec.seeds.end())
    Fail(path, template_seed_node.IsNull() ? seeds_node : template_seed_node, "template_seed",
         "must differ from every run seed (templates come from data the runs never see)");

  fs::path base = base_node.as<std::string>();
  if (base.is_relative()) base = fs::path(path).parent_path() / base;
  std::error_code ec;
  spec.base = fs::absolute(base, ec).lexically_normal();
  if (!fs::is_regular_file(spec.base, ec))
    Fail(path, base_node, "base", spec.base.string() + ": no such file");

  if (!table_methods_node.IsNull()) {
    std::string why;
    if (!config::Decode(table_methods_node, &spec.table_methods, &why))
      Fail(path, table_methods_node, "table_methods", why);
    for (const auto& name : spec.table_methods)
      if (std::none_of(spec.methods.begin(), spec.methods.end(),
                       [&](const auto& m) { return m.label == name; }))
        Fail(path, table_methods_node, "table_methods", "'" + name + "' is not one of the methods");
  }
  if (spec.table_methods.empty())
    for (const auto& m : spec.methods) spec.table_methods.push_back(m.label);

  uint64_t runs = spec.seeds.size() * spec.methods.size();
  for (const auto& a : spec.axes) {
    if (runs > kMaxSweepRuns) break;
    runs *= std::max<std::size_t>(a.settings.size(), 1);
  }
  if (runs > kMaxSweepRuns)
    Fail(path, seeds_node, "seeds",
         "the grid has more than " + std::to_string(kMaxSweepRuns) +
             " runs (axes x methods x seeds); split the sweep");

  std::set<std::string> axis_keys;
  for (const auto& a : spec.axes)
    if (!axis_keys.insert(a.key).second) Fail(path, axes_node, "axes." + a.key, "duplicate axis");

  // The longest run id: the longest label of every axis and method, and the longest seed.
  std::size_t longest_id = 0;
  for (const auto& a : spec.axes) {
    std::size_t longest = 0;
    for (const auto& st : a.settings) longest = std::max(longest, st.label.size());
    longest_id += longest + 1;
  }
  std::size_t longest_method = 0;
  for (const auto& m : spec.methods) longest_method = std::max(longest_method, m.label.size());
  const uint64_t largest_seed = *std::max_element(spec.seeds.begin(), spec.seeds.end());
  longest_id += longest_method + 1 + std::max<std::size_t>(4, 1 + std::to_string(largest_seed).size());
  if (longest_id > kMaxRunIdLength)
    Fail(path, root, "(run ids)",
         "the longest run id would have " + std::to_string(longest_id) + " characters (at most " +
             std::to_string(kMaxRunIdLength) + "): shorten the setting or method names");

  // Type-check every override once against the schema (cells re-apply them, in order).
  RunConfig check = LoadRunConfig(spec.base.string());
  for (const auto& o : spec.set) Apply(path, o, &check);
  for (const auto& a : spec.axes)
    for (const auto& s : a.settings)
      for (const auto& o : s.overrides) Apply(path, o, &check);
  for (const auto& m : spec.methods)
    for (const auto& o : m.overrides) Apply(path, o, &check);
  return spec;
}

void SetSeedCount(SweepSpec* spec, uint64_t count) {
  if (count == 0) throw InputError("--seeds: must be at least 1");
  if (count > kMaxSweepSeeds) throw InputError("--seeds: must be at most " + std::to_string(kMaxSweepSeeds));
  const uint64_t first = spec->seeds.front();
  if (first > UINT64_MAX - (count - 1))
    throw InputError("--seeds " + std::to_string(count) + ": the last seed would exceed 2^64 - 1");
  if (spec->template_seed >= first && spec->template_seed - first < count)
    throw InputError("--seeds " + std::to_string(count) + ": seeds " + std::to_string(first) + ".." +
                     std::to_string(first + count - 1) + " would include the template seed " +
                     std::to_string(spec->template_seed) + " (" + spec->path + ": template_seed)");
  spec->seeds.clear();
  for (uint64_t i = 0; i < count; ++i) spec->seeds.push_back(first + i);
}

std::string ResolvedSweepYaml(const SweepSpec& spec) {
  auto strip = [](const std::string& key, const std::string& prefix) {
    return key.compare(0, prefix.size() + 1, prefix + ".") == 0 ? key.substr(prefix.size() + 1) : key;
  };
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "base" << YAML::Value << spec.base.string();
  out << YAML::Key << "set" << YAML::Value << YAML::BeginMap;
  for (const auto& o : spec.set) out << YAML::Key << o.key << YAML::Value << o.value;
  out << YAML::EndMap;
  out << YAML::Key << "axes" << YAML::Value << YAML::BeginMap;
  for (const auto& a : spec.axes) {
    out << YAML::Key << a.key << YAML::Value;
    if (a.named) {
      out << YAML::BeginMap;
      for (const auto& s : a.settings) {
        out << YAML::Key << s.label << YAML::Value << YAML::Flow << YAML::BeginMap;
        for (const auto& o : s.overrides) out << YAML::Key << strip(o.key, a.key) << YAML::Value << o.value;
        out << YAML::EndMap;
      }
      out << YAML::EndMap;
    } else {
      out << YAML::Flow << YAML::BeginSeq;
      for (const auto& s : a.settings) out << s.overrides.front().value;
      out << YAML::EndSeq;
    }
  }
  out << YAML::EndMap;
  out << YAML::Key << "methods" << YAML::Value << YAML::BeginMap;
  for (const auto& m : spec.methods) {
    out << YAML::Key << m.label << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& o : m.overrides) out << YAML::Key << strip(o.key, "detector") << YAML::Value << o.value;
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  out << YAML::Key << "seeds" << YAML::Value << YAML::Flow << spec.seeds;
  out << YAML::Key << "template_seed" << YAML::Value << spec.template_seed;
  out << YAML::Key << "write_trajectories" << YAML::Value << spec.write_trajectories;
  // Only when off: a sweep directory started before the key existed resumes (its sweep.yaml is unchanged).
  if (!spec.write_figure_data) out << YAML::Key << "write_figure_data" << YAML::Value << false;
  out << YAML::Key << "table_methods" << YAML::Value << YAML::Flow << spec.table_methods;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::vector<SweepCell> EnumerateCells(const SweepSpec& spec) {
  std::vector<SweepCell> cells;
  SweepCell cell;
  cell.setting.assign(spec.axes.size(), 0);
  while (true) {
    for (int m = 0; m < static_cast<int>(spec.methods.size()); ++m) {
      cell.method = m;
      cells.push_back(cell);
    }
    // Odometer increment, the last axis fastest.
    int a = static_cast<int>(spec.axes.size()) - 1;
    for (; a >= 0; --a) {
      if (++cell.setting[a] < static_cast<int>(spec.axes[a].settings.size())) break;
      cell.setting[a] = 0;
    }
    if (a < 0) break;
  }
  return cells;
}

std::string CellGroupLabel(const SweepSpec& spec, const SweepCell& cell) {
  std::string label;
  for (std::size_t a = 0; a < spec.axes.size(); ++a)
    label += (a ? "-" : "") + spec.axes[a].settings[cell.setting[a]].label;
  return label.empty() ? "all" : label;
}

std::string RunId(const SweepSpec& spec, const SweepCell& cell, uint64_t seed) {
  char s[32];
  std::snprintf(s, sizeof s, "s%03llu", static_cast<unsigned long long>(seed));
  std::string id;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) id += spec.axes[a].settings[cell.setting[a]].label + "-";
  return id + spec.methods[cell.method].label + "-" + s;
}

namespace {

// The overrides that make a cell's configuration, in the order they apply: set, axes, method.
std::vector<const SweepOverride*> CellOverrides(const SweepSpec& spec, const SweepCell& cell) {
  std::vector<const SweepOverride*> applied;
  for (const auto& o : spec.set) applied.push_back(&o);
  for (std::size_t a = 0; a < spec.axes.size(); ++a)
    for (const auto& o : spec.axes[a].settings[cell.setting[a]].overrides) applied.push_back(&o);
  for (const auto& o : spec.methods[cell.method].overrides) applied.push_back(&o);
  return applied;
}

std::string CellOrigin(const SweepSpec& spec, const SweepCell& cell) {
  return spec.path + " (cell " + CellGroupLabel(spec, cell) + "-" + spec.methods[cell.method].label + ")";
}

}  // namespace

void ThrowCellError(const SweepSpec& spec, const SweepCell& cell, const std::string& message) {
  // Name the sweep-file line that set a key the error is about (the last one applied), else the base's.
  const std::string origin = CellOrigin(spec, cell), in_cell = origin.substr(spec.path.size());
  std::string rest;
  const std::vector<std::string> keys = KeysOfConfigError(origin + ": " + message, origin, &rest);
  const std::vector<const SweepOverride*> applied = CellOverrides(spec, cell);
  for (const std::string& key : keys)
    for (auto o = applied.rbegin(); o != applied.rend(); ++o)
      if (key == (*o)->key || key.rfind((*o)->key + ".", 0) == 0)  // the key, or a section holding it
        throw InputError(Located(spec.path, (*o)->line, rest + in_cell));
  const YAML::Node base = config::LoadYamlFile(spec.base.string());
  for (const std::string& key : keys)
    if (const int line = config::KeyLine(base, key); line > 0)
      throw InputError(Located(spec.base.string(), line, rest + in_cell));
  throw InputError(origin + ": " + message);
}

RunConfig ResolveCellConfig(const SweepSpec& spec, const SweepCell& cell) {
  RunConfig config = LoadRunConfig(spec.base.string());
  for (const SweepOverride* o : CellOverrides(spec, cell)) Apply(spec.path, *o, &config);
  ResolveRelativePaths(fs::path(spec.path).parent_path(), &config);
  try {
    sim::ResolveDurationToEnd(&config.sim);  // "duration_s: 0 runs to the end of ...": the cell's line
  } catch (const InputError& e) {
    ThrowCellError(spec, cell, e.what());
  }
  const std::string origin = CellOrigin(spec, cell);
  try {
    ValidateRunConfig(config, origin);
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.compare(0, origin.size() + 2, origin + ": ") != 0) throw;
    ThrowCellError(spec, cell, message.substr(origin.size() + 2));
  }
  return config;
}

std::vector<SweepRunRef> EnumerateRuns(const SweepSpec& spec, const std::vector<SweepCell>& cells) {
  std::vector<SweepRunRef> runs;
  runs.reserve(cells.size() * spec.seeds.size());
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (uint64_t seed : spec.seeds) runs.push_back({runs.size(), c, seed, RunId(spec, cells[c], seed)});
  return runs;
}

std::vector<double> SweepDistances(const SweepSpec& spec) {
  return ResolveCellConfig(spec, EnumerateCells(spec).front()).evaluation.distances_m;
}

}  // namespace vigil::experiments
