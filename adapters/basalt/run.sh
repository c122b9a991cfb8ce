#!/usr/bin/env bash
# vigil adapter for Basalt's visual-inertial odometry (basalt_vio) on a EuRoC-layout recording.
#
#   run.sh BASALT_VIO CAM_CALIB.json VIO_CONFIG.json RECORDING OUTPUT
#
# BASALT_VIO        the basalt_vio executable of your build (or its name in PATH)
# CAM_CALIB.json    Basalt calibration of the recording's cameras and IMU (README.md)
# VIO_CONFIG.json   Basalt VIO configuration (e.g. a copy of Basalt's euroc_config.json)
# RECORDING         the recording vigil wrote ({recording}: holds mav0/)
# OUTPUT            the output folder ({output}); Basalt writes trajectory.txt (TUM, seconds) into it
set -euo pipefail

if [[ $# -ne 5 ]]; then
  echo "usage: $0 BASALT_VIO CAM_CALIB.json VIO_CONFIG.json RECORDING OUTPUT" >&2
  exit 2
fi
basalt_vio=$1
calib=$2
config=$3
recording=$4
output=$5

for file in "$calib" "$config" "$recording/mav0/cam0/data.csv"; do
  if [[ ! -e "$file" ]]; then
    echo "$0: $file: not found" >&2
    exit 2
  fi
done
# basalt_vio is a stereo system: its EuRoC reader needs mav0/cam1 besides mav0/cam0. A vigil recording is
# monocular (cam0 only).
if [[ ! -e "$recording/mav0/cam1/data.csv" ]]; then
  echo "$0: $recording has no mav0/cam1 (basalt_vio needs a stereo pair; vigil records one camera)" >&2
  exit 2
fi

cd "$output"
"$basalt_vio" --dataset-path "$recording" --dataset-type euroc --cam-calib "$calib" --config-path "$config" \
  --show-gui 0 --save-trajectory tum
