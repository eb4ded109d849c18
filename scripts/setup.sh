#!/usr/bin/env bash
# Installs what tumble needs to build and test, from Debian 12's own packages. Safe to re-run:
# it installs only what is missing.
set -euo pipefail
packages=(
  g++ cmake ninja-build pkg-config clang-format clang libclang-rt-14-dev
  libeigen3-dev libyaml-cpp-dev libfmt-dev libcli11-dev libmuparser-dev libboost-dev
  libgtest-dev libgmock-dev libbenchmark-dev libmujoco-dev
  libopenmpi-dev openmpi-bin
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib python3-pandas
  chromium gnuplot-nox ffmpeg
)
# Node.js and npm build the animation page. A machine may already have them from elsewhere
# (nodesource's nodejs carries its own npm); install Debian's only where the commands are missing.
command -v node >/dev/null 2>&1 || packages+=(nodejs)
command -v npm >/dev/null 2>&1 || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
