"""The coupled system's description files, as fmu-pack writes them into
target/fmu/system/: SlowDrift_OspModelDescription.xml and Mooring_OspModelDescription.xml
(OSP variable groups), OspSystemStructure.xml (OSP, libcosim and ecos) and MooredPlatform.ssp
(SSP 1.0: SystemStructure.ssd and the two FMUs).

1. Schemas: the OSP model descriptions against OSP-IS's OspModelDescription 1.0.1 schema
   (tests/clients/schema/, from the osp-validator repository), OspSystemStructure.xml against
   the schema compiled into libcosimc (the master's own), the SSD against fmpy's SSP 1.0
   schemas.
2. Meaning, against the two FMUs' modelDescription.xml: every grouped variable exists with
   the unit given, a group has one causality and one unit, a port's sub-groups have opposite
   causalities; every connection (the OSP group connections expanded as libcosim expands
   them, and the SSD's) joins an output to an input of the same unit and axis, and every
   input of both FMUs is driven exactly once. No parameter is set (no OSP initial value, no
   SSP parameter binding, which fmpy's simulate_ssp never applies and ecos only when told):
   the system's SlowDrift.fmu has no internal stiffness by construction, its start values
   say stiffness 0 where the default SlowDrift.fmu's say the default mooring's.
   No connection needs a unit conversion, so a master that ignores units (libcosim and ecos
   read none) runs the system right; a unit that differed would be caught here (4).
3. The OSP structure and the SSP describe the same system: the same variable connections,
   no parameter values, the same 1 s macro step; the SSP's FMUs are the packed ones.
4. The checks catch broken copies: a unit changed, a variable renamed, groups of different
   kinds connected, an input left unconnected, an initial value of the wrong type, a
   schema violation.
5. The connection diagram of docs/coupling.md is drawn from these files by
   docs/figures/coupling_diagram.py: the committed SVG is the script's output.
"""

import os

import pytest

import system_files as sf

STIFFNESS = ("stiffnessSurge", "stiffnessSway", "stiffnessYaw")


@pytest.fixture(scope="module")
def system(fmu, mooring_fmu):
    d = sf.system_dir(fmu)
    expected = ["Mooring.fmu", "Mooring_OspModelDescription.xml", "MooredPlatform.ssp",
                "OspSystemStructure.xml", "SlowDrift.fmu", "SlowDrift_OspModelDescription.xml"]
    missing = [n for n in expected if not os.path.isfile(os.path.join(d, n))]
    assert not missing, f"{d} lacks {missing} (cargo run --release -p fmu-pack writes them)"
    return d


@pytest.fixture(scope="module")
def variables_of(system):
    return {sim: sf.model_variables(os.path.join(system, f)) for sim, f in sf.FMUS.items()}


def text(system, name):
    with open(os.path.join(system, name), encoding="utf-8") as f:
        return f.read()


def osp_md_name(sim):
    return sf.FMUS[sim].replace(".fmu", "_OspModelDescription.xml")


def groups_of(system):
    return {sim: sf.osp_groups(text(system, osp_md_name(sim))) for sim in sf.FMUS}


def test_schemas(system):
    md = sf.osp_model_description_schema()
    for sim in sf.FMUS:
        assert sf.schema_problems(md, text(system, osp_md_name(sim))) == [], sim
    assert sf.schema_problems(sf.osp_system_structure_schema(),
                              text(system, "OspSystemStructure.xml")) == []
    ssd = sf.read_ssp(os.path.join(system, sf.SSP_FILE))["SystemStructure.ssd"].decode()
    assert sf.schema_problems(sf.ssp_schema("SystemStructureDescription.xsd"), ssd) == []


def test_schemas_catch_a_broken_file(system):
    md = sf.osp_model_description_schema()
    good = text(system, "SlowDrift_OspModelDescription.xml")
    assert sf.schema_problems(md, good.replace('axis="z"', 'axis="yaw"', 1))
    # A port without its velocity group.
    start = good.index('<LinearVelocity name="velocity">')
    end = good.index("</LinearVelocity>", start) + len("</LinearVelocity>")
    assert sf.schema_problems(md, good[:start] + good[end:])
    oss = sf.osp_system_structure_schema()
    good = text(system, "OspSystemStructure.xml")
    assert sf.schema_problems(oss, good.replace("<BaseStepSize>1.0</BaseStepSize>",
                                                "<BaseStepSize>one</BaseStepSize>", 1))


def test_osp_model_descriptions_match_the_fmus(system, variables_of):
    for sim in sf.FMUS:
        assert sf.osp_model_description_problems(text(system, osp_md_name(sim)),
                                                 variables_of[sim]) == [], sim
    # The groups an OSP user connects by meaning, with the FMUs' units.
    slowdrift, mooring = (groups_of(system)[s] for s in ("slowdrift", "mooring"))
    # SlowDrift gives its whole motion (the totals), the mooring takes it.
    assert sf.group_variables(slowdrift, "linearMechanicalPort") == [
        ("Fx_ext", "N", "x"), ("Fy_ext", "N", "y"), ("Xdot_total", "m/s", "x"),
        ("Ydot_total", "m/s", "y")]
    assert sf.group_variables(mooring, "linearMechanicalPort") == [
        ("Fx", "N", "x"), ("Fy", "N", "y"), ("Xdot", "m/s", "x"), ("Ydot", "m/s", "y")]
    motion = {"position": (["X_total", "Y_total"], ["X", "Y"]),
              "heading": (["yaw_total"], ["theta"]),
              "heave": (["Z_total"], ["Z"]),
              "rollPitch": (["roll_total", "pitch_total"], ["roll", "pitch"]),
              "heaveVelocity": (["Zdot_total"], ["Zdot"]),
              "rollPitchRate": (["rolldot_total", "pitchdot_total"], ["rolldot", "pitchdot"])}
    for group, (platform, lines) in motion.items():
        assert [v[0] for v in sf.group_variables(slowdrift, group)] == platform, group
        assert [v[0] for v in sf.group_variables(mooring, group)] == lines, group
    for g in (slowdrift, mooring):
        assert [v[1] for v in sf.group_variables(g, "angularMechanicalPort")] == ["N.m", "rad/s"]


def test_osp_system_structure(system, variables_of):
    step, sources, initial, connections = sf.osp_system(text(system, "OspSystemStructure.xml"))
    assert step == 1.0
    assert sources == sf.FMUS
    assert all(values == {} for values in initial.values()), initial
    pairs, problems = sf.expand_group_connections(connections, groups_of(system), variables_of)
    assert problems == []
    assert sf.input_coverage_problems(pairs, variables_of) == []
    assert len(pairs) == 15  # 12 motion inputs of the mooring, 3 force inputs of SlowDrift


def test_ssp(system, variables_of):
    entries = sf.read_ssp(os.path.join(system, sf.SSP_FILE))
    assert sorted(entries) == ["SystemStructure.ssd", "resources/Mooring.fmu",
                               "resources/SlowDrift.fmu"]
    sources, connectors, parameters, connections, step = sf.ssd_system(
        entries["SystemStructure.ssd"].decode())
    assert step == 1.0
    assert sources == {sim: f"resources/{f}" for sim, f in sf.FMUS.items()}
    for sim, f in sf.FMUS.items():
        with open(os.path.join(system, f), "rb") as packed:
            assert entries[f"resources/{f}"] == packed.read(), f
    assert sf.ssd_problems(connectors, parameters, connections, variables_of) == []
    assert sf.input_coverage_problems(connections, variables_of) == []
    assert all(values == {} for values in parameters.values()), parameters


def test_the_systems_platform_has_no_internal_mooring(system, variables_of, fmu):
    """By construction, not by a binding: the system's SlowDrift.fmu starts (and, with no
    parameter set, runs: test_system_masters.py) at stiffness 0; the default FMU beside it
    at the default mooring's."""
    default = sf.model_variables(fmu)
    for name in STIFFNESS:
        assert float(variables_of["slowdrift"][name].start) == 0.0, name
        assert float(default[name].start) > 0.0, name


def test_osp_and_ssp_describe_one_system(system, variables_of):
    _step, _sources, initial, group_connections = sf.osp_system(text(system, "OspSystemStructure.xml"))
    osp_pairs, _ = sf.expand_group_connections(group_connections, groups_of(system), variables_of)
    _sources, _connectors, parameters, ssp_pairs, _step = sf.ssd_system(
        sf.read_ssp(os.path.join(system, sf.SSP_FILE))["SystemStructure.ssd"].decode())
    assert sorted(osp_pairs) == sorted(ssp_pairs)
    for sim in sf.FMUS:
        assert {n: float(v) for n, (_k, v) in initial[sim].items()} == {
            n: float(v) for n, (_k, v, _u) in parameters[sim].items()}


def test_the_checks_catch_broken_copies(system, variables_of):
    md = text(system, "Mooring_OspModelDescription.xml")
    assert any("unit" in p for p in sf.osp_model_description_problems(
        md.replace('ref="Fx" unit="N"', 'ref="Fx" unit="kN"'), variables_of["mooring"]))
    assert any("not a variable" in p for p in sf.osp_model_description_problems(
        md.replace('ref="Fy"', 'ref="Fy_lines"'), variables_of["mooring"]))
    # A port whose sub-groups have one causality (velocity groups swapped for outputs).
    sd = text(system, "SlowDrift_OspModelDescription.xml")
    assert any("opposite" in p for p in sf.osp_model_description_problems(
        sd.replace('ref="Fx_ext"', 'ref="Fx_wave"').replace('ref="Fy_ext"', 'ref="Fy_wave"'),
        variables_of["slowdrift"]))

    step, sources, initial, connections = sf.osp_system(text(system, "OspSystemStructure.xml"))
    # Position connected to velocity: groups of different kinds.
    wrong = [((("slowdrift", "position"), ("mooring", "linearMechanicalPort"))
              if c == (("slowdrift", "position"), ("mooring", "position")) else c)
             for c in connections]
    assert sf.expand_group_connections(wrong, groups_of(system), variables_of)[1]
    # The heading connection left out: the mooring's theta is never set.
    pairs, _ = sf.expand_group_connections(
        [c for c in connections if c[0][1] != "heading"], groups_of(system), variables_of)
    assert sf.input_coverage_problems(pairs, variables_of) == [
        "input mooring.theta is driven 0 times"]
    assert sf.initial_value_problems({"slowdrift": {"seed": ("Real", "3")}}, variables_of)

    ssd = sf.read_ssp(os.path.join(system, sf.SSP_FILE))["SystemStructure.ssd"].decode()
    for broken in (ssd.replace('name="Mz" kind="output"><ssc:Real unit="N.m"',
                               'name="Mz" kind="output"><ssc:Real unit="kN.m"'),
                   ssd.replace('endConnector="Fx_ext"', 'endConnector="Fx_wave"')):
        _s, connectors, parameters, ssp_connections, _step = sf.ssd_system(broken)
        assert sf.ssd_problems(connectors, parameters, ssp_connections, variables_of)


def test_the_diagram_is_the_scripts(tmp_path):
    """docs/figures/coupling_diagram.svg is what docs/figures/coupling_diagram.py draws from
    the system files now (a changed connection or parameter needs the picture redrawn)."""
    import subprocess
    import sys

    script = os.path.join(sf.HERE, "..", "..", "docs", "figures", "coupling_diagram.py")
    out = tmp_path / "diagram.svg"
    subprocess.run([sys.executable, script, str(out)], check=True, capture_output=True)
    with open(os.path.join(sf.HERE, "..", "..", "docs", "figures", "coupling_diagram.svg"),
              encoding="utf-8") as committed:
        assert out.read_text(encoding="utf-8") == committed.read(), (
            "run python3 docs/figures/coupling_diagram.py and commit the SVG")
