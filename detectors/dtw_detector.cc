#include "detectors/dtw_detector.h"

#include <algorithm>

#include "core/error.h"
#include "detectors/dtw_distance.h"

namespace vigil::detectors {
namespace {

const TemplateLibrary& Checked(const TemplateLibrary& library) {
  if (library.dims != 3 && library.dims != 6) throw InputError("template library: dims must be 3 or 6");
  if (library.slice_length < 2 || library.template_length < 1 || library.count() < 1 ||
      library.values.size() !=
          static_cast<std::size_t>(library.count()) * library.template_length * library.dims)
    throw InputError("template library: inconsistent sizes");
  if (!(library.threshold > 0.0)) throw InputError("template library: threshold must be > 0");
  return library;
}

}  // namespace

double EffectiveDtwThreshold(const DtwOptions& options, const TemplateLibrary& library) {
  return options.threshold > 0.0 ? options.threshold : library.threshold;
}

DtwDetector::DtwDetector(const DtwOptions& options, const TemplateLibrary& library)
    : library_(Checked(library)),
      threshold_(EffectiveDtwThreshold(options, library)),
      matcher_(library.values.data(), library.count(), library.template_length, library.dims) {
  const std::size_t m = library.slice_length, d = library.dims;
  pending_.reserve(m);
  previous_.reserve(m);
  slice_.resize(m * d);
  replacement_.resize(m * d);
  slice_f_.resize(m * d);
  matches_.resize(m);
}

void DtwDetector::Push(const ImuSample& raw, std::vector<DetectedSample>* out) {
  pending_.push_back(raw);
  if (static_cast<int>(pending_.size()) < library_.slice_length) return;
  Judge(pending_, 0, out);
  pending_.swap(previous_);
  pending_.clear();
}

void DtwDetector::Finish(std::vector<DetectedSample>* out) {
  const int m = library_.slice_length, r = static_cast<int>(pending_.size());
  if (r == 0) return;
  if (static_cast<int>(previous_.size()) < m) {  // the whole stream is shorter than one slice
    for (const ImuSample& s : pending_) out->push_back({s, 0});
    pending_.clear();
    return;
  }
  std::vector<ImuSample> window(previous_.end() - (m - r), previous_.end());
  window.insert(window.end(), pending_.begin(), pending_.end());
  Judge(window, m - r, out);
  pending_.clear();
}

void DtwDetector::Judge(std::vector<ImuSample>& window, int first_new, std::vector<DetectedSample>* out) {
  const int m = library_.slice_length, n = library_.template_length, d = library_.dims;
  NormalizeSlice(window.data(), m, d, library_.normalization, slice_.data(), &baseline_, &scratch_);
  for (std::size_t i = 0; i < slice_.size(); ++i) slice_f_[i] = static_cast<float>(slice_[i]);
  const DtwMatch best = matcher_.Best(slice_f_.data(), m);
  slice_distances_.push_back(best.distance);
  uint8_t flags = 0;
  if (best.distance > threshold_) {
    for (int c = 0; c < d; ++c) flags |= static_cast<uint8_t>(1u << ChannelAxis(c));
    // Align the best template to the slice (double precision) and average the rows matched with each sample.
    const DtwAlignment alignment = DtwAlign(library_.Template(best.index), n, slice_.data(), m, d);
    std::fill(replacement_.begin(), replacement_.end(), 0.0);
    std::fill(matches_.begin(), matches_.end(), 0);
    for (const auto& [j, i] : alignment.path) {
      ++matches_[i];
      for (int c = 0; c < d; ++c) replacement_[i * d + c] += library_.Template(best.index)[j * d + c];
    }
    for (int i = 0; i < m; ++i)
      for (int c = 0; c < d; ++c) replacement_[i * d + c] /= matches_[i];
    // Keep only the template's shape: remove its own baseline (the best template of a glitched slice is
    // biased toward the glitch's sign) and put the slice's baseline back.
    FitBaseline(replacement_.data(), m, d, library_.normalization, &template_baseline_, &scratch_);
    SubtractBaseline(template_baseline_, m, d, replacement_.data());
    for (int i = first_new; i < m; ++i)
      for (int c = 0; c < d; ++c)
        window[i].axis(ChannelAxis(c)) = replacement_[i * d + c] + baseline_.At(c, i, m);
  }
  for (int i = first_new; i < m; ++i) out->push_back({window[i], flags});
}

}  // namespace vigil::detectors
