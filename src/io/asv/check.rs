//! The course's validity rules on positions, written apart from `robot::AsvRobot`: the turning
//! test of convexity as the course's tester walks the polygon, the shoelace area, parametric
//! (Liang–Barsky) clipping of each broom against each rectangle shrunk by the tolerance.

use super::TOLERANCE as E;
use crate::math::Real;
use crate::scenario::{ObstacleSpec, RobotSpec, Scenario};
use std::f64::consts::PI;

type P = (Real, Real);

fn points(c: &[Real]) -> Vec<P> {
    c.chunks(2).map(|v| (v[0], v[1])).collect()
}

fn dist(a: P, b: P) -> Real {
    (b.0 - a.0).hypot(b.1 - a.1)
}

/// The largest distance any vehicle moves between configurations `a` and `b`.
pub fn max_move(a: &[Real], b: &[Real]) -> Real {
    points(a).into_iter().zip(points(b)).map(|(p, q)| dist(p, q)).fold(0.0, Real::max)
}

/// The course's cost of a path of configurations: the sum over steps of the distances moved by
/// all vehicles.
pub fn path_cost(configs: &[Vec<Real>]) -> Real {
    configs
        .windows(2)
        .map(|w| points(&w[0]).into_iter().zip(points(&w[1])).map(|(p, q)| dist(p, q)).sum::<Real>())
        .sum()
}

/// An angle in `(−π, π]`.
fn normalise(a: Real) -> Real {
    let mut a = a;
    while a <= -PI {
        a += 2.0 * PI;
    }
    while a > PI {
        a -= 2.0 * PI;
    }
    a
}

/// The course's convexity test: walking the closed polygon, every turn has one sign (turns within
/// ±e are straight), no turn is π, and the absolute turns sum to at most 3π.
fn convex(p: &[P]) -> Result<(), String> {
    let n = p.len();
    let heading = |i: usize| {
        let (a, b) = (p[i % n], p[(i + 1) % n]);
        (b.1 - a.1).atan2(b.0 - a.0)
    };
    let (mut sign, mut total) = (0.0, 0.0);
    for i in 0..n {
        let t = normalise(heading(i + 1) - heading(i));
        let vertex = (i + 1) % n + 1;
        if t == PI {
            return Err(format!("the chain turns back on itself at vehicle {vertex}"));
        }
        total += t.abs();
        if total > 3.0 * PI {
            return Err("the polygon crosses itself (its turns add up to more than 3π)".into());
        }
        let s = if t > E {
            1.0
        } else if t < -E {
            -1.0
        } else {
            0.0
        };
        if s * sign < 0.0 {
            return Err(format!("not convex: the turn at vehicle {vertex} ({t:.6} rad) is the other way"));
        }
        if s != 0.0 {
            sign = s;
        }
    }
    Ok(())
}

/// Whether no two non-adjacent edges of the closed polygon meet (for chains that may be concave).
fn simple(p: &[P]) -> bool {
    let n = p.len();
    // The exact orientation sign (robust, not the crate's geometry: this checker stays independent).
    let cross = |o: P, a: P, b: P| {
        let d = robust::orient2d(
            robust::Coord { x: o.0, y: o.1 },
            robust::Coord { x: a.0, y: a.1 },
            robust::Coord { x: b.0, y: b.1 },
        );
        (d > 0.0) as i8 as Real - (d < 0.0) as i8 as Real
    };
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            let (a, b, c, d) = (p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]);
            let (d1, d2, d3, d4) = (cross(c, d, a), cross(c, d, b), cross(a, b, c), cross(a, b, d));
            if d1 * d2 <= 0.0 && d3 * d4 <= 0.0 {
                return false;
            }
        }
    }
    true
}

/// Liang–Barsky: does the segment `a b` meet the closed box `[x0, x1] × [y0, y1]`?
fn clip(a: P, b: P, x0: Real, y0: Real, x1: Real, y1: Real) -> bool {
    if x0 > x1 || y0 > y1 {
        return false;
    }
    let (mut t0, mut t1) = (0.0, 1.0);
    let d = (b.0 - a.0, b.1 - a.1);
    for (p, q) in [(-d.0, a.0 - x0), (d.0, x1 - a.0), (-d.1, a.1 - y0), (d.1, y1 - a.1)] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = Real::max(t0, r);
            } else {
                t1 = Real::min(t1, r);
            }
        }
    }
    t0 <= t1
}

/// The chain's parameters from an ASV scenario.
fn spec(sc: &Scenario) -> Result<(usize, Real, Real, bool), String> {
    match sc.robot {
        RobotSpec::Asv { count, broom, min_area, convex, .. } => Ok((count, broom, min_area, convex)),
        _ => Err(format!("not an ASV scenario (its robot is a {} robot)", sc.robot.kind())),
    }
}

/// Why configuration `c` (`[x1, y1, ..., xn, yn]`) breaks the course's rules in scenario `sc`, if
/// it does: broom lengths, convexity, area, bounds, obstacles (the vehicle-chain course's rules, `docs/sources.md`).
pub fn check_configuration(sc: &Scenario, c: &[Real]) -> Result<(), String> {
    let (n, broom, min_area, is_convex) = spec(sc)?;
    if c.len() != 2 * n {
        return Err(format!("{} numbers, expected {} (x y for {n} vehicles)", c.len(), 2 * n));
    }
    let p = points(c);
    for i in 0..n - 1 {
        let len = dist(p[i], p[i + 1]);
        if len < broom - E || len > broom + E {
            return Err(format!("broom {} (vehicles {} to {}) is {len} long, not {broom}", i + 1, i + 1, i + 2));
        }
    }
    if is_convex {
        convex(&p)?;
    } else if !simple(&p) {
        return Err("the polygon crosses itself".into());
    }
    let area = (0..n).map(|i| p[i].0 * p[(i + 1) % n].1 - p[(i + 1) % n].0 * p[i].1).sum::<Real>().abs() / 2.0;
    if area < min_area - E {
        return Err(format!("the polygon's area {area} is below the minimum {min_area}"));
    }
    let b = sc.bounds;
    for (i, v) in p.iter().enumerate() {
        if v.0 < b[0] - E || v.0 > b[2] + E || v.1 < b[1] - E || v.1 > b[3] + E {
            return Err(format!("vehicle {} at ({}, {}) is out of bounds", i + 1, v.0, v.1));
        }
    }
    let shrink = if sc.touching_allowed { E } else { 0.0 };
    for (k, o) in sc.obstacles.iter().enumerate() {
        for i in 0..n - 1 {
            let hit = match o {
                ObstacleSpec::Rect(r) => {
                    let (x0, x1, y0, y1) = (r[0].min(r[2]), r[0].max(r[2]), r[1].min(r[3]), r[1].max(r[3]));
                    clip(p[i], p[i + 1], x0 + shrink, y0 + shrink, x1 - shrink, y1 - shrink)
                }
                other => {
                    let (a, b) = (p[i], p[i + 1]);
                    crate::problem::shape_of(other)
                        .intersects_segment(crate::math::Vec2::new(a.0, a.1), crate::math::Vec2::new(b.0, b.1))
                }
            };
            if hit {
                return Err(format!("broom {} (vehicles {} to {}) meets obstacle {}", i + 1, i + 1, i + 2, k + 1));
            }
        }
    }
    Ok(())
}

/// Re-check a solution (configurations, initial first) against the course's rules: every
/// configuration valid ([`check_configuration`]), no vehicle moving more than `max_step + e` in a
/// step, the first and last within `e` (largest vehicle distance) of the problem's initial and goal
/// configurations. Errors name the configuration (0-based; line `i + 2` of the file).
pub fn check_solution(sc: &Scenario, configs: &[Vec<Real>]) -> Result<(), String> {
    spec(sc)?;
    let max_step = match sc.robot {
        RobotSpec::Asv { max_step, .. } => max_step,
        _ => unreachable!("spec checked the robot"),
    };
    let (first, last) = match (configs.first(), configs.last()) {
        (Some(f), Some(l)) => (f, l),
        _ => return Err("the solution has no configurations".into()),
    };
    for (i, c) in configs.iter().enumerate() {
        check_configuration(sc, c).map_err(|e| format!("configuration {i} (line {}): {e}", i + 2))?;
    }
    let d = max_move(first, &sc.start);
    if d > E {
        return Err(format!("the first configuration is {d} from the initial one (more than {E})"));
    }
    let goal = sc.goal.as_ref().ok_or("the scenario has no goal")?;
    let d = max_move(last, goal);
    if d > E {
        return Err(format!("the last configuration is {d} from the goal (more than {E})"));
    }
    for (i, w) in configs.windows(2).enumerate() {
        let d = max_move(&w[0], &w[1]);
        if d > max_step + E {
            return Err(format!(
                "step {} (configurations {i} to {}) moves a vehicle {d}, more than {max_step}",
                i + 1,
                i + 1
            ));
        }
    }
    Ok(())
}
