// EuRoC's cam0 (MH_01 ... V2_03, as in its cam0/sensor.yaml): 752 x 480, strong barrel distortion. The camera
// of the tests of the lens model (core) and of the front-end's undistortion (frontend).
#pragma once

#include "core/camera.h"

namespace vigil::testing {

inline CameraModel EurocCam0() {
  CameraModel cam;
  cam.width = 752;
  cam.height = 480;
  cam.fx = 458.654;
  cam.fy = 457.296;
  cam.cx = 367.215;
  cam.cy = 248.375;
  cam.distortion = {-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05};
  return cam;
}

}  // namespace vigil::testing
