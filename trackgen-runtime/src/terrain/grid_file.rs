//! A height field from a file: the ESRI ASCII grid (`.asc`), the plain
//! raster format GIS tools export a surveyed surface or a digital
//! elevation model as (ESRI, *ArcGIS Help*, "Esri ASCII raster format").
//! Read here rather than by the `esri_ascii_grid` crate because a bad
//! file must be refused naming its line, which that crate's errors do
//! not.
//!
//! ```text
//! ncols        5                 the nodes along x
//! nrows        3                 the nodes along y
//! xllcenter    -10.0             m: the lower-left node (or xllcorner: its cell's corner)
//! yllcenter    -2.0              m (or yllcorner)
//! cellsize     2.0               m, the same along x and y
//! NODATA_value -9999             optional: a missing height (a hole, refused)
//! 0.0 0.0 0.1 0.0 0.0            the row of highest y first, x increasing
//! 0.0 0.0 0.0 0.0 0.0
//! 0.0 0.0 0.0 0.0 0.0            the row of lowest y last
//! ```
//!
//! Heights are in metres, `x` along the course and `y` to its left (the
//! raster's east and north). Each value is the height at its cell's
//! centre, a node of the field's grid, bilinear between nodes
//! ([`Grid`]); a header with `xllcorner` puts the first node half a cell
//! in from that corner. Keys are read in any order and any case, values
//! split by spaces or tabs over as many lines as they take; blank lines
//! and lines starting `#` are skipped.

use std::path::Path;

use thiserror::Error;

use super::field::{FieldError, Grid};

/// The most nodes a grid file may hold: 50 million (400 MB of heights),
/// so that a header cannot ask for more memory than a course needs.
pub const MAX_NODES: usize = 50_000_000;

/// Why a grid file cannot be read.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GridFileError {
    /// The file cannot be read.
    #[error("{file}: {message}")]
    File {
        /// The file's path.
        file: String,
        /// Why.
        message: String,
    },
    /// A line that breaks the format.
    #[error("{file}:{line}: {problem}")]
    Parse {
        /// The file's path.
        file: String,
        /// The line, from 1.
        line: usize,
        /// What is wrong there.
        problem: GridProblem,
    },
    /// The grid the header describes cannot be made.
    #[error("{file}: {source}")]
    Grid {
        /// The file's path.
        file: String,
        /// Why.
        source: FieldError,
    },
}

/// What is wrong on a line of a grid file.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GridProblem {
    /// A header key this reader does not know.
    #[error(
        "`{0}` is no header key (ncols, nrows, xllcenter or xllcorner, yllcenter or yllcorner, cellsize, NODATA_value)"
    )]
    UnknownKey(String),
    /// A header key given twice.
    #[error("`{0}` is given twice")]
    Repeated(String),
    /// A key the header needs, missing (named at the first height).
    #[error("the header has no `{0}`")]
    Missing(&'static str),
    /// A header value or a height that is not a number.
    #[error("{what} is `{text}`, not a number")]
    NotANumber {
        /// What was read.
        what: String,
        /// The text (its first 40 characters).
        text: String,
    },
    /// A count that is not a whole number of 2 or more, or too many
    /// nodes in all.
    #[error(
        "`{key}` is {value}: a whole number of 2 or more is needed (at most {MAX_NODES} nodes in all)"
    )]
    Count {
        /// `ncols` or `nrows`.
        key: &'static str,
        /// What was given.
        value: f64,
    },
    /// A missing height: the no-data value, or not finite.
    #[error("the height at x = {x} m, y = {y} m is {value}: a hole in the field")]
    Hole {
        /// The node's place, m.
        x: f64,
        /// The node's place, m.
        y: f64,
        /// What was given.
        value: f64,
    },
    /// More heights than `ncols × nrows`.
    #[error("more than the {0} heights the header counts")]
    TooMany(usize),
    /// Fewer (named at the last line).
    #[error("{got} heights where the header counts {want}")]
    TooFew {
        /// Heights read.
        got: usize,
        /// `ncols × nrows`.
        want: usize,
    },
}

/// The header's figures as read, each with its line.
#[derive(Default)]
struct Header {
    ncols: Option<f64>,
    nrows: Option<f64>,
    x: Option<(f64, bool)>,
    y: Option<(f64, bool)>,
    cellsize: Option<f64>,
    nodata: Option<f64>,
}

impl Header {
    /// Takes `key value` from `line`; `Ok(false)` where the line is not a
    /// header line (it starts with a number).
    fn take(&mut self, key: &str, value: &str) -> Result<bool, GridProblem> {
        let lower = key.to_ascii_lowercase();
        if lower.parse::<f64>().is_ok() {
            return Ok(false);
        }
        let number = number(value, &lower)?;
        let slot = match lower.as_str() {
            "ncols" => &mut self.ncols,
            "nrows" => &mut self.nrows,
            "cellsize" => &mut self.cellsize,
            "nodata_value" => &mut self.nodata,
            "xllcenter" | "xllcorner" | "yllcenter" | "yllcorner" => {
                let place = if lower.starts_with('x') {
                    &mut self.x
                } else {
                    &mut self.y
                };
                if place.is_some() {
                    return Err(GridProblem::Repeated(key.to_string()));
                }
                *place = Some((number, lower.ends_with("corner")));
                return Ok(true);
            }
            _ => return Err(GridProblem::UnknownKey(key.to_string())),
        };
        if slot.is_some() {
            return Err(GridProblem::Repeated(key.to_string()));
        }
        *slot = Some(number);
        Ok(true)
    }
}

/// `text` as a number, or what it is not.
fn number(text: &str, what: &str) -> Result<f64, GridProblem> {
    text.parse::<f64>().map_err(|_| GridProblem::NotANumber {
        what: what.to_string(),
        text: text.chars().take(40).collect(),
    })
}

/// A node count from the header: a whole number of 2 or more.
fn count(value: Option<f64>, key: &'static str) -> Result<usize, GridProblem> {
    let value = value.ok_or(GridProblem::Missing(key))?;
    if value.fract() == 0.0 && (2.0..=MAX_NODES as f64).contains(&value) {
        Ok(value as usize)
    } else {
        Err(GridProblem::Count { key, value })
    }
}

/// The figures of a grid whose heights are being read: its nodes, its
/// first node's place, its spacing and its no-data value.
struct Layout {
    nx: usize,
    ny: usize,
    origin: (f64, f64),
    cell: f64,
    nodata: Option<f64>,
}

impl Layout {
    fn of(header: &Header) -> Result<Layout, GridProblem> {
        let (nx, ny) = (count(header.ncols, "ncols")?, count(header.nrows, "nrows")?);
        if nx.saturating_mul(ny) > MAX_NODES {
            return Err(GridProblem::Count {
                key: "nrows",
                value: ny as f64,
            });
        }
        let cell = header.cellsize.ok_or(GridProblem::Missing("cellsize"))?;
        let place = |p: Option<(f64, bool)>, key| {
            let (value, corner) = p.ok_or(GridProblem::Missing(key))?;
            Ok::<f64, GridProblem>(if corner { value + 0.5 * cell } else { value })
        };
        Ok(Layout {
            nx,
            ny,
            origin: (
                place(header.x, "xllcenter or xllcorner")?,
                place(header.y, "yllcenter or yllcorner")?,
            ),
            cell,
            nodata: header.nodata,
        })
    }

    /// Where the `k`-th height of the file stands: rows from the highest
    /// `y` down, each along `x`; its index in [`Grid`]'s order and place.
    fn node(&self, k: usize) -> (usize, f64, f64) {
        let (row, i) = (k / self.nx, k % self.nx);
        let j = self.ny - 1 - row;
        let x = self.origin.0 + i as f64 * self.cell;
        let y = self.origin.1 + j as f64 * self.cell;
        (j * self.nx + i, x, y)
    }
}

/// Reads the grid file at `path`; its errors name the path and the line.
pub fn read_grid(path: impl AsRef<Path>) -> Result<Grid, GridFileError> {
    let path = path.as_ref();
    let name = path.display().to_string();
    let text = std::fs::read(path).map_err(|e| GridFileError::File {
        file: name.clone(),
        message: e.to_string(),
    })?;
    parse_grid(&String::from_utf8_lossy(&text), &name)
}

/// Reads a grid in the file format from `text`; its errors name `name`.
pub fn parse_grid(text: &str, name: &str) -> Result<Grid, GridFileError> {
    let at = |line: usize| {
        move |problem| GridFileError::Parse {
            file: name.to_string(),
            line,
            problem,
        }
    };
    let mut header = Header::default();
    let mut layout: Option<Layout> = None;
    let (mut heights, mut filled) = (Vec::new(), 0);
    let mut last = 1;
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        last = i + 1;
        if layout.is_none() {
            let mut fields = line.split_whitespace();
            let key = fields.next().unwrap_or_default();
            let value = fields.next().unwrap_or_default();
            if header.take(key, value).map_err(at(last))? {
                continue;
            }
            let made = Layout::of(&header).map_err(at(last))?;
            heights = vec![0.0; made.nx * made.ny];
            layout = Some(made);
        }
        let Some(grid) = &layout else { continue };
        for field in line.split_whitespace() {
            let value = number(field, "a height").map_err(at(last))?;
            if filled == heights.len() {
                return Err(at(last)(GridProblem::TooMany(heights.len())));
            }
            let (k, x, y) = grid.node(filled);
            if !value.is_finite() || grid.nodata == Some(value) {
                return Err(at(last)(GridProblem::Hole { x, y, value }));
            }
            heights[k] = value;
            filled += 1;
        }
    }
    let grid = match layout {
        Some(grid) => grid,
        // No height at all: the header's own problem, else too few.
        None => {
            let problem = match Layout::of(&header) {
                Err(problem) => problem,
                Ok(grid) => GridProblem::TooFew {
                    got: 0,
                    want: grid.nx * grid.ny,
                },
            };
            return Err(at(last)(problem));
        }
    };
    if filled < heights.len() {
        return Err(at(last)(GridProblem::TooFew {
            got: filled,
            want: heights.len(),
        }));
    }
    Grid::new(
        grid.origin,
        (grid.cell, grid.cell),
        (grid.nx, grid.ny),
        heights,
    )
    .map_err(|source| GridFileError::Grid {
        file: name.to_string(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::field::{FieldShape, HeightField};

    const FILE: &str = "ncols 4\nNROWS 3\nxllcorner -1\nyllcenter -2\ncellsize 2\n\
                        NODATA_value -9999\n# the highest y first\n\
                        0 1 2 3\n4 5 6 7\n8 9 10 11\n";

    fn field(grid: Grid) -> HeightField {
        HeightField {
            base: FieldShape::Grid(grid),
            ..HeightField::level()
        }
    }

    /// Each height at its node: the first at the lower-left cell's
    /// centre (a corner of -1 and a cell of 2 put it at x = 0), rows from
    /// the highest y down; bilinear between.
    #[test]
    fn heights_stand_at_their_nodes() {
        let f = field(parse_grid(FILE, "t.asc").expect("a grid"));
        for (x, y, z) in [
            (0.0, 2.0, 0.0),
            (6.0, 2.0, 3.0),
            (0.0, -2.0, 8.0),
            (6.0, 0.0, 7.0),
        ] {
            assert_eq!(f.height(x, y), z, "({x}, {y})");
        }
        assert_eq!(f.height(1.0, -1.0), 0.25 * (8.0 + 9.0 + 4.0 + 5.0));
    }

    /// Every problem is refused naming its line.
    #[test]
    fn a_bad_file_is_refused_naming_its_line() {
        let line = |text: &str| match parse_grid(text, "t.asc") {
            Err(GridFileError::Parse { line, problem, .. }) => (line, problem),
            other => panic!("{other:?}"),
        };
        let head = "ncols 2\nnrows 2\nxllcenter 0\nyllcenter 0\ncellsize 1\n";
        assert!(matches!(
            line(&format!("{head}NODATA_value -1\n0 -1\n0 0\n")),
            (7, GridProblem::Hole { x: 1.0, y: 1.0, .. })
        ));
        assert!(matches!(
            line(&format!("{head}0 0\n0 x\n")),
            (7, GridProblem::NotANumber { .. })
        ));
        assert!(matches!(
            line(&format!("{head}0 0\n0\n")),
            (7, GridProblem::TooFew { got: 3, want: 4 })
        ));
        assert!(matches!(
            line(&format!("{head}0 0\n0 0 0\n")),
            (7, GridProblem::TooMany(4))
        ));
        assert!(matches!(
            line("ncols 2\nrows 2\n"),
            (2, GridProblem::UnknownKey(_))
        ));
        assert!(matches!(
            line("ncols 2\nnrows 2.5\nxllcenter 0\nyllcenter 0\ncellsize 1\n0 0\n"),
            (6, GridProblem::Count { key: "nrows", .. })
        ));
        assert!(matches!(
            line("ncols 2\nnrows 2\nxllcenter 0\ncellsize 1\n0 0\n"),
            (5, GridProblem::Missing("yllcenter or yllcorner"))
        ));
        assert!(matches!(
            line("ncols 2\nncols 2\n"),
            (2, GridProblem::Repeated(_))
        ));
        let zero = parse_grid(
            &format!("{}0 0\n0 0\n", head.replace("cellsize 1", "cellsize 0")),
            "t.asc",
        );
        assert!(matches!(zero, Err(GridFileError::Grid { .. })), "{zero:?}");
    }
}
