//! SVG pictures of the walls, drawn by an embedded renderer that needs nothing
//! installed: an orthographic view along a chosen direction, planes first (as ground),
//! then triangles sorted far to near (the painter's algorithm) and shaded by how
//! squarely they face the viewer, each wall outlined where its surface ends, in
//! ssdraw's colours with transparency as opacity; particles as discs; axes and a scale
//! bar. Several frames make an animated SVG (SMIL: one group per frame, shown in its own
//! slot of the cycle by an `<animate>` of at most three values, so that the file grows
//! linearly with the frames), which browsers play without script.

use crate::escape;
use crate::mesh::WallMesh;
use nalgebra::Vector3;
use std::fmt::Write as _;
use std::io;
use walls_geometry::Particle;
use walls_geometry::units::{Readout, number};
use walls_model::direction;

type Vec3 = Vector3<f64>;

/// Where the picture is seen from, and its size.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// The direction from the scene towards the viewer.
    pub from: Vec3,
    /// Which way is up in the picture (projected).
    pub up: Vec3,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

impl Default for View {
    /// From (1, −1.5, 1) with z up, 800 × 600: the walls' tops and two sides.
    fn default() -> Self {
        View {
            from: Vec3::new(1.0, -1.5, 1.0),
            up: Vec3::z(),
            width: 800,
            height: 600,
        }
    }
}

/// One picture's content: the walls and particles at one time.
#[derive(Debug, Clone, Copy)]
pub struct Frame<'a> {
    /// The time, shown in the corner.
    pub t: f64,
    /// The walls there.
    pub walls: &'a [WallMesh],
    /// The particles there.
    pub particles: &'a [Particle],
}

/// The projection: screen axes, scale and offset.
struct Camera {
    right: Vec3,
    up: Vec3,
    towards: Vec3,
    scale: f64,
    centre: (f64, f64),
    size: (f64, f64),
}

impl Camera {
    /// Fits the box `lo`–`hi` (and the particles' `centres`) into the view, with a margin.
    fn new(view: &View, lo: &Vec3, hi: &Vec3, centres: impl Iterator<Item = Vec3>) -> Camera {
        // Directions of any length: 1e308 along x is x (scaled first, not squared).
        let towards = direction(&view.from).unwrap_or_else(Vec3::z);
        let right = direction(&view.up)
            .unwrap_or_else(Vec3::z)
            .cross(&towards)
            .try_normalize(1e-12)
            .unwrap_or_else(|| towards.cross(&Vec3::x()).normalize());
        let up = towards.cross(&right);
        let mut points: Vec<Vec3> = (0..8)
            .map(|k| {
                Vec3::new(
                    if k & 1 == 0 { lo.x } else { hi.x },
                    if k & 2 == 0 { lo.y } else { hi.y },
                    if k & 4 == 0 { lo.z } else { hi.z },
                )
            })
            .collect();
        points.extend(centres);
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for p in &points {
            let (x, y) = (right.dot(p), up.dot(p));
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
        }
        let (w, h) = (f64::from(view.width), f64::from(view.height));
        let scale = (0.8 * w / (x1 - x0).max(1e-300)).min(0.8 * h / (y1 - y0).max(1e-300));
        Camera {
            right,
            up,
            towards,
            scale,
            centre: ((x0 + x1) / 2.0, (y0 + y1) / 2.0),
            size: (w, h),
        }
    }

    /// Screen coordinates (y down) of `p`.
    fn screen(&self, p: &Vec3) -> (f64, f64) {
        (
            self.size.0 / 2.0 + (self.right.dot(p) - self.centre.0) * self.scale,
            self.size.1 / 2.0 - (self.up.dot(p) - self.centre.1) * self.scale,
        )
    }
}

/// Something to draw, at a depth (larger is nearer).
enum Item {
    Triangle {
        points: [(f64, f64); 3],
        fill: String,
        opacity: f64,
    },
    Disc {
        centre: (f64, f64),
        radius: f64,
        fill: String,
    },
    /// A wall's outline: an edge of only one of its triangles.
    Edge {
        from: (f64, f64),
        to: (f64, f64),
        opacity: f64,
    },
}

/// The edges of `m` that belong to one triangle only: the outline of an open surface
/// (a disk's rims, a rectangle's sides, a cylinder's ends, a shell's opening).
fn outline(m: &crate::Mesh) -> Vec<(u32, u32)> {
    let mut count: std::collections::HashMap<(u32, u32), u32> = std::collections::HashMap::new();
    for [a, b, c] in &m.triangles {
        for (u, v) in [(*a, *b), (*b, *c), (*c, *a)] {
            *count.entry((u.min(v), u.max(v))).or_default() += 1;
        }
    }
    let mut edges: Vec<(u32, u32)> = count
        .into_iter()
        .filter(|(_, n)| *n == 1)
        .map(|(e, _)| e)
        .collect();
    edges.sort_unstable();
    edges
}

/// The items of one frame, far to near.
fn items(camera: &Camera, frame: &Frame) -> Vec<(f64, Item)> {
    let mut out = Vec::new();
    for w in frame.walls {
        let Some(rgb) = w.rgb else { continue };
        let m = &w.mesh;
        for [a, b, c] in &m.triangles {
            let (a, b, c) = (
                m.positions[*a as usize],
                m.positions[*b as usize],
                m.positions[*c as usize],
            );
            let normal = (b - a)
                .cross(&(c - a))
                .try_normalize(0.0)
                .unwrap_or_else(Vec3::z);
            let light = 0.35 + 0.65 * normal.dot(&camera.towards).abs();
            // Planes are drawn first, as the ground they usually are: their two huge
            // triangles have no useful depth for the painter's sort.
            let depth = if w.wall_type == walls_keywords::WallType::Plane {
                f64::NEG_INFINITY
            } else {
                camera.towards.dot(&((a + b + c) / 3.0))
            };
            out.push((
                depth,
                Item::Triangle {
                    points: [camera.screen(&a), camera.screen(&b), camera.screen(&c)],
                    fill: shade(rgb, light),
                    opacity: w.opacity,
                },
            ));
        }
    }
    for w in frame.walls.iter().filter(|w| w.rgb.is_some()) {
        let m = &w.mesh;
        let plane = w.wall_type == walls_keywords::WallType::Plane;
        for (a, b) in outline(m) {
            let (a, b) = (m.positions[a as usize], m.positions[b as usize]);
            // Just in front of the triangles it bounds.
            let depth = if plane {
                f64::NEG_INFINITY
            } else {
                // A millionth of a pixel: in the scene's own length, whatever its scale.
                camera.towards.dot(&((a + b) / 2.0)) + 1e-6 / camera.scale
            };
            out.push((
                depth,
                Item::Edge {
                    from: camera.screen(&a),
                    to: camera.screen(&b),
                    opacity: w.opacity,
                },
            ));
        }
    }
    for p in frame.particles {
        // ssdraw's colour, a stuck particle's its wall's; mid grey for one ssdraw refuses.
        let wall_colour = |w: usize| frame.walls.iter().find(|m| m.wall == w).map(|m| m.color);
        let rgb = crate::palette::particle(i64::from(p.color), wall_colour)
            .and_then(crate::palette::rgb)
            .unwrap_or([0.5; 3]);
        out.push((
            camera.towards.dot(&p.pos) + p.radius,
            Item::Disc {
                centre: camera.screen(&p.pos),
                radius: p.radius * camera.scale,
                fill: shade(rgb, 1.0),
            },
        ));
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out
}

/// A colour darkened by `light` (0–1), as CSS. (Each triangle is also stroked in its
/// fill, a pixel wide, so that anti-aliasing leaves no light seams between triangles.)
fn shade(rgb: [f64; 3], light: f64) -> String {
    let byte = |x: f64| (x * light * 255.0).round().clamp(0.0, 255.0) as u8;
    format!(
        "#{:02x}{:02x}{:02x}",
        byte(rgb[0]),
        byte(rgb[1]),
        byte(rgb[2])
    )
}

/// The drawing of one frame's items, as SVG elements.
fn draw(camera: &Camera, frame: &Frame, readout: &Readout) -> String {
    let mut s = String::new();
    for (_, item) in items(camera, frame) {
        match item {
            Item::Triangle {
                points,
                fill,
                opacity,
            } => {
                let _ = write!(s, "<polygon points=\"");
                for (x, y) in points {
                    let _ = write!(s, "{x:.2},{y:.2} ");
                }
                let _ = write!(
                    s,
                    "\" fill=\"{fill}\" stroke=\"{fill}\" stroke-width=\"1\" stroke-linejoin=\"round\""
                );
                if opacity < 1.0 {
                    let _ = write!(
                        s,
                        " fill-opacity=\"{opacity:.3}\" stroke-opacity=\"{opacity:.3}\""
                    );
                }
                s.push_str("/>\n");
            }
            Item::Edge { from, to, opacity } => {
                let _ = writeln!(
                    s,
                    "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"#333333\" stroke-width=\"1.2\" stroke-opacity=\"{opacity:.3}\"/>",
                    from.0, from.1, to.0, to.1
                );
            }
            Item::Disc {
                centre,
                radius,
                fill,
            } => {
                let _ = writeln!(
                    s,
                    "<circle class=\"particle\" cx=\"{:.2}\" cy=\"{:.2}\" r=\"{:.2}\" fill=\"{fill}\" stroke=\"#000\" stroke-width=\"0.5\"/>",
                    centre.0,
                    centre.1,
                    radius.max(0.5)
                );
            }
        }
    }
    let _ = writeln!(
        s,
        "<text x=\"10\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">t = {}</text>",
        escape(&readout.time(frame.t))
    );
    s
}

/// The axes (bottom left) and a scale bar (bottom right) of a round length near a
/// fifth of the width, round in `readout`'s length unit and labelled in it.
fn furniture(camera: &Camera, readout: &Readout) -> String {
    let mut s = String::new();
    let (ox, oy) = (50.0, camera.size.1 - 50.0);
    for (axis, name, colour) in [
        (Vec3::x(), "x", "#d62728"),
        (Vec3::y(), "y", "#2ca02c"),
        (Vec3::z(), "z", "#1f77b4"),
    ] {
        let (dx, dy) = (camera.right.dot(&axis) * 30.0, -camera.up.dot(&axis) * 30.0);
        let _ = writeln!(
            s,
            "<line x1=\"{ox}\" y1=\"{oy}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"{colour}\" stroke-width=\"2\"/><text x=\"{:.1}\" y=\"{:.1}\" font-family=\"sans-serif\" font-size=\"12\" fill=\"{colour}\">{name}</text>",
            ox + dx,
            oy + dy,
            ox + dx * 1.25,
            oy + dy * 1.25
        );
    }
    let unit = &readout.scale.length;
    let target = unit.of(camera.size.0 / 5.0 / camera.scale);
    let decade = 10f64.powf(target.log10().floor());
    let shown = [5.0, 2.0, 1.0]
        .iter()
        .map(|m| m * decade)
        .find(|l| *l <= target)
        .unwrap_or(decade);
    // The bar's length in pkdgrav units, and its label.
    let length = shown / unit.per_pkdgrav;
    let label = escape(&if readout.with_pkdgrav && !unit.name.is_empty() {
        format!("{} {}", number(shown), unit.name)
    } else {
        readout.length(length)
    });
    let pixels = length * camera.scale;
    let (x1, y) = (camera.size.0 - 30.0, camera.size.1 - 30.0);
    let _ = writeln!(
        s,
        "<g class=\"scale\"><line x1=\"{:.1}\" y1=\"{y}\" x2=\"{x1}\" y2=\"{y}\" stroke=\"#000\" stroke-width=\"3\"/><text x=\"{:.1}\" y=\"{:.1}\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\">{label}</text></g>",
        x1 - pixels,
        x1 - pixels / 2.0,
        y - 8.0
    );
    s
}

/// Writes `frames` as one SVG: a still picture for one frame, an animation playing the
/// frames in turn over `seconds` for several. The view fits the box `lo`–`hi`; times
/// and the scale bar are shown as `readout` says. A frame with a number that cannot be
/// drawn ([`crate::finite`]) is refused with nothing written, as an
/// [`io::ErrorKind::InvalidData`] error holding its [`crate::finite::NotDrawable`].
/// The text goes to `out` a frame at a time, never held whole.
pub fn write(
    out: &mut impl io::Write,
    frames: &[Frame],
    view: &View,
    bounds: (Vec3, Vec3),
    seconds: f64,
    readout: &Readout,
) -> io::Result<()> {
    let camera = camera(frames, view, &bounds)?;
    render(out, &camera, frames, view, seconds, readout)
}

/// The SVG [`write()`] writes, or the first number of `frames` (or of the box) it cannot
/// draw.
pub fn document(
    frames: &[Frame],
    view: &View,
    bounds: (Vec3, Vec3),
    seconds: f64,
    readout: &Readout,
) -> Result<String, crate::finite::NotDrawable> {
    let camera = camera(frames, view, &bounds)?;
    let mut bytes = Vec::new();
    render(&mut bytes, &camera, frames, view, seconds, readout)
        .expect("writing to a Vec does not fail");
    Ok(String::from_utf8(bytes).expect("the SVG is written from strings"))
}

/// The camera fitting `bounds` and every frame's particles into `view`, once every
/// number of `frames` and of the box is checked drawable.
fn camera(
    frames: &[Frame],
    view: &View,
    bounds: &(Vec3, Vec3),
) -> Result<Camera, crate::finite::NotDrawable> {
    let n = frames.len();
    for (k, f) in frames.iter().enumerate() {
        crate::finite::check_frame(f.t, f.walls, f.particles).map_err(|e| {
            crate::finite::NotDrawable {
                frame: (n > 1).then_some((k + 1, n)),
                ..e
            }
        })?;
    }
    crate::finite::check_box(bounds, frames.first().map_or(0.0, |f| f.t))?;
    let centres = frames
        .iter()
        .flat_map(|f| f.particles.iter().map(|p| p.pos));
    Ok(Camera::new(view, &bounds.0, &bounds.1, centres))
}

/// Writes the SVG of `frames` through `camera` to `out`, a frame at a time. Several
/// frames animate: each frame's group is shown only during its own n-th of the cycle,
/// by an `<animate>` of three values at most (hidden, shown, hidden), so that the file
/// grows linearly with the frames (an animation listing every frame in every frame's
/// `<animate>` grew with their square: 10,000 frames of one particle made 1.4 GB).
fn render(
    out: &mut impl io::Write,
    camera: &Camera,
    frames: &[Frame],
    view: &View,
    seconds: f64,
    readout: &Readout,
) -> io::Result<()> {
    writeln!(
        out,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>",
        w = view.width,
        h = view.height
    )?;
    if let [frame] = frames {
        out.write_all(b"<g class=\"frame\">\n")?;
        out.write_all(draw(camera, frame, readout).as_bytes())?;
        out.write_all(b"</g>\n")?;
    } else {
        let n = frames.len();
        let at = |k: usize| format!("{:.6}", k as f64 / n as f64);
        for (k, frame) in frames.iter().enumerate() {
            // Shown from k/n to (k + 1)/n of the cycle (discrete keyTimes start at 0).
            let (values, times) = match k {
                0 => ("inline;none", format!("0;{}", at(1))),
                _ if k + 1 == n => ("none;inline", format!("0;{}", at(k))),
                _ => ("none;inline;none", format!("0;{};{}", at(k), at(k + 1))),
            };
            writeln!(
                out,
                "<g class=\"frame\" display=\"{}\">\n<animate attributeName=\"display\" values=\"{values}\" keyTimes=\"{times}\" dur=\"{seconds}s\" calcMode=\"discrete\" repeatCount=\"indefinite\"/>",
                if k == 0 { "inline" } else { "none" },
            )?;
            out.write_all(draw(camera, frame, readout).as_bytes())?;
            out.write_all(b"</g>\n")?;
        }
    }
    out.write_all(furniture(camera, readout).as_bytes())?;
    out.write_all(b"</svg>\n")
}
