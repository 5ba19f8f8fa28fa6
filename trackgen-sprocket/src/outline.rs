//! A hull's outline: the rule for a polygon the contact can use (convex,
//! so that a corner inside it is as deep as its distance to the nearest
//! side), shared by the compiler (an error at the declaration) and the
//! runtime (a vehicle built from anything else) like the sprocket's.

use std::fmt;

/// Why a list of corners is no convex outline.
#[derive(Debug, Clone, PartialEq)]
pub enum OutlineProblem {
    /// Fewer than three corners.
    TooFew {
        /// How many were given.
        count: usize,
    },
    /// A corner is NaN or infinite.
    NotFinite {
        /// Which (0-based).
        corner: usize,
    },
    /// Three consecutive corners on a line, or one repeated.
    Degenerate {
        /// The middle one (0-based).
        corner: usize,
    },
    /// The outline turns the other way at a corner, or winds more than
    /// once: not convex.
    NotConvex {
        /// The corner (0-based).
        corner: usize,
    },
}

impl fmt::Display for OutlineProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OutlineProblem::TooFew { count } => {
                write!(f, "an outline needs at least 3 corners, found {count}")
            }
            OutlineProblem::NotFinite { corner } => {
                write!(f, "corner {} is not a finite point", corner + 1)
            }
            OutlineProblem::Degenerate { corner } => write!(
                f,
                "corner {} repeats a corner or lies on the line through its neighbours",
                corner + 1
            ),
            OutlineProblem::NotConvex { corner } => write!(
                f,
                "the outline is not convex at corner {} (list the corners in order round \
                 the outline, every turn the same way)",
                corner + 1
            ),
        }
    }
}

impl std::error::Error for OutlineProblem {}

/// The corners of a convex polygon, counter-clockwise (x forward, y up),
/// from `corners` listed in order round it in either direction; or why
/// they are none.
pub fn convex_outline(corners: &[(f64, f64)]) -> Result<Vec<(f64, f64)>, OutlineProblem> {
    let n = corners.len();
    if n < 3 {
        return Err(OutlineProblem::TooFew { count: n });
    }
    if let Some(corner) = corners
        .iter()
        .position(|(x, y)| !(x.is_finite() && y.is_finite()))
    {
        return Err(OutlineProblem::NotFinite { corner });
    }
    let turn = |i: usize| {
        let (a, b, c) = (corners[(i + n - 1) % n], corners[i], corners[(i + 1) % n]);
        let (e1, e2) = ((b.0 - a.0, b.1 - a.1), (c.0 - b.0, c.1 - b.1));
        let scale = (e1.0.hypot(e1.1) * e2.0.hypot(e2.1)).max(f64::MIN_POSITIVE);
        (
            (e1.0 * e2.1 - e1.1 * e2.0) / scale,
            (e1.0 * e2.0 + e1.1 * e2.1) / scale,
        )
    };
    let mut sign = 0.0;
    let mut winding = 0.0;
    for i in 0..n {
        let (sine, dot) = turn(i);
        if sine.abs() < 1e-12 {
            return Err(OutlineProblem::Degenerate { corner: i });
        }
        if sign == 0.0 {
            sign = sine.signum();
        } else if sine.signum() != sign {
            return Err(OutlineProblem::NotConvex { corner: i });
        }
        winding += sine.atan2(dot);
    }
    // Every turn one way and the turns adding to one revolution: a simple
    // convex polygon (a star turns the same way but twice round).
    if (winding.abs() - 2.0 * std::f64::consts::PI).abs() > 1e-6 {
        return Err(OutlineProblem::NotConvex { corner: 0 });
    }
    let mut ccw = corners.to_vec();
    if sign < 0.0 {
        ccw.reverse();
    }
    Ok(ccw)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn squares_either_way_and_what_is_not_an_outline() {
        // Sides of very different lengths: the turns are angles, whatever
        // the sides' lengths.
        let long = [
            (0.45, 0.35),
            (-0.05, -0.15),
            (-4.41, -0.15),
            (-4.41, 1.27),
            (-0.55, 1.27),
        ];
        let ccw = convex_outline(&long).unwrap();
        assert_eq!(ccw[0], (-0.55, 1.27));
        let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        assert_eq!(convex_outline(&square).unwrap(), square.to_vec());
        let mut clockwise = square;
        clockwise.reverse();
        assert_eq!(convex_outline(&clockwise).unwrap(), square.to_vec());
        assert_eq!(
            convex_outline(&square[..2]),
            Err(OutlineProblem::TooFew { count: 2 })
        );
        let dented = [(0.0, 0.0), (1.0, 0.0), (0.5, 0.2), (1.0, 1.0), (0.0, 1.0)];
        assert!(matches!(
            convex_outline(&dented),
            Err(OutlineProblem::NotConvex { .. })
        ));
        let collinear = [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (0.0, 1.0)];
        assert_eq!(
            convex_outline(&collinear),
            Err(OutlineProblem::Degenerate { corner: 1 })
        );
        // A pentagram turns one way at every corner, twice round.
        let star: Vec<(f64, f64)> = (0..5)
            .map(|k| {
                let a = std::f64::consts::TAU * (2 * k) as f64 / 5.0;
                (a.cos(), a.sin())
            })
            .collect();
        assert!(matches!(
            convex_outline(&star),
            Err(OutlineProblem::NotConvex { .. })
        ));
        assert_eq!(
            convex_outline(&[(0.0, 0.0), (f64::NAN, 0.0), (0.0, 1.0)]),
            Err(OutlineProblem::NotFinite { corner: 1 })
        );
    }
}
