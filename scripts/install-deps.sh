#!/usr/bin/env bash
# Installs StrandFEM's build and test dependencies from Debian's archive (bookworm). Idempotent.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libsuitesparse-dev libmumps-seq-dev libmumps-dev libopenmpi-dev openmpi-bin libmetis-dev
  libopenblas0-pthread libopenblas-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-matplotlib python3-numpy python3-yaml
  python3-dev pybind11-dev python3-pandas python3-mpi4py python3-pytest
)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
