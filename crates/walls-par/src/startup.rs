//! What pkdgrav does with a `.par` file's values when it starts, and the values it takes
//! without a check that make the run something else than it says: one row a check
//! (docs/pkdgrav-physics.md §15, §19, and docs/pkdgrav-startup-checks.md, whose row ids
//! the rows keep: `A73` stops, `B38` warns, `C28` changes a value; `N…` are its "not
//! checked at start-up" notes, and N5 physics §2's `bDoGravity`).
//! [`crate::rules::startup`] reports them.
//!
//! The rows are the checks a `.par` file alone can show, of the walls builds: soft- and
//! hard-sphere, aggregates and springs; the rows left out are listed in
//! docs/par-files.md ("Rows not in the table").

use crate::check::File;

/// pkdgrav's 2/7, as its `master.c` writes it: `dKt = -1` means this times `dKn`, and
/// the two-layer `dKtOuter`/`dKtInner` = −1 this times their normal constant.
#[allow(
    clippy::excessive_precision,
    reason = "the digits pkdgrav's source writes"
)]
pub const KT_PER_KN: f64 = 0.2857142857142857143;

/// What pkdgrav does when a check holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// It stops (exit status 1, or an assertion), at start-up or at the first contact or
    /// output.
    Stops,
    /// It prints a warning and runs.
    Warns,
    /// It changes a value after reading, without a word.
    Changes,
    /// It runs without a word, and the run is not what the file says.
    Differs,
}

/// One check.
pub struct Check {
    /// Its row in startup_checks.md (`A73`), or `N…` for its notes on what is not
    /// checked.
    pub id: &'static str,
    /// The compile options it is made in (par_keys.md's notation).
    pub build: &'static str,
    /// What pkdgrav does.
    pub outcome: Outcome,
    /// Only when `bVWarnings` is on (its default).
    pub verbose: bool,
    /// The keys it reads; the first the file gives locates the finding.
    pub keys: &'static [&'static str],
    /// Whether it holds for the file.
    pub holds: fn(&File) -> bool,
    /// What pkdgrav does, in a sentence.
    pub says: &'static str,
}

/// The number pkdgrav runs with for `key` (NaN when there is none: no check holds).
fn n(file: &File, key: &str) -> f64 {
    file.real(key).unwrap_or(f64::NAN)
}

/// `dKt` as pkdgrav runs with it: −1 is 2/7 of `dKn`.
fn k_t(file: &File) -> f64 {
    spring(n(file, "dKt"), n(file, "dKn"))
}

/// A tangential constant with pkdgrav's −1 sentinel resolved against `k_n`.
fn spring(k_t: f64, k_n: f64) -> f64 {
    if k_t == -1.0 { KT_PER_KN * k_n } else { k_t }
}

/// Whether the hard-sphere block of checks runs: `nSmooth` ≥ 1 in a walls build
/// (startup_checks.md's legend).
fn hard_block(file: &File) -> bool {
    n(file, "nSmooth") >= 1.0
}

/// The two-layer normal constants as pkdgrav runs with them: both −1 are `dKn`.
fn layers(file: &File) -> (f64, f64) {
    let (outer, inner) = (n(file, "dKnOuter"), n(file, "dKnInner"));
    if outer == -1.0 && inner == -1.0 {
        (n(file, "dKn"), n(file, "dKn"))
    } else {
        (outer, inner)
    }
}

/// pkdgrav's hard-sphere outcomes, the bits of `iOutcomes` (startup_checks.md A43).
const MERGE: i64 = 1;
/// See [`MERGE`].
const BOUNCE: i64 = 2;
/// See [`MERGE`].
const FRAG: i64 = 4;

/// Whether `iOutcomes` as pkdgrav runs with it has `outcome`.
fn has(file: &File, outcome: i64) -> bool {
    let o = n(file, "iOutcomes");
    o.is_finite() && (o as i64) & outcome != 0
}

/// Whether `x` is in (0, 1], as pkdgrav's restitution checks want.
fn unit(x: f64) -> bool {
    x > 0.0 && x <= 1.0
}

/// Whether `x` is in [−1, 1], as pkdgrav's tangential restitution checks want.
fn signed_unit(x: f64) -> bool {
    (-1.0..=1.0).contains(&x)
}

const fn row(
    id: &'static str,
    build: &'static str,
    outcome: Outcome,
    keys: &'static [&'static str],
    holds: fn(&File) -> bool,
    says: &'static str,
) -> Check {
    Check {
        id,
        build,
        outcome,
        verbose: false,
        keys,
        holds,
        says,
    }
}

/// A row printed only with `bVWarnings` on.
const fn verbose(check: Check) -> Check {
    Check {
        verbose: true,
        ..check
    }
}

use Outcome::{Changes, Differs, Stops, Warns};

/// The checks, in startup_checks.md's order, then its notes.
pub const CHECKS: &[Check] = &[
    row(
        "A7",
        "always",
        Stops,
        &["dRungDDWeight"],
        |f| f.given("dRungDDWeight").is_some(),
        "pkdgrav aborts at start-up on an assertion when the .par file gives `dRungDDWeight` (registered as a double with an int's size)",
    ),
    row(
        "A9",
        "COLLISIONS",
        Stops,
        &["bKDK"],
        |f| n(f, "bKDK") == 0.0,
        "pkdgrav aborts at start-up: a collisions build runs kick-drift-kick only (`bKDK` must be 1)",
    ),
    row(
        "A10",
        "always",
        Stops,
        &["nDigits"],
        |f| !(1.0..=2048.0).contains(&n(f, "nDigits")),
        "pkdgrav stops at start-up: `nDigits` must be from 1 to 2048",
    ),
    row(
        "A11",
        "always",
        Stops,
        &["achInFile", "bRestart"],
        |f| f.string("achInFile").is_some_and(|s| s.is_empty()) && n(f, "bRestart") == 0.0,
        "pkdgrav stops at start-up: no input file (`achInFile`)",
    ),
    row(
        "A12",
        "always",
        Stops,
        &["dTheta"],
        |f| n(f, "dTheta") < 0.0,
        "pkdgrav stops at start-up: the opening angle `dTheta` must be 0 or more",
    ),
    row(
        "A13",
        "!CHANGESOFT",
        Stops,
        &["bPhysicalSoft", "bVariableSoft"],
        |f| n(f, "bPhysicalSoft") != 0.0 || n(f, "bVariableSoft") != 0.0,
        "pkdgrav stops at start-up: `bPhysicalSoft` and `bVariableSoft` need the CHANGESOFT compile option",
    ),
    row(
        "A15",
        "always",
        Stops,
        &["bGravStep", "bDoGravity"],
        |f| n(f, "bGravStep") != 0.0 && n(f, "bDoGravity") == 0.0,
        "pkdgrav stops at start-up: gravity stepping (`bGravStep`) needs `bDoGravity`",
    ),
    row(
        "A17",
        "always",
        Stops,
        &["bHeliocentric", "bDoGravity"],
        |f| n(f, "bHeliocentric") != 0.0 && n(f, "bDoGravity") == 0.0,
        "pkdgrav stops at start-up: heliocentric frames need `bDoGravity`",
    ),
    row(
        "A35",
        "COLLISIONS",
        Stops,
        &["dCentMass"],
        |f| n(f, "dCentMass") < 0.0,
        "pkdgrav aborts at start-up: `dCentMass` must be 0 or more",
    ),
    row(
        "A36",
        "COLLISIONS && WALLS",
        Stops,
        &["bFandG"],
        |f| n(f, "bFandG") != 0.0,
        "pkdgrav aborts at start-up: a walls build cannot use `bFandG`",
    ),
    row(
        "A41",
        "COLLISIONS",
        Stops,
        &["bFindRejects", "nSmooth"],
        |f| n(f, "bFindRejects") != 0.0 && n(f, "nSmooth") < 2.0,
        "pkdgrav stops at start-up: the search for rejects (`bFindRejects`) needs `nSmooth` of 2 or more",
    ),
    row(
        "A42",
        "COLLISIONS",
        Stops,
        &["iCollLogOption"],
        |f| ![0.0, 1.0, 2.0].contains(&n(f, "iCollLogOption")),
        "pkdgrav stops at start-up: `iCollLogOption` must be 0, 1 or 2",
    ),
    row(
        "A43",
        "COLLISIONS && !DEM",
        Stops,
        &["iOutcomes", "nSmooth"],
        |f| hard_block(f) && !has(f, MERGE | BOUNCE | FRAG),
        "pkdgrav stops at start-up: hard-sphere collisions need an outcome in `iOutcomes` (1 merge, 2 bounce, 4 fragment)",
    ),
    row(
        "A44",
        "COLLISIONS && !DEM",
        Stops,
        &["iOutcomes", "bDoSelfGravity", "nSmooth"],
        |f| {
            hard_block(f) && has(f, MERGE) && has(f, BOUNCE | FRAG) && n(f, "bDoSelfGravity") == 0.0
        },
        "pkdgrav stops at start-up: merging with another outcome (conditional merging) needs `bDoSelfGravity`",
    ),
    row(
        "A45",
        "COLLISIONS && !DEM",
        Stops,
        &["dDensity", "iOutcomes", "nSmooth"],
        |f| hard_block(f) && has(f, MERGE) && n(f, "dDensity") < 0.0,
        "pkdgrav stops at start-up: the merged density `dDensity` must be 0 or more",
    ),
    row(
        "A46",
        "COLLISIONS && !DEM",
        Stops,
        &["iDensityAltCol", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f)
                && has(f, MERGE)
                && (n(f, "iDensityAltCol") < 0.0 || n(f, "iDensityAltCol") == 3.0)
        },
        "pkdgrav stops at start-up: `iDensityAltCol` must be 0 or more and not 3 (the planetesimal colour)",
    ),
    row(
        "A47",
        "COLLISIONS && !DEM",
        Stops,
        &["dDensityAltVal", "iDensityAltCol", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f)
                && has(f, MERGE)
                && n(f, "iDensityAltCol") > 0.0
                && n(f, "dDensityAltVal") <= 0.0
        },
        "pkdgrav stops at start-up: an alternate-density colour needs `dDensityAltVal` above 0",
    ),
    row(
        "A48",
        "COLLISIONS && !DEM",
        Stops,
        &["dEpsN", "iEpsNOption", "iOutcomes", "nSmooth"],
        |f| hard_block(f) && has(f, BOUNCE) && n(f, "iEpsNOption") == 0.0 && !unit(n(f, "dEpsN")),
        "pkdgrav stops at start-up: bouncing with a constant restitution needs `dEpsN` in (0, 1]",
    ),
    row(
        "A49",
        "COLLISIONS && !DEM",
        Stops,
        &["dEpsNCoef", "iEpsNOption", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f)
                && has(f, BOUNCE)
                && n(f, "iEpsNOption") == 1.0
                && n(f, "dEpsNCoef") <= 0.0
        },
        "pkdgrav stops at start-up: the power-law restitution (`iEpsNOption = 1`) needs `dEpsNCoef` above 0",
    ),
    row(
        "A50",
        "COLLISIONS && !DEM",
        Stops,
        &["dEpsNVStar", "iEpsNOption", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f)
                && has(f, BOUNCE)
                && n(f, "iEpsNOption") == 3.0
                && n(f, "dEpsNVStar") < 0.0
        },
        "pkdgrav stops at start-up: `iEpsNOption = 3` needs `dEpsNVStar` of 0 or more",
    ),
    row(
        "A51",
        "COLLISIONS && !DEM",
        Stops,
        &["iEpsNOption", "iOutcomes", "nSmooth"],
        |f| hard_block(f) && has(f, BOUNCE) && !(0.0..=3.0).contains(&n(f, "iEpsNOption")),
        "pkdgrav stops at start-up: `iEpsNOption` must be 0 to 3",
    ),
    row(
        "A52",
        "COLLISIONS && !DEM",
        Stops,
        &["dEpsNMin", "iEpsNOption", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f) && has(f, BOUNCE) && n(f, "iEpsNOption") != 0.0 && !unit(n(f, "dEpsNMin"))
        },
        "pkdgrav stops at start-up: a variable restitution needs `dEpsNMin` in (0, 1]",
    ),
    row(
        "A53",
        "COLLISIONS && !DEM",
        Stops,
        &[
            "dSlideLimit",
            "dCollapseLimit",
            "dCrushLimit",
            "iOutcomes",
            "nSmooth",
        ],
        |f| {
            hard_block(f)
                && has(f, BOUNCE)
                && ["dSlideLimit", "dCollapseLimit", "dCrushLimit"]
                    .iter()
                    .any(|k| n(f, k) < 0.0)
        },
        "pkdgrav stops at start-up: `dSlideLimit`, `dCollapseLimit` and `dCrushLimit` must be 0 or more",
    ),
    row(
        "A54",
        "COLLISIONS && !DEM",
        Stops,
        &["dSlideEpsN", "dSlideLimit", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f)
                && has(f, BOUNCE)
                && n(f, "dSlideLimit") > 0.0
                && !unit(n(f, "dSlideEpsN"))
        },
        "pkdgrav stops at start-up: sliding (`dSlideLimit` above 0) needs `dSlideEpsN` in (0, 1]",
    ),
    row(
        "A55",
        "COLLISIONS && !DEM",
        Stops,
        &["dSlideEpsT", "dSlideLimit", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f)
                && has(f, BOUNCE)
                && n(f, "dSlideLimit") > 0.0
                && !signed_unit(n(f, "dSlideEpsT"))
        },
        "pkdgrav stops at start-up: sliding (`dSlideLimit` above 0) needs `dSlideEpsT` in [−1, 1]",
    ),
    row(
        "A56",
        "COLLISIONS && !DEM",
        Stops,
        &["dCrushEpsN", "dCrushLimit", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f)
                && has(f, BOUNCE)
                && n(f, "dCrushLimit") != 0.0
                && !unit(n(f, "dCrushEpsN"))
        },
        "pkdgrav stops at start-up: crushing (`dCrushLimit` not 0) needs `dCrushEpsN` in (0, 1]",
    ),
    row(
        "A57",
        "COLLISIONS && !DEM",
        Stops,
        &["dCrushEpsT", "dCrushLimit", "iOutcomes", "nSmooth"],
        |f| {
            hard_block(f)
                && has(f, BOUNCE)
                && n(f, "dCrushLimit") != 0.0
                && !signed_unit(n(f, "dCrushEpsT"))
        },
        "pkdgrav stops at start-up: crushing (`dCrushLimit` not 0) needs `dCrushEpsT` in [−1, 1]",
    ),
    row(
        "A58",
        "COLLISIONS && !DEM && !AGGS && !SPRINGS",
        Stops,
        &["iOutcomes", "nSmooth"],
        |f| hard_block(f) && has(f, FRAG),
        "pkdgrav stops at start-up: fragmentation (`iOutcomes` with 4) needs an AGGS or SPRINGS build",
    ),
    row(
        "A59",
        "COLLISIONS && !DEM",
        Stops,
        &["iOverlapOption", "nSmooth"],
        |f| hard_block(f) && !(-1.0..=4.0).contains(&n(f, "iOverlapOption")),
        "pkdgrav stops at start-up: `iOverlapOption` must be −1 to 4",
    ),
    row(
        "A60",
        "COLLISIONS && !DEM",
        Stops,
        &["iOverlapOption", "bDoSelfGravity", "nSmooth"],
        |f| hard_block(f) && n(f, "iOverlapOption") == 3.0 && n(f, "bDoSelfGravity") == 0.0,
        "pkdgrav stops at start-up: repelling overlaps (`iOverlapOption = 3`) needs `bDoSelfGravity`",
    ),
    row(
        "A61",
        "COLLISIONS && !DEM",
        Stops,
        &["iOverlapOption", "iOutcomes", "nSmooth"],
        |f| hard_block(f) && n(f, "iOverlapOption") == 4.0 && !has(f, MERGE),
        "pkdgrav stops at start-up: merging overlaps (`iOverlapOption = 4`) needs the merge outcome (1) in `iOutcomes`",
    ),
    row(
        "A62",
        "COLLISIONS && !DEM && WALLS",
        Stops,
        &["iOverlapOption", "bStrictOverlap", "nSmooth"],
        |f| hard_block(f) && n(f, "iOverlapOption") == 1.0 && n(f, "bStrictOverlap") == 0.0,
        "pkdgrav stops at start-up: hard-sphere walls with the backstep overlap option (`iOverlapOption = 1`) need `bStrictOverlap = 1`",
    ),
    row(
        "A63",
        "COLLISIONS && !DEM",
        Stops,
        &["dAdjPosLimit", "iOverlapOption", "nSmooth"],
        |f| {
            hard_block(f)
                && n(f, "iOverlapOption") == 2.0
                && !(n(f, "dAdjPosLimit") > 0.0 && n(f, "dAdjPosLimit") < 1.0)
        },
        "pkdgrav stops at start-up: adjusting positions (`iOverlapOption = 2`) needs `dAdjPosLimit` in (0, 1); its default is 0",
    ),
    row(
        "A64",
        "COLLISIONS && !DEM",
        Stops,
        &["dRepelFac", "iOverlapOption", "nSmooth"],
        |f| hard_block(f) && n(f, "iOverlapOption") == 3.0 && n(f, "dRepelFac") <= 0.0,
        "pkdgrav stops at start-up: repelling overlaps (`iOverlapOption = 3`) needs `dRepelFac` above 0; its default is 0",
    ),
    row(
        "A65",
        "COLLISIONS && !DEM",
        Stops,
        &["iOverlapOption", "nSmooth"],
        |f| !hard_block(f) && n(f, "iOverlapOption") == 3.0,
        "pkdgrav stops at start-up: repelling overlaps (`iOverlapOption = 3`) with collisions off (`nSmooth` below 1)",
    ),
    row(
        "A67",
        "AGGS",
        Stops,
        &["iOutcomes"],
        |f| has(f, FRAG) && !has(f, BOUNCE),
        "pkdgrav stops at start-up: fragmentation needs the bounce outcome (2) in `iOutcomes`",
    ),
    row(
        "A68",
        "AGGS",
        Stops,
        &["dFragLimit", "dMergeLimit", "iOutcomes"],
        |f| {
            let (frag, merge) = (n(f, "dFragLimit"), n(f, "dMergeLimit"));
            has(f, FRAG) && has(f, MERGE) && frag * merge > 0.0 && frag.abs() < merge.abs()
        },
        "pkdgrav stops at start-up: with fragmentation and merging, `dFragLimit` must not be below `dMergeLimit` in size",
    ),
    row(
        "A72",
        "SPRINGS",
        Stops,
        &["iForceOverrideOption"],
        |f| n(f, "iForceOverrideOption") == 0.0,
        "pkdgrav stops at start-up: a SPRINGS build needs `iForceOverrideOption = 2`",
    ),
    row(
        "A73",
        "DEM",
        Stops,
        &["iForceOverrideOption"],
        |f| n(f, "iForceOverrideOption") == 0.0,
        "pkdgrav stops at start-up: a DEM build needs `iForceOverrideOption = 2`",
    ),
    row(
        "A74",
        "always",
        Stops,
        &["iForceOverrideOption"],
        |f| n(f, "iForceOverrideOption") == 1.0,
        "pkdgrav stops at start-up: `iForceOverrideOption = 1` (van der Waals) is not implemented",
    ),
    row(
        "A75",
        "!SPRINGS && !DEM",
        Stops,
        &["iForceOverrideOption"],
        |f| n(f, "iForceOverrideOption") == 2.0,
        "pkdgrav stops at start-up: `iForceOverrideOption = 2` needs a DEM or SPRINGS build",
    ),
    row(
        "A76",
        "always",
        Stops,
        &["iForceOverrideOption"],
        |f| {
            ![0.0, 1.0, 2.0].contains(&n(f, "iForceOverrideOption"))
                && !n(f, "iForceOverrideOption").is_nan()
        },
        "pkdgrav stops at start-up: `iForceOverrideOption` must be 0, 1 or 2",
    ),
    row(
        "A77",
        "SPRINGS",
        Stops,
        &["iCheckInterval"],
        |f| n(f, "iCheckInterval") > 0.0,
        "pkdgrav stops at start-up: a SPRINGS build cannot restart from checkpoints (`iCheckInterval` must be 0)",
    ),
    row(
        "A78",
        "SPRINGS",
        Stops,
        &["iOutcomes"],
        |f| has(f, MERGE),
        "pkdgrav stops at start-up: a SPRINGS build cannot merge (`iOutcomes` with 1)",
    ),
    row(
        "A79",
        "SPRINGS",
        Stops,
        &["iOutcomes"],
        |f| !has(f, BOUNCE),
        "pkdgrav stops at start-up: a SPRINGS build needs the bounce outcome (2) in `iOutcomes`",
    ),
    row(
        "A80",
        "SPRINGS",
        Stops,
        &["dMeanYoungsModulus"],
        |f| n(f, "dMeanYoungsModulus") < 0.0,
        "pkdgrav stops at start-up: `dMeanYoungsModulus` must be 0 or more",
    ),
    row(
        "A81",
        "SPRINGS",
        Stops,
        &["dMeanStrainLimit"],
        |f| n(f, "dMeanStrainLimit") < 0.0,
        "pkdgrav stops at start-up: `dMeanStrainLimit` must be 0 or more",
    ),
    row(
        "A82",
        "SPRINGS",
        Stops,
        &["dMeanStrainLimit", "dMaxStrainLimit"],
        |f| n(f, "dMeanStrainLimit") > n(f, "dMaxStrainLimit"),
        "pkdgrav stops at start-up: `dMeanStrainLimit` must not be above `dMaxStrainLimit`",
    ),
    row(
        "A83",
        "SPRINGS",
        Stops,
        &["dLinkageLength"],
        |f| n(f, "dLinkageLength") <= 0.0,
        "pkdgrav stops at start-up: `dLinkageLength` must be above 0",
    ),
    row(
        "A84",
        "SPRINGS",
        Stops,
        &["dZeroStrainLength"],
        |f| n(f, "dZeroStrainLength") < 0.0,
        "pkdgrav stops at start-up: `dZeroStrainLength` must be 0 or more",
    ),
    row(
        "A85",
        "SPRINGS",
        Stops,
        &["dPorosityFactor"],
        |f| !unit(n(f, "dPorosityFactor")),
        "pkdgrav stops at start-up: `dPorosityFactor` must be in (0, 1]",
    ),
    row(
        "A86",
        "SPRINGS",
        Stops,
        &["nSmooth"],
        |f| n(f, "nSmooth") > 32.0,
        "pkdgrav stops at start-up: a SPRINGS build takes at most 32 neighbours (`nSmooth`); the default 64 is too many",
    ),
    row(
        "A87",
        "DEM",
        Stops,
        &["iCheckInterval"],
        |f| n(f, "iCheckInterval") > 0.0,
        "pkdgrav stops at start-up: a DEM build cannot restart from checkpoints (`iCheckInterval` must be 0)",
    ),
    row(
        "A88",
        "DEM",
        Stops,
        &["dKn"],
        |f| n(f, "dKn") < 0.0,
        "pkdgrav stops at start-up: the normal spring constant `dKn` must be 0 or more",
    ),
    row(
        "A89",
        "DEM",
        Stops,
        &["dKt", "dKn"],
        |f| k_t(f) < 0.0,
        "pkdgrav stops at start-up: the tangential spring constant `dKt` must be 0 or more (−1 is 2/7 of `dKn`)",
    ),
    row(
        "A90",
        "DEM",
        Stops,
        &["dMuS"],
        |f| n(f, "dMuS") < 0.0,
        "pkdgrav stops at start-up: `dMuS` must be 0 or more",
    ),
    row(
        "A91",
        "DEM",
        Stops,
        &["dMuR"],
        |f| n(f, "dMuR") < 0.0,
        "pkdgrav stops at start-up: `dMuR` must be 0 or more",
    ),
    row(
        "A92",
        "DEM",
        Stops,
        &["dMuT"],
        |f| n(f, "dMuT") < 0.0,
        "pkdgrav stops at start-up: `dMuT` must be 0 or more",
    ),
    row(
        "A93",
        "DEM",
        Stops,
        &["dAccCrit"],
        |f| n(f, "dAccCrit") < 0.0,
        "pkdgrav stops at start-up: `dAccCrit` must be 0 or more",
    ),
    row(
        "A94",
        "DEM",
        Stops,
        &["dTangentialSpringDrag"],
        |f| {
            !(0.0..=1.0).contains(&n(f, "dTangentialSpringDrag"))
                && !n(f, "dTangentialSpringDrag").is_nan()
        },
        "pkdgrav stops at start-up: `dTangentialSpringDrag` must be from 0 to 1",
    ),
    row(
        "A95",
        "DEM",
        Stops,
        &["dMinorFrac"],
        |f| n(f, "dMinorFrac") < 0.0,
        "pkdgrav stops at start-up: `dMinorFrac` must be 0 or more",
    ),
    row(
        "A96",
        "DEM",
        Stops,
        &["dMajorFrac", "dMinorFrac"],
        |f| n(f, "dMajorFrac") < n(f, "dMinorFrac"),
        "pkdgrav stops at start-up: `dMajorFrac` must be at least `dMinorFrac`",
    ),
    row(
        "A97",
        "DEM",
        Stops,
        &["dErrorFrac", "dMajorFrac"],
        |f| n(f, "dErrorFrac") < n(f, "dMajorFrac"),
        "pkdgrav stops at start-up: `dErrorFrac` must be at least `dMajorFrac`",
    ),
    row(
        "A98",
        "DEM",
        Stops,
        &["iDEMStatsInterval"],
        |f| n(f, "iDEMStatsInterval") < 0.0,
        "pkdgrav stops at start-up: `iDEMStatsInterval` must be 0 or more",
    ),
    row(
        "A99",
        "DEM && DEM_FIXED_BALL",
        Stops,
        &["iFixedBallOption"],
        |f| {
            ![0.0, 1.0, 2.0].contains(&n(f, "iFixedBallOption"))
                && !n(f, "iFixedBallOption").is_nan()
        },
        "pkdgrav stops at start-up: `iFixedBallOption` must be 0, 1 or 2",
    ),
    row(
        "A100",
        "DEM && DEM_ROTATION_DASHPOT",
        Stops,
        &["dBetaS"],
        |f| n(f, "dBetaS") < 0.0,
        "pkdgrav stops at start-up: `dBetaS` must be 0 or more",
    ),
    row(
        "A101",
        "DEM && DEM_COHESION",
        Stops,
        &["iCohesionModel"],
        |f| ![0.0, 1.0].contains(&n(f, "iCohesionModel")) && !n(f, "iCohesionModel").is_nan(),
        "pkdgrav stops at start-up: `iCohesionModel` must be 0 or 1",
    ),
    row(
        "A102",
        "DEM && DEM_COHESION",
        Stops,
        &["dCohesiveCoeff"],
        |f| n(f, "dCohesiveCoeff") < 0.0,
        "pkdgrav stops at start-up: `dCohesiveCoeff` must be 0 or more",
    ),
    row(
        "A103",
        "DEM && DEM_TWOLAYERS",
        Stops,
        &["dInnerOverlapBndry"],
        |f| n(f, "dInnerOverlapBndry") < 0.0,
        "pkdgrav stops at start-up: `dInnerOverlapBndry` must be 0 or more",
    ),
    row(
        "A104",
        "DEM && DEM_TWOLAYERS",
        Stops,
        &["dKnOuter", "dKnInner", "dKtOuter", "dKtInner", "dKn"],
        |f| {
            let (outer, inner) = layers(f);
            [
                outer,
                inner,
                spring(n(f, "dKtOuter"), outer),
                spring(n(f, "dKtInner"), inner),
            ]
            .iter()
            .any(|&k| k <= 0.0)
        },
        "pkdgrav stops at start-up: every two-layer spring constant must be above 0 once its −1 is resolved (both normal constants −1 are `dKn`; a tangential −1 is 2/7 of its normal constant; one normal constant alone left at −1 stays −1)",
    ),
    row(
        "A120",
        "COLLISIONS",
        Stops,
        &["nSuperCool"],
        |f| n(f, "nSuperCool") != 0.0,
        "pkdgrav aborts at start-up: `nSuperCool` must be 0 in a collisions build",
    ),
    row(
        "A126",
        "COLLISIONS",
        Stops,
        &["bFindRejects"],
        |f| n(f, "bFindRejects") != 0.0,
        "pkdgrav stops after its search for overlapping initial conditions (`bFindRejects`) and runs no step: status 1 when it finds some (it writes a rejects file), 0 otherwise",
    ),
    row(
        "N1",
        "DEM",
        Stops,
        &["dEpsN", "dEpsT"],
        |f| n(f, "dEpsN") <= 0.0 || n(f, "dEpsT") <= 0.0,
        "pkdgrav does not check it at start-up but aborts at the first particle contact: a DEM build needs `dEpsN` and `dEpsT` above 0",
    ),
    row(
        "N2",
        "DEM",
        Stops,
        &["nDEMOutputs", "iOutInterval"],
        |f| n(f, "nDEMOutputs") <= -2.0 && n(f, "iOutInterval") == 0.0,
        "pkdgrav divides by zero at the first output (SIGFPE): `nDEMOutputs` of −2 or less with `iOutInterval = 0`",
    ),
    row(
        "B4",
        "always",
        Warns,
        &["nReplicas", "bPeriodic"],
        |f| n(f, "bPeriodic") == 0.0 && n(f, "nReplicas") != 0.0,
        "pkdgrav warns at start-up: `nReplicas` is not 0 in a run that is not periodic",
    ),
    verbose(row(
        "B5",
        "always",
        Warns,
        &["dTheta"],
        |f| n(f, "dTheta") == 0.0,
        "pkdgrav warns at start-up: an opening angle `dTheta` of 0 is risky",
    )),
    row(
        "B6",
        "always",
        Warns,
        &["bDoSelfGravity", "bDoGravity"],
        |f| n(f, "bDoSelfGravity") != 0.0 && n(f, "bDoGravity") == 0.0,
        "pkdgrav warns at start-up: `bDoSelfGravity` may need `bDoGravity`",
    ),
    row(
        "B7",
        "always",
        Warns,
        &["bCannonical", "bComove"],
        |f| n(f, "bComove") == 0.0 && n(f, "bCannonical") == 0.0,
        "pkdgrav warns at start-up and sets `bCannonical` back to 1: without comoving coordinates (`bComove = 0`) it is always 1",
    ),
    row(
        "B8",
        "always",
        Warns,
        &["bPhysicalSoft", "bComove"],
        |f| n(f, "bComove") == 0.0 && n(f, "bPhysicalSoft") != 0.0,
        "pkdgrav warns at start-up and sets `bPhysicalSoft` back to 0: without comoving coordinates (`bComove = 0`) it is always 0",
    ),
    verbose(row(
        "B9",
        "always",
        Warns,
        &["iMaxRung"],
        |f| n(f, "iMaxRung") < 1.0,
        "pkdgrav warns at start-up and sets `iMaxRung` to 1",
    )),
    row(
        "B10",
        "always",
        Warns,
        &["iMaxRung"],
        |f| n(f, "iMaxRung") > 29.0,
        "pkdgrav warns at start-up and reduces `iMaxRung` to 29",
    ),
    verbose(row(
        "B15",
        "COLLISIONS && DEM && !DEM_FIXED_BALL",
        Warns,
        &["nSmooth"],
        |f| n(f, "nSmooth") < 2.0,
        "pkdgrav warns at start-up: with `nSmooth` below 2 no neighbours are found (no particle contacts)",
    )),
    verbose(row(
        "B16",
        "COLLISIONS && !DEM && WALLS",
        Warns,
        &["nSmooth"],
        |f| n(f, "nSmooth") < 1.0,
        "pkdgrav warns at start-up: with `nSmooth` below 1 collision detection is off",
    )),
    row(
        "B19",
        "COLLISIONS && !DEM",
        Warns,
        &[
            "dMergeLimit",
            "dDensity",
            "iDensityAltCol",
            "dDensityAltVal",
            "iOutcomes",
            "nSmooth",
        ],
        |f| {
            hard_block(f)
                && !has(f, MERGE)
                && [
                    "dMergeLimit",
                    "dDensity",
                    "iDensityAltCol",
                    "dDensityAltVal",
                ]
                .iter()
                .any(|k| n(f, k) != 0.0)
        },
        "pkdgrav warns at start-up that the merge parameters are ignored without the merge outcome; `dMergeLimit` defaults to 1, so set it to 0 to be rid of the warning",
    ),
    row(
        "B21",
        "COLLISIONS && !DEM",
        Warns,
        &["dFragLimit", "iOutcomes", "nSmooth"],
        |f| hard_block(f) && !has(f, FRAG) && n(f, "dFragLimit") != 0.0,
        "pkdgrav warns at start-up that `dFragLimit` is ignored without the fragmentation outcome (4)",
    ),
    row(
        "B22",
        "COLLISIONS && !DEM",
        Warns,
        &["iOverlapOption", "nSmooth"],
        |f| hard_block(f) && n(f, "iOverlapOption") == -1.0,
        "pkdgrav warns at start-up: overlaps are ignored (`iOverlapOption = -1`)",
    ),
    row(
        "B23",
        "COLLISIONS && !DEM",
        Warns,
        &["iOverlapOption", "nSmooth"],
        |f| hard_block(f) && (1.0..=4.0).contains(&n(f, "iOverlapOption")),
        "pkdgrav prints a long caution about its overlap handling (`iOverlapOption` 1 to 4) at start-up",
    ),
    row(
        "B24",
        "COLLISIONS && !DEM",
        Warns,
        &["dBackstepLimit", "iOverlapOption", "dDelta", "nSmooth"],
        |f| {
            hard_block(f)
                && n(f, "iOverlapOption") == 1.0
                && (n(f, "dBackstepLimit") == 0.0 || n(f, "dBackstepLimit") > n(f, "dDelta"))
        },
        "pkdgrav warns at start-up that the backstep limit exceeds `dDelta` (its default 0 means no limit)",
    ),
    row(
        "B25",
        "COLLISIONS && !DEM",
        Warns,
        &[
            "dBackstepLimit",
            "dAdjPosLimit",
            "dRepelFac",
            "iOverlapOption",
            "nSmooth",
        ],
        |f| {
            hard_block(f)
                && [
                    ("dBackstepLimit", 1.0),
                    ("dAdjPosLimit", 2.0),
                    ("dRepelFac", 3.0),
                ]
                .iter()
                .any(|&(k, option)| n(f, k) != 0.0 && n(f, "iOverlapOption") != option)
        },
        "pkdgrav warns at start-up that `dBackstepLimit`, `dAdjPosLimit` or `dRepelFac` is ignored without its overlap option (`iOverlapOption` 1, 2 or 3)",
    ),
    row(
        "B26",
        "COLLISIONS && AGGS",
        Warns,
        &["bDoGravity"],
        |f| n(f, "bDoGravity") == 0.0,
        "pkdgrav warns at start-up: aggregates' accelerations and torques expect `bDoGravity`",
    ),
    row(
        "B27",
        "AGGS",
        Warns,
        &["dFragLimit", "dMergeLimit", "iOutcomes"],
        |f| has(f, FRAG) && has(f, MERGE) && n(f, "dFragLimit") * n(f, "dMergeLimit") < 0.0,
        "pkdgrav warns at start-up that `dFragLimit` and `dMergeLimit` have opposite signs (one in escape speeds, the other in physical units)",
    ),
    row(
        "B28",
        "COLLISIONS && AGGS",
        Warns,
        &["iEpsNOption"],
        |f| n(f, "iEpsNOption") != 0.0 && !n(f, "iEpsNOption").is_nan(),
        "pkdgrav warns at start-up: a variable `dEpsN` (`iEpsNOption`) is a hack with aggregates",
    ),
    row(
        "B29",
        "COLLISIONS && AGGS",
        Warns,
        &["dEpsT"],
        |f| n(f, "dEpsT") != 1.0 && !n(f, "dEpsT").is_nan(),
        "pkdgrav warns at start-up: aggregates ignore the tangential restitution `dEpsT`",
    ),
    row(
        "B31",
        "DEM && AGGS",
        Warns,
        &["dMuR", "dMuT"],
        |f| n(f, "dMuR") > 0.0 || n(f, "dMuT") > 0.0,
        "pkdgrav warns at start-up and sets the particles' rolling and twisting friction (`dMuR`, `dMuT`) to 0 with aggregates",
    ),
    verbose(row(
        "B33",
        "WALLS",
        Warns,
        &["achWallsFile"],
        |f| f.string("achWallsFile").is_some_and(|s| s.is_empty()),
        "pkdgrav warns at start-up: no walls (`achWallsFile` is empty)",
    )),
    row(
        "B34",
        "WALLS && DEM_WALLS_REACT",
        Warns,
        &["bDoGravity"],
        |f| n(f, "bDoGravity") == 0.0,
        "pkdgrav warns at start-up: reactive walls expect `bDoGravity`",
    ),
    verbose(row(
        "B37",
        "DEM",
        Warns,
        &["iOutcomes"],
        |f| n(f, "iOutcomes") != 0.0 && !n(f, "iOutcomes").is_nan(),
        "pkdgrav warns at start-up that a DEM build ignores `iOutcomes` (set it to 0 to be rid of the warning; its default is 2)",
    )),
    row(
        "B38",
        "DEM",
        Warns,
        &["dKn"],
        |f| n(f, "dKn") == 0.0,
        "pkdgrav warns at start-up: the normal spring constant `dKn` is 0 (its default): particles pass through walls and each other",
    ),
    row(
        "B39",
        "DEM",
        Warns,
        &["dKt", "dKn"],
        |f| k_t(f) == 0.0,
        "pkdgrav warns at start-up: the tangential spring constant is 0 (`dKt`, or 2/7 of a `dKn` of 0)",
    ),
    row(
        "B40",
        "DEM",
        Warns,
        &["dEpsT", "dMuS"],
        |f| n(f, "dEpsT") < 1.0 && n(f, "dMuS") == 0.0,
        "pkdgrav warns at start-up: `dEpsT` below 1 does nothing without static friction (`dMuS` is 0)",
    ),
    row(
        "B41",
        "DEM",
        Warns,
        &["dTangentialSpringDrag"],
        |f| {
            ![0.0, 1.0].contains(&n(f, "dTangentialSpringDrag"))
                && !n(f, "dTangentialSpringDrag").is_nan()
        },
        "pkdgrav warns at start-up: a `dTangentialSpringDrag` other than 0 or 1 depends on the timestep",
    ),
    row(
        "B42",
        "DEM && DEM_TWOLAYERS",
        Warns,
        &["dKnOuter", "dKnInner", "dKn"],
        |f| {
            let (outer, inner) = layers(f);
            outer >= inner
        },
        "pkdgrav warns at start-up: the outer layer is as stiff as the inner one or stiffer (`dKnOuter` ≥ `dKnInner`, both −1 being `dKn`)",
    ),
    verbose(row(
        "B43",
        "always",
        Warns,
        &["bUseWallClock"],
        |f| n(f, "bUseWallClock") == 0.0,
        "pkdgrav warns at start-up: the times it reports are CPU time (`bUseWallClock = 0`)",
    )),
    row(
        "C5",
        "always",
        Changes,
        &["bFandG", "bPeriodic"],
        |f| n(f, "bFandG") != 0.0 && n(f, "bPeriodic") != 0.0,
        "pkdgrav sets `bPeriodic` to 0 when `bFandG` is on, without a word",
    ),
    row(
        "C7",
        "always",
        Changes,
        &["bPeriodic", "nReplicas"],
        |f| n(f, "bPeriodic") != 0.0 && f.given("nReplicas").is_none(),
        "pkdgrav sets `nReplicas` to 1 in a periodic run that does not give it",
    ),
    row(
        "C9",
        "always",
        Changes,
        &["dPeriod"],
        |f| {
            f.given("dPeriod").is_some()
                && ["dxPeriod", "dyPeriod", "dzPeriod"]
                    .iter()
                    .any(|k| f.given(k).is_none())
        },
        "pkdgrav copies `dPeriod` into each of `dxPeriod`, `dyPeriod`, `dzPeriod` the file does not give (a period of 0 is infinite)",
    ),
    row(
        "C28",
        "COLLISIONS",
        Changes,
        &["dSoft"],
        |f| f.given("dSoft").is_some(),
        "pkdgrav replaces every particle's radius with `dSoft` when the .par file gives it (any value, 0 too), without a word",
    ),
    row(
        "N3",
        "always",
        Differs,
        &["dDelta"],
        |f| n(f, "dDelta") <= 0.0,
        "pkdgrav never checks `dDelta`: 0 (its default) runs `nSteps` steps of no length, a negative value runs backwards",
    ),
    row(
        "N4",
        "always",
        Differs,
        &["nSteps", "iStartStep"],
        |f| n(f, "nSteps") <= n(f, "iStartStep"),
        "pkdgrav runs no step and writes no output, and exits with status 0, when `nSteps` is not above `iStartStep`",
    ),
    row(
        "N5",
        "DEM",
        Differs,
        &["bDoGravity"],
        |f| n(f, "bDoGravity") == 0.0,
        "pkdgrav evaluates no forces at all with `bDoGravity = 0` in a DEM build (its contact forces are computed in the gravity step): no uniform gravity, no contacts",
    ),
    row(
        "N6",
        "DEM",
        Differs,
        &["dEpsN", "dEpsT"],
        |f| n(f, "dEpsN") > 1.0 || n(f, "dEpsT") > 1.0,
        "pkdgrav accepts a restitution above 1 (`dEpsN`, `dEpsT`) without a word: negative damping, contacts that add energy",
    ),
    row(
        "N7",
        "DEM",
        Differs,
        &["iOutInterval", "nDEMOutputs"],
        |f| n(f, "iOutInterval") == 0.0 && n(f, "nDEMOutputs") >= 1.0,
        "pkdgrav deletes the `.dem` contact file it writes at the final output straight after writing it when `iOutInterval` is 0 and `nDEMOutputs` 1 or more (its defaults)",
    ),
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::keys;

    #[test]
    fn every_row_names_registered_keys_and_known_options() {
        let every = crate::options::every_build();
        let mut ids = std::collections::HashSet::new();
        for c in CHECKS {
            assert!(ids.insert(c.id), "{} twice", c.id);
            let _ = every.meets(c.build);
            for k in c.keys {
                assert!(keys::any(k).next().is_some(), "{}: `{k}` is no key", c.id);
            }
        }
    }
}
