"""SlowDrift.fmu through fmu-manipulation-toolbox 2.0's checker:
`fmutool -input SlowDrift.fmu -summary -check`.

Its output (stdout) is one log record per line, `LEVEL    | message`. The checks are the FMI
2.0 XSD validation ("This FMU seems to be compliant with FMI-2.0." or ERROR lines and "This
FMU does not validate with FMI standard.") and the semantic checks ("No semantic error
against the FMI-2 standard." or one ERROR line per finding and "N semantic error(s)"); at the
end "-check: N error(s) found." and a non-zero exit status when anything failed. The test
fails on any ERROR or WARNING line, a non-zero status or a missing success line. A control
run on a deliberately broken copy shows that this parsing does see failures.
"""

import os
import shutil
import subprocess
import sys
import tempfile
import zipfile

import pytest

FMUTOOL = os.path.join(os.path.dirname(sys.executable), "fmutool")


def run_fmutool(path):
    proc = subprocess.run([FMUTOOL, "-input", path, "-summary", "-check"],
                          capture_output=True, text=True, timeout=120)
    lines = (proc.stdout + proc.stderr).splitlines()
    levels = [line.split("|", 1)[0].strip() for line in lines if "|" in line]
    return proc.returncode, lines, levels


def test_fmutool_check(fmu):
    assert os.path.isfile(FMUTOOL), f"{FMUTOOL} missing (fmu-manipulation-toolbox not installed)"
    status, lines, levels = run_fmutool(fmu)
    text = "\n".join(lines)
    print("\n" + text)
    bad = [line for line in lines if line.startswith(("ERROR", "WARNING", "CRITICAL"))]
    assert not bad, "\n".join(bad)
    assert status == 0, text
    assert "This FMU seems to be compliant with FMI-2.0." in text
    assert "No semantic error against the FMI-2 standard." in text
    # The summary read the FMU: the ports of its modelDescription.xml, counted here.
    with zipfile.ZipFile(fmu) as archive:
        xml = archive.read("modelDescription.xml").decode()
    counts = {c: xml.count(f'causality="{c}"') for c in ("parameter", "input", "output")}
    assert all(counts.values()), counts
    for causality, count in counts.items():
        assert f"{causality} : {count}" in text, (causality, count)
    assert set(levels) <= {"INFO"}, set(levels)


@pytest.fixture
def broken_fmu(fmu):
    """A copy whose inputs claim variability "fixed" (illegal for causality "input") and
    whose first Real carries an attribute the XSD does not allow."""
    d = tempfile.mkdtemp(prefix="slowdrift-fmutool-")
    path = os.path.join(d, "broken.fmu")
    with zipfile.ZipFile(fmu) as src, zipfile.ZipFile(path, "w") as dst:
        for item in src.infolist():
            data = src.read(item.filename)
            if item.filename == "modelDescription.xml":
                data = data.replace(b'causality="input" variability="continuous"',
                                    b'causality="input" variability="fixed"')
                data = data.replace(b'start="7"/>', b'start="7" bogus="1"/>', 1)
            dst.writestr(item, data)
    yield path
    shutil.rmtree(d, ignore_errors=True)


def test_fmutool_reports_a_broken_copy(broken_fmu):
    status, lines, _ = run_fmutool(broken_fmu)
    errors = [line for line in lines if line.startswith("ERROR")]
    text = "\n".join(errors)
    assert status != 0
    assert "This FMU does not validate with FMI standard." in text
    assert "bogus" in text
    # Fx_ext, Fy_ext, Mz_ext and windVelocity_ext.
    assert sum("causality='input' and variability='fixed'" in e for e in errors) == 4, text
