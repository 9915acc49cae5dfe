#!/usr/bin/env bash
# Installs what is missing, builds, and opens MultiDir Studio on the built-in sample model
# (or on the model given as the first argument).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
exec "$root/build/app/multidir-studio" "$@"
