//! An interactive, self-contained HTML page of a scene or a movie (docs/spec.md §2
//! `walls-sim preview`): three.js draws the walls in ssdraw's colours (colour 0 not
//! drawn) and the particles as spheres in their ssdraw colours (0 black); a slider steps through
//! the frames, a play button runs through them, the mouse orbits the camera, and hovering
//! a wall shows its type, index and tokens.
//!
//! The page needs no network: the viewer, three.js and its OrbitControls come bundled in
//! one script (`assets/viewer.bundle.js`, built by `web/bundle.sh` from the npm packages
//! locked in `web/package-lock.json` and committed) and the movie is JSON in the page.
//! Where the browser has no WebGL the page shows why and what to do, and the SVG that
//! [`crate::svg`] draws of the frame asked for (every frame, or as many as
//! fit in [`FALLBACK_BYTES`], evenly spaced).
//!
//! [`write_movie`] writes frames ([`MovieFrame`]); [`write`] builds frames of a scene
//! (walls where their motion puts them at evenly spaced times, particles from
//! [`Particles`]) and writes them the same way. Every position is written relative to
//! the centre of the box around the whole movie and in units of its size, so that the
//! viewer works with numbers near 1 whatever the file's length unit (a scene in
//! centimetres converted to AU is 1e-13 across; `f32` would lose a 1e-13 offset added
//! to a 1e-13 centre). Walls are drawn from the first frame's meshes and moved in each
//! frame rigidly: turned by `turn_k · turn_0ᵀ` about their first origin and moved to
//! their origin then (a wall that never turns is written about the centre of its mesh,
//! moved as its origin moves). Between frames the page interpolates positions linearly
//! and takes each wall's turn from the nearest frame. Particles are matched across frames by
//! [`Particle::index`]; one missing from a frame is not drawn in it.
//!
//! The URL's fragment sets the initial time (`page.html#t=0.25`) and can hover a point
//! (`#hover=0.5,0.5`, as fractions of the canvas's width and height);
//! `window.wallsPreview` offers `setTime(t)`, `time()`, `setFrame(k)`, `frame()`,
//! `frames`, `play()`, `pause()` and `hoverAt(x, y)` (client pixels) once `ready`, and
//! `document.body.dataset` has `ready`, `time` and `frame`, for tests and scripts.

use crate::mesh::wall_meshes_in;
use crate::{MovieFrame, WallMesh, escape, palette};
use nalgebra::{Rotation3, UnitQuaternion, Vector3};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io;
use walls_geometry::units::{Readout, System, Unit};
use walls_geometry::{Particle, decode, scene_bounds_at};
use walls_keywords::Keyword;
use walls_model::{Scene, Value, Wall};

type Vec3 = Vector3<f64>;

/// The viewer with three.js, as `web/bundle.sh` builds it.
const BUNDLE: &str = include_str!("../assets/viewer.bundle.js");

/// Segments around round shapes.
const SEGMENTS: usize = 64;

/// Particles along their trajectories.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Particles {
    /// Each particle's radius.
    pub radii: Vec<f64>,
    /// Each particle's ssdraw colour (0 black; −1 − w, stuck to wall w, the wall's; any
    /// other colour outside 0–255, or a missing entry, draws it in light grey).
    pub colors: Vec<i64>,
    /// The time of each frame, increasing.
    pub times: Vec<f64>,
    /// Each frame's positions: `frames[k][i]` is particle i at `times[k]` (between frames
    /// the page interpolates linearly; a particle a frame lacks is not drawn in it).
    pub frames: Vec<Vec<Vec3>>,
}

/// How a movie is shown.
#[derive(Debug, Clone, PartialEq)]
pub struct MovieOptions {
    /// How times and lengths are labelled (the time label reads `t = ` and
    /// [`Readout::time`]).
    pub readout: Readout,
    /// Draw the path of each particle over its last this many frames as a line.
    pub trails: Option<usize>,
    /// The page's title.
    pub title: String,
}

/// Writes the page: the walls of `scene` (and `particles`, if given) over times 0 to
/// `t_end`, as a movie of `frames` evenly spaced frames (at least two; one frame, or
/// `t_end` ≤ 0, shows t = 0 only), each wall where its motion puts it and each particle
/// interpolated linearly between the times of `particles`. Times are labelled as a
/// picture labels them by default ([`Readout::picture`] of [`System::Auto`]: in seconds
/// when the file sets units).
pub fn write(
    out: &mut impl io::Write,
    scene: &Scene,
    particles: Option<&Particles>,
    t_end: f64,
    frames: usize,
) -> io::Result<()> {
    let t_end = if t_end.is_finite() && t_end > 0.0 {
        t_end
    } else {
        0.0
    };
    let n = if t_end > 0.0 { frames.max(2) } else { 1 };
    let times: Vec<f64> = (0..n)
        .map(|k| {
            if n > 1 {
                t_end * k as f64 / (n - 1) as f64
            } else {
                0.0
            }
        })
        .collect();
    let at: Vec<Vec<Particle>> = times
        .iter()
        .map(|&t| particles.map_or_else(Vec::new, |p| particles_at(p, t)))
        .collect();
    let all: Vec<Particle> = at.iter().flatten().cloned().collect();
    let walls = decode(scene);
    let scene_box = scene_bounds_at(&walls, &all, &times);
    let movie: Vec<MovieFrame> = times
        .iter()
        .zip(at)
        .map(|(&t, particles)| MovieFrame {
            t,
            step: None,
            walls: wall_meshes_in(&walls, t, SEGMENTS, &scene_box),
            particles,
        })
        .collect();
    let options = MovieOptions {
        readout: Readout::picture(System::Auto, &scene.units),
        trails: None,
        title: "walls preview".to_string(),
    };
    write_movie(out, scene, &movie, &options)
}

/// The particles of `p` at time `t`: each interpolated linearly between the frames
/// around `t` (the first or last frame outside them); one that either frame lacks is
/// taken from the nearer frame, and left out if that frame lacks it too.
fn particles_at(p: &Particles, t: f64) -> Vec<Particle> {
    let n = p.frames.len();
    if n == 0 {
        return Vec::new();
    }
    let time = |k: usize| p.times.get(k).copied().unwrap_or(0.0);
    // The frames k and k + 1 around t, and the fraction f of the way from one to the next.
    let k = (0..n.saturating_sub(1))
        .rfind(|&k| time(k) <= t)
        .unwrap_or(0);
    let next = (k + 1).min(n - 1);
    let span = time(next) - time(k);
    let f = if span > 0.0 {
        ((t - time(k)) / span).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let count = p.frames.iter().map(Vec::len).max().unwrap_or(0);
    (0..count)
        .filter_map(|i| {
            let pos = match (p.frames[k].get(i), p.frames[next].get(i)) {
                (Some(a), Some(b)) => a + (b - a) * f,
                (Some(a), None) if f < 0.5 => *a,
                (None, Some(b)) if f >= 0.5 => *b,
                _ => return None,
            };
            let radius = p.radii.get(i).copied().unwrap_or(0.0);
            let mut particle = Particle::at_rest(radius, pos, i);
            particle.color = p
                .colors
                .get(i)
                .and_then(|&c| i32::try_from(c).ok())
                // None: light grey, as a colour outside ssdraw's palette.
                .unwrap_or(i32::MIN);
            Some(particle)
        })
        .collect()
}

/// Writes the page of a movie: `frames` (in increasing time) of `scene`'s walls and the
/// particles, shown as `options` says. No frames give a page of an empty scene. A frame
/// with a number that cannot be drawn ([`crate::finite::check`]) is refused before
/// anything is written, as an [`io::ErrorKind::InvalidData`] error holding its
/// [`crate::finite::NotDrawable`].
pub fn write_movie(
    out: &mut impl io::Write,
    scene: &Scene,
    frames: &[MovieFrame],
    options: &MovieOptions,
) -> io::Result<()> {
    crate::finite::check(frames)?;
    let json = data(scene, frames, options);
    let (shown, picture) = fallback(frames, &options.readout)?;
    let shown: Vec<String> = shown.iter().map(usize::to_string).collect();
    let bundle = script_safe(BUNDLE);
    let title = escape(&options.title);
    write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title}</title>\n<style>{STYLE}</style>\n\
         <noscript><style>#no-webgl{{display:block}}</style></noscript>\n</head>\n<body>\n\
         <div id=\"no-webgl\" hidden>\n<p id=\"no-webgl-message\">{NO_WEBGL}</p>\n\
         <div id=\"no-webgl-picture\" data-frames=\"{}\" data-of=\"{}\">\n",
        shown.join(","),
        frames.len().max(1)
    )?;
    out.write_all(picture.as_bytes())?;
    write!(
        out,
        "</div>\n</div>\n<script id=\"walls-data\" type=\"application/json\">"
    )?;
    out.write_all(json.as_bytes())?;
    write!(
        out,
        "</script>\n<script>{bundle}</script>\n</body>\n</html>\n"
    )
}

/// What the page says where it cannot draw with WebGL, above the SVG picture; the
/// viewer fills in why (`#no-webgl-reason`) and which frame is shown
/// (`#no-webgl-frame`).
const NO_WEBGL: &str = "<b>This page draws the walls with WebGL, which this browser does \
not offer here</b> (<span id=\"no-webgl-reason\">WebGL, or JavaScript, is turned off: \
a headless browser, a remote desktop or a machine without a graphics processor</span>). \
Below is the same scene as an SVG picture, drawn by the code of <code>walls-sim preview \
FILE --out picture.svg</code>, seen from (1, &minus;1.5, 1). To turn the scene, hover \
its walls and play its frames, open this page in a browser with WebGL (on your own \
desktop, say); or draw the picture you need with <code>walls-sim preview</code>: \
<code>--out picture.svg</code> (with <code>--view</code> and <code>--size</code>), \
<code>--out scene.pov</code> for POV-Ray or <code>--out scene.vtp</code> for ParaView. \
<span id=\"no-webgl-frame\"></span>";

/// The most bytes of SVG a page holds for browsers without WebGL: past the first
/// frame's picture, a movie's pictures stop here (docs/preview.md).
pub const FALLBACK_BYTES: usize = 1_000_000;

/// The frames drawn for a browser without WebGL and their SVG (its XML declaration
/// left out, for the page): every frame when their pictures fit in [`FALLBACK_BYTES`];
/// else as many as fit, evenly spaced from the first to the last (the size of a
/// frame's picture taken as the larger of the first's and the last's); at least the
/// first. Several frames make one SVG with a group per frame, as `--out movie.svg`
/// does, which the viewer shows one at a time (and which plays by itself where
/// scripts are off).
fn fallback(frames: &[MovieFrame], readout: &Readout) -> io::Result<(Vec<usize>, String)> {
    let (lo, hi, _, _) = frame_box(frames);
    let view = crate::svg::View::default();
    let drawn = |ks: &[usize]| -> io::Result<String> {
        let frames: Vec<crate::svg::Frame> = ks
            .iter()
            .map(|&k| crate::svg::Frame {
                t: frames[k].t,
                walls: &frames[k].walls,
                particles: &frames[k].particles,
            })
            .collect();
        let seconds = (ks.len() as f64 / 10.0).max(10.0);
        let svg = crate::svg::document(&frames, &view, (lo, hi), seconds, readout)?;
        Ok(match svg.split_once('\n') {
            Some((declaration, rest)) if declaration.starts_with("<?xml") => rest.to_string(),
            _ => svg,
        })
    };
    let n = frames.len();
    if n == 0 {
        return Ok((Vec::new(), drawn(&[])?));
    }
    let first = drawn(&[0])?;
    if n == 1 {
        return Ok((vec![0], first));
    }
    let each = first.len().max(drawn(&[n - 1])?.len()).max(1);
    let fit = (FALLBACK_BYTES / each).clamp(1, n);
    if fit == 1 {
        return Ok((vec![0], first));
    }
    let mut ks: Vec<usize> = (0..fit)
        .map(|j| (j as f64 * (n - 1) as f64 / (fit - 1) as f64).round() as usize)
        .collect();
    ks.dedup();
    let svg = drawn(&ks)?;
    Ok((ks, svg))
}

const STYLE: &str = "html,body{margin:0;height:100%;overflow:hidden;background:#20232a;\
font:13px system-ui,sans-serif;color:#e8e8e8}canvas{display:block}\
#info{position:fixed;top:8px;left:10px;opacity:.8;pointer-events:none}\
#controls{position:fixed;left:10px;right:10px;bottom:10px;display:flex;gap:10px;\
align-items:center;background:rgba(0,0,0,.45);padding:6px 10px;border-radius:6px}\
#controls input{flex:1}#controls button{min-width:2.6em}\
#time-label{font-variant-numeric:tabular-nums;min-width:12em}\
#tooltip{position:fixed;background:rgba(0,0,0,.8);padding:6px 8px;border-radius:4px;\
pointer-events:none;white-space:nowrap;font:12px ui-monospace,monospace}\
#tooltip .key{color:#9cdcfe}\
#no-webgl{position:fixed;inset:0;overflow:auto;padding:10px 16px;box-sizing:border-box;\
line-height:1.45}#no-webgl p{max-width:60em;margin:0 0 10px}#no-webgl code{color:#9cdcfe}\
#no-webgl svg{display:block;max-width:100%;height:auto}\
#no-webgl-controls{display:flex;gap:10px;align-items:center;max-width:800px;margin:0 0 8px}\
#no-webgl-controls input{flex:1}";

/// `js` made safe inside a `<script>` element: no `</script` or `<!--` (each escaped
/// with a backslash, which means the same in JavaScript's strings and regular
/// expressions, where alone they can occur).
fn script_safe(js: &str) -> String {
    js.replace("</script", "<\\/script")
        .replace("</SCRIPT", "<\\/SCRIPT")
        .replace("<!--", "<\\!--")
}

/// A JSON number: shortest round-trip of the value as an `f32` (as the page draws), 0
/// for values that are not finite.
fn num(s: &mut String, x: f64) {
    let x = x as f32;
    if x.is_finite() {
        let _ = write!(s, "{x}");
    } else {
        s.push('0');
    }
}

/// A JSON array of `items`, each written by `item`.
fn array<T>(
    s: &mut String,
    items: impl IntoIterator<Item = T>,
    mut item: impl FnMut(&mut String, T),
) {
    s.push('[');
    for (i, x) in items.into_iter().enumerate() {
        if i > 0 {
            s.push(',');
        }
        item(s, x);
    }
    s.push(']');
}

/// A JSON array of numbers as [`num`] writes them.
fn nums(s: &mut String, xs: impl IntoIterator<Item = f64>) {
    array(s, xs, num);
}

/// A JSON string, with `<` escaped so that it cannot close the script element.
fn string(s: &mut String, text: &str) {
    s.push('"');
    for c in text.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            '<' => s.push_str("\\u003c"),
            c if (c as u32) < 0x20 => {
                let _ = write!(s, "\\u{:04x}", c as u32);
            }
            c => s.push(c),
        }
    }
    s.push('"');
}

/// A value as written in a walls file.
fn token(value: &Value) -> String {
    match value {
        Value::Number(x) => format!("{x}"),
        Value::Integer(i) => format!("{i}"),
        Value::Vector(v) => format!("{} {} {}", v.x, v.y, v.z),
        Value::Type(t) => t.name().to_string(),
    }
}

/// The tokens a hover shows: the origin and, for walls that have one, the orient
/// (always), then every other token the wall sets, in the order set.
fn tokens(wall: &Wall) -> Vec<(&'static str, String)> {
    let mut shown: Vec<(&'static str, String)> = Vec::new();
    let mut always = vec![Keyword::Origin];
    if Keyword::Orient.applies_to().contains(wall.wall_type()) {
        always.push(Keyword::Orient);
    }
    for k in always {
        if let Some(v) = wall.value(k) {
            shown.push((k.name(), token(&v)));
        }
    }
    for (k, setting) in wall.settings.iter() {
        if *k != Keyword::Type && !shown.iter().any(|(name, _)| *name == k.name()) {
            shown.push((k.name(), token(&setting.value)));
        }
    }
    shown
}

/// A JSON number of full precision (`f64`'s shortest round-trip), 0 for values that are
/// not finite.
fn num64(s: &mut String, x: f64) {
    if x.is_finite() {
        let _ = write!(s, "{x:e}");
    } else {
        s.push('0');
    }
}

/// A coordinate in units of the scene's size, to five decimals (a hundred-thousandth of
/// the scene, far below a pixel): `-0.12345`, `0.5`, `0`.
fn coord(s: &mut String, x: f64) {
    let q = (x * 1e5).round();
    if !q.is_finite() || q == 0.0 || q.abs() > 1e15 {
        s.push('0');
        return;
    }
    let q = q as i64;
    if q < 0 {
        s.push('-');
    }
    let (whole, mut frac) = (q.unsigned_abs() / 100_000, q.unsigned_abs() % 100_000);
    let _ = write!(s, "{whole}");
    if frac > 0 {
        // The five decimals without their trailing zeros.
        let mut digits = 5;
        while frac % 10 == 0 {
            frac /= 10;
            digits -= 1;
        }
        let _ = write!(s, ".{frac:0digits$}");
    }
}

/// The points `xs` in units of the scene's size about its centre, to five decimals.
fn coords(s: &mut String, xs: impl IntoIterator<Item = Vec3>, centre: &Vec3, size: f64) {
    array(
        s,
        xs.into_iter()
            .flat_map(|x| <[f64; 3]>::from((x - centre) / size)),
        coord,
    );
}
/// The box around the movie: every drawn wall's mesh in every frame and every particle.
/// Its corners, centre and size (the longest side), a size of 1 for a box of none (a
/// point or nothing).
fn frame_box(frames: &[MovieFrame]) -> (Vec3, Vec3, Vec3, f64) {
    let mut lo = Vec3::repeat(f64::INFINITY);
    let mut hi = Vec3::repeat(f64::NEG_INFINITY);
    // Every number finite and within ±1e150: `write_movie` checked the frames.
    let mut add = |a: Vec3, b: Vec3| {
        lo = lo.inf(&a);
        hi = hi.sup(&b);
    };
    for frame in frames {
        for wm in frame.walls.iter().filter(|wm| wm.rgb.is_some()) {
            for q in &wm.mesh.positions {
                add(*q, *q);
            }
        }
        for p in &frame.particles {
            let r = Vec3::repeat(p.radius.abs());
            add(p.pos - r, p.pos + r);
        }
    }
    if lo.x > hi.x {
        // Nothing drawn.
        return (Vec3::zeros(), Vec3::zeros(), Vec3::zeros(), 1.0);
    }
    let centre = (lo + hi) / 2.0;
    let size = (hi - lo).max();
    let size = if size > 0.0 && size.is_finite() {
        size
    } else if centre.norm() > 0.0 {
        centre.norm()
    } else {
        1.0
    };
    (lo, hi, centre, size)
}

/// The centre of the box around `mesh`'s vertices; `None` for an empty mesh.
fn mesh_centre(mesh: &crate::Mesh) -> Option<Vec3> {
    let first = *mesh.positions.first()?;
    let (lo, hi) = mesh
        .positions
        .iter()
        .fold((first, first), |(lo, hi), p| (lo.inf(p), hi.sup(p)));
    Some((lo + hi) / 2.0)
}

/// One unit of a readout for the page: `[name, per pkdgrav unit]`.
fn unit(s: &mut String, unit: &Unit) {
    s.push('[');
    string(s, unit.name);
    s.push(',');
    num64(s, unit.per_pkdgrav);
    s.push(']');
}

/// The page's data (the format is described at the top of `web/viewer.js`).
fn data(scene: &Scene, frames: &[MovieFrame], options: &MovieOptions) -> String {
    let (_, _, centre, size) = frame_box(frames);
    let readout = &options.readout;
    let mut s = String::new();
    s.push_str("{\"times\":");
    array(&mut s, frames.iter().map(|f| f.t), num64);
    s.push_str(",\"steps\":");
    array(&mut s, frames, |s, f| match f.step {
        Some(step) => {
            let _ = write!(s, "{step}");
        }
        None => s.push_str("null"),
    });
    s.push_str(",\"readout\":{\"time\":");
    unit(&mut s, &readout.scale.time);
    s.push_str(",\"length\":");
    unit(&mut s, &readout.scale.length);
    let _ = write!(s, ",\"withPkdgrav\":{}}}", readout.with_pkdgrav);
    s.push_str(",\"centre\":");
    array(&mut s, centre.iter().copied(), num64);
    s.push_str(",\"size\":");
    num64(&mut s, size);
    s.push_str(",\"sizeLabel\":");
    string(&mut s, &readout.length(size));
    let _ = write!(s, ",\"trails\":{}", options.trails.unwrap_or(0));
    s.push_str(",\"walls\":");
    // The walls drawn: those of the first frame with a colour (ssdraw's, or what an
    // ssdraw.par made it).
    let drawn: Vec<(&WallMesh, String)> = frames
        .first()
        .map_or(&[][..], |f| &f.walls[..])
        .iter()
        .filter_map(|wm| Some((wm, palette::css(wm.rgb?))))
        .collect();
    let placements = placements(frames, &drawn);
    array(
        &mut s,
        drawn.iter().zip(&placements),
        |s, ((wm, color), placed)| {
            wall(s, scene, wm, placed, color, (&centre, size));
        },
    );
    s.push_str(",\"particles\":");
    particles(&mut s, frames, &centre, size);
    s.push('}');
    s
}

/// Each drawn wall's origin and turn in every frame (a frame without the wall keeps the
/// one before), the frames' walls matched by index in one pass over each frame.
fn placements(
    frames: &[MovieFrame],
    drawn: &[(&WallMesh, String)],
) -> Vec<Vec<(Vec3, Rotation3<f64>)>> {
    let slot: BTreeMap<usize, usize> = drawn
        .iter()
        .enumerate()
        .map(|(i, (wm, _))| (wm.wall, i))
        .collect();
    let mut placed: Vec<(Vec3, Rotation3<f64>)> =
        drawn.iter().map(|(wm, _)| (wm.origin, wm.turn)).collect();
    let mut placements = vec![Vec::with_capacity(frames.len()); drawn.len()];
    for frame in frames {
        for m in &frame.walls {
            if let Some(&i) = slot.get(&m.wall) {
                placed[i] = (m.origin, m.turn);
            }
        }
        for (each, &now) in placements.iter_mut().zip(&placed) {
            each.push(now);
        }
    }
    placements
}

/// One wall of the first frame, `wm`: its mesh about its origin, and where each frame
/// has its origin and how it turns it (`placements`, about the origin, from the first
/// frame).
fn wall(
    s: &mut String,
    scene: &Scene,
    wm: &WallMesh,
    placements: &[(Vec3, Rotation3<f64>)],
    color: &str,
    (centre, size): (&Vec3, f64),
) {
    let _ = write!(s, "{{\"index\":{},\"type\":", wm.wall);
    string(s, wm.wall_type.name());
    s.push_str(",\"color\":");
    string(s, color);
    s.push_str(",\"opacity\":");
    num(s, wm.opacity);
    let turns: Vec<UnitQuaternion<f64>> = placements
        .iter()
        .map(|(_, turn)| UnitQuaternion::from_rotation_matrix(&(turn * wm.turn.inverse())))
        .collect();
    let turning = turns.iter().any(|q| q.angle() >= 1e-9);
    // The point the mesh is written about: the origin a turning wall turns about, else
    // the centre of the mesh's box, which is in the scene whatever the origin (a floor
    // whose origin is 1e40 away along it would not fit an f32 about its origin).
    let anchor = if turning {
        wm.origin
    } else {
        mesh_centre(&wm.mesh).unwrap_or(wm.origin)
    };
    s.push_str(",\"positions\":");
    nums(
        s,
        wm.mesh
            .positions
            .iter()
            .flat_map(|p| <[f64; 3]>::from((p - anchor) / size)),
    );
    s.push_str(",\"indices\":");
    nums(s, wm.mesh.triangles.iter().flatten().map(|&i| f64::from(i)));
    s.push_str(",\"origins\":");
    coords(
        s,
        placements.iter().map(|(o, _)| o + (anchor - wm.origin)),
        centre,
        size,
    );
    s.push_str(",\"turns\":");
    if turning {
        nums(s, turns.iter().flat_map(|q| [q.i, q.j, q.k, q.w]));
    } else {
        s.push_str("null");
    }
    s.push_str(",\"tokens\":");
    let shown = scene.walls.get(wm.wall).map(tokens).unwrap_or_default();
    array(s, shown, |s, (k, v)| array(s, [k, v.as_str()], string));
    s.push('}');
}

/// The particles of every frame, matched by their index: each one's index, radius (in
/// units of the scene's size) and colour, and in each frame its position (`null`s for
/// one the frame lacks); `null` for a movie without particles.
fn particles(s: &mut String, frames: &[MovieFrame], centre: &Vec3, size: f64) {
    // Every particle's slot, by index, with its radius and colour where first seen (a
    // stuck particle's, its wall's there).
    let mut seen: BTreeMap<i32, (f64, Option<String>)> = BTreeMap::new();
    for f in frames {
        let wall_colour = |w: usize| f.walls.iter().find(|m| m.wall == w).map(|m| m.color);
        for p in &f.particles {
            seen.entry(p.index).or_insert_with(|| {
                let colour = palette::particle(i64::from(p.color), wall_colour);
                (p.radius, colour.and_then(palette::hex))
            });
        }
    }
    if seen.is_empty() {
        s.push_str("null");
        return;
    }
    let slot: BTreeMap<i32, usize> = seen.keys().enumerate().map(|(i, &k)| (k, i)).collect();
    s.push_str("{\"ids\":");
    array(s, seen.keys(), |s, index| {
        let _ = write!(s, "{index}");
    });
    s.push_str(",\"radii\":");
    nums(s, seen.values().map(|(r, _)| r.abs() / size));
    s.push_str(",\"colors\":");
    array(s, seen.values(), |s, (_, color)| match color {
        Some(hex) => string(s, hex),
        None => s.push_str("null"),
    });
    s.push_str(",\"positions\":");
    let mut at: Vec<Option<Vec3>> = vec![None; seen.len()];
    array(s, frames, |s, frame| {
        at.iter_mut().for_each(|q| *q = None);
        for p in &frame.particles {
            if let Some(&i) = slot.get(&p.index) {
                at[i] = Some(p.pos);
            }
        }
        // Three coordinates a particle, `null`s for one the frame lacks.
        let xyz = at.iter().flat_map(|q| {
            let x = q.map(|q| <[f64; 3]>::from((q - centre) / size));
            (0..3).map(move |j| x.map(|x| x[j]))
        });
        array(s, xyz, |s, c| match c {
            Some(c) => coord(s, c),
            None => s.push_str("null"),
        });
    });
    s.push('}');
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scripts_cannot_close_their_element() {
        assert_eq!(
            script_safe("a=\"</script>\";b=/<!--/"),
            "a=\"<\\/script>\";b=/<\\!--/"
        );
        let mut s = String::new();
        string(&mut s, "</script> \"q\" \n");
        assert_eq!(s, "\"\\u003c/script> \\\"q\\\" \\u000a\"");
    }
}
