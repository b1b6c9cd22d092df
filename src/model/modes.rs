// The modes: every setting that takes one of a few words, each defined once. A mode's
// variants, their words (as the configuration file, the case table and the messages spell
// them), the FMU parameter whose Integer code is a word's position (after the word that
// keeps the configuration's choice, where there is one) and one line per word: serde reads
// the words from here, the override table its words and codes, and build.rs (which
// `include!`s this file with its own `modes!`) checks modelDescription.xml's min, max and
// description of each FMU parameter against it. A new mode, or a new word, is one edit
// here (and its XML when it has an FMU parameter).
//
// Syntax: `Name [in "fmuParameter" [, keeping "word": "description"]] { Variant = "word":
// "description", ... }`; the descriptions are the ones the XML lists ("1 separate (...)").

modes! {
    /// The kind of a sea's spectrum (`[sea] spectrum`; `sea_state::Spectrum::kind`).
    SpectrumKind {
        /// JONSWAP in the DNV-RP-C205 form.
        Jonswap = "jonswap": "JONSWAP (DNV-RP-C205) from hs, tp and gamma",
        /// Pierson-Moskowitz.
        PiersonMoskowitz = "pierson-moskowitz": "Pierson-Moskowitz from hs and tp",
        /// A tabulated density.
        Table = "table": "the density tabulated at omega",
    }

    /// The kind of a sea's directional spreading (`[sea] spreading`;
    /// `sea_state::Spreading::kind`).
    SpreadingKind {
        /// One direction.
        LongCrested = "long-crested": "one direction, the mean direction",
        /// The paper's cos^N (E&S 11).
        CosN = "cos-n": "cos^N (E&S 11), N = spreading_exponent",
        /// DNV's cos-2s.
        Cos2s = "cos-2s": "DNV's cos-2s, s = spreading_exponent",
    }

    /// How the slowly varying wave force is computed from second-order theory
    /// (`[model] second_order`; docs/theory.md#the-slowly-varying-force).
    SecondOrder {
        /// Newman's approximation from the drift table's diagonal, in the form `newman`.
        Newman = "newman": "Newman's approximation from the drift table's diagonal",
        /// The full difference-frequency QTF of the drift source, factorised at FFT cost
        /// (`forces::QtfFactorisation`), truncated at `qtf_tolerance`.
        FullQtf = "full-qtf":
            "the full difference-frequency QTF of the drift source, factorised",
    }

    /// Which form of Newman's approximation builds the slowly varying records
    /// (`[model] newman`; docs/theory.md#the-slowly-varying-force).
    NewmanForm {
        /// The paper's form (E&S 4): T_ij = sign * sqrt(T_ii T_jj) where the signs agree, 0
        /// otherwise.
        Geometric = "geometric": "sign sqrt(T_ii T_jj) where the signs agree, else 0 (E&S 4)",
        /// T_ij = (T_ii + T_jj) / 2.
        Arithmetic = "arithmetic": "(T_ii + T_jj) / 2",
    }

    /// Whether the components of different directions of a short-crested sea interact in the
    /// slowly varying force (`[model] interaction`;
    /// docs/theory.md#the-slowly-varying-force; `forces::directional`).
    Interaction in "interaction", keeping "configuration": "keep the configuration's" {
        /// The default: [`Interaction::Bidirectional`] when the drift source has
        /// bi-directional drift, else [`Interaction::MeanDirection`]. Without cross terms the
        /// slow-drift variance falls roughly like 1/N_beta as a spread sea is split into more
        /// directions (README "Spread seas"), so some interaction is always on unless asked
        /// otherwise.
        Auto = "auto":
            "bidirectional when the drift source has bi-directional drift, else mean-direction",
        /// Cross terms from the bi-directional drift of the drift source.
        Bidirectional = "bidirectional": "T(w; b_k, b_l), the drift source's bi-directional drift",
        /// Cross terms from T(omega; (beta_k + beta_l)/2) of the uni-directional drift table.
        MeanDirection = "mean-direction": "T(w; (b_k + b_l)/2) of the drift table",
        /// Each direction's own double sum only (no cross-direction terms).
        None = "none": "each direction's own double sum",
    }

    /// Where the wave-drift damping coefficients b_ij(omega, beta) come from
    /// (`[model] drift_damping`; docs/theory.md#wave-drift-damping-and-current).
    DriftDamping in "driftDamping" {
        /// No wave-drift damping.
        Off = "off": "no wave-drift damping",
        /// The b_ij columns of the drift table.
        Table = "table": "the drift table's coefficients b_ij",
        /// Aranha's formula from the drift table and its derivatives.
        Aranha = "aranha": "Aranha's formula on the drift table and its derivatives",
    }

    /// The kind of Morison drag model (`[model] drag`; `DragModel::kind`, E&S 8, 9).
    DragKind in "dragModel" {
        /// No viscous drag.
        Off = "off": "no viscous drag",
        /// Separate slow and fast parts (E&S 8).
        Separate = "separate": "C_DS U|U| + C_DL u|u|, E&S 8",
        /// One coefficient on the total relative velocity (E&S 9).
        Combined = "combined": "C_D (U + u)|U + u|, E&S 9",
    }

    /// Whether the wave-frequency (first-order) motion of the RAOs is added to the slow drift
    /// (`[model] wave_frequency_motion`; docs/theory.md#wave-frequency-motion). It never
    /// enters the slow-drift equations.
    WaveFrequencyMotion in "waveFrequencyMotion" {
        /// The slow drift alone: the wave-frequency outputs zero, the totals the slow drift.
        Off = "off": "the slow drift alone",
        /// The default: the RAOs' wave-frequency motion on the slow drift where the platform
        /// has RAOs (problem::motions), none otherwise.
        On = "on": "the RAOs' wave-frequency motion on the slow drift, where the platform has RAOs",
    }

    /// Where a database source's bi-directional drift comes from instead of its own table
    /// (`[drift] bidirectional`; absent: the database's own, if any).
    BidirectionalDrift {
        /// The deep-water column solver on `[[platform.columns]]` at the database's drift
        /// frequencies.
        ColumnArray = "column-array":
            "the deep-water column solver on the platform's columns",
    }

    /// The kind of the wind's gust spectrum, the longitudinal turbulence of the wind speed
    /// (`[wind] spectrum`; `wind::GustSpectrum::kind`, docs/theory.md#wind).
    WindSpectrumKind in "windSpectrum", keeping "configuration": "keep the configuration's" {
        /// NPD / Froya (ISO 19901-1, DNV-RP-C205 sec. 2.3.4).
        Npd = "npd": "NPD (Froya; ISO 19901-1, DNV-RP-C205) from the 1-hour mean at 10 m",
        /// API RP 2A (sec. 2.3.2).
        Api = "api": "API RP 2A from the 1-hour mean at the height and the turbulence intensity",
        /// Harris (1971).
        Harris = "harris": "Harris (1971), length 1800 m, from U10 and the drag coefficient",
        /// Davenport (1961).
        Davenport = "davenport": "Davenport (1961), length 1200 m, from U10 and the drag coefficient",
        /// Kaimal (IEC 61400-1).
        Kaimal = "kaimal": "Kaimal (IEC 61400-1) from the 10-min mean, intensity and length scale",
        /// Ochi and Shin (1988).
        OchiShin = "ochi-shin": "Ochi & Shin (1988) from U10 and the drag coefficient",
        /// No gust: the mean speed alone.
        Constant = "constant": "no gust: the mean speed alone",
    }

    /// Where the wind speed at the force's height comes from (`[wind] source`,
    /// docs/theory.md#wind-force).
    WindSource in "windSource" {
        /// The default: the mean speed and its gusts from the spectrum, seeded as the waves.
        Records = "records": "the mean speed with the gust spectrum's records",
        /// The FMU's input `windVelocity_ext`, held over each communication step (0 m/s,
        /// still air, outside an FMU); no gust records are made.
        Input = "input": "the input windVelocity_ext, held over each communication step",
    }

    /// The mean wind profile, the mean speed from its reference height to the height of the
    /// wind force (`[wind] profile`; `wind::WindProfile::kind`, docs/theory.md#wind).
    WindProfileKind {
        /// U(z) = U_r (z / z_r)^alpha.
        PowerLaw = "power-law": "U_r (z / z_r)^alpha",
        /// U(z) = U_r ln(z / z0) / ln(z_r / z0).
        Logarithmic = "logarithmic": "U_r ln(z / z0) / ln(z_r / z0)",
        /// ISO 19901-1 / NPD: U(z) = U0 [1 + C ln(z / 10)] from the 1-hour mean.
        Npd = "npd": "ISO 19901-1 / NPD from the 1-hour mean, with its averaging periods",
    }
}
