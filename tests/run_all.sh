#!/usr/bin/env bash
# Every test: the Rust workspace (unit, integration, FMU ABI), the Python FMI masters
# (fmpy, fmu-manipulation-toolbox, libcosimpy, ecospy, the MoorDyn loop, the coupled system)
# and the checks of the default platform's radiation-diffraction data (Capytaine), each in
# its own virtual environment. Each artefact is built once: fmu-pack builds and checks the
# FMUs and the system folder, which the Python masters then use as they are; the Python
# environments are installed from PyPI while cargo compiles.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
repo="$(pwd)"
source tests/venvs.sh

venv_log="$repo/target/venvs.log"
mkdir -p target
( client_venv "$repo" && bem_venv "$repo" ) >"$venv_log" 2>&1 &
venvs=$!

target_dir="${CARGO_TARGET_DIR:-$repo/target}"
[[ "$target_dir" = /* ]] || target_dir="$repo/$target_dir"
cargo run --release -p fmu-pack
# The user-FMU clients' FMU (tests/data/example.toml, and its FMI 3.0 twin beside it in
# fmi3/), packed now by the fmu-pack just built: after `cargo test` (the library with the
# CLI's features, the same cdylib file) fmu-pack would compile the library again (~50 s).
user_fmu="$target_dir/fmu/user/example.fmu"
cargo run --release -p fmu-pack -- --config tests/data/example.toml --out "$user_fmu"
cargo test --release --workspace

if ! wait "$venvs"; then
    cat "$venv_log" >&2
    echo "run_all.sh: the Python environments could not be made (log above)" >&2
    exit 1
fi
# The CLI `cargo test` built (its integration tests ran it), used as it is: a `cargo build`
# of it here would recompile the crate with another feature set.
SLOWDRIFT_FMU="$target_dir/fmu/SlowDrift.fmu" SLOWDRIFT_CLI="$target_dir/release/slowdrift" \
    SLOWDRIFT_USER_FMU="$user_fmu" bash tests/clients/run_clients.sh
bash tests/bem/run_bem.sh
