//! `io::par`: pkdgrav's `.par` keys as pkdgrav reads them: its sentinels (`dKt = -1`,
//! the two-layer −1s), step numbers and output interval, the refusals that are errors
//! with the line, the 127-byte line limit, and the warnings for every line the evaluator
//! does not follow.

use walls_sim::io::par::{KT_PER_KN, LINE_LIMIT, ParWarning, TwoLayer, read_par, suggestion};

/// The keys of a `.par` file's warnings, with their lines.
fn warned(text: &str) -> Vec<(Option<usize>, String)> {
    read_par(text)
        .unwrap()
        .warnings
        .into_iter()
        .map(|w| (w.line, w.key))
        .collect()
}

/// What a run directory sets so that pkdgrav's DEM build runs it (no warnings).
const QUIET: &str = "dKn = 1e5\nbDoSelfGravity = 0\niForceOverrideOption = 2\niCheckInterval = 0\n";

#[test]
fn pkdgrav_writes_2_7_as_the_double_nearest() {
    assert_eq!(KT_PER_KN, 2.0 / 7.0);
}

#[test]
fn dkt_minus_one_is_two_sevenths_of_dkn_and_other_negatives_are_errors() {
    let p = read_par(&format!("{QUIET}dKt = -1\n")).unwrap();
    // None: "2/7 of the normal constant", resolved against the run's k_n (config).
    assert_eq!((p.k_n, p.k_t), (Some(1e5), None));
    assert_eq!(p.warnings, vec![]);
    assert_eq!(read_par("dKt = 0\n").unwrap().k_t, Some(0.0));
    assert_eq!(read_par("dKt = 3e4\n").unwrap().k_t, Some(3e4));
    assert_eq!(
        read_par("dKt = -2\n").unwrap_err().to_string(),
        "line 1: `dKt` is `-2`; it must be 0 or more, or -1 (pkdgrav's \"2/7 of the normal constant\")"
    );
}

#[test]
fn two_layer_sentinels_fall_back_to_dkn_and_two_sevenths() {
    let p = read_par(&format!(
        "{QUIET}dInnerOverlapBndry = 0.1\ndKnOuter = -1\ndKtOuter = -1\ndKnInner = 4e5\ndKtInner = -1\n"
    ))
    .unwrap();
    assert_eq!(
        p.two_layer,
        Some(TwoLayer {
            boundary: 0.1,
            k_n_outer: 1e5,
            k_t_outer: KT_PER_KN * 1e5,
            k_n_inner: 4e5,
            k_t_inner: KT_PER_KN * 4e5,
        })
    );
    // Followed by a DEM_TWOLAYERS build: no warning here; each line is kept with its
    // option, for `config` to warn about when the run's build lacks it.
    assert_eq!(p.warnings, vec![]);
    let lines: Vec<_> = p.optional_keys.iter().map(|k| (k.line, k.option)).collect();
    assert_eq!(
        lines,
        [5, 6, 7, 8, 9].map(|n| (n, "DEM_TWOLAYERS")).to_vec()
    );
    // Only dKnInner given: the outer layer is dKn's.
    let p = read_par(&format!("{QUIET}dKnInner = 2e5\n")).unwrap();
    let layers = p.two_layer.unwrap();
    assert_eq!((layers.k_n_outer, layers.k_t_inner), (1e5, KT_PER_KN * 2e5));
    // Without them, no two-layer constants.
    assert_eq!(read_par(QUIET).unwrap().two_layer, None);
    // After the fall-backs every constant must be above 0: dKn 0 leaves the outer 0.
    assert_eq!(
        read_par("dKn = 0\ndKnInner = 5\n").unwrap_err().to_string(),
        "line 1: `dKnOuter` comes to 0; pkdgrav needs every two-layer spring constant above 0 (−1 means dKn, or 2/7 of the normal constant)"
    );
    assert_eq!(
        read_par("dKn = 1\ndKtOuter = -3\n")
            .unwrap_err()
            .to_string(),
        "line 2: `dKtOuter` is `-3`; it must be 0 or more, or -1 (pkdgrav's \"2/7 of the normal constant\")"
    );
}

#[test]
fn negative_values_pkdgrav_refuses_are_errors_with_the_line() {
    for (text, message) in [
        ("dKn = -1\n", "line 1: `dKn` is `-1`; it must be 0 or more"),
        (
            "nDigits = 5.5\n",
            "line 1: `nDigits` is `5.5`; it must be a whole number, 0 or more",
        ),
        (
            "nDigits = 99\n",
            "line 1: `nDigits` is `99`; it must be at most 20",
        ),
        (
            "\ndMuR = -0.5\n",
            "line 2: `dMuR` is `-0.5`; it must be 0 or more",
        ),
        (
            "dMuT = -1\n",
            "line 1: `dMuT` is `-1`; it must be 0 or more",
        ),
        (
            "dBetaS = -1\n",
            "line 1: `dBetaS` is `-1`; it must be 0 or more",
        ),
        (
            "iStartStep = -3\n",
            "line 1: `iStartStep` is `-3`; it must be a whole number, 0 or more",
        ),
        (
            "nSteps = 2e4\n",
            "line 1: `nSteps` is `2e4`; it must be a whole number, 0 or more",
        ),
    ] {
        assert_eq!(read_par(text).unwrap_err().to_string(), message, "{text}");
    }
}

#[test]
fn steps_start_and_output_interval() {
    let p = read_par("nSteps = 20000\niStartStep = 100\niOutInterval = 20\n").unwrap();
    assert_eq!(
        (p.steps, p.start_step, p.out_interval),
        (Some(20000), Some(100), Some(20))
    );
    let p = read_par("dDelta = 1.05309e-12\n").unwrap();
    assert_eq!((p.steps, p.start_step, p.out_interval), (None, None, None));
}

#[test]
fn lines_longer_than_pkdgrav_reads_are_errors() {
    let fits = format!("achOutName = {}\n", "a".repeat(LINE_LIMIT - 13));
    assert_eq!(fits.len(), LINE_LIMIT + 1);
    assert!(read_par(&fits).is_ok());
    // One byte more: pkdgrav's 128-byte chunk ends before the newline. Comments count.
    let long = format!(
        "dDelta = 1e-5\ndKn = 1  # {}\n",
        "x".repeat(LINE_LIMIT - 10)
    );
    assert_eq!(
        read_par(&long).unwrap_err().to_string(),
        "line 2: the line is 128 bytes long; pkdgrav reads .par lines 127 bytes at a time, so it would read the rest of the line as a line of its own and stop with a syntax error: keep lines (comments included) to 127 bytes"
    );
}

#[test]
fn unknown_keys_warn_with_a_suggestion() {
    let p = read_par(&format!(
        "{QUIET}dKN = 5\nnFoo = 3\ndMuS=0.1\ndzUnifGrv = -1\n"
    ))
    .unwrap();
    assert_eq!(
        p.warnings,
        vec![
            ParWarning {
                line: Some(5),
                key: "dKN".into(),
                message: "the evaluator does not model it, so it is ignored (pkdgrav follows it, if its build registers it); did you mean `dKn`?".into(),
            },
            ParWarning {
                line: Some(6),
                key: "nFoo".into(),
                message: "the evaluator does not model it, so it is ignored (pkdgrav follows it, if its build registers it)".into(),
            },
            ParWarning {
                line: Some(8),
                key: "dzUnifGrv".into(),
                message: "the evaluator does not model it, so it is ignored (pkdgrav follows it, if its build registers it); did you mean `dzUnifGrav`?".into(),
            },
        ]
    );
    // The misspelt key is not read.
    assert_eq!(p.k_n, Some(1e5));
    assert_eq!(p.gravity, None);
    assert_eq!(suggestion("achWallFile"), Some("achWallsFile"));
    assert_eq!(suggestion("bDoSelfGrav"), None);
    assert_eq!(
        p.warnings[0].to_string(),
        "line 5: `dKN`: the evaluator does not model it, so it is ignored (pkdgrav follows it, if its build registers it); did you mean `dKn`?"
    );
}

#[test]
fn values_and_keys_the_evaluator_does_not_model_warn() {
    // `dBetaS` and `bUseContactRadius` are modelled (the rolling and twisting of
    // Integrator::Pkdgrav), and so is `dErrorFrac` (the overlap levels): no warning. `bDoGravity = 0` is followed (no forces at all),
    // with a warning that says what it means.
    let text = format!(
        "{QUIET}bDoGravity = 0\ndBetaS = 0.6\ndErrorFrac = 0.4\ndCohesiveCoeff = 0\nbUseContactRadius = 1\ndSlideLimit = 0.1\nnSmooth = 16\n"
    );
    assert_eq!(
        warned(&text),
        [
            (Some(5), "bDoGravity".to_string()),
            (Some(10), "dSlideLimit".into()),
        ]
    );
    let p = read_par(&text).unwrap();
    assert!(
        p.warnings[0].message.contains("no forces at all"),
        "{}",
        p.warnings[0]
    );
    // Left out, pkdgrav's defaults the evaluator does not follow warn too.
    assert_eq!(
        warned("dDelta = 1e-5\n"),
        [
            (None, "bDoSelfGravity".to_string()),
            (None, "iForceOverrideOption".into()),
            (None, "iCheckInterval".into()),
            (None, "dKn".into()),
        ]
    );
    assert_eq!(
        read_par("dDelta = 1e-5\n").unwrap().warnings[3].to_string(),
        "`dKn` not given: pkdgrav's default is 0 (no normal spring); the evaluator derives k_n from the scene instead (docs/evaluator.md)"
    );
    // dKn = 0 is pkdgrav's warning.
    assert_eq!(
        warned("dKn = 0\nbDoSelfGravity = 0\niForceOverrideOption = 2\niCheckInterval = 0\n"),
        [(Some(1), "dKn".to_string())]
    );
}

#[test]
fn the_run_directory_case_reads() {
    let golden =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/sim/rundir/params.par");
    let p = read_par(&std::fs::read_to_string(golden).unwrap()).unwrap();
    assert_eq!(p.walls_file.as_deref(), Some("walls.dat"));
    assert_eq!(p.k_t, None, "dKt = -1");
}

#[test]
fn a_key_given_twice_takes_the_later_line_and_warns() {
    let p = read_par(&format!(
        "{QUIET}dDelta = 1e-5\ndDelta = 2e-5\nbDoGravity = 2\n"
    ))
    .unwrap();
    assert_eq!(p.dt, Some(2e-5));
    // A switch is on at any value but 0, as pkdgrav's C ints: no warning for 2.
    assert_eq!(
        p.warnings,
        vec![ParWarning {
            line: Some(5),
            key: "dDelta".into(),
            message: "given again on line 6, which wins (as in pkdgrav)".into(),
        }]
    );
}

#[test]
fn the_overlap_levels_are_read_and_must_be_in_order() {
    let p = read_par(&format!(
        "{QUIET}dMinorFrac = 0.01
dErrorFrac = 0.3
"
    ))
    .unwrap();
    assert_eq!(p.overlap_fracs, [Some(0.01), None, Some(0.3)]);
    assert_eq!(p.warnings, vec![]);
    assert_eq!(read_par(QUIET).unwrap().overlap_fracs, [None; 3]);
    // pkdgrav's defaults count: a minor level above 0.15 needs a major level too.
    assert_eq!(
        read_par("dMinorFrac = 0.2\n").unwrap_err().to_string(),
        "line 1: `dMinorFrac` is 0.2 and `dMajorFrac` 0.15: pkdgrav stops at start-up unless 0 ≤ dMinorFrac ≤ dMajorFrac ≤ dErrorFrac (its defaults 0.03, 0.15, 0.5)"
    );
    assert!(read_par("dMinorFrac = 0.2\ndMajorFrac = 0.2\n").is_ok());
    assert_eq!(
        read_par("dMajorFrac = 0.3\ndErrorFrac = 0.25\n")
            .unwrap_err()
            .to_string(),
        "line 2: `dMajorFrac` is 0.3 and `dErrorFrac` 0.25: pkdgrav stops at start-up unless 0 ≤ dMinorFrac ≤ dMajorFrac ≤ dErrorFrac (its defaults 0.03, 0.15, 0.5)"
    );
    assert_eq!(
        read_par("dMinorFrac = -0.1\n").unwrap_err().to_string(),
        "line 1: `dMinorFrac` is `-0.1`; it must be 0 or more"
    );
}

#[test]
fn the_reduced_output_interval_is_read_as_a_count() {
    let p = read_par(&format!("{QUIET}iRedOutInterval = 20\n")).unwrap();
    assert_eq!(p.red_out_interval, Some(20));
    assert_eq!(p.warnings, vec![]);
    assert_eq!(read_par(QUIET).unwrap().red_out_interval, None);
    assert_eq!(
        read_par("iRedOutInterval = 2e3\n").unwrap_err().to_string(),
        "line 1: `iRedOutInterval` is `2e3`; it must be a whole number, 0 or more"
    );
}
