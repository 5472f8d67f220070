//! The interactive HTML page, opened in a real headless Chromium (Debian's `chromium`,
//! installed by `scripts/install-test-tools`) with WebGL on SwiftShader: the walls and
//! particles are drawn in their colours, a wall of colour 0 is not, the time in the URL's
//! fragment moves the oscillating wall and the particle, and hovering a wall shows its
//! parameters. The page's data and its self-containedness are checked without a browser.

use std::path::{Path, PathBuf};
use std::process::Command;
use walls_model::Scene;
use walls_preview::html::{self, Particles};

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
    assert!(
        (0..41).all(|k| (0..3).all(|i| (origin(1, k, i) - [-3.0, -3.0, -1.0][i]).abs() < 1e-4))
    );
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

/// Runs headless Chromium on `file` with `fragment` and `args` (WebGL on SwiftShader,
/// an 800×600 window, five seconds of virtual time for the page to load and draw);
/// returns its standard output.
fn run_chromium(dir: &Path, file: &Path, fragment: &str, args: &[&str]) -> String {
    let profile = tempfile::tempdir_in(dir).unwrap();
    let url = format!("file://{}#{fragment}", file.display());
    let output = Command::new(chromium())
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader",
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
    let png_path = dir.join(name);
    let arg = format!("--screenshot={}", png_path.display());
    run_chromium(dir, file, fragment, &[&arg]);
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
