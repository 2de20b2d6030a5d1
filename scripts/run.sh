#!/usr/bin/env bash
# Builds StrandFEM (Release) and runs the default job: the 7-wire strand of Table 1 under axial strain,
# results in results/seven_wire_axial/. Extra arguments go to `strandfem run`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)"
./build/apps/strandfem run cases/examples/seven_wire_axial.yaml -o results/seven_wire_axial "$@"
