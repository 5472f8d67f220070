//! POV-Ray scenes rendered by the real `povray` (installed by `scripts/install-test-tools`):
//! every primitive of the sample scene parses and draws something, and a red disk shows
//! up exactly when it is drawn, on the side of the picture where it is (the camera is
//! right-handed, as the walls' axes are). Also what the scene text says: colour names,
//! greys, `transmit`, colour 0 left out.

use nalgebra::Vector3;
use std::path::Path;
use std::process::Command;
use walls_geometry::Particle;
use walls_model::Scene;
use walls_preview::pov::{self, View};
use walls_test_support::model_scene as scene;

const W: u32 = 160;
const H: u32 = 120;

fn particle(x: f64, y: f64, z: f64, radius: f64, color: i32) -> Particle {
    Particle {
        mass: 1.0,
        radius,
        pos: Vector3::new(x, y, z),
        vel: Vector3::zeros(),
        spin: Vector3::zeros(),
        color,
        index: 0,
    }
}

fn text(scene: &Scene, particles: &[Particle]) -> String {
    let mut out = Vec::new();
    pov::write(&mut out, scene, 0.0, particles, &View::default()).unwrap();
    String::from_utf8(out).unwrap()
}

/// A rendered picture: its pixels, row by row, as red, green, blue.
struct Picture {
    pixels: Vec<[u8; 3]>,
}

impl Picture {
    fn at(&self, x: u32, y: u32) -> [u8; 3] {
        self.pixels[(y * W + x) as usize]
    }

    /// The pixels where `pick` holds, and their mean column.
    fn find(&self, pick: impl Fn([u8; 3]) -> bool) -> (usize, f64) {
        let mut count = 0;
        let mut sum = 0.0;
        for y in 0..H {
            for x in 0..W {
                if pick(self.at(x, y)) {
                    count += 1;
                    sum += x as f64;
                }
            }
        }
        (count, if count > 0 { sum / count as f64 } else { -1.0 })
    }
}

/// Writes the scene (and `walls.inc`) to a new directory, renders it at W×H with
/// `povray`, asserts it rendered and returns the picture.
fn render(scene: &Scene, particles: &[Particle]) -> Picture {
    let dir = tempfile::tempdir().unwrap();
    let pov_path = dir.path().join("scene.pov");
    let mut scene_text = Vec::new();
    pov::write(&mut scene_text, scene, 0.0, particles, &View::default()).unwrap();
    std::fs::write(&pov_path, scene_text).unwrap();
    std::fs::write(dir.path().join(pov::INCLUDE_NAME), pov::INCLUDE).unwrap();
    let png_path = dir.path().join("scene.png");
    let output = Command::new("povray")
        .current_dir(dir.path())
        .arg("+Iscene.pov")
        .arg("+Oscene.png")
        .arg(format!("+W{W}"))
        .arg(format!("+H{H}"))
        .args(["-D", "+A0.3", "+FN8", "-GA"])
        .arg(format!("+L{}", dir.path().display()))
        .output()
        .unwrap_or_else(|e| {
            panic!("cannot run `povray` ({e}): install it with scripts/install-test-tools")
        });
    let scene_text = std::fs::read_to_string(&pov_path).unwrap();
    assert!(
        output.status.success() && png_path.exists(),
        "povray failed ({}):\n{}\n--- scene.pov ---\n{scene_text}",
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
    decode(&png_path)
}

fn decode(path: &Path) -> Picture {
    let mut decoder = png::Decoder::new(std::fs::File::open(path).unwrap());
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.width, info.height), (W, H));
    let samples = info.color_type.samples();
    assert!(samples >= 3, "{:?}", info.color_type);
    let pixels = buf[..info.buffer_size()]
        .chunks(samples)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    Picture { pixels }
}

fn background() -> [u8; 3] {
    View::default()
        .background
        .map(|c| (c * 255.0).round() as u8)
}

fn near(a: [u8; 3], b: [u8; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| x.abs_diff(y) <= 3)
}

fn red(p: [u8; 3]) -> bool {
    let [r, g, b] = p.map(u32::from);
    r > 100 && r > 2 * g && r > 2 * b
}

fn blue(p: [u8; 3]) -> bool {
    let [r, g, b] = p.map(u32::from);
    b > 100 && b > 2 * r && b > 2 * g
}

#[test]
fn the_sample_scene_renders_every_primitive() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/sample.walls");
    let s = scene(&std::fs::read_to_string(path).unwrap());
    let particles = [
        particle(0.0, 0.5, 0.3, 0.1, 3),
        particle(0.2, 0.4, 0.6, 0.08, 100),
    ];
    let t = text(&s, &particles);
    for primitive in [
        "box {",
        "disc {",
        "cylinder {",
        " open\n",
        "difference {",
        "polygon {",
        "sphere {",
    ] {
        assert!(t.contains(primitive), "no {primitive} in\n{t}");
    }
    let picture = render(&s, &particles);
    let bg = background();
    let (drawn, _) = picture.find(|p| !near(p, bg));
    assert!(
        drawn > picture.pixels.len() / 5,
        "only {drawn} of {} pixels are not the background",
        picture.pixels.len()
    );
    let (green, _) = picture.find(|p| {
        let [r, g, b] = p.map(u32::from);
        g > 100 && g > 2 * r && g > 2 * b
    });
    assert!(green > 0, "the green particle is not in the picture");
}

#[test]
fn a_red_disk_is_drawn_where_it_is() {
    let walls = |red_colour: i64| {
        format!(
            "wall type plane\n  color 180\n\
             wall type disk\n  origin 1 0 0.1\n  radius 0.6\n  color {red_colour}\n\
             wall type disk\n  origin -1 0 0.1\n  radius 0.6\n  color 4\n"
        )
    };
    let with = render(&scene(&walls(2)), &[]);
    let without = render(&scene(&walls(0)), &[]);
    let (reds, red_x) = with.find(red);
    let (blues, blue_x) = with.find(blue);
    assert!(reds > 200, "{reds} red pixels with the red disk");
    assert!(blues > 200, "{blues} blue pixels with the blue disk");
    assert_eq!(without.find(red).0, 0, "red pixels without the red disk");
    assert!(without.find(blue).0 > 200);
    // Every red pixel is a pixel the red disk changed.
    let changed = (0..with.pixels.len())
        .filter(|&i| red(with.pixels[i]) && !near(with.pixels[i], without.pixels[i]))
        .count();
    assert_eq!(changed, reds);
    // Seen from (1, −1.5, 1) with z up, +x is to the right of the picture.
    let mid = f64::from(W) / 2.0;
    assert!(
        red_x > mid && blue_x < mid,
        "red (x = +1) at column {red_x}, blue (x = −1) at {blue_x}: mirrored?"
    );
}

#[test]
fn shells_open_at_any_angle_and_every_wall_type_parse() {
    let s = scene(
        "wall type shell\n  radius 0.5\n\
         wall type shell\n  origin 1.2 0 0\n  radius 0.5\n  open-angle 45\n\
         wall type shell\n  origin 2.4 0 0\n  radius 0.5\n  open-angle 90\n\
         wall type shell\n  origin 3.6 0 0\n  radius 0.5\n  open-angle 135\n  color 8\n\
         wall type triangle\n  origin 0 -1.5 0\n  vertex1 1 0 0\n  vertex2 0 1 0\n  color 3\n\
         wall type cylinder-infinite\n  origin 0 2 0\n  orient 1 0 0\n  radius 0.2\n  color 5\n\
         wall type cylinder-finite\n  origin 2 -1.5 0\n  radius 0.3\n  length 0.5\n  taper 1\n\
         wall type disk\n  origin 3 -1.5 0\n  radius 0.4\n  hole-radius 0.2\n  color 150\n\
           transparency 0.5\n",
    );
    let t = text(&s, &[]);
    assert!(t.contains("plane {") && t.contains("intersection {"), "{t}");
    let picture = render(&s, &[]);
    let bg = background();
    assert!(picture.find(|p| !near(p, bg)).0 > 500);
}

#[test]
fn colours_follow_ssdraw() {
    let s = scene(
        "wall type disk\n  radius 1\n  color 2\n\
         wall type disk\n  radius 1\n  color 0\n\
         wall type disk\n  radius 1\n  color 255\n  transparency 0.25\n\
         wall type disk\n  radius 1\n  color 16\n  transparency 50\n",
    );
    let t = text(
        &s,
        &[
            particle(0.0, 0.0, 1.0, 0.1, 0),
            particle(0.0, 0.0, 2.0, 0.1, 15),
        ],
    );
    assert!(t.contains("DiskStyle(SsdrawRed, 0)"), "{t}");
    assert!(t.contains("// wall 1: disk, colour 0: not drawn"), "{t}");
    assert!(t.contains("DiskStyle(rgb <1, 1, 1>, 0.25)"), "{t}");
    assert!(t.contains("DiskStyle(rgb <0, 0, 0>, 0.5)"), "{t}");
    assert_eq!(t.matches("disc {").count(), 3, "{t}");
    // A particle of colour 0 is drawn, black (only walls of colour 0 are not).
    assert_eq!(t.matches("ParticleStyle(").count(), 2, "{t}");
    assert!(t.contains("ParticleStyle(SsdrawBlack)"), "{t}");
    assert!(t.contains("ParticleStyle(SsdrawNavy)"), "{t}");
    assert!(t.contains("#include \"walls.inc\""), "{t}");
    // The scene needs nothing of POV-Ray's library: ssdraw's colours are walls.inc's.
    assert!(!pov::INCLUDE.contains("colors.inc\""));
    assert!(!t.contains("White"), "{t}");
    for style in [
        "Plane",
        "Triangle",
        "Rectangle",
        "Disk",
        "Cylinder",
        "Shell",
        "Particle",
    ] {
        assert!(
            pov::INCLUDE.contains(&format!("#macro {style}Style(")),
            "{style}"
        );
    }
}

#[test]
fn a_stuck_particle_is_drawn_in_its_walls_colour() {
    // Colour −1 − w is wall w's colour (ssdraw's palette, §16); a wall that is not there
    // or a colour above 255 leaves the particle out.
    let s = scene(
        "wall type disk\n  radius 1\n  color 0\n\
         wall type disk\n  radius 1\n  color 8\n",
    );
    let t = text(
        &s,
        &[
            particle(0.0, 0.0, 1.0, 0.1, -2),
            particle(0.0, 0.0, 2.0, 0.1, -1),
            particle(0.0, 0.0, 3.0, 0.1, -3),
            particle(0.0, 0.0, 4.0, 0.1, 300),
        ],
    );
    assert!(t.contains("ParticleStyle(SsdrawGold)"), "{t}");
    assert!(t.contains("ParticleStyle(SsdrawBlack)"), "{t}");
    assert_eq!(t.matches("ParticleStyle(").count(), 2, "{t}");
}

#[test]
fn walls_inc_declares_ssdraws_palette() {
    // Each of colours 0–15 is declared once, as `rgb <r, g, b> / 255` with ssdraw's
    // bytes (gold 255 215 0, not colors.inc's 0.8 0.498 0.196), under the name the
    // scenes use.
    for (index, [r, g, b]) in walls_preview::palette::NAMED.iter().enumerate() {
        let name = pov::colour(index as i64).unwrap();
        let declared = format!("#declare {name} = rgb <{r}, {g}, {b}> / 255;");
        assert_eq!(pov::INCLUDE.matches(&declared).count(), 1, "{declared}");
        assert_eq!(
            pov::INCLUDE.matches(&format!("#declare {name} ")).count(),
            1
        );
    }
    assert_eq!(pov::colour(8).as_deref(), Some("SsdrawGold"));
    assert_eq!(pov::colour(14).as_deref(), Some("SsdrawAqua"));
    assert_eq!(pov::colour(16).as_deref(), Some("rgb <0, 0, 0>"));
    assert_eq!(
        pov::colour(135).as_deref(),
        Some("rgb <0.4941176471, 0.4941176471, 0.4941176471>")
    );
    assert_eq!(pov::colour(256), None);
    assert_eq!(pov::colour(-1), None);
}

#[test]
fn the_picture_is_the_same_at_any_scale() {
    // pkdgrav's files are in centimetres converted to AU: the same scene at 6.68445e-14
    // and at 1e+3 length units renders as at 1 (the scene is renormalised), particles
    // included.
    let walls = |unit: f64| {
        scene(&format!(
            "lengthunit {unit}\n\
             wall type plane\n  color 180\n\
             wall type disk\n  origin 1 0 0.1\n  radius 0.6\n  color 2\n\
             wall type disk\n  origin -1 0 0.1\n  radius 0.6\n  color 4\n"
        ))
    };
    let green = |unit: f64| [particle(0.0, 0.0, 0.5 * unit, 0.3 * unit, 3)];
    let is_green = |p: [u8; 3]| {
        let [r, g, b] = p.map(u32::from);
        g > 100 && g > 2 * r && g > 2 * b
    };
    let one = render(&walls(1.0), &green(1.0));
    let (reds, blues, greens) = (one.find(red).0, one.find(blue).0, one.find(is_green).0);
    assert!(
        reds > 200 && blues > 200 && greens > 100,
        "{reds} {blues} {greens}"
    );
    for unit in [6.68445e-14, 1e3] {
        let scaled = render(&walls(unit), &green(unit));
        let differ = (0..one.pixels.len())
            .filter(|&i| !near(one.pixels[i], scaled.pixels[i]))
            .count();
        assert!(
            differ < one.pixels.len() / 200,
            "at {unit} length units {differ} pixels differ from the picture at 1"
        );
    }
}
