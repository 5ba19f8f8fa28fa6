//! The ground in space, a height field `z(x, y)` (m; `x` along the
//! course, `y` to its left, `z` up): each side's own profile, a plane at
//! any heading (a grade, a side slope, a grade at an angle to the path),
//! heights on a grid, and a tilt added to any of them. The spatial
//! vehicle's tracks each meet the ground under their own shoes.

use nalgebra::Vector2;

use super::profile::{Profile, ProfileError};
use super::surface::{Terrain, TerrainError};

/// A height field: a base shape and a plane added to it.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightField {
    /// The shape.
    pub base: FieldShape,
    /// The added plane's gradient `(∂z/∂x, ∂z/∂y)`: a grade along `x`, a
    /// side slope along `y` (rise over run each).
    pub tilt: Vector2<f64>,
}

/// The shape of a [`HeightField`].
#[derive(Debug, Clone, PartialEq)]
pub enum FieldShape {
    /// Level ground at height 0.
    Level,
    /// One profile across the whole width: `z = profile(x)`.
    Profile(Terrain),
    /// Each side its own profile: `left` where `y ≥ divide + band/2`,
    /// `right` where `y ≤ divide − band/2`, blended linearly across the
    /// band between (so the height is continuous across the divide where
    /// the band is wider than 0).
    Sides {
        /// The left side's profile.
        left: Terrain,
        /// The right side's.
        right: Terrain,
        /// Where the sides meet, m along `y`.
        divide: f64,
        /// The blend's width, m (0: the sides meet at a step).
        band: f64,
    },
    /// Heights on a regular grid, bilinear between.
    Grid(Grid),
}

/// Heights on a regular grid: `heights[j · nx + i]` at
/// `(x0 + i dx, y0 + j dy)`; bilinear between the nodes, and beyond the
/// grid the nearest edge's height (the field is flat out there).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    x0: f64,
    y0: f64,
    dx: f64,
    dy: f64,
    nx: usize,
    ny: usize,
    heights: Vec<f64>,
}

/// Why a height field cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FieldError {
    /// The grid's spacing or origin is not positive and finite.
    #[error("the grid's {what} must be {range}, got {value}")]
    Grid {
        /// Which figure.
        what: &'static str,
        /// Its range.
        range: &'static str,
        /// What was given.
        value: f64,
    },
    /// The grid does not have `nx × ny` heights, or fewer than 2 × 2.
    #[error("a {nx} × {ny} grid needs {} heights (at least 2 × 2), got {got}", nx * ny)]
    Size {
        /// Nodes along `x`.
        nx: usize,
        /// Nodes along `y`.
        ny: usize,
        /// Heights given.
        got: usize,
    },
    /// A height is missing (not finite): a hole in the field.
    #[error("the height at node ({i}, {j}), x = {x} m, y = {y} m, is {value}: a hole in the field")]
    Hole {
        /// The node along `x`, 0-based.
        i: usize,
        /// The node along `y`, 0-based.
        j: usize,
        /// Its place, m.
        x: f64,
        /// Its place, m.
        y: f64,
        /// What was given.
        value: f64,
    },
    /// The sides' blend is not finite and at least 0, or the divide not
    /// finite.
    #[error("the sides' {what} must be {range}, got {value}")]
    Sides {
        /// Which figure.
        what: &'static str,
        /// Its range.
        range: &'static str,
        /// What was given.
        value: f64,
    },
    /// A profile of the field is refused by its own check.
    #[error("a profile of the field: {0}")]
    Profile(#[from] TerrainError),
    /// The tilt is not finite.
    #[error("the tilt must be finite, got ({x}, {y})")]
    Tilt {
        /// Along `x`.
        x: f64,
        /// Along `y`.
        y: f64,
    },
}

impl Grid {
    /// A grid of `nx × ny` heights (m, row by row along `x`) from
    /// `(x0, y0)` every `dx` along `x` and `dy` along `y` (m): a missing
    /// height (not finite) is refused, naming its node and place.
    pub fn new(
        (x0, y0): (f64, f64),
        (dx, dy): (f64, f64),
        (nx, ny): (usize, usize),
        heights: Vec<f64>,
    ) -> Result<Grid, FieldError> {
        for (what, value, positive) in [
            ("x origin (m)", x0, false),
            ("y origin (m)", y0, false),
            ("spacing along x (m)", dx, true),
            ("spacing along y (m)", dy, true),
        ] {
            if !value.is_finite() || (positive && value <= 0.0) {
                let range = if positive {
                    "positive and finite"
                } else {
                    "finite"
                };
                return Err(FieldError::Grid { what, range, value });
            }
        }
        if nx < 2 || ny < 2 || heights.len() != nx * ny {
            return Err(FieldError::Size {
                nx,
                ny,
                got: heights.len(),
            });
        }
        if let Some(k) = heights.iter().position(|h| !h.is_finite()) {
            let (i, j) = (k % nx, k / nx);
            return Err(FieldError::Hole {
                i,
                j,
                x: x0 + i as f64 * dx,
                y: y0 + j as f64 * dy,
                value: heights[k],
            });
        }
        Ok(Grid {
            x0,
            y0,
            dx,
            dy,
            nx,
            ny,
            heights,
        })
    }

    /// The ground along the line `y` (m) as a profile along `x`: the
    /// polyline through the heights on that line at the grid's columns,
    /// exactly the field's there (bilinear heights are linear along `x`
    /// within a cell at any `y`), flat beyond the grid's ends as the
    /// field is: what a track running along `x` at `y` is assembled on.
    pub fn section(&self, y: f64) -> Result<Profile, ProfileError> {
        let points = (0..self.nx)
            .map(|i| {
                let x = self.x0 + i as f64 * self.dx;
                (x, self.height_and_gradient(x, y).0)
            })
            .collect();
        Profile::new(points)
    }

    /// The height (m) and gradient at `(x, y)`: bilinear in the cell, the
    /// nearest edge's beyond the grid (where the gradient across that
    /// edge is 0).
    fn height_and_gradient(&self, x: f64, y: f64) -> (f64, Vector2<f64>) {
        let cell = |p: f64, p0: f64, d: f64, n: usize| {
            let s = (p - p0) / d;
            if s <= 0.0 {
                (0, 0.0, false)
            } else if s >= (n - 1) as f64 {
                (n - 2, 1.0, false)
            } else {
                let k = (s.floor() as usize).min(n - 2);
                (k, s - k as f64, true)
            }
        };
        let (i, u, inside_x) = cell(x, self.x0, self.dx, self.nx);
        let (j, v, inside_y) = cell(y, self.y0, self.dy, self.ny);
        let at = |a: usize, b: usize| self.heights[(j + b) * self.nx + i + a];
        let (h00, h10, h01, h11) = (at(0, 0), at(1, 0), at(0, 1), at(1, 1));
        let height =
            h00 * (1.0 - u) * (1.0 - v) + h10 * u * (1.0 - v) + h01 * (1.0 - u) * v + h11 * u * v;
        let along = ((h10 - h00) * (1.0 - v) + (h11 - h01) * v) / self.dx;
        let across = ((h01 - h00) * (1.0 - u) + (h11 - h10) * u) / self.dy;
        let gradient = Vector2::new(
            if inside_x { along } else { 0.0 },
            if inside_y { across } else { 0.0 },
        );
        (height, gradient)
    }

    /// The highest node over the cells that meet `[x0, x1] × [y0, y1]`
    /// (the edge's nodes beyond the grid): bilinear heights lie between
    /// their cell's nodes.
    fn max_height(&self, (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> f64 {
        let nodes = |a: f64, b: f64, p0: f64, d: f64, n: usize| {
            let last = (n - 1) as f64;
            let first = ((a - p0) / d).floor().clamp(0.0, last) as usize;
            let end = ((b - p0) / d).ceil().clamp(0.0, last) as usize;
            first..=end
        };
        let columns = nodes(x0, x1, self.x0, self.dx, self.nx);
        let mut top = f64::NEG_INFINITY;
        for j in nodes(y0, y1, self.y0, self.dy, self.ny) {
            let row = &self.heights[j * self.nx..(j + 1) * self.nx];
            top = row[columns.clone()].iter().fold(top, |m, &h| m.max(h));
        }
        top
    }
}

impl HeightField {
    /// `terrain`'s profile laid across the whole width, untilted: level
    /// ground for level terrain at height 0 (the same heights, found
    /// without the profile's lookup).
    pub fn profile(terrain: &Terrain) -> HeightField {
        let base = match terrain {
            Terrain::Flat { height } if *height == 0.0 => FieldShape::Level,
            _ => FieldShape::Profile(terrain.clone()),
        };
        HeightField {
            base,
            ..HeightField::level()
        }
    }

    /// Each track on its own profile, untilted: `right` under the right
    /// track (`y < 0`), `left` under the left, blended linearly across
    /// a band `band` m wide about the vehicle's centre line `y = 0` (the
    /// gauge less the track's width leaves every point of each track on
    /// its own profile while it runs along `x`); where the two are the
    /// same, [`profile`](Self::profile) of it, the same heights.
    pub fn sides(right: &Terrain, left: &Terrain, band: f64) -> HeightField {
        if right == left {
            return HeightField::profile(right);
        }
        HeightField {
            base: FieldShape::Sides {
                left: left.clone(),
                right: right.clone(),
                divide: 0.0,
                band,
            },
            ..HeightField::level()
        }
    }

    /// Level ground at height 0.
    pub fn level() -> HeightField {
        HeightField {
            base: FieldShape::Level,
            tilt: Vector2::zeros(),
        }
    }

    /// A plane through the origin rising `grade` (rise over run) along the
    /// heading `heading` (rad from `x` toward `y`): a grade at an angle to
    /// the path.
    pub fn plane(grade: f64, heading: f64) -> HeightField {
        HeightField {
            base: FieldShape::Level,
            tilt: grade * Vector2::new(heading.cos(), heading.sin()),
        }
    }

    /// The same field with a plane of gradient `tilt` added.
    pub fn tilted(self, tilt: Vector2<f64>) -> HeightField {
        HeightField {
            tilt: self.tilt + tilt,
            ..self
        }
    }

    /// The field checked: its profiles' own checks, the sides' divide and
    /// band, the tilt finite (a grid is checked when made).
    pub fn check(&self) -> Result<(), FieldError> {
        if !(self.tilt.x.is_finite() && self.tilt.y.is_finite()) {
            return Err(FieldError::Tilt {
                x: self.tilt.x,
                y: self.tilt.y,
            });
        }
        match &self.base {
            FieldShape::Profile(terrain) => terrain.check()?,
            FieldShape::Sides { left, right, .. } => {
                left.check()?;
                right.check()?;
            }
            FieldShape::Level | FieldShape::Grid(_) => {}
        }
        if let FieldShape::Sides { divide, band, .. } = self.base {
            if !divide.is_finite() {
                return Err(FieldError::Sides {
                    what: "divide (m)",
                    range: "finite",
                    value: divide,
                });
            }
            if !(band.is_finite() && band >= 0.0) {
                return Err(FieldError::Sides {
                    what: "band (m)",
                    range: "finite and at least 0",
                    value: band,
                });
            }
        }
        Ok(())
    }

    /// The height at `(x, y)`, m.
    pub fn height(&self, x: f64, y: f64) -> f64 {
        self.height_and_gradient(x, y).0
    }

    /// The height (m) and gradient `(∂z/∂x, ∂z/∂y)` at `(x, y)`.
    pub fn height_and_gradient(&self, x: f64, y: f64) -> (f64, Vector2<f64>) {
        let (h, g) = match &self.base {
            FieldShape::Level => (0.0, Vector2::zeros()),
            FieldShape::Profile(terrain) => {
                let (h, s) = terrain.height_and_slope(x);
                (h, Vector2::new(s, 0.0))
            }
            FieldShape::Sides {
                left,
                right,
                divide,
                band,
            } => {
                // Off the band a point stands on one profile: only that
                // one is looked up (a track's points always are).
                let offset = y - divide;
                if offset >= 0.5 * band {
                    let (hl, sl) = left.height_and_slope(x);
                    (hl, Vector2::new(sl, 0.0))
                } else if offset <= -0.5 * band {
                    let (hr, sr) = right.height_and_slope(x);
                    (hr, Vector2::new(sr, 0.0))
                } else {
                    let (hl, sl) = left.height_and_slope(x);
                    let (hr, sr) = right.height_and_slope(x);
                    let w = offset / band + 0.5;
                    let h = w * hl + (1.0 - w) * hr;
                    (h, Vector2::new(w * sl + (1.0 - w) * sr, (hl - hr) / band))
                }
            }
            FieldShape::Grid(grid) => grid.height_and_gradient(x, y),
        };
        (h + self.tilt.dot(&Vector2::new(x, y)), g + self.tilt)
    }

    /// No height in the box `[x0, x1] × [y0, y1]` (m) is above this, m:
    /// for culling. The base shape's highest point there (its own bound
    /// for a profile, the higher side's for two, the highest node of the
    /// cells met for a grid) plus the tilt's at the box's highest corner;
    /// infinite for a box that is not a number.
    pub fn max_height(&self, (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> f64 {
        if [x0, x1, y0, y1].iter().any(|v| v.is_nan()) {
            return f64::INFINITY;
        }
        let base = match &self.base {
            FieldShape::Level => 0.0,
            FieldShape::Profile(terrain) => terrain.max_height(x0, x1),
            FieldShape::Sides { left, right, .. } => {
                left.max_height(x0, x1).max(right.max_height(x0, x1))
            }
            FieldShape::Grid(grid) => grid.max_height((x0, x1), (y0, y1)),
        };
        let corner = |slope: f64, low: f64, high: f64| slope * if slope > 0.0 { high } else { low };
        base + corner(self.tilt.x, x0, x1) + corner(self.tilt.y, y0, y1)
    }
}
