#!/usr/bin/env bash
# vigil adapter for ORB-SLAM3's monocular-inertial EuRoC example (mono_inertial_euroc).
#
#   run.sh ORB_SLAM3_DIR SETTINGS.yaml RECORDING OUTPUT
#
# ORB_SLAM3_DIR  your built ORB_SLAM3 checkout (Examples/Monocular-Inertial/mono_inertial_euroc, Vocabulary/)
# SETTINGS.yaml  an ORB-SLAM3 settings file describing vigil's camera and IMU (README.md)
# RECORDING      the recording vigil wrote ({recording}: holds mav0/)
# OUTPUT         the output folder ({output}); ORB-SLAM3 writes f_vigil.txt (every frame) and kf_vigil.txt
set -euo pipefail

if [[ $# -ne 4 ]]; then
  echo "usage: $0 ORB_SLAM3_DIR SETTINGS.yaml RECORDING OUTPUT" >&2
  exit 2
fi
orb_dir=$1
settings=$2
recording=$3
output=$4

program="$orb_dir/Examples/Monocular-Inertial/mono_inertial_euroc"
vocabulary="$orb_dir/Vocabulary/ORBvoc.txt"
for file in "$program" "$vocabulary" "$settings" "$recording/mav0/cam0/data.csv"; do
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

# The image timestamps file of the EuRoC example: one timestamp [ns] per line.
times="$output/cam0_times.txt"
tail -n +2 "$recording/mav0/cam0/data.csv" | cut -d, -f1 > "$times"

# The example opens a viewer window; without a display, run it under a virtual one when available.
launcher=()
if [[ -z "${DISPLAY:-}" ]] && command -v xvfb-run > /dev/null; then
  launcher=(xvfb-run -a)
fi

cd "$output"
"${launcher[@]}" "$program" "$vocabulary" "$settings" "$recording" "$times" vigil
