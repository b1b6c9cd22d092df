#!/usr/bin/env bash
# Python client tests of SlowDrift.fmu and the coupled system: fmpy,
# fmu-manipulation-toolbox, libcosimpy, ecospy, the closed mooring loop with MoorDyn and the
# masters running target/fmu/system/. Creates target/client-venv from PyPI on first use and
# installs Debian's libtbb12 (ecos needs it) when missing (tests/venvs.sh), (re)builds the
# FMUs and the system folder with fmu-pack unless SLOWDRIFT_FMU names a packed FMU (as
# tests/run_all.sh does after packing it once), runs pytest on tests/clients.
#   tests/clients/run_clients.sh              # all client tests
#   tests/clients/run_clients.sh -k mooring   # extra arguments go to pytest
# Environment: SLOWDRIFT_FMU (another FMU file: no packing), SLOWDRIFT_CLI (the slowdrift
# executable to run as the native tool, as tests/run_all.sh gives the one `cargo test` built;
# unset: built once by cargo), SLOWDRIFT_USER_FMU (tests/data/example.toml packed by
# `fmu-pack --config`, as tests/run_all.sh packs it; unset: the user-FMU tests pack it),
# PYTHON (interpreter for the venv, python3), CARGO_TARGET_DIR
# (where fmu-pack writes the FMU).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$repo"

venv="$repo/target/client-venv"
source "$repo/tests/venvs.sh"
client_venv "$repo"

if [[ -z "${SLOWDRIFT_FMU:-}" ]]; then
    # Always pack the current sources (cargo only rebuilds what changed); fmu-pack checks
    # the archive by running it and removes it when that check fails.
    cargo run --release -p fmu-pack
fi
# fmu-pack writes into cargo's target directory: $CARGO_TARGET_DIR when set (relative to the
# workspace root, as cargo reads it here), else target/.
target_dir="${CARGO_TARGET_DIR:-$repo/target}"
[[ "$target_dir" = /* ]] || target_dir="$repo/$target_dir"
fmu="${SLOWDRIFT_FMU:-$target_dir/fmu/SlowDrift.fmu}"
if [[ ! -f "$fmu" ]]; then
    echo "run_clients.sh: $fmu is missing" >&2
    exit 1
fi

# libcosim unpacks FMUs under the first of $TMPDIR, $TMP, $TEMP, $TEMPDIR that is set and
# cannot fall back when it does not exist (fmpy's Python tempfile can): give every master a
# temporary directory that exists.
export TMPDIR="$target_dir/client-tmp"
mkdir -p "$TMPDIR"

export SLOWDRIFT_FMU="$fmu"
export SLOWDRIFT_REQUIRE_FMU=1
# exec: pytest's exit status is the script's.
exec "$venv/bin/python" -m pytest -ra "$repo/tests/clients" "$@"
