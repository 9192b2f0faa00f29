//! Decoding a map's image: PGM (P5 binary, P2 ASCII, 8 or 16 bit) and PNG (every colour type,
//! by the `png` crate), told apart by their magic bytes; sizes checked before anything is allocated.

use super::{check_size, file_err, Image, MAX_MAP_PIXELS};
use crate::limits;
use crate::scenario::ScenarioError;

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
