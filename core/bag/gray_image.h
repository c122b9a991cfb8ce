// A sensor_msgs/Image as the 8-bit grayscale image of the EuRoC cam0 layout (docs/safety.md, "Images"):
//   mono8 (or 8UC1)        as it is;
//   mono16 (or 16UC1)      scaled to 8 bits: v8 = round(v16 / 257), so 0 -> 0 and 65535 -> 255;
//   rgb8, bgr8, rgba8, bgra8  ITU-R BT.601 luma, 0.299 R + 0.587 G + 0.114 B (OpenCV's cvtColor).
// Any other encoding (Bayer, YUV, floats, ...) is refused with a reason, never guessed.
#pragma once

#include <opencv2/core/mat.hpp>

#include "core/bag/ros_message.h"

namespace vigil::bag {

// The largest image accepted (as the cam0 readers: at most 2^28 pixels and 65536 px a side).
inline constexpr uint32_t kMaxImageSide = 65536;
inline constexpr int64_t kMaxImagePixels = int64_t{1} << 28;

// A CV_8UC1 image of the message's size; MessageError with the reason ("encoding 'yuv422' is not supported
// (mono8, mono16, rgb8, bgr8, rgba8, bgra8)", "data holds N bytes, step x height needs M", ...).
cv::Mat ToGray8(const ImageMessage& image);

}  // namespace vigil::bag
