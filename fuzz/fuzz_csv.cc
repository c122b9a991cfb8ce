// libFuzzer target for one CSV / text reader, chosen by VIGIL_FUZZ_READER at compile time
// (fuzz/CMakeLists.txt): imu, glitches, groundtruth, landmarks, features (with the checks ReadDataset
// applies), tum, and the EuRoC layout's cam0 data.csv (euroc_images), cam0 / imu0 sensor.yaml (euroc_cam,
// euroc_imu) and scene.obj (obj).
#include "core/dataset.h"
#include "core/euroc.h"
#include "core/mesh.h"
#include "fuzz/fuzz_input.h"

namespace {
using namespace vigil;

void Read(const TextFile& path) {
  const std::string reader = VIGIL_FUZZ_READER;
  if (reader == "imu") {
    (void)ReadImuCsv(path);
  } else if (reader == "glitches") {
    (void)ReadGlitchesCsv(path);
  } else if (reader == "groundtruth") {
    (void)ReadGroundTruthCsv(path);
  } else if (reader == "landmarks") {
    (void)ReadLandmarksCsv(path);
  } else if (reader == "features") {
    static const CameraModel camera;
    static const std::vector<Landmark> landmarks = [] {
      std::vector<Landmark> l(200);
      for (int i = 0; i < 200; ++i) l[static_cast<std::size_t>(i)].id = i;
      return l;
    }();
    static const std::vector<int64_t> frame_times = CameraFrameTimes(camera.rate_hz, 0, 2000000000);
    FeatureChecks checks;
    checks.camera = &camera;
    checks.landmarks = &landmarks;
    (void)ReadFeaturesCsv(path, frame_times, &checks);
  } else if (reader == "tum") {
    (void)ReadTumTrajectory(path);
  } else if (reader == "euroc_images") {
    (void)ReadEurocImageList(path, "/nonexistent", /*check_files=*/false);
  } else if (reader == "euroc_cam") {
    (void)ReadEurocCameraSensorYaml(path);
  } else if (reader == "euroc_imu") {
    (void)ReadEurocImuSensorYaml(path);
  } else if (reader == "obj") {
    (void)ReadMeshObj(path);
  } else {
    std::abort();
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // In memory: the path variants only add ReadFile (fuzzed by the YAML targets) to the same parsers.
  const TextFile file{"<fuzz input>", std::string(reinterpret_cast<const char*>(data), size)};
  fuzz::ExpectOnlyInputErrors([&] { Read(file); });
  return 0;
}
