//! `io::trajectory`: the rows `Trajectory` writes to `particles.csv` and `walls.csv` read
//! back as the same rows, and what the readers refuse.

use nalgebra::Vector3;
use walls_sim::io::trajectory::{
    ParticleRow, ReadError, Trajectory, WallRow, read_particles, read_walls,
};
use walls_sim::run::State;
use walls_test_support::{ball as particle, scene};

#[test]
fn the_start_written_from_the_particles_is_their_first_states() {
    let floor = scene("wall type plane origin 0 0 0\nwall type disk origin 0 0 1 radius 2\n");
    let particles = [particle([0.0, 0.0, 0.3], [0.25, -1e-300, 7.0])];
    let write = |record: &dyn Fn(&mut Trajectory<Vec<u8>>)| {
        let mut out = Trajectory::new(Vec::new(), Vec::new()).unwrap();
        record(&mut out);
        let (particles, walls) = out.finish().unwrap();
        [particles, walls].map(|f| String::from_utf8(f).unwrap())
    };
    let states: Vec<State> = particles.iter().map(State::new).collect();
    assert_eq!(
        write(&|out| out.record_start(5, 0.5, &particles, &floor).unwrap()),
        write(&|out| out.record(5, 0.5, &states, &floor, &[]).unwrap()),
    );
}

#[test]
fn written_rows_read_back_the_same() {
    let floor = scene("wall type plane origin 0 0 0\nwall type disk origin 0 0 1 radius 2\n");
    let mut states: Vec<State> = [[0.0, 0.0, 0.3], [0.1, -0.2, 1.0 / 3.0]]
        .iter()
        .map(|&pos| State::new(&particle(pos, [0.25, -1e-300, 7.0])))
        .collect();
    states[1].particle.spin = Vector3::new(1.5, f64::MIN_POSITIVE, -0.1);
    states[1].alive = false;
    // Stuck to wall 1: pkdgrav's colour −1 − 1.
    states[1].particle.color = -2;
    let mut out = Trajectory::new(Vec::new(), Vec::new()).unwrap();
    out.record(0, 0.0, &states, &floor, &[]).unwrap();
    out.record(100, 0.1 + 0.2, &states, &floor, &[]).unwrap();
    let extra = ParticleRow {
        step: 200,
        t: 2.5e-7,
        particle: 0,
        alive: true,
        mass: 3.0,
        radius: 0.5,
        pos: Vector3::new(-1.0, 2.0, 1e10),
        vel: Vector3::zeros(),
        spin: Vector3::new(0.0, -0.0, 4.0),
        color: 12,
    };
    out.write_particle(&extra).unwrap();
    let (particles, walls) = out.finish().unwrap();

    let text = String::from_utf8(particles).unwrap();
    let rows = read_particles(&text).unwrap();
    let mut expected = Vec::new();
    for (step, t) in [(0, 0.0), (100, 0.1 + 0.2)] {
        for (i, s) in states.iter().enumerate() {
            expected.push(ParticleRow::new(step, t, i, s));
        }
    }
    expected.push(extra);
    assert_eq!(rows, expected);

    let text = String::from_utf8(walls).unwrap();
    let walls = read_walls(&text).unwrap();
    let origin = |wall: usize| Vector3::new(0.0, 0.0, wall as f64);
    let expected: Vec<WallRow> = [(0, 0.0), (100, 0.1 + 0.2)]
        .iter()
        .flat_map(|&(step, t)| {
            (0..2).map(move |wall| WallRow {
                step,
                t,
                wall,
                origin: origin(wall),
            })
        })
        .collect();
    assert_eq!(walls, expected);
}

#[test]
fn the_readers_say_what_is_wrong() {
    assert_eq!(
        read_particles("mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0,0,0,0\n"),
        Err(ReadError::NotATrajectory {
            what: "particles.csv"
        })
    );
    assert_eq!(
        read_particles("").unwrap_err().to_string(),
        "not a trajectory (the particles.csv of walls-sim run --out)"
    );
    let header = "step,t,particle,alive,mass,radius,x,y,z,vx,vy,vz,wx,wy,wz\n";
    let good = "0,0,0,1,1,0.1,0,0,0,0,0,0,0,0,0\n";
    let bad_x = "0,0,1,1,1,0.1,nan,0,0,0,0,0,0,0,0\n";
    let e = read_particles(&format!("{header}{good}{bad_x}")).unwrap_err();
    assert_eq!(e, ReadError::NotANumber { line: 3, column: 7 });
    assert_eq!(e.to_string(), "line 3: column 7 is not a number");
    // By the tools' one rule for numbers: a cell that underflows is no number either.
    let tiny_x = bad_x.replace("nan", "1e-400");
    let e = read_particles(&format!("{header}{good}{tiny_x}")).unwrap_err();
    assert_eq!(e, ReadError::NotANumber { line: 3, column: 7 });
    assert_eq!(
        read_particles(&format!("{header}0,0,0\n")).unwrap_err(),
        ReadError::NotANumber { line: 2, column: 4 }
    );
    assert_eq!(read_particles(header), Ok(Vec::new()));
    // A file written before the `color` column: its particles take the default colour.
    let old = read_particles(&format!("{header}{good}")).unwrap();
    assert_eq!(old[0].color, walls_sim::io::particles::DEFAULT_COLOR);
    // With the column, a colour that is not pkdgrav's is refused at its line.
    let header = header.replace("wz\n", "wz,color\n");
    let colored = |c: &str| {
        read_particles(&format!(
            "{header}{}",
            good.replace("0\n", &format!("0,{c}\n"))
        ))
    };
    assert_eq!(colored("-4").unwrap()[0].color, -4);
    for bad in ["256", "2.5", "1e12", "-3e9"] {
        let e = colored(bad).unwrap_err();
        assert_eq!(
            e,
            ReadError::NotAColor {
                line: 2,
                cell: bad.into()
            }
        );
        assert!(
            e.to_string()
                .starts_with(&format!("line 2: `color` is `{bad}`")),
            "{e}"
        );
    }
    assert_eq!(
        colored("red").unwrap_err(),
        ReadError::NotAColor {
            line: 2,
            cell: "red".into()
        }
    );
    assert_eq!(
        read_walls("step,t,wall,x,y\n"),
        Err(ReadError::NotATrajectory { what: "walls.csv" })
    );
}
