#!/usr/bin/env bash
# Builds OpenVINS's ov_msckf library and vigil's OpenVINS adapter (vigil-openvins) into a cache outside the
# repository, once per OpenVINS commit; prints the adapter's path on the last line of standard output.
#
#   build.sh [SOURCE]       build (or find built) for SOURCE
#   build.sh --print-binary print where the adapter of the pinned commit lives, without building
#
# SOURCE  an OpenVINS tarball made by `git archive` (default: ../shared/peers/open_vins-*.tar.gz beside the
#         repository), or a git clone of OpenVINS. Its commit names the cache folder
#         ${VIGIL_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/vigil}/openvins-<commit[0:8]>; OpenVINS is built
#         there once (600-800 s of CPU, some 5-7 min at -j2 on 2 idle cores) and reused until the commit or
#         the build options change; the adapter is rebuilt when its own sources change (seconds). A commit other than the pinned one builds, with a warning: the CI
#         baseline was recorded with the pinned one.
#   VIGIL_OPENVINS_JOBS  parallel compile jobs (default: nproc)
# Exit status 2 when SOURCE is missing or is neither; 77 when no SOURCE is given and the default is absent.
set -euo pipefail
pinned=69488123ed9362dd44b6f28e7f4680abbff1442b
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
cache_root=${VIGIL_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/vigil}
binary_of() { echo "$cache_root/openvins-${1:0:8}/adapter-build/vigil-openvins"; }

if [[ "${1:-}" == --print-binary ]]; then
  binary_of "$pinned"
  exit 0
fi
if [[ $# -gt 1 ]]; then
  echo "usage: $0 [SOURCE] | --print-binary" >&2
  exit 2
fi
if [[ $# -eq 1 ]]; then
  source=$1
  if [[ ! -e "$source" ]]; then
    echo "$0: $source: not found" >&2
    exit 2
  fi
else
  shopt -s nullglob
  tarballs=("$repo"/../shared/peers/open_vins-*.tar.gz)
  shopt -u nullglob
  if [[ ${#tarballs[@]} -eq 0 ]]; then
    echo "$0: no OpenVINS source given and none at $repo/../shared/peers/open_vins-*.tar.gz" >&2
    exit 77
  fi
  source=${tarballs[-1]}
fi

"$repo/scripts/install-packages" build-essential cmake ninja-build git libeigen3-dev libceres-dev libopencv-dev \
  libboost-system-dev libboost-filesystem-dev libboost-thread-dev libboost-date-time-dev

# The source's commit: a tarball of `git archive` carries it in its header; a clone has it checked out.
if [[ -f "$source" ]]; then
  # (git stops reading after the header, so gzip's broken pipe is not a failure)
  commit=$(set +o pipefail; gzip -dc "$source" 2> /dev/null | git get-tar-commit-id) || commit=""
elif [[ -d "$source/ov_msckf" ]] && git -C "$source" rev-parse --verify -q HEAD > /dev/null; then
  commit=$(git -C "$source" rev-parse HEAD)
  if [[ -n "$(git -C "$source" status --porcelain -- ov_core ov_init ov_msckf)" ]]; then
    echo "$0: $source has uncommitted changes under ov_core/ov_init/ov_msckf; the build takes commit $commit" >&2
  fi
else
  echo "$0: $source is neither an OpenVINS tarball (git archive) nor a git clone holding ov_msckf/" >&2
  exit 2
fi
if [[ ! "$commit" =~ ^[0-9a-f]{40}$ ]]; then
  echo "$0: $source: cannot tell its commit (not a tarball made by git archive)" >&2
  exit 2
fi
if [[ "$commit" != "$pinned" ]]; then
  echo "$0: warning: $source is OpenVINS $commit, not the pinned $pinned (the CI baseline's)" >&2
fi

dir=$cache_root/openvins-${commit:0:8}
mkdir -p "$dir"
exec 9> "$dir/.lock"
flock 9  # one build per cache folder at a time; the others wait and then find it built
jobs=${VIGIL_OPENVINS_JOBS:-$(nproc)}

# How OpenVINS is built, without ROS (the ROS 1 and ROS 2 build systems are not looked for even where they are
# installed) and only its library (no test or ROS programs). OpenVINS's own CMakeLists.txt adds -O3 -g3 to
# every compile; the build type's flags come after it on the command line and win: -O2 without debug info
# (a 7 MB library instead of 294 MB; 600-800 s of CPU, docs/development.md gives the times).
ov_options=(-G Ninja -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -g0 -DNDEBUG"
  -DENABLE_ROS=OFF -DENABLE_ARUCO_TAGS=OFF -DCMAKE_DISABLE_FIND_PACKAGE_catkin=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_ament_cmake=ON)
# The stamp names the commit and the options of a finished build: another stamp (or none) means a new build.
stamp="$commit ${ov_options[*]}"
if [[ "$(cat "$dir/ov-build/.vigil-built" 2> /dev/null)" != "$stamp" ]]; then
  if [[ ! -f "$dir/src/.vigil-unpacked" ]]; then
    rm -rf "$dir/src"
    mkdir -p "$dir/src"
    if [[ -f "$source" ]]; then
      tar -xzf "$source" -C "$dir/src"
    else
      git -C "$source" archive --prefix=open_vins/ "$commit" | tar -x -C "$dir/src"
    fi
    touch "$dir/src/.vigil-unpacked"
  fi
  rm -rf "$dir/ov-build" "$dir/adapter-build"
  echo "$0: building OpenVINS $commit (ov_msckf_lib) in $dir/ov-build, $jobs jobs" >&2
  start=$SECONDS
  cmake -S "$dir/src/open_vins/ov_msckf" -B "$dir/ov-build" "${ov_options[@]}" > "$dir/ov-configure.log"
  nice -n 10 cmake --build "$dir/ov-build" -j "$jobs" --target ov_msckf_lib > "$dir/ov-build.log" ||
    { tail -n 30 "$dir/ov-build.log" >&2; exit 1; }
  echo "$stamp" > "$dir/ov-build/.vigil-built"
  echo "$0: OpenVINS built in $((SECONDS - start)) s" >&2
fi

# The adapter's build belongs to one clone's sources: a build configured from another clone (a CI checkout,
# a worktree) is made again from this one (seconds).
if [[ -f "$dir/adapter-build/CMakeCache.txt" ]] &&
  ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$here" "$dir/adapter-build/CMakeCache.txt"; then
  rm -rf "$dir/adapter-build"
fi
cmake -S "$here" -B "$dir/adapter-build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DOPENVINS_SOURCE_DIR="$dir/src/open_vins" -DOPENVINS_BUILD_DIR="$dir/ov-build" > "$dir/adapter-configure.log"
cmake --build "$dir/adapter-build" -j "$jobs" > "$dir/adapter-build.log" ||
  { tail -n 30 "$dir/adapter-build.log" >&2; exit 1; }
binary_of "$commit"
