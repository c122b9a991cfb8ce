#!/usr/bin/python3
"""Writes a ROS 1 bag from a EuRoC folder, for the tests of `vigil import` (tests/app/import_cli_test.cc).

Uses Debian's python3-rosbag; the message classes are generated from their definitions (genpy), so no ROS
message package is needed. The images are read from binary PGM files (data/<stamp>.pgm beside the PNGs, which
the test writes). Options make the bad inputs the tests need: another image encoding, a ground truth of
another type, stamps that go back, a topic of another definition.

  write_bag.py MAV0 BAG [--encoding E] [--groundtruth TYPE] [--swap-imu K] [--compression C]
                        [--imu-topic T] [--image-topic T] [--groundtruth-topic T] [--imu-other-definition]
                        [--quaternion-scale K] [--seconds S]
"""
import argparse
import csv
import os

import genpy
import genpy.dynamic
import rosbag

HEADER = "uint32 seq\ntime stamp\nstring frame_id\n"
VECTOR3 = "float64 x\nfloat64 y\nfloat64 z\n"
QUATERNION = "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n"
DEFINITIONS = {
    "std_msgs/Header": HEADER,
    "geometry_msgs/Vector3": VECTOR3,
    "geometry_msgs/Point": VECTOR3,
    "geometry_msgs/Quaternion": QUATERNION,
    "geometry_msgs/Pose": "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n",
    "geometry_msgs/Transform": "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n",
    "geometry_msgs/Twist": "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n",
    "geometry_msgs/PoseWithCovariance": "geometry_msgs/Pose pose\nfloat64[36] covariance\n",
    "geometry_msgs/TwistWithCovariance": "geometry_msgs/Twist twist\nfloat64[36] covariance\n",
    "sensor_msgs/Imu": "std_msgs/Header header\ngeometry_msgs/Quaternion orientation\n"
                       "float64[9] orientation_covariance\ngeometry_msgs/Vector3 angular_velocity\n"
                       "float64[9] angular_velocity_covariance\ngeometry_msgs/Vector3 linear_acceleration\n"
                       "float64[9] linear_acceleration_covariance\n",
    "sensor_msgs/Image": "std_msgs/Header header\nuint32 height\nuint32 width\nstring encoding\n"
                         "uint8 is_bigendian\nuint32 step\nuint8[] data\n",
    "geometry_msgs/PoseStamped": "std_msgs/Header header\ngeometry_msgs/Pose pose\n",
    "geometry_msgs/TransformStamped": "std_msgs/Header header\nstring child_frame_id\n"
                                      "geometry_msgs/Transform transform\n",
    "geometry_msgs/PointStamped": "std_msgs/Header header\ngeometry_msgs/Point point\n",
    "nav_msgs/Odometry": "std_msgs/Header header\nstring child_frame_id\n"
                         "geometry_msgs/PoseWithCovariance pose\ngeometry_msgs/TwistWithCovariance twist\n",
}


def message_class(name, definition=None):
    """The class of `name`, generated from its definition and those of every type it uses."""
    text = definition or DEFINITIONS[name]
    full = text
    for dep in DEFINITIONS:
        if dep != name:
            full += "\n" + "=" * 80 + "\nMSG: " + dep + "\n" + DEFINITIONS[dep]
    return genpy.dynamic.generate_dynamic(name, full)[name]


def stamp(t_ns):
    return genpy.Time(t_ns // 1000000000, t_ns % 1000000000)


def rows(path):
    with open(path) as f:
        return [r for r in csv.reader(f) if r and not r[0].startswith("#")]


def until(table, end_ns):
    """The rows of `table` stamped before end_ns (all of them when it is None)."""
    return table if end_ns is None else [r for r in table if int(r[0]) < end_ns]


def read_pgm(path):
    data = open(path, "rb").read()
    fields, at = [], 0
    while len(fields) < 4:
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[at:end])
        at = end
    assert fields[0] == b"P5" and fields[3] == b"255", path
    width, height = int(fields[1]), int(fields[2])
    return width, height, data[at + 1:at + 1 + width * height]


def image_bytes(gray, width, encoding):
    """The pixel bytes and the row step of `gray` in `encoding`."""
    if encoding in ("mono8", "yuv422"):
        return gray, width
    channels = {"mono16": 2, "rgb8": 3, "bgr8": 3}[encoding]  # mono16: v16 = 257 v8, either byte order
    out = bytearray(channels * len(gray))
    for c in range(channels):
        out[c::channels] = gray
    return bytes(out), channels * width


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mav0")
    p.add_argument("bag")
    p.add_argument("--encoding", default="mono8")
    p.add_argument("--groundtruth", default="transform",
                   choices=["transform", "pose", "odometry", "point", "none"])
    p.add_argument("--swap-imu", type=int, default=-1, help="swap the stamps of IMU messages K and K+1")
    p.add_argument("--compression", default="none", choices=["none", "bz2", "lz4"])
    p.add_argument("--imu-topic", default="/imu0")
    p.add_argument("--image-topic", default="/cam0/image_raw")
    p.add_argument("--groundtruth-topic", default="/vicon/firefly_sbx/firefly_sbx")
    p.add_argument("--imu-other-definition", action="store_true",
                   help="sensor_msgs/Imu with another definition (another MD5)")
    p.add_argument("--quaternion-scale", type=float, default=1.0,
                   help="the ground truth's quaternions times this (not unit when not 1)")
    p.add_argument("--seconds", type=float, default=0.0,
                   help="only the messages of the first S seconds (0: all); short bags write fast")
    a = p.parse_args()

    imu_definition = None
    if a.imu_other_definition:
        imu_definition = DEFINITIONS["sensor_msgs/Imu"] + "float64 temperature\n"
    Imu = message_class("sensor_msgs/Imu", imu_definition)
    Image = message_class("sensor_msgs/Image")
    records = []  # (record time [ns], topic, message)

    imu = rows(os.path.join(a.mav0, "imu0", "data.csv"))
    end_ns = int(imu[0][0]) + int(a.seconds * 1e9) if a.seconds > 0 else None
    imu = until(imu, end_ns)
    times = [int(r[0]) for r in imu]
    if a.swap_imu >= 0:
        times[a.swap_imu], times[a.swap_imu + 1] = times[a.swap_imu + 1], times[a.swap_imu]
    for k, (r, t) in enumerate(zip(imu, times)):
        m = Imu()
        m.header.seq, m.header.stamp, m.header.frame_id = k, stamp(t), "imu4"
        m.orientation.w = 1.0
        m.angular_velocity.x, m.angular_velocity.y, m.angular_velocity.z = map(float, r[1:4])
        m.linear_acceleration.x, m.linear_acceleration.y, m.linear_acceleration.z = map(float, r[4:7])
        records.append((int(r[0]), a.imu_topic, m))

    cam = os.path.join(a.mav0, "cam0")
    for k, r in enumerate(until(rows(os.path.join(cam, "data.csv")), end_ns)):
        t = int(r[0])
        width, height, gray = read_pgm(os.path.join(cam, "data", r[1].replace(".png", ".pgm")))
        m = Image()
        m.header.seq, m.header.stamp, m.header.frame_id = k, stamp(t), "cam0"
        m.width, m.height, m.encoding, m.is_bigendian = width, height, a.encoding, 0
        m.data, m.step = image_bytes(gray, width, a.encoding)
        records.append((t, a.image_topic, m))

    if a.groundtruth != "none":
        kind = {"transform": "geometry_msgs/TransformStamped", "pose": "geometry_msgs/PoseStamped",
                "odometry": "nav_msgs/Odometry", "point": "geometry_msgs/PointStamped"}[a.groundtruth]
        Pose = message_class(kind)
        gt = until(rows(os.path.join(a.mav0, "state_groundtruth_estimate0", "data.csv")), end_ns)
        for k, r in enumerate(gt):
            t = int(r[0])
            p_w, (qw, qx, qy, qz), v_w = list(map(float, r[1:4])), map(float, r[4:8]), map(float, r[8:11])
            m = Pose()
            m.header.seq, m.header.stamp, m.header.frame_id = k, stamp(t), "world"
            if a.groundtruth == "transform":
                m.child_frame_id = "body"
                m.transform.translation.x, m.transform.translation.y, m.transform.translation.z = p_w
                q = m.transform.rotation
            elif a.groundtruth == "point":
                m.point.x, m.point.y, m.point.z = p_w
                q = None
            else:
                pose = m.pose.pose if a.groundtruth == "odometry" else m.pose
                pose.position.x, pose.position.y, pose.position.z = p_w
                q = pose.orientation
            if q is not None:
                k_q = a.quaternion_scale
                q.w, q.x, q.y, q.z = k_q * qw, k_q * qx, k_q * qy, k_q * qz
            if a.groundtruth == "odometry":  # the twist is in the child (body) frame: R_WB^T v_W
                v = list(v_w)
                r_wb = rotation(qw, qx, qy, qz)
                v_b = [sum(r_wb[i][j] * v[i] for i in range(3)) for j in range(3)]
                m.child_frame_id = "body"
                m.twist.twist.linear.x, m.twist.twist.linear.y, m.twist.twist.linear.z = v_b
            records.append((t, a.groundtruth_topic, m))

    records.sort(key=lambda r: r[0])  # the bag's time order: when each message was recorded
    with rosbag.Bag(a.bag, "w", compression=a.compression) as bag:
        for t, topic, m in records:
            bag.write(topic, m, stamp(t + 1000000000))


def rotation(w, x, y, z):
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


if __name__ == "__main__":
    main()
