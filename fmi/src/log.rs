//! The log categories of every FMU of this layer and which of them reach the host
//! ([`Switches`]): errors, warnings and discards always (they say why a call did not return
//! OK); events (initialisation, reset, states saved and restored) when `loggingOn` or the
//! debug-logging call turns them on; the trace of every call (`logAll`, a line per call and
//! so per step) only when the debug-logging call names it or names no category. `loggingOn`
//! alone leaves the trace off: masters such as libcosim instantiate with logging on and
//! write every line the FMU sends (FMI 2.0.4 section 2.1.5 leaves the categories that
//! `loggingOn` enables to the FMU).

use crate::Error;

/// A log category; every FMU's modelDescription.xml declares exactly [`Category::ALL`], in
/// this order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Category {
    /// Calls that return an error (or fatal).
    StatusError,
    /// Calls that return a warning.
    StatusWarning,
    /// Calls that return a discard.
    StatusDiscard,
    /// Initialisation, reset, states saved and restored.
    Events,
    /// A debug trace: every call, one line each.
    All,
}

impl Category {
    /// Every category, in the order of the model descriptions.
    pub const ALL: [Category; 5] = [
        Category::StatusError,
        Category::StatusWarning,
        Category::StatusDiscard,
        Category::Events,
        Category::All,
    ];

    /// The category's name in modelDescription.xml and in the host's logger.
    pub const fn name(self) -> &'static str {
        match self {
            Category::StatusError => "logStatusError",
            Category::StatusWarning => "logStatusWarning",
            Category::StatusDiscard => "logStatusDiscard",
            Category::Events => "logEvents",
            Category::All => "logAll",
        }
    }

    /// Whether the category always reaches the host (it says why a call did not return OK).
    fn always(self) -> bool {
        matches!(
            self,
            Category::StatusError | Category::StatusWarning | Category::StatusDiscard
        )
    }
}

/// Which categories reach the host (module documentation).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Switches {
    on: [bool; Category::ALL.len()],
}

impl Switches {
    /// The switches at instantiation: every category but the trace follows `logging_on`.
    pub fn new(logging_on: bool) -> Switches {
        let mut on = [logging_on; Category::ALL.len()];
        on[Category::All as usize] = false;
        Switches { on }
    }

    /// Whether lines of `category` reach the host.
    pub fn enabled(&self, category: Category) -> bool {
        category.always() || self.on[category as usize]
    }

    /// The debug-logging call: no category names them all; an unknown name changes nothing
    /// and is an error.
    pub fn set(&mut self, on: bool, names: &[&str]) -> Result<(), Error> {
        if names.is_empty() {
            self.on = [on; Category::ALL.len()];
            return Ok(());
        }
        let mut named = Vec::with_capacity(names.len());
        for name in names {
            let category = Category::ALL
                .into_iter()
                .find(|c| c.name() == *name)
                .ok_or_else(|| {
                    Error::Argument(format!(
                        "unknown log category {name:?}; the categories are {:?}",
                        Category::ALL.map(Category::name)
                    ))
                })?;
            named.push(category);
        }
        for category in named {
            self.on[category as usize] = on;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn logging_on_turns_on_the_events_not_the_trace() {
        for logging_on in [false, true] {
            let s = Switches::new(logging_on);
            assert!(s.enabled(Category::StatusError));
            assert!(s.enabled(Category::StatusWarning));
            assert!(s.enabled(Category::StatusDiscard));
            assert_eq!(s.enabled(Category::Events), logging_on);
            assert!(!s.enabled(Category::All));
        }
    }

    #[test]
    fn the_debug_logging_call_names_categories_or_all() {
        let mut s = Switches::new(false);
        s.set(true, &["logAll"]).unwrap();
        assert!(s.enabled(Category::All) && !s.enabled(Category::Events));
        s.set(false, &[]).unwrap();
        assert!(!s.enabled(Category::All) && s.enabled(Category::StatusError));
        s.set(true, &[]).unwrap();
        assert!(s.enabled(Category::All) && s.enabled(Category::Events));
        let before = s.clone();
        let refused = s.set(false, &["logEvents", "logNothing"]).unwrap_err();
        assert_eq!(
            refused.to_string(),
            "unknown log category \"logNothing\"; the categories are [\"logStatusError\", \
             \"logStatusWarning\", \"logStatusDiscard\", \"logEvents\", \"logAll\"]"
        );
        assert_eq!(s, before, "an unknown name changes nothing");
        // Errors cannot be switched off.
        s.set(false, &["logStatusError"]).unwrap();
        assert!(s.enabled(Category::StatusError));
    }
}
