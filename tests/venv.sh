# Sourced by the test scripts: ensure_venv VENV PACKAGE... creates the virtual environment
# VENV (with $PYTHON, default python3) on first use and installs the pinned PACKAGEs from PyPI
# whenever the list changes (VENV/.installed holds the list that was installed).
ensure_venv() {
    local venv="$1"
    shift
    local stamp="$venv/.installed"
    if [[ ! -x "$venv/bin/python" ]]; then
        echo "creating $venv" >&2
        "${PYTHON:-python3}" -m venv "$venv"
    fi
    if [[ ! -f "$stamp" || "$(cat "$stamp")" != "$*" ]]; then
        echo "installing $* into $venv" >&2
        "$venv/bin/python" -m pip install --quiet --disable-pip-version-check "$@"
        printf '%s' "$*" > "$stamp"
    fi
}
