//! pkdgrav's build: the compile options (its `Makefile.in`'s `USE_…` names) that decide
//! which physics a pkdgrav binary runs (docs/pkdgrav-physics.md §0). `walls-sim
//! --pkdgrav-build` takes them by pkdgrav's own names, space or comma separated, with or
//! without the `USE_` prefix; the default is pkdgrav's default build, `DEM DEM_FIXED_BALL
//! DEM_ROTATION_DASHPOT`.
//!
//! Options that change the physics set a switch of [`Build`]; those that do not
//! (`COLLISIONS`, `WALLS`, `NUMREC`, `DEM_FIXED_BALL`, `DEM_TRACK_ORIENT`) are accepted
//! and kept for the plan's listing. A name pkdgrav's wall physics does not know is an
//! error, with the nearest known name.

use walls_keywords::ContactModel;

/// One compile option the evaluator knows, with what it does.
struct Known {
    name: &'static str,
    effect: &'static str,
}

/// Every compile option the evaluator knows (docs/pkdgrav-physics.md §0).
const KNOWN: &[Known] = &[
    Known {
        name: "COLLISIONS",
        effect: "collisions (always on in the evaluator)",
    },
    Known {
        name: "WALLS",
        effect: "walls (always on in the evaluator)",
    },
    Known {
        name: "NUMREC",
        effect: "Numerical Recipes routines (no effect on the physics)",
    },
    Known {
        name: "DEM",
        effect: "soft-sphere contacts (without it: hard-sphere walls)",
    },
    Known {
        name: "DEM_FIXED_BALL",
        effect: "the neighbour search ball (no effect when every overlap is found)",
    },
    Known {
        name: "DEM_ROTATION_DASHPOT",
        effect: "rolling and twisting as spring-dashpot-sliders with beta_s (without it: directional constant torques)",
    },
    Known {
        name: "DEM_TRACK_ORIENT",
        effect: "orientation tracking and .ori files (no effect on the dynamics)",
    },
    Known {
        name: "DEM_COHESION",
        effect: "cohesion",
    },
    Known {
        name: "DEM_TWOLAYERS",
        effect: "two-layer contacts",
    },
    Known {
        name: "DEM_WALLS_REACT",
        effect: "reactive walls (walls with a mass)",
    },
    Known {
        name: "AGGS",
        effect: "aggregates (and no rolling or twisting friction between particles)",
    },
];

/// pkdgrav's default build (its `src/Makefile.in`).
pub const DEFAULT: &str = "DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT";

/// A pkdgrav build: the compile options given, and the switches they set.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Build {
    /// The options as given (without `USE_`), in order, each once.
    pub options: Vec<String>,
    /// `DEM`: soft-sphere contacts; without it, hard-sphere walls.
    pub dem: bool,
    /// `DEM_ROTATION_DASHPOT`: rolling and twisting as spring–dashpot–sliders (§1.4);
    /// without it, directional constant torques (§1.6).
    pub rotation_dashpot: bool,
    /// `DEM_COHESION` (§7).
    pub cohesion: bool,
    /// `DEM_TWOLAYERS` (§8).
    pub two_layers: bool,
    /// `DEM_WALLS_REACT` (§10).
    pub walls_react: bool,
    /// `AGGS` (§9).
    pub aggs: bool,
}

impl Default for Build {
    /// pkdgrav's default build, [`DEFAULT`].
    fn default() -> Self {
        Build::parse(DEFAULT).expect("the default build parses")
    }
}

/// A compile option the evaluator does not know.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownOption {
    /// The name as given.
    pub name: String,
    /// The nearest known name, if one is near.
    pub suggestion: Option<&'static str>,
}

impl std::fmt::Display for UnknownOption {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "unknown pkdgrav compile option `{}`", self.name)?;
        match self.suggestion {
            Some(s) => write!(f, ", did you mean `{s}`?"),
            None => write!(
                f,
                " (known: {})",
                KNOWN.iter().map(|k| k.name).collect::<Vec<_>>().join(", ")
            ),
        }
    }
}

impl std::error::Error for UnknownOption {}

impl Build {
    /// The build of `text`: option names separated by spaces or commas, with or
    /// without pkdgrav's `USE_` prefix (an empty text is a hard-sphere build).
    pub fn parse(text: &str) -> Result<Build, UnknownOption> {
        let mut options: Vec<String> = Vec::new();
        for word in text
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|w| !w.is_empty())
        {
            let name = word.strip_prefix("USE_").unwrap_or(word);
            let Some(known) = KNOWN.iter().find(|k| k.name == name) else {
                return Err(UnknownOption {
                    name: word.to_string(),
                    suggestion: nearest(name),
                });
            };
            if !options.iter().any(|o| o == known.name) {
                options.push(known.name.to_string());
            }
        }
        let has = |n: &str| options.iter().any(|o| o == n);
        Ok(Build {
            dem: has("DEM"),
            rotation_dashpot: has("DEM_ROTATION_DASHPOT"),
            cohesion: has("DEM_COHESION"),
            two_layers: has("DEM_TWOLAYERS"),
            walls_react: has("DEM_WALLS_REACT"),
            aggs: has("AGGS"),
            options,
        })
    }

    /// The contact model the build runs: soft spheres with `DEM`, else hard spheres.
    pub fn contact_model(&self) -> ContactModel {
        if self.dem {
            ContactModel::Ssdem
        } else {
            ContactModel::Hsdem
        }
    }

    /// pkdgrav's default build ([`DEFAULT`]) with `DEM` set or cleared to run `model`.
    pub fn default_for(model: ContactModel) -> Build {
        Build::default().with_model(model)
    }

    /// This build with `DEM` set or cleared to run `model`.
    pub fn with_model(mut self, model: ContactModel) -> Build {
        let dem = model == ContactModel::Ssdem;
        if dem != self.dem {
            self.dem = dem;
            if dem {
                self.options.insert(0, "DEM".to_string());
            } else {
                self.options.retain(|o| o != "DEM");
            }
        }
        self
    }

    /// The options, space separated, as pkdgrav's Makefile writes them.
    pub fn names(&self) -> String {
        self.options.join(" ")
    }

    /// What each option of the build does, by name.
    pub fn effects(&self) -> impl Iterator<Item = (&'static str, &'static str)> + '_ {
        self.options.iter().filter_map(|o| {
            KNOWN
                .iter()
                .find(|k| k.name == o)
                .map(|k| (k.name, k.effect))
        })
    }
}

/// What the inputs of a run show that `build` lacks: each missing option, with the
/// input that needs it (walls with a mass need `DEM_WALLS_REACT`; particles whose
/// `org_idx` is negative, aggregate members, need `AGGS`).
pub fn missing(
    build: &Build,
    walls: &[walls_geometry::Wall],
    particles: &[impl AsRef<walls_geometry::Particle>],
) -> Vec<(&'static str, String)> {
    let mut out = Vec::new();
    let heavy = walls.iter().filter(|w| w.reactive.is_heavy()).count();
    if build.dem && !build.walls_react && heavy > 0 {
        out.push((
            "DEM_WALLS_REACT",
            format!("{heavy} walls have a mass (reactive walls)"),
        ));
    }
    let members = particles.iter().filter(|p| p.as_ref().index < 0).count();
    if !build.aggs && members > 0 {
        out.push((
            "AGGS",
            format!("{members} particles have a negative org_idx (aggregate members)"),
        ));
    }
    out
}

/// The known option nearest to `name`: the same name in another case, or one within a
/// third of its length in edits.
fn nearest(name: &str) -> Option<&'static str> {
    let upper = name.to_ascii_uppercase();
    KNOWN
        .iter()
        .map(|k| (strsim::levenshtein(&upper, k.name), k.name))
        .filter(|(d, k)| *d <= k.len() / 3)
        .min()
        .map(|(_, k)| k)
}
