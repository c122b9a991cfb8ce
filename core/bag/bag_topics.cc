#include "core/bag/bag_topics.h"

#include <vector>

#include "core/bag/ros_message.h"
#include "core/error.h"

namespace vigil::bag {
namespace {

const BagTopic* FindTopic(const std::vector<BagTopic>& topics, const std::string& name) {
  for (const BagTopic& t : topics)
    if (t.name == name) return &t;
  return nullptr;
}

std::string TopicList(const std::vector<BagTopic>& topics) {
  std::string list;
  for (const BagTopic& t : topics) list += (list.empty() ? "" : ", ") + t.name + " (" + t.type + ")";
  return list.empty() ? "none" : list;
}

const BagTopic& RequireTopic(const BagFile& bag, const std::vector<BagTopic>& topics, const std::string& name,
                             const std::string& option) {
  const BagTopic* topic = FindTopic(topics, name);
  if (topic == nullptr)
    throw InputError(bag.path() + ": " + name + ": no such topic (" + option +
                     "; the bag's topics: " + TopicList(topics) + ")");
  if (topic->messages == 0) throw InputError(bag.path() + ": " + name + ": the topic has no messages");
  return *topic;
}

void RequireType(const BagFile& bag, const BagTopic& topic, const RosType& type, const std::string& option) {
  if (topic.type != type.name)
    throw InputError(bag.path() + ": " + topic.name + ": " + topic.type + " messages, " + option + " needs " +
                     type.name);
  if (topic.md5 != type.md5)
    throw InputError(bag.path() + ": " + topic.name + ": " + topic.type + " of another definition (MD5 " +
                     topic.md5 + ", vigil reads " + type.md5 + ")");
}

}  // namespace

ImportTopics ResolveTopics(const BagImportRequest& request, const BagPreset& preset, const BagFile& bag) {
  const std::vector<BagTopic> topics = bag.Topics();
  ImportTopics t;
  t.imu = request.imu_topic.empty() ? preset.imu_topic : request.imu_topic;
  const BagTopic& imu = RequireTopic(bag, topics, t.imu, "--imu-topic");
  RequireType(bag, imu, kImuType, "--imu-topic");
  t.messages = imu.messages;
  t.image = request.image_topic.empty() ? preset.image_topic : request.image_topic;
  if (t.image == kNoTopic) {
    t.image.clear();
  } else {
    const BagTopic& image = RequireTopic(bag, topics, t.image, "--image-topic");
    RequireType(bag, image, kImageType, "--image-topic");
    t.messages += image.messages;
  }
  t.groundtruth = request.groundtruth_topic.empty() ? preset.groundtruth_topic : request.groundtruth_topic;
  if (t.groundtruth == kNoTopic) {
    t.groundtruth.clear();
    return t;
  }
  // The preset's ground truth is optional (EuRoC's Machine Hall bags have none); a named one is required.
  if (request.groundtruth_topic.empty() && FindTopic(topics, t.groundtruth) == nullptr) {
    t.groundtruth_note = "no ground truth (the bag has no " + t.groundtruth + "; see --groundtruth-topic)";
    t.groundtruth.clear();
    return t;
  }
  const BagTopic& gt = RequireTopic(bag, topics, t.groundtruth, "--groundtruth-topic");
  std::string md5;
  if (!IsPoseType(gt.type, &md5))
    throw InputError(
        bag.path() + ": " + gt.name + ": " + gt.type +
        " messages, a ground truth needs a pose with its orientation (geometry_msgs/PoseStamped, "
        "geometry_msgs/TransformStamped or nav_msgs/Odometry)");
  RequireType(bag, gt, RosType{gt.type.c_str(), md5.c_str()}, "--groundtruth-topic");
  t.groundtruth_type = gt.type;
  t.messages += gt.messages;
  return t;
}

}  // namespace vigil::bag
