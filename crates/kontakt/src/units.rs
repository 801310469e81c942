//! Unit aliases. kontakt uses one consistent system everywhere, with no conversion inside
//! the library:
//!
//! | quantity | unit | alias |
//! |---|---|---|
//! | length | millimetre (mm) | [`Millimetre`] |
//! | force | newton (N) | [`Newton`] |
//! | stress, pressure, modulus | megapascal (MPa = N/mm²) | [`Megapascal`] |
//! | time | second (s) | [`Second`] |
//! | angle | radian (rad) | [`Radian`] |
//! | energy | newton-millimetre (N·mm = mJ) | [`NewtonMillimetre`] |
//! | mass | tonne (t = N·s²/mm) | [`Tonne`] |
//! | density | t/mm³ (steel: 7.85e-9) | [`TonnePerCubicMillimetre`] |
//! | velocity | mm/s | [`MillimetrePerSecond`] |
//! | surface energy, line load | N/mm (1 J/m² = 1e-3 N/mm) | [`NewtonPerMillimetre`] |
//!
//! The aliases are plain `f64`: they document intent, they do not enforce it.

/// Length in millimetres.
pub type Millimetre = f64;
/// Force in newtons.
pub type Newton = f64;
/// Stress, pressure or elastic modulus in megapascals (N/mm²).
pub type Megapascal = f64;
/// Time in seconds.
pub type Second = f64;
/// Angle in radians.
pub type Radian = f64;
/// Energy in newton-millimetres (millijoules).
pub type NewtonMillimetre = f64;
/// Mass in tonnes (the mass unit consistent with N, mm, s).
pub type Tonne = f64;
/// Density in tonnes per cubic millimetre (steel ≈ 7.85e-9).
pub type TonnePerCubicMillimetre = f64;
/// Velocity in millimetres per second.
pub type MillimetrePerSecond = f64;
/// Force per length (line load) or energy per area (surface energy) in N/mm.
pub type NewtonPerMillimetre = f64;
/// Stiffness in newtons per millimetre.
pub type NewtonPerMillimetreStiffness = f64;

/// Young's modulus of bearing steel (100Cr6 / AISI 52100), MPa, as used in the PimP papers
/// (Wirsching et al. 2019, 2020).
pub const STEEL_YOUNGS_MODULUS: Megapascal = 210_000.0;
/// Poisson's ratio of bearing steel.
pub const STEEL_POISSON_RATIO: f64 = 0.3;
/// Density of bearing steel, t/mm³ (7850 kg/m³).
pub const STEEL_DENSITY: TonnePerCubicMillimetre = 7.85e-9;
