//! Lowering a vehicle's `powertrain`: an engine's full-load map through a
//! torque converter with a lock-up clutch, a range gearbox and a final
//! drive (the runtime's `Driveline`). What the macro can evaluate is
//! checked here, at the offending token, by the runtime's rules; what is a
//! named constant is checked when the vehicle is built.

use quote::quote;
use syn::spanned::Spanned;
use syn::{Expr, Lit};

use super::Lowering;
use super::keys::{Fields, strip};
use crate::ir::{ConstCheck, Powertrain};
use crate::num::Num;

/// The keys of a `powertrain { … }` section.
const KEYS: [&str; 21] = [
    "reverse",
    "upshift",
    "downshift",
    "shift_time",
    "engine",
    "capacity",
    "torque_ratio",
    "ranges",
    "lockup",
    "lockup_speed_ratio",
    "final_drive",
    "gearbox_efficiency",
    "final_drive_efficiency",
    "share",
    "engine_inertia",
    "engine_drag",
    "governor_time",
    "lockup_capacity",
    "lockup_stiffness",
    "lockup_damping",
    "steer_ratios",
];

/// The side's share of the driveline's output when none is declared: a
/// planar model is one side of a two-track vehicle.
const DEFAULT_SHARE: f64 = 0.5;

/// What each value of a list of one per range must be.
struct PerRange {
    /// What one value is, for the messages: `speed`, `ratio`.
    one: &'static str,
    /// The list's form, for the message of a value that is no list.
    shape: &'static str,
    /// The rule a value the macro can read keeps.
    holds: fn(f64) -> bool,
    /// What breaking it is.
    broken: &'static str,
    /// The rule as a condition on a named constant, checked when the
    /// vehicle is built; `None`: such a value is the runtime's to check.
    built: Option<fn(&Num) -> proc_macro2::TokenStream>,
}

/// Which table, for its rules.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Table {
    /// Full-load torque against engine speed: speeds from one above 0.
    Engine,
    /// The converter's capacity factor: from speed ratio 0, each `K > 0`.
    Capacity,
    /// The converter's torque ratio: from speed ratio 0, each `TR ≥ 0`,
    /// `SR · TR ≤ 1`.
    TorqueRatio,
    /// The engine's torque at no fuel against its speed: speeds from one
    /// ≥ 0, each torque ≤ 0.
    Drag,
}

impl Lowering<'_> {
    /// The `powertrain` section, every problem reported at its token.
    pub(super) fn powertrain(&mut self, block: &crate::parse::Block) -> Option<Powertrain> {
        let fields = self.fields("powertrain", block, &KEYS);
        self.sections("powertrain", block, &[]);
        let engine = self.table(&fields, "engine", Table::Engine);
        let capacity = self.table(&fields, "capacity", Table::Capacity);
        let torque_ratio = self.table(&fields, "torque_ratio", Table::TorqueRatio);
        let ranges = self.ranges(&fields);
        // The ranges declared, counted even where one of them is wrong.
        let count = fields.map.get("ranges").and_then(|e| match strip(e) {
            Expr::Array(list) => Some(list.elems.len()),
            _ => None,
        });
        let lockup = self.lockup(&fields, count);
        let locks = lockup.as_ref().is_some_and(|l| !l.is_empty());
        // Without a locking range the clutch's speed ratio is never used.
        let lockup_speed_ratio = self
            .fraction(&fields, "lockup_speed_ratio", locks)
            .or(if locks { None } else { Some(Num::Known(1.0)) });
        let final_drive = self.positive(&fields, "final_drive", true);
        let gearbox_efficiency = self.fraction(&fields, "gearbox_efficiency", true);
        let final_drive_efficiency = self.fraction(&fields, "final_drive_efficiency", true);
        let share = match fields.map.get("share") {
            Some(_) => self.fraction(&fields, "share", true),
            None => Some(Num::Known(DEFAULT_SHARE)),
        };
        let shift = self.shift(&fields, count, ranges.as_deref());
        let reverse = match fields.map.get("reverse") {
            Some(_) => self.positive(&fields, "reverse", true).map(Some),
            None => Some(None),
        };
        let dynamics = self.engine_dynamics(&fields);
        let steer_ratios = self.steer_ratios(&fields, count);
        Some(Powertrain {
            engine: engine?,
            capacity: capacity?,
            torque_ratio: torque_ratio?,
            ranges: ranges?,
            lockup: lockup?,
            lockup_speed_ratio: lockup_speed_ratio?,
            final_drive: final_drive?,
            gearbox_efficiency: gearbox_efficiency?,
            final_drive_efficiency: final_drive_efficiency?,
            share: share?,
            shift: shift?,
            reverse: reverse?,
            dynamics: dynamics?,
            steer_ratios: steer_ratios?,
        })
    }

    /// The steer unit's minimum steer ratios `[ρ₁, ρ₂, …]`, one per
    /// declared range, each above 1 (the outer sprocket's speed over the
    /// inner's at full steer); none declared: no steer unit.
    fn steer_ratios(&mut self, fields: &Fields, count: Option<usize>) -> Option<Vec<Num>> {
        let Some(expr) = fields.map.get("steer_ratios") else {
            return Some(Vec::new());
        };
        let rule = PerRange {
            one: "ratio",
            shape: "minimum steer ratios `[ρ₁, ρ₂, …]`",
            holds: |v| v > 1.0,
            broken: "a minimum steer ratio must be above 1 (at 1 the sprockets turn alike)",
            built: Some(|v| quote!((#v) > 1.0 && (#v) <= f64::MAX)),
        };
        self.per_range(expr, "steer_ratios", count, &rule)
    }

    /// A list `[v₁, v₂, …]` under `key` (`expr`), one value per range where
    /// the ranges' `count` is known, each by `rule` at its token where the
    /// macro can read it, and when the vehicle is built where it is a named
    /// constant and the rule says how.
    fn per_range(
        &mut self,
        expr: &Expr,
        key: &str,
        count: Option<usize>,
        rule: &PerRange,
    ) -> Option<Vec<Num>> {
        let Expr::Array(list) = strip(expr) else {
            self.errors.spanned(
                expr,
                format!("`{key}` must be a list of {}, one per range", rule.shape),
            );
            return None;
        };
        if let Some(count) = count
            && list.elems.len() != count
        {
            self.errors.spanned(
                list,
                format!(
                    "`{key}` needs one {} per range: {} given for {count} ranges",
                    rule.one,
                    list.elems.len()
                ),
            );
            return None;
        }
        let mut out = Vec::new();
        let mut fine = true;
        for element in &list.elems {
            match self.eval(element, key) {
                Ok(Num::Known(v)) if !(rule.holds)(v) => {
                    self.errors
                        .spanned(element, format!("`{key}`: {}, found {v}", rule.broken));
                    fine = false;
                }
                Ok(value) => {
                    if let (Num::Expr(_), Some(condition)) = (&value, rule.built) {
                        self.checks.push(ConstCheck {
                            span: element.span(),
                            condition: condition(&value),
                            message: format!("`{key}`: {} and finite", rule.broken),
                        });
                    }
                    out.push(value);
                }
                Err(()) => fine = false,
            }
        }
        fine.then_some(out)
    }

    /// The shift schedule: `upshift` and `downshift`, one speed (rad/s,
    /// ≥ 0) per declared range, and `shift_time` (s, ≥ 0), all three or
    /// none (none: shifted ideally). Each downshift below its range's
    /// upshift and each upshift landing above the next range's
    /// downshift, where the macro knows the figures; the runtime's rule
    /// checks the rest when the vehicle is built.
    #[allow(clippy::type_complexity)]
    fn shift(
        &mut self,
        fields: &Fields,
        count: Option<usize>,
        ranges: Option<&[Num]>,
    ) -> Option<Option<(Vec<Num>, Vec<Num>, Num)>> {
        let keys = ["upshift", "downshift", "shift_time"];
        let given: Vec<&str> = keys
            .iter()
            .copied()
            .filter(|k| fields.map.contains_key(*k))
            .collect();
        if given.is_empty() {
            return Some(None);
        }
        if given.len() < keys.len() {
            let missing: Vec<String> = keys
                .iter()
                .filter(|k| !given.contains(k))
                .map(|k| format!("`{k}`"))
                .collect();
            let at = fields.map[given[0]];
            self.errors.spanned(
                at,
                format!(
                    "a shift schedule needs `upshift`, `downshift` and `shift_time` together: {} missing",
                    missing.join(" and ")
                ),
            );
            return None;
        }
        let up = self.speeds(fields, "upshift", count);
        let down = self.speeds(fields, "downshift", count);
        let time = self.non_negative(fields, "shift_time");
        let (up, down, time) = (up?, down?, time?);
        let known = |v: &[Num]| v.iter().map(Num::known).collect::<Option<Vec<f64>>>();
        let mut fine = true;
        if let (Some(u), Some(d), Some(r)) = (known(&up), known(&down), ranges.and_then(known)) {
            let list = fields.map["downshift"];
            for k in 1..u.len() {
                if k + 1 < u.len() && d[k] >= u[k] {
                    self.errors.spanned(
                        list,
                        format!(
                            "range {}'s downshift speed {} is not below its upshift speed {}",
                            k + 1,
                            d[k],
                            u[k]
                        ),
                    );
                    fine = false;
                }
                let lands = u[k - 1] * r[k] / r[k - 1];
                if lands <= d[k] {
                    self.errors.spanned(
                        list,
                        format!(
                            "the upshift from range {} lands at {lands:.3} rad/s, not above range {}'s downshift speed {}: the gearbox would hunt",
                            k,
                            k + 1,
                            d[k]
                        ),
                    );
                    fine = false;
                }
            }
        }
        if !fine {
            return None;
        }
        Some(Some((up, down, time)))
    }

    /// One gearbox input speed per range, rad/s, each ≥ 0.
    fn speeds(&mut self, fields: &Fields, key: &str, count: Option<usize>) -> Option<Vec<Num>> {
        let rule = PerRange {
            one: "speed",
            shape: "speeds `[ω₁, ω₂, …]`, rad/s",
            holds: |v| v >= 0.0,
            broken: "a speed must be 0 or more",
            built: None,
        };
        self.per_range(fields.map[key], key, count, &rule)
    }

    /// A number in (0, 1]: an efficiency, a share, a speed ratio.
    fn fraction(&mut self, fields: &Fields, key: &str, required: bool) -> Option<Num> {
        let expr = fields.map.get(key).copied();
        let value = self.number(fields, key, required)?;
        match &value {
            Num::Known(v) => {
                if !(*v > 0.0 && *v <= 1.0) {
                    self.errors
                        .spanned(expr?, format!("`{key}` must be in (0, 1], found {v}"));
                }
            }
            Num::Expr(_) => self.checks.push(ConstCheck {
                span: expr?.span(),
                condition: quote!((#value) > 0.0 && (#value) <= 1.0),
                message: format!("`{key}` must be in (0, 1]"),
            }),
        }
        Some(value)
    }

    /// A table `[(x, y), …]` of two or more points, its abscissae
    /// increasing, each point by `table`'s rules where the macro knows it.
    pub(super) fn table(
        &mut self,
        fields: &Fields,
        key: &str,
        table: Table,
    ) -> Option<Vec<(Num, Num)>> {
        let Some(expr) = fields.map.get(key) else {
            self.missing(fields, key);
            return None;
        };
        let Expr::Array(list) = strip(expr) else {
            self.errors
                .spanned(expr, format!("`{key}` must be a table `[(x, y), …]`"));
            return None;
        };
        if list.elems.len() < 2 {
            self.errors
                .spanned(list, format!("`{key}` needs two or more points"));
            return None;
        }
        let mut points = Vec::new();
        let mut previous: Option<f64> = None;
        let mut fine = true;
        for (i, element) in list.elems.iter().enumerate() {
            let Ok(point) = self.eval_point(element, key) else {
                fine = false;
                continue;
            };
            let (x, y) = (point.x.known(), point.y.known());
            if let Some(x) = x {
                let problem = if i == 0 && table == Table::Drag && x < 0.0 {
                    Some(format!(
                        "`{key}` must start at an engine speed of 0 rad/s or more, not {x}"
                    ))
                } else if i == 0 && !matches!(table, Table::Engine | Table::Drag) && x != 0.0 {
                    Some(format!(
                        "`{key}` must start at speed ratio 0 (stall), not {x}"
                    ))
                } else if i == 0 && table == Table::Engine && x <= 0.0 {
                    Some(format!(
                        "`{key}` must start at an engine speed above 0 rad/s, not {x}"
                    ))
                } else if previous.is_some_and(|p| x <= p) {
                    Some(format!(
                        "`{key}`'s abscissae must increase: point {} ({x}) is not past the one before",
                        i + 1
                    ))
                } else {
                    None
                };
                if let Some(problem) = problem {
                    self.errors.spanned(element, problem);
                    fine = false;
                }
                previous = Some(x);
            } else {
                previous = None;
            }
            if let Some(y) = y {
                let problem = match table {
                    Table::Capacity if y <= 0.0 => Some(format!(
                        "`{key}`: a capacity factor must be above 0, found {y}"
                    )),
                    Table::TorqueRatio if y < 0.0 => Some(format!(
                        "`{key}`: a torque ratio must be 0 or more, found {y}"
                    )),
                    Table::Drag if y > 0.0 => Some(format!(
                        "`{key}`: the engine's torque at no fuel is its drag, 0 or less, found {y}"
                    )),
                    Table::TorqueRatio if x.is_some_and(|x| x * y > 1.0) => Some(format!(
                        "`{key}`: the converter's efficiency SR·TR is {:.3} at point {}: more than 1",
                        x.unwrap_or(f64::NAN) * y,
                        i + 1
                    )),
                    _ => None,
                };
                if let Some(problem) = problem {
                    self.errors.spanned(element, problem);
                    fine = false;
                }
            }
            points.push((point.x, point.y));
        }
        fine.then_some(points)
    }

    /// The ranges' reductions `[r₁, r₂, …]`, each above 0, lowest range
    /// first.
    fn ranges(&mut self, fields: &Fields) -> Option<Vec<Num>> {
        let Some(expr) = fields.map.get("ranges") else {
            self.missing(fields, "ranges");
            return None;
        };
        let Expr::Array(list) = strip(expr) else {
            self.errors.spanned(
                expr,
                "`ranges` must be a list of reductions `[r₁, r₂, …]`, lowest range first",
            );
            return None;
        };
        if list.elems.is_empty() {
            self.errors
                .spanned(list, "`ranges` needs at least one range");
            return None;
        }
        let mut out = Vec::new();
        let mut fine = true;
        for element in &list.elems {
            match self.eval(element, "ranges") {
                Ok(Num::Known(v)) if v <= 0.0 => {
                    self.errors.spanned(
                        element,
                        format!("a range's reduction must be above 0, found {v}"),
                    );
                    fine = false;
                }
                Ok(value) => {
                    if let Num::Expr(_) = value {
                        self.checks.push(ConstCheck {
                            span: element.span(),
                            condition: quote!((#value) > 0.0 && (#value) <= f64::MAX),
                            message: "a range's reduction must be above 0 and finite".into(),
                        });
                    }
                    out.push(value);
                }
                Err(()) => fine = false,
            }
        }
        fine.then_some(out)
    }

    /// The ranges that lock up, `[2, 3, 4]`, numbered from 1 as manuals
    /// number them; 0-based for the runtime. None declared: none lock.
    fn lockup(&mut self, fields: &Fields, ranges: Option<usize>) -> Option<Vec<usize>> {
        let Some(expr) = fields.map.get("lockup") else {
            return Some(Vec::new());
        };
        let Expr::Array(list) = strip(expr) else {
            self.errors.spanned(
                expr,
                "`lockup` must be a list of range numbers `[2, 3, …]` (from 1)",
            );
            return None;
        };
        let mut out = Vec::new();
        let mut fine = true;
        for element in &list.elems {
            let number = match strip(element) {
                Expr::Lit(l) => match &l.lit {
                    Lit::Int(i) => self.integer::<usize>(i, "usize").ok().flatten(),
                    _ => None,
                },
                _ => None,
            };
            match (number, ranges) {
                (Some(n), Some(count)) if n >= 1 && n <= count => out.push(n - 1),
                (Some(n), None) if n >= 1 => out.push(n - 1),
                (Some(n), Some(count)) => {
                    self.errors.spanned(
                        element,
                        format!("`lockup`: range {n} is not one of the {count} declared (from 1)"),
                    );
                    fine = false;
                }
                _ => {
                    self.errors
                        .spanned(element, "`lockup` takes range numbers from 1, as literals");
                    fine = false;
                }
            }
        }
        fine.then_some(out)
    }
}
