#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (GUI tests under a virtual X server).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" -DMULTIDIR_STRICT=ON
cd "$root/build"
xvfb-run -a -s "-screen 0 1600x1200x24 -noreset" ctest --output-on-failure -j2 --timeout 600
