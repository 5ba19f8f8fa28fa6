//! The profile file: CSV `x,z`, read with errors that name the line,
//! written so that it reads back to the same bits.

use std::io::{self, Read, Write};
use std::path::Path;

use super::error::{ParseProblem, ProfileError, Whole};
use super::polyline::{PointCheck, Profile};

impl Profile {
    /// Reads a profile file (see the module docs for the format). Errors
    /// name the path.
    pub fn read_csv(path: impl AsRef<Path>) -> Result<Profile, ProfileError> {
        let path = path.as_ref();
        let name = path.display().to_string();
        match std::fs::read(path) {
            Ok(bytes) => parse_csv(&bytes, &name),
            Err(e) => Err(file_error(&name, &e)),
        }
    }

    /// Reads a profile in the file format from `reader`; errors name it
    /// `name` (a path, or what the caller calls the source).
    pub fn from_csv_reader(mut reader: impl Read, name: &str) -> Result<Profile, ProfileError> {
        let mut bytes = Vec::new();
        reader
            .read_to_end(&mut bytes)
            .map_err(|e| file_error(name, &e))?;
        parse_csv(&bytes, name)
    }

    /// Writes the profile in the file format: the header, then one point a
    /// line, each number in the shortest form that reads back to the same
    /// bits (`-0.0` included).
    pub fn write_csv(&self, writer: impl Write) -> io::Result<()> {
        let mut out = io::BufWriter::new(writer);
        out.write_all(b"x,z\n")?;
        for (x, z) in self.points() {
            writeln!(out, "{x:?},{z:?}")?;
        }
        out.flush()
    }
}

fn file_error(name: &str, e: &io::Error) -> ProfileError {
    ProfileError::File {
        file: name.to_owned(),
        kind: e.kind(),
        message: e.to_string(),
    }
}

/// A field or line for an error message: its first 40 characters.
fn excerpt(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    let mut chars = text.chars();
    let head: String = chars.by_ref().take(40).collect();
    if chars.next().is_some() {
        head + "…"
    } else {
        head
    }
}

/// Whether `line` is the header `x,z`.
fn is_header(line: &[u8]) -> bool {
    let mut fields = line.split(|&b| b == b',').map(<[u8]>::trim_ascii);
    matches!(
        (fields.next(), fields.next(), fields.next()),
        (Some(x), Some(z), None) if x.eq_ignore_ascii_case(b"x") && z.eq_ignore_ascii_case(b"z")
    )
}

/// A field as a number.
#[inline]
fn number(field: &[u8], column: &'static str) -> Result<f64, ParseProblem> {
    let field = field.trim_ascii();
    std::str::from_utf8(field)
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .ok_or_else(|| ParseProblem::NotANumber {
            column,
            text: excerpt(field),
        })
}

/// A point line, `x,z`.
#[inline]
fn point(line: &[u8]) -> Result<(f64, f64), ParseProblem> {
    let Some(comma) = line.iter().position(|&b| b == b',') else {
        return Err(ParseProblem::FieldCount(1));
    };
    let (fx, fz) = (&line[..comma], &line[comma + 1..]);
    let more = fz.iter().filter(|&&b| b == b',').count();
    if more > 0 {
        return Err(ParseProblem::FieldCount(2 + more));
    }
    Ok((number(fx, "x")?, number(fz, "z")?))
}

/// The reader proper: one pass over the lines, each point checked as it
/// comes.
fn parse_csv(bytes: &[u8], name: &str) -> Result<Profile, ProfileError> {
    let error = |line, problem| ProfileError::Parse {
        file: name.to_owned(),
        line,
        problem,
    };
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    // About 20 bytes a point on a long course.
    let capacity = bytes.len() / 16;
    let (mut x, mut z) = (Vec::with_capacity(capacity), Vec::with_capacity(capacity));
    let mut check = PointCheck::default();
    let mut header = false;
    // The last line with any text (a comment counts), and the last record.
    let (mut last_text, mut last_record) = (1, 1);
    for (i, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let line_no = i + 1;
        let line = raw.trim_ascii();
        if line.is_empty() {
            continue;
        }
        last_text = line_no;
        if line[0] == b'#' {
            continue;
        }
        last_record = line_no;
        if !header {
            if !is_header(line) {
                let problem = if point(line).is_ok() {
                    ParseProblem::MissingHeader(excerpt(line))
                } else {
                    ParseProblem::WrongHeader(excerpt(line))
                };
                return Err(error(line_no, problem));
            }
            header = true;
            continue;
        }
        let (px, pz) = point(line).map_err(|p| error(line_no, p))?;
        check
            .next(px, pz)
            .map_err(|p| error(line_no, ParseProblem::Point(p)))?;
        x.push(px);
        z.push(pz);
    }
    if !header {
        return Err(error(last_text, ParseProblem::Empty));
    }
    Profile::from_checked(x, z).map_err(|whole| {
        let problem = match whole {
            Whole::TooFew(n) => ParseProblem::TooFewPoints(n),
            Whole::NoLength(x) => ParseProblem::NoLength(x),
            Whole::TooMany(_) => ParseProblem::TooManyPoints,
        };
        error(last_record, problem)
    })
}
