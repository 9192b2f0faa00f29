//! Occupancy maps as people have them (issue 17): ROS map_server's form (a PGM or PNG image and its
//! YAML: `image`, `resolution`, `origin`, `negate`, `occupied_thresh`, `free_thresh`, `mode`) and a
//! plain image (dark = occupied), read into an [`OccupancyGrid`] and from there into a scenario;
//! and back: a scenario rasterised at a cell size, written as PGM (P5) + YAML or PNG.
//!
//! **Semantics (map_server's).** A pixel's value `v` of `maxval` gives `p = (maxval − v)/maxval`
//! (`v/maxval` with `negate`; colour pixels are the mean of their channels, alpha is ignored);
//! `p > occupied_thresh` is occupied, `p < free_thresh` free, anything between unknown. Planning
//! treats unknown as occupied. `mode: raw` reads `v` (8-bit) as the occupancy in percent (above 100:
//! unknown). Row 0 of the image is the top: pixel (column c, row r) covers
//! `x ∈ [ox + c·res, ox + (c+1)·res]`, `y ∈ [oy + (h−1−r)·res, oy + (h−r)·res]`. A nonzero yaw in
//! `origin` is refused (the scenario's obstacles are axis-aligned boxes).
//!
//! **A plain image** (no YAML) reads with map_server's defaults (thresholds 0.65 and 0.196, no
//! negate) at [`PLAIN_RESOLUTION`] (0.05, map_server's usual 5 cm) per pixel, origin (0, 0).
//!
//! **To a scenario.** Occupied (and unknown) pixels merge into axis-aligned rectangles (maximal
//! runs along each row, then runs with the same columns on consecutive rows), so the broad phase
//! gets few boxes; the bounds are the image's extent; the robot is a point; start and goal are the
//! free pixels' centres nearest the lower left and upper right corners within the largest
//! 4-connected free region (so the grid planners can always reach one from the other). The optional
//! scenario key `map` (`{"resolution", "origin"}`) remembers the pixel grid, so grid-search's
//! default cell is one pixel, aligned with the image.
//!
//! Every size is checked before anything is allocated ([`MAX_MAP_SIDE`], [`MAX_MAP_PIXELS`], the
//! scenario's obstacle limit); every error names the file and where in it (byte offset, line and
//! column, or key).

use crate::geometry::{Aabb, Shape, Workspace};
use crate::limits;
use crate::math::{Real, Vec2};
use crate::scenario::{Scenario, ScenarioError};
use serde_json::json;

pub use crate::limits::{MAX_MAP_PIXELS, MAX_MAP_SIDE};

/// Metres (scenario units) per pixel of a plain image without a YAML.
pub const PLAIN_RESOLUTION: Real = 0.05;

/// map_server's default thresholds.
pub const OCCUPIED_THRESH: Real = 0.65;
/// map_server's default free threshold.
pub const FREE_THRESH: Real = 0.196;

/// One cell of an occupancy grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Occupancy {
    /// Free.
    Free,
    /// Occupied.
    Occupied,
    /// Neither threshold met (planned as occupied).
    Unknown,
}

/// An occupancy grid: `cells[row * width + col]`, row 0 the top (largest y), as in the image.
#[derive(Clone, Debug, PartialEq)]
pub struct OccupancyGrid {
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// The cells, row 0 the top.
    pub cells: Vec<Occupancy>,
    /// Side of a cell in scenario units.
    pub resolution: Real,
    /// World position of the lower left corner of the lower left cell.
    pub origin: [Real; 2],
}

impl OccupancyGrid {
    /// Whether the cell at (col, row) blocks the robot (occupied or unknown).
    pub fn blocked(&self, col: usize, row: usize) -> bool {
        self.cells[row * self.width + col] != Occupancy::Free
    }
    /// The blocked cells as booleans, row 0 the top.
    pub fn blocked_mask(&self) -> Vec<bool> {
        self.cells.iter().map(|c| *c != Occupancy::Free).collect()
    }
    /// The x of the cell boundary `i` (0 = the left edge).
    fn x(&self, i: usize) -> Real {
        self.origin[0] + i as Real * self.resolution
    }
    /// The y of the cell boundary `j` counted from the bottom (0 = the lower edge).
    fn y(&self, j: usize) -> Real {
        self.origin[1] + j as Real * self.resolution
    }
}

/// A decoded image: grey values `0..=maxval`, row 0 the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// The largest value (255 for 8-bit, up to 65535).
    pub maxval: u16,
    /// Grey values, row-major.
    pub values: Vec<u16>,
}

/// How map_server reads the image (its YAML's keys).
#[derive(Clone, Debug, PartialEq)]
pub struct MapMeta {
    /// The image's file name, relative to the YAML's folder.
    pub image: String,
    /// Scenario units per pixel.
    pub resolution: Real,
    /// The lower left pixel's lower left corner `[x, y]` (yaw 0 only).
    pub origin: [Real; 2],
    /// Light is occupied.
    pub negate: bool,
    /// Above: occupied.
    pub occupied_thresh: Real,
    /// Below: free.
    pub free_thresh: Real,
    /// `trinary` (default), `scale` or `raw`.
    pub mode: String,
}

impl MapMeta {
    /// map_server's defaults, for a plain image.
    pub fn plain(image: &str) -> MapMeta {
        MapMeta {
            image: image.to_string(),
            resolution: PLAIN_RESOLUTION,
            origin: [0.0, 0.0],
            negate: false,
            occupied_thresh: OCCUPIED_THRESH,
            free_thresh: FREE_THRESH,
            mode: "trinary".into(),
        }
    }
}

fn file_err(file: &str, message: impl Into<String>) -> ScenarioError {
    ScenarioError::at(limits::cut(file, 100), message)
}

fn check_size(file: &str, width: u64, height: u64) -> Result<(usize, usize), ScenarioError> {
    if width == 0 || height == 0 {
        return Err(file_err(file, format!("the image is {width}×{height} pixels: it has no pixels")));
    }
    let side = MAX_MAP_SIDE as u64;
    let pixels = width.checked_mul(height);
    if width > side || height > side || pixels.is_none_or(|p| p > MAX_MAP_PIXELS as u64) {
        return Err(file_err(
            file,
            format!(
                "the image is {width}×{height} pixels; the limits are {MAX_MAP_SIDE} pixels a side and {MAX_MAP_PIXELS} pixels in all"
            ),
        ));
    }
    Ok((width as usize, height as usize))
}

/// Which kind of image `bytes` hold, by their magic bytes: `"pgm"`, `"png"` or `None`.
pub fn sniff(bytes: &[u8]) -> Option<&'static str> {
    if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
        Some("png")
    } else if bytes.len() >= 2 && bytes[0] == b'P' && (bytes[1] == b'5' || bytes[1] == b'2') {
        Some("pgm")
    } else {
        None
    }
}

/// Whether a file name or path looks like a map (by its extension): `.pgm`, `.png`, `.yaml`, `.yml`.
pub fn is_map_name(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    [".pgm", ".png", ".yaml", ".yml"].iter().any(|e| lower.ends_with(e))
}

/// Whether a file name is a map's YAML.
pub fn is_yaml_name(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    lower.ends_with(".yaml") || lower.ends_with(".yml")
}

/// Decode a PGM (P5 binary or P2 ASCII) or a PNG image, by its magic bytes.
pub fn decode_image(bytes: &[u8], file: &str) -> Result<Image, ScenarioError> {
    if bytes.len() > limits::MAX_TEXT_BYTES {
        return Err(file_err(
            file,
            format!("the file is {} bytes; the limit is {} bytes (16 MiB)", bytes.len(), limits::MAX_TEXT_BYTES),
        ));
    }
    match sniff(bytes) {
        Some("png") => decode_png(bytes, file),
        Some(_) => decode_pgm(bytes, file),
        None => Err(file_err(
            file,
            "not a map image: a PGM starts with \"P5\" or \"P2\", a PNG with its 8-byte signature (byte 0)",
        )),
    }
}

/// A PGM reader's position in the file.
struct Pgm<'a> {
    bytes: &'a [u8],
    at: usize,
    file: &'a str,
}

impl Pgm<'_> {
    fn err(&self, message: impl std::fmt::Display) -> ScenarioError {
        file_err(self.file, format!("byte {}: {message}", self.at))
    }
    /// Skip whitespace and `#` comments.
    fn skip(&mut self) {
        while let Some(&b) = self.bytes.get(self.at) {
            if b == b'#' {
                while self.bytes.get(self.at).is_some_and(|&c| c != b'\n' && c != b'\r') {
                    self.at += 1;
                }
            } else if b.is_ascii_whitespace() {
                self.at += 1;
            } else {
                break;
            }
        }
    }
    /// A decimal number (at most `max`), `what` naming it in errors.
    fn number(&mut self, what: &str, max: u64) -> Result<u64, ScenarioError> {
        self.skip();
        let from = self.at;
        let mut n: u64 = 0;
        while let Some(&b) = self.bytes.get(self.at).filter(|b| b.is_ascii_digit()) {
            n = n.saturating_mul(10).saturating_add(u64::from(b - b'0'));
            self.at += 1;
        }
        if self.at == from {
            return Err(match self.bytes.get(self.at) {
                None => self.err(format!("the file ends where the {what} should be (truncated)")),
                Some(_) => self.err(format!("expected the {what} (a whole number)")),
            });
        }
        if n > max {
            self.at = from;
            return Err(self.err(format!("the {what} {n} is above {max}")));
        }
        Ok(n)
    }
}

fn decode_pgm(bytes: &[u8], file: &str) -> Result<Image, ScenarioError> {
    let binary = bytes[1] == b'5';
    let mut r = Pgm { bytes, at: 2, file };
    if !r.bytes.get(2).is_some_and(|b| b.is_ascii_whitespace() || *b == b'#') {
        return Err(r.err("bad magic: a PGM starts with \"P5\" or \"P2\" and whitespace"));
    }
    let width = r.number("width", u64::from(u32::MAX))?;
    let height = r.number("height", u64::from(u32::MAX))?;
    let maxval = r.number("maxval", 65535)?;
    if maxval == 0 {
        return Err(r.err("the maxval must be 1 to 65535"));
    }
    let (w, h) = check_size(file, width, height)?;
    let n = w * h; // within MAX_MAP_PIXELS
    let maxval = maxval as u16;
    let mut values = Vec::with_capacity(n);
    if binary {
        // Exactly one whitespace byte ends the header.
        if !r.bytes.get(r.at).is_some_and(u8::is_ascii_whitespace) {
            return Err(r.err("expected one whitespace byte before the pixels"));
        }
        r.at += 1;
        let per = if maxval < 256 { 1 } else { 2 };
        let need = n * per;
        let data = &bytes[r.at..];
        if data.len() < need {
            return Err(
                r.err(format!("truncated: {w}×{h} pixels need {need} bytes of pixels, the file has {}", data.len()))
            );
        }
        for i in 0..n {
            let v = if per == 1 { u16::from(data[i]) } else { u16::from_be_bytes([data[2 * i], data[2 * i + 1]]) };
            if v > maxval {
                r.at += i * per;
                return Err(r.err(format!("pixel {i} is {v}, above the maxval {maxval}")));
            }
            values.push(v);
        }
    } else {
        for i in 0..n {
            let v = r.number(&format!("value of pixel {i}"), u64::from(maxval))?;
            values.push(v as u16);
        }
    }
    Ok(Image { width: w, height: h, maxval, values })
}

fn decode_png(bytes: &[u8], file: &str) -> Result<Image, ScenarioError> {
    let why = |e: png::DecodingError| file_err(file, format!("not a readable PNG: {e}"));
    let mut decoder = png::Decoder::new_with_limits(
        std::io::Cursor::new(bytes),
        png::Limits { bytes: MAX_MAP_PIXELS * 8 + (1 << 20) },
    );
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info().map_err(why)?;
    let (width, height) = reader.info().size();
    let (w, h) = check_size(file, u64::from(width), u64::from(height))?;
    let (color, depth) = reader.output_color_type();
    if depth != png::BitDepth::Eight {
        return Err(file_err(file, "a PNG this reader cannot bring to 8 bits a channel"));
    }
    let channels = color.samples();
    let size = reader.output_buffer_size().ok_or_else(|| file_err(file, "the PNG is too large to decode"))?;
    if size < w * h * channels {
        return Err(file_err(file, "the PNG's decoded size does not match its header"));
    }
    let mut buf = vec![0u8; size];
    let info = reader.next_frame(&mut buf).map_err(why)?;
    let stride = info.line_size;
    if stride < w * channels || stride.checked_mul(h).is_none_or(|n| n > buf.len()) {
        return Err(file_err(file, "the PNG's decoded rows do not match its header"));
    }
    let mut values = Vec::with_capacity(w * h);
    for row in 0..h {
        let line = &buf[row * stride..row * stride + w * channels];
        for px in line.chunks_exact(channels) {
            // Grey (and alpha): the grey; colour (and alpha): the mean of R, G, B, map_server's rule.
            let v = match channels {
                1 | 2 => u16::from(px[0]),
                _ => ((u32::from(px[0]) + u32::from(px[1]) + u32::from(px[2]) + 1) / 3) as u16,
            };
            values.push(v);
        }
    }
    Ok(Image { width: w, height: h, maxval: 255, values })
}

/// The grid map_server makes of `image` with `meta`'s thresholds.
pub fn classify(image: &Image, meta: &MapMeta) -> OccupancyGrid {
    let max = Real::from(image.maxval);
    let cells = image
        .values
        .iter()
        .map(|&v| {
            let v = Real::from(v);
            if meta.mode == "raw" {
                // The value is the occupancy in percent; above 100 unknown.
                if v > 100.0 {
                    return Occupancy::Unknown;
                }
                let p = v / 100.0;
                return if p > meta.occupied_thresh {
                    Occupancy::Occupied
                } else if p < meta.free_thresh {
                    Occupancy::Free
                } else {
                    Occupancy::Unknown
                };
            }
            let p = if meta.negate { v / max } else { (max - v) / max };
            if p > meta.occupied_thresh {
                Occupancy::Occupied
            } else if p < meta.free_thresh {
                Occupancy::Free
            } else {
                Occupancy::Unknown
            }
        })
        .collect();
    OccupancyGrid { width: image.width, height: image.height, cells, resolution: meta.resolution, origin: meta.origin }
}

// ---------------------------------------------------------------------------------------------
// map_server's YAML

/// Bytes of a map's YAML (they are a few lines).
pub const MAX_YAML_BYTES: usize = 64 * 1024;

struct YamlErr<'a> {
    file: &'a str,
}

impl YamlErr<'_> {
    fn at(&self, line: usize, column: usize, key: &str, message: impl std::fmt::Display) -> ScenarioError {
        let key = limits::cut(key, 40);
        ScenarioError {
            path: key.clone(),
            message: format!("{}: {key}: {message}", limits::cut(self.file, 100)),
            line: Some(line),
            column: Some(column),
        }
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

// ---------------------------------------------------------------------------------------------
// Grid → scenario

/// The grid's blocked cells as rectangles `[x0, y0, x1, y1]`: maximal runs along each row, merged
/// with the same run on the rows below. Deterministic (ordered by top row, then column).
pub fn rectangles(grid: &OccupancyGrid) -> Vec<[Real; 4]> {
    use std::collections::BTreeMap;
    // Open runs: (c0, c1) → the top row where they began.
    let mut open: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    let mut out: Vec<(usize, usize, [Real; 4])> = Vec::new();
    let close = |c0: usize, c1: usize, top: usize, bottom: usize, out: &mut Vec<_>| {
        // rows top..=bottom (row 0 the top); y counts boundaries from the bottom.
        let y0 = grid.y(grid.height - 1 - bottom);
        let y1 = grid.y(grid.height - top);
        out.push((top, c0, [grid.x(c0), y0, grid.x(c1), y1]));
    };
    for row in 0..=grid.height {
        let mut runs = Vec::new();
        if row < grid.height {
            let mut c = 0;
            while c < grid.width {
                if grid.blocked(c, row) {
                    let c0 = c;
                    while c < grid.width && grid.blocked(c, row) {
                        c += 1;
                    }
                    runs.push((c0, c));
                } else {
                    c += 1;
                }
            }
        }
        let here: std::collections::BTreeSet<(usize, usize)> = runs.iter().copied().collect();
        let ended: Vec<(usize, usize)> = open.keys().filter(|k| !here.contains(k)).copied().collect();
        for k in ended {
            let top = open.remove(&k).expect("an open run");
            close(k.0, k.1, top, row - 1, &mut out);
        }
        for r in runs {
            open.entry(r).or_insert(row);
        }
    }
    out.sort_by_key(|a| (a.0, a.1));
    out.into_iter().map(|(_, _, r)| r).collect()
}

/// Cells in ring order around (c, r) moving inward by `dir`: the first for which `ok` holds.
fn nearest(grid: &OccupancyGrid, from: (usize, usize), dir: (i64, i64), ok: impl Fn(usize) -> bool) -> Option<usize> {
    let (w, h) = (grid.width as i64, grid.height as i64);
    for d in 0..w.max(h) {
        for i in 0..=d {
            for (a, b) in [(i, d), (d, i)] {
                let (c, r) = (from.0 as i64 + dir.0 * a, from.1 as i64 + dir.1 * b);
                if c >= 0 && r >= 0 && c < w && r < h {
                    let k = (r * w + c) as usize;
                    if ok(k) {
                        return Some(k);
                    }
                }
            }
        }
    }
    None
}

/// The largest 4-connected region of free cells (ties: the first found in row order), as a mask.
fn largest_free_region(grid: &OccupancyGrid) -> Vec<bool> {
    let (w, h) = (grid.width, grid.height);
    let mut label = vec![u32::MAX; w * h];
    let mut best = (0usize, u32::MAX);
    let mut next = 0u32;
    let mut stack = Vec::new();
    for s in 0..w * h {
        if label[s] != u32::MAX || grid.cells[s] != Occupancy::Free {
            continue;
        }
        let mut size = 0;
        label[s] = next;
        stack.push(s);
        while let Some(k) = stack.pop() {
            size += 1;
            let (c, r) = (k % w, k / w);
            let mut visit = |m: usize| {
                if label[m] == u32::MAX && grid.cells[m] == Occupancy::Free {
                    label[m] = next;
                    stack.push(m);
                }
            };
            if c > 0 {
                visit(k - 1);
            }
            if c + 1 < w {
                visit(k + 1);
            }
            if r > 0 {
                visit(k - w);
            }
            if r + 1 < h {
                visit(k + w);
            }
        }
        if size > best.0 {
            best = (size, next);
        }
        next += 1;
    }
    label.iter().map(|&l| l == best.1 && l != u32::MAX).collect()
}

/// The scenario of an occupancy grid; `name` titles it.
pub fn grid_to_scenario(grid: &OccupancyGrid, name: &str) -> Result<Scenario, ScenarioError> {
    let rects = rectangles(grid);
    let max = limits::MAX_OBSTACLES.min(limits::MAX_TOTAL_VERTICES / 4);
    if rects.len() > max {
        return Err(file_err(
            name,
            format!(
                "the map's occupied pixels make {} rectangles; the limit is {max} obstacles (a coarser or simpler map is needed)",
                rects.len()
            ),
        ));
    }
    let region = largest_free_region(grid);
    let centre = |k: usize| {
        let (c, r) = (k % grid.width, k / grid.width);
        let j = grid.height - 1 - r;
        vec![grid.origin[0] + (c as Real + 0.5) * grid.resolution, grid.origin[1] + (j as Real + 0.5) * grid.resolution]
    };
    let free = |k: usize| region[k];
    let start = nearest(grid, (0, grid.height - 1), (1, -1), free)
        .ok_or_else(|| file_err(name, "the map has no free pixel (nothing below free_thresh) to start from"))?;
    let goal = nearest(grid, (grid.width - 1, 0), (-1, 1), free).unwrap_or(start);
    if goal == start {
        return Err(file_err(name, "the map's largest free region is a single pixel: there is nowhere to go"));
    }
    let (w, h) = (grid.width as Real * grid.resolution, grid.height as Real * grid.resolution);
    let bounds = [grid.origin[0], grid.origin[1], grid.x(grid.width), grid.y(grid.height)];
    let unknown = grid.cells.iter().filter(|c| **c == Occupancy::Unknown).count();
    let notes = format!(
        "An occupancy map of {}×{} pixels, {} units a pixel ({w}×{h}): occupied pixels (and the {unknown} unknown ones, which planning treats as occupied) \
         merged into {} rectangles. The point robot starts at the free pixel nearest the lower left corner and goes to the one nearest the upper right, \
         both in the largest connected free region; move them in the editor. Grid search's default cell is one pixel (on maps of at most a million pixels it is the default planner).",
        grid.width,
        grid.height,
        grid.resolution,
        rects.len()
    );
    let obstacles: Vec<_> = rects.iter().map(|r| json!({"rect": r})).collect();
    let v = json!({
        "format": crate::scenario::FORMAT,
        "name": format!("Occupancy map ({})", limits::cut(name, 100)),
        "notes": notes,
        "bounds": bounds,
        "obstacles": obstacles,
        "robot": {"kind": "point"},
        "start": centre(start),
        "goal": centre(goal),
        "resolution": grid.resolution * 0.5,
        "map": {"resolution": grid.resolution, "origin": grid.origin},
        // Grid-search a cell a pixel needs max_nodes ≥ the pixels (at most MAX_NODES).
        "planner": {"name": if (grid.width * grid.height) as f64 <= limits::MAX_NODES { "grid-search" } else { "rrt-connect" }, "seed": 1},
    });
    Scenario::from_value(&v).map_err(|e| file_err(name, e.to_string()))
}

/// Read a map: `bytes` are the image (PGM or PNG) named `name`; `yaml` is its map_server YAML
/// `(text, file name)`, if any (else the image reads as a plain image).
pub fn import_image(bytes: &[u8], name: &str, yaml: Option<(&str, &str)>) -> Result<Scenario, ScenarioError> {
    let meta = match yaml {
        Some((text, file)) => parse_yaml(text, file)?,
        None => MapMeta::plain(name),
    };
    let image = decode_image(bytes, name)?;
    let grid = classify(&image, &meta);
    let title = yaml.map_or(name, |(_, f)| f);
    grid_to_scenario(&grid, title)
}

// ---------------------------------------------------------------------------------------------
// Scenario → grid → files

/// Whether an obstacle meets the interior of the cell `[min, max]`: a rectangle when their open
/// interiors overlap (so a rectangle that only shares a side does not block, and a map's pixels
/// come back exactly); other shapes when they touch the cell at all (the closed test, which is
/// safe for moves between cell centres).
pub fn cell_blocked(ws: &Workspace, min: Vec2, max: Vec2) -> bool {
    let bbox = Aabb { min, max };
    let outline = [min, Vec2::new(max.x, min.y), max, Vec2::new(min.x, max.y)];
    ws.first_hit(&bbox, |i| match &ws.obstacles[i] {
        Shape::Rect(r) => r.min.x < max.x && min.x < r.max.x && r.min.y < max.y && min.y < r.max.y,
        s => s.intersects_polygon(&outline, &bbox),
    })
    .is_some()
}

/// The scenario rasterised at `cell` from its bounds' lower left corner: a cell is occupied when an
/// obstacle meets it ([`cell_blocked`]) or its centre is out of bounds.
pub fn scenario_to_grid(sc: &Scenario, cell: Real) -> Result<OccupancyGrid, ScenarioError> {
    let b = sc.bounds;
    if !(cell.is_finite() && cell >= limits::MIN_MAGNITUDE) {
        return Err(ScenarioError::at("cell", "must be a positive number"));
    }
    let (fx, fy) = (((b[2] - b[0]) / cell).ceil(), ((b[3] - b[1]) / cell).ceil());
    if !(fx.is_finite() && fy.is_finite())
        || fx > MAX_MAP_SIDE as Real
        || fy > MAX_MAP_SIDE as Real
        || fx * fy > MAX_MAP_PIXELS as Real
    {
        return Err(ScenarioError::at(
            "cell",
            format!(
                "{cell} makes a grid of {fx}×{fy} cells; the limits are {MAX_MAP_SIDE} a side and {MAX_MAP_PIXELS} in all"
            ),
        ));
    }
    let (w, h) = ((fx as usize).max(1), (fy as usize).max(1));
    let ws = Workspace::new(
        Aabb { min: Vec2::new(b[0], b[1]), max: Vec2::new(b[2], b[3]) },
        sc.obstacles.iter().map(crate::problem::shape_of).collect(),
    );
    let grid0 = OccupancyGrid { width: w, height: h, cells: Vec::new(), resolution: cell, origin: [b[0], b[1]] };
    let mut cells = Vec::with_capacity(w * h);
    for row in 0..h {
        let j = h - 1 - row;
        for c in 0..w {
            let (min, max) = (Vec2::new(grid0.x(c), grid0.y(j)), Vec2::new(grid0.x(c + 1), grid0.y(j + 1)));
            let centre = (min + max) * 0.5;
            let blocked = !ws.bounds.contains(centre) || cell_blocked(&ws, min, max);
            cells.push(if blocked { Occupancy::Occupied } else { Occupancy::Free });
        }
    }
    Ok(OccupancyGrid { cells, ..grid0 })
}

/// The grid as map_server writes it: a P5 PGM (occupied 0, free 254, unknown 205, as map_saver
/// does) and its YAML naming `image_name`.
pub fn to_pgm_yaml(grid: &OccupancyGrid, image_name: &str) -> (Vec<u8>, String) {
    let mut pgm =
        format!("P5\n# planarium occupancy map, {} per pixel\n{} {}\n255\n", grid.resolution, grid.width, grid.height)
            .into_bytes();
    pgm.extend(grid.cells.iter().map(|c| grey(*c)));
    let yaml = format!(
        "image: {image_name}\nresolution: {}\norigin: [{}, {}, 0.0]\nnegate: 0\noccupied_thresh: {OCCUPIED_THRESH}\nfree_thresh: {FREE_THRESH}\n",
        grid.resolution, grid.origin[0], grid.origin[1]
    );
    (pgm, yaml)
}

fn grey(c: Occupancy) -> u8 {
    match c {
        Occupancy::Free => 254,
        Occupancy::Occupied => 0,
        Occupancy::Unknown => 205,
    }
}

/// The grid as an 8-bit grey PNG (the same values as the PGM).
pub fn to_png(grid: &OccupancyGrid) -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, grid.width as u32, grid.height as u32);
        enc.set_color(png::ColorType::Grayscale);
        enc.set_depth(png::BitDepth::Eight);
        let data: Vec<u8> = grid.cells.iter().map(|c| grey(*c)).collect();
        let mut w = enc.write_header().expect("writing to a Vec does not fail");
        w.write_image_data(&data).expect("the data has the header's size");
    }
    out
}
