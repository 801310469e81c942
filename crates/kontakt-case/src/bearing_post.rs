//! What follows a bearing's equilibrium, the same for every command that solves one: the
//! raceway pressures, the rating (`[bearing.rating]`: ISO 76, ISO 281, ISO/TS 16281) with its
//! warnings, and the most loaded contacts sized for the validity check
//! ([`crate::validity`]). The report of `kontakt bearing` (and of a
//! [`crate::BearingModel`]) and a bearing sweep's row both go through [`RollerPost::run`] or
//! [`BallPost::run`], so that a check cannot be added to one of them only.
//!
//! A post is planned once per bearing (the slices' Hertz contacts, the buffers) and then
//! allocates nothing per solve but for the texts of its warnings, which exist only when
//! there are any. Pressures in MPa, loads in N, moments in N·mm.

use crate::bearing_rating::{LifeInput, RatingReport, RatingSpec, checked_spec, rating};
use crate::bearing_slices::SliceSolver;
use crate::validity::{ContactSize, Size, add_size_warnings, size_verdicts};
use kontakt::hertz::HertzPointContact;
use kontakt::hertz::validity::{SizeCheck, WARN_SIZE_RATIO, line_size, point_size};
use kontakt::{Error, Result};
use kontakt_bearing::ball_equilibrium::BallSolution;
use kontakt_bearing::equilibrium::{Dof, RingLoad, RollerLoad, RollerSolution};
use kontakt_bearing::geometry::{
    BallBearing, BallBearingKind, DEFAULT_SLICES, RollerBearing, RollerBearingKind,
};
use kontakt_bearing::life::RatingType;
use kontakt_bearing::roller_equilibrium::RibContactSolver;
use kontakt_bearing::stress::RollerStress;

/// The most loaded contact on one raceway, sized against its bodies (Copy data: the
/// validity check's texts are made only when it speaks).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct MostLoaded {
    size: SizeCheck,
    at: At,
    /// The case keys of the two bodies without their `bearing.` prefix.
    keys: [&'static str; 2],
}

/// Which contact a [`MostLoaded`] is.
#[derive(Debug, Clone, Copy, PartialEq)]
enum At {
    /// The most loaded slice of roller `.0` on raceway `.1`.
    Slice(usize, &'static str),
    /// The most loaded ball on raceway `.0`.
    Ball(&'static str),
    /// The most loaded roller's rib contact.
    Rib,
}

impl MostLoaded {
    /// As the validity check's contact, with its case keys and label.
    fn contact_size(&self) -> ContactSize {
        let at = match self.at {
            At::Slice(j, ring) => {
                format!("the most loaded slice of roller {j} on the {ring} raceway")
            }
            At::Ball(ring) => format!("the most loaded ball on the {ring} raceway"),
            At::Rib => "the most loaded roller's rib contact".to_string(),
        };
        let [k1, k2] = self.keys.map(|k| format!("bearing.{k}"));
        ContactSize::new(Size::Hertz(self.size), [&k1, &k2]).at(at)
    }
}

/// What a solve gives after the equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Post {
    /// The largest raceway pressure `[inner, outer]` of any element, MPa.
    pub(crate) max_pressure_mpa: [f64; 2],
    /// The rating (`[bearing.rating]`), its warnings already in the solve's warnings.
    pub(crate) rating: RatingReport,
    /// The most loaded contact on the inner and on the outer raceway, and on a rib (none
    /// without load).
    contacts: [Option<MostLoaded>; 3],
}

impl Post {
    /// The contacts for a report's validity check ([`crate::validity::checked`]).
    pub(crate) fn contact_sizes(&self) -> Vec<ContactSize> {
        self.contacts
            .iter()
            .flatten()
            .map(MostLoaded::contact_size)
            .collect()
    }

    /// The validity check of the contacts without a report (a sweep's row): the warnings
    /// first in `warnings` as [`crate::validity::checked`] puts them, or its refusal. A
    /// contact below the warning ratio says nothing, so only those above are made texts.
    ///
    /// # Errors
    /// The refusal of a contact as large as a body's radius of curvature.
    pub(crate) fn check_sizes(&self, warnings: &mut Vec<String>) -> Result<()> {
        if self
            .contacts
            .iter()
            .flatten()
            .all(|c| c.size.ratio <= WARN_SIZE_RATIO)
        {
            return Ok(());
        }
        add_size_warnings(size_verdicts(&self.contact_sizes())?, warnings);
        Ok(())
    }
}

/// A bearing's rating spec and type.
#[derive(Debug, Clone, Copy)]
struct Rater {
    spec: RatingSpec,
    kind: RatingType,
}

impl Rater {
    /// [`rating`] of a solve that carries `load` under the applied moment `moment` with the
    /// largest raceway pressures `p_max` (MPa).
    fn rate(
        &self,
        load: [f64; 5],
        moment: f64,
        p_max: [f64; 2],
        life: LifeInput<'_>,
        warnings: &mut Vec<String>,
    ) -> Result<RatingReport> {
        let p = p_max[0].max(p_max[1]);
        rating(self.kind, &self.spec, load, moment, p, life, warnings)
    }
}

/// The post of a roller bearing, planned once.
#[derive(Debug, Clone)]
pub(crate) struct RollerPost {
    stress: RollerStress,
    rater: Rater,
    coarse: Option<String>,
    /// One roller's slice pressures, inner and outer raceway, MPa.
    inner: Vec<f64>,
    outer: Vec<f64>,
    /// The raceway loads of a rib-contact model's rollers.
    ring: Vec<RollerLoad>,
}

impl RollerPost {
    /// Plan the post of `b` with the rating `spec` (`[bearing.rating]`).
    ///
    /// # Errors
    /// An invalid rating (named `bearing.rating.*`); a slice that is no Hertz line contact.
    pub(crate) fn new(b: &RollerBearing, spec: Option<&RatingSpec>) -> Result<Self> {
        let spec = checked_spec(spec, false)?;
        let kind = match b.kind {
            RollerBearingKind::Cylindrical => RatingType::Cylindrical,
            RollerBearingKind::Thrust => RatingType::Thrust,
            RollerBearingKind::Tapered => RatingType::Tapered {
                contact_angle_rad: b.contact_angle_rad,
            },
        };
        Ok(RollerPost {
            stress: RollerStress::new(b)?,
            rater: Rater { spec, kind },
            coarse: coarse_slices_warning(b.slices),
            inner: vec![0.0; b.slices],
            outer: vec![0.0; b.slices],
            ring: Vec::with_capacity(b.rollers),
        })
    }

    /// The post of `solver`'s solution `sol` under the applied moment `moment` (N·mm):
    /// adds the warnings to `warnings`; `each(j, [inner, outer] peaks, inner, outer, most)`
    /// receives the slice pressures (MPa) of every roller j, the model's own where it has
    /// them (coupled slices), else the Hertz line contacts of the independent slices.
    /// Allocates nothing but the texts of warnings.
    ///
    /// # Errors
    /// A non-finite slice load; the rating's errors.
    pub(crate) fn run<S: SliceSolver + ?Sized>(
        &mut self,
        solver: &S,
        sol: &RollerSolution,
        moment: f64,
        warnings: &mut Vec<String>,
        each: impl FnMut(usize, [f64; 2], &[f64], &[f64], bool),
    ) -> Result<Post> {
        let slices = Slices {
            bearing: solver.bearing(),
            rollers: solver.roller_loads(),
            loads: solver.slice_loads(),
            own: solver.slice_pressures(),
        };
        self.run_with(&slices, sol.load, moment, warnings, each)
    }

    /// [`RollerPost::run`] for the rib-contact roller model: the raceway pressures are the
    /// Hertz line contacts of the cup slices, the cone's scaled by the roller's
    /// cone-to-cup load ratio, and the most loaded rib contact is sized against the roller
    /// face's and the rib's radii.
    ///
    /// # Errors
    /// As [`RollerPost::run`]; the rib's Hertz contact's errors.
    pub(crate) fn run_rib(
        &mut self,
        solver: &RibContactSolver,
        sol: &RollerSolution,
        moment: f64,
        warnings: &mut Vec<String>,
        each: impl FnMut(usize, [f64; 2], &[f64], &[f64], bool),
    ) -> Result<Post> {
        // the raceway loads as the slice models give them, in a buffer planned once
        let mut ring = std::mem::take(&mut self.ring);
        ring.clear();
        ring.extend(solver.roller_loads().iter().map(|r| RollerLoad {
            azimuth_rad: r.azimuth_rad,
            outer_n: r.outer_n,
            inner_n: r.inner_n,
            rib_n: r.rib_n,
            max_approach_mm: r.max_approach_mm,
        }));
        let slices = Slices {
            bearing: solver.bearing(),
            rollers: &ring,
            loads: solver.cup_slice_loads(),
            own: None,
        };
        let post = self.run_with(&slices, sol.load, moment, warnings, each);
        self.ring = ring;
        let mut post = post?;
        let rib_max = solver.max_rib_load_n();
        if rib_max > 0.0 {
            let hertz = solver.rib_hertz();
            post.contacts[2] = Some(MostLoaded {
                size: point_size(hertz.geometry(), &hertz.solve_force(rib_max)?),
                at: At::Rib,
                keys: ["rib_contact.face", "rib_contact.rib"],
            });
        }
        Ok(post)
    }

    /// The post of a roller model's `slices` for the carried load `load` (N, N·mm).
    fn run_with(
        &mut self,
        slices: &Slices<'_>,
        load: [f64; 5],
        moment: f64,
        warnings: &mut Vec<String>,
        mut each: impl FnMut(usize, [f64; 2], &[f64], &[f64], bool),
    ) -> Result<Post> {
        warnings.extend(self.coarse.iter().cloned());
        let Slices {
            bearing: b,
            rollers,
            loads,
            own,
        } = *slices;
        let ns = b.slices;
        let most = (0..rollers.len()).fold(0, |m, j| {
            if rollers[j].outer_n > rollers[m].outer_n {
                j
            } else {
                m
            }
        });
        let peak = |p: &[f64]| p.iter().copied().fold(0.0, f64::max);
        let mut p_max = [0.0_f64; 2];
        // the most loaded slice of the most loaded roller on each raceway (Hertz)
        let mut most_slice = [None; 2];
        for (j, r) in rollers.iter().enumerate() {
            let q = &loads[j * ns..(j + 1) * ns];
            if own.is_none() || j == most {
                let m = self
                    .stress
                    .roller(q, ratio(r), &mut self.inner, &mut self.outer)?;
                if j == most {
                    for (ring, p) in [&self.inner, &self.outer].into_iter().enumerate() {
                        most_slice[ring] = (0..ns)
                            .max_by(|a, c| p[*a].total_cmp(&p[*c]))
                            .filter(|k| p[*k] > 0.0);
                    }
                }
                if own.is_none() {
                    each(j, m, &self.inner, &self.outer, j == most);
                    p_max = [p_max[0].max(m[0]), p_max[1].max(m[1])];
                }
            }
            if let Some((inner, outer)) = own {
                let (i, o) = (&inner[j * ns..(j + 1) * ns], &outer[j * ns..(j + 1) * ns]);
                let m = [peak(i), peak(o)];
                each(j, m, i, o, j == most);
                p_max = [p_max[0].max(m[0]), p_max[1].max(m[1])];
            }
        }
        let mut contacts = [None; 3];
        for (ring, name) in [(0, "inner"), (1, "outer")] {
            let Some(k) = most_slice[ring] else {
                continue;
            };
            let q = loads[most * ns + k];
            let load = if ring == 0 {
                q * ratio(&rollers[most])
            } else {
                q
            };
            let c = self.stress.contact(k, ring);
            let s = c.solve(load / self.stress.slice_width())?;
            contacts[ring] = Some(MostLoaded {
                size: line_size(c.radii(), &s),
                at: At::Slice(most, name),
                keys: ["roller_diameter_mm", "pitch_diameter_mm"],
            });
        }
        let inner_ratio = rollers.get(most).map_or(1.0, ratio);
        let life = LifeInput::Rollers(b, loads, inner_ratio);
        let rated = self.rater.rate(load, moment, p_max, life, warnings)?;
        Ok(Post {
            max_pressure_mpa: p_max,
            rating: rated,
            contacts,
        })
    }
}

/// What the post of a roller model reads of its solve.
#[derive(Clone, Copy)]
struct Slices<'a> {
    bearing: &'a RollerBearing,
    /// The raceway loads of every roller.
    rollers: &'a [RollerLoad],
    /// The outer raceway's slice loads, roller-major, N.
    loads: &'a [f64],
    /// The model's own slice pressures `(inner, outer)`, roller-major, MPa.
    own: Option<(&'a [f64], &'a [f64])>,
}

/// `Q_i/Q_o` of a roller (1 without load).
fn ratio(r: &RollerLoad) -> f64 {
    if r.outer_n > 0.0 {
        r.inner_n / r.outer_n
    } else {
        1.0
    }
}

/// The post of a ball bearing, planned once.
#[derive(Debug, Clone)]
pub(crate) struct BallPost {
    rater: Rater,
    /// The nominal contact angle of the reference life, rad.
    nominal: f64,
    /// The two Hertz contacts at the stiffness contact angle (`None`: their error, made
    /// again when a ball is loaded).
    pair: Option<[HertzPointContact; 2]>,
    /// The groove keys of the inner and outer raceway (without `bearing.`).
    keys: [&'static str; 2],
    /// The ball loads, N.
    loads: Vec<f64>,
}

impl BallPost {
    /// Plan the post of `solver`'s bearing with the rating `spec`; `keys` the case keys of
    /// the inner and outer groove (without `bearing.`).
    ///
    /// # Errors
    /// An invalid rating (named `bearing.rating.*`).
    pub(crate) fn new(
        b: &BallBearing,
        spec: Option<&RatingSpec>,
        keys: [&'static str; 2],
    ) -> Result<Self> {
        let spec = checked_spec(spec, true)?;
        let (kind, nominal) = match b.kind {
            BallBearingKind::DeepGroove => (RatingType::DeepGrooveBall, 0.0),
            BallBearingKind::AngularContact => (
                RatingType::AngularContactBall {
                    contact_angle_rad: b.contact_angle_rad,
                },
                b.contact_angle_rad,
            ),
        };
        Ok(BallPost {
            rater: Rater { spec, kind },
            nominal,
            pair: b.contacts(b.stiffness_contact_angle()).ok(),
            keys,
            loads: vec![0.0; b.balls],
        })
    }

    /// The post of the solution `sol` of bearing `b` whose balls carry `loads` on the inner
    /// ring (N, one per ball) and each raceway's most loaded contact `q_max` (N, `[inner,
    /// outer]`), under the applied moment `moment` (N·mm): adds the warnings to `warnings`;
    /// `field` names a geometry error by its case key. The pressures are those of the
    /// library's Hertz contacts at the stiffness contact angle, and so are the most loaded
    /// contacts, sized against the ball and the groove. Allocates nothing but the texts of
    /// warnings.
    ///
    /// # Errors
    /// The rating's errors; the Hertz contacts' errors.
    #[allow(clippy::too_many_arguments)] // the solve's parts, each once
    pub(crate) fn run(
        &mut self,
        b: &BallBearing,
        sol: &BallSolution,
        loads: impl Iterator<Item = f64>,
        q_max: [f64; 2],
        moment: f64,
        warnings: &mut Vec<String>,
        field: impl Fn(Error) -> Error,
    ) -> Result<Post> {
        for (q, load) in self.loads.iter_mut().zip(loads) {
            *q = load;
        }
        let p_max = sol.max_pressure_mpa;
        let life = LifeInput::Balls(b, self.nominal, &self.loads);
        let rated = self.rater.rate(sol.load, moment, p_max, life, warnings)?;
        let mut contacts = [None; 3];
        if q_max[0].max(q_max[1]) > 0.0 {
            let pair = match self.pair {
                Some(p) => p,
                None => b.contacts(b.stiffness_contact_angle()).map_err(field)?,
            };
            for (ring, name) in [(0, "inner"), (1, "outer")] {
                if q_max[ring] > 0.0 {
                    let c = &pair[ring];
                    contacts[ring] = Some(MostLoaded {
                        size: point_size(c.geometry(), &c.solve_force(q_max[ring])?),
                        at: At::Ball(name),
                        keys: ["ball_diameter_mm", self.keys[ring]],
                    });
                }
            }
        }
        Ok(Post {
            max_pressure_mpa: p_max,
            rating: rated,
            contacts,
        })
    }
}

/// The warning of a roller bearing with fewer slices than the default (a property of the
/// bearing, the same for every load).
fn coarse_slices_warning(slices: usize) -> Option<String> {
    (slices < DEFAULT_SLICES).then(|| {
        format!(
            "{slices} slices per roller: fewer than the recommended {DEFAULT_SLICES}, the roller loads are coarse (docs/bearing-model.md §6)"
        )
    })
}

/// The magnitude of the applied (force-controlled) moment, N·mm.
pub(crate) fn applied_moment(load: &RingLoad) -> f64 {
    let m = |d: Dof| match d {
        Dof::Force(v) => v,
        Dof::Displacement(_) => 0.0,
    };
    m(load.dofs[3]).hypot(m(load.dofs[4]))
}
