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
    /// An error at `path` (a JSON path, or a file's name) and, for a text's errors, a line and a
    /// column. The path and the message are [`echo`](crate::limits::echo)ed: user text in them
    /// (keys, values, words) shows its control and bidirectional characters as `[U+202E]`, so the
    /// message cannot be turned around. Every constructor goes through this.
    pub fn new(
        path: impl Into<String>,
        message: impl Into<String>,
        line: Option<usize>,
        column: Option<usize>,
    ) -> Self {
        let (path, message) = (path.into(), message.into());
        ScenarioError { path: crate::limits::echo(&path), message: crate::limits::echo(&message), line, column }
    }
    /// A JSON syntax error, with its line and column.
    pub fn syntax(e: &serde_json::Error) -> Self {
        ScenarioError::new(String::new(), format!("invalid JSON: {e}"), Some(e.line()), Some(e.column()))
    }
    /// An error about the document as a whole (not an object, too large): at line 1, column 1.
    pub fn document(message: impl Into<String>) -> Self {
        ScenarioError::new(String::new(), message, Some(1), Some(1))
    }
    /// An error at a JSON path.
    pub fn at(path: impl Into<String>, message: impl Into<String>) -> Self {
        ScenarioError::new(path, message, None, None)
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
