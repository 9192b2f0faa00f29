//! A convex hull whose support map climbs the hull's vertex graph instead of scanning every
//! vertex (the Puma's base hull has 39, its upper arm 49, and GJK asks each for a support point
//! several times a query).
//!
//! The climb starts at the vertex the last call for the same use ended on (successive GJK
//! directions, and the same pair's directions in successive queries, are close), and moves to the
//! first strictly better neighbour while there is one. Where it stops, either every neighbour is
//! strictly worse, or one ties:
//! - every neighbour strictly worse: on the triangulated boundary of a convex polytope, the
//!   triangles around a vertex span its tangent cone, so a strict local maximum of a linear
//!   function is the strict global one. (A point inside a flat face is a convex combination of its
//!   neighbours, so it always has a neighbour at least as good and never ends here.) The answer is
//!   the unique maximiser: the one parry's linear scan finds;
//! - a neighbour ties (or the direction is not a number): the maximum may be a face or an edge, or
//!   the climb may stand on a flat face opposite the direction; parry's scan decides, so the answer
//!   is then also the scan's (its first maximiser).
//!
//! So the point returned is, bit for bit, the one `ConvexPolyhedron`'s own support map returns, and
//! a run's answers do not change; only fewer vertices are looked at. Where a climb starts is kept
//! per use of the hull (a pair of solids and a side: a [`Climber`]), by the caller.

use parry3d_f64::math::Vector;
use parry3d_f64::shape::{ConvexPolyhedron, SupportMap};
use parry3d_f64::utils::point_cloud_support_point;
use std::cell::Cell;

/// A convex polyhedron with its vertices' neighbours (the hull triangulation's edges).
#[derive(Clone, Debug)]
pub struct Hull {
    /// parry's polyhedron (its points are the hull's vertices, in the triangulation's order).
    pub poly: ConvexPolyhedron,
    /// `adjacency[start[i]..start[i + 1]]`: the neighbours of vertex `i`.
    start: Vec<u32>,
    adjacency: Vec<u32>,
}

impl Hull {
    /// The convex hull of `points`, or `None` when parry cannot build it (fewer than four points
    /// not in one plane).
    pub fn of_points(points: &[Vector]) -> Option<Hull> {
        let (vertices, triangles) = parry3d_f64::transformation::try_convex_hull(points).ok()?;
        let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); vertices.len()];
        for t in &triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                for (u, v) in [(a, b), (b, a)] {
                    let list = neighbours.get_mut(u as usize)?;
                    if !list.contains(&v) {
                        list.push(v);
                    }
                }
            }
        }
        let poly = ConvexPolyhedron::from_convex_mesh(vertices, &triangles)?;
        let mut start = Vec::with_capacity(neighbours.len() + 1);
        let mut adjacency = Vec::new();
        start.push(0);
        for list in &neighbours {
            adjacency.extend_from_slice(list);
            start.push(adjacency.len() as u32);
        }
        Some(Hull { poly, start, adjacency })
    }

    /// The neighbours of vertex `i`.
    #[inline]
    fn neighbours(&self, i: usize) -> &[u32] {
        &self.adjacency[self.start[i] as usize..self.start[i + 1] as usize]
    }
}

impl Hull {
    /// The support point along `dir`, climbing from the vertex in `hint` (any vertex index; out
    /// of range counts as 0), which is left at the vertex the climb ended on.
    #[inline]
    pub fn climb(&self, dir: Vector, hint: &Cell<u32>) -> Vector {
        let pts = self.poly.points();
        let mut best = hint.get() as usize;
        if best >= pts.len() {
            best = 0;
        }
        let mut best_dot = pts[best].dot(dir);
        'climb: loop {
            let mut tie = false;
            for &n in self.neighbours(best) {
                let d = pts[n as usize].dot(dir);
                if d > best_dot {
                    // The first better neighbour: move on from there.
                    best_dot = d;
                    best = n as usize;
                    continue 'climb;
                }
                tie |= d == best_dot;
            }
            hint.set(best as u32);
            if tie || best_dot.is_nan() {
                return point_cloud_support_point(dir, pts);
            }
            return pts[best];
        }
    }
}

/// A hull with where its climbs start: one per use (a pair of solids and a side), so that each
/// climb starts where the same use's last one ended.
pub struct Climber<'a> {
    /// The hull.
    pub hull: &'a Hull,
    /// The vertex the last climb of this use ended on.
    pub hint: &'a Cell<u32>,
}

impl SupportMap for Climber<'_> {
    #[inline]
    fn local_support_point(&self, dir: Vector) -> Vector {
        self.hull.climb(dir, self.hint)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    fn check(points: &[Vector], rng: &mut Rng) {
        let hull = Hull::of_points(points).expect("a hull");
        let hint = Cell::new(0);
        let climber = Climber { hull: &hull, hint: &hint };
        let mut dirs: Vec<Vector> = hull.poly.faces().iter().flat_map(|f| [f.normal, -f.normal]).collect();
        for axis in [Vector::X, Vector::Y, Vector::Z] {
            dirs.extend([axis, -axis, axis + Vector::Y, axis - Vector::Z]);
        }
        for _ in 0..2000 {
            dirs.push(Vector::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)));
        }
        dirs.push(Vector::new(f64::NAN, 0.0, 1.0));
        for (k, d) in dirs.iter().enumerate() {
            let scan = hull.poly.local_support_point(*d);
            let climb = climber.local_support_point(*d);
            assert!(
                scan.x.to_bits() == climb.x.to_bits()
                    && scan.y.to_bits() == climb.y.to_bits()
                    && scan.z.to_bits() == climb.z.to_bits(),
                "direction {k} {d:?}: scan {scan:?}, climb {climb:?}"
            );
        }
    }

    /// The climb's point is the scan's, bit for bit: along every face normal and its opposite
    /// (where whole faces tie), the axes, and random directions, from wherever the last climb
    /// ended; on a cube with points inside its faces and edges, and on random clouds.
    #[test]
    fn the_climb_finds_the_scans_point() {
        let mut rng = Rng::new(7);
        let mut cube = Vec::new();
        for x in [-1.0, 0.0, 1.0] {
            for y in [-1.0, 0.0, 1.0] {
                for z in [-1.0, 0.0, 1.0] {
                    if (x, y, z) != (0.0, 0.0, 0.0) {
                        cube.push(Vector::new(x, y, z));
                    }
                }
            }
        }
        check(&cube, &mut rng);
        for n in [4, 12, 60, 300] {
            let cloud: Vec<Vector> = (0..n)
                .map(|_| Vector::new(rng.uniform(-1.0, 1.0), rng.uniform(-0.2, 0.3), rng.uniform(0.0, 2.0)))
                .collect();
            check(&cloud, &mut rng);
        }
    }
}
