#!/usr/bin/env bash
# vigil adapter for Basalt's visual-inertial odometry (basalt_vio) on a EuRoC-layout recording.
#
#   run.sh BASALT_VIO CAM_CALIB.json VIO_CONFIG.json RECORDING OUTPUT
#
# BASALT_VIO        the basalt_vio executable of your build: an absolute path, or its name in PATH
# CAM_CALIB.json    Basalt calibration of the recording's camera(s) and IMU (README.md); absolute path
# VIO_CONFIG.json   Basalt VIO configuration (e.g. a copy of Basalt's euroc_config.json); absolute path
# RECORDING         the recording vigil wrote ({recording}: holds mav0/)
# OUTPUT            the output folder ({output}); Basalt writes trajectory.txt (TUM, seconds) into it
#
# vigil runs the command in OUTPUT, so relative paths would resolve there: they are refused.
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

for path in "$calib" "$config"; do
  if [[ "$path" != /* ]]; then
    echo "$0: $path: give an absolute path (the command runs in {output}, not where vigil was started)" >&2
    exit 2
  fi
done
if [[ "$basalt_vio" == */* && "$basalt_vio" != /* ]]; then
  echo "$0: $basalt_vio: give an absolute path or a name in PATH" >&2
  exit 2
fi
for file in "$calib" "$config" "$recording/mav0/cam0/data.csv"; do
  if [[ ! -e "$file" ]]; then
    echo "$0: $file: not found" >&2
    exit 2
  fi
done
first_image=$(sed -n '2p' "$recording/mav0/cam0/data.csv" | cut -d, -f2 | tr -d '\r')
if [[ -z "$first_image" || ! -e "$recording/mav0/cam0/data/$first_image" ]]; then
  echo "$0: $recording has no camera images (Basalt tracks images; run vigil on a dataset with images)" >&2
  exit 2
fi
# Basalt's EuRoC reader always reads two image slots per frame (cam0 and cam1), listed by cam0/data.csv alone:
# cam1's image is looked up as mav0/cam1/data/<cam0's file name>, and cam1/data.csv is never read. The
# calibration decides how many cameras the VIO uses. A vigil recording has cam0 only, so the calibration must
# describe one camera; a two-camera calibration needs cam1 images named as cam0's.
cameras=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["value0"]["intrinsics"]))' "$calib" 2> /dev/null) || {
  echo "$0: $calib: not a Basalt calibration (value0.intrinsics)" >&2
  exit 2
}
if [[ "$cameras" -gt 1 && ! -e "$recording/mav0/cam1/data/$first_image" ]]; then
  echo "$0: $calib describes $cameras cameras, but $recording has no mav0/cam1/data/$first_image" \
    "(vigil records one camera: give a one-camera calibration)" >&2
  exit 2
fi

cd "$output"
"$basalt_vio" --dataset-path "$recording" --dataset-type euroc --cam-calib "$calib" --config-path "$config" \
  --show-gui 0 --save-trajectory tum
