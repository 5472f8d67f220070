//! The files of `walls-sim run --out DIR` (docs/evaluator.md, "Outputs"), through the one
//! writer (`walls-output`): the trajectory (`particles.csv`, `walls.csv`), pkdgrav's
//! WALLSREACT files when the run has reactive walls, and, with `--ss-output`, a `.ss`
//! file at each output step.
//!
//! Everything is planned before the run starts ([`RunOutputs::open`]), in DIR opened once
//! (a folder renamed or swapped for a link meanwhile does not move the outputs): every
//! file stays in DIR (`achOutName`'s folder part is not followed: [`walls_sim::config::ss_base`]), none is a
//! link, a file the run reads, a device, a FIFO, a hard link or a read-only file, and an
//! existing one is replaced only with `--force` (the WALLSREACT files are appended to, as
//! pkdgrav does, unless `--fresh` empties them). The trajectory's files take their names
//! when their first output step is whole: a run that fails before leaves DIR as it was. At
//! each output step ([`RunOutputs::record`]) every file's rows are written and sent to the
//! files, the `.ss` file is written whole, and only then is the step marked whole in each;
//! after a failed write ([`RunOutputs::rollback`]) every file is cut back to the last step
//! marked, so that all end at the same whole output step, and nothing is removed. The
//! WALLSREACT lines come at the output steps, or, when the `.par` file sets
//! `iRedOutInterval`, at pkdgrav's reduced outputs instead ([`Due`]).

use std::path::{Path, PathBuf};
use walls_geometry::{Particle, Wall};
use walls_output::{Folder, Outputs, Stream, Tool, WriteError, path_in};
use walls_sim::config::SsNames;
use walls_sim::dynamics::reactive::Assembly;
use walls_sim::io::particles::{ss_file_name, write_ss_output};
use walls_sim::io::trajectory::{PARTICLES_FILE, Trajectory, WALLS_FILE};
use walls_sim::io::wallsreact::{DATA_FILE, ReactiveOutput, VIZ_FILE};
use walls_sim::run::State;

/// What an output step writes: the trajectory (and the `.ss` file), the WALLSREACT lines,
/// or both.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Due {
    /// The trajectory's rows and the `.ss` file (an output step).
    pub trajectory: bool,
    /// The WALLSREACT lines (an output step, or pkdgrav's reduced output).
    pub reactive: bool,
}

/// Why the outputs could not be written at an output step.
#[derive(Debug)]
pub struct Failure {
    /// The output step.
    pub step: u64,
    /// Its time.
    pub t: f64,
    /// What could not be written, and why, as the user reads it.
    pub message: String,
}

/// The open outputs of a run.
pub struct RunOutputs {
    dir: PathBuf,
    folder: Folder,
    trajectory: Trajectory<Stream>,
    reactive: Option<ReactiveOutput<Stream>>,
    ss: Option<SsNames>,
    /// The first and last `.ss` files written.
    ss_written: Option<(String, String, usize)>,
    /// The last output step every file holds whole, and its time.
    last: Option<(u64, f64)>,
    /// The files of an earlier run replaced (with `--force`).
    replaced: Vec<PathBuf>,
}

impl RunOutputs {
    /// Plans and opens the outputs in `dir` (made if missing) for a run that reads
    /// `inputs`: the trajectory; the WALLSREACT files when `reactive` (appended to, or
    /// emptied when `fresh`); and the `.ss` outputs named by `ss`. Existing outputs are
    /// replaced only when `force`. Nothing is written if any output is refused.
    pub fn open(
        dir: &Path,
        force: bool,
        fresh: bool,
        reactive: bool,
        ss: Option<SsNames>,
        inputs: &[String],
    ) -> Result<RunOutputs, String> {
        let mut outputs = Outputs::new(Tool::RUN, force);
        for input in inputs {
            outputs.reads(input);
        }
        // The folder is opened once: every output is made in it as it is now.
        let folder = outputs.folder(dir, true).map_err(|e| match e {
            WriteError::Io(e) => format!("cannot write the outputs: {e}"),
            e => e.message(&dir.display().to_string(), Tool::RUN),
        })?;
        let refused = |name: &Path, e: WriteError| {
            e.message(&path_in(dir, name).display().to_string(), Tool::RUN)
        };
        let plan = |name: &str| {
            let name = Path::new(name);
            folder.plan(name).map_err(|e| refused(name, e))
        };
        let particles = plan(PARTICLES_FILE)?;
        let walls = plan(WALLS_FILE)?;
        let mut replaced: Vec<PathBuf> = [&particles, &walls]
            .into_iter()
            .filter(|t| t.exists())
            .map(|t| t.path().to_path_buf())
            .collect();
        let reacting = if reactive {
            let plan = |name: &str| {
                let name = Path::new(name);
                folder.plan_append(name).map_err(|e| refused(name, e))
            };
            Some((plan(DATA_FILE)?, plan(VIZ_FILE)?))
        } else {
            None
        };
        if let Some(names) = &ss {
            // Every .ss output of an earlier run in the folder, checked now rather than
            // when the run reaches its step.
            for name in ss_files_in(&folder, &names.base)? {
                folder.plan(Path::new(&name)).map_err(|e| match e {
                    WriteError::Refused(walls_output::Refusal::Exists) => format!(
                        "not writing the .ss outputs in {}: {} holds {name}, an output of \
                             an earlier run: pass --force to replace such files",
                        dir.display(),
                        dir.display()
                    ),
                    e => refused(Path::new(&name), e),
                })?;
            }
        }
        let stream = |target: &walls_output::Target, fresh: bool| {
            let opened = if fresh {
                target.stream()
            } else {
                target.append()
            };
            opened.map_err(|e| target.message(&e))
        };
        let trajectory = Trajectory::new(stream(&particles, true)?, stream(&walls, true)?)
            .map_err(|e| format!("cannot write to {}: {e}", dir.display()))?;
        let reactive = match reacting {
            Some((data, viz)) => {
                if fresh {
                    replaced.extend(
                        [&data, &viz]
                            .into_iter()
                            .filter(|t| t.exists())
                            .map(|t| t.path().to_path_buf()),
                    );
                } else {
                    for target in [&data, &viz].into_iter().filter(|t| t.exists()) {
                        crate::errln!(
                            "walls-sim: appending to {}, as pkdgrav does (--fresh empties it first)",
                            target.path().display()
                        );
                    }
                }
                Some(ReactiveOutput::new(
                    stream(&data, fresh)?,
                    stream(&viz, fresh)?,
                ))
            }
            None => None,
        };
        Ok(RunOutputs {
            dir: dir.to_path_buf(),
            folder,
            trajectory,
            reactive,
            ss,
            ss_written: None,
            last: None,
            replaced,
        })
    }

    /// Writes the particles as the run starts with them (all alive), and the walls, at
    /// `step`, time `t`, to the trajectory (pkdgrav writes no `.ss` output before its
    /// first step); and, given the `assemblies` as the walls file sets them, their
    /// WALLSREACT lines (pkdgrav's reduced output at the start step).
    pub fn record_start(
        &mut self,
        step: u64,
        t: f64,
        particles: &[impl AsRef<Particle>],
        scene: &[Wall],
        assemblies: Option<&[Assembly]>,
    ) -> Result<(), Failure> {
        let written = match (self.reactive.as_mut(), assemblies) {
            (Some(out), Some(assemblies)) => out.record_assemblies(step, scene, assemblies),
            _ => Ok(()),
        }
        .and_then(|()| self.trajectory.record_start(step, t, particles, scene));
        self.close_step(step, t, written, None)
    }

    /// Writes output step `step`, time `t`, as `due`: the reactive assemblies' lines, the
    /// trajectory's rows and the `.ss` file, then marks the step whole in every file.
    pub fn record(
        &mut self,
        (step, t): (u64, f64),
        states: &[State],
        scene: &[Wall],
        assemblies: &[Assembly],
        due: Due,
    ) -> Result<(), Failure> {
        let written = match self.reactive.as_mut() {
            Some(out) if due.reactive => out.record_assemblies(step, scene, assemblies),
            _ => Ok(()),
        };
        let written = written.and_then(|()| match due.trajectory {
            true => self.trajectory.record(step, t, states, scene, assemblies),
            false => Ok(()),
        });
        self.close_step(step, t, written, due.trajectory.then_some(states))
    }

    /// After the rows of `step` were `written` (or not): sends them to the files, writes
    /// the `.ss` file of `states` (if any), and marks the step whole; a failure names the
    /// file.
    fn close_step(
        &mut self,
        step: u64,
        t: f64,
        written: std::io::Result<()>,
        states: Option<&[State]>,
    ) -> Result<(), Failure> {
        let fail = |message: String| Failure { step, t, message };
        if let Err(e) = written {
            return Err(fail(self.which_failed(&e)));
        }
        self.send().map_err(fail)?;
        if let (Some(names), Some(states)) = (&self.ss, states) {
            let name = ss_file_name(&names.base, names.digits, step);
            let target = self.folder.plan(Path::new(&name)).map_err(|e| {
                fail(e.message(
                    &path_in(&self.dir, Path::new(&name)).display().to_string(),
                    Tool::RUN,
                ))
            })?;
            target
                .write_with(|out| write_ss_output(out, t, states))
                .map_err(|e| fail(target.message(&e)))?;
            if target.exists() {
                self.replaced.push(target.path().to_path_buf());
            }
            self.ss_written = Some(match self.ss_written.take() {
                None => (name.clone(), name, 1),
                Some((first, _, n)) => (first, name, n + 1),
            });
        }
        self.commit().map_err(fail)?;
        self.last = Some((step, t));
        Ok(())
    }

    /// The streams: the trajectory's, then the WALLSREACT files'.
    fn streams(&mut self) -> impl Iterator<Item = &mut Stream> {
        let reactive = self.reactive.as_mut().map(ReactiveOutput::writers_mut);
        self.trajectory
            .writers_mut()
            .into_iter()
            .chain(reactive.into_iter().flatten())
    }

    /// Sends what every stream holds to its file.
    fn send(&mut self) -> Result<(), String> {
        self.trajectory.flush().map_err(|e| self.which_failed(&e))?;
        for stream in self.streams() {
            std::io::Write::flush(stream)
                .map_err(|e| format!("cannot write {}: {e}", stream.path().display()))?;
        }
        Ok(())
    }

    /// Sends every stream's rows and marks them whole.
    fn commit(&mut self) -> Result<(), String> {
        self.send()?;
        for stream in self.streams() {
            // Nothing is left to send: marking cannot fail.
            stream
                .commit()
                .map_err(|e| format!("cannot write {}: {e}", stream.path().display()))?;
        }
        Ok(())
    }

    /// The message for `e`, a failure while writing rows, naming the file that failed.
    fn which_failed(&mut self, e: &std::io::Error) -> String {
        let shown = self
            .streams()
            .find(|s| s.failed())
            .map(|s| s.path().display().to_string());
        match shown {
            Some(path) => format!("cannot write {path}: {e}"),
            None => format!("cannot write to {}: {e}", self.dir.display()),
        }
    }

    /// Cuts every stream back to its last whole output step; the problems met doing so.
    pub fn rollback(&mut self) -> Vec<String> {
        self.streams()
            .filter_map(|s| {
                let e = s.rollback().err()?;
                Some(format!("{} may end mid-row ({e})", s.path().display()))
            })
            .collect()
    }

    /// Marks the last rows whole and closes the files.
    pub fn finish(self) -> Result<(), String> {
        let (particles, walls) = self
            .trajectory
            .finish()
            .map_err(|e| format!("cannot write to {}: {e}", self.dir.display()))?;
        let mut streams = vec![particles, walls];
        if let Some(reactive) = self.reactive {
            let (data, viz) = reactive
                .finish()
                .map_err(|e| format!("cannot write to {}: {e}", self.dir.display()))?;
            streams.extend([data, viz]);
        }
        for stream in streams {
            let path = stream.path().display().to_string();
            stream
                .finish()
                .map_err(|e| format!("cannot write {path}: {e}"))?;
        }
        Ok(())
    }

    /// The last output step every file holds whole, and its time.
    pub fn last(&self) -> Option<(u64, f64)> {
        self.last
    }

    /// The files of an earlier run that this one replaced (with `--force`, or the
    /// WALLSREACT files with `--fresh`), as a message says them; `None`: none.
    pub fn replaced(&self) -> Option<String> {
        let names: Vec<&Path> = self.replaced.iter().map(PathBuf::as_path).collect();
        (!names.is_empty()).then(|| walls_output::name_files(&names))
    }

    /// The files written, as paths to show: the trajectory's, the `.ss` outputs (the first
    /// and the last, and how many) and the WALLSREACT files.
    pub fn files(&self) -> Vec<String> {
        // Nothing takes its name before the first output step is whole.
        if self.last.is_none() {
            return Vec::new();
        }
        let path = |name: &str| path_in(&self.dir, Path::new(name)).display().to_string();
        let mut names = vec![path(PARTICLES_FILE), path(WALLS_FILE)];
        if let Some((first, last, n)) = &self.ss_written {
            names.push(match n {
                1 => path(first),
                _ => format!("{} … {} ({n} .ss files)", path(first), path(last)),
            });
        }
        if self.reactive.is_some() {
            names.extend([path(DATA_FILE), path(VIZ_FILE)]);
        }
        names
    }
}

/// The names of the files in `folder` that the `.ss` outputs named `base` could take:
/// `base.` and digits.
fn ss_files_in(folder: &Folder, base: &str) -> Result<Vec<String>, String> {
    let prefix = format!("{base}.");
    let entries = folder
        .names()
        .map_err(|e| format!("cannot read {}: {e}", folder.path().display()))?;
    let mut names = Vec::new();
    for entry in entries {
        let name = entry.to_string_lossy().into_owned();
        if let Some(step) = name.strip_prefix(&prefix)
            && !step.is_empty()
            && step.bytes().all(|b| b.is_ascii_digit())
        {
            names.push(name);
        }
    }
    names.sort();
    Ok(names)
}
