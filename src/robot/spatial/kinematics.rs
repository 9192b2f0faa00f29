//! Forward kinematics of a chain of revolute joints in classic Denavit–Hartenberg form, with
//! nalgebra's isometries: link `k`'s frame is link `k − 1`'s times `Rz(θ_k + q_k)·Tz(d_k)·Tx(a_k)·Rx(α_k)`,
//! link 0's frame is the base pose.
//!
//! Every sine and cosine comes from `libm` (the same bits natively and in wasm; the platform's
//! own `sin` may differ in the last place), one `sincos` of each joint's half angle, and rotations
//! are built as unit quaternions from them, so nalgebra only multiplies and adds.

use crate::math::Real;
use crate::scenario::{DhJoint, PoseSpec};
use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3};

/// A rotation about one axis (0: x, 1: y, 2: z) by `angle`, from its half angle's sine and cosine.
fn axis_rotation(axis: usize, angle: Real) -> UnitQuaternion<Real> {
    let (s, c) = libm::sincos(0.5 * angle);
    let mut v = [0.0; 3];
    v[axis] = s;
    UnitQuaternion::new_unchecked(Quaternion::new(c, v[0], v[1], v[2]))
}

/// The pose `Rz(rz)·Ry(ry)·Rx(rx)` after the translation.
pub fn pose_of(spec: &PoseSpec) -> Isometry3<Real> {
    let [rx, ry, rz] = spec.rotation;
    let r = axis_rotation(2, rz) * axis_rotation(1, ry) * axis_rotation(0, rx);
    let [x, y, z] = spec.translation;
    Isometry3::from_parts(Translation3::new(x, y, z), r)
}

/// One joint's row, with what does not depend on the joint's value computed once.
#[derive(Clone, Debug)]
struct Row {
    theta: Real,
    d: Real,
    a: Real,
    /// `Rx(α)`.
    twist: UnitQuaternion<Real>,
    /// `sin α`, `cos α` (for [`Chain::sweep`]).
    twist_sc: (Real, Real),
}

/// A serial chain of revolute joints.
#[derive(Clone, Debug)]
pub struct Chain {
    base: Isometry3<Real>,
    rows: Vec<Row>,
}

impl Chain {
    /// The chain of `joints` on `base`.
    pub fn new(base: &PoseSpec, joints: &[DhJoint]) -> Chain {
        Chain {
            base: pose_of(base),
            rows: joints
                .iter()
                .map(|j| Row {
                    theta: j.theta,
                    d: j.d,
                    a: j.a,
                    twist: axis_rotation(0, j.alpha),
                    twist_sc: libm::sincos(j.alpha),
                })
                .collect(),
        }
    }

    /// Number of joints.
    pub fn joints(&self) -> usize {
        self.rows.len()
    }

    /// Every link's frame in the world at `q` (link 0, the base, first): `out` holds
    /// `joints + 1` isometries.
    pub fn frames(&self, q: &[Real], out: &mut [Isometry3<Real>]) {
        let mut f = self.base;
        out[0] = f;
        for (k, r) in self.rows.iter().enumerate() {
            let angle = r.theta + q[k];
            // One `sincos`, of the half angle (the quaternion's); the whole angle's from it.
            let (hs, hc) = libm::sincos(0.5 * angle);
            let (s, c) = (2.0 * hs * hc, 1.0 - 2.0 * hs * hs);
            let turn = UnitQuaternion::new_unchecked(Quaternion::new(hc, 0.0, 0.0, hs));
            // Rz(θ)·Tz(d)·Tx(a)·Rx(α): the translation is Rz(θ)·(a, 0, d), the rotation Rz(θ)·Rx(α).
            let step = Isometry3::from_parts(Translation3::new(r.a * c, r.a * s, r.d), turn * r.twist);
            f *= step;
            out[k + 1] = f;
        }
    }

    /// The world position of `p` (in the last link's frame) at `q`.
    /// On the stack: it runs for every event a planner records (the tree is drawn at the tool).
    pub fn point_on_last(&self, q: &[Real], p: &[Real; 3]) -> [Real; 3] {
        let mut frames = [Isometry3::identity(); crate::limits::MAX_SPATIAL_JOINTS + 1];
        let n = self.rows.len();
        self.frames(q, &mut frames[..=n]);
        let w = frames[n] * nalgebra::Point3::from(Vector3::new(p[0], p[1], p[2]));
        [w.x, w.y, w.z]
    }

    /// The world position of `p` (in the last link's frame) at `points` evenly spread states of
    /// the straight motion `q(t) = a + t·delta`, `t = j / (points − 1)` for `j` in `0..points`
    /// (`t = 1` alone when `points` is 1): the curve a 3-D view draws an edge through.
    ///
    /// Cheaper than [`point_on_last`](Chain::point_on_last) at each state, for drawing only: each
    /// joint's angle is linear in `t`, so its sine and cosine step by one rotation from the last
    /// (one `sincos` per joint per curve, not per point), and the point is carried from the last
    /// link back to the base (`Rz·Tz·Tx·Rx` applied to a point, no frames composed). The ends are
    /// the `sincos` of their own angles; a point agrees with `point_on_last` to about 1e-15 of
    /// the arm's size (a test holds it to 1e-12 m).
    pub fn sweep(&self, a: &[Real], delta: &[Real], points: usize, p: &[Real; 3]) -> Vec<[Real; 3]> {
        let n = self.rows.len();
        let steps = points.max(1) - 1;
        let mut sc = [(0.0, 0.0); crate::limits::MAX_SPATIAL_JOINTS];
        let mut turn = [(0.0, 0.0); crate::limits::MAX_SPATIAL_JOINTS];
        let angle = |k: usize, t: Real| self.rows[k].theta + (a[k] + t * delta[k]);
        for k in 0..n {
            sc[k] = libm::sincos(angle(k, if steps == 0 { 1.0 } else { 0.0 }));
            turn[k] = libm::sincos(if steps == 0 { 0.0 } else { delta[k] / steps as Real });
        }
        let mut out = Vec::with_capacity(steps + 1);
        for j in 0..=steps {
            if j > 0 {
                for k in 0..n {
                    sc[k] = if j == steps {
                        libm::sincos(angle(k, 1.0))
                    } else {
                        let ((s, c), (ts, tc)) = (sc[k], turn[k]);
                        (s * tc + c * ts, c * tc - s * ts)
                    };
                }
            }
            // From the last link back: v ← Rz(θ)·(Rx(α)·v + (a, 0, d)).
            let mut v = Vector3::new(p[0], p[1], p[2]);
            for (r, &(s, c)) in self.rows.iter().zip(&sc).rev() {
                let (sa, ca) = r.twist_sc;
                let u = Vector3::new(v.x + r.a, ca * v.y - sa * v.z, sa * v.y + ca * v.z + r.d);
                v = Vector3::new(c * u.x - s * u.y, s * u.x + c * u.y, u.z);
            }
            let w = self.base * nalgebra::Point3::from(v);
            out.push([w.x, w.y, w.z]);
        }
        out
    }
}
