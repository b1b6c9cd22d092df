#!/usr/bin/env bash
# Every test: the Rust workspace (unit, integration, FMU ABI), the Python FMI masters
# (fmpy, fmu-manipulation-toolbox, libcosimpy, MoorDyn loop) and the checks of the default
# platform's radiation-diffraction data (Capytaine), each in its own virtual environment.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cargo test --release --workspace
bash tests/clients/run_clients.sh
bash tests/bem/run_bem.sh
