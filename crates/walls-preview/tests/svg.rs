//! The SVG renderer, checked by rasterising its output with an independent renderer
//! (resvg): walls appear in their colours where they stand, colour 0 is not drawn, a
//! moving wall moves between frames, and the animation has its frames, each shown in its
//! own slot, the file growing linearly with them.

use nalgebra::Vector3;
use walls_geometry::units::{Readout, System};
use walls_model::Scene;
use walls_preview::svg::{Frame, View, write};
use walls_preview::wall_meshes;
use walls_test_support::model_scene as scene;

/// The SVG of `scene` at the times `ts`, seen from above (z towards the viewer).
fn svg(scene: &Scene, ts: &[f64]) -> String {
    let meshes: Vec<_> = ts.iter().map(|t| wall_meshes(scene, *t, 64)).collect();
    let frames: Vec<Frame> = ts
        .iter()
        .zip(&meshes)
        .map(|(t, walls)| Frame {
            t: *t,
            walls,
            particles: &[],
        })
        .collect();
    let view = View {
        from: Vector3::z(),
        up: Vector3::y(),
        width: 200,
        height: 200,
    };
    let mut out = Vec::new();
    let box_ = (Vector3::new(-2.0, -2.0, -1.0), Vector3::new(2.0, 2.0, 1.0));
    let readout = Readout::new(System::Pkdgrav, &scene.units);
    write(&mut out, &frames, &view, box_, 2.0, &readout).unwrap();
    String::from_utf8(out).unwrap()
}

/// Rasterises an SVG; returns the pixels (RGBA) and the width.
fn raster(svg: &str) -> (Vec<u8>, u32) {
    let tree = resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default()).unwrap();
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pixmap.as_mut(),
    );
    (pixmap.data().to_vec(), size.width())
}

/// The centre of the pure red pixels (a red wall facing the viewer; the red x axis is
/// darker), and how many there are.
fn red(pixels: &[u8], width: u32) -> ((f64, f64), usize) {
    let (mut sx, mut sy, mut n) = (0.0, 0.0, 0usize);
    for (k, p) in pixels.chunks(4).enumerate() {
        if p[0] > 240 && p[1] < 128 && p[2] < 128 {
            sx += (k as u32 % width) as f64;
            sy += (k as u32 / width) as f64;
            n += 1;
        }
    }
    ((sx / n.max(1) as f64, sy / n.max(1) as f64), n)
}

#[test]
fn walls_are_drawn_in_their_colours_where_they_stand() {
    // A red disk of radius 1 at x = 1 and a wall of colour 0 (not drawn).
    let s = scene(
        "wall type disk\n  origin 1 0 0\n  radius 1\n  color 2\nwall type rectangle\n  origin -2 -2 0.5\n  vertex1 1 0 0\n  vertex2 0 1 0\n  color 0\n",
    );
    let (pixels, width) = raster(&svg(&s, &[0.0]));
    let ((x, y), n) = red(&pixels, width);
    // The box of 4 × 4 fills 80 % of 200 pixels: 40 pixels a unit, centred at 100.
    let area = std::f64::consts::PI * 40.0 * 40.0;
    assert!(
        (n as f64 / area - 1.0).abs() < 0.05,
        "{n} red pixels, {area} expected"
    );
    assert!(
        (x - 140.0).abs() < 1.5 && (y - 100.0).abs() < 1.5,
        "centre {x}, {y}"
    );
    // Nothing drawn for the colour-0 rectangle: around (−1.5, −1.5) it is white.
    let at = |px: u32, py: u32| &pixels[((py * width + px) * 4) as usize..][..3];
    assert_eq!(at(40, 160), [255, 255, 255]);
}

#[test]
fn a_moving_wall_moves_between_frames_and_the_animation_has_them_all() {
    let s = scene("wall type disk\n  radius 0.5\n  color 2\n  velocity 1 0 0\n");
    let (a, w) = raster(&svg(&s, &[0.0]));
    let (b, _) = raster(&svg(&s, &[1.0]));
    let ((xa, _), _) = red(&a, w);
    let ((xb, _), _) = red(&b, w);
    assert!((xb - xa - 40.0).abs() < 1.5, "moved {} pixels", xb - xa);
    let animated = svg(&s, &[0.0, 0.5, 1.0]);
    assert_eq!(animated.matches("<g class=\"frame\"").count(), 3);
    assert_eq!(animated.matches("<animate ").count(), 3);
    // It is valid SVG that resvg renders (the first frame shows).
    let (first, _) = raster(&animated);
    assert!(red(&first, w).1 > 100);
}

/// Each frame of an animation is shown in its own slot of the cycle by an `<animate>`
/// of at most three values (hidden, shown, hidden), so that the file grows linearly with
/// the frames: listing every frame in each frame's `<animate>` made 10,000 frames of
/// one particle 1.4 GB.
#[test]
fn an_animation_grows_linearly_with_its_frames() {
    let s = scene("wall type disk\n  radius 0.5\n  color 2\n  velocity 1 0 0\n");
    let times = |n: usize| -> Vec<f64> { (0..n).map(|k| k as f64 / n as f64).collect() };
    let animated = svg(&s, &times(4));
    let slots: Vec<(&str, &str)> = animated
        .lines()
        .filter(|l| l.starts_with("<animate "))
        .map(|l| {
            let attribute = |name: &str| {
                let from = l.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
                &l[from..from + l[from..].find('"').unwrap()]
            };
            (attribute("values"), attribute("keyTimes"))
        })
        .collect();
    assert_eq!(
        slots,
        [
            ("inline;none", "0;0.250000"),
            ("none;inline;none", "0;0.250000;0.500000"),
            ("none;inline;none", "0;0.500000;0.750000"),
            ("none;inline", "0;0.750000"),
        ]
    );
    let (small, large) = (svg(&s, &times(100)).len(), svg(&s, &times(400)).len());
    assert!(
        (large as f64) < 4.2 * small as f64,
        "100 frames {small} bytes, 400 frames {large}"
    );
}

/// Particles in ssdraw's palette: colour 0 black, a stuck particle (−1 − w) in wall w's
/// colour, a colour ssdraw refuses mid grey.
#[test]
fn particles_take_ssdraws_colours() {
    let scene = scene("wall type disk\n  radius 0.5\n  color 9\n");
    let meshes = wall_meshes(&scene, 0.0, 16);
    let particle = |x: f64, color| walls_geometry::Particle {
        color,
        ..walls_geometry::Particle::at_rest(0.1, Vector3::new(x, 0.0, 1.0), 0)
    };
    let particles = [particle(-1.0, 0), particle(0.0, -1), particle(1.0, 256)];
    let frames = [Frame {
        t: 0.0,
        walls: &meshes,
        particles: &particles,
    }];
    let mut out = Vec::new();
    let box_ = (Vector3::new(-2.0, -2.0, -1.0), Vector3::new(2.0, 2.0, 1.0));
    let readout = Readout::new(System::Pkdgrav, &scene.units);
    write(&mut out, &frames, &View::default(), box_, 1.0, &readout).unwrap();
    let svg = String::from_utf8(out).unwrap();
    let discs: Vec<&str> = svg.lines().filter(|l| l.starts_with("<circle")).collect();
    assert_eq!(discs.len(), 3, "{svg}");
    for fill in ["#000000", "#ffc0cb", "#808080"] {
        assert_eq!(
            discs
                .iter()
                .filter(|d| d.contains(&format!("fill=\"{fill}\"")))
                .count(),
            1,
            "{fill}: {discs:?}"
        );
    }
}

/// The time label and the scale bar in the units asked for: seconds and centimetres for
/// a file in centimetres read in cgs, both numbers with `auto`.
#[test]
fn labels_are_in_the_units_asked_for() {
    let mut scene = scene("wall type disk\n  radius 0.5\n  color 2\n");
    scene.units.length = 6.68459e-14;
    scene.units.time = 1.99102e-7;
    let meshes = wall_meshes(&scene, 0.0, 16);
    let frames = [Frame {
        t: 2.0 * scene.units.time,
        walls: &meshes,
        particles: &[],
    }];
    let view = View::default();
    let box_ = (Vector3::new(-1.0, -1.0, 0.0), Vector3::new(1.0, 1.0, 0.0));
    let label = |system| {
        let mut out = Vec::new();
        let readout = Readout::new(system, &scene.units);
        write(&mut out, &frames, &view, box_, 1.0, &readout).unwrap();
        String::from_utf8(out).unwrap()
    };
    let cgs = label(System::Cgs);
    assert!(cgs.contains(">t = 2 s</text>"), "{cgs}");
    assert!(cgs.contains(" cm</text></g>"), "{cgs}");
    let auto = label(System::Auto);
    assert!(auto.contains(">t = 3.982e-7 (2 s)</text>"), "{auto}");
}
