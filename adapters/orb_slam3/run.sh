#!/usr/bin/env bash
# vigil adapter for ORB-SLAM3's monocular-inertial EuRoC example (mono_inertial_euroc).
#
#   run.sh ORB_SLAM3_DIR SETTINGS.yaml RECORDING OUTPUT
#
# ORB_SLAM3_DIR  your built ORB_SLAM3 checkout (Examples/Monocular-Inertial/mono_inertial_euroc, Vocabulary/);
#                an absolute path (vigil runs the command in OUTPUT, where a relative path means nothing)
# SETTINGS.yaml  an ORB-SLAM3 settings file describing vigil's camera and IMU (README.md); absolute
# RECORDING      the recording vigil wrote ({recording}: holds mav0/)
# OUTPUT         the output folder ({output}); the frames' trajectory ends up as OUTPUT/trajectory.txt
#
# ORB-SLAM3 names its output after the last argument: `vigil_frames.txt` (v1.0) or `f_vigil.txt` (the 0.x
# betas); the script copies whichever was written to trajectory.txt (time in ns, TUM order).
set -euo pipefail

if [[ $# -ne 4 ]]; then
  echo "usage: $0 ORB_SLAM3_DIR SETTINGS.yaml RECORDING OUTPUT" >&2
  exit 2
fi
for path in "$1" "$2"; do
  if [[ "$path" != /* ]]; then
    echo "$0: $path: give an absolute path (the command runs in {output}, not where vigil was started)" >&2
    exit 2
  fi
done
orb_dir=$1
settings=$2
recording=$3
output=$4

program="$orb_dir/Examples/Monocular-Inertial/mono_inertial_euroc"
vocabulary="$orb_dir/Vocabulary/ORBvoc.txt"
for file in "$program" "$vocabulary" "$settings" "$recording/mav0/cam0/data.csv" "$recording/mav0/imu0/data.csv"; do
  if [[ ! -e "$file" ]]; then
    echo "$0: $file: not found" >&2
    exit 2
  fi
done
# ORB-SLAM3 needs the camera images, which a simulated vigil run does not have (feature tracks only).
first_image=$(sed -n '2p' "$recording/mav0/cam0/data.csv" | cut -d, -f2 | tr -d '\r')
if [[ -z "$first_image" || ! -e "$recording/mav0/cam0/data/$first_image" ]]; then
  echo "$0: $recording has no camera images (ORB-SLAM3 tracks images; run vigil on a dataset with images)" >&2
  exit 2
fi

# The image timestamps file of the EuRoC example: one timestamp [ns] per line. The example collects the IMU
# samples up to each frame with no bound on the IMU vector, so a frame at or after the last IMU sample makes
# it read past the end (a simulated recording's last frame falls on its last sample): such frames are left
# out.
last_imu=$(grep -v '^#' "$recording/mav0/imu0/data.csv" | tail -n 1 | cut -d, -f1 | tr -d '\r')
times="$output/cam0_times.txt"
tail -n +2 "$recording/mav0/cam0/data.csv" | cut -d, -f1 | tr -d '\r' |
  awk -v last="$last_imu" 'length($1) < length(last) || (length($1) == length(last) && $1 < last)' > "$times"
if [[ ! -s "$times" ]]; then
  echo "$0: $recording: no camera frame before the last IMU sample" >&2
  exit 2
fi

# The example opens a viewer window; without a display, run it under a virtual one when available.
launcher=()
if [[ -z "${DISPLAY:-}" ]] && command -v xvfb-run > /dev/null; then
  launcher=(xvfb-run -a)
fi

cd "$output"
"${launcher[@]}" "$program" "$vocabulary" "$settings" "$recording" "$times" vigil
for name in vigil_frames.txt f_vigil.txt; do
  if [[ -s "$name" ]]; then
    cp "$name" trajectory.txt
    exit 0
  fi
done
echo "$0: ORB-SLAM3 wrote neither vigil_frames.txt nor f_vigil.txt in $output" >&2
exit 1
