#!/usr/bin/env bash
# build.sh: configure and build wallload in build/ (Release; CUDA backend when
# nvcc is found). Extra arguments go to CMake's configure step.
set -eu
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j "$(nproc)"
