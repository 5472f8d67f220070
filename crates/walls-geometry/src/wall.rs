//! A wall decoded from its keywords once: [`Wall::decode`] is the one place the back end
//! reads a resolved wall's tokens. Everything downstream (contacts, bounds, meshes,
//! previews, the plan) reads the typed parts: [`Shape`], [`Motion`], [`Material`],
//! [`Appearance`] and [`Reactive`].

use crate::material::{Material, OptionalMaterial};
use crate::motion::{Motion, Oscillation};
use crate::shape::{
    Disk, FiniteCylinder, InfiniteCylinder, Plane, Rectangle, Shape, Shell, Triangle,
};
use nalgebra::Vector3;
use walls_keywords::{Keyword, WallType};
use walls_model::Scene;

type Vec3 = Vector3<f64>;

/// How ssdraw draws a wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Appearance {
    /// The ssdraw colour index (0: not drawn).
    pub color: i64,
    /// Transparency, as written (0 opaque, 1 invisible).
    pub transparency: f64,
}

/// A wall's reactive values (docs/spec.md §3 "Reactive walls"): they matter for walls
/// with a finite mass and an assembly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reactive {
    /// The mass (0: infinite, the wall does not react).
    pub mass: f64,
    /// The `assembly` number (negative: none).
    pub assembly: i64,
    /// The assembly's centre of gravity.
    pub cog: Vec3,
    /// The principal moments: the diagonal of `ixj-vec`, `iyj-vec`, `izj-vec` (pkdgrav
    /// uses only the diagonal).
    pub inertia: Vec3,
    /// The principal axes `pxj-vec`, `pyj-vec`, `pzj-vec`.
    pub axes: [Vec3; 3],
    /// The angular velocity `rot-vec`, in the body frame.
    pub rot_vec: Vec3,
}

impl Reactive {
    /// Whether the wall belongs to a moving assembly: a positive finite mass and an
    /// assembly number of 0 or more.
    pub fn is_heavy(&self) -> bool {
        self.mass > 0.0 && self.mass.is_finite() && self.assembly >= 0
    }
}

/// One wall as the back end uses it.
#[derive(Debug, Clone, PartialEq)]
pub struct Wall {
    /// Its index among the walls (pkdgrav's wall id), from 0.
    pub index: usize,
    /// Its shape with its origin where the file puts it (`origin`), before any motion.
    pub shape: Shape,
    /// How it moves.
    pub motion: Motion,
    /// Its contact values as written, with pkdgrav's fall-backs (−1, 99) unresolved:
    /// [`Material::against`] resolves them.
    pub material: Material,
    /// Its values for cohesion and two-layer contacts (pkdgrav's optional builds), as
    /// written.
    pub optional: OptionalMaterial,
    /// How it is drawn.
    pub appearance: Appearance,
    /// Its mass and assembly values.
    pub reactive: Reactive,
    /// The units the file was in when it described the wall: the scale it speaks in.
    pub units: walls_model::Units,
}

impl Wall {
    /// Decodes a resolved wall.
    pub fn decode(wall: &walls_model::Wall) -> Wall {
        let vector = |k| wall.vector(k);
        let number = |k| wall.number(k);
        let origin = vector(Keyword::Origin);
        let orient = vector(Keyword::Orient);
        let shape = match wall.wall_type() {
            WallType::Plane => Shape::Plane(Plane {
                origin,
                normal: orient,
            }),
            WallType::Triangle => Shape::Triangle(Triangle {
                origin,
                e1: vector(Keyword::Vertex1),
                e2: vector(Keyword::Vertex2),
            }),
            WallType::Rectangle => Shape::Rectangle(Rectangle {
                origin,
                e1: vector(Keyword::Vertex1),
                e2: vector(Keyword::Vertex2),
            }),
            WallType::Disk => Shape::Disk(Disk {
                center: origin,
                normal: orient,
                radius: number(Keyword::Radius),
                hole: number(Keyword::HoleRadius),
            }),
            WallType::CylinderInfinite => Shape::InfiniteCylinder(InfiniteCylinder {
                origin,
                axis: orient,
                radius: number(Keyword::Radius),
            }),
            WallType::CylinderFinite => Shape::FiniteCylinder(FiniteCylinder {
                center: origin,
                axis: orient,
                radius: number(Keyword::Radius),
                length: number(Keyword::Length),
                taper: number(Keyword::Taper),
            }),
            WallType::Shell => Shape::Shell(Shell {
                center: origin,
                axis: orient,
                radius: number(Keyword::Radius),
                open: number(Keyword::OpenAngle).to_radians(),
            }),
        };
        let motion = Motion {
            origin,
            velocity: vector(Keyword::Velocity),
            oscillation: Oscillation {
                amplitude: number(Keyword::OscAmpl),
                frequency: number(Keyword::OscFreq),
                phase: number(Keyword::OscPhase),
                direction: vector(Keyword::OscVec),
            },
            step: number(Keyword::Step),
            spin_axis: orient,
            ang_speed: number(Keyword::AngSpeed),
        };
        let material = Material {
            eps_n: number(Keyword::Epsn),
            eps_t: number(Keyword::Epst),
            k_n: number(Keyword::KN),
            k_t: number(Keyword::KT),
            mu_s: number(Keyword::MuS),
            mu_r: number(Keyword::MuR),
            mu_t: number(Keyword::MuT),
            beta_s: number(Keyword::BetaS),
        };
        let optional = OptionalMaterial {
            cohesion_model: wall.integer(Keyword::CohesionModel),
            cohesive_coeff: number(Keyword::CohesiveCoeff),
            inner_overlap_boundary: number(Keyword::InnerOverlapBoundary),
            k_n_outer: number(Keyword::KNOuter),
            k_t_outer: number(Keyword::KTOuter),
            k_n_inner: number(Keyword::KNInner),
            k_t_inner: number(Keyword::KTInner),
        };
        let appearance = Appearance {
            color: wall.integer(Keyword::Color),
            transparency: number(Keyword::Transparency),
        };
        let reactive = Reactive {
            mass: number(Keyword::Mass),
            assembly: wall.integer(Keyword::Assembly),
            cog: vector(Keyword::Cog),
            inertia: Vec3::new(
                vector(Keyword::IxjVec).x,
                vector(Keyword::IyjVec).y,
                vector(Keyword::IzjVec).z,
            ),
            axes: [Keyword::PxjVec, Keyword::PyjVec, Keyword::PzjVec].map(vector),
            rot_vec: vector(Keyword::RotVec),
        };
        Wall {
            index: wall.index,
            shape,
            motion,
            material,
            optional,
            appearance,
            reactive,
            units: wall.units,
        }
    }

    /// Its origin at t = 0 as the runs and previews place it: where [`Motion::position`]
    /// puts it, or its `origin` if that overflows.
    pub fn origin_at_start(&self) -> Vec3 {
        self.motion.position_or_origin(0.0)
    }
}

/// Where each token that set something for `wall` is written, by the token's name: the
/// span of its values (in the wall's own block or a `defaults` block), for reports that
/// point at a token of a decoded wall (a run directory's check before the job).
pub fn token_spans(wall: &walls_model::Wall) -> Vec<(&'static str, std::ops::Range<usize>)> {
    (wall.settings.iter())
        .filter_map(|(k, s)| Some((k.name(), s.source.span()?)))
        .collect()
}

/// Every wall of `scene`, decoded, in file order.
pub fn decode(scene: &Scene) -> Vec<Wall> {
    scene.walls.iter().map(Wall::decode).collect()
}
