#include "core/bag/bag_file.h"

#include <map>

#include <console_bridge/console.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include "core/error.h"
#include "core/output.h"

namespace vigil::bag {

struct BagFile::Impl {
  rosbag::Bag bag;
};

namespace {

[[noreturn]] void Corrupt(const std::string& path, const std::string& what, const std::string& reason) {
  throw InputError(path + ": " + what + ": " + reason);
}

}  // namespace

BagFile::BagFile(const std::string& path) : path_(path), impl_(std::make_unique<Impl>()) {
  // rosbag_storage reports through console_bridge (stderr); its failures reach vigil as exceptions.
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
  RequireRegularFile(path, UINTMAX_MAX);
  try {
    impl_->bag.open(path, rosbag::bagmode::Read);
  } catch (const std::exception& e) {
    Corrupt(path, "not a readable ROS bag", e.what());
  }
}

BagFile::~BagFile() = default;

std::vector<BagTopic> BagFile::Topics() const {
  std::map<std::string, BagTopic> topics;
  try {
    rosbag::View view(impl_->bag);
    for (const rosbag::ConnectionInfo* c : view.getConnections()) {
      BagTopic& t = topics[c->topic];
      if (t.name.empty()) {
        t = {c->topic, c->datatype, c->md5sum, 0};
      } else if (t.type != c->datatype || t.md5 != c->md5sum) {
        throw InputError(path_ + ": " + c->topic + ": messages of two types (" + t.type + " " + t.md5 + ", " +
                         c->datatype + " " + c->md5sum + ")");
      }
    }
    for (auto& [name, topic] : topics)
      topic.messages = rosbag::View(impl_->bag, rosbag::TopicQuery(name)).size();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    Corrupt(path_, "corrupt ROS bag", e.what());
  }
  std::vector<BagTopic> list;
  for (auto& [name, topic] : topics) list.push_back(std::move(topic));
  return list;
}

void BagFile::ForEach(const std::vector<std::string>& topics,
                      const std::function<void(const BagMessage&)>& visit) const {
  std::map<std::string, std::size_t> counts;
  std::vector<uint8_t> bytes;
  try {
    rosbag::View view(impl_->bag, rosbag::TopicQuery(topics));
    for (const rosbag::MessageInstance& m : view) {
      bytes.resize(m.size());
      ros::serialization::OStream stream(bytes.data(), static_cast<uint32_t>(bytes.size()));
      m.write(stream);
      std::size_t& index = counts[m.getTopic()];
      visit(BagMessage{m.getTopic(), index, bytes});
      ++index;
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    Corrupt(path_, "corrupt ROS bag", e.what());
  }
}

}  // namespace vigil::bag
