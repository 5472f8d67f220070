//! The interactive HTML page, opened in a real headless Chromium (Debian's `chromium`,
//! installed by `scripts/install-test-tools`) with WebGL on SwiftShader: the walls and
//! particles are drawn in their colours, a wall of colour 0 is not, the time in the URL's
//! fragment moves the oscillating wall and the particle, and hovering a wall shows its
//! parameters; the same scene draws the same at lengthunit 6.68445e-14, 1 and 1e3; and a
//! movie in centimetres steps through its frames (a particle moves, another is gone in
//! the last frame, a reactive wall turns) with the time in seconds. The page's data and
//! its self-containedness are checked without a browser.

use nalgebra::{Rotation3, Vector3};
use std::f64::consts::FRAC_PI_2;
use std::path::{Path, PathBuf};
use std::process::Command;
use walls_geometry::Particle;
use walls_geometry::units::{Readout, System};
use walls_model::Scene;
use walls_preview::html::{self, MovieOptions, Particles};
use walls_preview::{MovieFrame, wall_meshes_in};

/// A red disk oscillating along x (amplitude 1, period 1: at t = 0.25 it is 1 to the
/// right), a blue floor that stays, and a grey plane of colour 0 above both that would
/// hide them if it were drawn.
const SCENE: &str = "\
wall type disk
  radius 1
  color 2
  osc-ampl 1
  osc-freq 6.283185307179586
  osc-vec 1 0 0
wall type rectangle
  origin -3 -3 -1
  vertex1 6 0 0
  vertex2 0 6 0
  color 4
wall type plane
  origin 0 0 0.5
  color 0
";

fn scene() -> Scene {
    walls_test_support::model_scene(SCENE)
}

/// One green particle of radius 0.3 moving from x = −2 at t = 0 to x = 2 at t = 1, at
/// y = 1.5 on the plane z = 0.
fn particles() -> Particles {
    Particles {
        radii: vec![0.3],
        colors: vec![3],
        times: vec![0.0, 1.0],
        frames: vec![vec![[-2.0, 1.5, 0.0].into()], vec![[2.0, 1.5, 0.0].into()]],
    }
}

fn page() -> String {
    let mut out = Vec::new();
    html::write(&mut out, &scene(), Some(&particles()), 1.0, 41).unwrap();
    String::from_utf8(out).unwrap()
}

/// The page's embedded data.
fn data(page: &str) -> serde_json::Value {
    let start = "<script id=\"walls-data\" type=\"application/json\">";
    let i = page.find(start).expect("the data element") + start.len();
    let j = i + page[i..].find("</script>").unwrap();
    serde_json::from_str(&page[i..j]).expect("the data is JSON")
}

#[test]
fn the_page_is_self_contained_and_holds_each_drawn_wall_with_its_motion() {
    let page = page();
    // Two inline scripts (data, viewer with three.js) and nothing fetched.
    assert_eq!(page.matches("<script").count(), 2);
    assert!(!page.contains("<script src") && !page.contains("<link"));
    assert!(page.contains("OrbitControls") || page.contains("Three.js Authors"));

    let d = data(&page);
    let walls = d["walls"].as_array().unwrap();
    let indices: Vec<u64> = walls.iter().map(|w| w["index"].as_u64().unwrap()).collect();
    assert_eq!(indices, [0, 1], "the wall of colour 0 is left out");
    assert_eq!(walls[0]["color"], "#ff0000");
    assert_eq!(walls[1]["color"], "#0000ff");
    let times = d["times"].as_array().unwrap();
    assert_eq!(times.len(), 41);
    for w in walls {
        assert_eq!(w["origins"].as_array().unwrap().len(), 3 * 41);
        assert!(w["turns"].is_null(), "nothing turns");
    }
    // Positions are about the scene's centre in units of its size (the floor is 6
    // across, the disk oscillates by 1 inside it).
    let size = d["size"].as_f64().unwrap();
    let centre: Vec<f64> = (0..3).map(|i| d["centre"][i].as_f64().unwrap()).collect();
    assert!((size - 6.0).abs() < 1e-9, "size {size}");
    // Frame 10 is t = 0.25: the disk is 1 along x, the floor where it was.
    let origin = |w: usize, k: usize, i: usize| {
        walls[w]["origins"][3 * k + i].as_f64().unwrap() * size + centre[i]
    };
    assert_eq!(times[10].as_f64().unwrap(), 0.25);
    assert!((origin(0, 0, 0)).abs() < 1e-4);
    assert!((origin(0, 10, 0) - 1.0).abs() < 1e-4);
    assert!(origin(0, 10, 1).abs() < 1e-4 && origin(0, 10, 2).abs() < 1e-4);
    // The floor never turns: it is written about its anchor, the centre of its mesh.
    assert!((0..41).all(|k| (0..3).all(|i| (origin(1, k, i) - [0.0, 0.0, -1.0][i]).abs() < 1e-4)));
    // The hover's tokens: the origin, then what the wall sets.
    let tokens: Vec<String> = walls[0]["tokens"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| format!("{} {}", t[0].as_str().unwrap(), t[1].as_str().unwrap()))
        .collect();
    assert_eq!(tokens[0], "origin 0 0 0");
    assert!(tokens.contains(&"radius 1".to_string()), "{tokens:?}");
    assert!(tokens.contains(&"osc-vec 1 0 0".to_string()), "{tokens:?}");
    assert_eq!(d["particles"]["colors"][0], "#00ff00");
    // The particle at t = 0.25, a quarter of the way from x = −2 to 2.
    let x = d["particles"]["positions"][10][0].as_f64().unwrap() * size + centre[0];
    assert!((x + 1.0).abs() < 1e-4, "x = {x}");
    assert_eq!(
        d["particles"]["radii"][0].as_f64().unwrap() as f32,
        (0.3 / size) as f32
    );
}

/// Debian's chromium, or the test fails saying how to install it.
fn chromium() -> PathBuf {
    let path = std::env::var_os("CHROMIUM").map(PathBuf::from).or_else(|| {
        std::env::var_os("PATH").and_then(|paths| {
            std::env::split_paths(&paths)
                .map(|p| p.join("chromium"))
                .find(|p| p.is_file())
        })
    });
    path.expect(
        "chromium is not installed: run scripts/install-test-tools \
         (apt-get install chromium), or set CHROMIUM to a Chromium binary",
    )
}

/// WebGL on SwiftShader, Chromium's software GPU.
const WEBGL: &[&str] = &["--use-angle=swiftshader", "--enable-unsafe-swiftshader"];

/// No WebGL at all, as on a machine without a GPU where the software one is off
/// (Debian's Chromium 156 keeps WebGL on SwiftShader with `--disable-gpu` alone).
const NO_WEBGL: &[&str] = &["--disable-software-rasterizer"];

/// Runs headless Chromium on `file` with `fragment` and `args` (WebGL on SwiftShader,
/// an 800×600 window, five seconds of virtual time for the page to load and draw);
/// returns its standard output.
fn run_chromium(dir: &Path, file: &Path, fragment: &str, args: &[&str]) -> String {
    run_chromium_with(dir, file, fragment, WEBGL, args)
}

/// [`run_chromium`] with the GPU flags `gpu` ([`WEBGL`] or [`NO_WEBGL`]).
fn run_chromium_with(
    dir: &Path,
    file: &Path,
    fragment: &str,
    gpu: &[&str],
    args: &[&str],
) -> String {
    let profile = tempfile::tempdir_in(dir).unwrap();
    let url = format!("file://{}#{fragment}", file.display());
    let output = Command::new(chromium())
        .args(["--headless", "--no-sandbox", "--disable-gpu"])
        .args(gpu)
        .args([
            "--no-first-run",
            "--hide-scrollbars",
            "--window-size=800,600",
            "--virtual-time-budget=5000",
        ])
        .arg(format!("--user-data-dir={}", profile.path().display()))
        .args(args)
        .arg(&url)
        .output()
        .expect("chromium runs");
    assert!(
        output.status.success(),
        "chromium failed on {url}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// An RGB(A) screenshot: width, height and each pixel's red, green, blue.
struct Shot {
    width: usize,
    height: usize,
    rgb: Vec<[u8; 3]>,
}

fn screenshot(dir: &Path, file: &Path, fragment: &str, name: &str) -> Shot {
    screenshot_with(dir, file, fragment, WEBGL, name)
}

/// [`screenshot`] with the GPU flags `gpu`.
fn screenshot_with(dir: &Path, file: &Path, fragment: &str, gpu: &[&str], name: &str) -> Shot {
    let png_path = dir.join(name);
    let arg = format!("--screenshot={}", png_path.display());
    run_chromium_with(dir, file, fragment, gpu, &[&arg]);
    let decoder = png::Decoder::new(std::fs::File::open(&png_path).expect("the screenshot"));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    let channels = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        other => panic!("unexpected PNG colour type {other:?}"),
    };
    let rgb = buf[..info.buffer_size()]
        .chunks(channels)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    Shot {
        width: info.width as usize,
        height: info.height as usize,
        rgb,
    }
}

impl Shot {
    /// The pixels of the 3D view (between the info line and the time controls) for
    /// which `keep` holds: their count and centroid.
    fn region(&self, keep: impl Fn([u8; 3]) -> bool) -> (usize, f64, f64) {
        let (mut n, mut sx, mut sy) = (0, 0.0, 0.0);
        for y in 40..self.height - 60 {
            for x in 0..self.width {
                if keep(self.rgb[y * self.width + x]) {
                    n += 1;
                    sx += x as f64;
                    sy += y as f64;
                }
            }
        }
        (n, sx / n.max(1) as f64, sy / n.max(1) as f64)
    }
}

const BACKGROUND: [u8; 3] = [0x20, 0x23, 0x2a];

fn red([r, g, b]: [u8; 3]) -> bool {
    r > 150 && g < 60 && b < 60
}

fn blue([r, g, b]: [u8; 3]) -> bool {
    b > 150 && r < 80 && g < 80
}

fn green([r, g, b]: [u8; 3]) -> bool {
    g > 150 && r < 80 && b < 80
}

#[test]
fn chromium_draws_the_walls_and_the_time_moves_them() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("scene.html");
    std::fs::write(&file, page()).unwrap();

    let start = screenshot(dir.path(), &file, "t=0", "t0.png");
    let later = screenshot(dir.path(), &file, "t=0.25", "t025.png");
    assert_eq!((start.width, start.height), (800, 600));

    // (a) The walls are drawn: much of the view is not background, and the red disk,
    // the blue floor and the green particle each cover a region (the plane of colour 0,
    // above them all, is not drawn).
    let (drawn, _, _) = start.region(|p| p != BACKGROUND);
    let view = 800 * (600 - 100);
    assert!(drawn > view / 10, "{drawn} of {view} pixels drawn");
    let (reds, red_x, _) = start.region(red);
    let (blues, _, _) = start.region(blue);
    let (greens, green_x, _) = start.region(green);
    assert!(reds > 3000, "{reds} red pixels at t = 0");
    assert!(blues > 20000, "{blues} blue pixels at t = 0");
    assert!(greens > 300, "{greens} green pixels at t = 0");
    // The disk is centred in the view at t = 0 (the camera looks at the scene's centre).
    assert!((red_x - 400.0).abs() < 40.0, "the disk at x = {red_x}");

    // (b) The time moves the oscillating disk (+1 along x) and the particle (+1 along
    // x): the pictures differ, and both coloured regions moved right.
    let changed = (0..start.rgb.len())
        .filter(|&i| start.rgb[i] != later.rgb[i])
        .count();
    assert!(changed > 2000, "only {changed} pixels changed");
    let (reds_later, red_x_later, _) = later.region(red);
    let (greens_later, green_x_later, _) = later.region(green);
    assert!(reds_later > 3000, "{reds_later} red pixels at t = 0.25");
    assert!(
        greens_later > 300,
        "{greens_later} green pixels at t = 0.25"
    );
    eprintln!(
        "drawn {drawn}, changed {changed}; red {reds} at x {red_x:.0} -> {reds_later} at \
         {red_x_later:.0}; green {greens} at x {green_x:.0} -> {greens_later} at \
         {green_x_later:.0}; blue {blues}"
    );
    assert!(
        red_x_later - red_x > 40.0,
        "the disk moved from x = {red_x} to {red_x_later}"
    );
    assert!(
        green_x_later - green_x > 25.0,
        "the particle moved from x = {green_x} to {green_x_later}"
    );
}

#[test]
fn chromium_shows_a_walls_parameters_on_hover_and_takes_the_time_from_the_url() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("scene.html");
    std::fs::write(&file, page()).unwrap();
    // Just right of the centre of the view, where the disk is at t = 0.
    let dom = run_chromium(dir.path(), &file, "t=0&hover=0.53,0.5", &["--dump-dom"]);
    assert!(dom.contains("data-ready=\"true\""), "{dom:.2000}");
    let tooltip = dom
        .split("<div id=\"tooltip\"")
        .nth(1)
        .and_then(|rest| rest.split("</div>").next())
        .expect("the tooltip");
    assert!(!tooltip.contains("hidden"), "{tooltip}");
    for part in [
        "<b>wall 0</b> · disk",
        "origin</span> 0 0 0",
        "radius</span> 1",
        "osc-ampl</span> 1",
        "color</span> 2",
    ] {
        assert!(tooltip.contains(part), "{part:?} not in {tooltip}");
    }

    let dom = run_chromium(dir.path(), &file, "t=0.25", &["--dump-dom"]);
    assert!(dom.contains("data-time=\"0.25\""), "{dom:.2000}");
    assert!(dom.contains("t = 0.25</span>"), "{dom:.3000}");
}

fn magenta([r, g, b]: [u8; 3]) -> bool {
    r > 150 && b > 150 && g < 80
}

/// The scene of [`SCENE`] written in a length unit `unit` (pkdgrav lengths per file
/// length), with the particle of [`particles`] in the same unit.
fn page_in(unit: f64) -> String {
    let scene = walls_test_support::model_scene(&format!("lengthunit {unit:e}\n{SCENE}"));
    let mut p = particles();
    p.radii = p.radii.iter().map(|r| r * unit).collect();
    for frame in &mut p.frames {
        for q in frame.iter_mut() {
            *q *= unit;
        }
    }
    let mut out = Vec::new();
    html::write(&mut out, &scene, Some(&p), 1.0, 5).unwrap();
    String::from_utf8(out).unwrap()
}

#[test]
fn chromium_draws_the_same_scene_at_any_length_unit() {
    let dir = tempfile::tempdir().unwrap();
    let mut seen = Vec::new();
    for (i, unit) in [6.68445e-14, 1.0, 1e3].into_iter().enumerate() {
        let page = page_in(unit);
        let d = data(&page);
        let size = d["size"].as_f64().unwrap();
        assert!(
            (size / unit - 6.0).abs() < 1e-9,
            "size {size} at unit {unit}"
        );
        let file = dir.path().join(format!("scene{i}.html"));
        std::fs::write(&file, page).unwrap();
        let shot = screenshot(dir.path(), &file, "t=0", &format!("unit{i}.png"));
        let (drawn, _, _) = shot.region(|p| p != BACKGROUND);
        let (reds, red_x, red_y) = shot.region(red);
        let (blues, _, _) = shot.region(blue);
        let (greens, green_x, green_y) = shot.region(green);
        eprintln!(
            "unit {unit:e}: drawn {drawn}, red {reds} at ({red_x:.0}, {red_y:.0}), \
             blue {blues}, green {greens} at ({green_x:.0}, {green_y:.0})"
        );
        assert!(
            drawn > 800 * 500 / 10,
            "{drawn} pixels drawn at unit {unit}"
        );
        assert!(reds > 3000 && blues > 20000, "walls at unit {unit}");
        assert!(greens > 300, "{greens} green pixels at unit {unit}");
        seen.push((reds, red_x, red_y, greens, green_x, green_y));
    }
    // The same picture at every scale: the disk and the particle where they are at
    // lengthunit 1, as large.
    let (reds, red_x, red_y, greens, green_x, green_y) = seen[1];
    for &(r, rx, ry, g, gx, gy) in &seen {
        assert!((rx - red_x).abs() < 3.0 && (ry - red_y).abs() < 3.0);
        assert!((gx - green_x).abs() < 3.0 && (gy - green_y).abs() < 3.0);
        assert!((r as f64 / reds as f64 - 1.0).abs() < 0.05);
        assert!((g as f64 / greens as f64 - 1.0).abs() < 0.05);
    }
}

/// A three-frame movie of a file in centimetres (pkdgrav's cgs units): a blue floor 6 cm
/// across; a red reactive bar, 4 cm by 0.5 cm along x, turned 90° about z in frame 2
/// and 180° in frame 3 by the run; a green particle moving from x = −2 cm to 2 cm; a
/// magenta particle at rest that frame 3 lacks (a death wall took it).
const CGS: &str = "\
lengthunit 6.68445e-14
massunit 5.02739933e-34
timeunit 1.99102e-7
wall type rectangle
  origin -3 -3 -1
  vertex1 6 0 0
  vertex2 0 6 0
  color 4
wall type rectangle
  origin -2 -0.25 0
  vertex1 4 0 0
  vertex2 0 0.5 0
  mass 1
  color 2
";

const CM: f64 = 6.68445e-14;

fn movie() -> (Scene, Vec<MovieFrame>, MovieOptions) {
    use walls_preview::mesh::{Placement, place};
    let scene = walls_test_support::model_scene(CGS);
    let box_ = (
        Vector3::new(-3.0, -3.0, -1.0) * CM,
        Vector3::new(3.0, 3.0, 1.0) * CM,
    );
    let particle = |index: usize, color: i32, x: f64, y: f64| {
        let mut p = Particle::at_rest(0.3 * CM, Vector3::new(x, y, 0.0) * CM, index);
        p.color = color;
        p
    };
    let decoded = walls_geometry::decode(&scene);
    let frames = (0..3)
        .map(|k| {
            let mut walls = wall_meshes_in(&decoded, 0.0, 64, &box_);
            // The bar turned k quarter turns about z, about its centre (0, 0, 0).
            let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), FRAC_PI_2 * k as f64);
            let corner = Vector3::new(-2.0, -0.25, 0.0) * CM;
            place(
                &mut walls,
                &decoded,
                &[Placement::Polygon {
                    wall: 1,
                    origin: turn * corner,
                    vertex1: turn * Vector3::new(4.0, 0.0, 0.0) * CM,
                    vertex2: turn * Vector3::new(0.0, 0.5, 0.0) * CM,
                }],
            );
            let mut particles = vec![particle(7, 3, -2.0 + 2.0 * k as f64, 1.5)];
            if k < 2 {
                particles.push(particle(9, 6, 0.0, -1.5));
            }
            MovieFrame {
                t: 1e-7 * k as f64,
                step: Some(100 * k as u64),
                walls,
                particles,
            }
        })
        .collect();
    let options = MovieOptions {
        readout: Readout::new(System::Auto, &scene.units),
        trails: Some(2),
        title: "a <movie>".to_string(),
    };
    (scene, frames, options)
}

fn movie_page() -> String {
    let (scene, frames, options) = movie();
    let mut out = Vec::new();
    html::write_movie(&mut out, &scene, &frames, &options).unwrap();
    String::from_utf8(out).unwrap()
}

#[test]
fn a_movies_data_holds_each_frame_the_walls_turns_and_who_is_there() {
    let page = movie_page();
    assert!(page.contains("<title>a &lt;movie&gt;</title>"));
    let d = data(&page);
    assert_eq!(d["times"].as_array().unwrap().len(), 3);
    assert_eq!(d["times"][2].as_f64().unwrap(), 2e-7);
    assert_eq!(d["steps"][1], 100);
    assert_eq!(d["trails"], 2);
    let size = d["size"].as_f64().unwrap();
    assert!((size / CM - 6.0).abs() < 1e-9, "size {size}");
    assert_eq!(d["sizeLabel"], "4.011e-13 (6 cm)");
    // The floor stays; the bar turns a quarter turn about z each frame, about its
    // origin, which moves as the corner of the turned bar.
    let walls = d["walls"].as_array().unwrap();
    assert!(walls[0]["turns"].is_null());
    let turns: Vec<f64> = walls[1]["turns"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let expected = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, h, h, 0.0, 0.0, 1.0, 0.0];
    assert_eq!(turns.len(), 12);
    for (k, q) in turns.chunks(4).enumerate() {
        let e = &expected[4 * k..4 * k + 4];
        // q and −q are the same turn.
        let sign = if q.iter().zip(e).map(|(a, b)| a * b).sum::<f64>() < 0.0 {
            -1.0
        } else {
            1.0
        };
        assert!(
            q.iter().zip(e).all(|(a, b)| (sign * a - b).abs() < 1e-6),
            "frame {k}: {q:?}"
        );
    }
    let origin = |k: usize, i: usize| walls[1]["origins"][3 * k + i].as_f64().unwrap() * 6.0;
    assert!((origin(1, 0) - 0.25).abs() < 1e-4 && (origin(1, 1) + 2.0).abs() < 1e-4);
    assert!((origin(2, 0) - 2.0).abs() < 1e-4 && (origin(2, 1) - 0.25).abs() < 1e-4);
    // The particles by index; the magenta one is absent from frame 3.
    let p = &d["particles"];
    assert_eq!(p["ids"], serde_json::json!([7, 9]));
    assert_eq!(p["colors"], serde_json::json!(["#00ff00", "#ff00ff"]));
    let x = |k: usize, i: usize| p["positions"][k][i].as_f64();
    assert_eq!(
        x(0, 0),
        Some(-2.0 / 6.0_f64).map(|v| (v * 1e5).round() / 1e5)
    );
    assert_eq!(
        x(2, 0),
        Some(2.0 / 6.0_f64).map(|v| (v * 1e5).round() / 1e5)
    );
    assert!(x(1, 3).is_some() && p["positions"][2][3].is_null());
}

#[test]
fn chromium_plays_a_movie_frame_by_frame() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("movie.html");
    std::fs::write(&file, movie_page()).unwrap();
    let first = screenshot(dir.path(), &file, "frame=0", "f0.png");
    let last = screenshot(dir.path(), &file, "frame=2", "f2.png");
    let (greens, green_x, _) = first.region(green);
    let (greens_last, green_x_last, _) = last.region(green);
    let (magentas, _, _) = first.region(magenta);
    let (magentas_last, _, _) = last.region(magenta);
    let (reds, _, _) = first.region(red);
    let (reds_last, _, _) = last.region(red);
    eprintln!(
        "green {greens} at x {green_x:.0} -> {greens_last} at {green_x_last:.0}; \
         magenta {magentas} -> {magentas_last}; red {reds} -> {reds_last}"
    );
    // The green particle at x = −2 cm (left of the centre), then 2 cm (right).
    assert!(greens > 300 && greens_last > 300);
    assert!(
        green_x < 380.0 && green_x_last > 420.0,
        "{green_x} -> {green_x_last}"
    );
    // The magenta particle is drawn in frame 1 and not in frame 3.
    assert!(magentas > 300, "{magentas} magenta pixels in frame 1");
    assert!(
        magentas_last < 10,
        "{magentas_last} magenta pixels in frame 3"
    );
    // The bar is drawn, and turned a quarter turn in frame 2 (half a turn, in frame 3,
    // looks as it did in frame 1).
    assert!(reds > 1000 && reds_last > 1000);
    let turned = screenshot(dir.path(), &file, "frame=1", "f1.png");
    let changed = (0..first.rgb.len())
        .filter(|&i| red(first.rgb[i]) != red(turned.rgb[i]))
        .count();
    assert!(changed > 1000, "{changed} pixels changed redness");

    // The time label reads the time in pkdgrav's units and the file's (seconds).
    let (scene, _, _) = movie();
    let readout = Readout::new(System::Auto, &scene.units);
    let dom = run_chromium(dir.path(), &file, "frame=2", &["--dump-dom"]);
    assert!(dom.contains("data-frame=\"2\""), "{dom:.2000}");
    let label = format!(
        "<span id=\"time-label\" title=\"frame 3 of 3, step 200\">t = {}</span>",
        readout.time(2e-7)
    );
    assert!(label.contains("2e-7 (1.005 s)"), "{label}");
    assert!(dom.contains(&label), "{label} not in {dom:.3000}");
}

/// A floor whose origin is 1e40 along it: its mesh is written about the centre of its
/// mesh, in the scene, not about that origin (the offsets, 1e40 / 6, were past f32 and
/// written as 0: the floor drawn as a point).
#[test]
fn a_floor_whose_origin_is_far_along_it_is_drawn_where_it_is() {
    let s = walls_test_support::model_scene(&format!(
        "{SCENE}wall type plane\n  origin 1e40 0 -1\n  color 4\n"
    ));
    let mut out = Vec::new();
    html::write(&mut out, &s, None, 0.0, 1).unwrap();
    let d = data(&String::from_utf8(out).unwrap());
    let floor = d["walls"]
        .as_array()
        .unwrap()
        .iter()
        .find(|w| w["index"] == 3)
        .expect("the floor plane");
    let xs: Vec<f64> = floor["positions"]
        .as_array()
        .unwrap()
        .iter()
        .step_by(3)
        .map(|x| x.as_f64().unwrap())
        .collect();
    let (lo, hi) = xs
        .iter()
        .fold((f64::MAX, f64::MIN), |(lo, hi), x| (lo.min(*x), hi.max(*x)));
    // The plane cut to the scene's box: about one scene across along x, around its
    // anchor.
    assert!(
        lo < -0.4 && hi > 0.4 && lo > -2.0 && hi < 2.0,
        "{lo} to {hi}"
    );
    let size = d["size"].as_f64().unwrap();
    let anchor: Vec<f64> = (0..3)
        .map(|i| floor["origins"][i].as_f64().unwrap() * size + d["centre"][i].as_f64().unwrap())
        .collect();
    assert!(
        anchor[0].abs() < 1e-3 && (anchor[2] + 1.0).abs() < 1e-3,
        "{anchor:?}"
    );
}

/// The part of the DOM from `start` to the end of that element's first line.
fn element<'a>(dom: &'a str, start: &str) -> &'a str {
    let i = dom
        .find(start)
        .unwrap_or_else(|| panic!("{start} not in {dom:.3000}"));
    &dom[i..i + dom[i..].find('>').unwrap() + 1]
}

#[test]
fn chromium_without_webgl_shows_why_and_the_svg_of_the_frame_asked_for() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("scene.html");
    std::fs::write(&file, page()).unwrap();

    // The message is shown, says why and what to do, and the picture is walls-preview's
    // SVG (its groups of frames, its polygons), every frame held (41 small ones).
    let dom = run_chromium_with(dir.path(), &file, "t=0.25", NO_WEBGL, &["--dump-dom"]);
    assert!(dom.contains("data-webgl=\"false\""), "{dom:.2000}");
    assert!(dom.contains("data-ready=\"true\""), "{dom:.2000}");
    assert_eq!(
        element(&dom, "<div id=\"no-webgl\""),
        "<div id=\"no-webgl\">"
    );
    for part in [
        "This page draws the walls with WebGL, which this browser does not offer here",
        "this browser offers no WebGL 2 here",
        "open this page in a browser with WebGL",
        "<code>--out picture.svg</code>",
        "The picture is frame 11 of 41.",
    ] {
        assert!(dom.contains(part), "{part:?} not in the page");
    }
    let picture = element(&dom, "<div id=\"no-webgl-picture\"");
    let held: String = (0..41).map(|k| k.to_string()).collect::<Vec<_>>().join(",");
    assert!(
        picture.contains(&format!("data-frames=\"{held}\"")),
        "{picture}"
    );
    assert!(!dom.contains("<canvas"), "no canvas without WebGL");
    assert!(
        !dom.contains("<animate"),
        "the page steps the frames itself"
    );
    // Frame 10 (t = 0.25) shown, the others not.
    let groups: Vec<&str> = dom
        .match_indices("<g class=\"frame\"")
        .map(|(i, _)| &dom[i..i + 40])
        .collect();
    assert_eq!(groups.len(), 41);
    for (k, g) in groups.iter().enumerate() {
        let shown = if k == 10 { "inline" } else { "none" };
        assert!(
            g.contains(&format!("display=\"{shown}\"")),
            "frame {k}: {g}"
        );
    }

    // What a person sees: the message on top and the disk, floor and particle below it,
    // the disk 1 to the right at t = 0.25.
    let start = screenshot_with(dir.path(), &file, "t=0", NO_WEBGL, "no-webgl-0.png");
    let later = screenshot_with(dir.path(), &file, "t=0.25", NO_WEBGL, "no-webgl-1.png");
    let light = |[r, g, b]: [u8; 3]| r > 200 && g > 200 && b > 200;
    let text = (0..40 * start.width)
        .filter(|&i| light(start.rgb[i]))
        .count();
    assert!(text > 500, "{text} light pixels of text at the top");
    let (reds, red_x, _) = start.region(red);
    let (blues, _, _) = start.region(blue);
    let (greens, _, _) = start.region(green);
    let (reds_later, red_x_later, _) = later.region(red);
    eprintln!(
        "without WebGL: text {text}, red {reds} at x {red_x:.0} -> {reds_later} at \
         {red_x_later:.0}, blue {blues}, green {greens}"
    );
    assert!(
        reds > 3000 && blues > 20000 && greens > 100,
        "the SVG is drawn"
    );
    assert!(red_x_later - red_x > 40.0, "{red_x} -> {red_x_later}");
}

#[test]
fn chromium_without_webgl_steps_a_movie_through_its_pictures() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("movie.html");
    std::fs::write(&file, movie_page()).unwrap();
    let dom = run_chromium_with(dir.path(), &file, "frame=2", NO_WEBGL, &["--dump-dom"]);
    assert!(dom.contains("data-webgl=\"false\""), "{dom:.2000}");
    assert!(dom.contains("data-frame=\"2\""), "{dom:.2000}");
    assert!(dom.contains("The picture is frame 3 of 3."), "{dom:.3000}");
    // The slider steps through the held frames, at the one shown.
    let slider = element(&dom, "<input id=\"no-webgl-time\"");
    assert!(slider.contains("max=\"2\""), "{slider}");
    // The title is escaped as before; the picture's time in the file's units.
    assert!(dom.contains("<title>a &lt;movie&gt;</title>"));
    assert!(dom.contains("t = 2e-7 (1.005 s)"), "{dom:.3000}");
    // With WebGL the same page draws with three.js, its message hidden.
    let dom = run_chromium(dir.path(), &file, "frame=2", &["--dump-dom"]);
    assert!(dom.contains("data-webgl=\"true\""), "{dom:.2000}");
    assert_eq!(
        element(&dom, "<div id=\"no-webgl\""),
        "<div id=\"no-webgl\" hidden=\"\">"
    );
}

#[test]
fn a_long_movie_holds_at_most_a_megabyte_of_pictures_evenly_spaced() {
    use walls_preview::html::FALLBACK_BYTES;
    let scene = scene();
    let walls = walls_geometry::decode(&scene);
    let box_ = (Vector3::new(-3.0, -3.0, -1.0), Vector3::new(3.0, 3.0, 1.0));
    let n = 1000;
    let frames: Vec<MovieFrame> = (0..n)
        .map(|k| {
            let t = k as f64 / n as f64;
            let particles = (0..50)
                .map(|i| {
                    let mut p =
                        Particle::at_rest(0.05, Vector3::new(i as f64 * 0.1 - 2.5, t, 0.0), i);
                    p.color = 3;
                    p
                })
                .collect();
            MovieFrame {
                t,
                step: Some(k as u64),
                walls: wall_meshes_in(&walls, t, 64, &box_),
                particles,
            }
        })
        .collect();
    let options = MovieOptions {
        readout: Readout::new(System::Auto, &scene.units),
        trails: None,
        title: "long".into(),
    };
    let mut out = Vec::new();
    html::write_movie(&mut out, &scene, &frames, &options).unwrap();
    let page = String::from_utf8(out).unwrap();
    let i = page.find("<div id=\"no-webgl-picture\"").unwrap();
    let j = i + page[i..].find("</svg>").unwrap();
    let picture = &page[i..j];
    let held: Vec<usize> = element(picture, "<div")
        .split("data-frames=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .split(',')
        .map(|k| k.parse().unwrap())
        .collect();
    eprintln!(
        "1000 frames: {} held, {} bytes of SVG, page {} bytes",
        held.len(),
        picture.len(),
        page.len()
    );
    assert_eq!((held[0], *held.last().unwrap()), (0, n - 1));
    assert!(held.len() > 10 && held.len() < n, "{} held", held.len());
    assert!(
        picture.len() <= FALLBACK_BYTES + FALLBACK_BYTES / 10,
        "{}",
        picture.len()
    );
    assert_eq!(picture.matches("<g class=\"frame\"").count(), held.len());
    // Evenly spaced.
    let gaps: Vec<usize> = held.windows(2).map(|w| w[1] - w[0]).collect();
    assert!(
        gaps.iter().max().unwrap() - gaps.iter().min().unwrap() <= 1,
        "{gaps:?}"
    );
}

#[test]
fn a_page_of_no_frames_holds_the_picture_of_an_empty_scene() {
    let (scene, _, options) = movie();
    let mut out = Vec::new();
    html::write_movie(&mut out, &scene, &[], &options).unwrap();
    let page = String::from_utf8(out).unwrap();
    let picture = element(&page, "<div id=\"no-webgl-picture\"");
    assert_eq!(
        picture,
        "<div id=\"no-webgl-picture\" data-frames=\"\" data-of=\"1\">"
    );
    let i = page.find(picture).unwrap() + picture.len();
    assert!(
        page[i..].trim_start().starts_with("<svg xmlns="),
        "{:.200}",
        &page[i..]
    );
    assert!(!page.contains("<?xml"), "the SVG's declaration is left out");
}

#[test]
fn particles_take_ssdraws_colours() {
    // Colour 0 black; −2, stuck to wall 1 (the blue floor), blue; −3, stuck to the
    // plane of colour 0, black; 300 and a missing colour have none (light grey).
    let p = Particles {
        radii: vec![0.1; 5],
        colors: vec![0, -2, -3, 300],
        times: vec![0.0],
        frames: vec![
            (0..5)
                .map(|i| [f64::from(i) - 2.0, 0.0, 0.0].into())
                .collect(),
        ],
    };
    let mut out = Vec::new();
    html::write(&mut out, &scene(), Some(&p), 1.0, 2).unwrap();
    let d = data(&String::from_utf8(out).unwrap());
    assert_eq!(
        d["particles"]["colors"],
        serde_json::json!(["#000000", "#0000ff", "#000000", null, null])
    );
}
