#!/usr/bin/env bash
# README command 1: set up, build, and run the default example (configs/quickstart.yaml).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/iga-run configs/quickstart.yaml "$@"
