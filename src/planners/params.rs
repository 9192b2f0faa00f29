//! Parameter values, checked against a planner's declarations ([`ParamSpec`]s: its own, its
//! groups', the run's).

use super::PlannerSpec;
use crate::params::{ParamKind, ParamSpec, ParamValues};
use serde_json::{json, Map, Value};

/// Parameter values, checked against a planner's specs (its own, its groups', the run's).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Params {
    values: Map<String, Value>,
    /// The planner the values were checked for (its defaults apply); none: the first declaration.
    planner: Option<&'static str>,
}

impl Params {
    /// Check a JSON object of parameters against `spec`'s and the run loop's parameters. Unknown
    /// names and bad values are errors `(name, message)`.
    pub fn from_json(spec: &'static PlannerSpec, v: &Value) -> Result<Params, (String, String)> {
        let map = v.as_object().ok_or_else(|| (String::new(), "parameters must be an object".to_string()))?;
        let mut values = Map::new();
        for (k, val) in map {
            let ps = spec.param(k).ok_or_else(|| {
                let mut known: Vec<&str> = spec.all_params().map(|p| p.name).collect();
                known.dedup();
                (
                    crate::limits::cut(k, 100),
                    format!("unknown parameter of {} (known: {})", spec.name, known.join(", ")),
                )
            })?;
            values.insert(k.clone(), ps.check(val).map_err(|m| (k.clone(), m))?);
        }
        Ok(Params { values, planner: Some(spec.name) })
    }
    /// No values set, for `spec` (its defaults apply).
    pub fn defaults(spec: &'static PlannerSpec) -> Params {
        Params { values: Map::new(), planner: Some(spec.name) }
    }
    /// Set one value from text (the CLI): numbers or choice names. Checked like JSON.
    pub fn set_text(&mut self, spec: &'static PlannerSpec, name: &str, text: &str) -> Result<(), String> {
        let v = text.parse::<f64>().map(|x| json!(x)).unwrap_or_else(|_| json!(text));
        let mut m = self.values.clone();
        m.insert(name.to_string(), v);
        *self = Params::from_json(spec, &Value::Object(m)).map_err(|(k, e)| format!("{k}: {e}"))?;
        Ok(())
    }
    fn lookup(&self, name: &str) -> (Option<&Value>, &'static ParamSpec) {
        let spec = self.planner.and_then(super::find).and_then(|p| p.param(name));
        (self.values.get(name), spec.unwrap_or_else(|| find_spec(name)))
    }
    /// A number parameter (its default when unset).
    pub fn real(&self, name: &str) -> f64 {
        let (v, s) = self.lookup(name);
        v.and_then(Value::as_f64).unwrap_or(s.default)
    }
    /// A choice parameter's name (its default when unset).
    pub fn choice(&self, name: &str) -> &str {
        let (v, s) = self.lookup(name);
        match (v.and_then(Value::as_str), s.kind) {
            (Some(x), _) => x,
            (None, ParamKind::Choice(o)) => o[s.default as usize],
            _ => "",
        }
    }
    /// The values set explicitly.
    pub fn values(&self) -> &Map<String, Value> {
        &self.values
    }
}

/// The spec of a parameter name, searched over every planner and the run parameters.
fn find_spec(name: &str) -> &'static ParamSpec {
    super::REGISTRY
        .iter()
        .flat_map(|p| p.all_params())
        .find(|p| p.name == name)
        .unwrap_or_else(|| panic!("parameter {name} is not declared by any planner"))
}

impl ParamValues for Params {
    fn real(&self, name: &str) -> f64 {
        Params::real(self, name)
    }
    fn choice(&self, name: &str) -> &str {
        Params::choice(self, name)
    }
}

/// What is wrong with the conditions of a planner's parameters `all` (its own, its groups', the
/// run's, in lookup order): each must name a parameter in `all` (the first of that name, as a run
/// reads it) of the right kind, a choice only with values it has.
pub fn condition_problems(all: &[&'static ParamSpec]) -> Vec<String> {
    use crate::params::Condition;
    let mut out = Vec::new();
    for p in all {
        let Some(c) = p.applies else { continue };
        let Some(on) = all.iter().find(|q| q.name == c.param()) else {
            out.push(format!("{}: applies under {}, which is not a parameter here", p.name, c.param()));
            continue;
        };
        match (c, on.kind) {
            (Condition::OneOf(_, these), ParamKind::Choice(opts)) => {
                if these.is_empty() {
                    out.push(format!("{}: applies under no value of {}", p.name, on.name));
                }
                for v in these.iter().filter(|v| !opts.contains(v)) {
                    out.push(format!("{}: {} has no value {v} (it has {})", p.name, on.name, opts.join(", ")));
                }
            }
            (Condition::Positive(_), ParamKind::Real | ParamKind::Int) => {}
            _ => out.push(format!("{}: its condition does not fit {}'s kind", p.name, on.name)),
        }
        if on.name == p.name {
            out.push(format!("{}: applies under itself", p.name));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planners::{find, REGISTRY};

    #[test]
    fn every_condition_names_a_choice_of_the_same_planner_and_its_values() {
        let mut conditions = 0;
        for p in REGISTRY {
            let all: Vec<&'static ParamSpec> = p.all_params().collect();
            assert_eq!(condition_problems(&all), Vec::<String>::new(), "{}", p.name);
            conditions += all.iter().filter(|s| s.applies.is_some()).count();
        }
        assert!(conditions >= 20, "{conditions} conditions");
        // The checker itself: a value the choice lacks, a parameter the planner lacks, a kind.
        let connect = find("rrt-connect").unwrap();
        let range = *connect.param("range").unwrap();
        let epsilon = *connect.param("epsilon").unwrap();
        let conn: &'static ParamSpec = connect.param("connect").unwrap();
        let bad: &'static [ParamSpec] = Box::leak(Box::new([
            range.only_when("connect", &["rang"]),
            range.only_when("sampler", &["uniform"]),
            range.only_when_positive("connect"),
            epsilon.only_when("epsilon", &["x"]),
        ]));
        let mut all: Vec<&'static ParamSpec> = bad.iter().collect();
        all.push(conn);
        let problems = condition_problems(&all);
        assert_eq!(problems.len(), 5, "{problems:?}");
        assert!(problems[0].contains("no value rang"), "{problems:?}");
        assert!(problems[1].contains("not a parameter here"), "{problems:?}");
        assert!(problems[2].contains("kind"), "{problems:?}");
    }

    #[test]
    fn rrt_connect_range_and_epsilon_apply_by_connect_and_ladder_too() {
        let spec = find("rrt-connect").unwrap();
        let applies = |json: Value, name: &str| {
            let v = Params::from_json(spec, &json).unwrap();
            spec.param(name).unwrap().applies_with(&v)
        };
        assert!(applies(json!({}), "range"));
        assert!(!applies(json!({}), "epsilon"));
        assert!(applies(json!({}), "ladder"));
        assert!(!applies(json!({"connect": "last-free"}), "range"));
        assert!(applies(json!({"connect": "last-free"}), "epsilon"));
        assert!(!applies(json!({"connect": "last-free"}), "ladder"));
        // RRT has no connect: its ladder always applies; the sampler's sigma follows the sampler.
        let rrt = find("rrt").unwrap();
        let v = Params::from_json(rrt, &json!({"sampler": "bridge"})).unwrap();
        assert!(rrt.param("ladder").unwrap().applies_with(&v));
        assert!(rrt.param("sigma").unwrap().applies_with(&v));
        assert!(!rrt.param("collision_sigma").unwrap().applies_with(&v));
        assert!(!rrt.param("sigma").unwrap().applies_with(&Params::defaults(rrt)));
        assert!(!rrt.param("dd_adaptive").unwrap().applies_with(&Params::defaults(rrt)));
        let v = Params::from_json(rrt, &json!({"dd_radius": 0.1})).unwrap();
        assert!(rrt.param("dd_adaptive").unwrap().applies_with(&v));
    }

    #[test]
    fn the_registry_json_carries_each_condition() {
        let reg: Value = serde_json::from_str(&crate::planners::registry_json()).unwrap();
        let connect = reg.as_array().unwrap().iter().find(|p| p["name"] == "rrt-connect").unwrap();
        let own = |n: &str| connect["params"].as_array().unwrap().iter().find(|p| p["name"] == n).unwrap().clone();
        assert_eq!(own("range")["applies"], json!({"param": "connect", "one_of": ["range"]}));
        assert_eq!(own("epsilon")["applies"], json!({"param": "connect", "one_of": ["last-free"]}));
        assert_eq!(own("connect")["applies"], Value::Null);
        let tree = connect["groups"].as_array().unwrap().iter().find(|g| g["name"] == "tree").unwrap();
        let ladder = tree["params"].as_array().unwrap().iter().find(|p| p["name"] == "ladder").unwrap();
        assert_eq!(ladder["applies"], json!({"param": "connect", "one_of": ["range"]}));
        let dd = tree["params"].as_array().unwrap().iter().find(|p| p["name"] == "dd_min_radius").unwrap();
        assert_eq!(dd["applies"], json!({"param": "dd_radius", "above": 0}));
    }
}
