// The `frontend:` section of a run configuration: where a run's feature tracks come from, the tracker's
// options and the evaluation's.
#pragma once

#include "core/config.h"
#include "frontend/feature_tracker_options.h"
#include "frontend/frontend_evaluation.h"

namespace vigil::frontend {

// ideal: the dataset's features.csv (the simulator's projections of its landmarks);
// tracked: the KLT tracker on the dataset's camera images.
enum class FeatureSource { kIdeal, kTracked };

inline const config::EnumNames<FeatureSource>& FeatureSourceNames() {
  static const config::EnumNames<FeatureSource> names = {{"ideal", FeatureSource::kIdeal},
                                                         {"tracked", FeatureSource::kTracked}};
  return names;
}

struct FrontendOptions {
  FeatureSource features = FeatureSource::kIdeal;
  FeatureTrackerOptions tracker;
  FrontendEvaluationOptions evaluation;

  template <class V>
  void Visit(V& v) {
    v.Enum("features", features, FeatureSourceNames(),
           "feature tracks of a run: ideal (features.csv) or tracked (KLT on the camera images)");
    tracker.Visit(v);  // the tracker's keys sit directly under frontend
    v.Section("evaluation", evaluation, "evaluation of the tracks against the scene geometry");
  }
};

}  // namespace vigil::frontend
