//! Growing the obstacles for the visibility graph: a margin for a point, the bounding disc for a
//! rigid robot, circles and discs as circumscribed regular polygons (see the parent module's doc).

use crate::geometry::segment::orient_sign;
use crate::geometry::{polygon, Shape, Workspace};
use crate::math::{Real, Vec2};
use crate::space_info::SpaceInfo;

/// The margin kept from closed obstacles, as a fraction of the map's larger side.
pub const MARGIN: Real = 1e-7;

/// A grown map: the polygons the path may touch but not cross, and the graph's candidate vertices.
#[derive(Debug)]
pub struct Grown {
    /// The grown obstacles (bounds: the map's).
    pub ws: Workspace,
    /// How far the obstacles were grown (the disc's radius plus the margin).
    pub growth: Real,
    /// Convex vertices: point, and its two neighbours on its polygon (for the tangent test).
    pub corners: Vec<[Vec2; 3]>,
}

/// A regular `k`-gon of apothem `r` about `c` (counter-clockwise; edge normals at angles `2πi/k`, so
/// with `k` a multiple of 4 it has edges along the axes).
fn ngon(c: Vec2, r: Real, k: usize) -> Vec<Vec2> {
    let rv = r / (std::f64::consts::PI / k as Real).cos();
    (0..k)
        .map(|i| {
            let a = std::f64::consts::TAU * (i as Real + 0.5) / k as Real;
            c + Vec2::new(libm::cos(a), libm::sin(a)) * rv
        })
        .collect()
}

/// The convex hull of `pts`, counter-clockwise, no collinear vertices (Andrew's monotone chain on
/// exact orientations).
fn hull(mut pts: Vec<Vec2>) -> Vec<Vec2> {
    pts.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let mut h: Vec<Vec2> = Vec::with_capacity(2 * pts.len());
    for pass in 0..2 {
        let start = h.len();
        let it: Box<dyn Iterator<Item = &Vec2>> =
            if pass == 0 { Box::new(pts.iter()) } else { Box::new(pts.iter().rev()) };
        for &p in it {
            while h.len() >= start + 2 && orient_sign(h[h.len() - 2], h[h.len() - 1], p) <= 0 {
                h.pop();
            }
            h.push(p);
        }
        h.pop();
    }
    h
}

/// The corners of the convex polygon `poly` (counter-clockwise) with their neighbours.
fn corners_of(poly: &[Vec2], out: &mut Vec<[Vec2; 3]>) {
    let n = poly.len();
    let w = polygon::winding(poly);
    for i in 0..n {
        let (p, v, q) = (poly[(i + n - 1) % n], poly[i], poly[(i + 1) % n]);
        // Only convex corners: a shortest path never bends at a reflex one.
        if orient_sign(p, v, q) * w > 0 {
            out.push([v, p, q]);
        }
    }
}

/// Why the obstacles were not grown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GrowError {
    /// The grown polygons could have this many vertices, more than allowed (see [`grown_vertices`]).
    TooMany(u64),
    /// The run's deadline passed (or its batch was suspended) after this many obstacles of all.
    Stopped {
        /// Obstacles grown.
        done: usize,
        /// Obstacles in all.
        of: usize,
    },
}

/// The sides of the polygon a vertex is grown by: the disc's `k` for a round growth, else the
/// margin's square.
fn sides_of(k: usize, round: bool) -> u64 {
    if round {
        k as u64
    } else {
        4
    }
}

/// The most vertices [`grow`] can make from `ws` (known before anything is grown): a convex
/// obstacle of `m` vertices grows to at most `m + s` (a Minkowski sum of convex polygons has at
/// most the sum of their vertices; `s` the sides of the polygon a vertex is grown by), a circle to
/// `k`, a segment to `2 + s`, and each edge of a non-convex polygon to `2 + s`.
pub fn grown_vertices(ws: &Workspace, g: Real, k: usize, round: bool) -> u64 {
    let s = if g > 0.0 { sides_of(k, round) } else { 0 };
    ws.obstacles
        .iter()
        .map(|o| match o {
            Shape::Rect(_) => 4 + s,
            Shape::Circle(..) => k as u64,
            Shape::Segment(..) => 2 + s,
            Shape::Polygon(p) if g <= 0.0 || polygon::is_convex(p) => p.len() as u64 + s,
            Shape::Polygon(p) => p.len() as u64 * (2 + s),
        })
        .sum()
}

/// Grow the obstacles of `ws` by `g` (see the module's doc), circles as `k`-gons; `round`: whether
/// the growth is a disc's (vertices grown by a `k`-gon) or only the margin (by a square of apothem
/// `g`: fewer vertices, and the path's cost moves by a few `g` all the same).
///
/// Refused before anything is grown when the grown polygons could have more than `max_vertices`
/// vertices ([`grown_vertices`]); the run's deadline is looked at as the obstacles are grown and
/// their corners kept (`si.tick`: a unit per 16 vertices made, and per corner tested).
pub fn grow(
    si: &SpaceInfo,
    ws: &Workspace,
    g: Real,
    k: usize,
    round: bool,
    max_vertices: u64,
) -> Result<Grown, GrowError> {
    let most = grown_vertices(ws, g, k, round);
    if most > max_vertices {
        return Err(GrowError::TooMany(most));
    }
    let kv = sides_of(k, round) as usize;
    let mut shapes = Vec::new();
    let mut corners = Vec::new();
    let convex = |pts: Vec<Vec2>, shapes: &mut Vec<Shape>, corners: &mut Vec<[Vec2; 3]>| {
        let h = if g > 0.0 { hull(pts.iter().flat_map(|&p| ngon(p, g, kv)).collect()) } else { hull(pts) };
        corners_of(&h, corners);
        shapes.push(Shape::Polygon(h));
    };
    let of = ws.obstacles.len();
    let mut made = 0;
    for (done, o) in ws.obstacles.iter().enumerate() {
        let before = corners.len();
        match o {
            Shape::Rect(b) => convex(
                vec![b.min, Vec2::new(b.max.x, b.min.y), b.max, Vec2::new(b.min.x, b.max.y)],
                &mut shapes,
                &mut corners,
            ),
            Shape::Circle(c, r) => {
                let p = ngon(*c, r + g, k);
                corners_of(&p, &mut corners);
                shapes.push(Shape::Polygon(p));
            }
            Shape::Segment(a, b) if g <= 0.0 => {
                corners.push([*a, *b, *b]);
                corners.push([*b, *a, *a]);
                shapes.push(o.clone());
            }
            Shape::Segment(a, b) => convex(vec![*a, *b], &mut shapes, &mut corners),
            Shape::Polygon(p) if polygon::is_convex(p) => convex(p.clone(), &mut shapes, &mut corners),
            Shape::Polygon(p) => {
                if g <= 0.0 {
                    corners_of(p, &mut corners);
                } else {
                    for i in 0..p.len() {
                        convex(vec![p[i], p[(i + 1) % p.len()]], &mut shapes, &mut corners);
                    }
                }
                shapes.push(o.clone());
            }
        }
        made += corners.len() - before + 1;
        if made >= 16 {
            if si.tick(made as u64 / 16) {
                return Err(GrowError::Stopped { done, of });
            }
            made %= 16;
        }
    }
    let mut grown = Workspace::new(ws.bounds, shapes);
    grown.touching_allowed = true;
    // Candidate vertices: in bounds, strictly inside no grown polygon.
    let b = ws.bounds;
    let mut stopped = false;
    corners.retain(|c| {
        stopped = stopped || si.tick(1 + crate::geometry::take_tests() / 16);
        !stopped && b.contains(c[0]) && grown.sight_clear(c[0], c[0])
    });
    if stopped {
        return Err(GrowError::Stopped { done: of, of });
    }
    corners.dedup_by(|a, b| a[0] == b[0]);
    Ok(Grown { ws: grown, growth: g, corners })
}

/// How the robot is seen: a point or its bounding disc, and whether the result is its optimum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// The disc's radius (0: a point).
    pub radius: Real,
    /// Whether the robot is (nearly) that disc, so the path is its optimum: a point, or a
    /// footprint whose inner radius is at least 99% of its outer one.
    pub round: bool,
}

/// The robot as a point or disc, or why the planner does not apply to it.
pub fn body_of(si: &SpaceInfo) -> Result<Body, String> {
    // A robot with a body in the plane (its `WorkspaceBody`) has paths that are polylines of its
    // reference point: planned as the disc its outline at the origin fits in (a point: none).
    if si.body().is_none() {
        let kind = si.robot_kind();
        return Err(format!(
            "needs a point robot or a rigid robot (planned as its bounding disc); this is a{} {kind} robot, whose paths are not polylines in the plane",
            if kind.starts_with(['a', 'e', 'i', 'o', 'u']) { "n" } else { "" }
        ));
    }
    let origin = vec![0.0; si.dims()];
    let outline = si.outline(&origin);
    let pts: Vec<Vec2> = outline.iter().flatten().copied().collect();
    let outer = pts.iter().map(|p| p.norm()).fold(0.0, Real::max);
    let inner = outline
        .iter()
        .flat_map(|poly| (0..poly.len()).map(|i| (poly[i], poly[(i + 1) % poly.len()])))
        .map(|(a, b)| crate::geometry::segment::distance2_point_segment(Vec2::zeros(), a, b).sqrt())
        .fold(Real::INFINITY, Real::min);
    Ok(Body { radius: outer, round: inner >= 0.99 * outer })
}

/// The growth for a robot on a map: its disc's radius plus the margin ([`MARGIN`] × the map's
/// larger side), since a point or a rigid body touching an obstacle collides.
pub fn growth(si: &SpaceInfo, body: Body) -> Real {
    let b = si.workspace().bounds;
    body.radius + MARGIN * (b.max.x - b.min.x).max(b.max.y - b.min.y)
}
