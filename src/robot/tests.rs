use super::*;
use crate::geometry::{Aabb, Shape};
use crate::math::PI;

fn ws() -> Workspace {
    // A wall with a 0.06 slot at y = 0.5.
    Workspace::new(
        Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) },
        vec![
            Shape::Rect(Aabb { min: Vec2::new(0.45, 0.0), max: Vec2::new(0.55, 0.47) }),
            Shape::Rect(Aabb { min: Vec2::new(0.45, 0.53), max: Vec2::new(0.55, 1.0) }),
        ],
    )
}

fn bar() -> RigidRobot {
    RigidRobot::new(vec![Vec2::new(-0.1, -0.015), Vec2::new(0.1, -0.015), Vec2::new(0.1, 0.015), Vec2::new(-0.1, 0.015)], None, false)
}

#[test]
fn bar_fits_the_slot_only_when_flat() {
    let w = ws();
    assert_eq!(bar().verdict(&w, &[0.5, 0.5, 0.0]), Verdict::Valid);
    assert_eq!(bar().verdict(&w, &[0.5, 0.5, PI / 2.0]), Verdict::Collision(0));
    // Flat but too high: touches the upper wall's face exactly (closed sets).
    assert_eq!(bar().verdict(&w, &[0.5, 0.515, 0.0]), Verdict::Collision(1));
    assert_eq!(bar().verdict(&w, &[0.5, 0.5149, 0.0]), Verdict::Valid);
    // Rotation by a full turn is the same state.
    assert_eq!(bar().verdict(&w, &[0.5, 0.5, 2.0 * PI]), Verdict::Valid);
}

#[test]
fn reference_point_bounds_unless_body_in_bounds() {
    let w = ws();
    assert_eq!(bar().verdict(&w, &[0.05, 0.2, 0.0]), Verdict::Valid, "body may leave the bounds by default");
    let strict = RigidRobot::new(bar().footprint.clone(), None, true);
    assert_eq!(strict.verdict(&w, &[0.05, 0.2, 0.0]), Verdict::OutOfBounds(0));
    assert_eq!(bar().verdict(&w, &[1.01, 0.2, 0.0]), Verdict::OutOfBounds(0));
}

#[test]
fn point_sweep_catches_a_corner_between_samples() {
    // Dyadic coordinates, so the corner lies exactly on the segment.
    let w = Workspace::new(
        Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) },
        vec![Shape::Rect(Aabb { min: Vec2::new(0.375, 0.0), max: Vec2::new(0.625, 0.5) })],
    );
    let p = PointRobot;
    let (a, b) = ([0.75, 0.375], [0.5, 0.625]);
    assert_eq!(p.verdict(&w, &a), Verdict::Valid);
    assert_eq!(p.verdict(&w, &b), Verdict::Valid);
    assert_eq!(p.sweep_hits(&w, &a, &b), Some(true), "grazes the corner (0.625, 0.5)");
    assert_eq!(p.sweep_hits(&w, &[0.75, 0.376], &[0.5, 0.626]), Some(false));
}
