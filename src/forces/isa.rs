//! The instruction sets the vector kernels are built for, chosen at run time: the
//! baseline of the target, and AVX2 on x86-64 CPUs that have it. A kernel does the same
//! operations in the same order on every instruction set (no fused multiply-add), so its
//! results are the same bits on every CPU; only its speed differs.

/// An instruction set a kernel is compiled for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Isa {
    /// The target's baseline (x86-64: SSE2, registers of 128 bits).
    Baseline,
    /// AVX2: registers of 256 bits (four doubles, eight floats).
    #[cfg(target_arch = "x86_64")]
    Avx2,
}

impl Isa {
    /// The widest this CPU runs.
    pub fn detect() -> Isa {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") {
            return Isa::Avx2;
        }
        Isa::Baseline
    }

    /// The instruction set's name, as a run's summary gives it.
    pub fn name(self) -> &'static str {
        match self {
            Isa::Baseline => "baseline",
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => "AVX2",
        }
    }

    /// Every instruction set this CPU runs (for the tests and the benchmarks).
    pub fn available() -> Vec<Isa> {
        let mut all = vec![Isa::Baseline];
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") {
            all.push(Isa::Avx2);
        }
        all
    }
}
