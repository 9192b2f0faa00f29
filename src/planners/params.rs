use serde_json::{json, Map, Value};

/// The kind of value a parameter takes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamKind {
    /// A real number.
    Real,
    /// An integer.
    Int,
    /// One of a fixed list of names.
    Choice(&'static [&'static str]),
}

/// A parameter, declared as data (OMPL's `declareParam`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamSpec {
    /// Name used in JSON, on the CLI (`--name`, `_` as `-`) and in the page.
    pub name: &'static str,
    /// Label in the page.
    pub label: &'static str,
    /// Kind of value.
    pub kind: ParamKind,
    /// Smallest value (numbers).
    pub min: f64,
    /// Largest value (numbers).
    pub max: f64,
    /// Default (for a choice: the index of the default name).
    pub default: f64,
    /// What it does.
    pub doc: &'static str,
}

impl ParamSpec {
    /// A real parameter.
    pub const fn real(
        name: &'static str,
        label: &'static str,
        min: f64,
        max: f64,
        default: f64,
        doc: &'static str,
    ) -> Self {
        ParamSpec { name, label, kind: ParamKind::Real, min, max, default, doc }
    }
    /// An integer parameter.
    pub const fn int(
        name: &'static str,
        label: &'static str,
        min: f64,
        max: f64,
        default: f64,
        doc: &'static str,
    ) -> Self {
        ParamSpec { name, label, kind: ParamKind::Int, min, max, default, doc }
    }
    /// A choice parameter.
    pub const fn choice(
        name: &'static str,
        label: &'static str,
        options: &'static [&'static str],
        default: usize,
        doc: &'static str,
    ) -> Self {
        ParamSpec { name, label, kind: ParamKind::Choice(options), min: 0.0, max: 0.0, default: default as f64, doc }
    }
    /// The spec as JSON for the page.
    pub fn to_json(&self) -> Value {
        let (kind, options) = match self.kind {
            ParamKind::Real => ("real", Value::Null),
            ParamKind::Int => ("int", Value::Null),
            ParamKind::Choice(o) => ("choice", json!(o)),
        };
        let default = match self.kind {
            ParamKind::Choice(o) => json!(o[self.default as usize]),
            _ => json!(self.default),
        };
        json!({"name": self.name, "label": self.label, "kind": kind, "min": self.min, "max": self.max,
               "default": default, "options": options, "doc": self.doc})
    }
    fn check(&self, v: &Value) -> Result<Value, String> {
        match self.kind {
            ParamKind::Choice(opts) => match v.as_str() {
                Some(s) if opts.contains(&s) => Ok(v.clone()),
                _ => Err(format!("must be one of: {}", opts.join(", "))),
            },
            ParamKind::Real | ParamKind::Int => {
                let x = v.as_f64().ok_or_else(|| "must be a number".to_string())?;
                if self.kind == ParamKind::Int && x.fract() != 0.0 {
                    return Err("must be a whole number".into());
                }
                if !(self.min..=self.max).contains(&x) {
                    return Err(format!("must be between {} and {}", self.min, self.max));
                }
                Ok(json!(x))
            }
        }
    }
}

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
    pub fn from_json(spec: &'static super::PlannerSpec, v: &Value) -> Result<Params, (String, String)> {
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
    pub fn defaults(spec: &'static super::PlannerSpec) -> Params {
        Params { values: Map::new(), planner: Some(spec.name) }
    }
    /// Set one value from text (the CLI): numbers or choice names. Checked like JSON.
    pub fn set_text(&mut self, spec: &'static super::PlannerSpec, name: &str, text: &str) -> Result<(), String> {
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
