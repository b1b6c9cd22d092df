//! Fast (wave-frequency) kinematics at the columns, precomputed as records for the Morison
//! drag (E&S 8, 9; docs/theory.md#viscous-drag).
//!
//! Deep-water linear theory, at the columns' mean positions with the body at zero yaw:
//!   eta_c(t) = Re sum a_n e^{-i k_n (x_c cos b + y_c sin b)} e^{i omega_n t},
//!   u(z, t)  = Re sum a_n omega_n e^{k_n z} (cos b, sin b) e^{-i k_n (...)} e^{i omega_n t},
//! k_n = omega_n^2 / g, summed over the directions of the sea.
//!
//! Stretching: the wetted column, from the keel z = -d to the instantaneous surface
//! z = eta, is mapped linearly onto [-d, 0] (Wheeler's rule anchored at the keel instead of
//! the sea bed). Strip j of n then always sits at the fixed stretched level
//! z'_j = -d + (j + 1/2) d / n, so its velocity record is computed exactly once, and the
//! velocity at the surface is the linear-theory value at z = 0.

mod recombination;

use super::depth_basis::DepthBasis;
use super::record::SamplePoint;
use super::synthesis::Synthesizer;
use crate::forces::isa::Isa;
use crate::model::Cylinder;
use crate::sea_state::{Direction, FrequencyGrid, WaveComponents};
use recombination::{append_rows, lay_out_weights, RowLayout, Rows};
use rustfft::num_complex::{Complex32, Complex64};
use std::sync::Arc;

/// Rows a group holds at a time ([`Kinematics::make_rows`]): 512 s at the default 0.5-s
/// sampling, about 86 kB per group of the default platform (against 2.9 MB for a whole
/// block's rows), so that the rows are read while they are still in the core's cache.
pub const ROWS_WINDOW: usize = 1024;

/// The drag columns' kinematics records: every column, and the records of every group of
/// columns that share them ([`KinematicsKey`]).
///
/// A group's records are rows, sample-major: row m holds sample m of every series, so that
/// the drag reads one contiguous row per column and stage. A row is a run of floats: the
/// free-surface elevation at the column centre (m), then the horizontal velocity at every
/// strip's stretched level in strip order (body frame, m/s), as (u_x, u_y) pairs
/// ([`RowLayout::Interleaved`]: 1 + 2 strips floats), or u_x alone in waves along x, where
/// u_y = 0 on every strip ([`RowLayout::AlongX`]: 1 + strips floats, half the memory of a
/// row of complex samples).
///
/// The rows are stored in single precision: the transforms run in single precision
/// (`forces::synthesis`: their error 1.3e-7 of a series' rms), their joined outputs are
/// rounded to 24 significant bits (relative 6e-8, a few 1e-7 m/s for these velocities) and
/// the strips' velocities are recombined from the depth terms in single
/// precision ([`DepthBasis`], truncated at a relative rms error of 1e-6). The drag formulas
/// work in double precision on the stored values. The tests bound the difference from the
/// double-precision sums.
///
/// A segment's build makes the depth terms' series; the rows are recombined from them as
/// the run reaches them, into a window of [`ROWS_WINDOW`] rows ([`Kinematics::make_rows`],
/// which the simulation calls before each step), so an initialisation makes none, a run
/// shorter than the block only the rows it reads, and the rows take a window's memory, not
/// a block's. A row outside the window is recombined where it is read, by the same
/// operations ([`Rows::strip_float`]): the values never depend on which rows the window
/// holds.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Kinematics {
    columns: Vec<ColumnEntry>,
    groups: Vec<GroupRecords>,
}

/// A column, and the group whose records it reads.
#[derive(Debug, Clone, PartialEq)]
struct ColumnEntry {
    column: Cylinder,
    group: usize,
}

/// The records of one group of columns: the depth terms' series and the rows made so far.
#[derive(Debug, Clone, Default)]
struct GroupRecords {
    /// The series the rows are recombined from: the elevation at the columns' centre (m),
    /// the depth terms and their weights, the strips and how a row holds them (as many
    /// samples each as the elevation has: [`GroupRecords::len`]).
    source: Rows,
    /// The window's first row.
    first: usize,
    /// Rows first .. first + rows.len() / floats_per_sample, at most [`ROWS_WINDOW`].
    rows: Vec<f32>,
    /// One sample of every term (the recombination's scratch).
    samples: Vec<Complex32>,
}

/// Two groups' records are the same when the series their rows come from are: the rows
/// made so far are a function of them.
impl PartialEq for GroupRecords {
    fn eq(&self, other: &Self) -> bool {
        self.source == other.source
    }
}

impl GroupRecords {
    /// Samples per series.
    fn len(&self) -> usize {
        self.source.eta.len()
    }

    /// Floats of one row: the elevation and the strips' velocities.
    fn floats_per_sample(&self) -> usize {
        1 + self.source.layout.per_strip() * self.source.strips
    }

    /// The rows the window holds.
    #[cfg(test)]
    fn window(&self) -> std::ops::Range<usize> {
        self.first..self.first + self.rows.len() / self.floats_per_sample()
    }

    /// Whether the window holds rows `start .. end` (`end` at most the series' length; a
    /// product, not a division: asked before every step).
    #[inline]
    fn holds(&self, start: usize, end: usize) -> bool {
        let end = end.min(self.len());
        self.first <= start && self.rows.len() >= (end - self.first) * self.floats_per_sample()
    }

    /// Moves the window to rows `start .. start + ROWS_WINDOW` (at most the series' length).
    fn make_rows_from(&mut self, start: usize, isa: Isa) {
        let start = start.min(self.len());
        let end = (start + ROWS_WINDOW).min(self.len());
        self.first = start;
        self.rows.clear();
        append_rows(
            isa,
            &self.source,
            start..end,
            &mut self.samples,
            &mut self.rows,
        );
    }

    /// Row m when the window holds it: the elevation and the strips' velocities.
    #[inline]
    fn row(&self, m: usize) -> Option<(f64, StripVelocities<'_>)> {
        let width = self.floats_per_sample();
        let k = m.checked_sub(self.first)?;
        let row = self.rows.get(k * width..(k + 1) * width)?;
        let (eta, velocities) = row.split_first()?;
        let velocities = match self.source.layout {
            RowLayout::Interleaved => StripVelocities::Interleaved(velocities.as_chunks().0),
            RowLayout::AlongX => StripVelocities::AlongX(velocities),
        };
        Some((f64::from(*eta), velocities))
    }

    /// Float i of row m, in the window or not.
    #[inline]
    fn float(&self, m: usize, i: usize) -> f32 {
        let width = self.floats_per_sample();
        let held = m
            .checked_sub(self.first)
            .and_then(|k| self.rows.get(k * width + i));
        match held {
            Some(&v) => v,
            None => self.recombined(m, i),
        }
    }

    /// Float i of row m recombined here (a row outside the window: rare, so kept out of
    /// the readers' inlined code).
    #[cold]
    #[inline(never)]
    fn recombined(&self, m: usize, i: usize) -> f32 {
        match i {
            0 => self.source.eta[m],
            _ => self.source.strip_float(m, i - 1),
        }
    }
}

impl Kinematics {
    /// Number of columns.
    pub fn len(&self) -> usize {
        self.columns.len()
    }

    /// Whether there are no columns (no drag).
    pub fn is_empty(&self) -> bool {
        self.columns.is_empty()
    }

    /// Column c's kinematics.
    #[inline]
    pub fn column(&self, c: usize) -> ColumnKinematics<'_> {
        let entry = &self.columns[c];
        ColumnKinematics {
            column: &entry.column,
            group: entry.group,
            records: &self.groups[entry.group],
        }
    }

    /// The bytes the records hold: each group's series (the elevation, the depth terms, the
    /// weights) and its window of rows, as allocated.
    pub fn bytes(&self) -> usize {
        let f32s = |v: &Vec<f32>| v.capacity() * std::mem::size_of::<f32>();
        self.groups
            .iter()
            .map(|g| {
                f32s(&g.source.eta)
                    + f32s(&g.source.weights)
                    + f32s(&g.rows)
                    + (g.source.series.capacity() + g.samples.capacity())
                        * std::mem::size_of::<Complex32>()
            })
            .sum()
    }

    /// Every column's kinematics, in order.
    pub fn columns(&self) -> impl ExactSizeIterator<Item = ColumnKinematics<'_>> {
        (0..self.len()).map(|c| self.column(c))
    }

    /// Makes every group's window hold rows `start .. end` (`end` exclusive): when one does
    /// not, the windows move to the [`ROWS_WINDOW`] rows from `start`, recombined on the widest
    /// instruction set the CPU has (the same bits on every one). Rows past the window (a
    /// span longer than it) are read all the same, recombined where they are read.
    /// Allocates nothing: the build reserves a window's memory.
    pub fn make_rows(&mut self, start: usize, end: usize) {
        if self.groups.iter().all(|g| g.holds(start, end)) {
            return;
        }
        let isa = Isa::detect();
        for group in &mut self.groups {
            group.make_rows_from(start, isa);
        }
    }
}

/// One column's kinematics: the column and its group's records.
#[derive(Debug, Clone, Copy)]
pub struct ColumnKinematics<'a> {
    pub column: &'a Cylinder,
    /// The group whose records it reads (columns alike in their key share one).
    group: usize,
    records: &'a GroupRecords,
}

/// The strips' velocities of one row as stored, in strip order, m/s.
#[derive(Debug, Clone, Copy)]
pub enum StripVelocities<'a> {
    /// (u_x, u_y) of every strip.
    Interleaved(&'a [[f32; 2]]),
    /// u_x of every strip (waves along x: u_y = 0).
    AlongX(&'a [f32]),
}

/// A column's kinematics at one located time.
#[derive(Debug, Clone, Copy)]
pub struct ColumnState<'a> {
    kinematics: ColumnKinematics<'a>,
    at: SamplePoint,
}

impl<'a> ColumnKinematics<'a> {
    /// The group of columns whose records this column reads: two columns of one group have
    /// the same kinematics, bit for bit, at every time.
    pub fn group(&self) -> usize {
        self.group
    }

    /// Number of strips.
    pub fn strips(&self) -> usize {
        self.records.source.strips
    }

    /// Floats of one row: the elevation and the strips' velocities.
    pub fn floats_per_sample(&self) -> usize {
        self.records.floats_per_sample()
    }

    /// The records at a located time.
    #[inline]
    pub fn at(&self, p: &SamplePoint) -> ColumnState<'a> {
        ColumnState {
            kinematics: *self,
            at: *p,
        }
    }

    /// The row at a located time when it falls on a sample and the row is made: the
    /// elevation, as [`ColumnState::eta`] gives it, and the strips' velocities, as
    /// [`ColumnState::velocities_on_sample`] does.
    #[inline]
    pub fn row_on_sample(&self, at: &SamplePoint) -> Option<(f64, StripVelocities<'a>)> {
        if at.on_sample() {
            self.records.row(at.index())
        } else {
            None
        }
    }

    /// Float i of the rows at a located time.
    #[inline]
    fn value(&self, i: usize, at: &SamplePoint) -> f64 {
        at.interpolate_with(self.records.len(), |m| f64::from(self.records.float(m, i)))
    }
}

impl ColumnState<'_> {
    /// Free-surface elevation at the column centre, m.
    #[inline]
    pub fn eta(&self) -> f64 {
        self.kinematics.value(0, &self.at)
    }

    /// Horizontal velocity (body x, y) at strip j, m/s.
    #[inline]
    pub fn velocity(&self, j: usize) -> [f64; 2] {
        let (k, at) = (&self.kinematics, &self.at);
        match k.records.source.layout {
            RowLayout::Interleaved => [k.value(1 + 2 * j, at), k.value(2 + 2 * j, at)],
            RowLayout::AlongX => [k.value(1 + j, at), 0.0],
        }
    }

    /// The strips' velocities when the time falls on a sample whose row is made (one
    /// contiguous slice of the row, single precision).
    #[inline]
    pub fn velocities_on_sample(&self) -> Option<StripVelocities<'_>> {
        self.kinematics
            .row_on_sample(&self.at)
            .map(|(_, velocities)| velocities)
    }
}

/// [`KinematicsWork::build`] into new buffers (the tests' shorthand).
#[cfg(test)]
pub(crate) fn column_kinematics(
    components: &WaveComponents,
    columns: &[Cylinder],
    strips: usize,
    gravity: f64,
    synth: &mut Synthesizer,
) -> Kinematics {
    let mut out = Kinematics::default();
    KinematicsWork::default().build(components, columns, strips, gravity, synth, &mut out);
    out
}

/// The buffers of the kinematics records, kept from one build to the next (a stream's
/// segments): a build into records of the same shape allocates nothing.
#[derive(Default, Clone)]
pub struct KinematicsWork {
    zero: Vec<Complex64>,
    cx: Vec<Complex64>,
    cy: Vec<Complex64>,
    /// The direction sums (A_x, A_y, A) of every group of columns that share their records.
    sums: Vec<[Vec<Complex64>; 3]>,
    /// The first column of every such group.
    groups: Vec<usize>,
    /// The depth kernel of every draft built so far on these components' grid and spectrum
    /// (or given by the record plan).
    bases: Vec<Arc<DepthBasis>>,
    /// The groups' elevation series, two per transform (groups 2p and 2p + 1 as the real
    /// and imaginary parts of pair p's N samples), in single precision.
    eta: Vec<Complex32>,
    /// The key of every column.
    keys: Vec<KinematicsKey>,
    /// The phases of every group of columns built so far on these components' frequencies
    /// (or given by the record plan).
    phases: Vec<Arc<ColumnPhases>>,
}

/// e^{-i k_j d} for every direction and wave component j of a column centre at distance d
/// along the direction (the phase [`direction_sums`] gives each amplitude): the same for
/// every seed, so a record plan makes them once ([`KinematicsWork::for_plan`]).
#[derive(Debug)]
struct ColumnPhases {
    key: KinematicsKey,
    /// The frequencies they are on: (first, count, d_omega) of the grid, and gravity.
    frequencies: (usize, usize, f64, f64),
    /// Per direction, per component.
    phases: Vec<Vec<Complex64>>,
}

impl ColumnPhases {
    /// The phases of columns of key `key` on `grid` (k_j = omega_j^2 / gravity).
    fn new(grid: &FrequencyGrid, key: &KinematicsKey, gravity: f64) -> Self {
        let phases = key
            .along
            .iter()
            .map(|&along| {
                (0..grid.count)
                    .map(|j| {
                        let wavenumber = grid.omega(j).powi(2) / gravity;
                        Complex64::from_polar(1.0, -wavenumber * along)
                    })
                    .collect()
            })
            .collect();
        ColumnPhases {
            key: key.clone(),
            frequencies: Self::frequencies(grid, gravity),
            phases,
        }
    }

    fn frequencies(grid: &FrequencyGrid, gravity: f64) -> (usize, usize, f64, f64) {
        (grid.first, grid.count, grid.d_omega, gravity)
    }

    /// Whether these are the phases of key `key` on `grid`.
    fn fits(&self, key: &KinematicsKey, grid: &FrequencyGrid, gravity: f64) -> bool {
        self.key == *key && self.frequencies == Self::frequencies(grid, gravity)
    }
}

impl KinematicsWork {
    /// Buffers whose builds take the depth kernels from `bases` and the phases of `columns`
    /// on `components`' frequencies, made here, when they fit the column, the grid and the
    /// spectrum, else make their own: a record plan's, made once for all its seeds.
    pub fn for_plan(
        bases: Vec<Arc<DepthBasis>>,
        components: &WaveComponents,
        columns: &[Cylinder],
        gravity: f64,
    ) -> Self {
        let mut work = KinematicsWork {
            bases,
            ..KinematicsWork::default()
        };
        for column in columns {
            let key = KinematicsKey::of(&components.directions, column);
            if !work.phases.iter().any(|p| p.key == key) {
                let phases = ColumnPhases::new(&components.grid, &key, gravity);
                work.phases.push(Arc::new(phases));
            }
        }
        work
    }

    /// The kinematics records of every column with `strips` strips each, into `out` (whose
    /// previous records' buffers are reused), with no row made yet
    /// ([`Kinematics::make_rows`]).
    ///
    /// The depth profile omega e^{k z} is real and the same for every direction, so each
    /// column's direction sums are taken once (A_x, A_y for the velocity, A for the
    /// elevation). Strip j's coefficients would be omega_n e^{k_n z_j} (A_x, A_y)_n, one
    /// transform per strip; the depth kernel's few leading terms ([`DepthBasis`], at a
    /// relative rms error of 1e-6) take one transform each
    /// ([`Synthesizer::append_two_real_series`]: u_x + i u_y of the term; in waves along x,
    /// where u_y = 0, two terms' u_x share one), and every row's strip velocities are
    /// recombined from them. The elevations (real) of two groups of columns share one
    /// transform.
    pub fn build(
        &mut self,
        components: &WaveComponents,
        columns: &[Cylinder],
        strips: usize,
        gravity: f64,
        synth: &mut Synthesizer,
        out: &mut Kinematics,
    ) {
        out.columns.clear();
        if columns.is_empty() {
            // No drag: no records, and no record-length scratch to allocate and fault in.
            out.groups.clear();
            return;
        }
        let count = components.grid.count;
        for v in [&mut self.zero, &mut self.cx, &mut self.cy] {
            refill(v, std::iter::repeat_n(Complex64::default(), count));
        }
        if self.keys.len() != columns.len() {
            self.keys = columns
                .iter()
                .map(|c| KinematicsKey::of(&components.directions, c))
                .collect();
        }
        // The groups' direction sums, and their elevations two to a transform (each is
        // real).
        let keys = &self.keys;
        self.groups.clear();
        self.groups
            .extend((0..columns.len()).filter(|&c| !keys[..c].contains(&keys[c])));
        if self.sums.len() < self.groups.len() {
            self.sums.resize_with(self.groups.len(), Default::default);
        }
        let grid = &components.grid;
        for (sums, &c) in self.sums.iter_mut().zip(&self.groups) {
            let key = &keys[c];
            let phases = match self.phases.iter().position(|p| p.fits(key, grid, gravity)) {
                Some(p) => p,
                None => {
                    // Other frequencies: their phases will not be asked for again.
                    let on_grid = ColumnPhases::frequencies(grid, gravity);
                    self.phases.retain(|p| p.frequencies == on_grid);
                    self.phases
                        .push(Arc::new(ColumnPhases::new(grid, key, gravity)));
                    self.phases.len() - 1
                }
            };
            direction_sums(components, &self.phases[phases].phases, sums);
        }
        self.eta.clear();
        self.eta
            .reserve(self.groups.len().div_ceil(2) * synth.output_len());
        for pair in self.sums[..self.groups.len()].chunks(2) {
            let second = pair.get(1).map_or(&self.zero[..], |sums| &sums[2][..]);
            synth.append_two_real_series(&pair[0][2], second, &mut Narrowing(&mut self.eta));
        }
        out.groups
            .resize_with(self.groups.len(), GroupRecords::default);
        for (g, records) in out.groups.iter_mut().enumerate() {
            let column = &columns[self.groups[g]];
            self.group(components, g, column, strips, gravity, synth, records);
        }
        let keys = &self.keys;
        out.columns
            .extend(columns.iter().enumerate().map(|(c, column)| {
                let first = (0..=c).find(|&d| keys[d] == keys[c]).expect("c itself");
                let group = self.groups.iter().position(|&leader| leader == first);
                ColumnEntry {
                    column: column.clone(),
                    group: group.expect("the first column of every key leads a group"),
                }
            }));
    }

    /// The records of group `group`, led by `column`, into `records`: its elevation, its
    /// depth terms' series and their weights, and room for its rows (none made).
    #[allow(clippy::too_many_arguments)]
    fn group(
        &mut self,
        components: &WaveComponents,
        group: usize,
        column: &Cylinder,
        strips: usize,
        gravity: f64,
        synth: &mut Synthesizer,
        records: &mut GroupRecords,
    ) {
        let (n, count) = (synth.output_len(), components.grid.count);
        let basis = match self
            .bases
            .iter()
            .position(|b| b.fits(components, column.draft, strips))
        {
            Some(b) => b,
            None => {
                // Another grid or sea: its bases will not be asked for again.
                self.bases.retain(|b| b.is_on(components));
                self.bases.push(Arc::new(DepthBasis::new(
                    &components.grid,
                    components.expected_power(),
                    column.draft,
                    strips,
                    gravity,
                )));
                self.bases.len() - 1
            }
        };
        let basis = &self.bases[basis];
        let rank = basis.rank();
        let [ax, ay, _] = &self.sums[group];
        let along_x = ay[..count].iter().all(|&a| a == Complex64::default());
        let source = &mut records.source;
        source.series.clear();
        source.series.reserve(rank * n);
        if along_x {
            // Waves along x (long-crested head seas): u_y = 0 on every strip, so two terms'
            // u_x share a transform as its real and imaginary parts (half the transforms).
            for q in (0..rank).step_by(2) {
                let second = (q + 1 < rank).then(|| basis.profile(q + 1));
                for (j, &p) in basis.profile(q).iter().enumerate().take(count) {
                    self.cx[j] = ax[j] * p;
                    self.cy[j] = second.map_or(Complex64::default(), |s| ax[j] * s[j]);
                }
                let terms = &mut Narrowing(&mut source.series);
                synth.append_two_real_series(&self.cx, &self.cy, terms);
            }
        } else {
            for q in 0..rank {
                for (j, &p) in basis.profile(q).iter().enumerate().take(count) {
                    self.cx[j] = ax[j] * p;
                    self.cy[j] = ay[j] * p;
                }
                let terms = &mut Narrowing(&mut source.series);
                synth.append_two_real_series(&self.cx, &self.cy, terms);
            }
        }
        // V_jq laid out for the kernel (each twice, for u_x and u_y; once along x).
        let layout = if along_x {
            RowLayout::AlongX
        } else {
            RowLayout::Interleaved
        };
        lay_out_weights(layout, strips, rank, |q| basis.mix(q), &mut source.weights);
        // The group's elevation: the real part of its pair's series for the first of the
        // pair, the imaginary part for the second.
        let pair = &self.eta[group / 2 * n..][..n];
        let real = group.is_multiple_of(2);
        refill(
            &mut source.eta,
            pair.iter().map(|e| if real { e.re } else { e.im }),
        );
        (source.strips, source.layout, source.rank, source.paired) =
            (strips, layout, rank, along_x);
        // Row m: the elevation, then u_j(m) = sum_q V_jq g_q(m) for every strip j, in
        // single precision (the terms' rounding and the sum's, a few 1e-8 relative, are
        // below the storage's own and the truncation's 1e-6), summed over q in order.
        // The strips' floats are interleaved (u_x, u_y) (u_x alone in waves along x,
        // u_y = 0), recombined by the register-blocked kernel (kinematics/recombination.rs)
        // on the widest instruction set the CPU has (the same bits on every one), as the
        // run reaches them: room for a window of rows (and the padding the kernel writes
        // past the last one before dropping it), none made.
        records.first = 0;
        records.rows.clear();
        // The recombination's scratch, sized here so that making rows allocates nothing.
        records.samples.resize(rank, Complex32::default());
        let padding = layout.width(strips) - layout.per_strip() * strips;
        records
            .rows
            .reserve(ROWS_WINDOW.min(n) * records.floats_per_sample() + padding);
    }
}

/// Clears `v` and fills it from `values` (its capacity kept).
fn refill<T>(v: &mut Vec<T>, values: impl Iterator<Item = T>) {
    v.clear();
    v.extend(values);
}

/// A sink that stores the samples it takes in single precision ([`narrow`]).
struct Narrowing<'a>(&'a mut Vec<Complex32>);

impl Extend<Complex64> for Narrowing<'_> {
    fn extend<I: IntoIterator<Item = Complex64>>(&mut self, values: I) {
        self.0.extend(values.into_iter().map(narrow));
    }
}

/// A sample rounded to single precision for storage (to nearest).
#[inline]
fn narrow(v: Complex64) -> Complex32 {
    Complex32::new(v.re as f32, v.im as f32)
}

/// What a column's kinematics depend on besides the sea: its draft and, for every wave
/// direction, the distance of its centre along that direction. Two columns with equal keys
/// (say the two front columns of a square platform in head seas) have the same records,
/// bit for bit, and share one copy.
#[derive(Debug, PartialEq, Clone)]
struct KinematicsKey {
    draft: f64,
    along: Vec<f64>,
}

impl KinematicsKey {
    fn of(directions: &[Direction], column: &Cylinder) -> Self {
        KinematicsKey {
            draft: column.draft,
            along: directions
                .iter()
                .map(|dir| along(column, dir.heading))
                .collect(),
        }
    }
}

/// The number of distinct kinematics records of `columns` in a sea of `directions`: the
/// columns whose keys are equal share one ([`KinematicsKey`]).
pub fn distinct_kinematics(columns: &[Cylinder], directions: &[Direction]) -> usize {
    let keys: Vec<KinematicsKey> = columns
        .iter()
        .map(|c| KinematicsKey::of(directions, c))
        .collect();
    (0..keys.len())
        .filter(|&c| !keys[..c].contains(&keys[c]))
        .count()
}

/// Floats per sample of the rows of a column of `strips` strips in a sea of `directions`,
/// at most ([`ColumnKinematics::floats_per_sample`]): 1 + strips when every direction is
/// along x (sin b = 0, so A_y = 0 and the rows hold u_x alone), else 1 + 2 strips.
pub fn kinematics_row_floats(strips: usize, directions: &[Direction]) -> usize {
    let layout = if directions.iter().all(|d| d.heading.sin() == 0.0) {
        RowLayout::AlongX
    } else {
        RowLayout::Interleaved
    };
    1 + layout.per_strip() * strips
}

/// Distance of the column centre along a wave heading, m.
fn along(column: &Cylinder, heading: f64) -> f64 {
    let (sin, cos) = heading.sin_cos();
    column.x * cos + column.y * sin
}

/// sum over directions of the amplitudes with the phase of the column centre (`phases`:
/// [`ColumnPhases`]), times (cos b, sin b, 1), into `sums`.
fn direction_sums(
    components: &WaveComponents,
    phases: &[Vec<Complex64>],
    sums: &mut [Vec<Complex64>; 3],
) {
    let grid = &components.grid;
    for s in sums.iter_mut() {
        refill(s, std::iter::repeat_n(Complex64::default(), grid.count));
    }
    for (k, dir) in components.directions.iter().enumerate() {
        let (sin, cos) = dir.heading.sin_cos();
        let amplitudes = components.of_direction(k).iter().zip(&phases[k]);
        for (j, (a, phase)) in amplitudes.enumerate() {
            let phased = a * phase;
            sums[0][j] += phased * cos;
            sums[1][j] += phased * sin;
            sums[2][j] += phased;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sea_state::{FrequencyGrid, SeaState, Spectrum, Spreading};
    use std::f64::consts::PI;

    /// The clock of records over the grid's whole period (no stream).
    fn whole_period(grid: &FrequencyGrid) -> crate::forces::RecordClock {
        crate::forces::RecordClock {
            start_time: grid.start_time,
            dt: grid.dt,
            len: grid.len,
        }
    }

    const GRAVITY: f64 = 9.80665;

    fn square(draft: f64) -> Vec<Cylinder> {
        [(35.0, 35.0), (-35.0, 35.0), (-35.0, -35.0), (35.0, -35.0)]
            .map(|(x, y)| Cylinder {
                x,
                y,
                diameter: 20.0,
                draft,
            })
            .to_vec()
    }

    fn components(mean_direction: f64, spreading: Spreading) -> WaveComponents {
        let sea = SeaState {
            spectrum: Spectrum::Jonswap {
                hs: 6.0,
                tp: 10.0,
                gamma: Some(3.3),
            },
            spreading,
            mean_direction,
            n_directions: 5,
            seed: 7,
            band: None,
        };
        let grid = FrequencyGrid::new(0.0, 600.0, 0.5, sea.band()).unwrap();
        WaveComponents::generate(&sea, grid)
    }

    /// Direct sums of linear theory (the module's formulas, term by term, with no FFT and
    /// no shared factors): elevation at the centre and velocity at stretched level z.
    fn direct(c: &WaveComponents, column: &Cylinder, z: f64, t: f64) -> [f64; 3] {
        let mut out = [0.0; 3];
        for (k, dir) in c.directions.iter().enumerate() {
            for (j, a) in c.of_direction(k).iter().enumerate() {
                let w = c.grid.omega(j);
                let wavenumber = w * w / GRAVITY;
                let phase = w * t
                    - wavenumber * (column.x * dir.heading.cos() + column.y * dir.heading.sin());
                let e = (a * Complex64::from_polar(1.0, phase)).re;
                let speed = w * (wavenumber * z).exp() * e;
                out[0] += e;
                out[1] += speed * dir.heading.cos();
                out[2] += speed * dir.heading.sin();
            }
        }
        out
    }

    /// The direct sums at t, or between samples their cubic Lagrange interpolation from
    /// the four samples around t (what the records promise: record.rs).
    fn expected(c: &WaveComponents, column: &Cylinder, z: f64, t: f64) -> [f64; 3] {
        let s = t / c.grid.dt - (t / c.grid.dt).floor();
        if s == 0.0 {
            return direct(c, column, z, t);
        }
        let t0 = t - s * c.grid.dt;
        let nodes = [-1.0f64, 0.0, 1.0, 2.0];
        let mut out = [0.0; 3];
        for (i, &xi) in nodes.iter().enumerate() {
            let weight: f64 = nodes
                .iter()
                .enumerate()
                .filter(|&(k, _)| k != i)
                .map(|(_, &xk)| (s - xk) / (xi - xk))
                .product();
            let v = direct(c, column, z, t0 + xi * c.grid.dt);
            for (o, v) in out.iter_mut().zip(v) {
                *o += weight * v;
            }
        }
        out
    }

    /// Strip j's stored velocity (u_x, u_y), in double precision.
    fn stored(velocities: StripVelocities, j: usize) -> [f64; 2] {
        match velocities {
            StripVelocities::Interleaved(u) => u[j].map(f64::from),
            StripVelocities::AlongX(u) => [u[j].into(), 0.0],
        }
    }

    /// What single-precision storage may change, m or m/s: 2^-24 relative of values of a few
    /// units (Hs = 6 m) is 3e-7; the transforms' own error is some 1e-14.
    const STORED: f64 = 1e-6;

    /// Every column's records (shared or not) equal the direct sums at samples and their
    /// cubic interpolation between samples, for head seas and a spread sea, to within the
    /// rounding of single-precision storage.
    #[test]
    fn records_equal_the_direct_sums_of_linear_theory() {
        let strips = 5;
        for c in [
            components(0.0, Spreading::LongCrested),
            components(PI / 6.0, Spreading::CosN { n: 2.0 }),
        ] {
            let columns = square(30.0);
            let mut synth = Synthesizer::new(&c.grid);
            let mut records = column_kinematics(&c, &columns, strips, GRAVITY, &mut synth);
            records.make_rows(0, 1);
            let clock = whole_period(&c.grid);
            for (record, column) in records.columns().zip(&columns) {
                assert_eq!(record.strips(), strips);
                for t in [0.0, 137.5, 401.0, 250.3, 0.2] {
                    let state = record.at(&clock.locate(t).unwrap());
                    let eta = expected(&c, column, 0.0, t)[0];
                    assert!((state.eta() - eta).abs() < STORED, "t {t}: {}", state.eta());
                    // The window (its first ROWS_WINDOW rows) holds every sample read here.
                    let on_sample = state.velocities_on_sample();
                    assert_eq!(on_sample.is_some(), (t / c.grid.dt).fract() == 0.0);
                    for j in 0..strips {
                        let z = -30.0 + (j as f64 + 0.5) * 30.0 / strips as f64;
                        let [_, x, y] = expected(&c, column, z, t);
                        let [ux, uy] = state.velocity(j);
                        if let Some(row) = on_sample {
                            assert_eq!(stored(row, j), [ux, uy]);
                        }
                        assert!(
                            (ux - x).abs() < STORED && (uy - y).abs() < STORED,
                            "t {t} column ({}, {}) strip {j}: ({ux}, {uy}) vs ({x}, {y})",
                            column.x,
                            column.y,
                        );
                    }
                }
            }
        }
    }

    /// In waves along x the rows hold the elevation and u_x alone, 1 + strips floats per
    /// sample (against 1 + 2 strips in a spread sea; the budget's count,
    /// [`kinematics_row_floats`], is the same), and at every sample the clock locates every
    /// strip's velocity read from them, on the sample's slice and through `velocity` alike, is the direct
    /// double-precision sums' to within single-precision storage, with u_y exactly 0.
    #[test]
    fn rows_in_waves_along_x_hold_u_x_alone() {
        let strips = 6;
        let columns = square(30.0);
        for (c, floats) in [
            (components(0.0, Spreading::LongCrested), 1 + strips),
            (
                components(PI / 6.0, Spreading::CosN { n: 2.0 }),
                1 + 2 * strips,
            ),
        ] {
            let along_x = floats == 1 + strips;
            assert_eq!(kinematics_row_floats(strips, &c.directions), floats);
            let mut synth = Synthesizer::new(&c.grid);
            let mut records = column_kinematics(&c, &columns, strips, GRAVITY, &mut synth);
            let clock = whole_period(&c.grid);
            for (index, column) in columns.iter().enumerate() {
                // Every sample the clock locates (all but the last), the window moved to it.
                for m in 0..c.grid.len - 1 {
                    records.make_rows(m, m + 1);
                    let record = records.column(index);
                    assert_eq!(record.floats_per_sample(), floats);
                    assert_eq!(record.records.rows.len() % floats, 0);
                    let t = c.grid.start_time + m as f64 * c.grid.dt;
                    let state = record.at(&clock.locate(t).unwrap());
                    let row = state.velocities_on_sample().expect("on a sample");
                    assert_eq!(matches!(row, StripVelocities::AlongX(_)), along_x);
                    for j in 0..strips {
                        let [ux, uy] = state.velocity(j);
                        assert_eq!(stored(row, j), [ux, uy]);
                        if along_x {
                            let z = -30.0 + (j as f64 + 0.5) * 30.0 / strips as f64;
                            let [_, x, y] = direct(&c, column, z, t);
                            assert_eq!((uy, y), (0.0, 0.0));
                            assert!((ux - x).abs() < STORED, "t {t} strip {j}: {ux} vs {x}");
                        }
                    }
                }
            }
        }
    }

    /// A record plan's phases ([`KinematicsWork::for_plan`]) give the records a build
    /// makes with its own, bit for bit, and the build takes them (it makes none): the
    /// square platform in a spread sea (four keys) and in head seas (two: the columns at
    /// the same x share theirs).
    #[test]
    fn a_plans_phases_give_the_records_made_without_them() {
        for (c, keys) in [
            (components(PI / 6.0, Spreading::CosN { n: 2.0 }), 4),
            (components(0.0, Spreading::LongCrested), 2),
        ] {
            let columns = square(30.0);
            let mut synth = Synthesizer::new(&c.grid);
            let own = column_kinematics(&c, &columns, 20, GRAVITY, &mut synth);
            let mut work = KinematicsWork::for_plan(Vec::new(), &c, &columns, GRAVITY);
            assert_eq!(work.phases.len(), keys);
            let made: Vec<*const ColumnPhases> = work.phases.iter().map(Arc::as_ptr).collect();
            let mut planned = Kinematics::default();
            work.build(&c, &columns, 20, GRAVITY, &mut synth, &mut planned);
            assert_eq!(own, planned);
            let used: Vec<*const ColumnPhases> = work.phases.iter().map(Arc::as_ptr).collect();
            assert_eq!(made, used, "the build made phases of its own");
        }
    }

    /// The rows recombined from the depth kernel's leading terms against one transform
    /// per strip (strip j's coefficients omega e^{k z_j} (A_x, A_y), no factorisation):
    /// the rms velocity error over the record and the strips is within twice the
    /// [`KINEMATICS_TOLERANCE`] of the rms velocity (the basis promises the tolerance in
    /// expectation; the factor covers one realisation, and the single-precision storage
    /// adds some 1e-8), for the default platform's draft (30 m, 20 strips) and a deeper
    /// one (60 m, 28 strips) in a spread sea, and a spar's (120 m, 40 strips) and a short
    /// column's (30 m, 12 strips) in head seas (waves along x: u_x alone).
    #[test]
    fn rows_from_the_depth_terms_match_one_transform_per_strip() {
        use super::super::depth_basis::KINEMATICS_TOLERANCE;
        for (c, draft, strips) in [
            (components(PI / 6.0, Spreading::CosN { n: 2.0 }), 30.0, 20),
            (components(0.0, Spreading::LongCrested), 120.0, 40),
            // Interleaved (u_x, u_y): 7 blocks of 8 floats, recombined as 4 + 3; u_x alone
            // (waves along x): 2 blocks.
            (components(PI / 6.0, Spreading::CosN { n: 2.0 }), 60.0, 28),
            (components(0.0, Spreading::LongCrested), 30.0, 12),
        ] {
            let column = Cylinder {
                x: 35.0,
                y: -35.0,
                diameter: 20.0,
                draft,
            };
            let mut synth = Synthesizer::new(&c.grid);
            let records = column_kinematics(
                &c,
                std::slice::from_ref(&column),
                strips,
                GRAVITY,
                &mut synth,
            );
            let basis = DepthBasis::new(&c.grid, c.expected_power(), draft, strips, GRAVITY);
            assert!(basis.rank() < strips, "a truncation: rank {}", basis.rank());
            let mut sums: [Vec<Complex64>; 3] = Default::default();
            let key = KinematicsKey::of(&c.directions, &column);
            let phases = ColumnPhases::new(&c.grid, &key, GRAVITY);
            direction_sums(&c, &phases.phases, &mut sums);
            let [ax, ay, _] = &sums;
            let n = c.grid.len;
            let (mut error, mut power) = (0.0, 0.0);
            let dz = draft / strips as f64;
            for j in 0..strips {
                let z = -draft + (j as f64 + 0.5) * dz;
                let profile = |i: usize| {
                    let w = c.grid.omega(i);
                    w * (w * w / GRAVITY * z).exp()
                };
                let cx: Vec<Complex64> = (0..c.grid.count).map(|i| ax[i] * profile(i)).collect();
                let cy: Vec<Complex64> = (0..c.grid.count).map(|i| ay[i] * profile(i)).collect();
                let mut direct = Vec::new();
                synth.append_two_real_series(&cx, &cy, &mut direct);
                for (m, u) in direct.iter().enumerate() {
                    // Row m as the records give it (recombined where it is read).
                    let group = records.column(0).records;
                    let [x, y] = match group.source.layout {
                        RowLayout::Interleaved => [1 + 2 * j, 2 + 2 * j].map(|i| group.float(m, i)),
                        RowLayout::AlongX => [group.float(m, 1 + j), 0.0],
                    }
                    .map(f64::from);
                    error += (Complex64::new(x, y) - u).norm_sqr();
                    power += u.norm_sqr();
                }
            }
            let relative = (error / power).sqrt();
            println!(
                "draft {draft} m, {strips} strips: rank {}, expected {:.2e}, measured {relative:.2e} \
                 over {n} samples",
                basis.rank(),
                basis.discarded()
            );
            assert!(basis.discarded() <= KINEMATICS_TOLERANCE);
            assert!(
                relative < 2.0 * KINEMATICS_TOLERANCE,
                "draft {draft}: relative rms error {relative:e}"
            );
        }
    }

    /// Columns on one line across the waves share their records; any other pair does not.
    #[test]
    fn only_columns_with_the_same_phases_share_records() {
        let shared = |k: &Kinematics, a: usize, b: usize| k.columns[a].group == k.columns[b].group;
        let head = components(0.0, Spreading::LongCrested);
        let mut synth = Synthesizer::new(&head.grid);
        let r = column_kinematics(&head, &square(30.0), 3, GRAVITY, &mut synth);
        assert!(shared(&r, 0, 3) && shared(&r, 1, 2));
        assert!(!shared(&r, 0, 1));
        assert_eq!(r.groups.len(), 2);
        // A different draft is a different profile.
        let mut columns = square(30.0);
        columns[3].draft = 20.0;
        let r = column_kinematics(&head, &columns, 3, GRAVITY, &mut synth);
        assert!(!shared(&r, 0, 3));
        // Oblique spread seas: every column sees its own phases.
        let spread = components(PI / 6.0, Spreading::CosN { n: 2.0 });
        let mut synth = Synthesizer::new(&spread.grid);
        let r = column_kinematics(&spread, &square(30.0), 3, GRAVITY, &mut synth);
        for i in 0..4 {
            for j in i + 1..4 {
                assert!(!shared(&r, i, j), "{i} {j}");
            }
        }
    }

    /// A row reads the same bits whether the window holds it or it is recombined where it
    /// is read: every column's elevation and strip velocities at samples and between them
    /// (the stencil wrapping at sample 0 too), before any row is made, with the window at
    /// the start, in the middle and at the end of the records, in head seas (u_x alone) and
    /// a spread sea. A build makes no rows, and moving the window allocates nothing.
    #[test]
    fn rows_read_the_same_in_the_window_or_not() {
        let strips = 7;
        for c in [
            components(0.0, Spreading::LongCrested),
            components(PI / 6.0, Spreading::CosN { n: 2.0 }),
        ] {
            let mut synth = Synthesizer::new(&c.grid);
            let mut records = Kinematics::default();
            let columns = square(30.0);
            KinematicsWork::default().build(
                &c,
                &columns,
                strips,
                GRAVITY,
                &mut synth,
                &mut records,
            );
            assert!(records.groups.iter().all(|g| g.window().is_empty()));
            let clock = whole_period(&c.grid);
            let times = [0.0, 0.2, 137.5, 250.3, 401.0, 580.0];
            let read = |k: &Kinematics| -> Vec<u64> {
                let mut bits = Vec::new();
                for column in k.columns() {
                    for t in times {
                        let state = column.at(&clock.locate(t).unwrap());
                        bits.push(state.eta().to_bits());
                        for j in 0..strips {
                            bits.extend(state.velocity(j).map(f64::to_bits));
                        }
                    }
                }
                bits
            };
            let none = read(&records);
            let capacity: Vec<usize> = records.groups.iter().map(|g| g.rows.capacity()).collect();
            let len = c.grid.len;
            assert!(
                len > ROWS_WINDOW + 100,
                "the records are longer than a window"
            );
            // Each request outside the window before it moves the window.
            for (start, end) in [(0, 10), (len - 40, len), (274, 280)] {
                records.make_rows(start, end);
                let want = start..(start + ROWS_WINDOW).min(len);
                assert!(records.groups.iter().all(|g| g.window() == want), "{start}");
                // Held, the same window again.
                records.make_rows(start + 1, end);
                assert!(records.groups.iter().all(|g| g.window() == want), "{start}");
                assert_eq!(read(&records), none, "window from {start}");
            }
            let after: Vec<usize> = records.groups.iter().map(|g| g.rows.capacity()).collect();
            assert_eq!(after, capacity, "the rows were made in the build's room");
        }
    }
}
