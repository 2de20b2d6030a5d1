#!/usr/bin/env bash
# Builds StrandFEM (Release), makes `import strandfem` work in Debian's Python (/usr/bin/python3) from any folder, and
# runs the default job: the 7-wire strand of Table 1 with frictional wire contact pulled to 0.8 % axial strain,
# results in results/seven_wire_fixed/. Extra arguments go to `strandfem run`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)"
# `import strandfem` in Debian's Python from any folder: its user site points at the package in the build.
site="$(/usr/bin/python3 -m site --user-site)"
mkdir -p "$site" && echo "$PWD/build/python" > "$site/strandfem.pth"
./build/apps/strandfem run cases/paper/seven_wire_fixed.yaml -o results/seven_wire_fixed "$@"
