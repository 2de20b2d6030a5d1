#!/usr/bin/env bash
# Builds StrandFEM (Release) and runs the default job: the 7-wire strand of Table 1 with frictional wire
# contact pulled to 0.8 % axial strain, results in results/seven_wire_fixed/. Extra arguments go to
# `strandfem run`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)"
./build/apps/strandfem run cases/paper/seven_wire_fixed.yaml -o results/seven_wire_fixed "$@"
