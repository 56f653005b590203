#!/usr/bin/env bash
# Installs what silodem needs from Debian 12's packages (as root; uses sudo otherwise).
#   g++ cmake make          build
#   libtomlplusplus-dev     case files (TOML)
#   libcli11-dev            command line
#   libfmt-dev              formatting
#   nlohmann-json3-dev      reading summary.json back (study, calibrate): toml++ writes JSON only
#   libgtest-dev            tests (GoogleTest)
#   libbenchmark-dev        benchmarks (Google Benchmark)
#   clang-format            format check in CI
#   python3                 end-to-end test scripts (stdlib only)
#   python3-matplotlib      figures and report.html of a run (tools/*.py; Debian's /usr/bin/python3)
#   python3-vtk9            tests read the ParaView files back with the real VTK library
#   clang-14 libclang-rt-14-dev libomp-14-dev   the libFuzzer target over the case loader, and the
#                           ThreadSanitizer job (LLVM's OpenMP with its Archer tool) (CI)
set -euo pipefail
pkgs=(g++ cmake make libtomlplusplus-dev libcli11-dev libfmt-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
      clang-format python3 python3-matplotlib python3-vtk9 clang-14 libclang-rt-14-dev
      libomp-14-dev)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all installed"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${missing[@]}"
