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
/// The Real inputs X, Y, theta, Xdot, Ydot, thetadot: value references 0..6, in this order.
pub const INPUTS: [&str; 6] = ["X", "Y", "theta", "Xdot", "Ydot", "thetadot"];
/// The Real outputs Fx, Fy, Mz, fairleadTensionMax: value references 10..14, in this order.
pub const OUTPUTS: [&str; 4] = ["Fx", "Fy", "Mz", "fairleadTensionMax"];
/// The value reference of the first output.
pub const FIRST_OUTPUT: u32 = 10;
/// The file of the default mooring in the FMU's resources folder.
pub const DEFAULT_MOORING: &str = "spread_mooring.dat";

/// A Real variable by value reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Real {
    Input(usize),
    Output(usize),
}

impl Real {
    pub fn of(vr: u32) -> Option<Real> {
        let vr = vr as usize;
        let first = FIRST_OUTPUT as usize;
        if vr < INPUTS.len() {
            Some(Real::Input(vr))
        } else if (first..first + OUTPUTS.len()).contains(&vr) {
            Some(Real::Output(vr - first))
        } else {
            None
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
        for (i, n) in INPUTS.iter().enumerate() {
            expected.push((n.to_string(), i as u32, "input", "Real"));
        }
        for (i, n) in OUTPUTS.iter().enumerate() {
            expected.push((n.to_string(), FIRST_OUTPUT + i as u32, "output", "Real"));
        }
        expected.push((
            "mooringModel".to_string(),
            MOORING_MODEL,
            "parameter",
            "Integer",
        ));
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
            (13, Real::Output(3)),
        ] {
            assert_eq!(Real::of(vr), Some(real));
        }
        assert_eq!(Real::of(6), None);
        assert_eq!(Real::of(14), None);
    }
}
