#!/usr/bin/env bash
# Checks of the default platform's radiation-diffraction data (issue #14): creates
# target/bem-venv with Capytaine from PyPI on first use and runs pytest on tests/bem.
# The same environment runs the scripts that regenerate the data (docs/bem.md).
# Environment: PYTHON (interpreter for the venv, python3).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
venv="$repo/target/bem-venv"
packages=(capytaine==3.0.0 pytest)
stamp="$venv/.installed"

if [[ ! -x "$venv/bin/python" ]]; then
    echo "run_bem.sh: creating $venv" >&2
    "${PYTHON:-python3}" -m venv "$venv"
fi
if [[ ! -f "$stamp" || "$(cat "$stamp")" != "${packages[*]}" ]]; then
    echo "run_bem.sh: installing ${packages[*]}" >&2
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check "${packages[@]}"
    printf '%s' "${packages[*]}" > "$stamp"
fi
exec "$venv/bin/python" -m pytest -ra "$repo/tests/bem" "$@"
