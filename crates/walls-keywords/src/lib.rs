//! The one table of the walls language's words.
//!
//! Every keyword pkdgrav's walls-file reader knows (SPEC §1, including the five
//! undocumented two-layer contact tokens) and every wall type name, with what follows
//! each keyword. The lexer, the parser, "did you mean" suggestions, the grammar
//! documentation and, later, the checker, hover and completion all read this table, so
//! adding a token is one row here plus its lexer attribute (a test keeps the two in step).

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
    ($($variant:ident => $name:literal, $shape:ident, $role:ident, $ssdem:literal, $dim:ident, $default:expr, $types:ident;)*) => {
        /// A keyword of the walls language.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[allow(missing_docs)]
        pub enum Keyword {
            $($variant,)*
        }

        impl Keyword {
            /// Every keyword, in the order of SPEC §1.
            pub const ALL: &'static [Keyword] = &[$(Keyword::$variant,)*];

            /// The keyword as written in canonical (lower-case) form.
            pub const fn name(self) -> &'static str {
                match self { $(Keyword::$variant => $name,)* }
            }

            /// What follows the keyword.
            pub const fn shape(self) -> ValueShape {
                match self { $(Keyword::$variant => ValueShape::$shape,)* }
            }

            /// Where the keyword may stand.
            pub const fn role(self) -> Role {
                match self { $(Keyword::$variant => Role::$role,)* }
            }

            /// Whether only pkdgrav's soft-sphere (SSDEM) code reads the keyword.
            pub const fn ssdem_only(self) -> bool {
                match self { $(Keyword::$variant => $ssdem,)* }
            }

            /// How the unit tokens in force scale the keyword's value.
            pub const fn dimension(self) -> Dimension {
                match self { $(Keyword::$variant => Dimension::$dim,)* }
            }

            /// The value before any `defaults` or wall sets it.
            pub const fn builtin(self) -> Builtin {
                use Builtin::*;
                match self { $(Keyword::$variant => $default,)* }
            }

            /// The wall types whose geometry or motion reads the value.
            pub const fn applies_to(self) -> Types {
                match self { $(Keyword::$variant => Types::$types,)* }
            }
        }
    };
}

keywords! {
    Time => "time", Number, General, false, Time, Number(0.0), ALL;
    LengthUnit => "lengthunit", Number, General, false, Dimensionless, Number(1.0), ALL;
    MassUnit => "massunit", Number, General, false, Dimensionless, Number(1.0), ALL;
    TimeUnit => "timeunit", Number, General, false, Dimensionless, Number(1.0), ALL;
    Defaults => "defaults", None, Block, false, Dimensionless, None, ALL;
    Wall => "wall", None, Block, false, Dimensionless, None, ALL;
    Type => "type", TypeName, Property, false, Dimensionless, Type(WallType::Plane), ALL;
    Origin => "origin", Vector, Property, false, Length, Vector([0.0, 0.0, 0.0]), ALL;
    Orient => "orient", Vector, Property, false, Dimensionless, Vector([0.0, 0.0, 1.0]), NOT_POLYGON;
    Vertex1 => "vertex1", Vector, Property, false, Length, Vector([1.0, 0.0, 0.0]), POLYGON;
    Vertex2 => "vertex2", Vector, Property, false, Length, Vector([0.0, 1.0, 0.0]), POLYGON;
    Velocity => "velocity", Vector, Property, false, Velocity, Vector([0.0, 0.0, 0.0]), ALL;
    Step => "step", Number, Property, false, Time, Number(0.0), ALL;
    OscAmpl => "osc-ampl", Number, Property, false, Length, Number(0.0), ALL;
    OscFreq => "osc-freq", Number, Property, false, Frequency, Number(0.0), ALL;
    OscPhase => "osc-phase", Number, Property, false, Dimensionless, Number(0.0), ALL;
    OscVec => "osc-vec", Vector, Property, false, Dimensionless, Vector([0.0, 0.0, 1.0]), ALL;
    Radius => "radius", Number, Property, false, Length, Number(1.0), ROUND;
    HoleRadius => "hole-radius", Number, Property, false, Length, Number(0.0), DISK;
    Length => "length", Number, Property, false, Length, Number(1.0), FINITE_CYLINDER;
    Taper => "taper", Number, Property, true, Dimensionless, Number(0.0), FINITE_CYLINDER;
    OpenAngle => "open-angle", Number, Property, false, Dimensionless, Number(0.0), SHELL;
    AngSpeed => "ang-speed", Number, Property, false, Frequency, Number(0.0), NOT_POLYGON;
    Epsn => "epsn", Number, Property, false, Dimensionless, Number(99.0), ALL;
    Epst => "epst", Number, Property, false, Dimensionless, Number(99.0), ALL;
    Color => "color", Integer, Property, false, Dimensionless, Integer(223), ALL;
    Transparency => "transparency", Number, Property, false, Dimensionless, Number(0.0), ALL;
    KN => "k_n", Number, Property, true, PkdgravUnits, Number(-1.0), ALL;
    KT => "k_t", Number, Property, true, PkdgravUnits, Number(-1.0), ALL;
    MuS => "mu_s", Number, Property, true, Dimensionless, Number(-1.0), ALL;
    MuR => "mu_r", Number, Property, true, Dimensionless, Number(-1.0), ALL;
    MuT => "mu_t", Number, Property, true, Dimensionless, Number(-1.0), ALL;
    BetaS => "beta_s", Number, Property, true, Dimensionless, Number(-1.0), ALL;
    CohesionModel => "cohesion_model", Integer, Property, true, Dimensionless, Integer(-1), ALL;
    CohesiveCoeff => "cohesive_coeff", Number, Property, true, PkdgravUnits, Number(-1.0), ALL;
    InnerOverlapBoundary => "inner_overlap_boundary", Number, Property, true, PkdgravUnits, Number(-1.0), ALL;
    KNOuter => "k_n_outer", Number, Property, true, PkdgravUnits, Number(-1.0), ALL;
    KTOuter => "k_t_outer", Number, Property, true, PkdgravUnits, Number(-1.0), ALL;
    KNInner => "k_n_inner", Number, Property, true, PkdgravUnits, Number(-1.0), ALL;
    KTInner => "k_t_inner", Number, Property, true, PkdgravUnits, Number(-1.0), ALL;
    Mass => "mass", Number, Property, true, Mass, Number(0.0), ALL;
    Cog => "cog", Vector, Property, true, Length, Vector([0.0, 0.0, 0.0]), ALL;
    RotVec => "rot-vec", Vector, Property, true, Frequency, Vector([0.0, 0.0, 0.0]), ALL;
    IxjVec => "ixj-vec", Vector, Property, true, Inertia, Vector([1.0, 0.0, 0.0]), ALL;
    IyjVec => "iyj-vec", Vector, Property, true, Inertia, Vector([0.0, 1.0, 0.0]), ALL;
    IzjVec => "izj-vec", Vector, Property, true, Inertia, Vector([0.0, 0.0, 1.0]), ALL;
    PxjVec => "pxj-vec", Vector, Property, true, Dimensionless, Vector([1.0, 0.0, 0.0]), ALL;
    PyjVec => "pyj-vec", Vector, Property, true, Dimensionless, Vector([0.0, 1.0, 0.0]), ALL;
    PzjVec => "pzj-vec", Vector, Property, true, Dimensionless, Vector([0.0, 0.0, 1.0]), ALL;
    Assembly => "assembly", Integer, Property, true, Dimensionless, Integer(-1), ALL;
}

/// How a value is scaled by the unit tokens in force when it is read (SPEC §1).
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
