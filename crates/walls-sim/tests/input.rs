//! Reading particles (CSV, standard and reduced `.ss`) and pkdgrav parameter files, and
//! the located errors for broken ones.

use walls_sim::io::par::read_par;
use walls_sim::io::particles::{read_csv, read_ss};

#[test]
fn csv_with_and_without_optional_columns() {
    let ps = read_csv("mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,1,0,0,-2\n2, 0.2, 1,2,3, 4,5,6\n")
        .unwrap()
        .particles;
    assert_eq!(ps.len(), 2);
    assert_eq!(
        (
            ps[1].mass,
            ps[1].radius,
            ps[1].pos.z,
            ps[1].vel.x,
            ps[1].index
        ),
        (2.0, 0.2, 3.0, 4.0, 1)
    );
    let ps = read_csv("radius,mass,x,y,z,vx,vy,vz,wx,wy,wz,color\n0.1,1,0,0,0,0,0,0,1,2,3,7\n")
        .unwrap()
        .particles;
    assert_eq!((ps[0].mass, ps[0].spin.y, ps[0].color), (1.0, 2.0, 7));
    // Spaces around the names and the values are trimmed, row after row.
    let ps = read_csv("mass , radius,x,y,z,vx,vy,vz\n 1 ,0.1,0,0,0,0,0,0\n2, 0.2 ,0,0,5,0,0,0\n")
        .unwrap()
        .particles;
    assert_eq!(
        (ps[0].mass, ps[1].radius, ps[1].pos.z, ps[1].index),
        (1.0, 0.2, 5.0, 1)
    );
    // White space as Unicode has it, not only ASCII's: a no-break space, a vertical
    // tab, an em space around a value, a colour or a name.
    let ps = read_csv(
        "mass\u{a0},radius,x,y,z,vx,vy,vz,wx,wy,wz,color\n\u{a0}1,0.1\u{a0},0,0,1,\u{b}2,0,0,0,0,0,\u{2003}3\n",
    )
    .unwrap()
    .particles;
    assert_eq!(
        (ps[0].mass, ps[0].radius, ps[0].vel.x, ps[0].color),
        (1.0, 0.1, 2.0, 3)
    );
}

#[test]
fn csv_errors_say_where() {
    let e = read_csv("mass,radius,x,y,z,vx,vy\n").unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 1: the header has no `vz` column (it needs mass,radius,x,y,z,vx,vy,vz)"
    );
    let e = read_csv("mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0,0,0,0\n1,0.1,0,zero,0,0,0,0\n")
        .unwrap_err();
    assert_eq!(e.to_string(), "line 3: `y` is `zero`, not a number");
    let e = read_csv("mass,radius,x,y,z,vx,vy,vz\n0,0.1,0,0,0,0,0,0\n").unwrap_err();
    assert_eq!(e.to_string(), "line 2: mass and radius must be positive");
    // A row the CSV reader refuses, and a colour that is not an integer, after good rows.
    let e =
        read_csv("mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0,0,0,0\n1,0.1,0,0,0,0,0\n").unwrap_err();
    assert!(e.to_string().starts_with("line 3: "), "{e}");
    assert!(e.message.contains("found record with 7 fields"), "{e}");
    let e =
        read_csv("mass,radius,x,y,z,vx,vy,vz,color\n1,0.1,0,0,0,0,0,0,2\n1,0.1,0,0,0,0,0,0,red\n")
            .unwrap_err();
    assert_eq!(e.to_string(), "line 3: `color` is `red`, not an integer");
    // A field's bytes that are not UTF-8 are shown as U+FFFD, streamed from a file or
    // read whole.
    let bad = b"mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,\xff1\xe2\x82,0,0,0\n";
    let e = walls_sim::io::particles::read_bytes("p.csv", bad).unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 2: `z` is `\u{fffd}1\u{fffd}`, not a number"
    );
    // Two halves of one character split by a comma (the row's bytes, commas left out,
    // are UTF-8): each field is read on its own, each half shown as U+FFFD.
    let split = b"mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0,0,0\xc3,\xa90\n";
    let e = walls_sim::io::particles::read_bytes("p.csv", split).unwrap_err();
    assert_eq!(e.to_string(), "line 2: `vy` is `0\u{fffd}`, not a number");
    let e = read_csv("mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0,0,0,é0\n").unwrap_err();
    assert_eq!(e.to_string(), "line 2: `vz` is `é0`, not a number");
    assert!(
        read_csv("mass,radius,x,y,z,vx,vy,vz,spin\n")
            .unwrap_err()
            .message
            .contains("unknown column `spin`")
    ); // A column named twice is refused, not read from its first place alone.
    let e = read_csv("mass,radius,x,y,z,vx,vy,vz,x\n1,0.1,0,0,0,0,0,0,5\n").unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 1: the column `x` is named twice (columns 3 and 9)"
    );
    let e = read_csv("mass,radius,x,y,z,vx,vy,vz,color, color\n").unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 1: the column `color` is named twice (columns 9 and 10)"
    );
}

fn header(time: f64, count: i32, magic: i32) -> Vec<u8> {
    let mut b = time.to_be_bytes().to_vec();
    b.extend(count.to_be_bytes());
    b.extend(magic.to_be_bytes());
    b
}

#[test]
fn standard_and_reduced_ss_files() {
    let mut b = header(1.5, 1, -1);
    for x in [2.0f64, 0.25, 1.0, 2.0, 3.0, -1.0, 0.0, 0.5, 0.0, 0.0, 9.0] {
        b.extend(x.to_be_bytes());
    }
    b.extend(5i32.to_be_bytes());
    b.extend(42i32.to_be_bytes());
    assert_eq!(b.len(), 16 + 96);
    let (time, ps) = read_ss(&b).unwrap();
    assert_eq!(time, 1.5);
    let p = &ps.particles[0];
    assert_eq!(
        (
            p.mass, p.radius, p.pos.y, p.vel.x, p.vel.z, p.spin.z, p.color, p.index
        ),
        (2.0, 0.25, 2.0, -1.0, 0.5, 9.0, 5, 42)
    );

    let mut r = header(0.0, 2, -10101);
    for i in 0i32..2 {
        for x in [1.0f32, 0.5, i as f32, 0.0, 0.0] {
            r.extend(x.to_be_bytes());
        }
        r.extend(3i32.to_be_bytes());
        r.extend(i.to_be_bytes());
    }
    let ps = read_ss(&r).unwrap().1.particles;
    assert_eq!(
        (ps.len(), ps[1].pos.x, ps[1].radius, ps[1].index),
        (2, 1.0, 0.5, 1)
    );
}

#[test]
fn broken_ss_files_say_where() {
    let e = read_ss(&header(0.0, 1, 7)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "byte 12: magic number 7: a .ss file has −1 (standard) or −10101 (reduced)"
    );
    let e = read_ss(&header(0.0, 2, -1)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "byte 8: 2 particles of 96 bytes need 208 bytes, the file has 16"
    );
    let e = read_ss(&[0u8; 10]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "byte 8: the file ends inside a record (10 bytes in all)"
    );
    // Records a run cannot use: a particle with no mass, a NaN position.
    let reduced = |particles: &[[f32; 5]]| {
        let mut r = header(0.0, particles.len() as i32, -10101);
        for (i, p) in particles.iter().enumerate() {
            p.iter().for_each(|v| r.extend(v.to_be_bytes()));
            r.extend(3i32.to_be_bytes());
            r.extend((i as i32).to_be_bytes());
        }
        r
    };
    let good = [1.0, 0.5, 0.0, 0.0, 0.0];
    for (file, message) in [
        (
            reduced(&[good, [0.0, 0.5, 0.0, 0.0, 0.0]]),
            "byte 44: particle 1: mass and radius must be positive",
        ),
        (
            reduced(&[good, good, [1.0, 0.5, f32::NAN, 0.0, 0.0]]),
            "byte 72: particle 2: its values must be finite numbers",
        ),
    ] {
        assert_eq!(read_ss(&file).unwrap_err().to_string(), message);
    }
}

#[test]
fn parameter_files() {
    let p = read_par(
        "# a pkdgrav run\nachInFile = \"ic.ss\"\nachWallsFile = walls.dat  # the walls\ndDelta = 1e-6\nnSteps = 2000\n\
         dEpsN = 0.8\ndEpsT=1\ndKn = 1e5\ndMuS = 0.5\ndzUnifGrav = -9.8\nbWallsEdgeDetect = 0\n",
    )
    .unwrap();
    // pkdgrav keeps `achInFile`'s quotes (physics §14: only the walls, cohesion,
    // uniform-gravity and special-particles file names lose theirs), and so does the run.
    assert_eq!(p.in_file.as_deref(), Some("\"ic.ss\""));
    assert_eq!(p.walls_file.as_deref(), Some("walls.dat"));
    assert_eq!(
        (p.dt, p.steps, p.eps_n, p.eps_t, p.k_n, p.mu_s),
        (
            Some(1e-6),
            Some(2000),
            Some(0.8),
            Some(1.0),
            Some(1e5),
            Some(0.5)
        )
    );
    assert_eq!(p.gravity.unwrap().z, -9.8);
    assert_eq!(p.edge_detect, Some(false));
    assert_eq!(p.k_t, None);
    assert_eq!(
        read_par("dDelta = fast\n").unwrap_err().to_string(),
        "line 1: `dDelta` is `fast`, not a number"
    );
    assert_eq!(
        read_par("nSteps = 2.5\n").unwrap_err().to_string(),
        "line 1: `nSteps` is `2.5`; it must be a whole number, 0 or more"
    );
    assert_eq!(
        read_par("dDelta 1\n").unwrap_err().to_string(),
        "line 1: `dDelta 1` is not `name = value`"
    );
    // Values a run cannot use: a timestep that never advances, a spring that makes the
    // default timestep NaN, a restitution that creates energy, an infinity.
    for (text, message) in [
        (
            "dDelta = -1e-5\n",
            "line 1: `dDelta` is `-1e-5`; it must be greater than 0",
        ),
        (
            "# k\ndKn = -5\n",
            "line 2: `dKn` is `-5`; it must be 0 or more",
        ),
        (
            "dEpsN = 2\n",
            "line 1: `dEpsN` is `2`; it must be above 0 and at most 1",
        ),
        (
            "dEpsT = -1.5\n",
            "line 1: `dEpsT` is `-1.5`; it must be from -1 to 1",
        ),
        (
            "dMuS = -0.1\n",
            "line 1: `dMuS` is `-0.1`; it must be 0 or more",
        ),
        (
            "dzUnifGrav = inf\n",
            "line 1: `dzUnifGrav` is `inf`, not a finite number",
        ),
    ] {
        assert_eq!(read_par(text).unwrap_err().to_string(), message);
    }
}

proptest::proptest! {
    #[test]
    fn any_bytes_read_or_fail_cleanly(bytes in proptest::collection::vec(proptest::num::u8::ANY, 0..300)) {
        let _ = read_ss(&bytes);
        let text = String::from_utf8_lossy(&bytes);
        let _ = read_csv(&text);
        let _ = read_par(&text);
    }
}

#[test]
fn ss_files_written_read_back_exactly_with_pkdgrav_s_names() {
    use walls_sim::io::particles::{ss_file_name, write_ss};
    let mut a = walls_geometry::Particle::at_rest(0.1, nalgebra::Vector3::new(1.0, -2.0, 3.5), 0);
    a.vel = nalgebra::Vector3::new(1e-300, 1.2345678901234567e150, -0.0);
    a.spin = nalgebra::Vector3::new(0.1, 0.2, 0.30000000000000004);
    a.color = -3;
    a.index = -7;
    let b = walls_geometry::Particle::at_rest(2.0, nalgebra::Vector3::zeros(), 1);
    let ps = vec![a, b];
    let bytes = write_ss(1.4743270000000004e-10, &ps);
    assert_eq!(bytes.len(), 16 + 2 * 96);
    let (time, read) = read_ss(&bytes).unwrap();
    assert_eq!((time, read.particles), (1.4743270000000004e-10, ps.clone()));
    // A run's output: the living particles, stuck ones with the colour that says so,
    // written record by record as the file made whole.
    use walls_sim::run::State;
    let mut states: Vec<State> = ps.iter().map(State::new).collect();
    let mut gone = states[1].clone();
    gone.alive = false;
    states.push(gone);
    states[1].stuck_to = Some(Box::new((4, nalgebra::Vector3::zeros())));
    let mut streamed = Vec::new();
    walls_sim::io::particles::write_ss_output(&mut streamed, 0.5, &states).unwrap();
    let written: Vec<_> = states[..2].iter().map(State::as_written).collect();
    assert_eq!(written[1].color, -5);
    assert_eq!(streamed, write_ss(0.5, &written));
    assert_eq!(ss_file_name("ss", 5, 120), "ss.00120");
    assert_eq!(ss_file_name("run", 6, 1234567), "run.1234567");
}

#[test]
fn a_negative_colour_is_stuck_from_the_start_and_stuck_particles_are_written_so() {
    use walls_sim::run::{Settings, run};
    // Colour −2: stuck to wall 1, the oscillating plate; it rides with it, and keeps
    // its colour in the output. A free particle sticking to the sticky floor (wall 0)
    // is written with colour −1.
    let walls = walls_test_support::scene(
        "wall type plane origin 0 0 0 epsn 0\nwall type plane origin 0 0 5 osc-ampl 0.5 osc-vec 1 0 0 osc-freq 10\n",
    );
    let mut held = walls_geometry::Particle::at_rest(0.1, nalgebra::Vector3::new(0.0, 0.0, 4.9), 0);
    held.color = -2;
    let mut falling =
        walls_geometry::Particle::at_rest(0.1, nalgebra::Vector3::new(3.0, 0.0, 0.2), 1);
    falling.vel.z = -1.0;
    falling.color = 4;
    let mut s = Settings::new(1e-3, 0.3, walls_sim::run::defaults::default_material(1e5));
    s.particle_contacts = false;
    let out = run(&walls, vec![held, falling], &s);
    let (held, falling) = (&out.particles[0], &out.particles[1]);
    assert_eq!(held.stuck_to.as_deref().map(|&(w, _)| w), Some(1));
    let plate = walls[1].motion.position_or_origin(out.t);
    assert!(
        (held.particle.pos.x - plate.x).abs() < 1e-9,
        "{:?} vs {plate:?}",
        held.particle.pos
    );
    assert_eq!(held.as_written().color, -2);
    assert_eq!(falling.stuck_to.as_deref().map(|&(w, _)| w), Some(0));
    assert_eq!(falling.as_written().color, -1);
    assert_eq!(
        falling.particle.color, 4,
        "the run's own record keeps the colour given"
    );
}

/// A `.ss` header: `time`, `count` particles, the magic number `magic`.
fn ss_header(count: i32, magic: i32) -> Vec<u8> {
    let mut b = 0.0f64.to_be_bytes().to_vec();
    b.extend_from_slice(&count.to_be_bytes());
    b.extend_from_slice(&magic.to_be_bytes());
    b
}

#[test]
fn a_two_gigabyte_ss_file_is_refused_from_its_header_without_being_read() {
    use walls_sim::io::particles::{read_file, read_ss_file};
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.ss");
    let file = std::fs::File::create(&path).unwrap();
    std::io::Write::write_all(&mut &file, &ss_header(1, -1)).unwrap();
    // Sparse: no disk, and reading it would take 2 GB of memory and seconds.
    file.set_len(2 << 30).unwrap();
    let name = path.display();
    let expected = format!(
        "{name}: byte 8: 1 particles of 96 bytes need 112 bytes, the file has {}",
        2u64 << 30
    );
    let start = std::time::Instant::now();
    assert_eq!(read_ss_file(&path).unwrap_err().to_string(), expected);
    assert_eq!(
        read_file(&path.to_string_lossy()).unwrap_err().to_string(),
        expected
    );
    let took = start.elapsed();
    assert!(took < std::time::Duration::from_millis(500), "{took:?}");
    // Reduced records are counted as the reduced size, 28 bytes.
    std::fs::write(&path, ss_header(2, -10101)).unwrap();
    assert_eq!(
        read_ss_file(&path).unwrap_err().to_string(),
        format!("{name}: byte 8: 2 particles of 28 bytes need 72 bytes, the file has 16")
    );
}

#[test]
fn what_is_not_a_regular_file_is_refused_before_it_is_read() {
    use walls_sim::io::particles::{read_file, read_input, read_ss_file};
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("fifo.ss");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    let folder = dir.path().to_path_buf();
    let cases = [
        (std::path::PathBuf::from("/dev/zero"), "a character device"),
        (fifo, "a FIFO (named pipe)"),
        (folder, "a folder"),
    ];
    for (path, kind) in cases {
        let expected = format!(
            "cannot read {}: it is {kind}, not a regular file (for standard input, give -)",
            path.display()
        );
        let start = std::time::Instant::now();
        assert_eq!(read_ss_file(&path).unwrap_err().to_string(), expected);
        let text = path.to_string_lossy();
        assert_eq!(read_file(&text).unwrap_err().to_string(), expected);
        assert_eq!(read_input(&text).unwrap_err().to_string(), expected);
        let took = start.elapsed();
        assert!(took < std::time::Duration::from_millis(500), "{took:?}");
    }
}

#[test]
fn a_csv_is_read_whole_whatever_its_first_row_says_of_the_others() {
    // The reader makes room for as many rows as the file would hold were they all as
    // long as the first: a short first row over long ones, or a long one over short
    // ones, still gives every row, each as written.
    use walls_sim::io::particles::read_file;
    let dir = tempfile::tempdir().unwrap();
    let long = |i: usize| {
        format!(
            "1.0471975511965977e-05,0.001,{},0.0011000000000000001,0.0011000000000000001,0.017712582680027036,0.028491135608711082,0.0020466157203081537",
            i as f64 * 0.0022
        )
    };
    let short = |i: usize| format!("1,1,{i},0,0,0,0,0");
    for (name, first, rest) in [
        (
            "short-first.csv",
            short(0),
            (1..300).map(long).collect::<Vec<_>>(),
        ),
        (
            "long-first.csv",
            long(0),
            (1..300).map(short).collect::<Vec<_>>(),
        ),
    ] {
        let path = dir.path().join(name);
        let text = format!("mass,radius,x,y,z,vx,vy,vz\n{first}\n{}\n", rest.join("\n"));
        std::fs::write(&path, &text).unwrap();
        let read = read_file(&path.to_string_lossy()).unwrap();
        assert_eq!(read.particles.len(), 300, "{name}");
        let expected = walls_sim::io::particles::read_csv(&text).unwrap();
        assert_eq!(read.particles, expected.particles, "{name}");
        assert_eq!(
            read.particles[299].pos.x,
            if name == "short-first.csv" {
                299.0 * 0.0022
            } else {
                299.0
            }
        );
    }
}
