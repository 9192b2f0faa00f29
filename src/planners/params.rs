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
