#include "detectors/template_library.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <yaml-cpp/yaml.h>

#include "core/config.h"
#include "core/error.h"
#include "core/format.h"
#include "detectors/dtw_distance.h"
#include "detectors/dtw_matcher.h"
#include "detectors/slice_features.h"

namespace vigil::detectors {
namespace {

constexpr const char* kFormat = "vigil-dtw-templates-1";
constexpr double kInf = std::numeric_limits<double>::infinity();

void CheckGeometry(int k, int n, int m, int dims, const std::string& where) {
  if (dims != 3 && dims != 6)
    throw InputError(where + "dims: must be 3 (acc) or 6 (acc + gyro), got " + std::to_string(dims));
  if (k < 1) throw InputError(where + "templates: must be >= 1");
  if (m < 2) throw InputError(where + "slice_length: must be >= 2");
  if (n < 1 || n > m)
    throw InputError(where + "template_length: must be in [1, slice_length = " + std::to_string(m) +
                     "], got " + std::to_string(n));
}

// Normalized slices (m x d each, concatenated) of the complete slices `indices` of `stream`.
std::vector<double> NormalizedSlices(const ImuStream& stream, const std::vector<int>& indices, int m,
                                     int dims, SliceNormalization normalization) {
  std::vector<double> out(indices.size() * m * dims);
  SliceBaseline baseline;
  std::vector<double> scratch;
  for (std::size_t s = 0; s < indices.size(); ++s)
    NormalizeSlice(stream.data() + static_cast<std::size_t>(indices[s]) * m, m, dims, normalization,
                   out.data() + s * m * dims, &baseline, &scratch);
  return out;
}

// Nearest-rank quantile of `values` (non-empty), q in [0, 1].
double Quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  const auto n = static_cast<double>(values.size());
  const int rank = std::clamp(static_cast<int>(std::ceil(q * n)) - 1, 0, static_cast<int>(values.size()) - 1);
  return values[rank];
}

// k-medoids on a cost matrix cost[c * S + s] (candidate c as template, slice s): greedy start then PAM swaps.
std::vector<int> KMedoids(const std::vector<double>& cost, int candidates, int slices, int k,
                          int swap_passes) {
  auto at = [&](int c, int s) { return cost[static_cast<std::size_t>(c) * slices + s]; };
  std::vector<int> medoids;
  std::vector<char> chosen(candidates, 0);
  std::vector<double> nearest(slices, kInf);
  for (int step = 0; step < k; ++step) {
    int best_c = -1;
    double best_total = kInf;
    for (int c = 0; c < candidates; ++c) {
      if (chosen[c]) continue;
      double total = 0.0;
      for (int s = 0; s < slices; ++s) total += std::min(nearest[s], at(c, s));
      if (total < best_total) best_total = total, best_c = c;
    }
    medoids.push_back(best_c);
    chosen[best_c] = 1;
    for (int s = 0; s < slices; ++s) nearest[s] = std::min(nearest[s], at(best_c, s));
  }
  for (int pass = 0; pass < swap_passes; ++pass) {
    // Nearest and second-nearest medoid cost per slice.
    std::vector<double> d1(slices, kInf), d2(slices, kInf);
    std::vector<int> owner(slices, -1);
    for (int s = 0; s < slices; ++s) {
      for (int i = 0; i < k; ++i) {
        const double d = at(medoids[i], s);
        if (d < d1[s]) {
          d2[s] = d1[s], d1[s] = d, owner[s] = i;
        } else if (d < d2[s]) {
          d2[s] = d;
        }
      }
    }
    double current = 0.0;
    for (int s = 0; s < slices; ++s) current += d1[s];
    double best_total = current;
    int best_i = -1, best_c = -1;
    for (int i = 0; i < k; ++i) {
      for (int c = 0; c < candidates; ++c) {
        if (chosen[c]) continue;
        double total = 0.0;
        for (int s = 0; s < slices; ++s) total += std::min(at(c, s), owner[s] == i ? d2[s] : d1[s]);
        if (total < best_total - 1e-12 * std::abs(best_total)) best_total = total, best_i = i, best_c = c;
      }
    }
    if (best_i < 0) break;
    chosen[medoids[best_i]] = 0;
    chosen[best_c] = 1;
    medoids[best_i] = best_c;
  }
  return medoids;
}

std::string Where(const std::string& path, const YAML::Node& node, const std::string& key) {
  return Located(path, node.Mark().line >= 0 ? node.Mark().line + 1 : 0, key + ": ");
}

template <class T>
T Scalar(const std::string& path, const YAML::Node& root, const char* key) {
  const YAML::Node n = root[key];
  if (!n) throw InputError(Located(path, root.Mark().line + 1, std::string(key) + ": missing"));
  T value{};
  std::string why;
  if (!config::Decode(n, &value, &why)) throw InputError(Where(path, n, key) + why);
  return value;
}

}  // namespace

TemplateLibrary BuildTemplates(const ImuStream& clean, const DtwOptions& options) {
  const int k = options.templates, n = options.template_length, m = options.slice_length, d = options.dims;
  CheckGeometry(k, n, m, d, "detector.dtw.");
  const int available = static_cast<int>(clean.size()) / m;
  if (available < k + 1)
    throw InputError("detector.dtw.templates: a template library of k = " + std::to_string(k) +
                     " templates needs k + 1 = " + std::to_string(k + 1) + " clean slices of " +
                     std::to_string(m) + " samples, the clean data has " + std::to_string(available) +
                     ": lower detector.dtw.templates or give a longer clean recording");
  const int used = std::min(available, std::max(options.max_build_slices, k + 1));
  std::vector<int> indices(used);
  for (int s = 0; s < used; ++s)
    indices[s] = static_cast<int>(static_cast<int64_t>(s) * available / used);  // evenly spread
  const std::vector<double> slices = NormalizedSlices(clean, indices, m, d, options.normalization);
  const std::size_t slice_size = static_cast<std::size_t>(m) * d,
                    template_size = static_cast<std::size_t>(n) * d;

  // Candidate templates: every used slice, shortened to N rows.
  std::vector<double> candidates(used * template_size);
  for (int s = 0; s < used; ++s)
    ResampleRows(slices.data() + s * slice_size, m, d, n, candidates.data() + s * template_size);

  // cost(c, s) = DTW(candidate c, slice s), with the fast matcher (all candidates in lanes).
  std::vector<double> cost(static_cast<std::size_t>(used) * used);
  {
    DtwMatcher matcher(candidates.data(), used, n, d);
    std::vector<float> slice_f(slice_size), distances(used);
    for (int s = 0; s < used; ++s) {
      for (std::size_t i = 0; i < slice_size; ++i)
        slice_f[i] = static_cast<float>(slices[s * slice_size + i]);
      matcher.Distances(slice_f.data(), m, distances.data());
      for (int c = 0; c < used; ++c) cost[static_cast<std::size_t>(c) * used + s] = distances[c];
    }
  }
  const std::vector<int> medoids = KMedoids(cost, used, used, k, options.swap_passes);

  TemplateLibrary library;
  library.slice_length = m;
  library.template_length = n;
  library.dims = d;
  library.normalization = options.normalization;
  library.values.reserve(k * template_size);
  for (int c : medoids)
    library.values.insert(library.values.end(), candidates.begin() + c * template_size,
                          candidates.begin() + (c + 1) * template_size);

  // Leave-self-out best distances (double precision, Algorithm 1).
  std::vector<double> best(used, kInf), row(m + 1);
  for (int s = 0; s < used; ++s) {
    for (int t = 0; t < k; ++t) {
      if (medoids[t] == s) continue;
      best[s] = std::min(
          best[s], DtwDistance(library.Template(t), n, slices.data() + s * slice_size, m, d, row.data()));
    }
  }
  library.calibration_slices = used;
  library.calibration_quantile = options.threshold_quantile;
  library.calibration_margin = options.threshold_margin;
  library.calibration_quantile_distance = Quantile(best, options.threshold_quantile);
  library.threshold = options.threshold_margin * library.calibration_quantile_distance;
  return library;
}

std::vector<double> SliceDistances(const TemplateLibrary& library, const ImuStream& stream) {
  const int m = library.slice_length, n = library.template_length, d = library.dims;
  const int count = static_cast<int>(stream.size()) / m;
  std::vector<int> indices(count);
  for (int s = 0; s < count; ++s) indices[s] = s;
  const std::vector<double> slices = NormalizedSlices(stream, indices, m, d, library.normalization);
  std::vector<double> best(count, kInf), row(m + 1);
  for (int s = 0; s < count; ++s)
    for (int t = 0; t < library.count(); ++t)
      best[s] =
          std::min(best[s], DtwDistance(library.Template(t), n, slices.data() + s * m * d, m, d, row.data()));
  return best;
}

std::string TemplateLibraryYaml(const TemplateLibrary& library) {
  std::string y;
  y += std::string(kTemplateLibraryFirstLine) +
       " (written by `vigil templates`; see detectors/template_library.h).\n";
  y += "# Templates are normalized slices shortened to template_length rows; channels in m/s^2 and rad/s.\n";
  y += std::string("format: ") + kFormat + "\n";
  {
    YAML::Emitter source;
    source << library.source;
    y += std::string("source: ") + source.c_str() + "\n";
  }
  y += "slice_length: " + std::to_string(library.slice_length) + "\n";
  y += "template_length: " + std::to_string(library.template_length) + "\n";
  y += "dims: " + std::to_string(library.dims) + "\n";
  y += library.dims == 3 ? "channels: [ax, ay, az]\n" : "channels: [ax, ay, az, wx, wy, wz]\n";
  for (const auto& [name, value] : SliceNormalizationNames())
    if (value == library.normalization) y += "normalization: " + name + "\n";
  y += "threshold: " + FormatDouble(library.threshold) + "\n";
  y += "calibration: {slices: " + std::to_string(library.calibration_slices) +
       ", quantile: " + FormatDouble(library.calibration_quantile) +
       ", quantile_distance: " + FormatDouble(library.calibration_quantile_distance) +
       ", margin: " + FormatDouble(library.calibration_margin) + "}\n";
  y += "templates:\n";
  for (int t = 0; t < library.count(); ++t) {
    y += "  - # template " + std::to_string(t) + "\n";
    for (int j = 0; j < library.template_length; ++j) {
      y += "    - [";
      for (int c = 0; c < library.dims; ++c)
        y += (c ? ", " : "") + FormatDouble(library.Template(t)[j * library.dims + c]);
      y += "]\n";
    }
  }
  return y;
}

TemplateLibrary ReadTemplateLibrary(const std::string& path) {
  const YAML::Node root = config::LoadYamlFile(path);
  if (!root.IsMap()) throw InputError(path + ": not a template library (expected a YAML mapping)");
  const std::string format = root["format"] && root["format"].IsScalar() ? root["format"].Scalar() : "";
  if (format != kFormat)
    throw InputError(
        Located(path, root.Mark().line + 1,
                std::string("format: expected '") + kFormat + "' (a file written by `vigil templates`)"));
  TemplateLibrary lib;
  if (root["source"]) lib.source = Scalar<std::string>(path, root, "source");
  lib.slice_length = Scalar<int>(path, root, "slice_length");
  lib.template_length = Scalar<int>(path, root, "template_length");
  lib.dims = Scalar<int>(path, root, "dims");
  lib.threshold = Scalar<double>(path, root, "threshold");
  if (!(lib.threshold > 0.0)) throw InputError(Where(path, root["threshold"], "threshold") + "must be > 0");
  const std::string norm = Scalar<std::string>(path, root, "normalization");
  bool known = false;
  for (const auto& [name, value] : SliceNormalizationNames())
    if (name == norm) lib.normalization = value, known = true;
  if (!known)
    throw InputError(Where(path, root["normalization"], "normalization") + "must be none, median or linear");
  if (const YAML::Node cal = root["calibration"]; cal && cal.IsMap()) {
    lib.calibration_slices = Scalar<int>(path, cal, "slices");
    lib.calibration_quantile = Scalar<double>(path, cal, "quantile");
    lib.calibration_quantile_distance = Scalar<double>(path, cal, "quantile_distance");
    lib.calibration_margin = Scalar<double>(path, cal, "margin");
  }
  const YAML::Node templates = root["templates"];
  if (!templates || !templates.IsSequence() || templates.size() == 0)
    throw InputError(
        Located(path, root.Mark().line + 1, "templates: expected a non-empty list of templates"));
  try {
    CheckGeometry(static_cast<int>(templates.size()), lib.template_length, lib.slice_length, lib.dims, "");
  } catch (const InputError& e) {
    throw InputError(Located(path, root.Mark().line + 1, e.what()));
  }
  for (std::size_t t = 0; t < templates.size(); ++t) {
    const YAML::Node tpl = templates[t];
    const std::string key = "templates[" + std::to_string(t) + "]";
    if (!tpl.IsSequence() || static_cast<int>(tpl.size()) != lib.template_length)
      throw InputError(Where(path, tpl, key) + "expected " + std::to_string(lib.template_length) + " rows");
    for (std::size_t j = 0; j < tpl.size(); ++j) {
      const YAML::Node r = tpl[j];
      if (!r.IsSequence() || static_cast<int>(r.size()) != lib.dims)
        throw InputError(Where(path, r, key + "[" + std::to_string(j) + "]") + "expected a row of " +
                         std::to_string(lib.dims) + " numbers");
      for (std::size_t c = 0; c < r.size(); ++c) {
        double v = 0.0;
        std::string why;
        if (!config::Decode(r[c], &v, &why))
          throw InputError(Where(path, r[c], key + "[" + std::to_string(j) + "]") + why);
        lib.values.push_back(v);
      }
    }
  }
  return lib;
}

}  // namespace vigil::detectors
