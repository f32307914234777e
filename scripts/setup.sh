#!/usr/bin/env bash
# Installs every Debian package hrspace needs to build, test and benchmark.
# Idempotent: when everything is present it prints nothing and exits 0.
set -euo pipefail

packages=(
  g++ cmake ninja-build ccache pkg-config doxygen
  libcgal-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libompl-dev
  python3 python3-matplotlib linux-perf
  chromium chromium-driver python3-selenium
  pybind11-dev python3-dev python3-numpy python3-pytest
  slurm-wlm slurm-client munge
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "hrspace setup: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
