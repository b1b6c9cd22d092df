#!/usr/bin/env bash
# Every test: the Rust workspace (unit, integration, FMU ABI) and the Python FMI masters
# (fmpy, fmu-manipulation-toolbox, libcosimpy, MoorDyn loop) in their own virtual environment.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cargo test --release --workspace
bash tests/clients/run_clients.sh
