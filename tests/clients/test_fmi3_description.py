"""The FMI 3.0 model descriptions of both FMUs, as their build scripts generate them from
the FMI 2.0 ones (slowdrift-fmi-xml) and fmu-pack writes them into
target/fmu/fmi3/<model>/modelDescription.xml beside SlowDrift.fmu:

1. valid against the FMI 3.0 schema kept in the repository (fmi-xml/schema/fmi3/, v3.0.2),
   with xmlschema; a broken copy is refused;
2. valid for fmpy (its schema and its rules: exactly one independent variable, unique value
   references, the outputs and initial unknowns of the model structure);
3. the FMI 2.0 description of the packed FMU, variable by variable: the same names,
   causalities, variabilities and units, the value references moved by the documented
   offset of their type (SlowDrift: none; the mooring: Integer + 1000, String + 2000), the
   instantiation token the guid, and `time` at 999999.
"""

import os
import xml.etree.ElementTree as ET
import zipfile

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SCHEMA = os.path.join(HERE, "..", "..", "fmi-xml", "schema", "fmi3", "fmi3ModelDescription.xsd")
TIME_VALUE_REFERENCE = 999999
# FMI 2.0 type -> (FMI 3.0 element, value reference offset), per FMU (docs/fmu.md).
TYPES = {
    "SlowDrift": {"Real": ("Float64", 0), "Integer": ("Int32", 0), "String": ("String", 0)},
    "Mooring": {"Real": ("Float64", 0), "Integer": ("Int32", 1000), "String": ("String", 2000)},
}
# FMI 3.0 arrays made of FMI 2.0 Reals name1 .. nameN (docs/fmu.md): (name, N) per FMU.
ARRAYS = {"SlowDrift": [], "Mooring": [("fairleadTension", 8)]}


def element_of(name, arrays):
    """(array, k) of an FMI 2.0 name `{array}k`, k = 1 .. N; None otherwise."""
    for array, count in arrays:
        k = name[len(array):]
        if name.startswith(array) and k.isdigit() and 1 <= int(k) <= count:
            return array, int(k)
    return None


@pytest.fixture(scope="module", params=["SlowDrift", "Mooring"])
def fmi3(request, fmu, mooring_fmu):
    """(model, path of its FMI 3.0 description, its packed FMI 2.0 FMU)."""
    model = request.param
    path = os.path.join(os.path.dirname(fmu), "fmi3", model, "modelDescription.xml")
    if not os.path.isfile(path):
        pytest.fail(f"{path} not found (fmu-pack writes it: cargo run --release -p fmu-pack)")
    return model, path, fmu if model == "SlowDrift" else mooring_fmu


def test_fmi3_description_is_schema_valid(fmi3):
    import xmlschema

    schema = xmlschema.XMLSchema(SCHEMA)
    _, path, _ = fmi3
    assert list(schema.iter_errors(path)) == []
    # A broken copy is caught: no instantiationToken, a misspelt causality.
    text = open(path, encoding="utf-8").read()
    broken = text.replace("instantiationToken=", "guid=", 1)
    assert list(schema.iter_errors(broken))
    broken = text.replace('causality="independent"', 'causality="indep"', 1)
    assert list(schema.iter_errors(broken))


def test_fmi3_description_passes_fmpy(fmi3):
    from fmpy.model_description import read_model_description
    from fmpy.validation import validate_model_description

    _, path, _ = fmi3
    md = read_model_description(path, validate=True)
    assert md.fmiVersion == "3.0"
    assert validate_model_description(md, validate_variable_names=True,
                                      validate_model_structure=True) == []


def test_fmi3_description_is_the_fmi2_one(fmi3):
    model, path, fmu_file = fmi3
    with zipfile.ZipFile(fmu_file) as z:
        fmi2 = ET.fromstring(z.read("modelDescription.xml"))
    root = ET.parse(path).getroot()
    assert root.get("fmiVersion") == "3.0"
    assert root.get("instantiationToken") == fmi2.get("guid")
    assert root.get("modelName") == fmi2.get("modelName")
    assert root.find("CoSimulation").get("modelIdentifier") == model

    variables = list(root.find("ModelVariables"))
    time = variables[0]
    assert (time.tag, time.get("name"), time.get("valueReference"), time.get("causality")) == (
        "Float64", "time", str(TIME_VALUE_REFERENCE), "independent")
    assert [v for v in variables if v.get("causality") == "independent"] == [time]

    rest = variables[1:]
    # An array stands for its elements: the first's place, the others' none.
    scalars = [v for v in fmi2.find("ModelVariables")
               if (element_of(v.get("name"), ARRAYS[model]) or (None, 1))[1] == 1]
    assert len(rest) == len(scalars)
    for v3, v2 in zip(rest, scalars):
        base = v2[0]
        element, offset = TYPES[model][base.tag]
        assert v3.tag == element, v2.get("name")
        array = element_of(v2.get("name"), ARRAYS[model])
        if array is None:
            assert v3.get("name") == v2.get("name")
            assert v3.find("Dimension") is None
        else:
            count = dict(ARRAYS[model])[array[0]]
            assert v3.get("name") == array[0]
            assert v3.find("Dimension").get("start") == str(count)
        assert int(v3.get("valueReference")) == int(v2.get("valueReference")) + offset
        assert v3.get("causality") == v2.get("causality", "local")
        assert v3.get("variability") == v2.get("variability", "continuous")
        assert v3.get("unit") == base.get("unit")
        start = v3.find("Start").get("value") if v3.tag == "String" else v3.get("start")
        assert start == base.get("start"), v2.get("name")
