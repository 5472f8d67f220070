//! What the evaluator (walls-sim) does with each `.par` key pkdgrav registers: read and
//! followed, of no effect on what it computes, followed at one value only, or not
//! modelled yet ([`Use`], [`KEYS`]). walls-sim's run warns about the lines it does not
//! follow; the linter and the editor say the same of a `.par` file.

/// What the evaluator does with a key pkdgrav knows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Use {
    /// Read by walls-sim and followed (or checked and resolved as pkdgrav does).
    Read,
    /// Changes nothing the evaluator computes (output names, logging, the tree and
    /// neighbour search, settings pkdgrav itself overrides).
    NoEffect,
    /// The evaluator does what pkdgrav does at `value` only: another value warns, and
    /// so does leaving the key out when pkdgrav's `default` is not `value`.
    Only {
        /// The value the evaluator follows.
        value: f64,
        /// pkdgrav's default.
        default: f64,
        /// What pkdgrav does otherwise.
        why: &'static str,
    },
    /// Physics the evaluator does not model yet: any line warns.
    NotYet(&'static str),
}

const DEM_ONLY_2: &str = "pkdgrav's DEM builds need 2; the evaluator runs as if it were 2";
const HARD_OPTION: &str = "pkdgrav's hard-sphere overlap, slide, collapse and crush options are not modelled yet (DEM builds ignore them)";

/// Every `.par` key of pkdgrav's wall runs (docs/pkdgrav-physics.md §3–4), and a few
/// general ones, with what the evaluator does with it. Keys beginning `dSlide`,
/// `dCollapse` and `dCrush` (the hard-sphere options) are not listed one by one
/// ([`use_of`]).
pub const KEYS: &[(&str, Use)] = &[
    ("achInFile", Use::Read),
    ("achWallsFile", Use::Read),
    ("dDelta", Use::Read),
    ("nSteps", Use::Read),
    ("iStartStep", Use::Read),
    ("iOutInterval", Use::Read),
    ("dEpsN", Use::Read),
    ("dEpsT", Use::Read),
    ("dKn", Use::Read),
    ("dKt", Use::Read),
    ("dMuS", Use::Read),
    ("dMuR", Use::Read),
    ("dMuT", Use::Read),
    ("dxUnifGrav", Use::Read),
    ("dyUnifGrav", Use::Read),
    ("dzUnifGrav", Use::Read),
    ("bWallsEdgeDetect", Use::Read),
    ("dInnerOverlapBndry", Use::Read),
    ("dKnOuter", Use::Read),
    ("dKtOuter", Use::Read),
    ("dKnInner", Use::Read),
    ("dKtInner", Use::Read),
    ("dBetaS", Use::Read),
    ("achOutName", Use::Read),
    ("nDigits", Use::Read),
    ("iLogInterval", Use::NoEffect),
    ("iRedOutInterval", Use::Read),
    ("bVWarnings", Use::NoEffect),
    ("bVStart", Use::NoEffect),
    ("bVDetails", Use::NoEffect),
    ("bDoDensity", Use::NoEffect),
    ("nSmooth", Use::NoEffect),
    ("iFixedBallOption", Use::NoEffect),
    ("bReadDEMData", Use::NoEffect),
    ("nDEMOutputs", Use::NoEffect),
    ("iDEMStatsInterval", Use::NoEffect),
    ("dTangentialSpringDrag", Use::NoEffect),
    ("iMaxRung", Use::NoEffect),
    // The merge limit of hard-sphere collisions, of no effect without the merge outcome
    // (the evaluator only bounces, `iOutcomes = 2`).
    ("dMergeLimit", Use::NoEffect),
    ("iCohesionModel", Use::Read),
    ("dCohesiveCoeff", Use::Read),
    ("achCohesionFile", Use::Read),
    ("dTheta", Use::NoEffect),
    ("dEta", Use::NoEffect),
    ("nBucket", Use::NoEffect),
    ("dExtraStore", Use::NoEffect),
    ("bOverwrite", Use::NoEffect),
    ("bDoGravity", Use::Read),
    (
        "bDoSelfGravity",
        Use::Only {
            value: 0.0,
            default: 1.0,
            why: "pkdgrav adds self-gravity between the particles (tree gravity); the evaluator does not: set 0 for wall scenes",
        },
    ),
    (
        "iForceOverrideOption",
        Use::Only {
            value: 2.0,
            default: 0.0,
            why: DEM_ONLY_2,
        },
    ),
    (
        "iCheckInterval",
        Use::Only {
            value: 0.0,
            default: 10.0,
            why: "pkdgrav's DEM builds refuse checkpoints and exit at the start; the evaluator runs anyway: set 0",
        },
    ),
    (
        "bKDK",
        Use::Only {
            value: 1.0,
            default: 1.0,
            why: "the evaluator runs kick-drift-kick only (bKDK = 1)",
        },
    ),
    (
        "bHeliocentric",
        Use::Only {
            value: 0.0,
            default: 0.0,
            why: "heliocentric frames are not modelled",
        },
    ),
    (
        "bPeriodic",
        Use::Only {
            value: 0.0,
            default: 0.0,
            why: "periodic boundaries are not modelled",
        },
    ),
    (
        "iOutcomes",
        Use::Only {
            value: 2.0,
            default: 2.0,
            why: "the evaluator only bounces (2); DEM builds ignore iOutcomes, pkdgrav's hard-sphere code would merge or fragment",
        },
    ),
    ("dAccCrit", Use::Read),
    ("dMinorFrac", Use::Read),
    ("dMajorFrac", Use::Read),
    ("dErrorFrac", Use::Read),
    ("bUseContactRadius", Use::Read),
    ("bUseLegacyRoll", Use::Read),
    (
        "bWallsSolveQuartic",
        Use::Only {
            value: 0.0,
            default: 0.0,
            why: "the quartic prediction near rotating cylinders is not modelled yet",
        },
    ),
    ("iOverlapOption", Use::NotYet(HARD_OPTION)),
];

/// Whether walls-sim's rule for `name` holds in a build with (`dem`) or without DEM:
/// DEM builds ignore `iOutcomes` (pkdgrav warns unless it is 0); the values walls-sim
/// follows for `iForceOverrideOption` and `iCheckInterval` are the DEM builds' (a
/// hard-sphere build stops on 2 and takes checkpoints).
pub fn follows_alone(name: &str, dem: bool) -> bool {
    match name {
        "iOutcomes" => !dem,
        "iForceOverrideOption" | "iCheckInterval" => dem,
        _ => true,
    }
}

/// What the evaluator does with `key`; `None` for a key it does not know.
pub fn use_of(key: &str) -> Option<Use> {
    if ["dSlide", "dCollapse", "dCrush"]
        .iter()
        .any(|p| key.starts_with(p))
    {
        return Some(Use::NotYet(HARD_OPTION));
    }
    KEYS.iter().find(|(k, _)| *k == key).map(|&(_, u)| u)
}
