#include "frontend/feature_tracker.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/frontend_evaluation.h"
#include "tests/frontend/synthetic_images.h"

namespace vigil::frontend {
namespace {

using testing::Apply;
using testing::MakeTexture;
using testing::PlaneMotion;
using testing::Warp;

constexpr int64_t kFramePeriod_ns = 50'000'000;  // 20 Hz

// 640 x 480, focal length 460 px, principal point at (320, 240); no distortion.
CameraModel Camera640() {
  CameraModel camera;
  camera.width = 640;
  camera.height = 480;
  camera.cx = 320.0;
  camera.cy = 240.0;
  return camera;
}

std::vector<CameraFrame> TrackAll(FeatureTracker& tracker, const std::vector<cv::Mat>& images) {
  std::vector<CameraFrame> frames;
  for (std::size_t k = 0; k < images.size(); ++k)
    if (auto frame = tracker.Track(images[k], static_cast<int64_t>(k) * kFramePeriod_ns))
      frames.push_back(*frame);
  return frames;
}

// True pixels of a plane-motion sequence: each track's first observation mapped by the known homographies.
TruePixels PlaneTruth(const std::vector<CameraFrame>& frames, const PlaneMotion& motion) {
  std::map<int, std::pair<int, cv::Point2d>> first;  // id -> (frame, pixel)
  TruePixels truth(frames.size());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const int k = static_cast<int>(frames[f].t_ns / kFramePeriod_ns);
    for (const FeatureObservation& obs : frames[f].features) {
      const cv::Point2d p(obs.uv_px.x(), obs.uv_px.y());
      const auto [it, inserted] = first.emplace(obs.id, std::make_pair(k, p));
      const cv::Point2d q = Apply(motion.H(k) * motion.H(it->second.first).inv(), it->second.second);
      truth[f].push_back(Eigen::Vector2d(q.x, q.y));
    }
  }
  return truth;
}

double Quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1))];
}

// Each tracked point moves from one frame to the next as the known homography moves it.
TEST(FeatureTracker, TracksFollowAKnownHomography) {
  const PlaneMotion motion;  // 1.9 px, 0.29 deg and 0.4 % of zoom per frame
  const cv::Mat texture = MakeTexture(1280, 1000, 7);
  const std::vector<cv::Mat> images = motion.Frames(texture, 12);
  FeatureTracker tracker(FeatureTrackerOptions{}, Camera640());
  const std::vector<CameraFrame> frames = TrackAll(tracker, images);
  ASSERT_EQ(frames.size(), images.size());
  EXPECT_GE(frames.front().features.size(), 140u);

  std::vector<double> step_errors;  // |tracked - true| of a point moved from its previous tracked position
  std::map<int, Eigen::Vector2d> previous;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const cv::Matx33d H = motion.H(static_cast<int>(f)) * motion.H(static_cast<int>(f) - 1).inv();
    for (const FeatureObservation& obs : frames[f].features) {
      if (const auto it = previous.find(obs.id); it != previous.end()) {
        const cv::Point2d q = Apply(H, {it->second.x(), it->second.y()});
        step_errors.push_back((obs.uv_px - Eigen::Vector2d(q.x, q.y)).norm());
      }
      previous[obs.id] = obs.uv_px;
    }
  }
  ASSERT_GT(step_errors.size(), 1500u);
  EXPECT_LT(Quantile(step_errors, 0.5), 0.05);
  EXPECT_LT(Quantile(step_errors, 0.99), 0.3);

  // Over 11 frames the errors add up (a translation-only window drifts under rotation and zoom, about
  // 0.02 px per frame here) but stay sub-pixel: no observation is 1 px off.
  const ReprojectionEvaluation e = EvaluateReprojection(frames, PlaneTruth(frames, motion), 1.0);
  EXPECT_LT(Quantile(e.errors_px, 0.5), 0.3);
  EXPECT_EQ(e.outliers, 0);
  EXPECT_GE(frames.back().features.size(), 140u);
}

// Under a pure translation the window does not deform: tracks stay within 0.1 px of the truth throughout.
TEST(FeatureTracker, TranslationIsTrackedWithoutDrift) {
  PlaneMotion motion;
  motion.angle_rad = motion.scale = 0.0;
  motion.translation_px = {3.3, 1.45};
  const cv::Mat texture = MakeTexture(1280, 1000, 8);
  const std::vector<cv::Mat> images = motion.Frames(texture, 12);
  FeatureTracker tracker(FeatureTrackerOptions{}, Camera640());
  const std::vector<CameraFrame> frames = TrackAll(tracker, images);
  const ReprojectionEvaluation e = EvaluateReprojection(frames, PlaneTruth(frames, motion), 0.3);
  ASSERT_GT(e.errors_px.size(), 1500u);
  EXPECT_LT(Quantile(e.errors_px, 0.5), 0.1);
  EXPECT_LT(Quantile(e.errors_px, 0.99), 0.3);
}

// Background moving 2 px/frame to the right, a nearer band of the scene 6 px/frame (a camera translating
// sideways: every epipolar line is horizontal), and a small pasted patch moving down 3 px/frame, which no
// camera motion explains.
struct LayeredScene {
  cv::Mat background = MakeTexture(1400, 700, 11);
  cv::Mat band = MakeTexture(1400, 200, 12);
  cv::Mat patch;
  cv::Rect band_rows{0, 300, 640, 120};
  cv::Point patch_origin{420, 80};

  LayeredScene() {
    patch = cv::Mat(24, 24, CV_8UC1, cv::Scalar(30));
    cv::rectangle(patch, cv::Rect(0, 0, 12, 12), cv::Scalar(230), cv::FILLED);
    cv::rectangle(patch, cv::Rect(12, 12, 12, 12), cv::Scalar(230), cv::FILLED);
  }

  cv::Mat Frame(int k) const {
    cv::Mat image = background(cv::Rect(400 - 2 * k, 0, 640, 480)).clone();
    band(cv::Rect(400 - 6 * k, 0, 640, band_rows.height)).copyTo(image(band_rows));
    patch.copyTo(image(cv::Rect(patch_origin.x, patch_origin.y + 3 * k, patch.cols, patch.rows)));
    return image;
  }
  bool OnPatch(const Eigen::Vector2d& uv, int k) const {
    const cv::Rect r(patch_origin.x - 3, patch_origin.y + 3 * k - 3, patch.cols + 6, patch.rows + 6);
    return r.contains(cv::Point(static_cast<int>(uv.x()), static_cast<int>(uv.y())));
  }
};

TEST(FeatureTracker, RansacRejectsAPointWithAWrongMotion) {
  const LayeredScene scene;
  std::vector<cv::Mat> images;
  for (int k = 0; k < 6; ++k) images.push_back(scene.Frame(k));

  FeatureTrackerOptions options;
  FeatureTracker tracker(options, Camera640());
  const std::vector<CameraFrame> frames = TrackAll(tracker, images);
  std::set<int> patch_ids;
  for (const FeatureObservation& obs : frames[0].features)
    if (scene.OnPatch(obs.uv_px, 0)) patch_ids.insert(obs.id);
  ASSERT_FALSE(patch_ids.empty()) << "the patch's corner must be detected";
  for (const FeatureObservation& obs : frames[1].features)
    EXPECT_EQ(patch_ids.count(obs.id), 0u) << "track " << obs.id << " on the pasted patch survived RANSAC";
  EXPECT_GE(tracker.stats().ransac_outliers, static_cast<int64_t>(patch_ids.size()));
  // The background and band tracks move consistently and survive.
  EXPECT_GE(frames[1].features.size(), frames[0].features.size() - patch_ids.size() - 5);

  // Without RANSAC the patch's track goes on (it is tracked, just with the wrong motion).
  options.ransac = false;
  FeatureTracker no_ransac(options, Camera640());
  const std::vector<CameraFrame> unfiltered = TrackAll(no_ransac, images);
  bool survived = false;
  for (const FeatureObservation& obs : unfiltered[1].features) survived |= patch_ids.count(obs.id) > 0;
  EXPECT_TRUE(survived);
}

TEST(FeatureTracker, LostTracksAreReplacedWithFreshIdsAndSpacing) {
  const cv::Mat texture = MakeTexture(1500, 480, 21);
  std::vector<cv::Mat> images;
  for (int k = 0; k < 60; ++k) images.push_back(texture(cv::Rect(800 - 12 * k, 0, 640, 480)).clone());
  const FeatureTrackerOptions options;
  FeatureTracker tracker(options, Camera640());
  const std::vector<CameraFrame> frames = TrackAll(tracker, images);
  ASSERT_EQ(frames.size(), images.size());

  std::map<int, std::pair<std::size_t, std::size_t>> span;  // id -> first, last frame
  std::map<int, int> count;
  int max_id_before = -1;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto& features = frames[f].features;
    EXPECT_GE(features.size(), 100u) << "frame " << f;
    EXPECT_LE(features.size(), static_cast<std::size_t>(options.max_features));
    int max_id_now = max_id_before;
    for (std::size_t i = 0; i < features.size(); ++i) {
      const int id = features[i].id;
      if (i > 0) {
        EXPECT_LT(features[i - 1].id, id);
      }
      if (!span.count(id)) {
        EXPECT_GT(id, max_id_before) << "a new track must get an id above every earlier one";
        span[id] = {f, f};
      }
      span[id].second = f;
      ++count[id];
      max_id_now = std::max(max_id_now, id);
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_GE((features[i].uv_px - features[j].uv_px).norm(), options.min_distance_px - 1.0);
    }
    max_id_before = max_id_now;
  }
  // Ids are never reused: every track appears in one unbroken run of frames.
  for (const auto& [id, s] : span) EXPECT_EQ(count[id], static_cast<int>(s.second - s.first + 1)) << id;
  // The texture moved by 708 px: none of the first frame's tracks is left, many were created since.
  for (const FeatureObservation& obs : frames.back().features) EXPECT_GT(span[obs.id].first, 0u);
  EXPECT_GT(tracker.stats().tracks_created, 2 * options.max_features);
}

TEST(FeatureTracker, SameImagesGiveIdenticalOutput) {
  const LayeredScene scene;
  std::vector<cv::Mat> images;
  for (int k = 0; k < 8; ++k) images.push_back(scene.Frame(k));
  FeatureTrackerOptions options;
  options.backward_check = true;
  FeatureTracker a(options, Camera640());
  const std::vector<CameraFrame> first = TrackAll(a, images);
  cv::theRNG().state = 0x1234567;  // OpenCV's global generator has no influence
  FeatureTracker b(options, Camera640());
  const std::vector<CameraFrame> second = TrackAll(b, images);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t f = 0; f < first.size(); ++f) {
    ASSERT_EQ(first[f].features.size(), second[f].features.size());
    for (std::size_t i = 0; i < first[f].features.size(); ++i) {
      EXPECT_EQ(first[f].features[i].id, second[f].features[i].id);
      EXPECT_EQ(first[f].features[i].uv_px, second[f].features[i].uv_px);
    }
  }
}

TEST(FeatureTracker, OutputIsUndistorted) {
  const PlaneMotion motion;
  const cv::Mat texture = MakeTexture(1280, 1000, 9);
  const std::vector<cv::Mat> images = motion.Frames(texture, 5);
  FeatureTrackerOptions options;
  options.ransac = false;  // RANSAC on differently undistorted points may decide differently
  CameraModel distorted = Camera640();
  distorted.distortion = {0.05, 0.01, 0.001, -0.0005};  // pincushion: undistorted pixels stay in the image
  FeatureTracker raw_tracker(options, Camera640());
  FeatureTracker tracker(options, distorted);
  const std::vector<CameraFrame> raw = TrackAll(raw_tracker, images);
  const std::vector<CameraFrame> undistorted = TrackAll(tracker, images);
  ASSERT_EQ(raw.size(), undistorted.size());
  for (std::size_t f = 0; f < raw.size(); ++f) {
    ASSERT_EQ(raw[f].features.size(), undistorted[f].features.size());
    for (std::size_t i = 0; i < raw[f].features.size(); ++i) {
      ASSERT_EQ(raw[f].features[i].id, undistorted[f].features[i].id);
      const Eigen::Vector2d& p = raw[f].features[i].uv_px;
      const Eigen::Vector2d back = distorted.DistortPixel(undistorted[f].features[i].uv_px);
      EXPECT_NEAR(back.x(), p.x(), 1e-3);
      EXPECT_NEAR(back.y(), p.y(), 1e-3);
    }
  }
}

TEST(FeatureTracker, PublishesAtMostMaxRate) {
  const PlaneMotion motion;
  const cv::Mat texture = MakeTexture(1280, 1000, 3);
  const std::vector<cv::Mat> images = motion.Frames(texture, 12);
  FeatureTrackerOptions options;
  options.max_rate_hz = 10.0;  // images at 20 Hz: every other one
  FeatureTracker tracker(options, Camera640());
  const std::vector<CameraFrame> frames = TrackAll(tracker, images);
  ASSERT_EQ(frames.size(), 6u);
  for (std::size_t f = 0; f < frames.size(); ++f)
    EXPECT_EQ(frames[f].t_ns, static_cast<int64_t>(2 * f) * kFramePeriod_ns);
  // Tracking went on through the unpublished images: the tracks still follow the motion.
  const ReprojectionEvaluation e = EvaluateReprojection(frames, PlaneTruth(frames, motion), 1.0);
  EXPECT_GT(e.errors_px.size(), 600u);
  EXPECT_LT(e.outlier_ratio, 0.01);
  EXPECT_EQ(tracker.stats().images, 12);
}

// With max_track_length, tracks end after about that many published frames and their corners come back as new
// tracks; the refresh is staggered, so consecutive frames keep sharing most of their tracks.
TEST(FeatureTracker, TracksAgeOutAfterMaxTrackLength) {
  const PlaneMotion motion;
  const cv::Mat texture = MakeTexture(1280, 1000, 4);
  const std::vector<cv::Mat> images = motion.Frames(texture, 16);
  FeatureTrackerOptions options;
  options.max_track_length = 4;
  FeatureTracker tracker(options, Camera640());
  const std::vector<CameraFrame> frames = TrackAll(tracker, images);
  const std::vector<int> lengths = TrackLengths(frames);
  const int longest = *std::max_element(lengths.begin(), lengths.end());
  EXPECT_LT(longest, static_cast<int>(frames.size()) / 2);
  EXPECT_GT(tracker.stats().aged_out, options.max_features);
  for (std::size_t f = 1; f < frames.size(); ++f) {
    std::set<int> before;
    for (const FeatureObservation& obs : frames[f - 1].features) before.insert(obs.id);
    std::size_t shared = 0;
    for (const FeatureObservation& obs : frames[f].features) shared += before.count(obs.id);
    EXPECT_GE(shared, 100u) << "frame " << f;
    EXPECT_GE(frames[f].features.size(), 140u) << "frame " << f;  // refreshed, not lost
  }
}

// Sub-pixel refinement of tracked points keeps them on their corners: over 11 frames of rotation and zoom the
// refined tracks stay closer to the truth than the unrefined ones.
TEST(FeatureTracker, RefinedTracksDriftLess) {
  const PlaneMotion motion;
  const cv::Mat texture = MakeTexture(1280, 1000, 7);
  const std::vector<cv::Mat> images = motion.Frames(texture, 12);
  FeatureTrackerOptions options;
  FeatureTracker plain(options, Camera640());
  options.subpixel_window_px = 3;
  options.refine_tracks = true;
  FeatureTracker refined(options, Camera640());
  const std::vector<CameraFrame> a = TrackAll(plain, images), b = TrackAll(refined, images);
  const ReprojectionEvaluation ea = EvaluateReprojection(a, PlaneTruth(a, motion), 1.0);
  const ReprojectionEvaluation eb = EvaluateReprojection(b, PlaneTruth(b, motion), 1.0);
  ASSERT_GT(eb.errors_px.size(), 1000u);
  EXPECT_LT(Quantile(eb.errors_px, 0.5), Quantile(ea.errors_px, 0.5));
  EXPECT_LT(Quantile(eb.errors_px, 0.9), 0.3);
}

// Anchor refinement: each tracked point is aligned again, under an affine warp, with the patch its track
// began with, so the frame-to-frame errors no longer add up. Over 24 frames of rotation and zoom the anchored
// tracks stay several times closer to the truth than the frame-to-frame ones; re-anchoring every 8 images
// keeps most of the gain.
TEST(FeatureTracker, AnchoredTracksDriftLess) {
  const PlaneMotion motion;
  const cv::Mat texture = MakeTexture(1280, 1000, 7);
  const std::vector<cv::Mat> images = motion.Frames(texture, 24);
  FeatureTrackerOptions options;
  FeatureTracker plain(options, Camera640());
  options.anchor_refinement = true;
  FeatureTracker anchored(options, Camera640());
  options.anchor_max_age = 8;
  FeatureTracker reanchored(options, Camera640());
  const std::vector<CameraFrame> a = TrackAll(plain, images), b = TrackAll(anchored, images),
                                 c = TrackAll(reanchored, images);
  const auto old_errors = [&](const std::vector<CameraFrame>& frames) {  // observations 12 frames old or more
    const ReprojectionEvaluation e = EvaluateReprojection(frames, PlaneTruth(frames, motion), 1.0);
    std::vector<double> old;
    for (std::size_t i = 0; i < e.errors_px.size(); ++i)
      if (e.ages_frames[i] >= 12) old.push_back(e.errors_px[i]);
    return old;
  };
  const std::vector<double> ea = old_errors(a), eb = old_errors(b), ec = old_errors(c);
  ASSERT_GT(eb.size(), 1000u);
  ASSERT_GT(ec.size(), 1000u);
  EXPECT_LT(Quantile(eb, 0.5), 0.25 * Quantile(ea, 0.5));
  EXPECT_LT(Quantile(ec, 0.5), 0.5 * Quantile(ea, 0.5));
  EXPECT_GT(anchored.stats().anchor_refined, 2000);
  // (rejected: mostly points within a patch of the border, where the zoom pushes them out of the image)
  EXPECT_LT(anchored.stats().anchor_rejected, anchored.stats().anchor_refined / 5);
}

TEST(FeatureTracker, RejectsWrongImages) {
  FeatureTracker tracker(FeatureTrackerOptions{}, Camera640());
  EXPECT_THROW(tracker.Track(cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(0)), 0), std::invalid_argument);
  EXPECT_THROW(tracker.Track(cv::Mat(480, 752, CV_8UC1, cv::Scalar(0)), 0), std::invalid_argument);
  tracker.Track(cv::Mat(480, 640, CV_8UC1, cv::Scalar(0)), 10);
  EXPECT_THROW(tracker.Track(cv::Mat(480, 640, CV_8UC1, cv::Scalar(0)), 10), std::invalid_argument);
}

}  // namespace
}  // namespace vigil::frontend
