//! An interactive, self-contained HTML page of a scene (SPEC §2 `walls-sim preview`):
//! three.js draws the walls in ssdraw's colours (colour 0 not drawn) and the particles as
//! spheres; a slider and a play button move them through time, the mouse orbits the
//! camera, and hovering a wall shows its type, index and tokens.
//!
//! The page needs no network: the viewer, three.js and its OrbitControls come bundled in
//! one script (`assets/viewer.bundle.js`, built by `web/bundle.sh` from the npm packages
//! locked in `web/package-lock.json` and committed) and the scene is JSON in the page.
//! Walls move rigidly (SPEC §1 "Motion"; spin never moves the drawn shape), so each wall
//! is one mesh at t = 0 and its origin's offset at `frames` times over [0, t_end],
//! interpolated linearly in between. Geometry and motion come from the typed walls
//! (walls-geometry); the hover lists the tokens as the file set them, so it alone reads
//! the resolved wall's settings.
//!
//! The URL's fragment sets the initial time (`page.html#t=0.25`) and can hover a point
//! (`#hover=0.5,0.5`, as fractions of the canvas's width and height);
//! `window.wallsPreview` offers `setTime(t)`, `time()`, `play()`, `pause()` and
//! `hoverAt(x, y)` (client pixels) once `ready`, and `document.body.dataset` has `ready`
//! and `time`, for tests and scripts.

use crate::mesh::wall_meshes;
use crate::palette;
use nalgebra::Vector3;
use std::fmt::Write as _;
use std::io;
use walls_geometry::{decode, scene_bounds};
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
    /// Each particle's ssdraw colour (0 draws it in the default light grey, as do missing
    /// entries).
    pub colors: Vec<i64>,
    /// The time of each frame, increasing.
    pub times: Vec<f64>,
    /// Each frame's positions: `frames[k][i]` is particle i at `times[k]` (between frames
    /// the page interpolates linearly).
    pub frames: Vec<Vec<Vec3>>,
}

/// Writes the page: the walls of `scene` (and `particles`, if given) over times 0 to
/// `t_end`, with each wall's position computed at `frames` evenly spaced times (at least
/// one; one frame, or `t_end` ≤ 0, shows t = 0 only).
pub fn write(
    out: &mut impl io::Write,
    scene: &Scene,
    particles: Option<&Particles>,
    t_end: f64,
    frames: usize,
) -> io::Result<()> {
    let json = data(scene, particles, t_end, frames);
    let bundle = script_safe(BUNDLE);
    write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>walls preview</title>\n<style>{STYLE}</style>\n</head>\n<body>\n\
         <script id=\"walls-data\" type=\"application/json\">{json}</script>\n\
         <script>{bundle}</script>\n</body>\n</html>\n"
    )
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
#tooltip .key{color:#9cdcfe}";

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

fn nums(s: &mut String, xs: impl IntoIterator<Item = f64>) {
    s.push('[');
    for (i, x) in xs.into_iter().enumerate() {
        if i > 0 {
            s.push(',');
        }
        num(s, x);
    }
    s.push(']');
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

/// The page's data (the format is described at the top of `web/viewer.js`).
fn data(scene: &Scene, particles: Option<&Particles>, t_end: f64, frames: usize) -> String {
    let t_end = if t_end.is_finite() && t_end > 0.0 {
        t_end
    } else {
        0.0
    };
    let frames = if t_end > 0.0 { frames.max(2) } else { 1 };
    let times: Vec<f64> = (0..frames)
        .map(|k| {
            if frames > 1 {
                t_end * k as f64 / (frames - 1) as f64
            } else {
                0.0
            }
        })
        .collect();
    let decoded = decode(scene);
    let (mut lo, mut hi) = scene_bounds(&decoded, &[]);
    if let Some(p) = particles {
        for frame in &p.frames {
            for (i, q) in frame.iter().enumerate() {
                let r = Vec3::repeat(p.radii.get(i).copied().unwrap_or(0.0).abs());
                (lo, hi) = (lo.inf(&(q - r)), hi.sup(&(q + r)));
            }
        }
    }
    let centre = (lo + hi) / 2.0;

    let mut s = String::new();
    s.push_str("{\"tEnd\":");
    num(&mut s, t_end);
    s.push_str(",\"times\":");
    nums(&mut s, times.iter().copied());
    s.push_str(",\"centre\":");
    nums(&mut s, centre.iter().copied());
    s.push_str(",\"size\":");
    num(&mut s, (hi - lo).max());
    s.push_str(",\"walls\":[");
    let mut first = true;
    for wm in wall_meshes(scene, 0.0, SEGMENTS) {
        let Some(color) = palette::hex(wm.color) else {
            continue;
        };
        if !first {
            s.push(',');
        }
        first = false;
        let wall = &scene.walls[wm.wall];
        let motion = &decoded[wm.wall].motion;
        let _ = write!(s, "{{\"index\":{},\"type\":", wm.wall);
        string(&mut s, wm.wall_type.name());
        s.push_str(",\"color\":");
        string(&mut s, &color);
        s.push_str(",\"opacity\":");
        num(&mut s, wm.opacity);
        s.push_str(",\"positions\":");
        nums(
            &mut s,
            wm.mesh.positions.iter().flat_map(|p| p.iter().copied()),
        );
        s.push_str(",\"indices\":");
        nums(
            &mut s,
            wm.mesh.triangles.iter().flatten().map(|&i| f64::from(i)),
        );
        s.push_str(",\"offsets\":");
        nums(
            &mut s,
            times.iter().flat_map(|&t| {
                let o = motion.position(t).unwrap_or(wm.origin);
                (o - wm.origin).iter().copied().collect::<Vec<_>>()
            }),
        );
        s.push_str(",\"tokens\":[");
        for (i, (k, v)) in tokens(wall).into_iter().enumerate() {
            if i > 0 {
                s.push(',');
            }
            s.push('[');
            string(&mut s, k);
            s.push(',');
            string(&mut s, &v);
            s.push(']');
        }
        s.push_str("]}");
    }
    s.push_str("],\"particles\":");
    match particles {
        Some(p) if !p.radii.is_empty() && !p.frames.is_empty() => {
            let n = p.radii.len();
            s.push_str("{\"radii\":");
            nums(&mut s, p.radii.iter().copied());
            s.push_str(",\"colors\":[");
            for i in 0..n {
                if i > 0 {
                    s.push(',');
                }
                match p.colors.get(i).and_then(|&c| palette::hex(c)) {
                    Some(hex) => string(&mut s, &hex),
                    None => s.push_str("null"),
                }
            }
            s.push_str("],\"times\":");
            nums(
                &mut s,
                (0..p.frames.len()).map(|k| p.times.get(k).copied().unwrap_or(0.0)),
            );
            s.push_str(",\"positions\":[");
            for (k, frame) in p.frames.iter().enumerate() {
                if k > 0 {
                    s.push(',');
                }
                // Every frame has n positions: a missing particle stays at the origin.
                nums(
                    &mut s,
                    (0..n).flat_map(|i| {
                        let q = frame.get(i).copied().unwrap_or_else(Vec3::zeros);
                        [q.x, q.y, q.z]
                    }),
                );
            }
            s.push_str("]}");
        }
        _ => s.push_str("null"),
    }
    s.push('}');
    s
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
