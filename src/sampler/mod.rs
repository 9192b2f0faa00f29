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
//! `sigma`, `collision_sigma` and `random_sigma` are fractions of each coordinate's range, so one
//! value means the same on every robot. With probability `goal_bias` any sampler returns the goal
//! instead. A sampler that needs validity (gaussian, bridge, obstacle) gives up after
//! `sampler_tries` raw draws; the iteration then grows nothing. [`SamplerStats`] counts raw draws
//! and state checks per accepted sample. Raw draws are logged as [`EventKind::SampleTry`] events.

mod bridge;
mod gaussian;
mod near_collision;
mod obstacle;

use crate::events::{EventKind, EventLog};
use crate::math::Real;
use crate::planners::{ParamGroup, ParamSpec, Params};
use crate::rng::Rng;
use crate::space_info::SpaceInfo;
use serde::Serialize;

/// The sampler names, in the order the page lists them.
pub const NAMES: &[&str] = &["uniform", "goal-biased", "gaussian", "bridge", "obstacle", "near-collision"];

/// The sampler parameters, shared by every sampling planner.
pub static SAMPLER_PARAMS: &[ParamSpec] = &[
    ParamSpec::choice("sampler", "Sampler", NAMES, 0, "Where samples come from: uniform, goal-biased, gaussian, bridge, obstacle (based) or near-collision."),
    ParamSpec::real("goal_bias", "Goal bias", 0.0, 1.0, 0.0, "Probability of sampling the goal itself (any sampler)."),
    ParamSpec::real("sigma", "Sigma", 0.0, 1.0, 0.05, "Gaussian and bridge samplers: standard deviation, as a fraction of each coordinate's range."),
    ParamSpec::real("collision_sigma", "Collision sigma", 0.0, 1.0, 0.03, "Near-collision sampler: standard deviation around the last collision point (fraction of each range)."),
    ParamSpec::real("random_sigma", "Random sigma", 0.0, 10.0, 0.5, "Near-collision sampler: standard deviation around a random centre (fraction of each range)."),
    ParamSpec::int("perseverance", "Perseverance", 1.0, 1e6, 20.0, "Near-collision sampler: samples around one centre before re-centring at random."),
    ParamSpec::int("sampler_tries", "Sampler tries", 1.0, 1e6, 100.0, "Raw draws a validity-checking sampler may spend on one sample before giving up."),
];

/// The sampler parameters as a group of the page's parameter panel.
pub const SAMPLER_GROUP: ParamGroup = ParamGroup { name: "sampler", label: "Sampler", params: SAMPLER_PARAMS };

/// What a sampler spent.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct SamplerStats {
    /// Samples handed to the planner.
    pub accepted: u64,
    /// Samples that gave up after `sampler_tries` draws.
    pub failed: u64,
    /// Raw states drawn (goal samples included).
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
    sigma: Real,
    collision_sigma: Real,
    random_sigma: Real,
    perseverance: u64,
    tries: u64,
    /// Near-collision: the current centre and its sigma, and samples drawn around it.
    centre: Option<Vec<Real>>,
    centre_sigma: Real,
    around_centre: u64,
    a: Vec<Real>,
    b: Vec<Real>,
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
    /// A raw draw from the robot's sampler.
    fn uniform(&mut self, out: &mut [Real]) {
        self.si.sample(self.rng, out);
    }
    /// Whether `q` is valid, logging the check as a raw try.
    fn check(&mut self, q: &[Real]) -> bool {
        let ok = self.si.is_valid(q);
        self.events.mark(EventKind::SampleTry, self.tree, ok as i64, -1.0, self.si.project(q), 0.0, 0.0);
        ok
    }
    /// Write into `out` a Gaussian neighbour of `centre`: each coordinate moved by a normal
    /// deviate of `sigma` × its range (angles wrap, bounded coordinates are clamped).
    fn gaussian_near(&mut self, centre: &[Real], sigma: Real, out: &mut [Real]) {
        for (i, d) in self.si.space.dims.iter().enumerate() {
            let v = centre[i] + self.rng.normal() * sigma * (d.hi - d.lo);
            out[i] = if d.wraps { v } else { v.clamp(d.lo, d.hi) };
        }
        self.si.space.enforce(out);
    }
}

impl Sampler {
    /// The sampler `params` name, for a task with `goal` (used when `goal_bias` > 0).
    pub fn from_params(si: &SpaceInfo, goal: Option<&[Real]>, params: &Params) -> Sampler {
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

    /// Draw one sample into `out`; `false` when the sampler gave up (after `sampler_tries` raw
    /// draws), in which case `out` holds nothing useful.
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
        if self.goal_bias > 0.0 && d.rng.uniform01() < self.goal_bias {
            if let Some(g) = &self.goal {
                out.copy_from_slice(g);
                self.stats.draws += 1;
                return true;
            }
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

    /// A motion toward a sample collided at `q` (the near-collision sampler re-centres there).
    pub fn note_collision(&mut self, q: &[Real]) {
        if self.kind == Kind::NearCollision {
            near_collision::note_collision(self, q);
        }
    }
}

#[cfg(test)]
mod tests;
