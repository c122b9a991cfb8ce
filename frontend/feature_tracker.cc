#include "frontend/feature_tracker.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <opencv2/calib3d.hpp>
#include <opencv2/video/tracking.hpp>

#include "frontend/corner_detector.h"

namespace vigil::frontend {
namespace {

// RANSAC needs at least this many correspondences (the eight-point minimum).
constexpr std::size_t kMinRansacPoints = 8;
// Publication slack: a frame is published once 0.9 periods of max_rate_hz have passed, so that timestamp
// jitter does not skip a frame that is due.
constexpr double kPublishSlack = 0.9;

}  // namespace

FeatureTracker::FeatureTracker(const FeatureTrackerOptions& options, const CameraModel& camera)
    : options_(options), camera_(camera), undistorter_(camera) {
  if (options_.clahe)
    clahe_ = cv::createCLAHE(options_.clahe_clip_limit, cv::Size(options_.clahe_tiles, options_.clahe_tiles));
}

bool FeatureTracker::InsideBorder(const cv::Point2f& p) const {
  const float b = static_cast<float>(options_.border_px);
  return p.x >= b && p.y >= b && p.x < static_cast<float>(camera_.width) - b &&
         p.y < static_cast<float>(camera_.height) - b;
}

bool FeatureTracker::InsideImage(const cv::Point2f& p) const {
  return p.x >= 0.0f && p.y >= 0.0f && p.x < static_cast<float>(camera_.width) &&
         p.y < static_cast<float>(camera_.height);
}

bool FeatureTracker::ShouldPublish(int64_t t_ns) const {
  if (!last_published_t_ns_ || options_.max_rate_hz <= 0.0) return true;
  const double elapsed_s = static_cast<double>(t_ns - *last_published_t_ns_) * 1e-9;
  return elapsed_s >= kPublishSlack / options_.max_rate_hz;
}

std::optional<CameraFrame> FeatureTracker::Track(const cv::Mat& image, int64_t t_ns) {
  if (image.type() != CV_8UC1)
    throw std::invalid_argument("feature tracker: expected an 8-bit grayscale image");
  if (image.cols != camera_.width || image.rows != camera_.height)
    throw std::invalid_argument("feature tracker: image of " + std::to_string(image.cols) + " x " +
                                std::to_string(image.rows) + " px, the camera's is " +
                                std::to_string(camera_.width) + " x " + std::to_string(camera_.height));
  if (last_t_ns_ && t_ns <= *last_t_ns_)
    throw std::invalid_argument("feature tracker: timestamps must increase");
  last_t_ns_ = t_ns;
  ++stats_.images;

  cv::Mat gray;
  if (clahe_)
    clahe_->apply(image, gray);
  else
    gray = image;
  // One pyramid (with its derivatives) per image, used to track into it and, next time, out of it.
  std::vector<cv::Mat> pyramid;
  const cv::Size window(options_.klt_window_px, options_.klt_window_px);
  // (copied, never sharing the caller's pixels, which it may reuse for its next image)
  cv::buildOpticalFlowPyramid(gray, pyramid, window, options_.klt_pyramid_levels, true,
                              cv::BORDER_REFLECT_101, cv::BORDER_CONSTANT, false);
  if (!previous_pyramid_.empty() && !tracks_.empty()) {
    TrackIntoImage(pyramid);
    if (options_.refine_tracks && options_.subpixel_window_px > 0) {
      std::vector<cv::Point2f> points(tracks_.size());
      for (std::size_t i = 0; i < tracks_.size(); ++i) points[i] = tracks_[i].raw_px;
      RefineCorners(gray, &points, options_.subpixel_max_shift_px);
      for (std::size_t i = 0; i < tracks_.size(); ++i) tracks_[i].raw_px = points[i];
    }
    if (options_.anchor_refinement) RefineAgainstAnchors(gray);
  }
  previous_pyramid_ = std::move(pyramid);
  if (!ShouldPublish(t_ns)) return std::nullopt;
  last_published_t_ns_ = t_ns;
  ++stats_.published_frames;

  std::vector<cv::Point2f> raw(tracks_.size());
  for (std::size_t i = 0; i < tracks_.size(); ++i) raw[i] = tracks_[i].raw_px;
  const std::vector<cv::Point2f> undistorted = undistorter_.Undistort(raw);
  // Tracks that existed at the last published frame keep their undistorted pixel of then until RANSAC.
  RejectWithFundamental(undistorted);
  EndAgedTracks();
  EnforceSpacing();
  DetectNewCorners(gray);

  CameraFrame frame;
  frame.t_ns = t_ns;
  frame.features.reserve(tracks_.size());
  for (TrackState& track : tracks_) {
    ++track.length;
    frame.features.push_back({track.id, Eigen::Vector2d(track.undistorted_px.x, track.undistorted_px.y)});
  }
  std::sort(frame.features.begin(), frame.features.end(),
            [](const FeatureObservation& a, const FeatureObservation& b) { return a.id < b.id; });
  return frame;
}

void FeatureTracker::TrackIntoImage(const std::vector<cv::Mat>& pyramid) {
  std::vector<cv::Point2f> before(tracks_.size()), after;
  for (std::size_t i = 0; i < tracks_.size(); ++i) before[i] = tracks_[i].raw_px;
  std::vector<uchar> status;
  std::vector<float> error;
  const cv::Size window(options_.klt_window_px, options_.klt_window_px);
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS,
                                  options_.klt_max_iterations, options_.klt_epsilon_px);
  cv::calcOpticalFlowPyrLK(previous_pyramid_, pyramid, before, after, status, error, window,
                           options_.klt_pyramid_levels, criteria);
  std::vector<uchar> back_status;
  std::vector<cv::Point2f> back;
  if (options_.backward_check) {
    back = before;
    cv::calcOpticalFlowPyrLK(pyramid, previous_pyramid_, after, back, back_status, error, window,
                             options_.klt_pyramid_levels, criteria, cv::OPTFLOW_USE_INITIAL_FLOW);
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    bool ok = status[i] != 0 && InsideBorder(after[i]);
    if (ok && options_.backward_check)
      ok = back_status[i] != 0 && cv::norm(back[i] - before[i]) <= options_.backward_check_px;
    if (!ok) {
      ++stats_.klt_failures;
      continue;
    }
    tracks_[i].raw_px = after[i];
    tracks_[kept++] = tracks_[i];
  }
  tracks_.resize(kept);
}

void FeatureTracker::RefineAgainstAnchors(const cv::Mat& image) {
  AffineAlignOptions align;
  align.max_iterations = options_.klt_max_iterations;
  align.epsilon_px = options_.klt_epsilon_px;
  for (TrackState& track : tracks_) {
    std::optional<AffineWarp> warp;
    if (track.anchor)
      warp = AlignAffinePatch(*track.anchor, image, {track.anchor_linear, track.raw_px}, align);
    if (warp && cv::norm(warp->centre_px - track.raw_px) <= options_.anchor_max_shift_px &&
        InsideBorder(warp->centre_px)) {
      track.raw_px = warp->centre_px;
      track.anchor_linear = warp->linear;
      ++stats_.anchor_refined;
    } else {
      ++stats_.anchor_rejected;
    }
    // (a track without a patch gets one as soon as it can)
    if (!track.anchor || stats_.images - track.anchor_image >= options_.anchor_max_age) Anchor(image, &track);
  }
}

void FeatureTracker::Anchor(const cv::Mat& image, TrackState* track) {
  if (!options_.anchor_refinement) return;
  std::optional<AffinePatch> patch = MakeAffinePatch(image, track->raw_px, options_.anchor_patch_px / 2);
  track->anchor = patch ? std::make_shared<const AffinePatch>(std::move(*patch)) : nullptr;
  track->anchor_image = stats_.images;
  track->anchor_linear = cv::Matx22f::eye();
}

void FeatureTracker::RejectWithFundamental(const std::vector<cv::Point2f>& undistorted_now) {
  std::vector<uchar> inlier(tracks_.size(), 1);
  if (options_.ransac && tracks_.size() >= kMinRansacPoints) {
    std::vector<cv::Point2f> then(tracks_.size());
    for (std::size_t i = 0; i < tracks_.size(); ++i) then[i] = tracks_[i].undistorted_px;
    cv::findFundamentalMat(then, undistorted_now, cv::FM_RANSAC, options_.ransac_threshold_px,
                           options_.ransac_confidence, inlier);
    // A degenerate configuration returns no model and an empty mask: then keep every track.
    if (inlier.size() != tracks_.size()) inlier.assign(tracks_.size(), 1);
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    if (!inlier[i]) {
      ++stats_.ransac_outliers;
      continue;
    }
    if (!InsideImage(undistorted_now[i])) {
      ++stats_.outside_undistorted;
      continue;
    }
    tracks_[i].undistorted_px = undistorted_now[i];
    tracks_[kept++] = tracks_[i];
  }
  tracks_.resize(kept);
}

void FeatureTracker::RefineCorners(const cv::Mat& image, std::vector<cv::Point2f>* points,
                                   double max_shift_px) const {
  if (points->empty()) return;
  std::vector<cv::Point2f> refined = *points;
  const cv::Size half(options_.subpixel_window_px, options_.subpixel_window_px);
  cv::cornerSubPix(image, refined, half, cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS,
                                    options_.subpixel_iterations, options_.subpixel_epsilon_px));
  for (std::size_t i = 0; i < refined.size(); ++i)
    if (cv::norm(refined[i] - (*points)[i]) <= max_shift_px && InsideBorder(refined[i]))
      (*points)[i] = refined[i];
}

void FeatureTracker::EndAgedTracks() {
  if (options_.max_track_length <= 0) return;
  // Staggered: at most max_features / max_track_length tracks end per frame, the longest first (ties: lower
  // id), so that tracks born together do not all end together and consecutive frames keep sharing tracks.
  const std::size_t per_frame = static_cast<std::size_t>(
      (options_.max_features + options_.max_track_length - 1) / options_.max_track_length);
  std::vector<std::size_t> aged;
  for (std::size_t i = 0; i < tracks_.size(); ++i)
    if (tracks_[i].length >= options_.max_track_length) aged.push_back(i);
  std::sort(aged.begin(), aged.end(), [&](std::size_t a, std::size_t b) {
    if (tracks_[a].length != tracks_[b].length) return tracks_[a].length > tracks_[b].length;
    return tracks_[a].id < tracks_[b].id;
  });
  if (aged.size() > per_frame) aged.resize(per_frame);
  std::vector<bool> ends(tracks_.size(), false);
  for (std::size_t i : aged) ends[i] = true;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < tracks_.size(); ++i)
    if (!ends[i]) tracks_[kept++] = tracks_[i];
  stats_.aged_out += static_cast<int64_t>(tracks_.size() - kept);
  tracks_.resize(kept);
}

void FeatureTracker::EnforceSpacing() {
  if (options_.min_distance_px <= 0.0) return;
  std::vector<std::size_t> order(tracks_.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (tracks_[a].length != tracks_[b].length) return tracks_[a].length > tracks_[b].length;
    return tracks_[a].id < tracks_[b].id;
  });
  const double drop_px = options_.spacing_drop_px > 0.0 ? options_.spacing_drop_px : options_.min_distance_px;
  const double min_d2 = drop_px * drop_px;
  std::vector<TrackState> kept;
  kept.reserve(tracks_.size());
  for (std::size_t i : order) {
    const cv::Point2f p = tracks_[i].raw_px;
    const bool crowded = std::any_of(kept.begin(), kept.end(), [&](const TrackState& k) {
      const cv::Point2f d = k.raw_px - p;
      return static_cast<double>(d.x) * d.x + static_cast<double>(d.y) * d.y < min_d2;
    });
    if (crowded) {
      ++stats_.spacing_drops;
      continue;
    }
    kept.push_back(tracks_[i]);
  }
  tracks_ = std::move(kept);
}

void FeatureTracker::DetectNewCorners(const cv::Mat& image) {
  const int wanted = options_.max_features - static_cast<int>(tracks_.size());
  if (wanted <= 0) return;
  cv::Mat mask(image.size(), CV_8UC1, cv::Scalar(255));
  const int radius = static_cast<int>(std::ceil(options_.min_distance_px));
  for (const TrackState& track : tracks_)
    cv::circle(mask, cv::Point(cvRound(track.raw_px.x), cvRound(track.raw_px.y)), radius, cv::Scalar(0),
               cv::FILLED);
  CornerDetectorOptions detector;
  detector.max_corners = wanted;
  detector.quality_level = options_.quality_level;
  detector.min_distance_px = options_.min_distance_px;
  const std::vector<cv::Point2f> corners = DetectShiTomasiCorners(image, mask, detector);
  std::vector<cv::Point2f> inside;
  for (const cv::Point2f& c : corners)
    if (InsideBorder(c)) inside.push_back(c);
  if (options_.subpixel_window_px > 0) RefineCorners(image, &inside, options_.subpixel_window_px);
  const std::vector<cv::Point2f> undistorted = undistorter_.Undistort(inside);
  for (std::size_t i = 0; i < inside.size(); ++i) {
    if (!InsideImage(undistorted[i])) continue;
    TrackState track;
    track.id = next_id_++;
    track.raw_px = inside[i];
    track.undistorted_px = undistorted[i];
    Anchor(image, &track);
    tracks_.push_back(track);
    ++stats_.tracks_created;
  }
}

}  // namespace vigil::frontend
