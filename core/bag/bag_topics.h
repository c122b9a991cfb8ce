// Which topics of a bag `vigil import` converts: the ones named on the command line, else the preset's, each
// checked against the bag (present, with messages, of the expected type and definition) before anything is
// written.
#pragma once

#include <cstddef>
#include <string>

#include "core/bag/bag_file.h"
#include "core/bag/bag_import.h"
#include "core/bag/bag_presets.h"

namespace vigil::bag {

// The topics to import; an empty name is not imported.
struct ImportTopics {
  std::string imu, image, groundtruth;  // empty: not imported
  std::string groundtruth_type;
  std::string groundtruth_note;
  std::size_t messages = 0;  // of the three together
};

// InputError naming the bag and the topic: a missing topic (with the bag's topics), one without messages, of
// another type or of another definition (MD5), a ground truth that is not a pose. The preset's ground-truth
// topic may be absent (groundtruth empty, groundtruth_note says so); a named one may not.
ImportTopics ResolveTopics(const BagImportRequest& request, const BagPreset& preset, const BagFile& bag);

}  // namespace vigil::bag
