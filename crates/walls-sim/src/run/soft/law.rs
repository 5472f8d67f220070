//! What the soft-sphere run decides once at set-up about its contacts: the fractions of
//! a step each kick covers ([`Kicks`]), and the contact law with pkdgrav's choices for
//! rolling and twisting ([`ContactLaw`]), the same for walls and pairs; with the one
//! place that turns those choices into a [`Dashpot`] contact's rolling radius and
//! constant torques ([`ContactLaw::rolling`]).

use super::{Integrator, Settings, Vec3};
use crate::contact::ssdem::{ConstantTorque, Sliding, lever_contact_radius};
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;

#[cfg(doc)]
use crate::contact::ssdem::Dashpot;

/// The fractions of a step each kick of the integrator covers, and how far ahead the
/// dashpot's velocities are predicted.
#[derive(Clone, Copy)]
pub(super) struct Kicks {
    /// The kick before the drift.
    pub(super) opening: f64,
    /// The kick after the drift, with the last acceleration.
    pub(super) late: f64,
    /// The kick after the forces.
    pub(super) closing: f64,
    /// The contact-velocity prediction with the last acceleration, against walls.
    pub(super) predict: f64,
    /// The prediction of spins (against walls and particles) and of the velocities of
    /// particles meeting each other.
    pub(super) predict_all: f64,
    /// pkdgrav's levers (docs/pkdgrav-physics.md §1.1) instead of the radii.
    pub(super) pkdgrav_levers: bool,
}

impl Kicks {
    pub(super) fn of(integrator: Integrator) -> Kicks {
        let (opening, late, closing, predict, predict_all) = match integrator {
            Integrator::Leapfrog => (0.5, 0.0, 0.5, 0.0, 0.0),
            Integrator::LeapfrogPredicted => (0.5, 0.0, 0.5, 0.5, 0.0),
            Integrator::ExplicitEuler => (0.0, 1.0, 0.0, 0.0, 0.0),
            Integrator::Pkdgrav => (0.5, 0.0, 0.5, 0.5, 0.5),
        };
        Kicks {
            opening,
            late,
            closing,
            predict,
            predict_all,
            pkdgrav_levers: integrator == Integrator::Pkdgrav,
        }
    }

    /// pkdgrav's force evaluation at the start (docs/pkdgrav-physics.md §2): the
    /// velocities and spins as they are (v^pred = v, w^pred = w), and no kick after it.
    pub(super) fn at_start(self) -> Kicks {
        Kicks {
            closing: 0.0,
            predict: 0.0,
            predict_all: 0.0,
            ..self
        }
    }
}

/// The contact law of a run, against walls and between particles alike.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Law {
    /// pkdgrav's spring–dashpot, in its frame ([`crate::contact::ssdem::dashpot_contact_with`],
    /// docs/pkdgrav-physics.md §1.1–§1.5): pkdgrav's integrator, with friction, rolling,
    /// twisting or one of its optional builds.
    Pkdgrav,
    /// The spring–dashpot of [`crate::contact::ssdem::contact`] (with sliding friction)
    /// or [`crate::contact::ssdem::normal_contact`], with rolling and twisting
    /// resistance beside it.
    Linear,
}

/// The contact law of a run and pkdgrav's choices that shape it (its build and `.par`
/// keys), decided once at set-up ([`ContactLaw::of`]) for walls and pairs alike.
#[derive(Clone, Copy)]
pub(super) struct ContactLaw {
    pub(super) law: Law,
    /// pkdgrav's rolling radius is the contact radius (`bUseContactRadius`).
    contact_radius: bool,
    /// `bUseLegacyRoll`: the rolling levers are l₁, l₂ (docs/pkdgrav-physics.md §1.6).
    legacy_roll: bool,
    /// A build without `DEM_ROTATION_DASHPOT`: rolling and twisting are constant torques
    /// (docs/pkdgrav-physics.md §1.6) instead of springs.
    constant_torque: bool,
    /// What the shear spring of a sliding contact does.
    pub(super) sliding: Sliding,
}

/// One side of a contact as [`ContactLaw::rolling`] needs it: its radius, its lever,
/// its predicted spin and its moment of inertia (infinite for a stuck particle).
#[derive(Clone, Copy)]
pub(super) struct Side {
    pub(super) radius: f64,
    pub(super) lever: f64,
    pub(super) spin: Vec3,
    pub(super) inertia: f64,
}

impl ContactLaw {
    /// The law of a run with these settings, kicks, plan and optional physics.
    pub(super) fn of(
        settings: &Settings,
        kicks: &Kicks,
        plan: &Plan,
        optional: &OptionalPhysics,
    ) -> ContactLaw {
        let dashpot = plan.sliding_friction || plan.rolling || plan.twisting;
        ContactLaw {
            law: if kicks.pkdgrav_levers && (dashpot || optional.any()) {
                Law::Pkdgrav
            } else {
                Law::Linear
            },
            contact_radius: settings.contact_radius,
            legacy_roll: settings.legacy_roll,
            constant_torque: !settings.build.rotation_dashpot,
            sliding: settings.sliding,
        }
    }

    /// Whether a contact is pkdgrav's law with the rolling radius R* and the springs of
    /// `DEM_ROTATION_DASHPOT`: no contact radius, no constant torques (the contacts the
    /// four-at-a-time lanes take, [`crate::contact::lanes`]).
    pub(super) fn plain_dashpot(&self) -> bool {
        self.law == Law::Pkdgrav && !self.contact_radius && !self.constant_torque
    }

    /// pkdgrav's contact radius of a particle of radius `r` with lever `lever`, when the
    /// run uses it (`bUseContactRadius`, docs/pkdgrav-physics.md §1.4).
    #[inline(always)]
    pub(super) fn contact_radius(&self, r: f64, lever: f64) -> Option<f64> {
        self.contact_radius.then(|| lever_contact_radius(r, lever))
    }

    /// The rolling radius R* of a [`Dashpot`] contact of particle `one` with its
    /// `partner` (a wall when `None`), and, in a build without `DEM_ROTATION_DASHPOT`,
    /// its constant torques (docs/pkdgrav-physics.md §1.4, §1.6); `a` is the contact
    /// radius ([`ContactLaw::contact_radius`]). Between particles R* is the reduced
    /// radius r₁r₂/(r₁+r₂) (the contact radius with `bUseContactRadius`, never worked out
    /// with `bUseLegacyRoll` as well: 0), against a wall r₁ (or the contact radius); the
    /// rolling levers are R* for both sides (a wall's 0), l₁, l₂ with
    /// `bUseLegacyRoll`, the contact radius with `bUseContactRadius`.
    #[inline(always)]
    pub(super) fn rolling(
        &self,
        a: Option<f64>,
        one: Side,
        partner: Option<Side>,
    ) -> (f64, Option<ConstantTorque>) {
        let legacy = self.legacy_roll;
        let (radius, reduced, two) = match partner {
            Some(two) => {
                let reduced = one.radius * two.radius / (one.radius + two.radius);
                let radius = match a {
                    Some(_) if legacy => 0.0,
                    Some(a) => a,
                    None => reduced,
                };
                (radius, reduced, two)
            }
            None => {
                let wall = Side {
                    radius: 0.0,
                    lever: 0.0,
                    spin: Vec3::zeros(),
                    inertia: f64::INFINITY,
                };
                (a.unwrap_or(one.radius), one.radius, wall)
            }
        };
        let wall = partner.is_none();
        let torques = self.constant_torque.then(|| ConstantTorque {
            spins: (one.spin, two.spin),
            roll_levers: match (a, legacy) {
                (Some(a), _) => (a, if wall { 0.0 } else { a }),
                (None, true) => (one.lever, two.lever),
                (None, false) => (reduced, if wall { 0.0 } else { reduced }),
            },
            twist_radius: a.unwrap_or(0.0),
            inertias: (one.inertia, two.inertia),
        });
        (radius, torques)
    }
}
