//! A run as a pkdgrav run directory (`walls-sim export`): the `.par` file's settings that
//! make pkdgrav run what walls-sim runs, each with where its value came from, and the
//! directory's README naming the build and the commands. walls-cli writes the files.
//!
//! Every value the run depends on is written, with the exact digits that read back as
//! the run's double: the timestep and the last step (the end time counted in steps),
//! the outputs, the particles' material, gravity, the contact switches, cohesion and
//! two-layer constants in the builds that have them, and the keys walls-sim follows at
//! one value only where pkdgrav's default differs ([`walls_par::evaluator::Use::Only`]:
//! `iForceOverrideOption = 2`, `iCheckInterval = 0`, `bDoSelfGravity = 0`). The other
//! lines of a `.par` file the run came from are copied as they were, after them.
//! What pkdgrav has no key for (`--no-particle-contacts`, no particles) is refused.

use crate::config::{self, Flags, Outputs};
use crate::run::Settings;
use walls_par::check::File;
use walls_par::evaluator::{self, Use};
use walls_par::write::{Section, Setting, Value};

/// The names of the run directory's files, as the `.par` file names them.
#[derive(Debug, Clone, Copy)]
pub struct Names<'a> {
    /// The `.par` file.
    pub par: &'a str,
    /// The walls file (`achWallsFile`).
    pub walls: &'a str,
    /// The initial conditions (`achInFile`).
    pub particles: &'a str,
    /// The cohesion file (`achCohesionFile`), when the run reads one.
    pub cohesion: Option<&'a str>,
}

/// The `.par` file a run came from: its name, and its lines read for the build.
pub struct Source<'a> {
    /// Its name, as the comments show it (the last part of its path: the comments do
    /// not carry the folders of the machine it was exported on).
    pub path: &'a str,
    /// Its lines.
    pub file: &'a File<'a>,
}

/// What the exported `.par` file says, and what it is for.
pub struct Export {
    /// The file's text.
    pub par: String,
    /// The build pkdgrav must be compiled with.
    pub build: walls_par::Build,
    /// The number of the last step (`nSteps`).
    pub last_step: u64,
    /// The digits of the outputs' step numbers (`nDigits`).
    pub digits: usize,
    /// What the user should know: the source's lines copied that name files the export
    /// does not carry, or whose physics walls-sim does not follow; a folder of
    /// `achOutName` not kept.
    pub warnings: Vec<String>,
}

/// The `.par` file of the run that `flags`, `source` and the defaults settled as
/// `settings` (with `outputs`), for the directory whose files are `names`; an error
/// saying what pkdgrav cannot be told.
pub fn par_file(
    flags: &Flags,
    source: Option<&Source>,
    settings: &Settings,
    outputs: &Outputs,
    names: &Names,
) -> Result<Export, String> {
    let build = walls_par::Build::parse(&settings.build.names())
        .map_err(|e| format!("the build's option {} is not pkdgrav's", e.name))?;
    if !settings.particle_contacts {
        return Err(
            "--no-particle-contacts has no pkdgrav key: pkdgrav's particles always meet each other; leave it out to export"
                .into(),
        );
    }
    let last_step = settings.end_step();
    let mut written = Written {
        warnings: Vec::new(),
        source,
        build: &build,
        sections: Vec::new(),
    };
    written.section("the files (beside this one)");
    written.text("achInFile", names.particles, "the initial conditions");
    written.text("achWallsFile", names.walls, "the walls file");
    written.text(
        "achOutName",
        &outputs.ss.base,
        "the outputs' names, NAME.STEP (pkdgrav's default is pkdgrav)",
    );
    // A folder in the source's `achOutName` is not kept: the outputs go beside `ss.par`.
    if let (Some(_), Some(source)) = (&outputs.ss_warning, source)
        && let Some(entry) = source.file.given("achOutName")
    {
        let said = format!(
            "{} line {} names `{}`: its folder is not kept, the outputs are named {}.NNNNN beside ss.par",
            source.path,
            entry.line,
            source.file.string("achOutName").unwrap_or_default(),
            outputs.ss.base
        );
        written.append_to_last(&format!("; {said}"));
        written.warnings.push(said);
    }
    // Every output's name is as wide as the last one's, so that they sort in step order
    // (R008): pkdgrav's default, or the source's nDigits, is widened when it is narrower.
    let wide = last_step.to_string().len();
    let digits = outputs.ss.digits.max(wide);
    if digits == outputs.ss.digits {
        written.int("nDigits", digits as i128, None, "pkdgrav's default");
    } else {
        let was = match source.and_then(|s| Some((s.path, s.file.given("nDigits")?))) {
            Some((path, entry)) => {
                let said = format!(
                    "{path} line {} gives nDigits = {}, narrower than the last step's {digits} digits: written {digits}, so that the outputs' names sort in step order",
                    entry.line, outputs.ss.digits
                );
                written.warnings.push(said);
                format!("{path} line {}'s {}", entry.line, outputs.ss.digits)
            }
            None => format!("pkdgrav's default {}", outputs.ss.digits),
        };
        written.push(
            "nDigits",
            Value::Int(digits as i128),
            format!(
                "nDigits: the last step's {digits} digits ({was} would make the last outputs' names wider than the first ones')"
            ),
        );
    }
    if let Some(file) = names.cohesion {
        written.text(
            "achCohesionFile",
            file,
            "the cohesion coefficients by colour",
        );
    }

    written.section("the steps");
    written.real(
        "dDelta",
        settings.dt,
        flag(flags.inputs.dt, "--dt"),
        &dt_default(settings),
    );
    let steps_from = flags.inputs.t_end.map(|t| {
        format!(
            "--t-end {} in steps of dDelta (the last ends at or after it)",
            walls_par::write::real(t)
        )
    });
    let ends = format!(
        "; the run ends at t = nSteps*dDelta = {}",
        walls_par::write::real(last_step as f64 * settings.dt)
    );
    written.int(
        "nSteps",
        i128::from(last_step),
        steps_from,
        "walls-sim's default end time (three free falls over the scene) in steps of dDelta",
    );
    written.append_to_last(&ends);
    if settings.start_step != 0 || written.given("iStartStep") {
        written.int(
            "iStartStep",
            i128::from(settings.start_step),
            None,
            "pkdgrav's default",
        );
    }
    if let Some(n) = outputs.reduced {
        written.int("iRedOutInterval", i128::from(n), None, "pkdgrav's default");
    }
    written.int(
        "iOutInterval",
        i128::from(outputs.every),
        flags.counts.every.map(|n| format!("--every {n}")),
        &format!(
            "walls-sim's default, an output every {} steps",
            config::EVERY
        ),
    );

    written.section("the particles' material");
    let m = &settings.material;
    let material_default = if source.is_some() {
        "pkdgrav's default"
    } else {
        "walls-sim's default"
    };
    let given = &flags.inputs;
    written.real(
        "dEpsN",
        m.eps_n,
        flag(given.eps_n, "--epsn"),
        material_default,
    );
    written.real(
        "dEpsT",
        m.eps_t,
        flag(given.eps_t, "--epst"),
        material_default,
    );
    written.real(
        "dKn",
        m.k_n,
        flag(given.k_n, "--k-n"),
        "walls-sim's default, from the particles' size and speed and the scene (docs/evaluator.md)",
    );
    // pkdgrav's −1 is 2/7 of dKn, computed as the run computed it.
    let k_t = if m.k_t.to_bits() == (walls_par::KT_PER_KN * m.k_n).to_bits() {
        -1.0
    } else {
        m.k_t
    };
    written.real(
        "dKt",
        k_t,
        flag(given.k_t, "--k-t"),
        "2/7 of dKn, pkdgrav's default (-1)",
    );
    written.real("dMuS", m.mu_s, flag(given.mu_s, "--mu-s"), material_default);
    written.real("dMuR", m.mu_r, flag(given.mu_r, "--mu-r"), material_default);
    written.real("dMuT", m.mu_t, flag(given.mu_t, "--mu-t"), material_default);
    written.real("dBetaS", m.beta_s, None, "pkdgrav's default");

    written.section("forces and contacts");
    let gravity_from = given.gravity.as_ref().map(|_| "--gravity".to_string());
    let gravity_default = if source.is_none() && flags.inputs.particles.is_none() {
        "walls-sim's default for its own particles"
    } else {
        "pkdgrav's default"
    };
    for (key, g) in ["dxUnifGrav", "dyUnifGrav", "dzUnifGrav"]
        .into_iter()
        .zip(settings.gravity.iter())
    {
        written.real(key, *g, gravity_from.clone(), gravity_default);
    }
    written.flag_key(
        "bDoGravity",
        settings.forces,
        None,
        "pkdgrav's default: forces are evaluated",
    );
    written.flag_key(
        "bWallsEdgeDetect",
        settings.edges,
        flags.inputs.no_edges.then(|| "--no-edges".to_string()),
        "pkdgrav's default",
    );
    written.flag_key(
        "bUseContactRadius",
        settings.contact_radius,
        None,
        "pkdgrav's default",
    );
    written.flag_key(
        "bUseLegacyRoll",
        settings.legacy_roll,
        None,
        "pkdgrav's default",
    );
    written.real(
        "dAccCrit",
        settings.acc_crit,
        None,
        "pkdgrav's default: off",
    );
    let levels = &settings.overlap_levels;
    for (key, level) in [
        ("dMinorFrac", levels.minor),
        ("dMajorFrac", levels.major),
        ("dErrorFrac", levels.error),
    ] {
        written.real(
            key,
            level,
            None,
            "pkdgrav's default overlap level, a fraction of the radius",
        );
    }
    if build.has("DEM_COHESION") {
        written.int(
            "iCohesionModel",
            settings.cohesion.model.code().into(),
            None,
            "pkdgrav's default",
        );
        written.real(
            "dCohesiveCoeff",
            settings.cohesion.coefficient,
            None,
            "pkdgrav's default",
        );
    }
    if let Some(t) = settings.two_layer.filter(|_| build.has("DEM_TWOLAYERS")) {
        for (key, x) in [
            ("dInnerOverlapBndry", t.boundary),
            ("dKnOuter", t.k_n_outer),
            ("dKtOuter", t.k_t_outer),
            ("dKnInner", t.k_n_inner),
            ("dKtInner", t.k_t_inner),
        ] {
            written.real(key, x, None, "pkdgrav's default");
        }
    }

    written.section("what walls-sim runs as pkdgrav does at one value only");
    for &(key, u) in evaluator::KEYS {
        if let Use::Only {
            value,
            default,
            why,
        } = u
            && (value != default || written.says_otherwise(key, value))
            && (build.has("DEM") || !DEM_ONLY.contains(&key))
            && !(build.has("DEM") && key == "iOutcomes")
        {
            written.only(key, value, default, why);
        }
    }
    if build.has("DEM") {
        written.only(
            "iOutcomes",
            0.0,
            2.0,
            "a DEM build ignores it, and warns at start-up unless it is 0 (B37)",
        );
    } else {
        written.only(
            "dMergeLimit",
            0.0,
            1.0,
            "without the merge outcome pkdgrav ignores it, and warns at start-up unless it is 0 (B19)",
        );
    }
    written.section("for pkdgrav's MPI build");
    let extra = source
        .and_then(|s| s.file.given("dExtraStore"))
        .and_then(|e| e.value.as_ref()?.real())
        .unwrap_or(1.0);
    written.real(
        "dExtraStore",
        extra,
        None,
        "room for small runs on several ranks: with pkdgrav's default 0.1 a few hundred particles on two ranks abort at start-up (docs/pkdgrav-physics.md §19)",
    );
    if let Some(source) = source {
        written.copy(source);
    }
    let header = format!(
        "pkdgrav parameters of a run exported by walls-sim {}: {} steps of {} from t = {}. \
         Build: {} (README.md). Each key says where its value came from; \
         pkdgrav reads at most 127 bytes a line and refuses an exclamation mark anywhere.",
        env!("CARGO_PKG_VERSION"),
        last_step.saturating_sub(settings.start_step),
        walls_par::write::real(settings.dt),
        walls_par::write::real(settings.t_start()),
        build.names(),
    );
    let par = walls_par::write::render(&header, &written.sections, &build)?;
    let warnings = written.warnings;
    Ok(Export {
        par,
        build,
        last_step,
        digits,
        warnings,
    })
}

/// The keys walls-sim follows at one value only that only a DEM build needs at that value
/// (A75: `iForceOverrideOption = 2` stops a build without DEM or SPRINGS; checkpoints are
/// refused only by DEM builds).
const DEM_ONLY: [&str; 2] = ["iForceOverrideOption", "iCheckInterval"];

/// `Some(flag)` when the command line gave `value`.
fn flag<T>(value: Option<T>, flag: &str) -> Option<String> {
    value.map(|_| flag.to_string())
}

/// Where a timestep of walls-sim's own came from.
fn dt_default(settings: &Settings) -> String {
    let travel = 100.0 * crate::run::defaults::TRAVEL_PER_STEP;
    let rule = match settings.method() {
        crate::run::ContactModel::Ssdem => "pi*sqrt(m/(2 dKn))/100 for the lightest particle",
        crate::run::ContactModel::Hsdem => {
            "a step's straight path within 0.1 % of the smallest radius of the parabola (without gravity a hundredth of the run)"
        }
    };
    format!(
        "walls-sim's default timestep: {rule}, at most what moves anything {travel} % of the smallest radius, shortened so that whole steps end on the end time"
    )
}

/// The settings written so far, and what they are written from.
struct Written<'a> {
    warnings: Vec<String>,
    source: Option<&'a Source<'a>>,
    build: &'a walls_par::Build,
    sections: Vec<Section>,
}

impl Written<'_> {
    /// Starts a section headed `heading`.
    fn section(&mut self, heading: &str) {
        self.sections.push(Section {
            heading: heading.to_uppercase(),
            ..Section::default()
        });
    }

    /// Whether the source `.par` file gives `key`.
    fn given(&self, key: &str) -> bool {
        self.source.is_some_and(|s| s.file.given(key).is_some())
    }

    /// Whether the source `.par` file gives `key` a value other than `value` (the line
    /// pkdgrav follows, the last).
    fn says_otherwise(&self, key: &str, value: f64) -> bool {
        self.source
            .and_then(|s| s.file.given(key))
            .is_some_and(|entry| entry.value.as_ref().and_then(|v| v.real()) != Some(value))
    }

    /// Where a value came from: the command line's `flag`, else the source's line of
    /// `key`, else `default`.
    fn origin(&self, key: &str, flag: Option<String>, default: &str) -> String {
        if let Some(flag) = flag {
            return format!("{key}: from {flag}");
        }
        if let Some((source, entry)) = self.source.and_then(|s| Some((s, s.file.given(key)?))) {
            return format!("{key}: from {} line {}", source.path, entry.line);
        }
        format!("{key}: {default}")
    }

    /// Adds `more` to the comment of the setting written last.
    fn append_to_last(&mut self, more: &str) {
        if let Some(s) = self.sections.last_mut().and_then(|s| s.settings.last_mut()) {
            s.comment.push_str(more);
        }
    }

    /// Adds `key = value` (when the build registers `key`: a key it lacks changes
    /// nothing pkdgrav or the run does) with its origin.
    fn push(&mut self, key: &'static str, value: Value, comment: String) {
        if walls_par::keys::registered(key, self.build).is_none() {
            return;
        }
        let section = self
            .sections
            .last_mut()
            .expect("a section is started first");
        section.settings.push(Setting {
            key,
            value,
            comment,
        });
    }

    fn real(&mut self, key: &'static str, x: f64, flag: Option<String>, default: &str) {
        let comment = self.origin(key, flag, default);
        self.push(key, Value::Real(x), comment);
    }

    fn int(&mut self, key: &'static str, n: i128, flag: Option<String>, default: &str) {
        let comment = self.origin(key, flag, default);
        self.push(key, Value::Int(n), comment);
    }

    fn flag_key(&mut self, key: &'static str, on: bool, flag: Option<String>, default: &str) {
        let comment = self.origin(key, flag, default);
        self.push(key, Value::Bool(on), comment);
    }

    fn text(&mut self, key: &'static str, text: &str, what: &str) {
        self.push(key, Value::Text(text.to_string()), format!("{key}: {what}"));
    }

    /// A key walls-sim follows at `value` only, pkdgrav's default being `default`.
    fn only(&mut self, key: &'static str, value: f64, default: f64, why: &str) {
        let Some(registered) = walls_par::keys::registered(key, self.build) else {
            return;
        };
        let said = self
            .source
            .filter(|_| self.says_otherwise(key, value))
            .and_then(|s| Some((s.path, s.file.given(key)?)))
            .map(|(path, entry)| format!(" ({path} line {} said otherwise)", entry.line))
            .unwrap_or_default();
        let comment = format!(
            "{key}: pkdgrav's default is {}; {why}{said}",
            walls_par::write::real(default)
        );
        let value = match registered.kind {
            walls_par::keys::Kind::Double => Value::Real(value),
            walls_par::keys::Kind::Bool => Value::Bool(value != 0.0),
            _ => Value::Int(value as i128),
        };
        self.push(key, value, comment);
    }

    /// The source's lines that set keys not written above, as they were (the last of
    /// each key, which is the one pkdgrav follows).
    fn copy(&mut self, source: &Source) {
        let written: Vec<&str> = self
            .sections
            .iter()
            .flat_map(|section| &section.settings)
            .map(|s| s.key)
            .collect();
        let file = source.file;
        let mut copied = Vec::new();
        for entry in &file.entries {
            let key = entry.key.name;
            if written.contains(&key)
                || crate::io::par::PATH_KEYS.contains(&key)
                || !file.wins(entry)
            {
                continue;
            }
            let line = file.text[entry.line_span.clone()].trim_end().to_string();
            let at = format!("{} line {}", source.path, entry.line);
            let what = match evaluator::use_of(key) {
                Some(Use::NotYet(why)) => format!(" (walls-sim does not model it: {why})"),
                Some(_) => String::new(),
                None => {
                    self.warnings.push(format!(
                        "{at}: `{key}` is copied, and walls-sim does not follow it: pkdgrav's run may differ from walls-sim's"
                    ));
                    " (walls-sim does not follow it: pkdgrav's run may differ from walls-sim's)"
                        .to_string()
                }
            };
            let names_file = entry.key.kind == walls_par::keys::Kind::Str
                && matches!(&entry.value, Some(walls_par::value::Value::Str(t)) if !t.is_empty());
            let what = if names_file {
                self.warnings.push(format!(
                    "{at}: `{key}` names a file or folder, which the export does not copy: put it beside ss.par"
                ));
                format!("{what} (it names a file or folder, which the export does not copy)")
            } else {
                what
            };
            let why = format!("{key}: from {at}{what}");
            copied.push((line, why));
        }
        if !copied.is_empty() {
            self.sections.push(Section {
                heading: format!("THE OTHER KEYS OF {}", source.path),
                settings: Vec::new(),
                copied,
            });
        }
    }
}

/// The run directory's README: what is in it, the build pkdgrav needs, and the commands
/// that check it, run it here, run it with pkdgrav (serial and MPI) and bring the outputs
/// back. `outputs` names and spaces pkdgrav's outputs.
pub fn readme(export: &Export, names: &Names, particles: usize, outputs: &Outputs) -> String {
    let Names {
        par,
        walls,
        particles: ss,
        cohesion,
    } = *names;
    let cohesion = cohesion
        .map(|c| format!("* `{c}`: the cohesion coefficients by colour.\n"))
        .unwrap_or_default();
    let build = export.build.names();
    let last = export.last_step;
    let name =
        |step: u64| crate::io::particles::ss_file_name(&outputs.ss.base, export.digits, step);
    let written = if outputs.every == 0 {
        format!("the last step's, `{}`", name(last))
    } else {
        format!(
            "every {} steps and after the last, `{}` to `{}`",
            outputs.every,
            name(outputs.every.min(last)),
            name(last)
        )
    };
    let default = export.build == walls_par::Build::default();
    let flag = if default {
        String::new()
    } else {
        format!(" --pkdgrav-build \"{build}\"")
    };
    format!(
        "# A pkdgrav run directory\n\n\
Exported by `walls-sim export` (walls {version}).\n\n\
* `{par}`: pkdgrav's parameters; each key says where its value came from.\n\
* `{walls}`: the walls file.\n\
* `{ss}`: the initial conditions, {particles} particle(s), in pkdgrav's `.ss` format.\n\
{cohesion}\
* `walls.toml`: the build, for `walls-lint` and the editor.\n\n\
## The build\n\n\
Compile pkdgrav with the options\n\n    {build}\n\n\
A build without one of them refuses `{par}` at start-up or runs other physics.\n\n\
## Check, run here, run on the cluster\n\n\
```sh\n\
walls-lint .            # what pkdgrav would refuse or warn about (the build: walls.toml)\n\
walls-sim run --par {par}{flag} --out here --ss-output\n\
pkdgrav {par}           # serial\n\
mpirun -np 8 pkdgrav {par}\n\
```\n\n\
`pkdgrav` is the program your build makes; with MPI, as many ranks as the job has\n\
cores (`dExtraStore` in `{par}` leaves the room small runs need on several ranks).\n\
pkdgrav writes its outputs in the folder it runs in, {written}.\n\n\
## Bring the outputs back\n\n\
```sh\n\
walls-sim preview {walls} --particles . --out movie.html\n\
```\n\n\
draws the `.ss` series of this folder as a movie (docs/preview.md).\n",
        version = env!("CARGO_PKG_VERSION"),
    )
}

/// The run directory's settings file: its build, which `walls-lint` and the editor check
/// the `.par` file for (docs/configuration.md).
pub fn settings_file(export: &Export) -> String {
    format!(
        "# The pkdgrav build this run directory is for (walls-sim export).\n[run]\npkdgrav-build = \"{}\"\n",
        export.build.names()
    )
}
