//! ssdraw's palette (docs/pkdgrav-physics.md §16, docs/spec.md §3 "Drawing"), the same
//! for particles and walls: 0 black, 1 white, 2 red, 3 green, 4 blue, 5 yellow, 6
//! magenta, 7 cyan, 8 gold, 9 pink, 10 orange, 11 khaki, 12 violet, 13 maroon, 14 aqua,
//! 15 navy ([`NAMED`] holds their bytes); 16–255 greys of level ⌊255·(c − 16)/239⌋. Walls
//! of colour 0 are not drawn ([`wall`]); particles of colour 0 are drawn black, and a
//! particle of colour −1 − w (stuck to wall w) in wall w's colour ([`particle`]).

/// The names of colours 0–15, as the POV-Ray scenes' `walls.inc` declares them
/// (`Ssdraw` and the name: `SsdrawGold`).
pub const NAMES: [&str; 16] = [
    "Black", "White", "Red", "Green", "Blue", "Yellow", "Magenta", "Cyan", "Gold", "Pink",
    "Orange", "Khaki", "Violet", "Maroon", "Aqua", "Navy",
];

/// Colours 0–15 as red, green and blue bytes.
pub const NAMED: [[u8; 3]; 16] = [
    [0, 0, 0],
    [255, 255, 255],
    [255, 0, 0],
    [0, 255, 0],
    [0, 0, 255],
    [255, 255, 0],
    [255, 0, 255],
    [0, 255, 255],
    [255, 215, 0],
    [255, 192, 203],
    [255, 165, 0],
    [240, 230, 140],
    [238, 130, 238],
    [176, 48, 96],
    [127, 255, 212],
    [0, 0, 128],
];

/// The colour `index` as red, green and blue bytes; `None` outside 0–255.
pub fn bytes(index: i64) -> Option<[u8; 3]> {
    match index {
        0..=15 => Some(NAMED[index as usize]),
        16..=255 => {
            // ⌊255·(c − 16)/239⌋: 16 is black, 255 white.
            let level = (255 * (index - 16) / 239) as u8;
            Some([level; 3])
        }
        _ => None,
    }
}

/// The colour `index` as red, green and blue from 0 to 1; `None` outside 0–255. A
/// particle's colour, drawn whatever it is (0 black).
pub fn rgb(index: i64) -> Option<[f64; 3]> {
    bytes(index).map(|b| b.map(|x| f64::from(x) / 255.0))
}

/// A wall's colour `index` as [`rgb`] gives it; `None` for 0 (ssdraw does not draw the
/// wall) and outside 0–255.
pub fn wall(index: i64) -> Option<[f64; 3]> {
    rgb(index).filter(|_| index != 0)
}

/// The colour a particle of colour `color` is drawn in, as an index of the palette: its
/// own for 0–255; for −1 − w (a particle stuck to wall w), wall w's, which
/// `wall_colour` gives (0 too: the particle is drawn black); `None` for anything else
/// (ssdraw refuses it), a wall `wall_colour` does not know included.
pub fn particle(color: i64, wall_colour: impl Fn(usize) -> Option<i64>) -> Option<i64> {
    let own = |c: i64| (0..=255).contains(&c).then_some(c);
    match color {
        0..=255 => Some(color),
        ..0 => {
            // −1 − color is 0 to i64::MAX: no overflow.
            let wall = usize::try_from(-1 - color).ok()?;
            own(wall_colour(wall)?)
        }
        _ => None,
    }
}

/// The colour `index` as a CSS hex colour (`#rrggbb`), or `None` outside 0–255.
pub fn hex(index: i64) -> Option<String> {
    bytes(index).map(|[r, g, b]| format!("#{r:02x}{g:02x}{b:02x}"))
}

/// Red, green and blue from 0 to 1 as a CSS colour, `#rrggbb`.
pub fn css([r, g, b]: [f64; 3]) -> String {
    let byte = |x: f64| (x * 255.0).round().clamp(0.0, 255.0) as u8;
    format!("#{:02x}{:02x}{:02x}", byte(r), byte(g), byte(b))
}
