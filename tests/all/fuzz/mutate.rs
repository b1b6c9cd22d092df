//! Mutations of a text input: numbers replaced by the values that break size computations
//! and parsers, bytes flipped, inserted and deleted, lines deleted, duplicated, swapped and
//! spliced in from another input, the text cut anywhere.

use rand_xoshiro::rand_core::{Rng as _, SeedableRng};
use rand_xoshiro::Xoshiro256PlusPlus;

/// The fuzzer's random numbers: one seeded xoshiro256++ stream.
pub struct Rng(Xoshiro256PlusPlus);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(Xoshiro256PlusPlus::seed_from_u64(seed))
    }

    /// Uniform in 0..n (n > 0).
    pub fn below(&mut self, n: usize) -> usize {
        (self.0.next_u64() % n as u64) as usize
    }

    /// True with probability 1/n.
    pub fn one_in(&mut self, n: usize) -> bool {
        self.below(n) == 0
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }

    pub fn byte(&mut self) -> u8 {
        self.0.next_u64() as u8
    }
}

/// Values that break sizes, ranges and parsers, as text.
pub const INTERESTING: &[&str] = &[
    "0",
    "-0",
    "-1",
    "1",
    "2",
    "1e308",
    "-1e308",
    "1e-320",
    "1e400",
    "nan",
    "inf",
    "-inf",
    "NaN",
    "255",
    "65535",
    "4294967295",
    "4294967296",
    "2147483647",
    "-2147483648",
    "9223372036854775807",
    "18446744073709551615",
    "18446744073709551616",
    "1e9",
    "1e16",
    "1e200",
    "0.001",
    "1.",
    ".5",
    "1e",
    "0x10",
    "\"\"",
    "[]",
    "{}",
    "true",
];

/// Runs of bytes that look like a number: [0-9.eE+-] with at least one digit.
fn numbers(text: &[u8]) -> Vec<(usize, usize)> {
    let in_number = |b: u8| b.is_ascii_digit() || b"+-.eE".contains(&b);
    let mut out = Vec::new();
    let mut k = 0;
    while k < text.len() {
        if in_number(text[k]) {
            let start = k;
            while k < text.len() && in_number(text[k]) {
                k += 1;
            }
            if text[start..k].iter().any(u8::is_ascii_digit) {
                out.push((start, k));
            }
        } else {
            k += 1;
        }
    }
    out
}

/// Line boundaries of `text`: (start, end including the newline).
fn lines(text: &[u8]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = 0;
    for (k, &b) in text.iter().enumerate() {
        if b == b'\n' {
            out.push((start, k + 1));
            start = k + 1;
        }
    }
    if start < text.len() {
        out.push((start, text.len()));
    }
    out
}

/// One to four mutations of `input`; `other` is another input of the corpus to splice from.
pub fn mutate(rng: &mut Rng, input: &[u8], other: &[u8]) -> Vec<u8> {
    let mut text = input.to_vec();
    for _ in 0..1 + rng.below(4) {
        text = mutate_once(rng, &text, other);
    }
    text
}

fn mutate_once(rng: &mut Rng, text: &[u8], other: &[u8]) -> Vec<u8> {
    let mut out = text.to_vec();
    match rng.below(10) {
        // A number replaced by an interesting value (most mutations: they reach the checks
        // behind the parser).
        0..=3 => {
            let found = numbers(text);
            if !found.is_empty() {
                let (a, b) = *rng.pick(&found);
                out.splice(a..b, rng.pick(INTERESTING).bytes());
            }
        }
        4 => {
            if !out.is_empty() {
                let k = rng.below(out.len());
                out[k] ^= 1 << rng.below(8);
            }
        }
        5 => {
            let k = rng.below(out.len() + 1);
            let b = rng.byte();
            out.insert(k, b);
        }
        6 => {
            let found = lines(text);
            if !found.is_empty() {
                let (a, b) = *rng.pick(&found);
                if rng.one_in(2) {
                    out.drain(a..b);
                } else {
                    let line = text[a..b].to_vec();
                    out.splice(a..a, line);
                }
            }
        }
        7 => {
            let found = lines(text);
            if found.len() >= 2 {
                let (a, b) = *rng.pick(&found);
                let (c, d) = *rng.pick(&found);
                if b <= c {
                    let mut swapped = text[..a].to_vec();
                    swapped.extend_from_slice(&text[c..d]);
                    swapped.extend_from_slice(&text[b..c]);
                    swapped.extend_from_slice(&text[a..b]);
                    swapped.extend_from_slice(&text[d..]);
                    out = swapped;
                }
            }
        }
        8 => {
            let found = lines(other);
            if !found.is_empty() {
                let (a, b) = *rng.pick(&found);
                let at = lines(text)
                    .get(rng.below(lines(text).len() + 1))
                    .map_or(0, |l| l.0);
                out.splice(at..at, other[a..b].iter().copied());
            }
        }
        // Cut anywhere: a file that ends inside a number, a line or a string.
        _ => out.truncate(rng.below(text.len() + 1)),
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_lines_are_found() {
        assert_eq!(numbers(b"a = 1.5e3\nb = x2"), vec![(4, 9), (15, 16)]);
        assert_eq!(lines(b"ab\ncd"), vec![(0, 3), (3, 5)]);
    }
}
