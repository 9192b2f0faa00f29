//! Parameters declared as data (OMPL's `declareParam`): a [`ParamSpec`] per parameter, named
//! [`ParamGroup`]s of them shared by several planners, and [`ParamValues`], the read side of a
//! run's values.
//!
//! Declaring is separate from the planners, so a component below them (the sampler, whose
//! parameters every sampling planner takes) declares its parameters and reads their values
//! without knowing the registry. The values themselves, checked against a planner's declarations,
//! are [`planners::Params`](crate::planners::Params).

use serde_json::{json, Value};

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
    /// When it applies (none: always). A parameter that does not apply is read by nothing in that
    /// set-up: the page hides it, the CLI's help says when it applies and a run that sets it
    /// anyway notes so.
    pub applies: Option<Condition>,
}

/// The set-up under which a parameter applies: another parameter of the same planner (its own, a
/// group's, or the run's) has one of some values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Condition {
    /// Choice parameter `.0` is one of `.1`.
    OneOf(&'static str, &'static [&'static str]),
    /// Number parameter `.0` is above 0 (a variant that 0 turns off).
    Positive(&'static str),
}

impl Condition {
    /// The parameter it reads.
    pub fn param(&self) -> &'static str {
        match *self {
            Condition::OneOf(p, _) | Condition::Positive(p) => p,
        }
    }
    /// Whether it holds for `values`.
    pub fn holds(&self, values: &dyn ParamValues) -> bool {
        match *self {
            Condition::OneOf(p, these) => these.contains(&values.choice(p)),
            Condition::Positive(p) => values.real(p) > 0.0,
        }
    }
    /// In words, with `flag` writing a parameter's name (`connect`, or `--connect` on the CLI):
    /// "connect range", "dd_radius above 0".
    pub fn describe(&self, flag: impl Fn(&str) -> String) -> String {
        match *self {
            Condition::OneOf(p, these) => format!("{} {}", flag(p), these.join(" or ")),
            Condition::Positive(p) => format!("{} above 0", flag(p)),
        }
    }
    /// As JSON for the page: `{"param", "one_of": [names]}` or `{"param", "above": 0}`.
    pub fn to_json(&self) -> Value {
        match *self {
            Condition::OneOf(p, these) => json!({"param": p, "one_of": these}),
            Condition::Positive(p) => json!({"param": p, "above": 0}),
        }
    }
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
        ParamSpec { name, label, kind: ParamKind::Real, min, max, default, doc, applies: None }
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
        ParamSpec { name, label, kind: ParamKind::Int, min, max, default, doc, applies: None }
    }
    /// A choice parameter.
    pub const fn choice(
        name: &'static str,
        label: &'static str,
        options: &'static [&'static str],
        default: usize,
        doc: &'static str,
    ) -> Self {
        ParamSpec {
            name,
            label,
            kind: ParamKind::Choice(options),
            min: 0.0,
            max: 0.0,
            default: default as f64,
            doc,
            applies: None,
        }
    }
    /// The same parameter, applying only when choice parameter `param` is one of `values`.
    pub const fn only_when(self, param: &'static str, values: &'static [&'static str]) -> Self {
        ParamSpec { applies: Some(Condition::OneOf(param, values)), ..self }
    }
    /// The same parameter, applying only when number parameter `param` is above 0.
    pub const fn only_when_positive(self, param: &'static str) -> Self {
        ParamSpec { applies: Some(Condition::Positive(param)), ..self }
    }
    /// Whether it applies under `values` (a parameter without a condition always does).
    pub fn applies_with(&self, values: &dyn ParamValues) -> bool {
        self.applies.is_none_or(|c| c.holds(values))
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
               "default": default, "options": options, "doc": self.doc,
               "applies": self.applies.map(|c| c.to_json())})
    }
    /// Check a value against the spec: a known name for a choice, a number in range (whole for an
    /// integer) otherwise. The value to keep, or what is wrong with it.
    pub fn check(&self, v: &Value) -> Result<Value, String> {
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

/// A named group of parameters shared by several planners.
#[derive(Clone, Copy, Debug)]
pub struct ParamGroup {
    /// Name (JSON).
    pub name: &'static str,
    /// Title in the page.
    pub label: &'static str,
    /// The parameters.
    pub params: &'static [ParamSpec],
}

/// Parameter values read by name, each its declared default when unset (a planner may change a
/// group's default: the planner's declaration wins).
pub trait ParamValues {
    /// A number parameter (its default when unset).
    fn real(&self, name: &str) -> f64;
    /// A choice parameter's name (its default when unset).
    fn choice(&self, name: &str) -> &str;
}
