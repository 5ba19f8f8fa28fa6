//! The real vehicle's figures, to set beside the events' answers.

/// How far an answer may stand from the published figure and still be
/// said to agree with it: 15 %, relative.
pub const AGREEMENT: f64 = 0.15;

/// A figure published for a real vehicle that one of the events answers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Published {
    /// The event's quantity it answers, by its name in
    /// [`quantity`](super::quantity) ([`quantity::HIGHEST_STEP`](super::quantity::HIGHEST_STEP), …).
    pub quantity: &'static str,
    /// The published value, in [`unit`](Self::unit).
    pub value: f64,
    /// Its unit, the event's (`"rise over run"`, `"m"`).
    pub unit: &'static str,
    /// Where it is published.
    pub source: &'static str,
}

/// An event's answer against the published figure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Comparison {
    /// The answer over the published value.
    pub ratio: f64,
    /// Whether it is within [`AGREEMENT`] of it.
    pub agrees: bool,
}

impl Published {
    /// `answer` (in [`unit`](Self::unit)) against the published value:
    /// their ratio, and whether they agree within [`AGREEMENT`]. A NaN or
    /// infinite answer (no limit found) agrees with nothing.
    pub fn compare(&self, answer: f64) -> Comparison {
        let ratio = answer / self.value;
        Comparison {
            ratio,
            agrees: ratio.is_finite() && (ratio - 1.0).abs() <= AGREEMENT,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agreement_is_within_fifteen_percent_either_way() {
        let step = Published {
            quantity: crate::mobility::quantity::HIGHEST_STEP,
            value: 0.61,
            unit: "m",
            source: "",
        };
        assert!(step.compare(0.61 * 1.149).agrees);
        assert!(step.compare(0.61 * 0.851).agrees);
        assert!(!step.compare(0.61 * 1.151).agrees);
        assert!(!step.compare(0.61 * 0.849).agrees);
        assert!(!step.compare(f64::NAN).agrees);
        assert_eq!(step.compare(1.22).ratio, 2.0);
    }
}
