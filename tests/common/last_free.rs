//! What a last-free run (report 001's course connect) tested, rebuilt from its events and trees:
//! shared by tests/course_connect.rs and tests/spatial_arm.rs.

use planarium::events::{EventKind, STRIDE};
use planarium::run::Session;

/// The steps (lengths along the line) at which rl's `Rrt::connect` tests configurations on a line
/// of length `d` in steps of `delta`, up to the one of length `end` (`d` when it reaches the
/// target): its running sum, re-done here.
pub fn steps(end: f64, d: f64, delta: f64) -> Vec<f64> {
    let mut step = if d <= delta { d } else { delta };
    let mut out = vec![step];
    while step < end {
        step += delta;
        if step >= d {
            step = d;
        }
        out.push(step);
    }
    assert_eq!(step, end, "the stop is one of the line's steps");
    out
}

/// Every configuration a last-free run tested and kept as part of an edge, rebuilt from its events
/// and trees: a connect's `Steer` gives where it stopped and the line's length, a `Collision` that
/// the stop collided, and its `NodeAdded` the edge; the edge's configurations are the line's steps
/// up to the last free one, which is the node (so the k-th is the fraction `s_k / s_last` of the
/// way from the parent to the node).
pub fn kept_configurations(s: &Session, events: &[f64]) -> Vec<Vec<f64>> {
    let data = s.planner_data();
    let delta = s.problem().si.resolution;
    let (mut pending, mut out) = (None, Vec::new());
    for r in events.chunks(STRIDE) {
        match r[0] as u8 {
            k if k == EventKind::Nearest as u8 => pending = None,
            k if k == EventKind::Steer as u8 => pending = Some((r[8], r[9], false)),
            k if k == EventKind::Collision as u8 => {
                if let Some(p) = &mut pending {
                    p.2 = true;
                }
            }
            k if k == EventKind::NodeAdded as u8 => {
                let (end, d, collided) = pending.take().expect("a NodeAdded follows a Steer");
                let tree = &data.trees[r[1] as usize];
                let (p, n) = (tree.state(r[3] as u32), tree.state(r[2] as u32));
                let all = steps(end, d, delta);
                let kept = &all[..all.len() - collided as usize];
                let last = *kept.last().unwrap();
                out.extend(kept.iter().map(|sk| super::spatial::lerp(p, n, sk / last)));
            }
            _ => {}
        }
    }
    out
}
