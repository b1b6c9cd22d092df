//! How a number is written, to tell a number cut short from a whole one: a
//! reader compares a number with the same field of an earlier line of its file. A field
//! whose earlier number has an exponent must have one (a mantissa whose exponent was lost,
//! `6.273170` for `6.273170E+09`, reads a billion times too small); on the last line of a
//! file that ends without a newline, where a file cut inside a number ends, a field must
//! also have as many exponent digits and decimals.

/// How a number is written: the digits after its decimal point and after its exponent's
/// letter and sign.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Written {
    decimals: usize,
    exponent: Option<usize>,
}

impl Written {
    pub fn of(text: &str) -> Written {
        let (mantissa, exponent) = match text.find(['E', 'e', 'D', 'd']) {
            Some(at) => (&text[..at], Some(&text[at + 1..])),
            None => (text, None),
        };
        let digits = |t: &str| t.chars().filter(char::is_ascii_digit).count();
        Written {
            decimals: mantissa.split_once('.').map_or(0, |(_, d)| digits(d)),
            exponent: exponent.map(digits),
        }
    }

    /// Whether a number written like this is a cut copy of one written like `reference`
    /// (the same field of an earlier line): its exponent lost where the reference has one;
    /// on a file's unterminated last line (`last`) also fewer exponent digits or decimals.
    /// (Elsewhere those vary between writers: Rust writes `3.5e-2` where Fortran writes
    /// `0.35E-01`.)
    pub fn is_cut(self, reference: &Written, last: bool) -> bool {
        let exponent_lost = reference.exponent.is_some() && self.exponent.is_none();
        let shorter = self.exponent < reference.exponent || self.decimals < reference.decimals;
        exponent_lost || (last && shorter)
    }
}

/// A field read as a cut copy of the same field of a reference row: its 0-based index, its
/// text and the reference's text.
pub struct Cut<'a> {
    pub field: usize,
    pub text: &'a str,
    pub was: &'a str,
}

impl Cut<'_> {
    /// The message a reader gives, naming the field (1-based) and the reference row's line;
    /// `last` says the file ends in this row without a newline.
    pub fn message(&self, reference_line: usize, last: bool) -> String {
        format!(
            "field {} (\"{}\") has fewer digits than the same field on line {reference_line} \
             (\"{}\"){}: the number looks cut",
            self.field + 1,
            self.text,
            self.was,
            if last {
                ", and the file ends in this line without a newline"
            } else {
                ""
            }
        )
    }
}

/// The first field of `fields` that is a cut copy of the same field of `reference` (see
/// [`Written::is_cut`]); fields beyond the reference's are not compared.
pub fn first_cut<'a>(fields: &[&'a str], reference: &[&'a str], last: bool) -> Option<Cut<'a>> {
    fields
        .iter()
        .zip(reference)
        .position(|(text, was)| Written::of(text).is_cut(&Written::of(was), last))
        .map(|field| Cut {
            field,
            text: fields[field],
            was: reference[field],
        })
}
