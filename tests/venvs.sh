# Sourced by the test scripts: the pinned Python environments of the test command, one
# function each, so that tests/run_all.sh can make them while cargo compiles and the scripts
# that use them make them on first use (tests/venv.sh: installed once per package list).
source "$(dirname "${BASH_SOURCE[0]}")/venv.sh"

# target/client-venv: the FMI masters and their helpers (tests/clients), and Debian's
# libtbb12, which ecos (ecospy's libecosc.so) links against.
client_venv() {
    local repo="$1"
    ensure_venv "$repo/target/client-venv" fmpy==0.3.32 fmu-manipulation-toolbox==2.0 \
        libcosimpy==0.0.6 moordyn==2.7.2 ecospy==0.7.2 xmlschema==4.3.2 moorpy==1.3.0 \
        dask==2026.8.0 distributed==2026.8.0 numpy pytest
    if ! /sbin/ldconfig -p | grep -q 'libtbb\.so\.12 '; then
        echo "installing libtbb12 (ecospy's libecosc.so needs libtbb.so.12)" >&2
        apt-get install -y -q libtbb12 >/dev/null 2>&1 \
            || { apt-get update -q >/dev/null && apt-get install -y -q libtbb12 >/dev/null; } \
            || { echo "could not install libtbb12 (apt-get, as root)" >&2; return 1; }
    fi
}

# target/bem-venv: Capytaine for the checks of the default platform's data (tests/bem).
bem_venv() {
    local repo="$1"
    ensure_venv "$repo/target/bem-venv" capytaine==3.0.0 pytest
}
