//! map_server's YAML: a bounded reader of its flat `key: value` form (`image`, `resolution`,
//! `origin`, `negate`, `occupied_thresh`, `free_thresh`, `mode`); errors name line, column and key.

use super::MapMeta;
use crate::limits;
use crate::math::Real;
use crate::scenario::ScenarioError;

/// Bytes of a map's YAML (they are a few lines).
pub const MAX_YAML_BYTES: usize = 64 * 1024;

struct YamlErr<'a> {
    file: &'a str,
}

impl YamlErr<'_> {
    fn at(&self, line: usize, column: usize, key: &str, message: impl std::fmt::Display) -> ScenarioError {
        let key = limits::cut(key, 40);
        let message = format!("{}: {key}: {message}", limits::cut(self.file, 100));
        ScenarioError::new(key, message, Some(line), Some(column))
    }
}

/// Strip a `#` comment that is not inside quotes.
fn strip_comment(line: &str) -> &str {
    let mut quote: Option<char> = None;
    for (i, c) in line.char_indices() {
        match (quote, c) {
            (None, '#') if i == 0 || line[..i].ends_with([' ', '\t']) => return &line[..i],
            (None, '"' | '\'') => quote = Some(c),
            (Some(q), c) if c == q => quote = None,
            _ => {}
        }
    }
    line
}

fn unquote(v: &str) -> &str {
    let b = v.as_bytes();
    if b.len() >= 2 && (b[0] == b'"' || b[0] == b'\'') && b[b.len() - 1] == b[0] {
        &v[1..v.len() - 1]
    } else {
        v
    }
}

/// Read map_server's YAML: flat `key: value` lines, `#` comments, `origin: [x, y, yaw]`. Errors
/// name the line, the column and the key. Unknown keys are refused (they are almost always typos).
pub fn parse_yaml(text: &str, file: &str) -> Result<MapMeta, ScenarioError> {
    let e = YamlErr { file };
    if text.len() > MAX_YAML_BYTES {
        return Err(e.at(1, 1, "document", format!("the YAML is {} bytes; the limit is {MAX_YAML_BYTES}", text.len())));
    }
    const KEYS: [&str; 7] = ["image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode"];
    let mut seen: Vec<&str> = Vec::new();
    let mut meta = MapMeta::plain("");
    let mut image = None;
    let mut resolution = None;
    for (n, raw) in text.lines().enumerate() {
        let line_no = n + 1;
        let line = strip_comment(raw);
        if line.trim().is_empty() || line.trim() == "---" {
            continue;
        }
        let indent = line.len() - line.trim_start().len();
        let col = |byte: usize| raw[..byte.min(raw.len())].chars().count() + 1;
        let Some(colon) = line.find(':') else {
            return Err(e.at(line_no, col(indent), line.trim(), "expected `key: value`"));
        };
        let key = line[..colon].trim();
        let key = unquote(key);
        let after = &line[colon + 1..];
        let vstart = colon + 1 + (after.len() - after.trim_start().len());
        let value = after.trim();
        let vcol = col(vstart);
        let Some(&k) = KEYS.iter().find(|k| **k == key) else {
            return Err(e.at(
                line_no,
                col(indent),
                key,
                format!("unknown key in a map_server YAML (known keys: {})", KEYS.join(", ")),
            ));
        };
        if seen.contains(&k) {
            return Err(e.at(line_no, col(indent), k, "appears twice"));
        }
        seen.push(k);
        if value.is_empty() {
            return Err(e.at(line_no, vcol, k, "has no value"));
        }
        let num = |s: &str, c: usize| -> Result<Real, ScenarioError> {
            s.trim()
                .parse::<Real>()
                .ok()
                .filter(|x| x.is_finite() && x.abs() <= limits::MAX_MAGNITUDE)
                .ok_or_else(|| e.at(line_no, c, k, format!("\"{}\" is not a number", limits::cut(s.trim(), 40))))
        };
        match k {
            "image" => image = Some(unquote(value).to_string()),
            "resolution" => {
                let r = num(value, vcol)?;
                if r < limits::MIN_MAGNITUDE {
                    return Err(e.at(line_no, vcol, k, "must be positive"));
                }
                resolution = Some(r);
            }
            "origin" => {
                let inner = value
                    .strip_prefix('[')
                    .and_then(|v| v.strip_suffix(']'))
                    .ok_or_else(|| e.at(line_no, vcol, k, "must be a list [x, y, yaw]"))?;
                let mut xs = Vec::new();
                let mut off = vcol + 1;
                for part in inner.split(',') {
                    let lead = part.len() - part.trim_start().len();
                    xs.push(num(part, off + lead)?);
                    off += part.chars().count() + 1;
                    if xs.len() > 3 {
                        break;
                    }
                }
                if xs.len() != 3 && xs.len() != 2 {
                    return Err(e.at(line_no, vcol, k, format!("must be [x, y, yaw], found {} numbers", xs.len())));
                }
                if xs.len() == 3 && xs[2] != 0.0 {
                    return Err(e.at(
                        line_no,
                        vcol,
                        k,
                        format!("a yaw of {} is not supported: Planarium reads maps whose yaw is 0", xs[2]),
                    ));
                }
                meta.origin = [xs[0], xs[1]];
            }
            "negate" => {
                meta.negate = match unquote(value) {
                    "0" | "false" | "False" => false,
                    "1" | "true" | "True" => true,
                    other => {
                        return Err(e.at(line_no, vcol, k, format!("\"{}\" is not 0 or 1", limits::cut(other, 40))))
                    }
                }
            }
            "occupied_thresh" | "free_thresh" => {
                let t = num(value, vcol)?;
                if !(0.0..=1.0).contains(&t) {
                    return Err(e.at(line_no, vcol, k, format!("{t} is not between 0 and 1")));
                }
                if k == "free_thresh" {
                    meta.free_thresh = t;
                } else {
                    meta.occupied_thresh = t;
                }
            }
            _ => {
                let m = unquote(value);
                if !["trinary", "scale", "raw"].contains(&m) {
                    return Err(e.at(
                        line_no,
                        vcol,
                        k,
                        format!("\"{}\" is not a mode (trinary, scale or raw)", limits::cut(m, 40)),
                    ));
                }
                meta.mode = m.to_string();
            }
        }
    }
    let end = (text.lines().count().max(1), 1);
    meta.image = image.ok_or_else(|| e.at(end.0, end.1, "image", "is missing (the image file's name)"))?;
    meta.resolution = resolution.ok_or_else(|| e.at(end.0, end.1, "resolution", "is missing (metres per pixel)"))?;
    if meta.free_thresh > meta.occupied_thresh {
        return Err(e.at(end.0, end.1, "free_thresh", "is above occupied_thresh"));
    }
    Ok(meta)
}
