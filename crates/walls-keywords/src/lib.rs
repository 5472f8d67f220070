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
    ($($variant:ident => $name:literal, $shape:ident, $role:ident, $ssdem:literal;)*) => {
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
        }
    };
}

keywords! {
    Time => "time", Number, General, false;
    LengthUnit => "lengthunit", Number, General, false;
    MassUnit => "massunit", Number, General, false;
    TimeUnit => "timeunit", Number, General, false;
    Defaults => "defaults", None, Block, false;
    Wall => "wall", None, Block, false;
    Type => "type", TypeName, Property, false;
    Origin => "origin", Vector, Property, false;
    Orient => "orient", Vector, Property, false;
    Vertex1 => "vertex1", Vector, Property, false;
    Vertex2 => "vertex2", Vector, Property, false;
    Velocity => "velocity", Vector, Property, false;
    Step => "step", Number, Property, false;
    OscAmpl => "osc-ampl", Number, Property, false;
    OscFreq => "osc-freq", Number, Property, false;
    OscPhase => "osc-phase", Number, Property, false;
    OscVec => "osc-vec", Vector, Property, false;
    Radius => "radius", Number, Property, false;
    HoleRadius => "hole-radius", Number, Property, false;
    Length => "length", Number, Property, false;
    Taper => "taper", Number, Property, true;
    OpenAngle => "open-angle", Number, Property, false;
    AngSpeed => "ang-speed", Number, Property, false;
    Epsn => "epsn", Number, Property, false;
    Epst => "epst", Number, Property, false;
    Color => "color", Integer, Property, false;
    Transparency => "transparency", Number, Property, false;
    KN => "k_n", Number, Property, true;
    KT => "k_t", Number, Property, true;
    MuS => "mu_s", Number, Property, true;
    MuR => "mu_r", Number, Property, true;
    MuT => "mu_t", Number, Property, true;
    BetaS => "beta_s", Number, Property, true;
    CohesionModel => "cohesion_model", Integer, Property, true;
    CohesiveCoeff => "cohesive_coeff", Number, Property, true;
    InnerOverlapBoundary => "inner_overlap_boundary", Number, Property, true;
    KNOuter => "k_n_outer", Number, Property, true;
    KTOuter => "k_t_outer", Number, Property, true;
    KNInner => "k_n_inner", Number, Property, true;
    KTInner => "k_t_inner", Number, Property, true;
    Mass => "mass", Number, Property, true;
    Cog => "cog", Vector, Property, true;
    RotVec => "rot-vec", Vector, Property, true;
    IxjVec => "ixj-vec", Vector, Property, true;
    IyjVec => "iyj-vec", Vector, Property, true;
    IzjVec => "izj-vec", Vector, Property, true;
    PxjVec => "pxj-vec", Vector, Property, true;
    PyjVec => "pyj-vec", Vector, Property, true;
    PzjVec => "pzj-vec", Vector, Property, true;
    Assembly => "assembly", Integer, Property, true;
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
