#!/usr/bin/env bash
# vigil adapter for OpenVINS (ov_msckf) through its ROS 1 serial launch file, which reads a rosbag.
#
#   run.sh CONFIG RECORDING OUTPUT
#
# CONFIG     the OpenVINS config folder name or path, as serial.launch's `config:=` takes it (README.md)
# RECORDING  the recording vigil wrote ({recording}: holds mav0/)
# OUTPUT     the output folder ({output}); OpenVINS writes traj_estimate.txt (seconds, TUM order + covariance)
#
# Needs a sourced ROS 1 workspace with ov_msckf built (roslaunch in PATH) and Kalibr's kalibr_bagcreater,
# which turns the image folder and IMU csv into a rosbag (topics /cam0/image_raw and /imu0).
set -euo pipefail

if [[ $# -ne 3 ]]; then
  echo "usage: $0 CONFIG RECORDING OUTPUT" >&2
  exit 2
fi
config=$1
recording=$2
output=$3

for program in roslaunch kalibr_bagcreater; do
  if ! command -v "$program" > /dev/null; then
    echo "$0: $program not found in PATH (source your ROS workspace)" >&2
    exit 2
  fi
done
first_image=$(sed -n '2p' "$recording/mav0/cam0/data.csv" | cut -d, -f2 | tr -d '\r')
if [[ -z "$first_image" || ! -e "$recording/mav0/cam0/data/$first_image" ]]; then
  echo "$0: $recording has no camera images (OpenVINS tracks images; run vigil on a dataset with images)" >&2
  exit 2
fi

# Kalibr's bag creator reads DIR/cam0/<timestamp>.png and DIR/imu0.csv (the EuRoC imu0 columns).
staging="$output/bag_input"
mkdir -p "$staging/cam0"
for image in "$recording"/mav0/cam0/data/*.png; do
  ln -s "$(readlink -f "$image")" "$staging/cam0/$(basename "$image")"
done
cp "$recording/mav0/imu0/data.csv" "$staging/imu0.csv"
kalibr_bagcreater --folder "$staging" --output-bag "$output/recording.bag"

# A monocular run (vigil records one camera), saving the estimated path without a live viewer.
roslaunch ov_msckf serial.launch "config:=$config" "bag:=$output/recording.bag" bag_start:=0 \
  max_cameras:=1 use_stereo:=false dolivetraj:=false dosave:=true "path_est:=$output/traj_estimate.txt"
