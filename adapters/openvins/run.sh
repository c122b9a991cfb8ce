#!/usr/bin/env bash
# vigil's OpenVINS adapter as an external estimator command: runs vigil-openvins, which build.sh built for the
# pinned OpenVINS commit, with the given arguments (README.md):
#
#   run.sh RECORDING TRAJECTORY [--init openvins|groundtruth] [--gravity M_S2] [--pixel-sigma PX] [--verbosity L]
set -euo pipefail
binary=$("$(dirname "$0")/build.sh" --print-binary)
if [[ ! -x "$binary" ]]; then
  echo "$0: $binary is not built: run adapters/openvins/build.sh first" >&2
  exit 2
fi
exec "$binary" "$@"
