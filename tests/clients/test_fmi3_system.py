"""The coupled platform and mooring as FMI 3.0 FMUs connected by their terminals
(terminalsAndIcons/terminalsAndIcons.xml of target/fmu/fmi3/SlowDrift.fmu and Mooring.fmu),
against the FMI 2.0 system connected by the SSD's connections (fmu-pack/system/):

1. fmpy validates both FMI 3.0 archives; both terminal files are valid against the FMI 3.0 schema kept in the repository
   (fmi-xml/schema/fmi3/fmi3TerminalsAndIcons.xsd) and name variables of their FMU;
2. matched by member name (the terminals' "bus" rule), the two terminals give each output
   of one FMU to an input of the other with the same unit: exactly the connections of the
   SSD, by variable name, from the other side of the standard;
3. the same Jacobi co-simulation loop (fmpy's FMU2Slave and FMU3Slave, 1 s steps, 30 min,
   the platform without an internal spring as in the system) runs both systems: every
   connected value, every SlowDrift output and the eight fairlead tensions (FMI 3.0: the one
   array fairleadTension, read with nValues 8; FMI 2.0: fairleadTension1 .. 8) equal at
   every step, bit for bit.
"""

import os
import xml.etree.ElementTree as ET
import zipfile

import numpy as np
import pytest

import system_files as sf

HERE = os.path.dirname(os.path.abspath(__file__))
TERMINALS_XSD = os.path.join(HERE, "..", "..", "fmi-xml", "schema", "fmi3",
                             "fmi3TerminalsAndIcons.xsd")
TERMINALS = "terminalsAndIcons/terminalsAndIcons.xml"
SSD = os.path.join(HERE, "..", "..", "fmu-pack", "system", "SystemStructure.ssd")
# The system's platform: no internal spring (the lines alone moor it).
LINES_ONLY = {"stiffnessSurge": 0.0, "stiffnessSway": 0.0, "stiffnessYaw": 0.0}
DURATION, DT = 1800.0, 1.0
LINES = 8  # the default mooring's lines


@pytest.fixture(scope="module")
def fmi3_fmus(fmu, mooring_fmu):
    paths = {name: os.path.join(os.path.dirname(fmu), "fmi3", f"{file}.fmu")
             for name, file in (("slowdrift", "SlowDrift"), ("mooring", "Mooring"))}
    for path in paths.values():
        if not os.path.isfile(path):
            pytest.fail(f"{path} not found (fmu-pack packs it: cargo run --release -p fmu-pack)")
    return paths


def terminal(path):
    """[(memberName, variableName)] of the one terminal of an FMU archive, and its rule."""
    with zipfile.ZipFile(path) as z:
        root = ET.fromstring(z.read(TERMINALS))
    (t,) = root.findall("Terminals/Terminal")
    return t.get("matchingRule"), [(m.get("memberName"), m.get("variableName"))
                                   for m in t.findall("TerminalMemberVariable")]


def test_fmpy_validates_both_fmi3_archives(fmi3_fmus):
    from fmpy.validation import validate_fmu

    for path in fmi3_fmus.values():
        assert validate_fmu(path) == [], path


def test_terminals_are_schema_valid(fmi3_fmus):
    import xmlschema

    schema = xmlschema.XMLSchema(TERMINALS_XSD)
    for path in fmi3_fmus.values():
        with zipfile.ZipFile(path) as z:
            schema.validate(z.read(TERMINALS).decode())
    # Control: a member without its required variableKind is refused.
    with zipfile.ZipFile(fmi3_fmus["mooring"]) as z:
        broken = z.read(TERMINALS).decode().replace(' variableKind="signal"', "", 1)
    assert not schema.is_valid(broken)


def connections_by_terminals(fmi3_fmus):
    """[((from component, output), (to component, input))] of the two terminals, matched by
    member name; checks causality and units on the way."""
    from fmpy import read_model_description

    variables = {name: {v.name: v for v in read_model_description(path).modelVariables}
                 for name, path in fmi3_fmus.items()}
    members = {}
    for name, path in fmi3_fmus.items():
        rule, pairs = terminal(path)
        assert rule == "bus", rule
        for member, variable in pairs:
            assert variable in variables[name], (name, variable)
            members.setdefault(member, {})[name] = variables[name][variable]
    connections = []
    for member, ends in members.items():
        if len(ends) < 2:
            continue  # a member of one side only (the mooring's fz, mx, my)
        (a, va), (b, vb) = ends.items()
        assert {va.causality, vb.causality} == {"input", "output"}, member
        assert va.unit == vb.unit, (member, va.unit, vb.unit)
        start, end = ((a, va), (b, vb)) if va.causality == "output" else ((b, vb), (a, va))
        connections.append(((start[0], start[1].name), (end[0], end[1].name)))
    return sorted(connections)


def test_terminals_give_the_ssds_connections(fmi3_fmus):
    _, _, _, ssd, _ = sf.ssd_system(open(SSD).read())
    assert connections_by_terminals(fmi3_fmus) == sorted(ssd)


class Slave:
    """One FMU through fmpy's low-level slave of its FMI version, Reals by name."""

    def __init__(self, path, name, parameters, fmi3):
        from fmpy import extract, read_model_description
        from fmpy.fmi2 import FMU2Slave
        from fmpy.fmi3 import FMU3Slave

        md = read_model_description(path)
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.fmi3 = fmi3
        cls = FMU3Slave if fmi3 else FMU2Slave
        self.fmu = cls(guid=md.guid, unzipDirectory=extract(path),
                       modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
        self.fmu.instantiate()
        if fmi3:
            self.set(parameters)
            self.fmu.enterInitializationMode(startTime=0.0, stopTime=DURATION)
        else:
            self.fmu.setupExperiment(startTime=0.0, stopTime=DURATION)
            self.set(parameters)
            self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()

    def get(self, names):
        refs = [self.vr[n] for n in names]
        return self.fmu.getFloat64(refs) if self.fmi3 else self.fmu.getReal(refs)

    def set(self, values):
        if values:
            refs = [self.vr[n] for n in values]
            vals = [float(v) for v in values.values()]
            (self.fmu.setFloat64 if self.fmi3 else self.fmu.setReal)(refs, vals)

    def tensions(self):
        """The mooring's eight fairlead tensions: FMI 3.0's array, FMI 2.0's scalars."""
        if self.fmi3:
            return self.fmu.getFloat64([self.vr["fairleadTension"]], nValues=LINES)
        return self.fmu.getReal([self.vr[f"fairleadTension{k}"] for k in range(1, LINES + 1)])

    def step(self, t):
        self.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=DT)

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()


def jacobi(paths, connections, fmi3):
    """The Jacobi loop: at each communication point every input takes its output's value,
    then both FMUs step from there. Returns the record of every connected value and
    SlowDrift's outputs, one row per communication point."""
    from routes import OUTPUTS

    slaves = {"slowdrift": Slave(paths["slowdrift"], "slowdrift", LINES_ONLY, fmi3),
              "mooring": Slave(paths["mooring"], "mooring", {}, fmi3)}
    record = []
    try:
        for n in range(int(DURATION / DT) + 1):
            values = {}
            for (a, out), _ in connections:
                values[(a, out)] = slaves[a].get([out])[0]
            for (a, out), (b, inp) in connections:
                slaves[b].set({inp: values[(a, out)]})
            record.append([values[c[0]] for c in connections]
                          + list(slaves["slowdrift"].get(list(OUTPUTS)))
                          + list(slaves["mooring"].tensions()))
            if n * DT < DURATION:
                for s in slaves.values():
                    s.step(n * DT)
    finally:
        for s in slaves.values():
            s.close()
    return np.array(record)


def test_the_fmi3_system_by_terminals_is_the_fmi2_system(fmu, mooring_fmu, fmi3_fmus):
    _, _, _, ssd, _ = sf.ssd_system(open(SSD).read())
    two = jacobi({"slowdrift": fmu, "mooring": mooring_fmu}, sorted(ssd), fmi3=False)
    three = jacobi(fmi3_fmus, connections_by_terminals(fmi3_fmus), fmi3=True)
    from routes import OUTPUTS

    assert two.shape == three.shape == (int(DURATION / DT) + 1,
                                        len(ssd) + len(OUTPUTS) + LINES)
    assert np.array_equal(three.view(np.uint64), two.view(np.uint64))
    # The lines moor the platform: the surge force is not nil after the start.
    forces = [i for i, (c, _) in enumerate(sorted(ssd)) if c == ("mooring", "Fx")]
    assert np.max(np.abs(three[10:, forces[0]])) > 1.0e4
    assert np.all(three[:, -LINES:] > 0.0), "every line is taut"
