#!/usr/bin/env bash
# Checks of the default platform's radiation-diffraction data: creates
# target/bem-venv with Capytaine from PyPI on first use and runs pytest on tests/bem.
# The same environment runs the scripts that regenerate the data (docs/bem.md).
# Environment: PYTHON (interpreter for the venv, python3).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
venv="$repo/target/bem-venv"
source "$repo/tests/venvs.sh"
bem_venv "$repo"
exec "$venv/bin/python" -m pytest -ra "$repo/tests/bem" "$@"
