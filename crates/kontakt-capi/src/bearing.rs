//! The bearing element: a whole rolling bearing as one force element between a shaft and
//! a housing, over [`kontakt_case::bearing_model::BearingElement`] (a bearing case,
//! `method = "bearing"`, planned once by `BearingModel` and evaluated at many
//! displacements). docs/mbs.md, section "The bearing element from C", documents it.
//!
//! - Input: the inner ring's displacement relative to the outer ring,
//!   `δx, δy, δz` \[mm\], `θx, θy` \[rad\] (z the bearing axis; small rotations about x and
//!   y through the bearing centre), and its velocity `δ̇x, δ̇y, δ̇z` \[mm/s\],
//!   `θ̇x, θ̇y` \[rad/s\], in the outer ring's frame.
//! - Output: the bearing's reaction **on the inner ring** (force N, moment N·mm about the
//!   bearing centre; the outer ring gets minus it), the 5 × 5 stiffness
//!   `K = −∂reaction/∂displacement`, the damping part and a status with a message.
//! - Velocity: a viscous damping `β K` with β set by [`kontakt_bearing_element_set_damping`]
//!   (s, default 0: no effect).
//! - Friction: with a `[lubricant]` in the case, the bearing's friction torque about z, its
//!   power and breakdown (`friction_*` fields) at the ring speeds of
//!   [`kontakt_bearing_element_set_speeds`] (rad/s; initially the case's `[speed]`); while
//!   the rings turn relative to each other `moment[2]` is the friction moment on the inner
//!   ring, `−M sign(ω_i − ω_o)`; at equal speeds `friction_torque` is the starting torque and
//!   `moment[2]` 0. Without a lubricant `friction_status` is
//!   [`KONTAKT_FRICTION_OFF`] and the fields 0.

use crate::{
    Failure, KONTAKT_MESSAGE_LEN, c_message, create, doubles, from_case_file, guard, library_error,
    null, release, text,
};
use kontakt_case::bearing_model::{
    BearingElement, BearingElementOutput, BearingElementStatus, ElementFrictionStatus,
};
use std::ffi::c_char;

/// [`KontaktBearingResult::status`]: every rolling element is lifted off (zero force and
/// stiffness; [`KontaktBearingResult::message`] says so). Not an error.
pub const KONTAKT_BEARING_LIFTED_OFF: i32 = 0;
/// [`KontaktBearingResult::status`]: at least one rolling element carries load.
pub const KONTAKT_BEARING_LOADED: i32 = 1;

/// [`KontaktBearingResult::friction_status`]: the case has no `[lubricant]`, no friction
/// (every `friction_*` field 0).
pub const KONTAKT_FRICTION_OFF: i32 = 0;
/// [`KontaktBearingResult::friction_status`]: the rings turn relative to each other; the
/// running torque, applied as `moment[2]`.
pub const KONTAKT_FRICTION_RUNNING: i32 = 1;
/// [`KontaktBearingResult::friction_status`]: equal ring speeds; `friction_torque` is the
/// starting torque, not applied (`moment[2]` and `friction_power` 0).
pub const KONTAKT_FRICTION_STARTING: i32 = 2;
/// [`KontaktBearingResult::friction_status`]: a lubricant, but no friction model for this
/// bearing yet (ball and thrust bearings); every `friction_*` field 0.
pub const KONTAKT_FRICTION_NOT_BUILT: i32 = 3;

/// A bearing element planned from a bearing case (opaque; create with
/// [`kontakt_bearing_element_from_toml`] or [`kontakt_bearing_element_from_file`], release
/// with [`kontakt_bearing_element_free`]).
pub struct KontaktBearingElement {
    inner: BearingElement,
}

/// What a bearing element's evaluation returns: the bearing's reaction on the inner ring
/// in the outer ring's frame (z the bearing axis); N, N·mm.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct KontaktBearingResult {
    /// [`KONTAKT_BEARING_LIFTED_OFF`] (0) or [`KONTAKT_BEARING_LOADED`] (1).
    pub status: i32,
    /// Force of the bearing on the inner ring `Fx, Fy, Fz` \[N\], elastic plus damping; the
    /// outer ring gets minus this. Opposes the displacement: `δz > 0` pressing a tapered
    /// bearing gives `Fz < 0`.
    pub force: [f64; 3],
    /// Moment of the bearing on the inner ring about the bearing centre `Mx, My, Mz`
    /// \[N·mm\]; `Mz` is the friction moment `friction_inner_ring` (0 without a lubricant
    /// and at equal ring speeds).
    pub moment: [f64; 3],
    /// The damping part of `force` and `moment`, `−β K v`, in the order
    /// `Fx, Fy, Fz, Mx, My` \[N, N·mm\] (zero while β = 0).
    pub damping: [f64; 5],
    /// The stiffness `K[i][j] = ∂F_i/∂u_j` of the load the rolling elements carry
    /// (`= −∂reaction_i/∂u_j`), row-major, rows and columns `x, y, z, θx, θy`: N/mm,
    /// N/rad, N (moment per mm), N·mm/rad. Symmetric, positive semi-definite; the damping
    /// matrix is β times it.
    pub stiffness: [[f64; 5]; 5],
    /// The largest rolling-element load (a roller's outer raceway load, a ball's load)
    /// \[N\].
    pub max_element_load: f64,
    /// Newton iterations of the solve (0: every degree of freedom is prescribed).
    pub iterations: u64,
    /// Why the status is what it is, NUL-terminated UTF-8 (empty when loaded).
    pub message: [c_char; KONTAKT_MESSAGE_LEN],
    /// [`KONTAKT_FRICTION_OFF`], [`KONTAKT_FRICTION_RUNNING`],
    /// [`KONTAKT_FRICTION_STARTING`] or [`KONTAKT_FRICTION_NOT_BUILT`].
    pub friction_status: i32,
    /// Ring speeds of the friction `ω_i, ω_o` \[rad/s\] about +z.
    pub ring_speeds: [f64; 2],
    /// The bearing's friction torque M ≥ 0 \[N·mm\] (at equal speeds the starting torque).
    pub friction_torque: f64,
    /// The friction moment on the inner ring about +z, `−M sign(ω_i − ω_o)` \[N·mm\] (0 at
    /// equal speeds): `moment[2]`.
    pub friction_inner_ring: f64,
    /// Friction power `M |ω_i − ω_o|` \[W\] (0 at equal speeds).
    pub friction_power: f64,
    /// The shares of M: cone (inner raceway), cup (outer raceway), rib (roller ends), drag
    /// \[N·mm\]; they add up to `friction_torque`.
    pub friction_breakdown: [f64; 4],
}

impl KontaktBearingResult {
    /// The C record of `r`.
    pub fn from_output(r: &BearingElementOutput) -> Self {
        let f = &r.friction;
        KontaktBearingResult {
            status: match r.status {
                BearingElementStatus::LiftedOff => KONTAKT_BEARING_LIFTED_OFF,
                BearingElementStatus::Loaded => KONTAKT_BEARING_LOADED,
            },
            force: r.force_n,
            moment: r.moment_nmm,
            damping: r.damping,
            stiffness: r.stiffness,
            max_element_load: r.max_element_load_n,
            iterations: r.iterations as u64,
            message: c_message(r.message),
            friction_status: match f.status {
                ElementFrictionStatus::Off => KONTAKT_FRICTION_OFF,
                ElementFrictionStatus::Running => KONTAKT_FRICTION_RUNNING,
                ElementFrictionStatus::Starting => KONTAKT_FRICTION_STARTING,
                ElementFrictionStatus::NotBuilt => KONTAKT_FRICTION_NOT_BUILT,
            },
            ring_speeds: [f.inner_speed_rad_s, f.outer_speed_rad_s],
            friction_torque: f.torque_nmm,
            friction_inner_ring: f.inner_ring_nmm,
            friction_power: f.power_w,
            friction_breakdown: [f.cone_nmm, f.cup_nmm, f.rib_nmm, f.drag_nmm],
        }
    }
}

/// Create a bearing element from a bearing case (`method = "bearing"`, TOML text; the
/// schema of docs/case-schema.md; its `[load]` is required but not used). On success
/// `*out` is the new element (release it with [`kontakt_bearing_element_free`]); on failure
/// `*out` is set to null. The element starts undamped (β = 0).
///
/// Returns `KONTAKT_OK`, `KONTAKT_INVALID_INPUT` (a TOML error or a key
/// out of range, named in the message: `bearing.roller_diameter_mm`),
/// `KONTAKT_FAILED`, `KONTAKT_NULL_OR_UTF8` (`toml` or `out` null,
/// `toml` not UTF-8) or `KONTAKT_PANIC`.
///
/// # Safety
/// `toml` is null or a NUL-terminated string; `out` is null or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn kontakt_bearing_element_from_toml(
    toml: *const c_char,
    out: *mut *mut KontaktBearingElement,
) -> i32 {
    // SAFETY: `out` is null (refused) or writable; `toml` null (refused) or a
    // NUL-terminated string, by contract.
    unsafe {
        create(out, || {
            let text = text(toml, "toml")?;
            let inner = BearingElement::from_toml(text).map_err(library_error)?;
            Ok(KontaktBearingElement { inner })
        })
    }
}

/// Create a bearing element from a bearing case file (UTF-8 path). As
/// [`kontakt_bearing_element_from_toml`]; a file that cannot be read is
/// `KONTAKT_INVALID_INPUT` with field `path`.
///
/// # Safety
/// `path` is null or a NUL-terminated string; `out` is null or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn kontakt_bearing_element_from_file(
    path: *const c_char,
    out: *mut *mut KontaktBearingElement,
) -> i32 {
    // SAFETY: `out` is null (refused) or writable; `path` null (refused) or a
    // NUL-terminated string, by contract.
    unsafe {
        create(out, || {
            let inner = from_case_file(path, BearingElement::from_toml)?;
            Ok(KontaktBearingElement { inner })
        })
    }
}

/// The element behind a handle.
///
/// # Safety
/// `element` is null (refused) or from this API, alive and not used by another thread
/// during the call.
unsafe fn element<'a>(
    element: *mut KontaktBearingElement,
) -> Result<&'a mut BearingElement, Failure> {
    if element.is_null() {
        return Err(null("element"));
    }
    // SAFETY: non-null, from this API, alive and exclusively ours during the call.
    Ok(&mut unsafe { &mut *element }.inner)
}

/// Set the viscous damping of the element: the damping matrix is `damping_s` times the
/// stiffness (stiffness-proportional damping; β in s, finite, ≥ 0; default 0).
///
/// Returns `KONTAKT_OK`, `KONTAKT_INVALID_INPUT` (field `damping_s`,
/// negative or not finite: the element keeps its β), `KONTAKT_NULL_OR_UTF8` or
/// `KONTAKT_PANIC`.
///
/// # Safety
/// `element` is null or an element from this API, not yet freed and not used by another
/// thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn kontakt_bearing_element_set_damping(
    element: *mut KontaktBearingElement,
    damping_s: f64,
) -> i32 {
    guard(|| {
        // SAFETY: by the caller's contract.
        let e = unsafe { self::element(element) }?;
        e.set_damping(damping_s).map_err(library_error)
    })
}

/// Set the ring speeds of the element's friction torque: inner ring `inner_rad_s`, outer
/// ring `outer_rad_s`, rad/s about +z (finite, |ω| ≤ 100 000 r/min). They change the
/// friction only, not the load distribution (whose centrifugal forces stay those of the
/// case's `[speed]`). Equal speeds give the starting torque. Without a lubricant in the case
/// the speeds are kept but have no effect.
///
/// Returns `KONTAKT_OK`, `KONTAKT_INVALID_INPUT` (field `inner_rad_s` or `outer_rad_s`: not
/// finite or too fast; the element keeps its speeds), `KONTAKT_NULL_OR_UTF8` or
/// `KONTAKT_PANIC`.
///
/// # Safety
/// `element` is null or an element from this API, not yet freed and not used by another
/// thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn kontakt_bearing_element_set_speeds(
    element: *mut KontaktBearingElement,
    inner_rad_s: f64,
    outer_rad_s: f64,
) -> i32 {
    guard(|| {
        // SAFETY: by the caller's contract.
        let e = unsafe { self::element(element) }?;
        e.set_speeds(inner_rad_s, outer_rad_s)
            .map_err(library_error)
    })
}

/// Evaluate the bearing at the inner ring's `displacement` relative to the outer ring
/// (`δx, δy, δz` \[mm\], `θx, θy` \[rad\]; z the bearing axis) and its `velocity`
/// (`mm/s`, `rad/s`, same order), and write the bearing's reaction on the inner ring to
/// `*out` (left unchanged on failure), with the friction torque at the element's ring
/// speeds when its case has a `[lubricant]`. Warm-started from the element's previous call;
/// allocates nothing (but the rib contact fields of a lubricated rib-contact bearing).
///
/// Returns `KONTAKT_OK` (also when every rolling element is lifted off: then
/// `status` is [`KONTAKT_BEARING_LIFTED_OFF`], force and stiffness zero),
/// `KONTAKT_INVALID_INPUT` (field `displacement[i]` or `velocity[i]`: not finite,
/// or a displacement beyond the model's validity — a translation above the rolling
/// element's diameter, or a tilt moving the ring by more than that at the pitch radius),
/// `KONTAKT_FAILED` (the solver did not converge), `KONTAKT_NULL_OR_UTF8`
/// or `KONTAKT_PANIC`.
///
/// # Safety
/// `element` is null or an element from this API, not yet freed and not used by another
/// thread during the call; `displacement` and `velocity` are null or point to 5 doubles;
/// `out` is null or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn kontakt_bearing_element_evaluate(
    element: *mut KontaktBearingElement,
    displacement: *const f64,
    velocity: *const f64,
    out: *mut KontaktBearingResult,
) -> i32 {
    guard(|| {
        // SAFETY: by the caller's contract.
        let e = unsafe { self::element(element) }?;
        if out.is_null() {
            return Err(null("out"));
        }
        // SAFETY: each pointer is null (refused) or points to 5 doubles.
        let (u, v) = unsafe {
            (
                doubles::<5>(displacement, "displacement")?,
                doubles::<5>(velocity, "velocity")?,
            )
        };
        let r = e.evaluate(u, v).map_err(library_error)?;
        // SAFETY: `out` is non-null and writable by the caller's contract.
        unsafe { out.write(KontaktBearingResult::from_output(&r)) };
        Ok(())
    })
}

/// Forget the element's last equilibrium (the next evaluation starts from the closed
/// forms). Returns `KONTAKT_OK` or `KONTAKT_NULL_OR_UTF8`.
///
/// # Safety
/// `element` is null or an element from this API, not yet freed and not used by another
/// thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn kontakt_bearing_element_reset(element: *mut KontaktBearingElement) -> i32 {
    guard(|| {
        // SAFETY: by the caller's contract.
        unsafe { self::element(element) }?.reset();
        Ok(())
    })
}

/// Release a bearing element. Null is ignored.
///
/// # Safety
/// `element` is null or an element from this API that is not used afterwards (freeing it
/// twice is undefined behaviour).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn kontakt_bearing_element_free(element: *mut KontaktBearingElement) {
    // SAFETY: null or from this API and freed once (the caller's contract).
    unsafe { release(element) }
}
