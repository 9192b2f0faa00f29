use std::fmt;

/// What is wrong with a scenario, and where.
#[derive(Clone, Debug, PartialEq)]
pub struct ScenarioError {
    /// JSON path of the offending value (`obstacles[3].polygon`), empty for the whole document.
    pub path: String,
    /// What is wrong, in words a student can act on.
    pub message: String,
    /// 1-based line of a syntax error, when known.
    pub line: Option<usize>,
    /// 1-based column of a syntax error, when known.
    pub column: Option<usize>,
}

impl ScenarioError {
    /// A JSON syntax error, with its line and column.
    pub fn syntax(e: &serde_json::Error) -> Self {
        ScenarioError {
            path: String::new(),
            message: format!("invalid JSON: {e}"),
            line: Some(e.line()),
            column: Some(e.column()),
        }
    }
    /// An error about the document as a whole (not an object, too large): at line 1, column 1.
    pub fn document(message: impl Into<String>) -> Self {
        ScenarioError { path: String::new(), message: message.into(), line: Some(1), column: Some(1) }
    }
    /// An error at a JSON path.
    pub fn at(path: impl Into<String>, message: impl Into<String>) -> Self {
        ScenarioError { path: path.into(), message: message.into(), line: None, column: None }
    }
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let (Some(l), Some(c)) = (self.line, self.column) {
            write!(f, "line {l}, column {c}: {}", self.message)
        } else if self.path.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.path, self.message)
        }
    }
}

impl std::error::Error for ScenarioError {}
