#!/usr/bin/env bash
# setup.sh: install the Debian packages wallload needs to build and test, and
# only those that are missing. Idempotent; silent when everything is present.
#
#   usage: scripts/setup.sh            (as root, or with sudo available)
#
# Build:   gcc, cmake, pkg-config, GSL, libyaml, cairo (+pango), HDF5, OpenMP (libgomp
#          comes with gcc), Open MPI (libopenmpi-dev; openmpi-bin: mpirun, for
#          `mpirun -np N wallload sweep` and its tests; the build works without them).
# Tests:   poppler-utils (pdfinfo, pdftotext, pdftoppm check the PDF report), python3
#          (the command-line tests read summary.json and the CSV files with it).
# Fuzzing: clang (clang-14), libclang-rt-14-dev (libFuzzer and the sanitizer runtimes
#          for clang: libclang_rt.fuzzer-x86_64.a; clang only recommends it) and
#          libomp-14-dev (OpenMP for clang: omp.h, libomp) for scripts/fuzz.sh.
# CUDA is optional: where nvcc is on the PATH or in /usr/local/cuda, the CUDA backend
# is compiled; it is never installed from here.
set -eu

packages="build-essential cmake pkg-config libgsl-dev libyaml-dev libcairo2-dev
libpango1.0-dev libhdf5-dev libopenmpi-dev openmpi-bin poppler-utils python3 clang
libclang-rt-14-dev libomp-14-dev"

missing=""
for p in $packages; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $p"
  fi
done
[ -z "$missing" ] && exit 0

echo "setup: installing$missing" >&2
if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq >/dev/null
# shellcheck disable=SC2086
$sudo apt-get install -y -qq --no-install-recommends $missing >/dev/null
echo "setup: done" >&2
