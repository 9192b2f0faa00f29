//! A fixed-base planar arm (reports 003 and 004 and OMPL's horn, `docs/sources.md`): `n` revolute links, joint angles relative to the
//! previous link, each joint limited or wrapping around.
//!
//! Valid when every joint is within its limits, every joint point (base and tip included) lies in
//! the bounds, no link meets an obstacle (the interior only, when touching is allowed), and, with
//! `self_collision`, no two non-adjacent links meet and no two adjacent links fold onto each other.
//! An optional `tip` continues the last link (OMPL's chain benchmark checks a 0.001 tip).
//!
//! Motions are certified with clearances: along a straight joint-space motion, a point at distance
//! `R` from joint `i` moves at most `R·|Δqᵢ|` because of that joint. Per motion, each segment gets
//! its own speed bound (joints before it only, each times the length from that joint to the
//! segment's far end), and each pair of segments a bound on how fast they approach each other (the
//! joints between them only). The motion clearance of a state is the smallest distance (to
//! obstacles, to the bounds, between segments) divided by its bound: the fraction of the motion
//! it takes to close. Two neighbouring links that barely turn relative to each other no longer
//! force fine steps because the whole arm swings: on the 10-link horn, RRT-Connect's median checks
//! fell from 24 254 (one displacement bound for the whole arm) to 3 904.

use super::capability::{MotionModel, Sensor};
use super::{Robot, Verdict};
use crate::geometry::segment::{
    contains_segment_point, distance2_point_segment, distance_segment_segment, intersect_segment_segment,
};
use crate::geometry::{Aabb, SensorPose, Workspace};
use crate::math::{angle_diff, MinMax, Real, Vec2, PI};
use crate::robot::kinds::{Drawn, Pose, RobotKind};
use crate::scenario::RobotSpec;
use crate::space::{Dim, Metric, StateSpace};

/// How close to ±π a joint's angle may come before its links count as folded.
const FOLD_TOLERANCE: Real = 1e-9;

/// The most joint points kept on the stack.
const STACK_POINTS: usize = 40;

/// A fixed-base planar arm.
#[derive(Clone, Debug)]
pub struct ArmRobot {
    base: Vec2,
    links: Vec<Real>,
    limits: Vec<Option<[Real; 2]>>,
    self_collision: bool,
    metric: Metric,
    tip: Real,
    /// The rates of the latest motion certified (see [`ArmRobot::set_motion`]).
    rates: std::cell::RefCell<MotionRates>,
}

/// Speed bounds along one motion: per segment, and per pair of segments relative to each other.
/// Its vectors are refilled for each motion, never reallocated once grown.
#[derive(Clone, Debug, Default)]
struct MotionRates {
    a: Vec<Real>,
    b: Vec<Real>,
    seg: Vec<Real>,
    /// `rel[i * segs + j]` for `i < j`.
    rel: Vec<Real>,
    segs: usize,
    /// Scratch for [`ArmRobot::clearance_at`], reused across states and motions: the joint
    /// points and each segment's box.
    pts: Vec<Vec2>,
    boxes: Vec<Aabb>,
    /// Scratch for [`ArmRobot::set_motion`]: each joint's turn, and prefix sums of the segments'
    /// lengths.
    dq: Vec<Real>,
    prefix: Vec<Real>,
}

impl ArmRobot {
    /// The robot a scenario's `arm` block describes.
    pub fn from_spec(spec: &RobotSpec) -> Result<Self, String> {
        let RobotSpec::Arm { base, links, limits, self_collision, metric, tip } = spec else {
            return Err("not an arm".into());
        };
        let metric = match metric.as_str() {
            "joint" => Metric::Euclidean,
            "max" => Metric::ChainMax { links: links.clone() },
            "fk" => Metric::ChainNorm { links: links.clone() },
            _ => Metric::ChainSum { links: links.clone() },
        };
        Ok(ArmRobot {
            base: Vec2::new(base[0], base[1]),
            links: links.clone(),
            limits: limits.clone(),
            self_collision: *self_collision,
            metric,
            tip: *tip,
            rates: std::cell::RefCell::new(MotionRates::default()),
        })
    }

    /// Number of points of the arm at a state: base, one per link end, and the tip's end if any.
    fn point_count(&self) -> usize {
        self.links.len() + 1 + usize::from(self.tip > 0.0)
    }

    /// Forward kinematics: write every joint point (base first, tip end last) into `out`.
    pub fn joint_points(&self, q: &[Real], out: &mut [Vec2]) {
        let mut p = self.base;
        let mut theta = 0.0;
        let (mut s, mut c) = (0.0, 1.0);
        out[0] = p;
        for (i, l) in self.links.iter().enumerate() {
            theta += q[i];
            // sincos shares one argument reduction; it equals sin and cos bit for bit.
            (s, c) = libm::sincos(theta);
            p += Vec2::new(l * c, l * s);
            out[i + 1] = p;
        }
        if self.tip > 0.0 {
            out[self.links.len() + 1] = p + Vec2::new(self.tip * c, self.tip * s);
        }
    }

    /// The verdict at `q`; `any`: a collision names any obstacle met, not the first (for validity
    /// alone, where the search can stop at the first found).
    fn verdict_at(&self, ws: &Workspace, q: &[Real], any: bool) -> Verdict {
        if !self.within_limits(q) {
            return Verdict::Invalid("a joint is outside its limits");
        }
        self.with_points(q, |pts| {
            if let Some(p) = pts.iter().find(|p| !ws.bounds.contains(**p)) {
                return Verdict::OutOfBounds(if p.x < ws.bounds.min.x || p.x > ws.bounds.max.x { 0 } else { 1 });
            }
            for w in pts.windows(2) {
                if let Some(i) =
                    if any { ws.any_obstacle_on_segment(w[0], w[1]) } else { ws.first_obstacle_on_segment(w[0], w[1]) }
                {
                    return Verdict::Collision(i);
                }
            }
            match self.self_collision.then(|| Self::self_problem(q, pts)).flatten() {
                Some(why) => Verdict::Invalid(why),
                None => Verdict::Valid,
            }
        })
    }

    fn with_points<T>(&self, q: &[Real], f: impl FnOnce(&[Vec2]) -> T) -> T {
        let m = self.point_count();
        if m <= STACK_POINTS {
            let mut buf = [Vec2::default(); STACK_POINTS];
            self.joint_points(q, &mut buf[..m]);
            f(&buf[..m])
        } else {
            let mut buf = vec![Vec2::default(); m];
            self.joint_points(q, &mut buf);
            f(&buf)
        }
    }

    /// Segment `k`'s length (the links, then the tip).
    fn seg_len(&self, k: usize) -> Real {
        self.links.get(k).copied().unwrap_or(self.tip)
    }

    /// How far joint `i` turns along the straight joint-space motion `a → b` (the shorter way for a
    /// joint without limits).
    fn joint_travel(&self, i: usize, a: &[Real], b: &[Real]) -> Real {
        if self.limits[i].is_some() {
            (b[i] - a[i]).abs()
        } else {
            angle_diff(a[i], b[i]).abs()
        }
    }

    /// How fast each segment, and each pair of segments relative to each other, can move along the
    /// straight joint-space motion `a → b`, per unit of the motion's parameter `t ∈ [0, 1]`.
    ///
    /// A point of segment `k` at distance `r` from joint `m` (`m ≤ k`) moves at most `r·|Δq_m|`
    /// because of that joint, and `r ≤ R(m, k)`, the length from joint `m` to segment `k`'s far
    /// end: so segment `k` moves at most `Σ_{m ≤ k} |Δq_m|·R(m, k)`. Seen from segment `i`, segment
    /// `j > i` moves only by the joints between them: at most `Σ_{i < m ≤ j} |Δq_m|·R(m, j)`. Two
    /// links next to each other therefore close in only by their shared joint, however fast the
    /// arm as a whole swings.
    fn set_motion(&self, rates: &mut MotionRates, a: &[Real], b: &[Real]) {
        let n = self.links.len();
        let segs = self.point_count() - 1;
        let MotionRates { a: ra, b: rb, seg, rel, segs: rs, dq, prefix, .. } = rates;
        dq.clear();
        dq.extend((0..n).map(|i| self.joint_travel(i, a, b)));
        // R(m, k), by prefix sums of the segment lengths.
        prefix.clear();
        prefix.push(0.0);
        for k in 0..segs {
            prefix.push(prefix[k] + self.seg_len(k));
        }
        let r = |m: usize, k: usize| prefix[k + 1] - prefix[m];
        let joints_of = |k: usize| k.min(n - 1); // the tip turns with the last joint
        ra.clear();
        ra.extend_from_slice(a);
        rb.clear();
        rb.extend_from_slice(b);
        *rs = segs;
        seg.clear();
        seg.extend((0..segs).map(|k| (0..=joints_of(k)).map(|m| dq[m] * r(m, k)).sum::<Real>()));
        rel.clear();
        rel.resize(segs * segs, 0.0);
        for i in 0..segs {
            for j in i + 1..segs {
                rel[i * segs + j] = (i + 1..=joints_of(j)).map(|m| dq[m] * r(m, j)).sum();
            }
        }
    }

    /// The clearance of state `q` on the motion whose `rates` are given, capped at `cap`, in units
    /// of the motion's parameter: each distance (to obstacles, to the bounds, between segments)
    /// divided by how fast it can close, so motions whose links barely move relative to each
    /// other certify in few steps.
    fn clearance_at(&self, ws: &Workspace, q: &[Real], cap: Real, rates: &mut MotionRates) -> Real {
        if !self.within_limits(q) {
            return 0.0;
        }
        let MotionRates { seg, rel, segs, pts, boxes, .. } = rates;
        let seg_rate = |k: usize| seg[k];
        let pair_rate = |i: usize, j: usize| rel[i * *segs + j];
        // A distance over a rate, in the clearance's units (a constraint that cannot close: none).
        let over = |dist: Real, rate: Real| {
            if dist <= 0.0 {
                0.0
            } else if rate <= 0.0 {
                Real::INFINITY
            } else {
                dist / rate
            }
        };
        pts.resize(self.point_count(), Vec2::default());
        self.joint_points(q, pts);
        let pts = &pts[..];
        let b = ws.bounds;
        let mut c = cap;
        // The base never moves: only the other points can leave the bounds (the Technion base
        // sits on the bounds' corner).
        for (k, p) in pts.iter().enumerate().skip(1) {
            let d = (p.x - b.min.x).at_most(b.max.x - p.x).at_most(p.y - b.min.y).at_most(b.max.y - p.y).at_least(0.0);
            c = c.at_most(over(d, seg_rate(k - 1)));
        }
        for (k, w) in pts.windows(2).enumerate() {
            if c == 0.0 {
                return 0.0;
            }
            let rate = seg_rate(k);
            // Within this segment's reach of c: the capped distance, else only whether it meets.
            let reach = if rate > 0.0 && c.is_finite() { c * rate } else { Real::MIN_POSITIVE };
            c = c.at_most(over(ws.segment_clearance(w[0], w[1], reach), rate));
        }
        if self.self_collision {
            let segs = pts.len() - 1;
            // Each segment's box, once (the pairs' broad phase reads them 2·segs times each).
            boxes.clear();
            boxes.extend(pts.windows(2).map(Aabb::of_points));
            for i in 0..segs {
                let bi = boxes[i];
                for j in i + 1..segs {
                    let tip_pair = self.tip > 0.0 && j == segs - 1 && i == segs - 2;
                    if tip_pair {
                        continue; // the tip continues the last link by construction
                    }
                    let rate = pair_rate(i, j);
                    let d = if j == i + 1 {
                        // Adjacent links meet at their joint; they fold when either far end
                        // reaches the other link.
                        let (a, m, e) = (pts[i], pts[i + 1], pts[i + 2]);
                        if contains_segment_point(m, e, a) || contains_segment_point(a, m, e) {
                            0.0
                        } else {
                            distance2_point_segment(a, m, e).at_most(distance2_point_segment(e, a, m)).sqrt()
                        }
                    } else {
                        // Broad phase: two links whose boxes are c·rate apart cannot lower c
                        // (the result is the same; most pairs of a long chain are far apart).
                        let g = bi.gap(&boxes[j]);
                        let reach = c * rate;
                        if g.norm_squared() >= reach * reach && g.x + g.y > 0.0 {
                            continue;
                        }
                        distance_segment_segment(pts[i], pts[i + 1], pts[j], pts[j + 1])
                    };
                    c = c.at_most(over(d, rate));
                }
            }
        }
        c
    }

    fn within_limits(&self, q: &[Real]) -> bool {
        self.limits.iter().zip(q).all(|(l, v)| l.is_none_or(|[lo, hi]| *v >= lo && *v <= hi))
    }

    /// Why the arm at state `q` (joint points `pts`) breaks its own rules, if it does.
    fn self_problem(q: &[Real], pts: &[Vec2]) -> Option<&'static str> {
        // Adjacent links fold onto each other when the joint between them turns by ±π (judged on
        // the angle: forward kinematics in floating point never makes them exactly collinear).
        if q[1..].iter().any(|a| (PI - crate::math::wrap_angle(*a).abs()).abs() < FOLD_TOLERANCE) {
            return Some("two adjacent links fold onto each other");
        }
        let segs = pts.len() - 1;
        for i in 0..segs {
            for j in i + 2..segs {
                // Boxes apart: the links cannot meet (most pairs of a long chain; exact).
                let (p, q, r, s) = (pts[i], pts[i + 1], pts[j], pts[j + 1]);
                if Aabb::of_points(&[p, q]).intersects(&Aabb::of_points(&[r, s]))
                    && intersect_segment_segment(p, q, r, s)
                {
                    return Some("the arm crosses itself");
                }
            }
        }
        None
    }
}

/// The kind's record ([`super::kinds`]).
pub const KIND: RobotKind = RobotKind {
    name: "arm",
    label: "Planar arm",
    drawn: Drawn::OpenChain,
    body: false,
    sensor: true,
    cspace: true,
    course_cost: Some("fk"),
    pose: Pose::Joints,
    solution_file: false,
    default_range: None,
};

impl Robot for ArmRobot {
    fn caps(&self) -> &'static RobotKind {
        &KIND
    }
    fn external_dims(&self) -> usize {
        self.links.len()
    }
    fn space(&self, _ws: &Workspace) -> StateSpace {
        let dims = self
            .limits
            .iter()
            .map(|l| match l {
                Some([lo, hi]) => Dim { lo: *lo, hi: *hi, wraps: false },
                None => Dim { lo: -PI, hi: PI, wraps: true },
            })
            .collect();
        StateSpace { dims, metric: self.metric.clone() }
    }
    fn verdict(&self, ws: &Workspace, q: &[Real]) -> Verdict {
        self.verdict_at(ws, q, false)
    }
    fn is_valid(&self, ws: &Workspace, q: &[Real]) -> bool {
        self.verdict_at(ws, q, true) == Verdict::Valid
    }
    fn project(&self, q: &[Real]) -> Vec2 {
        // The end effector (the last link's end).
        self.with_points(q, |pts| pts[self.links.len()])
    }
    fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>> {
        let mut pts = vec![Vec2::default(); self.point_count()];
        self.joint_points(q, &mut pts);
        vec![pts]
    }
    fn motion(&self) -> Option<&dyn MotionModel> {
        Some(self)
    }
    fn sensor(&self) -> Option<&dyn Sensor> {
        Some(self)
    }
}

/// Motions are certified by clearances in units of the motion, each link at its own speed.
impl MotionModel for ArmRobot {
    fn has_motion_clearance(&self) -> bool {
        true
    }
    fn motion_clearance(&self, ws: &Workspace, a: &[Real], b: &[Real], q: &[Real], cap: Real) -> Option<Real> {
        let mut rates = self.rates.borrow_mut();
        if rates.a != a || rates.b != b {
            self.set_motion(&mut rates, a, b);
        }
        Some(self.clearance_at(ws, q, cap, &mut rates))
    }
    /// Every rate of [`set_motion`](ArmRobot::set_motion) is a sum of joint travels `|Δq_m|`
    /// times lengths `R ≥ 0`, so when each joint travels at most `μ` times as far along `a → b` as
    /// along `pa → pb`, every rate is at most `μ` times its value there (a joint still along
    /// `pa → pb` must be still along `a → b`, else `None`). For two steps of one walk along a line,
    /// `μ` is the ratio of their lengths (1 but for rounding, less for the shorter last step).
    /// With self-collision, two neighbouring links fold when the joint between them reaches ±π:
    /// a motion that turns a wrapping joint (not the base's) through ±π passes through that
    /// fold. Certification would refuse it only at its bisection's depth limit, after 40 or more
    /// clearance queries (`docs/performance.md`, "The chain's checks against OMPL's").
    fn refused_at(&self, a: &[Real], b: &[Real]) -> Option<Real> {
        if !self.self_collision {
            return None;
        }
        (1..self.links.len()).filter(|&i| self.limits[i].is_none()).find_map(|i| {
            let d = angle_diff(a[i], b[i]);
            let end = a[i] + d;
            // From a[i] in [−π, π], the unwrapped joint reaches ±π when it ends beyond it.
            (d != 0.0 && end.abs() >= PI).then(|| ((end.signum() * PI - a[i]) / d).clamp(0.0, 1.0))
        })
    }
    fn motion_rate_ratio(&self, pa: &[Real], pb: &[Real], a: &[Real], b: &[Real]) -> Option<Real> {
        let mut mu: Real = 0.0;
        for i in 0..self.links.len() {
            let (was, now) = (self.joint_travel(i, pa, pb), self.joint_travel(i, a, b));
            if now == 0.0 {
                continue;
            }
            if was.is_nan() || was <= 0.0 || now.is_nan() {
                return None;
            }
            mu = mu.max(now / was);
        }
        Some(mu * (1.0 + RATE_SLACK))
    }
}

/// The slack by which [`MotionModel::motion_rate_ratio`] is rounded up: the rates are sums of at
/// most [`MAX_LINKS`](crate::limits::MAX_LINKS) + 1 products, each rounded (relative error below
/// 2⁻⁵³ a term), and the ratio and the carried clearance `c / μ` are rounded once more each; 1e-12
/// is above (66 + 2)·2⁻⁵² ≈ 1.5e-14 with room to spare, and far below any clearance that decides.
const RATE_SLACK: Real = 1e-12;

/// The cost of `path` in report 004's unit: the sum over its motions of the Euclidean norm of the
/// difference of the stacked link-end points (the `fk` metric), for an arm of `links`.
pub fn fk_path_cost(links: &[Real], path: &[Vec<Real>]) -> Real {
    let space = StateSpace { dims: Vec::new(), metric: Metric::ChainNorm { links: links.to_vec() } };
    path.windows(2).map(|w| space.distance(&w[0], &w[1])).sum()
}

/// The end effector (the last link's end, before any tip), looking along the last link: its
/// heading is the sum of the (relative) joint angles, as in the Technion course.
impl Sensor for ArmRobot {
    fn pose(&self, q: &[Real]) -> SensorPose {
        let heading = q[..self.links.len()].iter().sum();
        SensorPose { at: self.project(q), heading: Some(heading) }
    }
}
