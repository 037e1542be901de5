#!/usr/bin/env bash
# Installs the Debian 12 packages mrsim needs, only those that are missing. Idempotent.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config git
  libeigen3-dev libyaml-cpp-dev libvtk9-dev libhdf5-dev zlib1g-dev
  libcli11-dev libvalijson-dev nlohmann-json3-dev libgmsh-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-h5py python3-vtk9 python3-jsonschema python3-numpy python3-matplotlib python3-yaml
  xvfb xauth
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} Debian packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
