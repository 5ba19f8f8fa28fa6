//! Soft soil: the terramechanics laws a deformable terrain is made of, as
//! Wong, *Theory of Ground Vehicles* (4th ed., Wiley, 2008, chapter 2)
//! gives them after Bekker and Janosi–Hanamoto, with the elastic unloading
//! of Project Chrono's SCM terrain (`SCMTerrain.cpp`); and the textbook
//! soils (the guide's chapter "Soft soil").
//!
//! * Loading: Bekker's pressure–sinkage law `p = (k_c/b + k_φ) zⁿ`, with
//!   `b` the track's width (the planar model does not see it, so it is a
//!   parameter).
//! * Unloading and reloading below the largest pressure reached: elastic,
//!   `p = K_e (z − z_p)`, with `z_p` the plastic sinkage left behind (the
//!   linear unloading of Wong's repetitive-loading model and of Chrono's
//!   SCM).
//! * Shear: Mohr–Coulomb strength `τ_max = c + p tan φ`, mobilised with the
//!   shear displacement `j` by Janosi–Hanamoto,
//!   `τ = τ_max (1 − e^{−j/K})`.
//!
//! [`Soil`] holds a soil's parameters and evaluates the laws;
//! [`SoilPreset`] names the rows of Wong's Table 2.3; [`SoilMemory`] is
//! what a patch of ground remembers of its loading (the plastic sinkage
//! and the yield pressure). The closed forms of a track on soil under a
//! uniform pressure (Wong, chapter 2: [`Soil::static_sinkage`],
//! [`Soil::tractive_effort`],
//! [`Soil::compaction_resistance`]) are the test oracles of the simulated
//! soil.

use std::fmt;
use std::str::FromStr;

use thiserror::Error;

/// A soil's terramechanics parameters, SI units throughout (Wong's tables
/// give `k_c`, `k_φ` in kN and `c` in kPa: [`Soil::from_wong`] converts).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Soil {
    /// Sinkage exponent `n` (dimensionless, > 0).
    pub n: f64,
    /// Cohesive modulus `k_c`, N/m^(n+1) (≥ 0).
    pub k_c: f64,
    /// Frictional modulus `k_φ`, N/m^(n+2) (≥ 0).
    pub k_phi: f64,
    /// Cohesion `c`, Pa (≥ 0).
    pub cohesion: f64,
    /// Internal friction angle `φ`, degrees (0 ≤ φ < 90; tables give
    /// degrees).
    pub friction_angle_deg: f64,
    /// Shear deformation modulus `K` of Janosi–Hanamoto, m (> 0): the
    /// shear displacement that mobilises 63 % of the strength.
    pub shear_modulus: f64,
    /// Unloading and reloading stiffness `K_e`, Pa/m (≥ `k_φ`, as Chrono's
    /// SCM asks; keep it above the Bekker secant stiffness at working
    /// sinkage).
    pub unloading_stiffness: f64,
    /// Normal damping `R`, Pa s/m (≥ 0): a pressure `R · (rate of sinkage)`
    /// added while the ground is being pressed (Chrono's SCM,
    /// `SCMTerrain.cpp`).
    pub damping: f64,
}

/// Why a soil's parameters make no soil.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SoilError {
    /// A parameter is outside its range (or not a finite number).
    #[error("soil parameter `{name}` = {value} is out of range: it must be {allowed}")]
    OutOfRange {
        /// The parameter's field name.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    /// `k_c = k_φ = 0`: the soil carries no pressure at any sinkage.
    #[error("soil with k_c = k_φ = 0 carries no load: give one of them a positive value")]
    NoBearing,
    /// The unloading stiffness is below `k_φ`.
    #[error(
        "soil unloading stiffness K_e = {unloading_stiffness} Pa/m is below k_φ = {k_phi}: unloading would be softer than loading"
    )]
    SoftUnloading {
        /// `K_e`, Pa/m.
        unloading_stiffness: f64,
        /// `k_φ`, N/m^(n+2).
        k_phi: f64,
    },
    /// A preset's name is not known.
    #[error("unknown soil `{0}`: one of {names}", names = SoilPreset::names())]
    UnknownPreset(String),
}

/// Default `K_e`, Pa/m, for the textbook soils, which have none: the
/// softest of Chrono's SCM presets (its co-simulation "soft" set,
/// `data/vehicle/cosim/terrain/scm_soft.json`),
/// 200 times the stiffest `k_φ` of Table 2.3 and far above the Bekker
/// secant stiffness of every row at 1 cm or more of sinkage.
pub const DEFAULT_UNLOADING_STIFFNESS: f64 = 4e7;

/// Default `R`, Pa s/m: Chrono's SCM demos and presets
/// (`demo_VEH_SCMTerrain_TrackedVehicle.cpp`, `scm_soft.json`).
pub const DEFAULT_DAMPING: f64 = 3e4;

impl Soil {
    /// A soil from a row of Wong's Table 2.3 as printed (`k_c` in
    /// kN/m^(n+1), `k_φ` in kN/m^(n+2), `c` in kPa, `φ` in degrees), with
    /// `K` in m and the default `K_e` and `R`.
    pub fn from_wong(
        n: f64,
        k_c: f64,
        k_phi: f64,
        c: f64,
        phi_deg: f64,
        shear_modulus: f64,
    ) -> Soil {
        Soil {
            n,
            k_c: k_c * 1e3,
            k_phi: k_phi * 1e3,
            cohesion: c * 1e3,
            friction_angle_deg: phi_deg,
            shear_modulus,
            unloading_stiffness: DEFAULT_UNLOADING_STIFFNESS,
            damping: DEFAULT_DAMPING,
        }
    }

    /// Checks every parameter's range; every soil built by hand should
    /// pass this before it is used.
    pub fn check(&self) -> Result<(), SoilError> {
        let range = |name, value: f64, ok: bool, allowed| {
            if ok && value.is_finite() {
                Ok(())
            } else {
                Err(SoilError::OutOfRange {
                    name,
                    value,
                    allowed,
                })
            }
        };
        range("n", self.n, self.n > 0.0, "positive")?;
        range("k_c", self.k_c, self.k_c >= 0.0, "zero or more")?;
        range("k_phi", self.k_phi, self.k_phi >= 0.0, "zero or more")?;
        range(
            "cohesion",
            self.cohesion,
            self.cohesion >= 0.0,
            "zero or more",
        )?;
        range(
            "friction_angle_deg",
            self.friction_angle_deg,
            (0.0..90.0).contains(&self.friction_angle_deg),
            "at least 0 and below 90 degrees",
        )?;
        range(
            "shear_modulus",
            self.shear_modulus,
            self.shear_modulus > 0.0,
            "positive",
        )?;
        range(
            "unloading_stiffness",
            self.unloading_stiffness,
            self.unloading_stiffness > 0.0,
            "positive",
        )?;
        range("damping", self.damping, self.damping >= 0.0, "zero or more")?;
        if self.k_c == 0.0 && self.k_phi == 0.0 {
            return Err(SoilError::NoBearing);
        }
        if self.unloading_stiffness < self.k_phi {
            return Err(SoilError::SoftUnloading {
                unloading_stiffness: self.unloading_stiffness,
                k_phi: self.k_phi,
            });
        }
        Ok(())
    }

    /// Bekker's modulus `k_c/b + k_φ` for a track of width `width` (m),
    /// N/m^(n+2).
    pub fn modulus(&self, width: f64) -> f64 {
        self.k_c / width + self.k_phi
    }

    /// Bekker's pressure at sinkage `z` (m) under a track of width `width`
    /// (m), Pa: `(k_c/b + k_φ) zⁿ`, zero for `z ≤ 0`.
    pub fn bekker_pressure(&self, z: f64, width: f64) -> f64 {
        if z <= 0.0 {
            0.0
        } else {
            self.modulus(width) * z.powf(self.n)
        }
    }

    /// `tan φ`.
    pub fn tan_phi(&self) -> f64 {
        self.friction_angle_deg.to_radians().tan()
    }

    /// Mohr–Coulomb strength at normal pressure `p` (Pa): `c + p tan φ`, Pa.
    pub fn shear_strength(&self, p: f64) -> f64 {
        self.shear_law().strength(p)
    }

    /// Janosi–Hanamoto: the shear stress (Pa) mobilised at pressure `p`
    /// (Pa) by a shear displacement of magnitude `j` (m),
    /// `(c + p tan φ)(1 − e^{−j/K})`.
    pub fn shear_stress(&self, p: f64, j: f64) -> f64 {
        self.shear_law().stress(p, j)
    }

    /// The shear laws with `tan φ` worked out once, for evaluating them
    /// many times.
    pub fn shear_law(&self) -> ShearLaw {
        ShearLaw {
            cohesion: self.cohesion,
            tan_phi: self.tan_phi(),
            shear_modulus: self.shear_modulus,
        }
    }

    /// Spec "Closed-form checks" (a): the sinkage (m) of a rigid track of
    /// width `width` and contact length `length` (m) under a load `load`
    /// (N), uniformly spread: `z₀ = (W/(b l) / (k_c/b + k_φ))^{1/n}`.
    pub fn static_sinkage(&self, load: f64, width: f64, length: f64) -> f64 {
        (load / (width * length) / self.modulus(width)).powf(1.0 / self.n)
    }

    /// Bekker's compaction (rut-making) resistance of one track, N, at the
    /// sinkage of [`static_sinkage`](Self::static_sinkage):
    /// `R_c = b (k_c/b + k_φ) z₀^{n+1} / (n + 1)`.
    pub fn compaction_resistance(&self, load: f64, width: f64, length: f64) -> f64 {
        let z0 = self.static_sinkage(load, width, length);
        width * self.modulus(width) * z0.powf(self.n + 1.0) / (self.n + 1.0)
    }

    /// Spec "Closed-form checks" (b), after Wong: the tractive effort (N) of
    /// a track of width `width` and contact length `length` (m) under a
    /// uniform pressure from load `load` (N), at slip `slip` (> 0):
    /// `F = (A c + W tan φ)[1 − K/(i l) (1 − e^{−i l/K})]`.
    pub fn tractive_effort(&self, load: f64, width: f64, length: f64, slip: f64) -> f64 {
        let limit = width * length * self.cohesion + load * self.tan_phi();
        let x = slip * length / self.shear_modulus;
        // 1 − (1 − e^{−x})/x, written to keep its accuracy at small x.
        let mobilised = if x.abs() < 1e-4 {
            x / 2.0 - x * x / 6.0
        } else {
            1.0 + (-x).exp_m1() / x
        };
        limit * mobilised
    }
}

/// Mohr–Coulomb strength and Janosi–Hanamoto shear, the one owner of both
/// ([`Soil::shear_law`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearLaw {
    /// Cohesion `c`, Pa.
    pub cohesion: f64,
    /// `tan φ`.
    pub tan_phi: f64,
    /// Shear deformation modulus `K`, m.
    pub shear_modulus: f64,
}

impl ShearLaw {
    /// Mohr–Coulomb strength at normal pressure `p` (Pa): `c + p tan φ`, Pa.
    #[inline]
    pub fn strength(&self, p: f64) -> f64 {
        self.cohesion + p * self.tan_phi
    }

    /// The shear stress (Pa) mobilised at pressure `p` (Pa) by a shear
    /// displacement of magnitude `|j|` (m): `(c + p tan φ)(1 − e^{−|j|/K})`.
    #[inline]
    pub fn stress(&self, p: f64, j: f64) -> f64 {
        self.strength(p) * -(-j.abs() / self.shear_modulus).exp_m1()
    }
}

/// What a patch of ground remembers of its loading: the plastic sinkage
/// left behind and the pressure at which the soil yields again.
///
/// Fresh soil is `SoilMemory::default()` (no plastic sinkage, yielding at
/// once). The pressure under a sinkage `z` is elastic up to the deepest
/// sinkage reached before, `z_y = z_p + p_y / K_e`, and Bekker's beyond it:
/// continuous at `z_y`, where `K_e (z_y − z_p) = p_y = (k_c/b + k_φ) z_yⁿ`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SoilMemory {
    /// Plastic sinkage `z_p`, m: where the unloaded surface lies.
    pub plastic: f64,
    /// Yield pressure `p_y`, Pa: the largest pressure reached so far.
    pub yield_pressure: f64,
}

impl SoilMemory {
    /// The deepest sinkage reached so far, m.
    pub fn deepest(&self, soil: &Soil) -> f64 {
        self.plastic + self.yield_pressure / soil.unloading_stiffness
    }

    /// The pressure (Pa) at sinkage `z` (m) under a track of width `width`
    /// (m), without damping: elastic (`K_e (z − z_p)`, never pulling) up
    /// to the deepest sinkage reached, Bekker's beyond it.
    pub fn pressure(&self, soil: &Soil, z: f64, width: f64) -> f64 {
        if z > self.deepest(soil) {
            soil.bekker_pressure(z, width)
        } else {
            (soil.unloading_stiffness * (z - self.plastic)).max(0.0)
        }
    }

    /// The memory after the ground has been pressed to sinkage `z` (m):
    /// deeper than before, the soil yielded, and its new plastic sinkage is
    /// what is left when the elastic part springs back,
    /// `z_p = z − p/K_e`.
    pub fn pressed_to(&self, soil: &Soil, z: f64, width: f64) -> SoilMemory {
        if z > self.deepest(soil) {
            let p = soil.bekker_pressure(z, width);
            SoilMemory {
                plastic: z - p / soil.unloading_stiffness,
                yield_pressure: p,
            }
        } else {
            *self
        }
    }
}

/// The textbook soils: rows of Wong, *Theory of Ground Vehicles*, 4th ed.,
/// Table 2.3, with the shear modulus `K` (not in that table) as commonly
/// quoted from Wong's chapter 2 after Bekker (1 cm firm sandy terrain, 2.5 cm loose sand, 0.6 cm
/// clay; where no textbook value exists — loams, snow — 2.5 cm, the middle
/// of the 2–3 cm third-party scripts use, marked on each), and the default
/// `K_e` and `R`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SoilPreset {
    /// Dry sand (Land Locomotion Lab., 0 % moisture); `K` 2.5 cm (loose
    /// sand).
    DrySand,
    /// Sandy loam (LLL, 15 %); `K` 2.5 cm (no textbook value).
    SandyLoam,
    /// Clayey soil (Thailand, 38 %); `K` 0.6 cm (clay).
    Clay,
    /// Heavy clay (WES, 25 %); `K` 0.6 cm (clay).
    HeavyClay,
    /// LETE sand (Wong); `K` 1.2 cm (Chrono's "hard" set).
    LeteSand,
    /// Snow (U.S.); `K` 2.5 cm (no textbook value).
    Snow,
}

impl SoilPreset {
    /// Every preset, in the order listed.
    pub const ALL: [SoilPreset; 6] = [
        SoilPreset::DrySand,
        SoilPreset::SandyLoam,
        SoilPreset::Clay,
        SoilPreset::HeavyClay,
        SoilPreset::LeteSand,
        SoilPreset::Snow,
    ];

    /// The preset's name on a command line (`dry-sand`, …).
    pub fn name(self) -> &'static str {
        match self {
            SoilPreset::DrySand => "dry-sand",
            SoilPreset::SandyLoam => "sandy-loam",
            SoilPreset::Clay => "clay",
            SoilPreset::HeavyClay => "heavy-clay",
            SoilPreset::LeteSand => "lete-sand",
            SoilPreset::Snow => "snow",
        }
    }

    /// All names, comma-separated.
    pub fn names() -> String {
        Self::ALL.map(Self::name).join(", ")
    }

    /// The soil.
    pub fn soil(self) -> Soil {
        match self {
            SoilPreset::DrySand => Soil::from_wong(1.1, 0.99, 1528.43, 1.04, 28.0, 0.025),
            SoilPreset::SandyLoam => Soil::from_wong(0.7, 5.27, 1515.04, 1.72, 29.0, 0.025),
            SoilPreset::Clay => Soil::from_wong(0.5, 13.19, 692.15, 4.14, 13.0, 0.006),
            SoilPreset::HeavyClay => Soil::from_wong(0.13, 12.70, 1555.95, 68.95, 34.0, 0.006),
            SoilPreset::LeteSand => Soil::from_wong(0.79, 102.0, 5301.0, 1.3, 31.1, 0.012),
            SoilPreset::Snow => Soil::from_wong(1.6, 4.37, 196.72, 1.03, 19.7, 0.025),
        }
    }
}

impl fmt::Display for SoilPreset {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for SoilPreset {
    type Err = SoilError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| SoilError::UnknownPreset(s.to_string()))
    }
}
