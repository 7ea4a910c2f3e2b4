#!/usr/bin/env bash
# Installs what vibro needs from Debian's packages (apt-get, as root or through sudo) and
# builds it into build/, and installs the Python module `vibro` for Debian's /usr/bin/python3
# (python/CMakeLists.txt). Usage: scripts/setup.sh [--test]  (--test adds what the tests need).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make pkg-config libeigen3-dev libosmesa6-dev libcairo2-dev libdeflate-dev
          nlohmann-json3-dev libcpp-httplib-dev libgtest-dev librapidcheck-dev fonts-dejavu-core
          openmpi-bin libopenmpi-dev libcli11-dev ccache
          python3-dev pybind11-dev python3-pybind11 python3-numpy)
if [[ "${1:-}" == "--test" ]]; then
  packages+=(libbenchmark-dev python3-scipy chromium curl jq nginx zlib1g-dev clang-format
             python3-pytest python3-matplotlib python3-pandas)
  # The base image ships Node.js (with npm) from its own packages; Debian's would conflict.
  command -v node > /dev/null || packages+=(nodejs)
  command -v npm > /dev/null || packages+=(npm)
fi

bash scripts/install_packages.sh setup "${packages[@]}"

# ccache makes a rebuild of an unchanged tree (a second clone, CI) take seconds. A first build
# takes minutes: its percentage shows as it goes, the whole output goes to build.log.
echo "setup: configuring build/ (the log: build.log)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
  -DCMAKE_C_COMPILER_LAUNCHER=ccache > build.log 2>&1 || { cat build.log; exit 1; }
echo "setup: building on $(nproc) cores (a first build takes some minutes)"
cmake --build build -j"$(nproc)" 2>&1 | bash scripts/build_progress.sh setup build.log \
  || { tail -50 build.log; exit 1; }
# `import vibro` for /usr/bin/python3 in any shell: the package goes into its site-packages
# (/usr/local/lib/python3.X/dist-packages), which needs root.
sudo=""
[[ $(id -u) -ne 0 ]] && sudo="sudo"
$sudo cmake --install build --component python >> build.log 2>&1 || { tail -20 build.log; exit 1; }
echo "setup: built build/vibro; installed the Python module vibro for /usr/bin/python3"
