//! Trajectory output (`walls-sim run --out DIR --every N`): the particles and the walls'
//! origins at step 0 and every N steps after, as two CSV files in DIR.
//!
//! * `particles.csv`: `step,t,particle,alive,mass,radius,x,y,z,vx,vy,vz,wx,wy,wz`, one
//!   row per particle per output step;
//! * `walls.csv`: `step,t,wall,x,y,z`, where each wall's origin is (SPEC §1 "Motion"; a
//!   reactive wall's where its assembly has moved it).
//!
//! One long table per kind loads in one call into pandas, ParaView's CSV reader or a
//! spreadsheet, and a particle's path is a filter on its index. Numbers are written with
//! Rust's shortest round-trip formatting, so nothing is lost.

use crate::run::State;
use std::fs::File;
use std::io::{self, BufWriter};
use std::path::Path;
use walls_geometry::Wall;

/// The open trajectory files.
pub struct Trajectory {
    particles: csv::Writer<BufWriter<File>>,
    walls: csv::Writer<BufWriter<File>>,
}

impl Trajectory {
    /// Creates `dir` if needed, and the two files in it (replacing earlier ones).
    pub fn create(dir: &Path) -> io::Result<Trajectory> {
        std::fs::create_dir_all(dir)?;
        let open = |name: &str, header: &[&str]| -> io::Result<csv::Writer<BufWriter<File>>> {
            let mut w = csv::Writer::from_writer(BufWriter::new(File::create(dir.join(name))?));
            w.write_record(header)?;
            Ok(w)
        };
        Ok(Trajectory {
            particles: open(
                "particles.csv",
                &[
                    "step", "t", "particle", "alive", "mass", "radius", "x", "y", "z", "vx", "vy",
                    "vz", "wx", "wy", "wz",
                ],
            )?,
            walls: open("walls.csv", &["step", "t", "wall", "x", "y", "z"])?,
        })
    }

    /// Writes the particles and the walls at `step`, time `t`: each wall where its
    /// motion puts it, or where its reactive `assemblies` have moved it.
    pub fn record(
        &mut self,
        step: u64,
        t: f64,
        states: &[State],
        scene: &[Wall],
        assemblies: &[crate::reactive::Assembly],
    ) -> io::Result<()> {
        let (step, time) = (step.to_string(), t.to_string());
        for (i, s) in states.iter().enumerate() {
            let p = &s.particle;
            let mut row = vec![
                step.clone(),
                time.clone(),
                i.to_string(),
                u8::from(s.alive).to_string(),
                p.mass.to_string(),
                p.radius.to_string(),
            ];
            for v in [&p.pos, &p.vel, &p.spin] {
                row.extend(v.iter().map(f64::to_string));
            }
            self.particles.write_record(&row)?;
        }
        for (w, wall) in scene.iter().enumerate() {
            let moved = assemblies.iter().find_map(|a| {
                let k = a.walls.iter().position(|x| *x == w)?;
                Some(a.origin(k))
            });
            let o = moved.unwrap_or_else(|| wall.motion.position_or_origin(t));
            let mut row = vec![step.clone(), time.clone(), w.to_string()];
            row.extend(o.iter().map(f64::to_string));
            self.walls.write_record(&row)?;
        }
        Ok(())
    }

    /// Writes out what is buffered.
    pub fn finish(mut self) -> io::Result<()> {
        self.particles.flush()?;
        self.walls.flush()
    }
}
