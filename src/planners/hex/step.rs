//! The step test: may the robot move from one cell centre to the next?
//!
//! The robot (a rectangle `l × w`, `t = √(l² + w²)`) turns on the spot at a cell centre and
//! then drives straight, along its length, to the next centre. Turning sweeps the circle of
//! radius `t/2` about the centre; driving from `a` to `b` sweeps at most the rectangle of width `t`
//! between the two centres plus the half circles at its ends. The report's test (its Q3) makes
//! the step impassable when an obstacle *vertex* lies
//!
//! 1. within the circle of radius `t/2` about the next centre `b`, or
//! 2. inside the rectangle of width `t` swept between `a` and `b`
//!
//! (points on the dashed boundary count as inside). The circle about `a` was tested by the step
//! that arrived at `a` (or, at the start, by [`disc_blocked`]). Vertices alone miss an obstacle
//! edge that crosses the region with both its ends outside (a long wall across a corridor), so
//! we complete the test with
//!
//! 3. an obstacle edge (or a disc obstacle) meeting the region, and
//! 4. the region leaving the map (the body stays on the map).
//!
//! With all four, the swept body of every accepted step is collision-free exactly.

use crate::geometry::polygon::contains_polygon_point;
use crate::geometry::segment::contains_segment_point;
use crate::geometry::{Aabb, Shape, Workspace};
use crate::math::{Real, Vec2};

/// Why a step is impassable (the number carried by the `CellState` event).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Blocked {
    /// An obstacle vertex within `t/2` of the next centre.
    VertexInCircle = 1,
    /// An obstacle vertex inside the rectangle swept between the centres.
    VertexInRectangle = 2,
    /// An obstacle edge (or disc) meets the region though no vertex lies in it.
    EdgeCrosses = 3,
    /// The region leaves the map.
    MapEdge = 4,
}

/// The corners of the rectangle of width `t` swept from `a` to `b` (counter-clockwise).
pub fn swept_rectangle(a: Vec2, b: Vec2, t: Real) -> [Vec2; 4] {
    let d = b - a;
    let len = d.norm();
    let n = if len > 0.0 { Vec2::new(-d.y / len, d.x / len).scale(t / 2.0) } else { Vec2::new(0.0, 0.0) };
    [a - n, b - n, b + n, a + n]
}

/// The vertices an obstacle has (a disc has none).
fn vertices(shape: &Shape) -> Vec<Vec2> {
    match shape {
        Shape::Rect(r) => vec![r.min, Vec2::new(r.max.x, r.min.y), r.max, Vec2::new(r.min.x, r.max.y)],
        Shape::Polygon(p) => p.clone(),
        Shape::Segment(a, b) => vec![*a, *b],
        Shape::Circle(..) => Vec::new(),
    }
}

/// The step test from centre `a` to centre `b` for a robot of diagonal `t`: `Ok` if passable,
/// else the first reason in the order above (the report's two vertex tests first).
pub fn step_test(ws: &Workspace, a: Vec2, b: Vec2, t: Real) -> Result<(), Blocked> {
    let r = t / 2.0;
    let rect = swept_rectangle(a, b, t);
    let region_box = Aabb::of_points(&rect).grown(r);
    let near: Vec<&Shape> = ws.obstacles.iter().filter(|s| s.aabb().intersects(&region_box)).collect();
    // 1. A vertex within the circle about b (on the circle counts).
    if near.iter().any(|s| vertices(s).iter().any(|&v| (v - b).norm_squared() <= r * r)) {
        return Err(Blocked::VertexInCircle);
    }
    // 2. A vertex inside the swept rectangle (the crossing-number test; the boundary counts).
    let in_rect = |v: Vec2| if t > 0.0 { contains_polygon_point(&rect, v) } else { contains_segment_point(a, b, v) };
    if near.iter().any(|s| vertices(s).iter().any(|&v| in_rect(v))) {
        return Err(Blocked::VertexInRectangle);
    }
    // 3. An edge or a disc meeting the region with no vertex inside it.
    let rect_box = Aabb::of_points(&rect);
    for s in &near {
        let hits_rect = if t > 0.0 { s.intersects_polygon(&rect, &rect_box) } else { s.intersects_segment(a, b) };
        if hits_rect || s.distance_to_segment(b, b, r + 1.0) <= r {
            return Err(Blocked::EdgeCrosses);
        }
    }
    // 4. The map's edge.
    let inside = |p: Vec2| ws.bounds.contains(p);
    let disc_inside = b.x - r >= ws.bounds.min.x
        && b.x + r <= ws.bounds.max.x
        && b.y - r >= ws.bounds.min.y
        && b.y + r <= ws.bounds.max.y;
    if !disc_inside || !rect.iter().all(|&p| inside(p)) {
        return Err(Blocked::MapEdge);
    }
    Ok(())
}

/// Whether the robot cannot turn on the spot at `p`: an obstacle or the map's edge within `t/2`
/// (the reason as for a step).
pub fn disc_blocked(ws: &Workspace, p: Vec2, t: Real) -> Option<Blocked> {
    step_test(ws, p, p, t).err()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ws(obstacles: Vec<Shape>) -> Workspace {
        Workspace::new(Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) }, obstacles)
    }
    fn rect(x0: Real, y0: Real, x1: Real, y1: Real) -> Shape {
        Shape::Rect(Aabb { min: Vec2::new(x0, y0), max: Vec2::new(x1, y1) })
    }
    // Numbers exact in binary, so "on the circle" is exactly on it: t/2 = 0.0625.
    const A: Vec2 = Vec2::new(0.25, 0.5);
    const B: Vec2 = Vec2::new(0.5, 0.5);
    const T: Real = 0.125;
    fn tri(p: Vec2) -> Shape {
        Shape::Polygon(vec![p, Vec2::new(0.7, 0.45), Vec2::new(0.7, 0.55)])
    }
    fn spike(tip_y: Real) -> Shape {
        Shape::Polygon(vec![Vec2::new(0.38, 0.2), Vec2::new(0.42, 0.2), Vec2::new(0.4, tip_y)])
    }

    #[test]
    fn open_space_is_passable() {
        assert_eq!(step_test(&ws(vec![rect(0.8, 0.8, 0.9, 0.9)]), A, B, T), Ok(()));
    }

    #[test]
    fn a_vertex_inside_the_circle_blocks() {
        // A corner 0.05 beyond B: inside t/2, outside the rectangle.
        assert_eq!(step_test(&ws(vec![tri(Vec2::new(0.55, 0.5))]), A, B, T), Err(Blocked::VertexInCircle));
    }

    #[test]
    fn a_vertex_on_the_circle_counts_as_inside() {
        assert_eq!(step_test(&ws(vec![tri(Vec2::new(0.5625, 0.5))]), A, B, T), Err(Blocked::VertexInCircle));
        assert_eq!(step_test(&ws(vec![tri(Vec2::new(0.563, 0.5))]), A, B, T), Ok(()));
    }

    #[test]
    fn a_vertex_inside_the_rectangle_blocks() {
        // A spike from below, its tip between the centres: inside, on the long side, below it.
        assert_eq!(step_test(&ws(vec![spike(0.47)]), A, B, T), Err(Blocked::VertexInRectangle));
        assert_eq!(step_test(&ws(vec![spike(0.4375)]), A, B, T), Err(Blocked::VertexInRectangle));
        assert_eq!(step_test(&ws(vec![spike(0.437)]), A, B, T), Ok(()));
    }

    #[test]
    fn a_diagonal_step_uses_the_rotated_rectangle() {
        // Step along the diagonal; a vertex 0.05 off the line (inside) and 0.075 off (outside).
        let (a, b) = (Vec2::new(0.25, 0.25), Vec2::new(0.5, 0.5));
        let off = |d: Real| Vec2::new(0.375 - d / 2f64.sqrt(), 0.375 + d / 2f64.sqrt());
        let tip = |p: Vec2| Shape::Polygon(vec![p, Vec2::new(0.05, 0.9), Vec2::new(0.0, 0.85)]);
        assert_eq!(step_test(&ws(vec![tip(off(0.05))]), a, b, T), Err(Blocked::VertexInRectangle));
        assert_eq!(step_test(&ws(vec![tip(off(0.075))]), a, b, T), Ok(()));
    }

    #[test]
    fn the_circle_is_tested_before_the_rectangle() {
        // A vertex in both (near B, on the line): the report's first test answers.
        let t = Shape::Polygon(vec![Vec2::new(0.48, 0.5), Vec2::new(0.6, 0.1), Vec2::new(0.7, 0.1)]);
        assert_eq!(step_test(&ws(vec![t]), A, B, T), Err(Blocked::VertexInCircle));
    }

    #[test]
    fn an_edge_across_the_corridor_blocks_without_a_vertex_inside() {
        // A long wall crossing between the centres: no vertex in the region.
        assert_eq!(step_test(&ws(vec![rect(0.39, 0.0, 0.41, 1.0)]), A, B, T), Err(Blocked::EdgeCrosses));
        let seg = Shape::Segment(Vec2::new(0.4, 0.1), Vec2::new(0.4, 0.9));
        assert_eq!(step_test(&ws(vec![seg]), A, B, T), Err(Blocked::EdgeCrosses));
        // A disc has no vertex: it blocks when it meets the region.
        let disc = Shape::Circle(Vec2::new(0.5, 0.6), 0.05);
        assert_eq!(step_test(&ws(vec![disc]), A, B, T), Err(Blocked::EdgeCrosses));
    }

    #[test]
    fn a_gap_narrower_than_t_is_impassable_and_a_wider_one_is_not() {
        // Two walls with a gap of width g around y = 0.5, the step crossing it.
        let walls = |g: Real| vec![rect(0.38, 0.0, 0.42, 0.5 - g / 2.0), rect(0.38, 0.5 + g / 2.0, 0.42, 1.0)];
        assert_eq!(step_test(&ws(walls(0.9 * T)), A, B, T), Err(Blocked::VertexInRectangle));
        assert_eq!(step_test(&ws(walls(1.1 * T)), A, B, T), Ok(()));
    }

    #[test]
    fn the_map_edge_blocks() {
        let (a, b) = (Vec2::new(0.5, 0.97), Vec2::new(0.7, 0.97));
        assert_eq!(step_test(&ws(vec![]), a, b, T), Err(Blocked::MapEdge));
        assert_eq!(disc_blocked(&ws(vec![]), Vec2::new(0.03, 0.5), T), Some(Blocked::MapEdge));
        assert_eq!(disc_blocked(&ws(vec![]), Vec2::new(0.5, 0.5), T), None);
    }

    #[test]
    fn a_point_robot_tests_the_segment() {
        let wall = rect(0.39, 0.0, 0.41, 0.6);
        assert_eq!(step_test(&ws(vec![wall.clone()]), A, B, 0.0), Err(Blocked::EdgeCrosses));
        assert_eq!(step_test(&ws(vec![wall]), Vec2::new(0.3, 0.7), Vec2::new(0.5, 0.7), 0.0), Ok(()));
    }
}
