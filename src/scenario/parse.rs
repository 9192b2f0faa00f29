//! From JSON text to a validated [`Scenario`], with the JSON path of every error.

use super::types::*;
use super::ScenarioError;
use crate::geometry::polygon::is_simple;
use crate::limits;
use crate::math::{Real, Vec2};
use serde_json::{Map, Value};

type Result<T> = std::result::Result<T, ScenarioError>;

/// An object being read: remembers its path and which keys were used, so leftovers are errors.
pub(super) struct Obj<'a> {
    pub(super) path: String,
    pub(super) map: &'a Map<String, Value>,
    used: Vec<&'static str>,
}

pub(crate) fn join(path: &str, key: &str) -> String {
    let key = key_name(key);
    if path.is_empty() {
        key
    } else {
        format!("{path}.{key}")
    }
}

/// A key as an error's path names it: itself, or `""` for the empty key (so the path is never
/// empty: an empty path means the whole document).
pub(crate) fn key_name(key: &str) -> String {
    if key.is_empty() {
        "\"\"".to_string()
    } else {
        key.to_string()
    }
}

pub(super) fn describe(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

impl<'a> Obj<'a> {
    pub(super) fn new(path: &str, v: &'a Value) -> Result<Self> {
        match v {
            Value::Object(map) => Ok(Obj { path: path.to_string(), map, used: Vec::new() }),
            // The document itself: it starts at line 1, column 1.
            other if path.is_empty() => {
                Err(ScenarioError::document(format!("must be an object, found {}", describe(other))))
            }
            other => Err(ScenarioError::at(path, format!("must be an object, found {}", describe(other)))),
        }
    }
    pub(super) fn get(&mut self, key: &'static str) -> Option<(&'a Value, String)> {
        self.used.push(key);
        self.map.get(key).map(|v| (v, join(&self.path, key)))
    }
    /// A required key; when it is missing, the error's path is where it belongs (`robot.kind`).
    pub(super) fn req(&mut self, key: &'static str) -> Result<(&'a Value, String)> {
        let path = join(&self.path, key);
        self.get(key).ok_or_else(|| ScenarioError::at(path, "is missing (a required key)"))
    }
    /// Every key not read is an unknown key: almost always a typo.
    pub(super) fn finish(self) -> Result<()> {
        for k in self.map.keys() {
            if !self.used.iter().any(|u| u == k) {
                let mut known: Vec<&str> = self.used.clone();
                crate::math::sort_short(&mut known);
                return Err(ScenarioError::at(
                    join(&self.path, &limits::cut(k, 100)),
                    format!("unknown key (known keys here: {})", known.join(", ")),
                ));
            }
        }
        Ok(())
    }
}

/// A finite number within [`limits::MAX_MAGNITUDE`], and 0 or at least [`limits::MIN_MAGNITUDE`].
pub(super) fn number(v: &Value, path: &str) -> Result<Real> {
    match v.as_f64() {
        Some(x) if x != 0.0 && x.abs() < limits::MIN_MAGNITUDE => Err(ScenarioError::at(
            path,
            format!("{x:e} is too small: numbers other than 0 must be at least 1e-100 in size"),
        )),
        Some(x) if x.is_finite() && x.abs() <= limits::MAX_MAGNITUDE => Ok(x),
        Some(x) => Err(ScenarioError::at(path, format!("{x:e} is too large: numbers must lie between -1e9 and 1e9"))),
        None => Err(ScenarioError::at(path, format!("must be a number, found {}", describe(v)))),
    }
}

/// An array of at most `max` items (`what` names them in the error).
pub(super) fn array<'a>(v: &'a Value, path: &str, expected: &str, max: usize, what: &str) -> Result<&'a Vec<Value>> {
    let arr =
        v.as_array().ok_or_else(|| ScenarioError::at(path, format!("must be {expected}, found {}", describe(v))))?;
    if arr.len() > max {
        return Err(ScenarioError::at(path, format!("has {} {what}; the limit is {max}", arr.len())));
    }
    Ok(arr)
}

/// Numbers in a state or a list: a state has at most a few hundred (64 vehicles' positions).
const MAX_NUMBERS: usize = 1_000;

pub(super) fn numbers(v: &Value, path: &str) -> Result<Vec<Real>> {
    let arr = array(v, path, "an array of numbers", MAX_NUMBERS, "numbers")?;
    arr.iter().enumerate().map(|(i, x)| number(x, &format!("{path}[{i}]"))).collect()
}

pub(super) fn fixed<const N: usize>(v: &Value, path: &str, what: &str) -> Result<[Real; N]> {
    let xs = numbers(v, path)?;
    xs.try_into().map_err(|xs: Vec<Real>| {
        ScenarioError::at(path, format!("must be {what} ({N} numbers), found {} numbers", xs.len()))
    })
}

fn points(v: &Value, path: &str, max: usize) -> Result<Vec<[Real; 2]>> {
    let arr = array(v, path, "an array of [x, y] points", max, "points")?;
    arr.iter().enumerate().map(|(i, p)| fixed::<2>(p, &format!("{path}[{i}]"), "a point [x, y]")).collect()
}

pub(super) fn string(v: &Value, path: &str) -> Result<String> {
    v.as_str()
        .map(str::to_string)
        .ok_or_else(|| ScenarioError::at(path, format!("must be a string, found {}", describe(v))))
}

/// A string of at most `max` characters.
pub(super) fn text(v: &Value, path: &str, max: usize) -> Result<String> {
    let s = string(v, path)?;
    let n = s.chars().count();
    if n > max {
        return Err(ScenarioError::at(path, format!("has {n} characters; the limit is {max}")));
    }
    Ok(s)
}

pub(super) fn boolean(v: &Value, path: &str) -> Result<bool> {
    v.as_bool().ok_or_else(|| ScenarioError::at(path, format!("must be true or false, found {}", describe(v))))
}

fn polygon_check(pts: &[[Real; 2]], path: &str) -> Result<()> {
    if pts.len() < 3 {
        return Err(ScenarioError::at(path, format!("needs at least 3 points, found {}", pts.len())));
    }
    let poly: Vec<Vec2> = pts.iter().map(|p| Vec2::new(p[0], p[1])).collect();
    if !is_simple(&poly) {
        return Err(ScenarioError::at(
            path,
            "must be a simple polygon (its edges cross, fold back, or repeat a point)",
        ));
    }
    Ok(())
}

fn obstacle(v: &Value, path: &str) -> Result<ObstacleSpec> {
    let mut o = Obj::new(path, v)?;
    if o.map.len() != 1 {
        return Err(ScenarioError::at(path, "must have exactly one key: rect, polygon, circle or segment"));
    }
    let spec = if let Some((v, p)) = o.get("rect") {
        let r = fixed::<4>(v, &p, "[x0, y0, x1, y1]")?;
        if r[0] == r[2] || r[1] == r[3] {
            return Err(ScenarioError::at(p, "has zero width or height (use a segment for a wall)"));
        }
        ObstacleSpec::Rect(r)
    } else if let Some((v, p)) = o.get("polygon") {
        let pts = points(v, &p, limits::MAX_POLYGON_VERTICES)?;
        polygon_check(&pts, &p)?;
        ObstacleSpec::Polygon(pts)
    } else if let Some((v, p)) = o.get("circle") {
        let c = fixed::<3>(v, &p, "[cx, cy, r]")?;
        if c[2] <= 0.0 {
            return Err(ScenarioError::at(format!("{p}[2]"), "radius must be positive"));
        }
        ObstacleSpec::Circle(c)
    } else if let Some((v, p)) = o.get("segment") {
        let s = fixed::<4>(v, &p, "[x0, y0, x1, y1]")?;
        if s[0] == s[2] && s[1] == s[3] {
            return Err(ScenarioError::at(p, "has zero length"));
        }
        ObstacleSpec::Segment(s)
    } else {
        let k = o.map.keys().next().map(|k| limits::cut(k, 100)).unwrap_or_default();
        return Err(ScenarioError::at(join(path, &k), "unknown obstacle kind (use rect, polygon, circle or segment)"));
    };
    o.finish()?;
    Ok(spec)
}

fn robot(v: &Value, path: &str) -> Result<RobotSpec> {
    let mut o = Obj::new(path, v)?;
    let (kv, kp) = o.req("kind")?;
    let kind = string(kv, &kp)?;
    let spec = match kind.as_str() {
        "point" => RobotSpec::Point,
        "rigid" => {
            let (fv, fp) = o.req("footprint")?;
            let footprint = points(fv, &fp, limits::MAX_POLYGON_VERTICES)?;
            polygon_check(&footprint, &fp)?;
            let rotation_weight = match o.get("rotation_weight") {
                Some((v, p)) => {
                    let w = number(v, &p)?;
                    if w <= 0.0 {
                        return Err(ScenarioError::at(p, "must be positive"));
                    }
                    Some(w)
                }
                None => None,
            };
            RobotSpec::Rigid { footprint, rotation_weight }
        }
        "arm" => arm(&mut o)?,
        "asv" => asv(&mut o)?,
        "spatial-arm" => super::parse3d::spatial_arm(&mut o)?,
        other => {
            return Err(ScenarioError::at(
                kp,
                format!(
                    "unknown robot kind \"{}\" (use point, rigid, arm, asv or spatial-arm)",
                    limits::cut(other, 100)
                ),
            ))
        }
    };
    o.finish()?;
    Ok(spec)
}

fn positive(o: &mut Obj, key: &'static str, default: Option<Real>) -> Result<Real> {
    match o.get(key) {
        Some((v, p)) => {
            let x = number(v, &p)?;
            if x <= 0.0 {
                return Err(ScenarioError::at(p, "must be positive"));
            }
            Ok(x)
        }
        None => default.ok_or_else(|| ScenarioError::at(join(&o.path, key), "is missing (a required key)")),
    }
}

fn arm(o: &mut Obj) -> Result<RobotSpec> {
    let base = match o.get("base") {
        Some((v, p)) => fixed::<2>(v, &p, "a point [x, y]")?,
        None => [0.0, 0.0],
    };
    let (lv, lp) = o.req("links")?;
    let links = numbers(lv, &lp)?;
    if links.len() > limits::MAX_LINKS {
        return Err(ScenarioError::at(lp, format!("has {} links; the limit is {}", links.len(), limits::MAX_LINKS)));
    }
    if links.is_empty() {
        return Err(ScenarioError::at(lp, "needs at least one link"));
    }
    if let Some(i) = links.iter().position(|l| *l <= 0.0) {
        return Err(ScenarioError::at(format!("{lp}[{i}]"), "a link length must be positive"));
    }
    let n = links.len();
    let limits = match o.get("limits") {
        None => vec![None; n],
        Some((Value::Null, _)) => vec![None; n],
        Some((v, p)) => {
            let arr = v
                .as_array()
                .ok_or_else(|| ScenarioError::at(&p, "must be an array of [lo, hi] or null per joint, or null"))?;
            if arr.len() != n {
                return Err(ScenarioError::at(&p, format!("needs one entry per joint ({n}), found {}", arr.len())));
            }
            arr.iter()
                .enumerate()
                .map(|(i, x)| {
                    let path = format!("{p}[{i}]");
                    if x.is_null() {
                        return Ok(None);
                    }
                    let [lo, hi] = fixed::<2>(x, &path, "[lo, hi] or null")?;
                    if lo >= hi || hi - lo > 2.0 * std::f64::consts::PI {
                        return Err(ScenarioError::at(path, "needs lo < hi, at most 2π apart"));
                    }
                    Ok(Some([lo, hi]))
                })
                .collect::<Result<Vec<_>>>()?
        }
    };
    let self_collision = match o.get("self_collision") {
        Some((v, p)) => boolean(v, &p)?,
        None => true,
    };
    let metric = match o.get("metric") {
        Some((v, p)) => {
            let m = string(v, &p)?;
            if !["joint", "chain", "max", "fk"].contains(&m.as_str()) {
                return Err(ScenarioError::at(p, "must be joint, chain, max or fk"));
            }
            m
        }
        None => "chain".to_string(),
    };
    let tip = match o.get("tip") {
        Some((v, p)) => {
            let t = number(v, &p)?;
            if t < 0.0 {
                return Err(ScenarioError::at(p, "must be 0 or more"));
            }
            t
        }
        None => 0.0,
    };
    Ok(RobotSpec::Arm { base, links, limits, self_collision, metric, tip })
}

fn asv(o: &mut Obj) -> Result<RobotSpec> {
    let (cv, cp) = o.req("count")?;
    let count =
        cv.as_u64().filter(|c| *c >= 2).ok_or_else(|| ScenarioError::at(&cp, "must be a whole number, 2 or more"))?;
    if count > limits::MAX_VEHICLES as u64 {
        return Err(ScenarioError::at(&cp, format!("{count} vehicles; the limit is {}", limits::MAX_VEHICLES)));
    }
    let count = count as usize;
    let broom = positive(o, "broom", Some(0.05))?;
    let min_area = match o.get("min_area") {
        Some((v, p)) => {
            let a = number(v, &p)?;
            if a < 0.0 {
                return Err(ScenarioError::at(p, "must be 0 or more"));
            }
            a
        }
        None => std::f64::consts::PI * (0.007 * (count as Real - 1.0)).powi(2),
    };
    let convex = match o.get("convex") {
        Some((v, p)) => boolean(v, &p)?,
        None => true,
    };
    let max_step = positive(o, "max_step", Some(0.001))?;
    Ok(RobotSpec::Asv { count, broom, min_area, convex, max_step })
}

fn inspection(v: &Value, path: &str) -> Result<Inspection> {
    let mut o = Obj::new(path, v)?;
    let (pv, pp) = o.req("points")?;
    let points = points(pv, &pp, limits::MAX_INSPECTION_POINTS)?;
    let mut num = |key: &'static str, default: Real| -> Result<Real> {
        match o.get(key) {
            Some((v, p)) => number(v, &p),
            None => Ok(default),
        }
    };
    let fov = num("fov", std::f64::consts::FRAC_PI_3)?;
    let range = num("range", 60.0)?;
    let coverage = num("coverage", 0.5)?;
    if !(0.0..=1.0).contains(&coverage) {
        return Err(ScenarioError::at(join(path, "coverage"), "must be between 0 and 1"));
    }
    let coverage_mode = match o.get("coverage_mode") {
        Some((v, p)) => {
            let m = string(v, &p)?;
            if !["continuous", "vertices"].contains(&m.as_str()) {
                return Err(ScenarioError::at(p, "must be continuous or vertices"));
            }
            m
        }
        None => "continuous".to_string(),
    };
    let touch_hides = match o.get("touch_hides") {
        Some((v, p)) => boolean(v, &p)?,
        None => false,
    };
    o.finish()?;
    Ok(Inspection { points, fov, range, coverage, coverage_mode, touch_hides })
}

fn planner(v: &Value, path: &str) -> Result<PlannerDefaults> {
    let map =
        v.as_object().ok_or_else(|| ScenarioError::at(path, format!("must be an object, found {}", describe(v))))?;
    let name = string(
        map.get("name").ok_or_else(|| ScenarioError::at(join(path, "name"), "is missing (a required key)"))?,
        &join(path, "name"),
    )?;
    let seed = match map.get("seed") {
        Some(s) => {
            Some(s.as_u64().ok_or_else(|| ScenarioError::at(join(path, "seed"), "must be a non-negative integer"))?)
        }
        None => None,
    };
    let mut params = map.clone();
    params.remove("name");
    params.remove("seed");
    // What only the registry knows (the planner, its parameters) is checked above the planners,
    // when the scenario becomes a problem ([`crate::problem::Problem::from_scenario`]).
    Ok(PlannerDefaults { name, seed, params })
}

impl Scenario {
    /// Parse and validate a scenario document. Syntax errors carry their line and column; every
    /// other error names its JSON path. (Start and goal validity, and the planner block's planner
    /// and parameters, are checked when the scenario becomes a
    /// [`Problem`](crate::problem::Problem).)
    pub fn from_json(text: &str) -> Result<Scenario> {
        if let Some(why) = limits::text_too_large(text) {
            return Err(ScenarioError::document(why));
        }
        let value: Value = serde_json::from_str(text).map_err(|e| ScenarioError::syntax(&e))?;
        Scenario::from_value(&value)
    }

    /// Validate an already parsed JSON value.
    pub fn from_value(v: &Value) -> Result<Scenario> {
        let mut o = Obj::new("", v)?;
        if let Some((f, p)) = o.get("format") {
            let f = string(f, &p)?;
            if f != FORMAT {
                return Err(ScenarioError::at(
                    p,
                    format!("unsupported format \"{}\" (this version reads \"{FORMAT}\")", limits::cut(&f, 100)),
                ));
            }
        }
        let name = match o.get("name") {
            Some((v, p)) => text(v, &p, limits::MAX_NAME_CHARS)?,
            None => "Untitled".to_string(),
        };
        let notes = match o.get("notes") {
            Some((v, p)) => text(v, &p, limits::MAX_NOTES_CHARS)?,
            None => String::new(),
        };
        let (bv, bp) = o.req("bounds")?;
        let bounds = fixed::<4>(bv, &bp, "[xmin, ymin, xmax, ymax]")?;
        if bounds[0] >= bounds[2] || bounds[1] >= bounds[3] {
            return Err(ScenarioError::at(bp, "needs xmin < xmax and ymin < ymax"));
        }
        let obstacles = match o.get("obstacles") {
            Some((v, p)) => {
                let arr = array(v, &p, "an array", limits::MAX_OBSTACLES, "obstacles")?;
                let mut vertices = 0;
                let mut out = Vec::with_capacity(arr.len());
                for (i, x) in arr.iter().enumerate() {
                    let path = format!("{p}[{i}]");
                    let o = obstacle(x, &path)?;
                    vertices += match &o {
                        ObstacleSpec::Polygon(pts) => pts.len(),
                        _ => 4,
                    };
                    if vertices > limits::MAX_TOTAL_VERTICES {
                        return Err(ScenarioError::at(
                            path,
                            format!(
                                "the obstacles up to here have {vertices} vertices (a rect counts 4); the limit is {}",
                                limits::MAX_TOTAL_VERTICES
                            ),
                        ));
                    }
                    out.push(o);
                }
                out
            }
            None => Vec::new(),
        };
        let (rv, rp) = o.req("robot")?;
        let robot = robot(rv, &rp)?;
        let obstacles3d = match o.get("obstacles3d") {
            Some((v, p)) => super::parse3d::solids(v, &p)?,
            None => Vec::new(),
        };
        super::parse3d::check_dimension(&robot, &obstacles, &obstacles3d)?;
        let (sv, sp) = o.req("start")?;
        let start = numbers(sv, &sp)?;
        let goal = match o.get("goal") {
            Some((v, p)) => Some(numbers(v, &p)?),
            None => None,
        };
        let goal_tolerance = match o.get("goal_tolerance") {
            Some((v, p)) => {
                let t = number(v, &p)?;
                if t < 0.0 {
                    return Err(ScenarioError::at(p, "must be 0 or more"));
                }
                t
            }
            None => 0.0,
        };
        let extent = (bounds[2] - bounds[0]).max(bounds[3] - bounds[1]);
        let resolution = match o.get("resolution") {
            Some((v, p)) => {
                let r = number(v, &p)?;
                if r <= 0.0 {
                    return Err(ScenarioError::at(p, "must be positive"));
                }
                r
            }
            None => extent * 0.002,
        };
        let body_in_bounds = match o.get("body_in_bounds") {
            Some((v, p)) => boolean(v, &p)?,
            None => false,
        };
        let touching_allowed = match o.get("touching_allowed") {
            Some((v, p)) => boolean(v, &p)?,
            None => false,
        };
        let inspection = match o.get("inspection") {
            Some((v, p)) => Some(inspection(v, &p)?),
            None => None,
        };
        if goal.is_none() && inspection.is_none() {
            return Err(ScenarioError::at("goal", "is missing (only an inspection task may omit it)"));
        }
        let planner = match o.get("planner") {
            Some((v, p)) => Some(planner(v, &p)?),
            None => None,
        };
        let map = match o.get("map") {
            Some((v, p)) => Some(map_grid(v, &p)?),
            None => None,
        };
        o.finish()?;
        Ok(Scenario {
            format: FORMAT.to_string(),
            name,
            notes,
            bounds,
            obstacles,
            obstacles3d,
            robot,
            start,
            goal,
            goal_tolerance,
            resolution,
            body_in_bounds,
            touching_allowed,
            inspection,
            planner,
            map,
        })
    }
}

/// The optional `map` block: `{"resolution": r, "origin": [x, y]}`.
fn map_grid(v: &Value, path: &str) -> Result<MapGrid> {
    let mut o = Obj::new(path, v)?;
    let (rv, rp) = o.req("resolution")?;
    let resolution = number(rv, &rp)?;
    if resolution <= 0.0 {
        return Err(ScenarioError::at(rp, "must be positive"));
    }
    let (ov, op) = o.req("origin")?;
    let origin = fixed::<2>(ov, &op, "a point [x, y]")?;
    o.finish()?;
    Ok(MapGrid { resolution, origin })
}
