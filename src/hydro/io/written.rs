//! How a number is written, to tell a number cut short from a whole one (issue #15): a
//! reader compares a number with the same field of an earlier line of its file. A field
//! whose earlier number has an exponent must have one with as many digits (a mantissa
//! whose exponent was lost, `6.273170` for `6.273170E+09`, reads a billion times too
//! small); on the last line of a file that ends without a newline, where a file cut inside
//! a number ends, a field must also have as many decimals.

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
    /// (the same field of an earlier line): its exponent lost or shortened where the
    /// reference has one; on a file's unterminated last line (`last`) also fewer decimals.
    pub fn is_cut(self, reference: &Written, last: bool) -> bool {
        let exponent_lost = match (self.exponent, reference.exponent) {
            (_, None) => false,
            (None, Some(_)) => true,
            (Some(digits), Some(expected)) => digits < expected,
        };
        exponent_lost || (last && self.decimals < reference.decimals)
    }
}
