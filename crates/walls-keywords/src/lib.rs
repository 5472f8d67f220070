//! The one table of the walls language's words.
//!
//! Every keyword pkdgrav's walls-file reader knows (docs/spec.md §1, including the five
//! undocumented two-layer contact tokens) and every wall type name, with what follows
//! each keyword. The lexer, the parser, "did you mean" suggestions, the grammar
//! documentation, the checker, hover and completion all read this table, so adding a token
//! is one row here plus its lexer attribute (a test keeps the two in step). A row's
//! [`ValueRange`] column names the rule that checks the keyword's value as pkdgrav reads
//! it; `walls-model` maps each range to the rule file that reports it.
//!
//! Beside the words, [`number`] is the one rule for numbers that every reader of the
//! tools follows: what a number's text or value means to pkdgrav, and which are refused
//! (not finite, overflow, underflow) or warned about (subnormal), and [`pkdgrav_units`]
//! holds pkdgrav's units in SI (what `lengthunit 1`, `massunit 1` and `timeunit 1` are),
//! the one place every tool takes them from.

pub mod number;
pub mod pkdgrav_units;

/// pkdgrav's two contact models: what a file is checked for, and how a run treats
/// contacts. The keyword table records which keywords only the soft-sphere model reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum ContactModel {
    /// Soft-sphere DEM (the default).
    #[default]
    Ssdem,
    /// Hard-sphere DEM.
    Hsdem,
}

/// What a keyword expects after it on its line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ValueShape {
    /// Nothing: `wall`, `defaults`.
    None,
    /// One decimal real.
    Number,
    /// One integer (pkdgrav reads it with `atoi`, so `12.5` would silently become 12).
    Integer,
    /// Exactly three decimal reals.
    Vector,
    /// One wall type name.
    TypeName,
}

impl ValueShape {
    /// How many values the shape takes.
    pub const fn arity(self) -> usize {
        match self {
            ValueShape::None => 0,
            ValueShape::Number | ValueShape::Integer | ValueShape::TypeName => 1,
            ValueShape::Vector => 3,
        }
    }

    /// The value as the grammar and messages name it.
    pub const fn describe(self) -> &'static str {
        match self {
            ValueShape::None => "no value",
            ValueShape::Number => "a number",
            ValueShape::Integer => "an integer",
            ValueShape::Vector => "a vector of 3 numbers",
            ValueShape::TypeName => "a wall type name",
        }
    }
}

/// Where a keyword may stand and what it does to the reader's state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Role {
    /// `wall` or `defaults`: opens a block.
    Block,
    /// `time` and the unit tokens: allowed anywhere; they close an open wall block.
    General,
    /// A wall property: only inside a `wall` or `defaults` block.
    Property,
}

macro_rules! keywords {
    ($($variant:ident => $name:literal, $shape:ident, $role:ident, $ssdem:literal, $dim:ident, $default:expr, $range:expr, $types:ident, $doc:literal;)*) => {
        /// A keyword of the walls language.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[allow(missing_docs)]
        pub enum Keyword {
            $($variant,)*
        }

        impl Keyword {
            /// Every keyword, in the order of docs/spec.md §1.
            pub const ALL: &'static [Keyword] = &[$(Keyword::$variant,)*];

            /// The keyword as written in canonical (lower-case) form.
            #[inline]
            pub const fn name(self) -> &'static str {
                match self { $(Keyword::$variant => $name,)* }
            }

            /// What follows the keyword.
            #[inline]
            pub const fn shape(self) -> ValueShape {
                match self { $(Keyword::$variant => ValueShape::$shape,)* }
            }

            /// Where the keyword may stand.
            #[inline]
            pub const fn role(self) -> Role {
                match self { $(Keyword::$variant => Role::$role,)* }
            }

            /// Whether only pkdgrav's soft-sphere (SSDEM) code reads the keyword.
            #[inline]
            pub const fn ssdem_only(self) -> bool {
                match self { $(Keyword::$variant => $ssdem,)* }
            }

            /// How the unit tokens in force scale the keyword's value.
            #[inline]
            pub const fn dimension(self) -> Dimension {
                match self { $(Keyword::$variant => Dimension::$dim,)* }
            }

            /// The value before any `defaults` or wall sets it.
            #[inline]
            pub const fn builtin(self) -> Builtin {
                use Builtin::*;
                match self { $(Keyword::$variant => $default,)* }
            }

            /// The values the keyword accepts: the rule that checks a value as it is read.
            #[inline]
            pub const fn value_range(self) -> ValueRange {
                use ValueRange::*;
                match self { $(Keyword::$variant => $range,)* }
            }

            /// The wall types whose geometry or motion reads the value.
            #[inline]
            pub const fn applies_to(self) -> Types {
                match self { $(Keyword::$variant => Types::$types,)* }
            }

            /// What the keyword does, for hovers, completion and `--explain`.
            pub const fn doc(self) -> &'static str {
                match self { $(Keyword::$variant => $doc,)* }
            }
        }
    };
}

keywords! {
    Time => "time", Number, General, false, Time, Number(0.0), NonNegative, ALL, "Sets the current time. pkdgrav reads it but does not use it: to place moving walls at a time, change the time in the particle (ss) file. Must not be negative.";
    LengthUnit => "lengthunit", Number, General, false, Dimensionless, Number(1.0), Positive, ALL, "Multiplies every length (and, with timeunit, every speed) read after it. Default 1, that is pkdgrav's unit of 1 AU. Must be positive. Closes an open wall block.";
    MassUnit => "massunit", Number, General, false, Dimensionless, Number(1.0), Positive, ALL, "Multiplies every mass (and moment of inertia) read after it; only reactive walls have masses. Default 1 (one solar mass). Must be positive. Closes an open wall block.";
    TimeUnit => "timeunit", Number, General, false, Dimensionless, Number(1.0), Positive, ALL, "Multiplies every time read after it and divides every speed and frequency. Default 1 (a year over 2π). Must be positive. Closes an open wall block.";
    Defaults => "defaults", None, Block, false, Dimensionless, None, Any, ALL, "Opens the default wall for editing: the tokens that follow change what every later `wall` starts as, until the next `wall` or `defaults`.";
    Wall => "wall", None, Block, false, Dimensionless, None, Any, ALL, "Appends a new wall, a copy of the defaults in force (its type included), and opens it for editing until the next `wall` or `defaults`, or a unit or `time` token.";
    Type => "type", TypeName, Property, false, Dimensionless, Type(WallType::Plane), Any, ALL, "The wall's geometry: plane, triangle, rectangle, disk (or disc), cylinder-infinite, cylinder-finite or shell. Default plane. Triangles and shells exist only in SSDEM.";
    Origin => "origin", Vector, Property, false, Length, Vector([0.0, 0.0, 0.0]), Any, ALL, "A point of the wall: on the plane, the reference vertex of a triangle or rectangle, the centre of a disk or shell, on the axis of a cylinder (midway along a finite one).";
    Orient => "orient", Vector, Property, false, Dimensionless, Vector([0.0, 0.0, 1.0]), Direction, NOT_POLYGON, "The wall's normal or axis (normalised on reading; must not be zero). Not used by triangles and rectangles, whose normal is vertex1 × vertex2. A shell's opening is centred on +orient.";
    Vertex1 => "vertex1", Vector, Property, false, Length, Vector([1.0, 0.0, 0.0]), NonZero, POLYGON, "For triangles and rectangles: the vector from the origin to a second vertex. Must not be zero; a rectangle's two vectors must be perpendicular.";
    Vertex2 => "vertex2", Vector, Property, false, Length, Vector([0.0, 1.0, 0.0]), NonZero, POLYGON, "For triangles and rectangles: the vector from the origin to the third vertex (or the other side of the rectangle). The normal is vertex1 × vertex2.";
    Velocity => "velocity", Vector, Property, false, Velocity, Vector([0.0, 0.0, 0.0]), Any, ALL, "The wall's constant velocity: after time t its origin has moved by velocity·t (in whole steps when `step` is set).";
    Step => "step", Number, Property, false, Time, Number(0.0), NonNegative, ALL, "The update step of a moving wall: its motion is evaluated at ⌊t/step⌋·step. 0 (the default) means the simulation's timestep in pkdgrav.";
    OscAmpl => "osc-ampl", Number, Property, false, Length, Number(0.0), Any, ALL, "The amplitude A of the wall's oscillation: its origin moves by A·sin(ω·t + 2πφ) along osc-vec. Negative values flip the direction.";
    OscFreq => "osc-freq", Number, Property, false, Frequency, Number(0.0), NonNegativeFrequency, ALL, "The angular frequency ω of the oscillation, in radians per time unit. pkdgrav rejects a negative value (the document allows it).";
    OscPhase => "osc-phase", Number, Property, false, Dimensionless, Number(0.0), Phase, ALL, "The phase φ of the oscillation as a fraction of a cycle, from 0 to 1 (0.75 starts the wall at the bottom of its cycle).";
    OscVec => "osc-vec", Vector, Property, false, Dimensionless, Vector([0.0, 0.0, 1.0]), Direction, ALL, "The direction of the oscillation (normalised). Its default is the initial orient, 0 0 1, and does not follow a later `orient`.";
    Radius => "radius", Number, Property, false, Length, Number(1.0), NonNegative, ROUND, "The radius of a disk, cylinder or shell. 0 makes a point, a line or a ring. Must not be negative.";
    HoleRadius => "hole-radius", Number, Property, false, Length, Number(0.0), NonNegative, DISK, "The radius of a hole in a disk, centred on its origin: smaller than the radius, or 0.";
    Length => "length", Number, Property, false, Length, Number(1.0), NonNegative, FINITE_CYLINDER, "The length of a finite cylinder along its axis; 0 makes a ring. Must not be negative.";
    Taper => "taper", Number, Property, true, Dimensionless, Number(0.0), Fraction, FINITE_CYLINDER, "How much a finite cylinder narrows towards +orient: its radius there is radius·(1 − taper); 1 makes a cone. 0 to 1. SSDEM only.";
    OpenAngle => "open-angle", Number, Property, false, Dimensionless, Number(0.0), HalfTurn, SHELL, "The half-angle in degrees of the cap removed from a shell around +orient: 0 is a closed sphere, 90 a hemisphere.";
    AngSpeed => "ang-speed", Number, Property, false, Frequency, Number(0.0), Any, NOT_POLYGON, "The wall's spin about its orient axis through its origin, in radians per time unit. It changes only the surface speed particles feel, never the drawn shape.";
    Epsn => "epsn", Number, Property, false, Dimensionless, Number(99.0), NormalRestitution, ALL, "The normal coefficient of restitution: at most 1 (elastic); 0 sticks particles to the wall; negative removes them. 99 (the default) uses the particle's value in SSDEM; HSDEM takes 99 literally.";
    Epst => "epst", Number, Property, false, Dimensionless, Number(99.0), TangentialRestitution, ALL, "The tangential coefficient of restitution: −1 to 1 in HSDEM, 0 to 1 in SSDEM. 99 (the default) uses the particle's value in SSDEM; HSDEM takes 99 literally.";
    Color => "color", Integer, Property, false, Dimensionless, Integer(223), Palette, ALL, "The colour ssdraw draws the wall in, 0 to 255: 0 is not drawn, 1–15 are named colours, 16–255 greys. Default 223, a light grey.";
    Transparency => "transparency", Number, Property, false, Dimensionless, Number(0.0), Transparency, ALL, "How transparent ssdraw draws the wall: 0 (opaque) to 1, or a percentage above 1 up to 100.";
    KN => "k_n", Number, Property, true, PkdgravUnits, Number(-1.0), ParticleOrNonNegative, ALL, "The normal spring constant of the SSDEM contact, in pkdgrav units (not scaled by the unit tokens). Setting it also sets k_t to 2/7 of it. −1 (default) uses the particle's value.";
    KT => "k_t", Number, Property, true, PkdgravUnits, Number(-1.0), ParticleOrNonNegative, ALL, "The tangential spring constant of the SSDEM contact, in pkdgrav units. A later k_n overwrites it with 2/7·k_n, so set it after k_n. −1 uses the particle's value.";
    MuS => "mu_s", Number, Property, true, Dimensionless, Number(-1.0), ParticleOrNonNegative, ALL, "The coefficient of static (sliding) friction of the SSDEM contact. −1 uses the particle's value; 0 means no sliding friction.";
    MuR => "mu_r", Number, Property, true, Dimensionless, Number(-1.0), ParticleOrNonNegative, ALL, "The coefficient of rolling friction of the SSDEM contact. −1 uses the particle's value; 0 means none.";
    MuT => "mu_t", Number, Property, true, Dimensionless, Number(-1.0), ParticleOrNonNegative, ALL, "The coefficient of twisting friction of the SSDEM contact. −1 uses the particle's value; 0 means none.";
    BetaS => "beta_s", Number, Property, true, Dimensionless, Number(-1.0), ParticleOrNonNegative, ALL, "The shape parameter of SSDEM's rolling and twisting friction (and of microscopic cohesion). −1 uses the particle's value; 0 has no effect.";
    CohesionModel => "cohesion_model", Integer, Property, true, Dimensionless, Integer(-1), CohesionModel, ALL, "The SSDEM cohesion model: 0 the microscopic contact model, 1 the cohesive bridge model, −1 the particle's. Walls count as infinitely large.";
    CohesiveCoeff => "cohesive_coeff", Number, Property, true, PkdgravUnits, Number(-1.0), ParticleOrNonNegative, ALL, "The cohesive coefficient, in pkdgrav pressure units (not scaled by the unit tokens). −1 uses the particle's value; 0 means no cohesion.";
    InnerOverlapBoundary => "inner_overlap_boundary", Number, Property, true, PkdgravUnits, Number(-1.0), ParticleOrNonNegative, ALL, "Undocumented in the reference document: the overlap at which pkdgrav's two-layer contact model switches from the outer to the inner spring constants. −1 uses the particle's value.";
    KNOuter => "k_n_outer", Number, Property, true, PkdgravUnits, Number(-1.0), ParticleOrNonNegative, ALL, "Undocumented: the normal spring constant of the outer layer of pkdgrav's two-layer contact model. Setting it also sets k_t_outer to 2/7 of it. −1 uses the particle's value.";
    KTOuter => "k_t_outer", Number, Property, true, PkdgravUnits, Number(-1.0), ParticleOrNonNegative, ALL, "Undocumented: the tangential spring constant of the outer layer of the two-layer contact model; set it after k_n_outer. −1 uses the particle's value.";
    KNInner => "k_n_inner", Number, Property, true, PkdgravUnits, Number(-1.0), ParticleOrNonNegative, ALL, "Undocumented: the normal spring constant of the inner layer of pkdgrav's two-layer contact model. Setting it also sets k_t_inner to 2/7 of it. −1 uses the particle's value.";
    KTInner => "k_t_inner", Number, Property, true, PkdgravUnits, Number(-1.0), ParticleOrNonNegative, ALL, "Undocumented: the tangential spring constant of the inner layer of the two-layer contact model; set it after k_n_inner. −1 uses the particle's value.";
    Mass => "mass", Number, Property, true, Mass, Number(0.0), NonNegative, ALL, "The mass of a reactive wall; 0 (default) means infinite: the wall does not respond to particles. An assembly's mass is the sum of its walls'. SSDEM only.";
    Cog => "cog", Vector, Property, true, Length, Vector([0.0, 0.0, 0.0]), Any, ALL, "The centre of mass of the wall's assembly: rotations are about this point. SSDEM reactive walls only.";
    RotVec => "rot-vec", Vector, Property, true, Frequency, Vector([0.0, 0.0, 0.0]), Any, ALL, "The angular velocity of the wall's assembly about its principal axes (body frame), in radians per time unit. SSDEM reactive walls only.";
    IxjVec => "ixj-vec", Vector, Property, true, Inertia, Vector([1.0, 0.0, 0.0]), InertiaRow(0), ALL, "The first row of the assembly's inertia tensor. pkdgrav uses only the diagonal: give it in the principal frame. SSDEM reactive walls only.";
    IyjVec => "iyj-vec", Vector, Property, true, Inertia, Vector([0.0, 1.0, 0.0]), InertiaRow(1), ALL, "The second row of the assembly's inertia tensor (only the diagonal is used). SSDEM reactive walls only.";
    IzjVec => "izj-vec", Vector, Property, true, Inertia, Vector([0.0, 0.0, 1.0]), InertiaRow(2), ALL, "The third row of the assembly's inertia tensor (only the diagonal is used). SSDEM reactive walls only.";
    PxjVec => "pxj-vec", Vector, Property, true, Dimensionless, Vector([1.0, 0.0, 0.0]), UnitVector, ALL, "The first principal axis of the assembly: a unit vector, orthogonal to the other two. SSDEM reactive walls only.";
    PyjVec => "pyj-vec", Vector, Property, true, Dimensionless, Vector([0.0, 1.0, 0.0]), UnitVector, ALL, "The second principal axis of the assembly: a unit vector, orthogonal to the other two. SSDEM reactive walls only.";
    PzjVec => "pzj-vec", Vector, Property, true, Dimensionless, Vector([0.0, 0.0, 1.0]), UnitVector, ALL, "The third principal axis of the assembly: a unit vector, orthogonal to the other two. SSDEM reactive walls only.";
    Assembly => "assembly", Integer, Property, true, Dimensionless, Integer(-1), Assembly, ALL, "The reactive assembly (0 or 1) the wall moves with; walls of one assembly move as one rigid body. Leave it out for a wall in no assembly. SSDEM only.";
}

/// The values a keyword accepts, as checked when the value is read (docs/spec.md §1
/// table).
///
/// Each range is checked by one rule of `walls-model` (named in brackets) for the
/// keywords that have it, so a keyword's range is changed here and nowhere else. Ranges
/// that read alike but are reported under different codes are different variants.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ValueRange {
    /// Any value the shape allows.
    Any,
    /// Greater than 0, and finite: the unit tokens (C101; the unit in force is kept).
    Positive,
    /// 0 or more: `time` (C102, and C103 when not 0), sizes, `step` and `mass` (C107).
    NonNegative,
    /// 0 or more, a rate: `osc-freq` (C113, reported when its block ends, with the
    /// positive frequency, amplitude and phase that give the same motion).
    NonNegativeFrequency,
    /// Any vector but zero, normalised when read: `orient`, `osc-vec` (C104).
    Direction,
    /// Any vector but zero: `vertex1`, `vertex2` (C104).
    NonZero,
    /// 0 to 1: `taper` (C109).
    Fraction,
    /// A fraction of a cycle, 0 to 1: `osc-phase` (C112).
    Phase,
    /// 0 to 180 degrees: `open-angle` (C111).
    HalfTurn,
    /// At most 1, or 99 for the particle's value: `epsn` (C114).
    NormalRestitution,
    /// −1 to 1 in HSDEM, 0 to 1 in SSDEM, or 99 for the particle's value: `epst` (C115).
    TangentialRestitution,
    /// 0 to 255, ssdraw's palette: `color` (C116).
    Palette,
    /// 0 to 1, or a percentage above 1 up to 100 (stored as a fraction):
    /// `transparency` (C117).
    Transparency,
    /// −1 for the particle's value, or at least 0: spring constants, friction and
    /// cohesion (C118).
    ParticleOrNonNegative,
    /// −1, 0 or 1: `cohesion_model` (C119).
    CohesionModel,
    /// 0 or 1: `assembly` (C305).
    Assembly,
    /// A unit vector (to 0.001): the principal axes (C306).
    UnitVector,
    /// A row of the inertia tensor whose only non-zero term should be the diagonal one,
    /// at this index (C308, a warning: pkdgrav ignores the others).
    InertiaRow(usize),
}

/// How a value is scaled by the unit tokens in force when it is read (docs/spec.md §1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Dimension {
    /// × lengthunit.
    Length,
    /// × timeunit.
    Time,
    /// × massunit.
    Mass,
    /// × lengthunit / timeunit.
    Velocity,
    /// ÷ timeunit (angular speeds and frequencies, radians per time unit).
    Frequency,
    /// × massunit · lengthunit².
    Inertia,
    /// Not scaled: a pure number, a direction, a code or a fraction.
    Dimensionless,
    /// Not scaled although it has physical dimensions (spring constants, cohesion):
    /// it must already be in pkdgrav units.
    PkdgravUnits,
}

impl Dimension {
    /// The factor a value read under these units is multiplied by.
    pub fn factor(self, length: f64, mass: f64, time: f64) -> f64 {
        match self {
            Dimension::Length => length,
            Dimension::Time => time,
            Dimension::Mass => mass,
            Dimension::Velocity => length / time,
            Dimension::Frequency => 1.0 / time,
            Dimension::Inertia => mass * length * length,
            Dimension::Dimensionless | Dimension::PkdgravUnits => 1.0,
        }
    }

    /// A short description for messages and hovers.
    pub const fn describe(self) -> &'static str {
        match self {
            Dimension::Length => "length (× lengthunit)",
            Dimension::Time => "time (× timeunit)",
            Dimension::Mass => "mass (× massunit)",
            Dimension::Velocity => "speed (× lengthunit / timeunit)",
            Dimension::Frequency => "rate in radians per time (÷ timeunit)",
            Dimension::Inertia => "moment of inertia (× massunit · lengthunit²)",
            Dimension::Dimensionless => "not scaled",
            Dimension::PkdgravUnits => "not scaled: give it in pkdgrav units",
        }
    }
}

/// A keyword's value before anything sets it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Builtin {
    /// The keyword takes no value.
    None,
    /// A real.
    Number(f64),
    /// An integer.
    Integer(i64),
    /// A vector.
    Vector([f64; 3]),
    /// A wall type.
    Type(WallType),
}

/// A set of wall types.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Types(u8);

impl Types {
    /// Every type.
    pub const ALL: Types = Types(0b111_1111);
    /// Triangles and rectangles, whose normal comes from their vertices.
    pub const POLYGON: Types =
        Types(Types::bit(WallType::Triangle) | Types::bit(WallType::Rectangle));
    /// All but triangles and rectangles.
    pub const NOT_POLYGON: Types = Types(Types::ALL.0 & !Types::POLYGON.0);
    /// Types with a radius: disk, both cylinders, shell.
    pub const ROUND: Types = Types(
        Types::bit(WallType::Disk)
            | Types::bit(WallType::CylinderInfinite)
            | Types::bit(WallType::CylinderFinite)
            | Types::bit(WallType::Shell),
    );
    /// Disks only.
    pub const DISK: Types = Types(Types::bit(WallType::Disk));
    /// Finite cylinders only.
    pub const FINITE_CYLINDER: Types = Types(Types::bit(WallType::CylinderFinite));
    /// Shells only.
    pub const SHELL: Types = Types(Types::bit(WallType::Shell));
    /// The types a reactive (finite-mass) wall may have.
    pub const REACTIVE: Types = Types(
        Types::bit(WallType::Triangle)
            | Types::bit(WallType::Rectangle)
            | Types::bit(WallType::CylinderFinite)
            | Types::bit(WallType::Disk)
            | Types::bit(WallType::Shell),
    );

    const fn bit(t: WallType) -> u8 {
        1 << t as u8
    }

    /// Whether the set holds `t`.
    pub const fn contains(self, t: WallType) -> bool {
        self.0 & Types::bit(t) != 0
    }

    /// The names of the types in the set, canonical order.
    pub fn names(self) -> Vec<&'static str> {
        WallType::ALL
            .iter()
            .filter(|&&t| self.contains(t))
            .map(|t| t.name())
            .collect()
    }
}

/// A wall geometry, the value of `type`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum WallType {
    /// An infinite plane.
    Plane,
    /// A finite triangle (SSDEM only).
    Triangle,
    /// A finite rectangle.
    Rectangle,
    /// A circular disk, optionally with a hole (`disc` is an alias).
    Disk,
    /// An infinite straight tube.
    CylinderInfinite,
    /// A finite open-ended cylinder, optionally tapered.
    CylinderFinite,
    /// A hollow sphere, optionally opened (SSDEM only).
    Shell,
}

impl WallType {
    /// Every wall type.
    pub const ALL: &'static [WallType] = &[
        WallType::Plane,
        WallType::Triangle,
        WallType::Rectangle,
        WallType::Disk,
        WallType::CylinderInfinite,
        WallType::CylinderFinite,
        WallType::Shell,
    ];

    /// Every spelling the reader accepts, canonical names first, then aliases.
    pub const SPELLINGS: &'static [(&'static str, WallType)] = &[
        ("plane", WallType::Plane),
        ("triangle", WallType::Triangle),
        ("rectangle", WallType::Rectangle),
        ("disk", WallType::Disk),
        ("cylinder-infinite", WallType::CylinderInfinite),
        ("cylinder-finite", WallType::CylinderFinite),
        ("shell", WallType::Shell),
        ("disc", WallType::Disk),
    ];

    /// The canonical name.
    pub const fn name(self) -> &'static str {
        match self {
            WallType::Plane => "plane",
            WallType::Triangle => "triangle",
            WallType::Rectangle => "rectangle",
            WallType::Disk => "disk",
            WallType::CylinderInfinite => "cylinder-infinite",
            WallType::CylinderFinite => "cylinder-finite",
            WallType::Shell => "shell",
        }
    }

    /// Whether pkdgrav implements the type only in its soft-sphere (SSDEM) code.
    pub const fn ssdem_only(self) -> bool {
        matches!(self, WallType::Triangle | WallType::Shell)
    }
}

impl Keyword {
    /// The keyword's documentation as Markdown: its value, how units scale it, its
    /// default, the wall types that read it, and what it does. The same text serves
    /// `walls-lint --explain KEYWORD` and editor hovers.
    pub fn markdown(self) -> String {
        let mut out = format!("**{}**", self.name());
        if self.shape() != ValueShape::None {
            out.push_str(&format!(" — {}", self.shape().describe()));
            if self.role() == Role::Property || self == Keyword::Time {
                out.push_str(&format!(", {}", self.dimension().describe()));
            }
        }
        match self.builtin() {
            Builtin::None => {}
            Builtin::Number(x) => out.push_str(&format!("; default {x}")),
            Builtin::Integer(i) => out.push_str(&format!("; default {i}")),
            Builtin::Vector([x, y, z]) => out.push_str(&format!("; default {x} {y} {z}")),
            Builtin::Type(t) => out.push_str(&format!("; default {}", t.name())),
        }
        out.push_str("\n\n");
        if self.role() == Role::Property && self.applies_to() != Types::ALL {
            out.push_str(&format!(
                "Used by {} walls. ",
                self.applies_to().names().join(", ")
            ));
        }
        if self.ssdem_only() {
            out.push_str("Read only by pkdgrav's soft-sphere (SSDEM) code. ");
        }
        out.push_str(self.doc());
        out.push('\n');
        out
    }
}

/// Looks a keyword up by name, ignoring ASCII case as pkdgrav does.
pub fn keyword(name: &str) -> Option<Keyword> {
    Keyword::ALL
        .iter()
        .copied()
        .find(|k| k.name().eq_ignore_ascii_case(name))
}

/// Looks a wall type up by any of its spellings, ignoring ASCII case.
pub fn wall_type(name: &str) -> Option<WallType> {
    WallType::SPELLINGS
        .iter()
        .find(|(s, _)| s.eq_ignore_ascii_case(name))
        .map(|&(_, t)| t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_lower_case_and_round_trip() {
        let mut seen = std::collections::HashSet::new();
        for &k in Keyword::ALL {
            assert!(seen.insert(k.name()), "duplicate {}", k.name());
            assert_eq!(k.name(), k.name().to_ascii_lowercase());
            assert_eq!(keyword(&k.name().to_ascii_uppercase()), Some(k));
        }
        for &(s, t) in WallType::SPELLINGS {
            assert!(seen.insert(s), "type name {s} clashes");
            assert_eq!(wall_type(&s.to_ascii_uppercase()), Some(t));
        }
        assert_eq!(Keyword::ALL.len(), 50);
    }

    #[test]
    fn every_keyword_is_documented() {
        for &k in Keyword::ALL {
            assert!(k.doc().len() > 40 && k.doc().ends_with('.'), "{k:?}");
            let md = k.markdown();
            assert!(
                md.starts_with(&format!("**{}**", k.name())) && md.ends_with(".\n"),
                "{md}"
            );
        }
        assert_eq!(
            Keyword::Radius.markdown(),
            "**radius** — a number, length (× lengthunit); default 1\n\nUsed by disk, cylinder-infinite, cylinder-finite, shell walls. The radius of a disk, cylinder or shell. 0 makes a point, a line or a ring. Must not be negative.\n"
        );
    }

    #[test]
    fn builtin_values_fit_their_shapes() {
        for &k in Keyword::ALL {
            let fits = matches!(
                (k.shape(), k.builtin()),
                (ValueShape::None, Builtin::None)
                    | (ValueShape::Number, Builtin::Number(_))
                    | (ValueShape::Integer, Builtin::Integer(_))
                    | (ValueShape::Vector, Builtin::Vector(_))
                    | (ValueShape::TypeName, Builtin::Type(_))
            );
            assert!(fits, "{k:?}");
        }
    }

    #[test]
    fn value_ranges_fit_their_shapes() {
        for &k in Keyword::ALL {
            let fits = match k.value_range() {
                ValueRange::Any => true,
                ValueRange::Direction
                | ValueRange::NonZero
                | ValueRange::UnitVector
                | ValueRange::InertiaRow(0..=2) => k.shape() == ValueShape::Vector,
                ValueRange::InertiaRow(_) => false,
                ValueRange::Palette | ValueRange::CohesionModel | ValueRange::Assembly => {
                    k.shape() == ValueShape::Integer
                }
                _ => k.shape() == ValueShape::Number,
            };
            assert!(fits, "{k:?}");
        }
    }

    #[test]
    fn only_blocks_take_no_value() {
        for &k in Keyword::ALL {
            assert_eq!(
                k.shape() == ValueShape::None,
                k.role() == Role::Block,
                "{k:?}"
            );
        }
    }
}
