// A ROS 1 bag file (format 2.0) opened for reading through Debian's rosbag_storage, which reads the container
// (chunks, bz2 / lz4 compression, the index); the messages come out as their serialized bytes, which
// core/bag/ros_message.h decodes. rosbag_storage's own log output is silenced and every failure it reports
// (not a bag, a truncated file without its index, a corrupt chunk) becomes one InputError naming the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vigil::bag {

// One topic of the bag: its message type and the MD5 sum of the type's definition.
struct BagTopic {
  std::string name, type, md5;
  std::size_t messages = 0;
};

// One message handed to BagFile::ForEach: its topic, its index among that topic's messages (0-based, in the
// bag's time order) and its serialized bytes.
struct BagMessage {
  const std::string& topic;
  std::size_t index;
  const std::vector<uint8_t>& bytes;
};

class BagFile {
 public:
  // Opens `path` (a regular file); InputError "PATH: not a readable ROS bag: REASON".
  explicit BagFile(const std::string& path);
  ~BagFile();
  BagFile(const BagFile&) = delete;
  BagFile& operator=(const BagFile&) = delete;

  const std::string& path() const { return path_; }
  // Every topic, sorted by name. InputError "PATH: TOPIC: messages of two types (A, B)" for a topic whose
  // connections disagree on the type or its MD5.
  std::vector<BagTopic> Topics() const;
  // Calls `visit` for every message of `topics`, in the bag's time order. An InputError from `visit` passes
  // through; any failure of the container is InputError "PATH: corrupt ROS bag: REASON".
  void ForEach(const std::vector<std::string>& topics,
               const std::function<void(const BagMessage&)>& visit) const;

 private:
  struct Impl;
  std::string path_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vigil::bag
