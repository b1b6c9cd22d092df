"""Reading and checking the coupled system's description files: the OSP
model descriptions, the OSP system structure and the SSP system structure description in
target/fmu/system/ (fmu-pack writes them), against their schemas and against the model
descriptions of the two FMUs.

Each check returns a list of problems (empty when the files are right), so that the tests
can show both that the shipped files pass and that a broken copy is caught.
"""

import os
import re
import xml.etree.ElementTree as ET
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
OSP_MD_XSD = os.path.join(HERE, "schema", "OspModelDescription-1.0.1.xsd")
OSP_MD_NS = "https://open-simulation-platform.com/OspModelDescription/1.0.1"
OSP_SS_NS = "http://opensimulationplatform.com/MSMI/OSPSystemStructure"
NS = {
    "md": OSP_MD_NS,
    "ss": OSP_SS_NS,
    "ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
    "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
    "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues",
}
SSP_FILE = "MooredPlatform.ssp"
# The FMU file of each simulator/component name the system files use.
FMUS = {"slowdrift": "SlowDrift.fmu", "mooring": "Mooring.fmu"}
# OSP-IS: the groups made of two sub-groups of opposite causality.
PORTS = {"LinearMechanicalPort": ("Force", "LinearVelocity"),
         "AngularMechanicalPort": ("Torque", "AngularVelocity")}


def system_dir(fmu):
    """target/fmu/system/ beside SlowDrift.fmu (fmu-pack writes it)."""
    return os.path.join(os.path.dirname(fmu), "system")


def model_variables(fmu_path):
    """{name: fmpy ScalarVariable} of an FMU's modelDescription.xml."""
    from fmpy import read_model_description

    return {v.name: v for v in read_model_description(fmu_path).modelVariables}


# --- schemas -------------------------------------------------------------------------------


def osp_system_structure_schema():
    """The OspSystemStructure XSD that libcosim validates with, taken from the libcosimc
    library installed with libcosimpy (a copy of libcosim's data/xsd/OspSystemStructure.xsd
    is compiled into it)."""
    import libcosimpy
    import xmlschema

    lib = os.path.join(os.path.dirname(libcosimpy.__file__), "libcosimc", "libcosimc.so")
    with open(lib, "rb") as f:
        data = f.read()
    m = re.search(rb"<\?xml[^>]*\?>\s*(?:<!--.*?-->\s*)?<xs:schema[^>]*"
                  + re.escape(OSP_SS_NS.encode()) + rb".*?</xs:schema>", data, re.S)
    assert m, f"{lib} holds no OspSystemStructure schema"
    return xmlschema.XMLSchema(m.group(0).decode())


def osp_model_description_schema():
    import xmlschema

    return xmlschema.XMLSchema(OSP_MD_XSD)


def ssp_schema(name):
    """One of the SSP 1.0 schemas fmpy ships (fmpy/ssp/schema)."""
    import fmpy
    import xmlschema

    return xmlschema.XMLSchema(os.path.join(os.path.dirname(fmpy.__file__), "ssp", "schema", name))


def schema_problems(schema, xml_text):
    return [str(e).splitlines()[0] for e in schema.iter_errors(xml_text)]


# --- OSP model descriptions ----------------------------------------------------------------


def osp_groups(xml_text):
    """{group name: (element type, [(ref, unit, axis)], [sub-group names])} of an OSP model
    description, nested groups included (names are unique per document)."""
    groups = {}

    def visit(element):
        tag = element.tag.split("}")[1]
        variables = [(v.get("ref"), v.get("unit"), v.get("axis"))
                     for v in element.findall("md:Variable", NS)]
        subs = [c for c in element if c.tag.split("}")[1] != "Variable"]
        groups[element.get("name")] = (tag, variables, [c.get("name") for c in subs])
        for c in subs:
            visit(c)

    root = ET.fromstring(xml_text)
    for g in root.find("md:VariableGroups", NS):
        visit(g)
    return groups


def group_variables(groups, name):
    """The variables of a group, those of its sub-groups in order for a port."""
    tag, variables, subs = groups[name]
    out = list(variables)
    for s in subs:
        out += group_variables(groups, s)
    return out


def osp_model_description_problems(xml_text, variables):
    """An OSP model description against the FMU's variables ({name: fmpy variable}): every
    Variable names a variable of the FMU with its unit; a group's variables share one
    causality (input or output) and one unit; a port's two sub-groups are of the types OSP-IS
    names and of opposite causalities."""
    problems = []
    groups = osp_groups(xml_text)
    for name, (tag, members, subs) in groups.items():
        causalities = set()
        for ref, unit, _axis in members:
            v = variables.get(ref)
            if v is None:
                problems.append(f"group {name}: {ref} is not a variable of the FMU")
                continue
            if unit != v.unit:
                problems.append(f"group {name}: {ref} has unit {unit!r} here and {v.unit!r} "
                                "in modelDescription.xml")
            causalities.add(v.causality)
        if len(causalities) > 1 or not causalities <= {"input", "output"}:
            problems.append(f"group {name}: causalities {sorted(causalities)}, not one of "
                            "input or output")
        if len({u for _r, u, _a in members}) > 1:
            problems.append(f"group {name}: mixed units {[u for _r, u, _a in members]}")
        if tag in PORTS:
            kinds = tuple(groups[s][0] for s in subs)
            if kinds != PORTS[tag]:
                problems.append(f"port {name}: sub-groups {kinds}, OSP-IS wants {PORTS[tag]}")
            else:
                c = [{variables[r].causality for r, _u, _a in groups[s][1] if r in variables}
                     for s in subs]
                if len(c[0] | c[1]) != 2:
                    problems.append(f"port {name}: its sub-groups are not of opposite causality")
    return problems


# --- OSP system structure ------------------------------------------------------------------


def osp_system(xml_text):
    """(step, {simulator: source}, {simulator: {variable: (type, value)}},
    [((simA, groupA), (simB, groupB))]) of an OspSystemStructure.xml."""
    root = ET.fromstring(xml_text)
    step = float(root.findtext("ss:BaseStepSize", namespaces=NS))
    sources, initial = {}, {}
    for s in root.find("ss:Simulators", NS):
        sources[s.get("name")] = s.get("source")
        initial[s.get("name")] = {}
        for iv in s.findall("ss:InitialValues/ss:InitialValue", NS):
            (value,) = list(iv)
            initial[s.get("name")][iv.get("variable")] = (value.tag.split("}")[1], value.get("value"))
    connections = []
    for c in root.find("ss:Connections", NS):
        a, b = c.findall("ss:VariableGroup", NS) or c.findall("ss:Variable", NS)
        connections.append(((a.get("simulator"), a.get("name")), (b.get("simulator"), b.get("name"))))
    return step, sources, initial, connections


def expand_group_connections(connections, groups_of, variables_of):
    """The variable connections (output (sim, var), input (sim, var)) that OSP group
    connections make, pairing the groups' variables in order as libcosim does; problems
    where the two groups differ in type, shape, units or axes, or a pair is not one output
    and one input."""
    problems, pairs = [], []
    for (sa, ga), (sb, gb) in connections:
        for sim, g in ((sa, ga), (sb, gb)):
            if g not in groups_of[sim]:
                problems.append(f"{sim} has no variable group {g}")
        if problems:
            continue
        ta, tb = groups_of[sa][ga][0], groups_of[sb][gb][0]
        if ta != tb:
            problems.append(f"{sa}.{ga} ({ta}) connected to {sb}.{gb} ({tb})")
        va, vb = group_variables(groups_of[sa], ga), group_variables(groups_of[sb], gb)
        if len(va) != len(vb):
            problems.append(f"{sa}.{ga} has {len(va)} variables, {sb}.{gb} {len(vb)}")
            continue
        for (ra, ua, xa), (rb, ub, xb) in zip(va, vb):
            if ua != ub or xa != xb:
                problems.append(f"{sa}.{ra} ({ua}, axis {xa}) connected to {sb}.{rb} ({ub}, axis {xb})")
            ca, cb = variables_of[sa][ra].causality, variables_of[sb][rb].causality
            if {ca, cb} != {"input", "output"}:
                problems.append(f"{sa}.{ra} ({ca}) connected to {sb}.{rb} ({cb})")
            elif ca == "output":
                pairs.append(((sa, ra), (sb, rb)))
            else:
                pairs.append(((sb, rb), (sa, ra)))
    return pairs, problems


def initial_value_problems(initial, variables_of):
    """Every initial value names a parameter of its FMU, of the same type."""
    problems = []
    for sim, values in initial.items():
        for name, (kind, _value) in values.items():
            v = variables_of[sim].get(name)
            if v is None:
                problems.append(f"{sim} has no variable {name}")
            elif v.causality != "parameter" or v.type != kind:
                problems.append(f"{sim}.{name} is a {v.causality} {v.type}, set as a {kind}")
    return problems


# Inputs that no output drives: SlowDrift's windVelocity_ext (a master's own wind field, used
# only when windSource = 1; the system's wind, if any, is SlowDrift's own records). The system
# connects SlowDrift's whole motion to all twelve of the mooring's motion inputs.
UNDRIVEN = {("slowdrift", "windVelocity_ext")}


def input_coverage_problems(pairs, variables_of):
    """Every input of both FMUs (the parameters apart) is driven by exactly one output, but
    those of UNDRIVEN, which no output drives."""
    problems = []
    driven = [end for _start, end in pairs]
    for sim, variables in variables_of.items():
        for name, v in variables.items():
            due = 0 if (sim, name) in UNDRIVEN else 1
            if v.causality == "input" and driven.count((sim, name)) != due:
                problems.append(f"input {sim}.{name} is driven {driven.count((sim, name))} times")
    return problems


# --- SSP -----------------------------------------------------------------------------------


def ssd_system(xml_text):
    """({component: source}, {component: {connector: (kind, unit)}},
    {component: {parameter: (type, value, unit)}}, [((startElement, startConnector),
    (endElement, endConnector))], step of the OSP annotation) of a SystemStructure.ssd."""
    root = ET.fromstring(xml_text)
    system = root.find("ssd:System", NS)
    sources, connectors, parameters = {}, {}, {}
    for c in system.find("ssd:Elements", NS):
        name = c.get("name")
        sources[name] = c.get("source")
        connectors[name] = {}
        for k in c.findall("ssd:Connectors/ssd:Connector", NS):
            (kind,) = list(k)
            connectors[name][k.get("name")] = (k.get("kind"), kind.get("unit"))
        parameters[name] = {}
        for p in c.findall("ssd:ParameterBindings/ssd:ParameterBinding/ssd:ParameterValues/"
                           "ssv:ParameterSet/ssv:Parameters/ssv:Parameter", NS):
            (value,) = list(p)
            parameters[name][p.get("name")] = (value.tag.split("}")[1], value.get("value"),
                                               value.get("unit"))
    connections = [((c.get("startElement"), c.get("startConnector")),
                    (c.get("endElement"), c.get("endConnector")))
                   for c in system.find("ssd:Connections", NS)]
    step = root.find("ssd:DefaultExperiment/ssd:Annotations/ssc:Annotation", NS)
    fixed = step.find("{http://opensimulationplatform.com/SSP/OSPAnnotations}Algorithm/"
                      "{http://opensimulationplatform.com/SSP/OSPAnnotations}FixedStepAlgorithm")
    return sources, connectors, parameters, connections, float(fixed.get("baseStepSize"))


def ssd_problems(connectors, parameters, connections, variables_of):
    """The SSD against the FMUs: every connector is a variable of its FMU with that causality
    and unit; every connection joins an output to an input of the same unit; every parameter
    binding names a parameter of its FMU with its type and unit."""
    problems = []
    for comp, conns in connectors.items():
        for name, (kind, unit) in conns.items():
            v = variables_of[comp].get(name)
            if v is None:
                problems.append(f"connector {comp}.{name} is not a variable of the FMU")
            elif v.causality != kind or v.unit != unit:
                problems.append(f"connector {comp}.{name}: {kind} in {unit!r} here, "
                                f"{v.causality} in {v.unit!r} in modelDescription.xml")
    for (sc, sn), (ec, en) in connections:
        start, end = connectors[sc].get(sn), connectors[ec].get(en)
        if start is None or end is None:
            problems.append(f"connection {sc}.{sn} -> {ec}.{en} names a missing connector")
        elif start[0] != "output" or end[0] != "input" or start[1] != end[1]:
            problems.append(f"connection {sc}.{sn} ({start[0]}, {start[1]}) -> {ec}.{en} "
                            f"({end[0]}, {end[1]})")
    for comp, values in parameters.items():
        for name, (kind, _value, unit) in values.items():
            v = variables_of[comp].get(name)
            if v is None or v.causality != "parameter" or v.type != kind:
                problems.append(f"parameter binding {comp}.{name} ({kind}) is not a {kind} "
                                "parameter of the FMU")
            elif unit is not None and unit != v.unit:
                problems.append(f"parameter binding {comp}.{name} in {unit!r}, "
                                f"modelDescription.xml in {v.unit!r}")
    return problems


def read_ssp(path):
    """{entry name: bytes} of an SSP package."""
    with zipfile.ZipFile(path) as z:
        return {n: z.read(n) for n in z.namelist()}
