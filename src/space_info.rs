//! [`SpaceInfo`]: everything a planner may know about the problem's space, in one bundle
//! (OMPL's `SpaceInformation`). Planners import this, never scenario or robot types.

use crate::clock::Instant;
use crate::geometry::SensorPose;
use crate::journal::{Entry, Journal};
use crate::math::{Real, Vec2};
use crate::rng::Rng;
use crate::robot::{DiscreteOnly, MotionModel, OwnSampler, Sensor, Verdict, WorkspaceBody};
use crate::space::StateSpace;
use crate::validity::RobotInWorkspace;
use std::cell::{Cell, RefCell};

/// When long work must stop: the run's time limit, as an instant (none: no limit). Loops that can
/// run long inside one planner iteration (a motion check's states, smoothing, a heat map) look at
/// it every so often, so a time limit holds inside them too.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Deadline(pub Option<Instant>);

impl Deadline {
    /// No deadline.
    pub const NONE: Deadline = Deadline(None);
    /// `ms` milliseconds from now (none when `ms` is infinite or too large for the clock).
    pub fn in_ms(ms: f64) -> Deadline {
        if !(ms.is_finite() && ms < 1e12) {
            return Deadline::NONE;
        }
        Deadline(Instant::now().checked_add(std::time::Duration::from_secs_f64(ms.max(0.0) / 1000.0)))
    }
    /// Whether it has passed (reads the clock: call it every few hundred units of work).
    #[inline]
    pub fn passed(&self) -> bool {
        self.0.is_some_and(|t| Instant::now() >= t)
    }
}

/// Most units of work (states checked, shortcuts tried) between two looks at the clock. A run
/// looks first after one unit (again after its set-up), and the interval doubles while looks are
/// quick (less than an eighth of [`SLOW_LOOK_MS`] apart), up to this. When a unit is slow (a sight
/// line across 100,000 obstacles), the clock is read more often: when looks are more than
/// [`SLOW_LOOK_MS`] apart, the interval drops at once to the units that take about that long (at
/// least halving), down to every unit. So two looks are at most about `SLOW_LOOK_MS`, or one
/// call's units, apart.
pub const CLOCK_EVERY: u64 = 256;

/// Looks at the clock further apart than this make the interval between them shorter.
pub const SLOW_LOOK_MS: f64 = 0.5;

/// The state space, validity checker and motion resolution, with the count of state checks.
///
/// The robot's capabilities are asked for here ([`motion_model`](SpaceInfo::motion_model),
/// [`own_sampler`](SpaceInfo::own_sampler), [`body`](SpaceInfo::body),
/// [`sensor`](SpaceInfo::sensor)): `None` when the robot lacks one (a robot without a motion model
/// has its motions checked discretely). Questions a planner decides by
/// go through the counted, journalled methods ([`is_valid`](SpaceInfo::is_valid),
/// [`sample`](SpaceInfo::sample), [`sees`](SpaceInfo::sees), motion checks); the capabilities'
/// own methods are neither counted nor journalled.
pub struct SpaceInfo {
    /// The state space.
    pub space: StateSpace,
    /// Largest step between two checked states along a motion, in the space's metric.
    pub resolution: Real,
    pub(crate) validity: RobotInWorkspace,
    pub(crate) checks: Cell<u64>,
    /// Scratch for the clearances along a motion (reused, so checking does not allocate).
    pub(crate) clearances: RefCell<Vec<Real>>,
    /// The run's deadline (see [`Deadline`]), and whether work was cut short by it.
    deadline: Cell<Deadline>,
    interrupted: Cell<bool>,
    /// Units of work since the clock was last read, the units between two reads, and the last read.
    ticks: Cell<u64>,
    every: Cell<u64>,
    last_look: Cell<Option<Instant>>,
    /// The bounded batch's journal (see [`crate::journal`]), whether it is in use, when the batch
    /// is suspended, whether it was, and the units of new work done in the batch.
    pub(crate) journal: RefCell<Journal>,
    journal_on: Cell<bool>,
    suspend_at: Cell<Deadline>,
    suspended: Cell<bool>,
    fresh: Cell<u64>,
}

impl SpaceInfo {
    /// A bundle over a space and validity checker.
    pub fn new(space: StateSpace, validity: RobotInWorkspace, resolution: Real) -> Self {
        SpaceInfo {
            space,
            resolution,
            validity,
            checks: Cell::new(0),
            clearances: RefCell::new(Vec::new()),
            deadline: Cell::new(Deadline::NONE),
            interrupted: Cell::new(false),
            ticks: Cell::new(0),
            // From every unit, doubling while looks are quick: the first look comes after one
            // unit however long a unit takes.
            every: Cell::new(1),
            last_look: Cell::new(None),
            journal: RefCell::new(Journal::default()),
            journal_on: Cell::new(false),
            suspend_at: Cell::new(Deadline::NONE),
            suspended: Cell::new(false),
            fresh: Cell::new(0),
        }
    }
    /// Set the deadline of the work that follows, and forget an earlier interruption.
    pub fn set_deadline(&self, deadline: Deadline) {
        self.deadline.set(deadline);
        self.interrupted.set(false);
    }
    /// Look at the clock again from the next unit of work on, and learn anew how often: what units
    /// cost may have changed (a set-up's quick tests, then a run's slow ones).
    pub fn look_again_soon(&self) {
        self.ticks.set(0);
        self.every.set(1);
        self.last_look.set(None);
    }
    /// The current deadline.
    pub fn deadline(&self) -> Deadline {
        self.deadline.get()
    }
    /// Whether work in progress must wind down, reading the clock now: the deadline has passed
    /// (or the bounded batch was suspended). Once it has, motion checks refuse at once, so nothing
    /// unchecked is ever accepted, and the run stops with its time limit.
    pub fn out_of_time(&self) -> bool {
        self.look();
        self.stopped()
    }
    /// Whether work was cut short by the deadline (without reading the clock).
    pub fn interrupted(&self) -> bool {
        self.interrupted.get()
    }
    /// Whether work in progress must wind down: the run is out of time, or the batch was
    /// suspended (see [`crate::journal`]). Without reading the clock.
    #[inline]
    pub fn stopped(&self) -> bool {
        self.interrupted.get() || self.suspended.get()
    }
    /// Whether the bounded batch was suspended (its iteration is thrown away and done again).
    pub fn suspended(&self) -> bool {
        self.suspended.get()
    }
    /// Count `units` of new work; every so often (see [`CLOCK_EVERY`]), read the clock. Returns
    /// whether work in progress must wind down ([`SpaceInfo::stopped`]).
    #[inline]
    pub fn tick(&self, units: u64) -> bool {
        crate::clock::work(units);
        self.count_units(units)
    }
    #[inline]
    fn count_units(&self, units: u64) -> bool {
        let t = self.ticks.get() + units;
        if t >= self.every.get() {
            self.ticks.set(0);
            self.look();
        } else {
            self.ticks.set(t);
        }
        self.stopped()
    }
    /// Count `units` of new work in a bounded batch (answers computed, not replayed): a batch is
    /// suspended only after some, so every batch advances the run. Returns [`SpaceInfo::tick`]'s.
    #[inline]
    pub(crate) fn fresh_work(&self, units: u64) -> bool {
        // A query among many obstacles is more than one unit: one more per 16 exact tests.
        let units = units + crate::geometry::take_tests() / 16;
        self.fresh.set(self.fresh.get() + units);
        crate::clock::work_new(units);
        self.count_units(units)
    }
    /// Journal a unit of work that fills `out` (a sensor's look, a sweep): replayed when recorded,
    /// else computed by `compute` and kept as one entry in place of the answers it asked for.
    /// `unit` tells its kind apart from the units it is made of.
    pub(crate) fn journalled_bits(&self, unit: u8, out: &mut [u64], compute: impl FnOnce(&mut [u64])) {
        if !self.journal_on.get() {
            return compute(out);
        }
        let at = match self.journal.borrow().peek() {
            Some(&Entry::Bits { unit: u, at }) if u == unit => Some(at),
            _ => None,
        };
        if let Some(at) = at {
            let mut j = self.journal.borrow_mut();
            j.take();
            j.load_bits(at, out);
            return;
        }
        let mark = self.journal.borrow().mark();
        compute(out);
        if !self.stopped() {
            self.journal.borrow_mut().compact_bits(mark, unit, out);
            // New work, even when it asked nothing the journal records (a look that sees nothing).
            self.fresh_work(1);
        }
    }
    /// Read the clock: the run's deadline, the batch's suspension, and how often to look again.
    fn look(&self) {
        let now = Instant::now();
        if !self.interrupted.get() && self.deadline.get().0.is_some_and(|t| now >= t) {
            self.interrupted.set(true);
        }
        // A batch is suspended only once it has done new work, so every batch advances the run.
        if self.journal_on.get()
            && !self.suspended.get()
            && self.fresh.get() > 0
            && self.suspend_at.get().0.is_some_and(|t| now >= t)
            && self.journal.borrow().on()
        {
            self.suspended.set(true);
        }
        if let Some(last) = self.last_look.get() {
            let ms = now.saturating_duration_since(last).as_secs_f64() * 1000.0;
            let every = self.every.get();
            // Slow units: at once down to as many as take about SLOW_LOOK_MS (at least halved).
            self.every.set(if ms > SLOW_LOOK_MS {
                ((every as f64 * SLOW_LOOK_MS / ms) as u64).clamp(1, (every / 2).max(1))
            } else if ms < SLOW_LOOK_MS / 8.0 {
                (every * 2).min(CLOCK_EVERY)
            } else {
                every
            });
        }
        self.last_look.set(Some(now));
    }
    /// Start a bounded batch: questions are journalled, and past `suspend_at` (once the batch has
    /// done new work) the batch is suspended. See [`crate::journal`].
    pub fn begin_batch(&self, suspend_at: Deadline) {
        self.journal.borrow_mut().begin();
        self.journal_on.set(true);
        self.suspend_at.set(suspend_at);
        self.suspended.set(false);
        self.fresh.set(0);
    }
    /// End a bounded batch; returns whether it was suspended (its answers are then kept for the
    /// next batch, which replays them).
    pub fn end_batch(&self) -> bool {
        let suspended = self.suspended.get() && !self.interrupted.get();
        let mut j = self.journal.borrow_mut();
        if suspended {
            j.pause();
        } else {
            j.finish();
        }
        self.journal_on.set(false);
        self.suspended.set(false);
        self.suspend_at.set(Deadline::NONE);
        suspended
    }
    /// Whether questions go through the batch journal.
    #[inline]
    pub(crate) fn journal_on(&self) -> bool {
        self.journal_on.get()
    }
    /// Restore the state-check count (a suspended batch's checks are counted again when its
    /// iterations are replayed).
    pub(crate) fn set_checks(&self, n: u64) {
        self.checks.set(n);
    }
    /// Answer a question through the journal: replayed when recorded, else computed (and counted
    /// as a unit of new work), or `refuse` once the batch is suspended.
    #[inline]
    pub(crate) fn journalled<T: Copy>(
        &self,
        get: impl Fn(&Entry) -> Option<T>,
        make: impl Fn(T) -> Entry,
        refuse: T,
        compute: impl FnOnce() -> T,
    ) -> T {
        if !self.journal_on.get() {
            // Still a unit of work: the run's deadline is looked at inside long checks.
            let v = compute();
            self.fresh_work(1);
            return v;
        }
        let next = self.journal.borrow_mut().take();
        if let Some(e) = next {
            if let Some(v) = get(&e) {
                return v;
            }
            self.desync();
        }
        if self.suspended.get() {
            return refuse;
        }
        let v = compute();
        self.journal.borrow_mut().push(make(v));
        self.fresh_work(1);
        v
    }
    /// A replayed answer was not the question asked: a planner is not deterministic. Stop
    /// replaying (answers are computed from here) and say so in debug builds.
    #[cold]
    pub(crate) fn desync(&self) {
        debug_assert!(false, "the journal's answers do not match the questions replayed");
        self.journal.borrow_mut().mode = crate::journal::Mode::Full;
    }
    /// Numbers per state.
    #[inline]
    pub fn dims(&self) -> usize {
        self.space.dim_count()
    }
    /// Whether `q` is valid (counted as one state check).
    #[inline]
    pub fn is_valid(&self, q: &[Real]) -> bool {
        self.checks.set(self.checks.get() + 1);
        self.journalled(
            |e| if let Entry::Valid(v) = e { Some(*v) } else { None },
            Entry::Valid,
            false,
            || self.validity.is_valid(q),
        )
    }
    /// State checks so far.
    pub fn checks(&self) -> u64 {
        self.checks.get()
    }
    /// Reset the check counter.
    pub fn reset_checks(&self) {
        self.checks.set(0)
    }
    /// Distance between two states.
    #[inline]
    pub fn distance(&self, a: &[Real], b: &[Real]) -> Real {
        self.space.distance(a, b)
    }
    /// The state a fraction `t` from `a` to `b`.
    #[inline]
    pub fn interpolate(&self, a: &[Real], b: &[Real], t: Real, out: &mut [Real]) {
        self.space.interpolate(a, b, t, out)
    }
    /// A random state from the robot's sampler (uniform over the space unless the robot knows
    /// better). The checks the robot's sampler spends count as state checks.
    #[inline]
    pub fn sample(&self, rng: &mut Rng, out: &mut [Real]) {
        let spent = if self.journal_on.get() { self.sample_journalled(rng, out) } else { self.sample_now(rng, out) };
        self.checks.set(self.checks.get() + spent);
    }
    /// A state from the robot's own sampler, else uniform; the checks it spent.
    #[inline]
    fn sample_now(&self, rng: &mut Rng, out: &mut [Real]) -> u64 {
        match self.own_sampler() {
            Some(own) => own.sample(&self.space, rng, out, &|| {
                self.look();
                self.interrupted.get()
            }),
            None => {
                self.space.sample_uniform(rng, out);
                0
            }
        }
    }
    fn sample_journalled(&self, rng: &mut Rng, out: &mut [Real]) -> u64 {
        let mut j = self.journal.borrow_mut();
        if let Some(e) = j.take() {
            if let Entry::Sample { spent, at, rng: after } = e {
                j.load(at, out);
                *rng = after;
                return spent;
            }
            drop(j);
            self.desync();
        } else {
            drop(j);
        }
        if self.suspended.get() {
            // Winding down: a uniform state, unchecked (the iteration is thrown away).
            self.space.sample_uniform(rng, out);
            return 0;
        }
        let spent = self.sample_now(rng, out);
        let mut j = self.journal.borrow_mut();
        let at = j.store(out);
        j.push(Entry::Sample { spent, at, rng: rng.clone() });
        drop(j);
        self.fresh_work(1);
        spent
    }
    /// The robot's own sampler (OMPL's `StateSampler`), when it has one; `None`: samples are
    /// uniform and Gaussian neighbours move each coordinate independently. Its draws are not
    /// counted: planners sample through [`SpaceInfo::sample`] (and the run's sampler).
    #[inline]
    pub fn own_sampler(&self) -> Option<&dyn OwnSampler> {
        self.validity.robot.sampler()
    }
    /// How the robot's motions are checked ([`DiscreteOnly`] when it has no model of its own).
    /// Planners check motions through [`MotionValidator`](crate::motion::MotionValidator).
    #[inline]
    pub fn motion_model(&self) -> &dyn MotionModel {
        self.validity.robot.motion().unwrap_or(&DiscreteOnly)
    }
    /// The robot as a mobile body in the workspace (workspace planners: hexagonal decomposition,
    /// potential fields); `None` for robots that are not one.
    #[inline]
    pub fn body(&self) -> Option<&dyn WorkspaceBody> {
        self.validity.robot.body()
    }
    /// The robot's sensor (inspection tasks), when it has one; what it sees is [`SpaceInfo::sees`].
    #[inline]
    pub fn sensor(&self) -> Option<&dyn Sensor> {
        self.validity.robot.sensor()
    }
    /// The `robot.kind` of the scenario format (for messages).
    pub fn robot_kind(&self) -> &'static str {
        self.validity.robot.kind()
    }
    /// Where a state is drawn in the workspace.
    #[inline]
    pub fn project(&self, q: &[Real]) -> Vec2 {
        self.validity.robot.project(q)
    }
    /// The body's outline at `q`, as closed polygons (none for a point robot).
    pub fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>> {
        self.validity.robot.outline(q)
    }
    /// The workspace (for planners that plan in it rather than in configuration space, and for
    /// the capabilities' methods that take it).
    #[inline]
    pub fn workspace(&self) -> &crate::geometry::Workspace {
        &self.validity.workspace
    }
    /// Whether `q` is valid, and if not, why: **not** counted as a state check, not journalled
    /// (for explanations and checks of a finished path, which decide nothing in the run).
    pub fn verdict(&self, q: &[Real]) -> Verdict {
        self.validity.verdict(q)
    }
    /// Whether `q` is valid, **not** counted as a state check and not journalled: for work that
    /// counts its own checks (a potential field's clearances, inside one journalled answer) or that
    /// is not part of a run (a configuration-space picture). Planners deciding by a state use
    /// [`SpaceInfo::is_valid`].
    #[inline]
    pub fn is_valid_uncounted(&self, q: &[Real]) -> bool {
        self.validity.is_valid(q)
    }
    /// What blocked the motion `a → b`, found invalid at `at`, for the explanation of a
    /// [`Collision`](crate::events::EventKind::Collision) event, and the workspace point to show
    /// it at. What: the index of the obstacle the robot meets at `at` (the first in scenario
    /// order; for a robot with an exact sweep whose state `at` is free, the first obstacle the
    /// sweep meets), -2 the map's edge, -3 one of the robot's own rules (self-collision, a joint
    /// limit), -1 not known (a motion refused unchecked: out of time, or too long to check).
    /// Where: for a body meeting an obstacle at `at`, where they meet ([`SpaceInfo::contact`]);
    /// else the state's reference point. Not counted as a state check, not journalled: it asks
    /// nothing a planner decides by.
    pub fn blocked_at(&self, a: &[Real], b: &[Real], at: &[Real]) -> (i64, Vec2) {
        let reference = self.project(at);
        match self.validity.verdict(at) {
            Verdict::Collision(i) => (i as i64, self.contact(at, i).unwrap_or(reference)),
            Verdict::OutOfBounds(_) => (-2, reference),
            Verdict::Invalid(_) => (-3, reference),
            Verdict::Valid => match self.motion_model().sweep_hits(self.workspace(), a, b) {
                Some(true) => {
                    let hit = self.workspace().first_obstacle_on_segment(self.project(a), self.project(b));
                    (hit.map_or(-1, |i| i as i64), reference)
                }
                _ => (-1, reference),
            },
        }
    }
    /// Where the robot's body at `q` meets obstacle `i`: the first point, along its outline's
    /// edges in order (a rigid body's polygon, an arm's links, a vehicle chain's brooms), that lies
    /// in the obstacle; else (the obstacle wholly inside a rigid body) a point of the obstacle.
    /// `None` for a point robot (no outline). For drawing and captions only: the verdict is the
    /// robot's.
    pub fn contact(&self, q: &[Real], i: usize) -> Option<Vec2> {
        let shape = self.validity.workspace.obstacles.get(i)?;
        let open = self.validity.workspace.touching_allowed;
        let closed = self.validity.robot.body().is_some(); // see `Robot::outline`
        let outline = self.outline(q);
        for poly in &outline {
            let n = poly.len();
            let edges = if closed && n > 2 { n } else { n.saturating_sub(1) };
            if let Some(p) = (0..edges).find_map(|k| shape.first_point_on(poly[k], poly[(k + 1) % n], open)) {
                return Some(p);
            }
        }
        (closed && !outline.is_empty()).then(|| shape.some_point())
    }
    /// Count `n` geometric tests as state checks (workspace planners test cells and steps rather
    /// than states; their tests are counted here so `checks` compares work across planners).
    pub fn count_checks(&self, n: u64) {
        self.checks.set(self.checks.get() + n);
    }
    /// Whether a sensor at `pose` sees the workspace point `p`: within `range`, within `fov / 2`
    /// of its heading, and with a sight line through no obstacle's interior (touching an obstacle
    /// does not block; see [`crate::geometry::sight`]). Exact: no sampling along the sight line.
    /// Not counted as a state check.
    #[inline]
    pub fn sees(&self, pose: &SensorPose, p: Vec2, fov: Real, range: Real) -> bool {
        self.sees_by(pose, p, fov, range, false)
    }
    /// [`SpaceInfo::sees`] with the sight rule chosen: `touch_hides` (the Technion course's test),
    /// a sight line that meets an obstacle at all, its boundary included, hides the point; else
    /// only one through an obstacle's interior does.
    #[inline]
    pub fn sees_by(&self, pose: &SensorPose, p: Vec2, fov: Real, range: Real, touch_hides: bool) -> bool {
        pose.in_view(p, fov, range)
            && self.journalled(
                |e| if let Entry::Sight(v) = e { Some(*v) } else { None },
                Entry::Sight,
                false,
                || {
                    let ws = &self.validity.workspace;
                    if touch_hides {
                        ws.sight_untouched(pose.at, p)
                    } else {
                        ws.sight_clear(pose.at, p)
                    }
                },
            )
    }
}
