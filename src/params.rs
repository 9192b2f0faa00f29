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
