//! Samplers: where the next sample comes from (OMPL's `StateSampler` and `ValidStateSampler`).
//!
//! Every planner draws through one [`Sampler`], chosen by name with the parameters of
//! [`SAMPLER_PARAMS`], so any planner can use any sampler:
//!
//! | name | draws |
//! |---|---|
//! | `uniform` | the robot's own sampler (uniform over the space unless the robot knows better) |
//! | `goal-biased` | `uniform`, named for the goal bias every sampler honours (`goal_bias`) |
//! | `gaussian` | a uniform state and a Gaussian neighbour (`sigma`); keeps the free one when exactly one is free |
//! | `bridge` | two occupied states a Gaussian distance apart (`sigma`); keeps their midpoint when it is free |
//! | `obstacle` | a free and an occupied state; walks from the free one toward the occupied one and keeps the last free state |
//! | `near-collision` | Gaussian around the last collision point (`collision_sigma`), re-centred at random with `random_sigma` every `perseverance` samples |
//!
//! "Uniform" draws are always the robot's own sampler ([`SpaceInfo::sample`]): the vehicle chain
//! draws valid-looking chains, since uniform chain states are almost never valid. Every sample
//! is in the space's bounds (a draw the robot's sampler put outside them is clamped into them).
//!
//! `sigma`, `collision_sigma` and `random_sigma` are fractions of each coordinate's range, so one
//! value means the same on every robot. A Gaussian neighbour wraps on an angle that wraps, and is
//! *reflected* back into the bounds on any other coordinate. (Clamping would put a point mass on
//! the bounds, holding a third of the samples or more with the default `random_sigma` of 0.5 and
//! nearly all of them with a spread of several ranges; reflected, a wide spread tends to uniform.)
//!
//! With probability `goal_bias` any sampler returns the goal instead. Otherwise, with probability
//! `uniform_share`, the gaussian, bridge, obstacle and near-collision samplers return one plain
//! uniform draw, unchecked like the uniform sampler's (the hybrid form of the literature: a bridge
//! test alone almost never samples a corridor wider than its `sigma`, so on a zigzag of 0.15-wide
//! corridors RRT-Connect found no path in 30 s; with the default share of 0.1 it finds one in
//! about 85 ms). A share of 0 is the pure form, with the same random stream as before the share
//! existed. A sampler that needs
//! validity (gaussian, bridge, obstacle) gives up after `sampler_tries` attempts (an attempt draws
//! one or two raw states, so at most twice that many draws); the iteration then grows nothing. The
//! obstacle-based walk that follows is not an attempt: it checks at most one state per
//! `resolution` of the distance walked. [`SamplerStats`] counts raw draws (goal samples and
//! near-collision centres included) and state checks per accepted sample. Every state these
//! samplers check is logged as an [`EventKind::SampleTry`] event (not the candidates a robot's own
//! sampler may check). Only the run's seeded [`Rng`] is used, so a seed fixes every sample.

mod bridge;
mod gaussian;
mod near_collision;
mod obstacle;

use crate::events::{EventKind, EventLog};
use crate::math::Real;
use crate::params::{ParamGroup, ParamSpec, ParamValues};
use crate::rng::Rng;
pub use crate::space::gaussian_coordinates;
use crate::space_info::SpaceInfo;
use serde::Serialize;

/// The sampler names, in the order the page lists them.
pub const NAMES: &[&str] = &["uniform", "goal-biased", "gaussian", "bridge", "obstacle", "near-collision"];

/// The sampler parameters, shared by every sampling planner.
pub static SAMPLER_PARAMS: &[ParamSpec] = &[
    ParamSpec::choice(
        "sampler",
        "Sampler",
        NAMES,
        0,
        "Where samples come from: uniform, goal-biased, gaussian, bridge, obstacle (based) or near-collision.",
    ),
    ParamSpec::real("goal_bias", "Goal bias", 0.0, 1.0, 0.0, "Probability of sampling the goal itself (any sampler)."),
    ParamSpec::real(
        "sigma",
        "Sigma",
        0.0,
        1.0,
        0.05,
        "Gaussian and bridge samplers: standard deviation, as a fraction of each coordinate's range.",
    ).only_when("sampler", &["gaussian", "bridge"]),
    ParamSpec::real(
        "collision_sigma",
        "Collision sigma",
        0.0,
        1.0,
        0.03,
        "Near-collision sampler: standard deviation around the last collision point (fraction of each range).",
    ).only_when("sampler", &["near-collision"]),
    ParamSpec::real(
        "random_sigma",
        "Random sigma",
        0.0,
        10.0,
        0.5,
        "Near-collision sampler: standard deviation around a random centre (fraction of each range).",
    ).only_when("sampler", &["near-collision"]),
    ParamSpec::int(
        "perseverance",
        "Perseverance",
        1.0,
        1e6,
        20.0,
        "Near-collision sampler: samples around one centre before re-centring at random.",
    ).only_when("sampler", &["near-collision"]),
    ParamSpec::real(
        "uniform_share",
        "Uniform share",
        0.0,
        1.0,
        0.1,
        "Gaussian, bridge, obstacle and near-collision samplers: probability of a plain uniform sample instead (the hybrid form; 0: the pure sampler).",
    ).only_when("sampler", &["gaussian", "bridge", "obstacle", "near-collision"]),
    ParamSpec::int(
        "sampler_tries",
        "Sampler tries",
        1.0,
        1e4,
        100.0,
        "Attempts (of one or two draws) a validity-checking sampler makes for one sample before giving up.",
    ).only_when("sampler", &["gaussian", "bridge", "obstacle"]),
];

/// The sampler parameters as a group of the page's parameter panel.
pub const SAMPLER_GROUP: ParamGroup = ParamGroup { name: "sampler", label: "Sampler", params: SAMPLER_PARAMS };

/// What a sampler spent.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct SamplerStats {
    /// Samples handed to the planner.
    pub accepted: u64,
    /// Samples given up after `sampler_tries` attempts.
    pub failed: u64,
    /// Raw states drawn (goal samples and near-collision centres included).
    pub draws: u64,
    /// State checks spent by the sampler itself.
    pub checks: u64,
}

impl SamplerStats {
    /// Raw draws per accepted sample.
    pub fn draws_per_sample(&self) -> Real {
        self.draws as Real / self.accepted.max(1) as Real
    }
    /// State checks per accepted sample.
    pub fn checks_per_sample(&self) -> Real {
        self.checks as Real / self.accepted.max(1) as Real
    }
}

/// Which sampling rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The robot's sampler.
    Uniform,
    /// Gaussian pairs.
    Gaussian,
    /// Bridge test.
    Bridge,
    /// Obstacle-based.
    Obstacle,
    /// Near the last collision.
    NearCollision,
}

/// A sampler with its parameters, scratch and statistics.
#[derive(Clone, Debug)]
pub struct Sampler {
    kind: Kind,
    name: &'static str,
    goal: Option<Vec<Real>>,
    goal_bias: Real,
    uniform_share: Real,
    sigma: Real,
    collision_sigma: Real,
    random_sigma: Real,
    perseverance: u64,
    tries: u64,
    /// Near-collision: the current centre and its sigma, and samples drawn around it.
    centre: Option<Vec<Real>>,
    centre_sigma: Real,
    around_centre: u64,
    /// The two states the last sample was judged by (see [`Sampler::witnesses`]), and scratch.
    a: Vec<Real>,
    b: Vec<Real>,
    c: Vec<Real>,
    /// Whether `a` and `b` are the last sample's witnesses.
    witnessed: bool,
    /// Whether the last sample was the goal itself (the goal bias).
    goal_drawn: bool,
    /// Whether the last sample was a plain uniform one (the uniform share).
    uniform_drawn: bool,
    stats: SamplerStats,
}

/// What a sampler may use while drawing.
pub struct Draw<'a> {
    /// The space bundle (validity checks are counted).
    pub si: &'a SpaceInfo,
    /// The run's generator.
    pub rng: &'a mut Rng,
    /// Where raw draws are logged.
    pub events: &'a mut EventLog,
    /// Which tree the sample is for (events).
    pub tree: usize,
}

impl Draw<'_> {
    /// A raw draw from the robot's sampler, clamped into the space's bounds: a robot's sampler
    /// may return a state outside them (the vehicle chain's last resort, an invalid chain, can
    /// have its centroid off the map).
    fn uniform(&mut self, out: &mut [Real]) {
        self.si.sample(self.rng, out);
        for (v, d) in out.iter_mut().zip(&self.si.space.dims) {
            if !d.wraps {
                *v = v.clamp(d.lo, d.hi);
            }
        }
        self.si.space.enforce(out);
    }
    /// Whether `q` is valid (one counted check), logged as a `SampleTry` event: `id` 1 free,
    /// 0 occupied; the state's point and first two coordinates, as for any event at one state.
    fn check(&mut self, q: &[Real]) -> bool {
        let ok = self.si.is_valid(q);
        let p = self.si.project(q);
        self.events.push(EventKind::SampleTry, self.tree, ok as i64, -1, p, p, q, q);
        ok
    }
    /// Write into `out` a Gaussian neighbour of `centre`: each coordinate moved by a normal
    /// deviate of `sigma` × its range; an angle that wraps is wrapped, any other coordinate is
    /// reflected back into its bounds.
    ///
    /// A robot whose coordinates are not independent (the vehicle chain, whose turns must keep
    /// the polygon convex) moves them its own way: see [`SpaceInfo::own_sampler`].
    fn gaussian_near(&mut self, centre: &[Real], sigma: Real, out: &mut [Real]) {
        match self.si.own_sampler() {
            Some(own) => own.sample_gaussian(&self.si.space, self.rng, centre, sigma, out),
            None => gaussian_coordinates(&self.si.space, self.rng, centre, sigma, out),
        }
    }
}

impl Sampler {
    /// The sampler `params` name, for a task with `goal` (used when `goal_bias` > 0).
    pub fn from_params(si: &SpaceInfo, goal: Option<&[Real]>, params: &dyn ParamValues) -> Sampler {
        let name = NAMES.iter().copied().find(|n| *n == params.choice("sampler")).unwrap_or("uniform");
        let kind = match name {
            "gaussian" => Kind::Gaussian,
            "bridge" => Kind::Bridge,
            "obstacle" => Kind::Obstacle,
            "near-collision" => Kind::NearCollision,
            _ => Kind::Uniform,
        };
        let n = si.dims();
        Sampler {
            kind,
            name,
            goal: goal.map(<[Real]>::to_vec),
            goal_bias: params.real("goal_bias"),
            uniform_share: params.real("uniform_share"),
            sigma: params.real("sigma"),
            collision_sigma: params.real("collision_sigma"),
            random_sigma: params.real("random_sigma"),
            perseverance: params.real("perseverance") as u64,
            tries: params.real("sampler_tries") as u64,
            centre: None,
            centre_sigma: 0.0,
            around_centre: 0,
            a: vec![0.0; n],
            b: vec![0.0; n],
            c: vec![0.0; n],
            witnessed: false,
            goal_drawn: false,
            uniform_drawn: false,
            stats: SamplerStats::default(),
        }
    }

    /// The sampler's name.
    pub fn name(&self) -> &'static str {
        self.name
    }
    /// Which rule it follows.
    pub fn kind(&self) -> Kind {
        self.kind
    }
    /// What it spent so far.
    pub fn stats(&self) -> SamplerStats {
        self.stats
    }
    /// The two states the last accepted sample was judged by, for tests and figures: `gaussian`,
    /// the uniform state and its Gaussian neighbour (the sample is the free one); `bridge`, the
    /// two occupied ends (the sample is their midpoint); `obstacle`, the free state the walk
    /// started from and the occupied state it walked toward. `None` for the other samplers, a
    /// goal sample, or a sampler that gave up.
    pub fn witnesses(&self) -> Option<(&[Real], &[Real])> {
        self.witnessed.then_some((&self.a[..], &self.b[..]))
    }
    /// Whether the last sample drawn was the goal itself (the goal bias), not the sampler's.
    pub fn drew_goal(&self) -> bool {
        self.goal_drawn
    }
    /// Whether the last sample was a plain uniform one drawn for the uniform share, not by the
    /// sampler's own rule.
    pub fn drew_uniform_share(&self) -> bool {
        self.uniform_drawn
    }
    /// How the last sample came about, as the `Sample` event's `id`: 0 the sampler's rule,
    /// 1 the goal (goal bias), 2 a uniform draw of the uniform share.
    pub fn origin(&self) -> i64 {
        if self.goal_drawn {
            1
        } else if self.uniform_drawn {
            2
        } else {
            0
        }
    }
    /// The near-collision sampler's current centre and its sigma (a fraction of each range), and
    /// the samples drawn since it was last re-centred at random; `None` before its first sample
    /// or collision, and for the other samplers.
    pub fn centre(&self) -> Option<(&[Real], Real, u64)> {
        self.centre.as_deref().map(|c| (c, self.centre_sigma, self.around_centre))
    }

    /// Draw one sample into `out`; `false` when the sampler gave up (after `sampler_tries`
    /// attempts), in which case `out` holds nothing useful.
    pub fn sample(&mut self, d: &mut Draw, out: &mut [Real]) -> bool {
        let checks0 = d.si.checks();
        let ok = self.draw(d, out);
        self.stats.checks += d.si.checks() - checks0;
        if ok {
            self.stats.accepted += 1;
        } else {
            self.stats.failed += 1;
        }
        ok
    }

    fn draw(&mut self, d: &mut Draw, out: &mut [Real]) -> bool {
        self.witnessed = false;
        self.goal_drawn = false;
        self.uniform_drawn = false;
        if self.goal_bias > 0.0 && d.rng.uniform01() < self.goal_bias {
            if let Some(g) = &self.goal {
                out.copy_from_slice(g);
                self.goal_drawn = true;
                self.stats.draws += 1;
                return true;
            }
        }
        // The hybrid form: a share of plain uniform samples, so a sampler made for narrow passages
        // still covers wide-open space. No number is drawn at share 0 (the pure form's stream).
        if self.kind != Kind::Uniform && self.uniform_share > 0.0 && d.rng.uniform01() < self.uniform_share {
            d.uniform(out);
            self.stats.draws += 1;
            self.uniform_drawn = true;
            return true;
        }
        match self.kind {
            Kind::Uniform => {
                d.uniform(out);
                self.stats.draws += 1;
                true
            }
            Kind::Gaussian => gaussian::draw(self, d, out),
            Kind::Bridge => bridge::draw(self, d, out),
            Kind::Obstacle => obstacle::draw(self, d, out),
            Kind::NearCollision => near_collision::draw(self, d, out),
        }
    }

    /// A motion toward a sample collided; `q` is the tree node it started from (report 001's
    /// "last connected node": a free state beside the obstacle). The near-collision sampler
    /// re-centres there, with `collision_sigma`; its count of samples since the last random centre
    /// goes on.
    pub fn note_collision(&mut self, q: &[Real]) {
        if self.kind == Kind::NearCollision {
            near_collision::note_collision(self, q);
        }
    }
}

#[cfg(test)]
mod tests;
