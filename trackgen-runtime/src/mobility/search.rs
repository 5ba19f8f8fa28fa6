//! Finding where a trial stops passing: bracketing, then bisection or
//! ITP interpolation over one parameter, the trials kept.

use super::EventError;

/// One run of an event at a parameter: what it measured and whether it
/// passed the event's criterion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trial {
    /// The parameter run (a speed, m/s; a height or width, m; a grade,
    /// rise over run).
    pub parameter: f64,
    /// The figure the criterion reads (absorbed power, W; peak
    /// acceleration, g; the distance reached past the obstacle, m).
    pub figure: f64,
    /// Whether it passed.
    pub passed: bool,
}

/// Where the criterion is crossed in the searched range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Limit {
    /// Between a passing and a failing parameter no further apart than
    /// the search's tolerance; `value` is their midpoint.
    Found {
        /// The limit, the bracket's midpoint.
        value: f64,
        /// The largest parameter that passed (the smallest, for a
        /// criterion that fails below its limit).
        passed: f64,
        /// The nearest parameter that failed.
        failed: f64,
    },
    /// Every parameter up to the range's end passed: the limit is beyond
    /// it.
    Beyond {
        /// The range's end, which passed.
        end: f64,
    },
    /// The range's start already failed: the limit is before it.
    Before {
        /// The range's start, which failed.
        start: f64,
    },
}

impl Limit {
    /// The limit's value: the midpoint of its bracket, or the end of the
    /// range it lies beyond (`Beyond`) or before (`Before`), as
    /// [`relation`](Self::relation) says.
    pub fn value(&self) -> f64 {
        match *self {
            Limit::Found { value, .. } => value,
            Limit::Beyond { end } => end,
            Limit::Before { start } => start,
        }
    }

    /// `=`, `>` or `<`: how the limit relates to [`value`](Self::value)
    /// (`<`: the limit is before the range's start, which failed).
    pub fn relation(&self) -> &'static str {
        match self {
            Limit::Found { .. } => "=",
            Limit::Beyond { .. } => ">",
            Limit::Before { .. } => "<",
        }
    }
}

/// A search's answer: the limit and every trial run, in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Search {
    /// Where the criterion is crossed.
    pub limit: Limit,
    /// The trials, in the order they ran.
    pub trials: Vec<Trial>,
    /// The vehicle at the limit, for the events that show it: on an
    /// obstacle's largest crossed, at its steepest moment (the geometry
    /// to draw, `trackgen-draw`'s `vehicle::picture`).
    pub picture: Option<crate::scene::Picture>,
    /// The limit's bracket run again at a tighter integrator tolerance
    /// ([`confirm`]), or `None` where it was not.
    pub confirmation: Option<Confirmation>,
}

/// A search's final bracket run again at a tighter integrator tolerance:
/// whether its verdicts held, and where the search went on if not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Confirmation {
    /// The integrator tolerance of the confirming trials.
    pub tolerance: f64,
    /// The index in [`Search::trials`] of the first confirming trial:
    /// those before it ran at the settings' own tolerance.
    pub first_trial: usize,
    /// The limit found at the settings' own tolerance, where a verdict
    /// changed at the tighter one and the search went on from it; `None`:
    /// the verdicts held, and the limit stands.
    pub moved_from: Option<Limit>,
}

impl Search {
    /// The number of runs it took.
    pub fn runs(&self) -> usize {
        self.trials.len()
    }
}

/// The parameter in `[start, end]` where `trial` stops passing, to within
/// `tolerance`: trials pass below the limit and fail above it (for a
/// criterion the other way round, pass `start > end`: the search runs from
/// `start` towards `end` whichever way that is). It runs `start`, then
/// `end`, then halves the bracket until it is at most `tolerance` wide:
/// `2 + ⌈log₂(|end − start| / tolerance)⌉` runs at most. A failed run is
/// the search's error.
pub fn bisect(
    start: f64,
    end: f64,
    tolerance: f64,
    trial: impl FnMut(f64) -> Result<Trial, EventError>,
) -> Result<Search, EventError> {
    let mut runs = Runs::new(trial);
    let limit = match runs.bracket(start, end)? {
        Ok(_) => runs.narrow(start, end, tolerance)?,
        Err(outside) => outside,
    };
    Ok(runs.search(limit))
}

/// As [`bisect`], for a criterion that reads a positive figure against
/// `limit` (a trial passes while its figure is below it, as an absorbed
/// power against 6 W): the bracket is narrowed by the ITP method
/// (interpolate, truncate, project: Oliveira and Takahashi, *ACM Trans.
/// Math. Softw.* 47(1), 2021, Algorithm 1, with `κ₁ = 0.2 / |end − start|`,
/// `κ₂ = 2`, `n₀ = 1`) on `ln(figure / limit)`, the regula falsi point
/// taken on `ln(parameter)` over a positive range (a power law in one
/// step). Where the figure is smooth in the parameter each trial lands
/// near the crossing, superlinearly; where it is not, the projection keeps every trial
/// within bisection's worst case: at most one run more than [`bisect`]'s
/// `2 + ⌈log₂(|end − start| / tolerance)⌉`. The bracket ends at most
/// `tolerance` wide, as bisection's. A failed run is the search's error.
pub fn interpolate(
    start: f64,
    end: f64,
    tolerance: f64,
    limit: f64,
    trial: impl FnMut(f64) -> Result<Trial, EventError>,
) -> Result<Search, EventError> {
    let mut runs = Runs::new(trial);
    let limit = match runs.bracket(start, end)? {
        Ok((first, last)) => runs.narrow_itp(first, last, tolerance, limit)?,
        Err(outside) => outside,
    };
    Ok(runs.search(limit))
}

/// The trials of one search, kept as they run.
struct Runs<F> {
    trial: F,
    trials: Vec<Trial>,
}

impl<F: FnMut(f64) -> Result<Trial, EventError>> Runs<F> {
    fn new(trial: F) -> Self {
        Runs {
            trial,
            trials: Vec::new(),
        }
    }

    /// Runs a trial at `p`: whether it passed.
    fn passes(&mut self, p: f64) -> Result<bool, EventError> {
        Ok(self.run(p)?.passed)
    }

    /// Runs `start`, then (if it passed) `end`: the two trials, a bracket
    /// of the limit; or, as `Err`, the limit outside it (`start` failed:
    /// before the range; `end` passed: beyond it).
    fn bracket(
        &mut self,
        start: f64,
        end: f64,
    ) -> Result<Result<(Trial, Trial), Limit>, EventError> {
        let first = self.run(start)?;
        if !first.passed {
            return Ok(Err(Limit::Before { start }));
        }
        let last = self.run(end)?;
        if last.passed {
            return Ok(Err(Limit::Beyond { end }));
        }
        Ok(Ok((first, last)))
    }

    /// Runs a trial at `p`, kept.
    fn run(&mut self, p: f64) -> Result<Trial, EventError> {
        let t = (self.trial)(p)?;
        self.trials.push(t);
        Ok(t)
    }

    /// Narrows the bracket from the passing trial `passed` to the failing
    /// `failed` by ITP ([`interpolate`]) until it is at most `tolerance`
    /// wide, on `y = ln(figure / limit)` (below 0 passing). Worked in
    /// `s ∈ [0, 1]` from `passed` to `failed`, so either may be the
    /// larger parameter. Over a positive range the regula falsi point is
    /// taken on `ln(parameter)`: a power law's crossing (a figure growing
    /// as a power of speed) in one step; the truncation and projection
    /// keep the method's bound whatever the interpolation. A figure that gives no finite `y` (not positive,
    /// or on the wrong side of the limit for its verdict) makes that
    /// step a bisection.
    fn narrow_itp(
        &mut self,
        passed: Trial,
        failed: Trial,
        tolerance: f64,
        limit: f64,
    ) -> Result<Limit, EventError> {
        let (p0, width) = (passed.parameter, failed.parameter - passed.parameter);
        let geometric = p0 > 0.0 && failed.parameter > 0.0;
        let level = |t: &Trial| {
            let y = (t.figure / limit).ln();
            let consistent = if t.passed { y < 0.0 } else { y >= 0.0 };
            (y.is_finite() && consistent).then_some(y)
        };
        // The bracket [a, b] in s, with y(a) < 0 ≤ y(b) where known.
        let (mut a, mut b) = (0.0_f64, 1.0_f64);
        let (mut ya, mut yb) = (level(&passed), level(&failed));
        let epsilon = 0.5 * tolerance / width.abs();
        let halvings = (1.0 / (2.0 * epsilon)).log2().ceil().max(0.0);
        let most = halvings + 1.0;
        let kappa1 = 0.2;
        let mut j = 0.0;
        while (b - a) * width.abs() > tolerance {
            let middle = 0.5 * (a + b);
            let next = match (ya, yb) {
                (Some(ya), Some(yb)) if yb > ya => {
                    // Interpolate, truncate toward the middle, project
                    // into the minmax radius.
                    let falsi = if geometric {
                        let (ua, ub) = ((p0 + a * width).ln(), (p0 + b * width).ln());
                        ((ua + (ub - ua) * -ya / (yb - ya)).exp() - p0) / width
                    } else {
                        (yb * a - ya * b) / (yb - ya)
                    };
                    let sigma = (middle - falsi).signum();
                    let delta = kappa1 * (b - a).powi(2);
                    let truncated = if delta <= (middle - falsi).abs() {
                        falsi + sigma * delta
                    } else {
                        middle
                    };
                    let radius = epsilon * 2f64.powf(most - j) - 0.5 * (b - a);
                    if (truncated - middle).abs() <= radius {
                        truncated
                    } else {
                        middle - sigma * radius
                    }
                }
                _ => middle,
            };
            let t = self.run(p0 + next * width)?;
            if t.passed {
                (a, ya) = (next, level(&t));
            } else {
                (b, yb) = (next, level(&t));
            }
            j += 1.0;
        }
        let (passed, failed) = (p0 + a * width, p0 + b * width);
        Ok(Limit::Found {
            value: 0.5 * (passed + failed),
            passed,
            failed,
        })
    }

    /// Halves the bracket from a passing to a failing parameter until it
    /// is at most `tolerance` wide: the limit, its midpoint.
    fn narrow(
        &mut self,
        mut passed: f64,
        mut failed: f64,
        tolerance: f64,
    ) -> Result<Limit, EventError> {
        while (failed - passed).abs() > tolerance {
            let middle = 0.5 * (passed + failed);
            if self.passes(middle)? {
                passed = middle;
            } else {
                failed = middle;
            }
        }
        Ok(Limit::Found {
            value: 0.5 * (passed + failed),
            passed,
            failed,
        })
    }

    fn search(self, limit: Limit) -> Search {
        Search {
            limit,
            trials: self.trials,
            picture: None,
            confirmation: None,
        }
    }

    /// From `from`, trials towards `toward` at `step`, twice that, four
    /// times… (the last at `toward` itself) until one's verdict is
    /// `wanted`: that parameter and the one tried before it (`from` at
    /// first), or `None` if `toward` is reached without it.
    fn seek(
        &mut self,
        from: f64,
        toward: f64,
        step: f64,
        wanted: bool,
    ) -> Result<Option<(f64, f64)>, EventError> {
        let direction = (toward - from).signum();
        let (mut before, mut step) = (from, step.abs());
        while before != toward {
            let next = before + direction * step;
            let next = if (toward - next) * direction <= 0.0 {
                toward
            } else {
                next
            };
            if self.passes(next)? == wanted {
                return Ok(Some((next, before)));
            }
            before = next;
            step *= 2.0;
        }
        Ok(None)
    }

    /// The limit beyond `from`, whose verdict changed: towards `start`
    /// (`back`: `from` failed) or towards `end` (it passed), stepping out
    /// from `step` ([`seek`](Self::seek)) to the first changed-back
    /// verdict, then bisecting to `tolerance`; the range's end where none
    /// changes back.
    fn search_on(
        &mut self,
        from: f64,
        (start, end): (f64, f64),
        back: bool,
        step: f64,
        tolerance: f64,
    ) -> Result<Limit, EventError> {
        let toward = if back { start } else { end };
        Ok(match self.seek(from, toward, step, back)? {
            Some((passing, failing)) if back => self.narrow(passing, failing, tolerance)?,
            Some((failing, passing)) => self.narrow(passing, failing, tolerance)?,
            None if back => Limit::Before { start },
            None => Limit::Beyond { end },
        })
    }
}

/// `search` (run from `start` towards `end` by [`bisect`],
/// [`interpolate`] or [`scan_then_bisect`]) confirmed by `trial`, the
/// same trial at a tighter integrator tolerance `integrator_tolerance`:
/// the bracket's two ends are run again (the range's end alone, for a
/// limit beyond or before it). Where both verdicts hold the limit stands.
/// Where one changes, the limit lies outside the bracket on that side:
/// the search goes on at the tighter tolerance, stepping away from the
/// bracket by its width, doubling, until a verdict changes back, then
/// bisecting to `tolerance`, as the first search did, and the first
/// answer is kept as [`Confirmation::moved_from`]. A search's answer that
/// the integrator's error decides is found so at the tolerance that
/// settles it, at the cost of the two runs that show whether it does.
/// A failed run is the search's error.
pub fn confirm(
    search: Search,
    (start, end): (f64, f64),
    tolerance: f64,
    integrator_tolerance: f64,
    trial: impl FnMut(f64) -> Result<Trial, EventError>,
) -> Result<Search, EventError> {
    let first_trial = search.trials.len();
    let mut runs = Runs {
        trial,
        trials: search.trials,
    };
    let tolerance = tolerance.abs();
    let first = search.limit;
    // Where a verdict changed, the limit lies beyond the bracket on that
    // side: the search goes on from it, that way.
    let limit = match first {
        Limit::Found { passed, failed, .. } => {
            let width = (failed - passed).abs().max(tolerance);
            if !runs.passes(passed)? {
                runs.search_on(passed, (start, end), true, width, tolerance)?
            } else if runs.passes(failed)? {
                runs.search_on(failed, (start, end), false, width, tolerance)?
            } else {
                first
            }
        }
        Limit::Beyond { end } => match runs.passes(end)? {
            true => first,
            false => runs.search_on(end, (start, end), true, tolerance, tolerance)?,
        },
        Limit::Before { start } => match runs.passes(start)? {
            false => first,
            true => runs.search_on(start, (start, end), false, tolerance, tolerance)?,
        },
    };
    Ok(Search {
        confirmation: Some(Confirmation {
            tolerance: integrator_tolerance,
            first_trial,
            moved_from: (limit != first).then_some(first),
        }),
        limit,
        trials: runs.trials,
        picture: search.picture,
    })
}

/// The *first* parameter from `start` towards `end` where `trial` stops
/// passing, to within `tolerance`: trials at `start`, then every `step`
/// towards `end` (the last at `end`) until one fails, then bisection of
/// that bracket. For a figure that need not be monotone in the parameter
/// (a seat's peak acceleration rises and falls with speed through the
/// suspension's resonances), where bisection over the whole range finds
/// *a* crossing, not necessarily the first. A failing stretch narrower
/// than `step` between two passing trials is not seen. Runs: 1 + the
/// scanned trials + `⌈log₂(step / tolerance)⌉` at most. A failed run is
/// the search's error.
pub fn scan_then_bisect(
    start: f64,
    end: f64,
    step: f64,
    tolerance: f64,
    trial: impl FnMut(f64) -> Result<Trial, EventError>,
) -> Result<Search, EventError> {
    let mut runs = Runs::new(trial);
    if !runs.passes(start)? {
        return Ok(runs.search(Limit::Before { start }));
    }
    let direction = (end - start).signum();
    let step = step.abs().max(tolerance.abs());
    let mut passed = start;
    loop {
        let next = passed + direction * step;
        let next = if (end - next) * direction <= 0.0 {
            end
        } else {
            next
        };
        if !runs.passes(next)? {
            let limit = runs.narrow(passed, next, tolerance)?;
            return Ok(runs.search(limit));
        }
        if next == end {
            return Ok(runs.search(Limit::Beyond { end }));
        }
        passed = next;
    }
}
