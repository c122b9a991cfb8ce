#include "plots/method_colors.h"

#include <algorithm>
#include <iterator>
#include <set>

#include "plots/style.h"

namespace vigil::plots {
namespace {

constexpr int kPaletteSize = 8;
constexpr int kGrey = 6;

// The palette index a paper method keeps in every figure, or -1.
int PaperMethodIndex(const std::string& method) {
  if (method == "original") return 1;
  if (method == "trunc") return 0;
  if (method == "dtw") return 2;
  if (method == "hampel") return 3;
  return -1;
}

// Shade k (1, 2, ...) of a colour: odd shades mixed towards black, even ones towards white.
Color Shade(Color c, int k) {
  const float t = k % 2 == 1 ? 0.45f : 0.5f;
  const float target = k % 2 == 1 ? 0.0f : 1.0f;
  return {c.r + (target - c.r) * t, c.g + (target - c.g) * t, c.b + (target - c.b) * t, c.a};
}

struct Variant {
  std::string prefix, base;
};

// The methods that are PREFIX_BASE with BASE another of `methods`, by method, where PREFIX_ is shared by at
// least two of them.
std::map<std::string, Variant> Variants(const std::vector<std::string>& methods) {
  const std::set<std::string> names(methods.begin(), methods.end());
  std::map<std::string, Variant> candidates;
  std::map<std::string, int> prefix_count;
  for (const std::string& m : methods) {
    const std::size_t cut = m.find('_');
    if (cut == std::string::npos || cut == 0) continue;
    Variant v{m.substr(0, cut), m.substr(cut + 1)};
    if (!names.count(v.base) || candidates.count(m)) continue;
    ++prefix_count[v.prefix];
    candidates.emplace(m, std::move(v));
  }
  std::map<std::string, Variant> out;
  for (auto& [m, v] : candidates)
    if (prefix_count[v.prefix] >= 2) out.emplace(m, v);
  // A variant of a variant keeps a colour of its own (its base has no hue to share yet).
  for (auto it = out.begin(); it != out.end();)
    it = out.count(it->second.base) ? out.erase(it) : std::next(it);
  return out;
}

}  // namespace

MethodColors::MethodColors(const std::vector<std::string>& methods) {
  const std::map<std::string, Variant> variants = Variants(methods);
  // The paper's methods first, then the others in order on the free palette indices.
  std::vector<bool> used(kPaletteSize, false);
  for (const std::string& m : methods)
    if (const int index = PaperMethodIndex(m); index >= 0 && !variants.count(m)) {
      colors_[m] = PaletteColor(index);
      used[static_cast<std::size_t>(index)] = true;
    }
  int next = 0;
  for (const std::string& m : methods) {
    if (variants.count(m) || colors_.count(m)) continue;
    int index = -1;
    for (int k = 0; k < kPaletteSize && index < 0; ++k)
      if (!used[static_cast<std::size_t>(k)]) index = k;
    if (index < 0)
      index = next++ % kPaletteSize;  // the palette is spent: it wraps around
    else
      used[static_cast<std::size_t>(index)] = true;
    colors_[m] = PaletteColor(index);
  }
  // Variants: their method's hue, one shade per prefix in order of first appearance.
  std::vector<std::string> prefixes;
  for (const std::string& m : methods) {
    const auto it = variants.find(m);
    if (it == variants.end()) continue;
    auto p = std::find(prefixes.begin(), prefixes.end(), it->second.prefix);
    if (p == prefixes.end()) p = prefixes.insert(prefixes.end(), it->second.prefix);
    colors_[m] = Shade(colors_.at(it->second.base), static_cast<int>(p - prefixes.begin()) + 1);
  }
}

Color MethodColors::Of(const std::string& method) const {
  const auto it = colors_.find(method);
  return it == colors_.end() ? PaletteColor(kGrey) : it->second;
}

}  // namespace vigil::plots
