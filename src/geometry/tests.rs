use super::polygon::*;
use super::segment::*;
use super::*;
use crate::math::Vec2;

fn v(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

#[test]
fn segments_cross_touch_and_miss() {
    assert!(intersect_segment_segment(v(0., 0.), v(1., 1.), v(0., 1.), v(1., 0.)));
    // T-junction touch counts (closed sets).
    assert!(intersect_segment_segment(v(0., 0.), v(1., 0.), v(0.5, 0.), v(0.5, 1.)));
    // Collinear overlap and collinear disjoint.
    assert!(intersect_segment_segment(v(0., 0.), v(2., 0.), v(1., 0.), v(3., 0.)));
    assert!(!intersect_segment_segment(v(0., 0.), v(1., 0.), v(2., 0.), v(3., 0.)));
    assert!(!intersect_segment_segment(v(0., 0.), v(1., 1.), v(0., 0.1), v(0.9, 1.0)));
}

#[test]
fn non_convex_polygon_contains() {
    // A "U": the notch at the top middle is outside.
    let u = [v(0., 0.), v(3., 0.), v(3., 3.), v(2., 3.), v(2., 1.), v(1., 1.), v(1., 3.), v(0., 3.)];
    assert!(contains_polygon_point(&u, v(0.5, 2.0)));
    assert!(!contains_polygon_point(&u, v(1.5, 2.0)));
    assert!(contains_polygon_point(&u, v(1.5, 1.0)), "boundary counts");
    assert!(contains_polygon_point(&u, v(3.0, 3.0)), "vertex counts");
    assert!(!is_convex(&u));
    assert!(is_simple(&u));
    let bow = [v(0., 0.), v(1., 1.), v(1., 0.), v(0., 1.)];
    assert!(!is_simple(&bow));
}

#[test]
fn segment_through_notch_misses_u() {
    let u = Shape::Polygon(vec![v(0., 0.), v(3., 0.), v(3., 3.), v(2., 3.), v(2., 1.), v(1., 1.), v(1., 3.), v(0., 3.)]);
    assert!(!u.intersects_segment(v(1.5, 4.0), v(1.5, 1.01)));
    assert!(u.intersects_segment(v(1.5, 4.0), v(1.5, 1.0)));
    // Wholly inside.
    assert!(u.intersects_segment(v(0.2, 0.2), v(0.3, 0.3)));
}

#[test]
fn corner_grazing_segment_is_a_collision() {
    let r = Shape::Rect(Aabb { min: v(0.45, 0.0), max: v(0.55, 0.49) });
    // Passes exactly through the corner (0.55, 0.49).
    assert!(r.intersects_segment(v(0.5, 0.44), v(0.6, 0.54)));
    assert!(!r.intersects_segment(v(0.5, 0.5), v(0.6, 0.6)));
}

#[test]
fn polygon_inside_polygon_and_circle() {
    let big = [v(0., 0.), v(4., 0.), v(4., 4.), v(0., 4.)];
    let small = [v(1., 1.), v(2., 1.), v(2., 2.)];
    assert!(intersect_polygon_polygon(&big, &small));
    let c = Shape::Circle(v(2., 2.), 0.1);
    assert!(c.intersects_polygon(&big, &Aabb::of_points(&big)), "disc wholly inside the robot");
    let far = Shape::Circle(v(6., 2.), 1.0);
    assert!(!far.intersects_polygon(&big, &Aabb::of_points(&big)));
    let touching = Shape::Circle(v(5., 2.), 1.0);
    assert!(touching.intersects_polygon(&big, &Aabb::of_points(&big)));
}

#[test]
fn open_obstacles_allow_touching_but_not_entering() {
    let rect = Shape::Rect(Aabb { min: v(0., 0.), max: v(1., 1.) });
    let tri = Shape::Polygon(vec![v(0., 0.), v(2., 0.), v(0., 2.)]);
    let wall = Shape::Segment(v(0., 0.), v(0., 2.));
    let disc = Shape::Circle(v(0., 0.), 1.0);
    for s in [&rect, &tri] {
        assert!(!s.interior_meets_segment(v(-1., 0.), v(3., 0.)), "along an edge");
        assert!(!s.interior_meets_segment(v(-1., -1.), v(0., 0.)), "ending at a vertex");
        assert!(s.interior_meets_segment(v(-1., 0.5), v(3., 0.5)), "through");
        assert!(s.interior_meets_segment(v(0.2, 0.2), v(0.3, 0.3)), "inside");
        assert!(!s.interior_meets_segment(v(-1., 3.), v(-0.5, 5.)), "far");
    }
    // Touching the hypotenuse of the triangle at one point from outside.
    assert!(!tri.interior_meets_segment(v(1., 1.), v(2., 2.)));
    assert!(tri.interior_meets_segment(v(0.9, 0.9), v(2., 2.)));
    // A non-convex polygon: a chord between two notch vertices runs outside.
    let u = Shape::Polygon(vec![v(0., 0.), v(3., 0.), v(3., 3.), v(2., 3.), v(2., 1.), v(1., 1.), v(1., 3.), v(0., 3.)]);
    assert!(!u.interior_meets_segment(v(1., 3.), v(2., 3.)));
    assert!(!u.interior_meets_segment(v(1., 1.), v(2., 1.)), "along the notch floor");
    assert!(!u.interior_meets_segment(v(0.5, 3.), v(2.5, 3.)), "along the top edges and across the notch mouth");
    assert!(u.interior_meets_segment(v(0.5, 2.9), v(2.5, 2.9)));
    assert!(!wall.interior_meets_segment(v(0., 1.), v(1., 1.)), "touching a wall");
    assert!(wall.interior_meets_segment(v(-1., 1.), v(1., 1.)), "crossing a wall");
    assert!(!disc.interior_meets_segment(v(-1., 1.), v(1., 1.)), "tangent");
    assert!(disc.interior_meets_segment(v(-1., 0.9), v(1., 0.9)));
}

#[test]
fn segment_distance_to_shapes() {
    let rect = Shape::Rect(Aabb { min: v(0., 0.), max: v(1., 1.) });
    assert!((rect.distance_to_segment(v(2., -1.), v(2., 3.), 10.) - 1.0).abs() < 1e-12);
    assert_eq!(rect.distance_to_segment(v(2., -1.), v(2., 3.), 0.5), 0.5, "capped");
    assert_eq!(rect.distance_to_segment(v(0.5, 0.5), v(0.6, 0.6), 1.), 0.0);
    let disc = Shape::Circle(v(0., 0.), 1.0);
    assert!((disc.distance_to_segment(v(-1., 2.), v(1., 2.), 5.) - 1.0).abs() < 1e-12);
}
