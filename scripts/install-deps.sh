#!/usr/bin/env bash
# Installs every Debian 12 package MultiDir needs to build, test and run. Idempotent: a second run
# finds nothing missing and only checks. Needs root (or sudo) for apt-get.
# --sanitizers also installs clang and its runtimes, for scripts/fuzz.sh and scripts/thread-sanitizer.sh.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  qt6-base-dev libqt6opengl6-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-charts-dev
  qt6-translations-l10n
  libvtk9-dev libopenmesh-dev libeigen3-dev libmodbus-dev nlohmann-json3-dev libcpp-httplib-dev
  libcgal-dev libgmp-dev libmpfr-dev lib3mf-dev zlib1g-dev libtbb-dev
  libgtest-dev libgmock-dev
  libgoogle-perftools-dev
  xvfb xauth libgl1-mesa-dri
  prusa-slicer
)
if [ "${1:-}" = "--sanitizers" ]; then
  packages+=(clang libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

echo "install-deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
