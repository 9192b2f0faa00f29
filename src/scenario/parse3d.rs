//! The 3-D keys of the contract: the `spatial-arm` robot block and `obstacles3d`, each error naming
//! its JSON path, every size bounded ([`limits`]).

use super::parse::{array, fixed, number, string, text, Obj};
use super::types::*;
use super::ScenarioError;
use crate::limits;
use crate::math::Real;
use serde_json::Value;

type Result<T> = std::result::Result<T, ScenarioError>;

/// Names of links, boxes and obstacles: short labels for explanations.
const MAX_LABEL_CHARS: usize = 100;

/// The largest joint limit in size, radians (two turns either way).
const MAX_JOINT_ANGLE: Real = 4.0 * std::f64::consts::PI;

/// Link pairs listed in `ignore` (every pair of 13 links).
const MAX_IGNORED_PAIRS: usize = 78;

fn point3(v: &Value, path: &str) -> Result<[Real; 3]> {
    fixed::<3>(v, path, "a point [x, y, z]")
}

/// Points of a convex hull: 4 to [`limits::MAX_HULL_POINTS`], not all in one plane.
pub(super) fn hull(v: &Value, path: &str) -> Result<Vec<[Real; 3]>> {
    let arr = array(v, path, "an array of [x, y, z] points", limits::MAX_HULL_POINTS, "points")?;
    let pts = arr.iter().enumerate().map(|(i, p)| point3(p, &format!("{path}[{i}]"))).collect::<Result<Vec<_>>>()?;
    if pts.len() < 4 {
        return Err(ScenarioError::at(path, format!("needs at least 4 points, found {}", pts.len())));
    }
    if is_flat(&pts) {
        return Err(ScenarioError::at(path, "its points lie in one plane (a hull needs volume)"));
    }
    crate::geometry::solid::Solid::hull("", &pts).map_err(|e| ScenarioError::at(path, e))?;
    Ok(pts)
}

/// Whether the points span less than three dimensions (relative to their extent).
fn is_flat(pts: &[[Real; 3]]) -> bool {
    let sub = |a: &[Real; 3], b: &[Real; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dot = |a: &[Real; 3], b: &[Real; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cross = |a: &[Real; 3], b: &[Real; 3]| {
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    };
    let p0 = pts[0];
    let far = |f: &dyn Fn(&[Real; 3]) -> Real| {
        pts.iter().copied().max_by(|a, b| f(a).total_cmp(&f(b))).expect("at least 4 points")
    };
    let p1 = far(&|p| dot(&sub(p, &p0), &sub(p, &p0)));
    let e1 = sub(&p1, &p0);
    let p2 = far(&|p| {
        let c = cross(&e1, &sub(p, &p0));
        dot(&c, &c)
    });
    let n = cross(&e1, &sub(&p2, &p0));
    let p3 = far(&|p| dot(&n, &sub(p, &p0)).abs());
    let volume = dot(&n, &sub(&p3, &p0)).abs();
    let extent = dot(&e1, &e1).sqrt();
    // NaN (no extent) counts as flat too.
    volume.partial_cmp(&(1e-12 * extent * extent * extent)) != Some(std::cmp::Ordering::Greater)
}

fn label(o: &mut Obj, default: String) -> Result<String> {
    match o.get("name") {
        Some((v, p)) => text(v, &p, MAX_LABEL_CHARS),
        None => Ok(default),
    }
}

/// `{"center": [x, y, z], "size": [sx, sy, sz]}`, each size positive.
fn center_size(o: &mut Obj) -> Result<([Real; 3], [Real; 3])> {
    let (cv, cp) = o.req("center")?;
    let center = point3(cv, &cp)?;
    let (sv, sp) = o.req("size")?;
    let size = fixed::<3>(sv, &sp, "a size [sx, sy, sz]")?;
    if let Some(i) = size.iter().position(|s| *s <= 0.0) {
        return Err(ScenarioError::at(format!("{sp}[{i}]"), "a box's size must be positive"));
    }
    Ok((center, size))
}

fn box_spec(v: &Value, path: &str) -> Result<BoxSpec> {
    let mut o = Obj::new(path, v)?;
    let name = label(&mut o, String::new())?;
    let (center, size) = center_size(&mut o)?;
    o.finish()?;
    Ok(BoxSpec { name, center, size })
}

/// The `obstacles3d` list.
pub(super) fn solids(v: &Value, path: &str) -> Result<Vec<SolidSpec>> {
    let arr = array(v, path, "an array", limits::MAX_SOLIDS, "obstacles")?;
    let mut total = 0;
    let mut out = Vec::with_capacity(arr.len());
    for (i, x) in arr.iter().enumerate() {
        let p = format!("{path}[{i}]");
        let mut o = Obj::new(&p, x)?;
        let name = label(&mut o, String::new())?;
        let shape = if let Some((bv, bp)) = o.get("box") {
            let mut b = Obj::new(&bp, bv)?;
            let (center, size) = center_size(&mut b)?;
            b.finish()?;
            SolidShape::Box { center, size }
        } else if let Some((hv, hp)) = o.get("hull") {
            let pts = hull(hv, &hp)?;
            total += pts.len();
            if total > limits::MAX_TOTAL_HULL_POINTS {
                return Err(ScenarioError::at(
                    hp,
                    format!("the hulls up to here have {total} points; the limit is {}", limits::MAX_TOTAL_HULL_POINTS),
                ));
            }
            SolidShape::Hull(pts)
        } else {
            return Err(ScenarioError::at(p, "needs a box or a hull"));
        };
        if o.map.contains_key("box") && o.map.contains_key("hull") {
            return Err(ScenarioError::at(p, "has both a box and a hull (one shape per obstacle)"));
        }
        o.finish()?;
        out.push(SolidSpec { name, shape });
    }
    Ok(out)
}

/// A whole number below `n` (an index into `n` links).
fn index(v: &Value, path: &str, n: usize, what: &str) -> Result<usize> {
    v.as_u64()
        .filter(|i| *i < n as u64)
        .map(|i| i as usize)
        .ok_or_else(|| ScenarioError::at(path, format!("must be {what}: a whole number from 0 to {}", n - 1)))
}

fn pose(v: &Value, path: &str) -> Result<PoseSpec> {
    let mut o = Obj::new(path, v)?;
    let translation = match o.get("translation") {
        Some((v, p)) => point3(v, &p)?,
        None => [0.0; 3],
    };
    let rotation = match o.get("rotation") {
        Some((v, p)) => fixed::<3>(v, &p, "angles [rx, ry, rz] in radians")?,
        None => [0.0; 3],
    };
    o.finish()?;
    Ok(PoseSpec { translation, rotation })
}

fn joint(v: &Value, path: &str) -> Result<DhJoint> {
    let mut o = Obj::new(path, v)?;
    let mut num = |key: &'static str| -> Result<Real> {
        match o.get(key) {
            Some((v, p)) => number(v, &p),
            None => Ok(0.0),
        }
    };
    let (d, theta, a, alpha) = (num("d")?, num("theta")?, num("a")?, num("alpha")?);
    let (lv, lp) = o.req("limits")?;
    let [lo, hi] = fixed::<2>(lv, &lp, "[lo, hi] in radians")?;
    if lo >= hi {
        return Err(ScenarioError::at(lp, "needs lo < hi"));
    }
    if lo.abs() > MAX_JOINT_ANGLE || hi.abs() > MAX_JOINT_ANGLE {
        return Err(ScenarioError::at(lp, "must lie within ±4π (two turns)"));
    }
    o.finish()?;
    Ok(DhJoint { d, theta, a, alpha, limits: [lo, hi] })
}

fn link(v: &Value, path: &str, k: usize) -> Result<LinkSpec> {
    let mut o = Obj::new(path, v)?;
    let name = label(&mut o, format!("link{k}"))?;
    let hull = match o.get("hull") {
        Some((v, p)) => hull(v, &p)?,
        None => Vec::new(),
    };
    let boxes = match o.get("boxes") {
        Some((v, p)) => array(v, &p, "an array of boxes", limits::MAX_LINK_BOXES, "boxes")?
            .iter()
            .enumerate()
            .map(|(i, b)| box_spec(b, &format!("{p}[{i}]")))
            .collect::<Result<Vec<_>>>()?,
        None => Vec::new(),
    };
    o.finish()?;
    Ok(LinkSpec { name, hull, boxes })
}

/// The `spatial-arm` robot block's keys (after `kind`).
pub(super) fn spatial_arm(o: &mut Obj) -> Result<RobotSpec> {
    let base = match o.get("base") {
        Some((v, p)) => pose(v, &p)?,
        None => PoseSpec::default(),
    };
    let (jv, jp) = o.req("joints")?;
    let rows = array(jv, &jp, "an array of joints", limits::MAX_SPATIAL_JOINTS, "joints")?;
    if rows.is_empty() {
        return Err(ScenarioError::at(jp, "needs at least one joint"));
    }
    let joints = rows.iter().enumerate().map(|(i, j)| joint(j, &format!("{jp}[{i}]"))).collect::<Result<Vec<_>>>()?;
    let n = joints.len() + 1;
    let (lv, lp) = o.req("links")?;
    let arr = array(lv, &lp, "an array of links", limits::MAX_SPATIAL_JOINTS + 1, "links")?;
    if arr.len() != n {
        return Err(ScenarioError::at(lp, format!("needs one link per joint and the base ({n}), found {}", arr.len())));
    }
    let links = arr.iter().enumerate().map(|(k, l)| link(l, &format!("{lp}[{k}]"), k)).collect::<Result<Vec<_>>>()?;
    let mut ignore = Vec::new();
    if let Some((v, p)) = o.get("ignore") {
        for (i, pair) in array(v, &p, "an array of link pairs [i, j]", MAX_IGNORED_PAIRS, "pairs")?.iter().enumerate() {
            let pp = format!("{p}[{i}]");
            let ends = array(pair, &pp, "a link pair [i, j]", 2, "numbers")?;
            if ends.len() != 2 {
                return Err(ScenarioError::at(pp, "must be a link pair [i, j]"));
            }
            let (a, b) = (
                index(&ends[0], &format!("{pp}[0]"), n, "a link")?,
                index(&ends[1], &format!("{pp}[1]"), n, "a link")?,
            );
            if a == b {
                return Err(ScenarioError::at(pp, "pairs two different links"));
            }
            let pair = [a.min(b), a.max(b)];
            if !ignore.contains(&pair) {
                ignore.push(pair);
            }
        }
        crate::math::sort_short(&mut ignore);
    }
    let mut exempt = Vec::new();
    if let Some((v, p)) = o.get("exempt") {
        for (i, x) in array(v, &p, "an array of links", n, "links")?.iter().enumerate() {
            let k = index(x, &format!("{p}[{i}]"), n, "a link")?;
            if !exempt.contains(&k) {
                exempt.push(k);
            }
        }
        crate::math::sort_short(&mut exempt);
    }
    let tool = match o.get("tool") {
        Some((v, p)) => point3(v, &p)?,
        None => [0.0; 3],
    };
    let metric = match o.get("metric") {
        Some((v, p)) => {
            let m = string(v, &p)?;
            if m != "joint" {
                return Err(ScenarioError::at(p, "must be joint (Euclidean over the joint angles, radians)"));
            }
            m
        }
        None => "joint".to_string(),
    };
    Ok(RobotSpec::SpatialArm(Box::new(SpatialArmSpec { base, joints, links, ignore, exempt, tool, metric })))
}

/// A spatial arm's scene is `obstacles3d`; a planar robot's is `obstacles`. A scenario that mixes
/// them would have part of its scene silently ignored, so it is refused.
pub(super) fn check_dimension(robot: &RobotSpec, obstacles: &[ObstacleSpec], solids: &[SolidSpec]) -> Result<()> {
    let spatial = matches!(robot, RobotSpec::SpatialArm(_));
    if spatial && !obstacles.is_empty() {
        return Err(ScenarioError::at("obstacles", "a spatial arm moves in 3-D: give its scene as obstacles3d"));
    }
    if !spatial && !solids.is_empty() {
        return Err(ScenarioError::at(
            "obstacles3d",
            format!("only a spatial-arm robot moves in 3-D; this one is a {} robot", robot.kind()),
        ));
    }
    Ok(())
}
