//! POV-Ray scenes of walls files, after ssdraw's conventions (docs/spec.md §3 "Drawing"):
//!
//! - each wall as a POV-Ray primitive where it has one: a plane as a large thin square
//!   (a `box` twice the scene's size across, as [`crate::mesh`]'s squares), a triangle as
//!   a `triangle`, a rectangle as a `polygon`, a disk as a `disc` with its hole, a finite
//!   cylinder as an open `cone` from R at −length/2 to R(1 − taper) at +length/2, an
//!   infinite cylinder as an open `cylinder` twice the scene's size long, a shell as a
//!   `sphere` minus a slightly smaller one minus the cap within `open-angle` of its axis;
//! - ssdraw's palette ([`crate::palette`]): colours 0–15 by the names `walls.inc`
//!   declares for them (`SsdrawBlack` … `SsdrawNavy`, ssdraw's values, not those of
//!   POV-Ray's `colors.inc`), 16–255 greys `rgb <l, l, l>` with l = ⌊255·(c − 16)/239⌋/255;
//!   walls of colour 0 are not drawn; a wall's transparency is its `transmit`;
//! - particles are spheres in their colour (0 black, as ssdraw draws them; −1 − w, a
//!   particle stuck to wall w, in the wall's colour; any other colour not drawn);
//! - a camera looking at the box around the walls and particles from a [`View`]'s
//!   direction, a light over its shoulder, a dim one at the camera, and a background.
//! - like ssdraw's "Renormalize?", every coordinate written as (p − centre)/size of
//!   the scene's box, so that POV-Ray sees numbers near 1 at any scale (a 5 cm tube in
//!   AU is 3.7e-13 long, below POV-Ray's tolerances); the scene's first comment says so.
//!
//! The styles are macros of an include file of our own, [`INCLUDE`] (`walls.inc`):
//! `PlaneStyle(Colour, Transmit)`, … `ShellStyle`, all drawing `WallPlain` unless
//! edited, and `ParticleStyle(Colour)`. [`write`] and [`write_frame`] write a scene; with
//! `walls.inc` beside it (`walls-sim preview --out scene.pov` writes both),
//! `povray +I scene.pov +O scene.png +W640 +H480 -D +A` renders it.

use crate::finite::{NotDrawable, Subject};
use crate::palette;
use nalgebra::Vector3;
use std::collections::BTreeMap;
use std::io::{self, Write};
use walls_geometry::Particle;
use walls_geometry::mesh::basis;
use walls_geometry::shape::{Disk, FiniteCylinder, InfiniteCylinder, Rectangle, Shell, Triangle};
use walls_geometry::{Shape, decode, scene_bounds};
use walls_model::{Scene, direction};

type Vec3 = Vector3<f64>;

/// The include file every scene includes: the wall and particle styles.
pub const INCLUDE: &str = include_str!("walls.inc");

/// Its name, as the scenes include it.
pub const INCLUDE_NAME: &str = "walls.inc";

/// Where the camera looks from and what the picture is like.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// From the centre of the scene towards the camera (any length; z is up unless this
    /// is along z).
    pub from: Vec3,
    /// Horizontal field of view, degrees.
    pub angle: f64,
    /// Width over height of the picture to be rendered.
    pub aspect: f64,
    /// The background's red, green and blue from 0 to 1.
    pub background: [f64; 3],
    /// Where the camera is and the point it looks at, in the scene's coordinates
    /// (ssdraw's `Camera position` and `Camera look-at`); `None`: from `from`, far
    /// enough to see the whole scene.
    pub camera: Option<(Vec3, Vec3)>,
    /// The picture's up (POV-Ray's `sky`); `None`: z, or y when looking along z.
    pub sky: Option<Vec3>,
}

impl Default for View {
    /// From (1, −1.5, 1), 40° across, 4:3, on a dark slate background.
    fn default() -> Self {
        View {
            from: Vec3::new(1.0, -1.5, 1.0),
            angle: 40.0,
            aspect: 4.0 / 3.0,
            background: [0.12, 0.14, 0.18],
            camera: None,
            sky: None,
        }
    }
}

/// Writes one frame of a movie of `scene` to `out`: each wall where the frame places it
/// (reactive walls as a run turned them), its particles, framed by `bounds` (the movie's
/// box, the same for every frame). Like [`write`], it includes [`INCLUDE_NAME`]. A number
/// that cannot be drawn ([`crate::finite`]) is refused before anything is written, as an
/// [`io::ErrorKind::InvalidData`] error holding its [`crate::finite::NotDrawable`].
pub fn write_frame(
    out: &mut impl Write,
    scene: &Scene,
    frame: &crate::MovieFrame,
    bounds: (Vec3, Vec3),
    view: &View,
) -> io::Result<()> {
    crate::finite::check(std::slice::from_ref(frame))?;
    let walls = decode(scene);
    // The frame's walls by index, looked up once each (a hull of 10⁴ triangles).
    let placed: BTreeMap<usize, &crate::WallMesh> =
        frame.walls.iter().map(|m| (m.wall, m)).collect();
    let shapes = walls
        .iter()
        .map(|w| match placed.get(&w.index) {
            Some(m) => w.shape.turned(m.origin, &m.turn),
            None => w.shape.at(w.motion.position_or_origin(frame.t)),
        })
        .collect();
    let framing = framing(bounds, frame.t, view).map_err(|e| NotDrawable {
        step: frame.step,
        ..e
    })?;
    write_shapes(out, &walls, shapes, frame.t, &frame.particles, &framing)
}

/// Writes the POV-Ray scene of `scene` at time `t` with `particles` seen from `view`; it
/// includes `walls.inc` ([`INCLUDE`]), which must be beside it (or on POV-Ray's `+L`
/// path) to render. A number that cannot be drawn is refused before anything is
/// written, as [`write_frame`] says.
pub fn write(
    out: &mut impl Write,
    scene: &Scene,
    t: f64,
    particles: &[Particle],
    view: &View,
) -> io::Result<()> {
    let (walls, shapes, framing) = still(scene, t, particles, view)?;
    write_shapes(out, &walls, shapes, t, particles, &framing)
}

/// The walls of `scene` at `t` and their shapes there, framed with `particles` (the box
/// around the walls and the drawn particles), once [`crate::finite::check_frame`] has
/// passed the walls (tessellated) and the particles.
fn still(
    scene: &Scene,
    t: f64,
    particles: &[Particle],
    view: &View,
) -> io::Result<(Vec<walls_geometry::Wall>, Vec<Shape>, Framing)> {
    let walls = decode(scene);
    let drawn_particles: Vec<Particle> = particles
        .iter()
        .filter(|p| particle_colour(p, &walls).is_some())
        .cloned()
        .collect();
    let bounds = scene_bounds(&walls, &drawn_particles);
    let meshes = crate::wall_meshes_in(&walls, t, 8, &bounds);
    crate::finite::check_frame(t, &meshes, particles)?;
    let shapes = walls
        .iter()
        .map(|w| w.shape.at(w.motion.position_or_origin(t)))
        .collect();
    Ok((walls, shapes, framing(bounds, t, view)?))
}

/// How a scene is written: its box's centre and size, and the view in the renormalised
/// coordinates (p − centre)/size.
struct Framing {
    lo: Vec3,
    hi: Vec3,
    centre: Vec3,
    size: f64,
    view: View,
}

/// The framing of the box `bounds` seen from `view`: ssdraw's "Renormalize?", every
/// coordinate written as (p − centre)/size, so that POV-Ray sees numbers near 1 at any
/// scale (a 5 cm tube in AU is 3.7e-13 long, below POV-Ray's tolerances). A box, or a
/// camera renormalised, with a number that cannot be drawn is refused.
fn framing(bounds: (Vec3, Vec3), t: f64, view: &View) -> Result<Framing, NotDrawable> {
    crate::finite::check_box(&bounds, t)?;
    let (lo, hi) = bounds;
    let centre = (lo + hi) / 2.0;
    let size = (hi - lo).max();
    let size = if size > 0.0 && size.is_finite() {
        size
    } else {
        1.0
    };
    let unit = |p: &Vec3, part| {
        let q = (p - centre) / size;
        match q.iter().find(|x| !x.is_finite()) {
            Some(&value) => Err(NotDrawable {
                subject: Subject::View,
                part,
                value,
                t,
                step: None,
                frame: None,
            }),
            None => Ok(q),
        }
    };
    let camera = match view.camera {
        Some((at, to)) => Some((
            unit(&at, "its camera position, in units of the scene's size,")?,
            unit(&to, "its look-at point, in units of the scene's size,")?,
        )),
        None => None,
    };
    Ok(Framing {
        lo,
        hi,
        centre,
        size,
        view: View {
            camera,
            ..view.clone()
        },
    })
}

/// Writes the scene of `walls` drawn as `shapes` (each wall's shape where it is) at `t`,
/// with `particles`, as `framing` says.
fn write_shapes(
    out: &mut impl Write,
    walls: &[walls_geometry::Wall],
    shapes: Vec<Shape>,
    t: f64,
    particles: &[Particle],
    framing: &Framing,
) -> io::Result<()> {
    let Framing {
        lo,
        hi,
        centre,
        size,
        ref view,
    } = *framing;
    let unit = |p: &Vec3| (p - centre) / size;

    writeln!(
        out,
        "// Walls at t = {t}, written by walls-preview (ssdraw's conventions)."
    )?;
    writeln!(out, "#version 3.7;")?;
    writeln!(out, "global_settings {{ assumed_gamma 1.0 }}")?;
    writeln!(out, "#include \"{INCLUDE_NAME}\"")?;
    writeln!(
        out,
        "// Renormalised: coordinates are (x - <{}, {}, {}>) / {}.",
        num(centre.x),
        num(centre.y),
        num(centre.z),
        num(size)
    )?;
    writeln!(out)?;
    camera(out, Vec3::zeros(), (hi - lo).norm() / size / 2.0, view)?;
    writeln!(out)?;
    for (i, (wall, shape)) in walls.iter().zip(&shapes).enumerate() {
        let color = wall.appearance.color;
        let kind = wall.shape.wall_type().name();
        let Some(colour) = colour(color).filter(|_| color != 0) else {
            writeln!(out, "// wall {i}: {kind}, colour {color}: not drawn")?;
            continue;
        };
        let transmit = wall.appearance.transparency.clamp(0.0, 1.0);
        writeln!(out, "// wall {i}: {kind}")?;
        match primitive(&shape.renormalised(&centre, size)) {
            Some((object, style)) => {
                writeln!(out, "{object}\n  {style}({colour}, {})\n}}", num(transmit))?
            }
            None => writeln!(out, "// (no area: not drawn)")?,
        }
    }
    if !particles.is_empty() {
        writeln!(out, "\n// Particles")?;
    }
    for p in particles {
        let index = particle_colour(p, walls);
        if let Some(colour) = index.and_then(colour).filter(|_| p.radius > 0.0) {
            writeln!(
                out,
                "sphere {{ {}, {} ParticleStyle({colour}) }}",
                vec(&unit(&p.pos)),
                num(p.radius / size)
            )?;
        }
    }
    Ok(())
}

/// The palette index particle `p` is drawn in (a stuck particle's, its wall's among
/// `walls`); `None`: not drawn (a colour ssdraw refuses).
fn particle_colour(p: &Particle, walls: &[walls_geometry::Wall]) -> Option<i64> {
    let wall_colour =
        |w: usize| (walls.iter().find(|wall| wall.index == w)).map(|wall| wall.appearance.color);
    palette::particle(p.color.into(), wall_colour)
}

/// The POV-Ray colour of ssdraw's colour `index`: the name `walls.inc` declares for
/// 0–15 (`SsdrawGold`), a grey `rgb <l, l, l>` for 16–255; `None` outside 0–255. (A
/// wall of colour 0 is not drawn; a particle of colour 0 is, black.)
pub fn colour(index: i64) -> Option<String> {
    match index {
        0..=15 => Some(format!("Ssdraw{}", palette::NAMES[index as usize])),
        16..=255 => {
            let [l, _, _] = palette::rgb(index)?;
            let l = num(l);
            Some(format!("rgb <{l}, {l}, {l}>"))
        }
        _ => None,
    }
}

/// A number as POV-Ray reads it (non-finite numbers as 0, rounded to 10 significant
/// digits to keep the scene readable).
fn num(x: f64) -> String {
    if !x.is_finite() {
        return "0".into();
    }
    let s = format!("{x:.9e}");
    let value: f64 = s.parse().unwrap_or(x);
    let plain = format!("{value}");
    if plain.len() <= 20 { plain } else { s }
}

fn vec(v: &Vec3) -> String {
    format!("<{}, {}, {}>", num(v.x), num(v.y), num(v.z))
}

/// The camera, looking at `centre` from `view.from` far enough for the sphere of
/// `radius` around it to fit, and the lights.
fn camera(out: &mut impl Write, centre: Vec3, radius: f64, view: &View) -> io::Result<()> {
    let dir = view
        .camera
        .and_then(|(at, to)| direction(&(at - to)))
        .or_else(|| direction(&view.from))
        .unwrap_or_else(|| View::default().from.normalize());
    let sky = match view.sky.and_then(|s| direction(&s)) {
        Some(s) => s,
        None if dir.cross(&Vec3::z()).norm() > 1e-6 => Vec3::z(),
        None => Vec3::y(),
    };
    let aspect = if view.aspect.is_finite() && view.aspect > 0.0 {
        view.aspect
    } else {
        4.0 / 3.0
    };
    let angle = if view.angle.is_finite() && view.angle > 0.0 && view.angle < 180.0 {
        view.angle
    } else {
        40.0
    };
    let half_h = (angle / 2.0).to_radians();
    let half_v = (half_h.tan() / aspect).atan();
    let distance = 1.05 * radius.max(1e-9) / half_h.min(half_v).sin();
    let (location, centre) = match view.camera {
        Some((at, to)) => (at, to),
        None => (centre + dir * distance, centre),
    };
    let [r, g, b] = view.background.map(|c| if c.is_finite() { c } else { 0.0 });
    // The picture's right: forward × sky, for a light over the camera's right shoulder.
    let right = direction(&(-dir).cross(&sky)).unwrap_or_else(Vec3::x);
    let key = centre + (dir + sky * 0.8 + right * 0.5) * distance * 1.5;
    writeln!(
        out,
        "background {{ color rgb <{}, {}, {}> }}",
        num(r),
        num(g),
        num(b)
    )?;
    // `right -x` before `look_at`: a right-handed camera, as the walls' axes are.
    writeln!(
        out,
        "camera {{\n  location {}\n  up y\n  right -x * {}\n  sky {}\n  angle {}\n  look_at {}\n}}",
        vec(&location),
        num(aspect),
        vec(&sky),
        num(angle),
        vec(&centre)
    )?;
    writeln!(out, "light_source {{ {} color rgb <1, 1, 1> }}", vec(&key))?;
    writeln!(
        out,
        "light_source {{ {} color rgb <0.25, 0.25, 0.25> shadowless }}",
        vec(&location)
    )
}

/// The wall's object in renormalised coordinates (the scene's centre at 0, its size 1),
/// without its texture and closing brace, and its style macro; `None` for shapes of no
/// area.
fn primitive(shape: &Shape) -> Option<(String, &'static str)> {
    let axis = shape
        .axis()
        .and_then(|a| direction(&a))
        .unwrap_or_else(Vec3::z);
    let o = shape.origin();
    let v = vec;
    match *shape {
        Shape::Plane(_) => {
            // A square twice the scene's size across centred where the scene's centre
            // projects onto the plane, a thousandth of it thick: the box in the frame
            // (u, v, axis) moved there.
            let c = axis * axis.dot(&o);
            let (u, w) = basis(&axis);
            let (h, e) = (num(1.0), num(1e-3));
            let m = [u, w, axis, c].map(|x| format!("{}, {}, {}", num(x.x), num(x.y), num(x.z)));
            Some((
                format!(
                    "box {{ <-{h}, -{h}, -{e}>, <{h}, {h}, {e}>\n  matrix <{}, {}, {}, {}>",
                    m[0], m[1], m[2], m[3]
                ),
                "PlaneStyle",
            ))
        }
        Shape::Triangle(Triangle { e1: a, e2: b, .. }) => (a.cross(&b).norm() > 0.0).then(|| {
            (
                format!("triangle {{ {}, {}, {}", v(&o), v(&(o + a)), v(&(o + b))),
                "TriangleStyle",
            )
        }),
        Shape::Rectangle(Rectangle { e1: a, e2: b, .. }) => (a.cross(&b).norm() > 0.0).then(|| {
            (
                format!(
                    "polygon {{ 5, {}, {}, {}, {}, {}",
                    v(&o),
                    v(&(o + a)),
                    v(&(o + a + b)),
                    v(&(o + b)),
                    v(&o)
                ),
                "RectangleStyle",
            )
        }),
        Shape::Disk(Disk { radius, hole, .. }) => (radius > 0.0 && hole < radius).then(|| {
            (
                format!(
                    "disc {{ {}, {}, {}, {}",
                    v(&o),
                    v(&axis),
                    num(radius),
                    num(hole.max(0.0))
                ),
                "DiskStyle",
            )
        }),
        Shape::FiniteCylinder(FiniteCylinder {
            radius,
            length,
            taper,
            ..
        }) => {
            let top = (radius * (1.0 - taper)).max(0.0);
            (radius > 0.0 && length > 0.0).then(|| {
                let (a, b) = (o - axis * (length / 2.0), o + axis * (length / 2.0));
                let object = if top == radius {
                    format!("cylinder {{ {}, {}, {} open", v(&a), v(&b), num(radius))
                } else {
                    format!(
                        "cone {{ {}, {}, {}, {} open",
                        v(&a),
                        num(radius),
                        v(&b),
                        num(top)
                    )
                };
                (object, "CylinderStyle")
            })
        }
        Shape::InfiniteCylinder(InfiniteCylinder { radius, .. }) => (radius > 0.0).then(|| {
            let c = o - axis * axis.dot(&o);
            let (a, b) = (c - axis, c + axis);
            (
                format!("cylinder {{ {}, {}, {} open", v(&a), v(&b), num(radius)),
                "CylinderStyle",
            )
        }),
        Shape::Shell(Shell { radius, open, .. }) => {
            let open = open.to_degrees().clamp(0.0, 180.0);
            (radius > 0.0 && open < 180.0).then(|| (shell(o, axis, radius, open), "ShellStyle"))
        }
    }
}

/// A shell: the sphere minus one 1% smaller, minus the cap within `open` degrees of
/// `axis` (a cone from the centre up to 90°, a half-space at 90°; beyond, what is kept
/// is within 180° − `open` of −`axis`, an intersection with that cone).
fn shell(o: Vec3, axis: Vec3, radius: f64, open: f64) -> String {
    let sphere = |r: f64| format!("sphere {{ {}, {} }}", vec(&o), num(r));
    let spheres = format!("{}\n  {}", sphere(radius), sphere(radius * 0.99));
    // A cone from the centre along `dir`, of half-angle `half` (degrees, < 90), beyond
    // the sphere.
    let cone = |dir: Vec3, half: f64| {
        let length = radius * 1.01;
        let top = length * half.to_radians().tan();
        format!(
            "cone {{ {}, 0, {}, {} }}",
            vec(&o),
            vec(&(o + dir * length)),
            num(top)
        )
    };
    if open <= 0.0 {
        format!("difference {{\n  {spheres}")
    } else if (open - 90.0).abs() < 1e-9 {
        // Inside this plane is axis · (p − o) > 0: the half with the opening.
        let plane = format!("plane {{ {}, {} }}", vec(&-axis), num(-axis.dot(&o)));
        format!("difference {{\n  {spheres}\n  {plane}")
    } else if open < 90.0 {
        format!("difference {{\n  {spheres}\n  {}", cone(axis, open))
    } else {
        format!(
            "intersection {{\n  difference {{ {spheres} }}\n  {}",
            cone(-axis, 180.0 - open)
        )
    }
}
