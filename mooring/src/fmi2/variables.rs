//! The variables of `mooring/modelDescription.xml` (checked against it by the test below).

/// The GUID of the model description; `fmi2Instantiate` must receive it.
pub const GUID: &str = "{28340ea3-9278-444d-aad1-d64fa1e238e1}";
/// The model identifier (the library's name in the FMU).
pub const MODEL_IDENTIFIER: &str = "Mooring";
/// The String parameter `mooringFile`.
pub const MOORING_FILE: u32 = 0;
/// The Integer parameter `mooringModel` and its codes.
pub const MOORING_MODEL: u32 = 0;
pub const DYNAMIC: i32 = 0;
pub const QUASI_STATIC: i32 = 1;
/// The Real inputs (name, value reference), in their order in modelDescription.xml and in
/// the instance's array of inputs: the planar motion at 0..5, then the heave, roll and pitch
/// and their rates at 20..25 (added later; the frames and angles are
/// [`crate::motion`]'s).
pub const INPUTS: [(&str, u32); 12] = [
    ("X", 0),
    ("Y", 1),
    ("theta", 2),
    ("Xdot", 3),
    ("Ydot", 4),
    ("thetadot", 5),
    ("Z", 20),
    ("roll", 21),
    ("pitch", 22),
    ("Zdot", 23),
    ("rolldot", 24),
    ("pitchdot", 25),
];
/// The indices in [`INPUTS`] of MoorDyn's six coupled positions (x, y, z, roll, pitch,
/// yaw) and of their rates.
pub const POSITION: [usize; 6] = [0, 1, 6, 7, 8, 2];
pub const VELOCITY: [usize; 6] = [3, 4, 9, 10, 11, 5];
/// The Real outputs Fx, Fy, Mz, fairleadTensionMax, Fz, Mx, My: value references 10..17, in
/// this order.
pub const OUTPUTS: [&str; 7] = ["Fx", "Fy", "Mz", "fairleadTensionMax", "Fz", "Mx", "My"];
/// The value reference of the first output.
pub const FIRST_OUTPUT: u32 = 10;
/// The lines of the mooring the FMU is packed with ([`DEFAULT_MOORING`]): one Real output
/// each, its fairlead tension, named [`line_tension_name`] with value reference
/// [`LINE_TENSIONS`] + n for MoorDyn's line n = 1, 2, ... (the file's line IDs, which MoorDyn
/// requires to be 1, 2, ... in order). A `mooringFile` with another number of lines is
/// refused.
pub const LINE_COUNT: usize = 8;
pub const LINE_TENSIONS: u32 = 100;
/// The file of the default mooring in the FMU's resources folder.
pub const DEFAULT_MOORING: &str = "spread_mooring.dat";

/// The name of line n's fairlead tension output (n from 1).
pub fn line_tension_name(n: usize) -> String {
    format!("fairleadTension{n}")
}

/// A Real variable by value reference: the index in [`INPUTS`], in [`OUTPUTS`], or the
/// line's index from 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Real {
    Input(usize),
    Output(usize),
    LineTension(usize),
}

impl Real {
    pub fn of(vr: u32) -> Option<Real> {
        if let Some(i) = INPUTS.iter().position(|&(_, v)| v == vr) {
            return Some(Real::Input(i));
        }
        let output = vr.checked_sub(FIRST_OUTPUT).map(|i| i as usize);
        let line = vr.checked_sub(LINE_TENSIONS + 1).map(|i| i as usize);
        match (output, line) {
            (Some(i), _) if i < OUTPUTS.len() => Some(Real::Output(i)),
            (_, Some(i)) if i < LINE_COUNT => Some(Real::LineTension(i)),
            _ => None,
        }
    }

    /// The variable's name.
    pub fn name(self) -> String {
        match self {
            Real::Input(i) => INPUTS[i].0.to_string(),
            Real::Output(i) => OUTPUTS[i].to_string(),
            Real::LineTension(i) => line_tension_name(i + 1),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use quick_xml::events::Event;
    use quick_xml::Reader;
    use slowdrift_fmi::log::Category;

    /// (name, valueReference, causality, type) of every ScalarVariable, and the GUID, model
    /// identifier and log categories (the FMI layer's, in its order), read with quick-xml.
    #[test]
    fn constants_are_the_model_description() {
        let xml = include_str!("../../modelDescription.xml");
        let mut reader = Reader::from_str(xml);
        let (mut vars, mut guid, mut id, mut categories) = (Vec::new(), None, None, Vec::new());
        let mut current: Option<(String, u32, String)> = None;
        loop {
            let (e, tag) = match reader.read_event().unwrap() {
                Event::Start(e) | Event::Empty(e) => {
                    let tag = e.name().as_ref().to_string();
                    (e, tag)
                }
                Event::Eof => break,
                _ => continue,
            };
            let get = |k: &str| {
                e.attributes()
                    .map(|a| a.unwrap())
                    .find(|a| a.key.as_ref() == k)
                    .map(|a| a.value.to_string())
            };
            match tag.as_str() {
                "fmiModelDescription" => guid = get("guid"),
                "CoSimulation" => id = get("modelIdentifier"),
                "Category" => categories.push(get("name").unwrap()),
                "ScalarVariable" => {
                    current = Some((
                        get("name").unwrap(),
                        get("valueReference").unwrap().parse().unwrap(),
                        get("causality").unwrap(),
                    ))
                }
                "Real" | "String" | "Integer" | "Boolean" | "Enumeration" => {
                    if let Some((n, vr, c)) = current.take() {
                        vars.push((n, vr, c, tag.clone(), get("unit")));
                    }
                }
                _ => {}
            }
        }
        assert_eq!(guid.as_deref(), Some(GUID));
        assert_eq!(id.as_deref(), Some(MODEL_IDENTIFIER));
        assert_eq!(categories, Category::ALL.map(Category::name));
        let mut expected = vec![(
            "mooringFile".to_string(),
            MOORING_FILE,
            "parameter",
            "String",
        )];
        // The original variables first, in their original order and indices; what the 6-DOF
        // motion added after them.
        for &(n, vr) in &INPUTS[..6] {
            expected.push((n.to_string(), vr, "input", "Real"));
        }
        for (i, n) in OUTPUTS[..4].iter().enumerate() {
            expected.push((n.to_string(), FIRST_OUTPUT + i as u32, "output", "Real"));
        }
        expected.push((
            "mooringModel".to_string(),
            MOORING_MODEL,
            "parameter",
            "Integer",
        ));
        for &(n, vr) in &INPUTS[6..] {
            expected.push((n.to_string(), vr, "input", "Real"));
        }
        for (i, n) in OUTPUTS.iter().enumerate().skip(4) {
            expected.push((n.to_string(), FIRST_OUTPUT + i as u32, "output", "Real"));
        }
        for n in 1..=LINE_COUNT {
            expected.push((
                line_tension_name(n),
                LINE_TENSIONS + n as u32,
                "output",
                "Real",
            ));
        }
        let found: Vec<_> = vars
            .iter()
            .map(|(n, vr, c, t, _)| (n.clone(), *vr, c.as_str(), t.as_str()))
            .collect();
        assert_eq!(found, expected);
        // Every Real carries its unit (OMSimulator does not inherit one from a declaredType).
        assert!(vars.iter().all(|v| v.3 != "Real" || v.4.is_some()));
        for (vr, real) in [
            (0, Real::Input(0)),
            (5, Real::Input(5)),
            (20, Real::Input(6)),
            (25, Real::Input(11)),
            (13, Real::Output(3)),
            (16, Real::Output(6)),
            (101, Real::LineTension(0)),
            (108, Real::LineTension(7)),
        ] {
            assert_eq!(Real::of(vr), Some(real));
        }
        for vr in [6, 9, 17, 19, 26, 100, 109] {
            assert_eq!(Real::of(vr), None, "{vr}");
        }
        // POSITION and VELOCITY pick (x, y, z, roll, pitch, yaw) and their rates.
        let names = |idx: [usize; 6]| idx.map(|i| INPUTS[i].0);
        assert_eq!(names(POSITION), ["X", "Y", "Z", "roll", "pitch", "theta"]);
        assert_eq!(
            names(VELOCITY),
            ["Xdot", "Ydot", "Zdot", "rolldot", "pitchdot", "thetadot"]
        );
    }

    /// The line outputs are those of the packed default mooring: one per line, its ID n.
    #[test]
    fn line_outputs_are_the_default_moorings_lines() {
        let lines = crate::lines_file::parse(include_str!("../../spread_mooring.dat")).unwrap();
        let ids: Vec<String> = lines.iter().map(|l| l.id.clone()).collect();
        let expected: Vec<String> = (1..=LINE_COUNT).map(|n| n.to_string()).collect();
        assert_eq!(ids, expected);
        assert_eq!(Real::LineTension(0).name(), "fairleadTension1");
        assert_eq!(
            Real::of(LINE_TENSIONS + 3).map(Real::name).as_deref(),
            Some("fairleadTension3")
        );
    }
}
