//! The batch journal: how a bounded batch of planning can stop in the middle of an iteration and
//! carry on in the next batch with the run unchanged, bit for bit.
//!
//! A page's worker plans in batches of a few milliseconds so it keeps reading its messages, but
//! one planner iteration can take far longer than a batch (a motion checked at 100,000 states
//! among 100,000 obstacles). Rust has no way to pause an iteration half-way, so the session does
//! the next best thing, which is exact because planners are deterministic:
//!
//! 1. At the start of a bounded batch the session keeps a snapshot of everything an iteration
//!    changes (the planner, the generator, the sampler, the event count, the check count). The
//!    planner's is its [`Checkpoint`](crate::planners::Checkpoint): a copy, or, for RRT and
//!    RRT-Connect, whose trees only grow, a mark of each tree that it can rewind to.
//! 2. While the batch runs, every expensive question the planner asks [`SpaceInfo`] (a state
//!    check, a clearance, a sight line, a robot's own sample, a whole motion check) is *recorded*
//!    here with its answer.
//! 3. When the batch is far past its budget, the next question is refused: the space is
//!    *suspended*, every further question gets a quick pessimistic answer, the iteration winds
//!    down, and the session throws it away by restoring the snapshot.
//! 4. The next batch runs the same iterations again. They ask the same questions in the same
//!    order (same state, same generator), and the journal *replays* the recorded answers without
//!    computing them, until it runs out; from there the batch records again. A motion check that
//!    was cut short resumes at the state it had reached.
//!
//! Every batch records at least one new answer before it can be suspended, so a run always
//! advances. Answers are compacted as they complete (a finished motion check is one entry, not
//! its states), so replaying is cheap next to the work it skips.
//!
//! [`SpaceInfo`]: crate::space_info::SpaceInfo

use crate::math::Real;
use crate::rng::Rng;

/// Most entries one journal holds. Past it, the batch stops recording and is not suspended again
/// (it overruns its budget rather than keep unbounded memory).
pub const MAX_ENTRIES: usize = 1 << 22;

/// Most numbers (failed motions' states, robot samples) one journal holds.
pub const MAX_REALS: usize = 1 << 23;

/// One recorded answer.
#[derive(Clone, Debug)]
pub enum Entry {
    /// A state check.
    Valid(bool),
    /// A capped clearance.
    Clear(Real),
    /// A robot's exact swept test.
    Hit(Option<bool>),
    /// A sight line's test.
    Sight(bool),
    /// A robot's own sample.
    Sample {
        /// The state checks it spent.
        spent: u64,
        /// Where the state is in the arena.
        at: usize,
        /// The generator after it.
        rng: Rng,
    },
    /// A finished motion check.
    Motion {
        /// Whether the motion was valid.
        ok: bool,
        /// The state checks it counted.
        checks: u64,
        /// Of those, the ones that found their state valid.
        free: u64,
        /// For an invalid motion, where the state found is in the arena.
        at: usize,
        /// For a walk's step certified by clearances, the clearance at its end, carried into the
        /// next step (0: none).
        end: Real,
    },
    /// A unit of work that leaves words of bits (a sensor's look, a sweep made of looks).
    Bits {
        /// Which kind of unit (units of one kind may hold units of another).
        unit: u8,
        /// Where the words are in the arena.
        at: usize,
    },
    /// A discrete motion check cut short.
    Partial {
        /// The states it visited (all valid), in its order.
        visited: u64,
    },
}

/// Whether the journal is in use, and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Not in a bounded batch: questions are answered directly.
    Off,
    /// Recording answers (and replaying first, while `pos` is short of the end).
    On,
    /// Full (see [`MAX_ENTRIES`]): answers are computed, not recorded, and nothing is suspended.
    Full,
}

/// The journal of one suspended (or running) batch.
#[derive(Debug)]
pub struct Journal {
    /// How it is used.
    pub mode: Mode,
    entries: Vec<Entry>,
    /// The arena's length after each entry (so entries are cut back with their numbers).
    ends: Vec<usize>,
    reals: Vec<Real>,
    /// Replay cursor: entries before it have been answered again in this batch.
    pos: usize,
}

impl Default for Journal {
    fn default() -> Self {
        Journal { mode: Mode::Off, entries: Vec::new(), ends: Vec::new(), reals: Vec::new(), pos: 0 }
    }
}

impl Journal {
    /// Start a batch: replay from the first entry (none after a batch that finished).
    pub fn begin(&mut self) {
        self.mode =
            if self.entries.len() >= MAX_ENTRIES || self.reals.len() >= MAX_REALS { Mode::Full } else { Mode::On };
        self.pos = 0;
    }
    /// End a batch that was not suspended: its iterations are done, forget their answers.
    pub fn finish(&mut self) {
        self.entries.clear();
        self.ends.clear();
        self.reals.clear();
        self.mode = Mode::Off;
        self.pos = 0;
    }
    /// End a suspended batch: keep the answers for the next one.
    pub fn pause(&mut self) {
        self.mode = Mode::Off;
    }
    /// Whether answers are being recorded (or replayed).
    #[inline]
    pub fn on(&self) -> bool {
        self.mode == Mode::On
    }
    /// Whether the next question is answered from the journal.
    #[inline]
    pub fn replaying(&self) -> bool {
        self.mode == Mode::On && self.pos < self.entries.len()
    }
    /// The next recorded answer (advancing the cursor), if replaying.
    #[inline]
    pub fn take(&mut self) -> Option<Entry> {
        if !self.replaying() {
            return None;
        }
        let e = self.entries[self.pos].clone();
        self.pos += 1;
        Some(e)
    }
    /// The next recorded answer, if replaying, without taking it.
    #[inline]
    pub fn peek(&self) -> Option<&Entry> {
        if self.replaying() {
            self.entries.get(self.pos)
        } else {
            None
        }
    }
    /// Record an answer (when recording), with the numbers `state` when it has some.
    pub fn push(&mut self, e: Entry) {
        if self.mode != Mode::On {
            return;
        }
        debug_assert_eq!(
            self.pos,
            self.entries.len(),
            "recording {e:?} while replay is unfinished: next {:?}",
            self.entries.get(self.pos)
        );
        self.entries.push(e);
        self.ends.push(self.reals.len());
        self.pos = self.entries.len();
        if self.entries.len() >= MAX_ENTRIES || self.reals.len() >= MAX_REALS {
            self.mode = Mode::Full;
        }
    }
    /// Store numbers in the arena for the entry about to be pushed; returns where.
    pub fn store(&mut self, q: &[Real]) -> usize {
        let at = self.reals.len();
        if self.mode == Mode::On {
            self.reals.extend_from_slice(q);
        }
        at
    }
    /// Numbers stored at `at`.
    pub fn load(&self, at: usize, out: &mut [Real]) {
        out.copy_from_slice(&self.reals[at..at + out.len()]);
    }
    /// Words stored at `at` (as [`Journal::compact_bits`] kept them).
    pub fn load_bits(&self, at: usize, out: &mut [u64]) {
        let words = &self.reals[at..at + out.len()];
        for (o, r) in out.iter_mut().zip(words) {
            *o = r.to_bits();
        }
    }
    /// Where the next question's answer is: a unit of work's first entry will be there.
    pub fn mark(&self) -> usize {
        self.pos
    }
    /// Replace the entries from `mark` on (a unit of work's own answers, all at the end) by `e`,
    /// with `state` (an invalid motion's state) stored for it.
    pub fn compact(&mut self, mark: usize, e: Entry, state: Option<&[Real]>) {
        if self.mode != Mode::On {
            return;
        }
        self.cut(mark);
        let e = match (e, state) {
            (Entry::Motion { ok, checks, free, end, .. }, Some(q)) => {
                Entry::Motion { ok, checks, free, at: self.store(q), end }
            }
            (e, _) => e,
        };
        self.push(e);
    }
    /// Like [`Journal::compact`], for a unit of work that left the words `bits`.
    pub fn compact_bits(&mut self, mark: usize, unit: u8, bits: &[u64]) {
        if self.mode != Mode::On {
            return;
        }
        self.cut(mark);
        let at = self.reals.len();
        self.reals.extend(bits.iter().map(|b| Real::from_bits(*b)));
        self.push(Entry::Bits { unit, at });
    }
    /// Drop the entries from `mark` on, with their numbers.
    fn cut(&mut self, mark: usize) {
        debug_assert_eq!(self.pos, self.entries.len(), "a unit of work finished before its replay did");
        self.entries.truncate(mark);
        self.ends.truncate(mark);
        self.reals.truncate(self.ends.last().copied().unwrap_or(0));
        self.pos = mark;
    }
}
