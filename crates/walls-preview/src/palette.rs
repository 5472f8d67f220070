//! ssdraw's colours (docs/spec.md §3 "Drawing"): 0 is not drawn; 1–15 are POV-Ray's named
//! colours White, Red, Green, Blue, Yellow, Magenta, Cyan, Gold, Pink, Orange, Khaki,
//! Violet, Maroon, Aquamarine, Navy (values from POV-Ray's `colors.inc`); 16–255 are
//! greys of level (c − 16)/239.

/// The POV-Ray names of colours 1–15.
pub const NAMES: [&str; 15] = [
    "White",
    "Red",
    "Green",
    "Blue",
    "Yellow",
    "Magenta",
    "Cyan",
    "Gold",
    "Pink",
    "Orange",
    "Khaki",
    "Violet",
    "Maroon",
    "Aquamarine",
    "Navy",
];

const NAMED: [[f64; 3]; 15] = [
    [1.0, 1.0, 1.0],
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
    [1.0, 1.0, 0.0],
    [1.0, 0.0, 1.0],
    [0.0, 1.0, 1.0],
    [0.8, 0.498039, 0.196078],
    [0.737255, 0.560784, 0.560784],
    [1.0, 0.5, 0.0],
    [0.623529, 0.623529, 0.372549],
    [0.309804, 0.184314, 0.309804],
    [0.556863, 0.137255, 0.419608],
    [0.439216, 0.858824, 0.576471],
    [0.137255, 0.137255, 0.556863],
];

/// The colour `index` as red, green and blue from 0 to 1; `None` for 0 (not drawn) and
/// for indices outside 0–255.
pub fn rgb(index: i64) -> Option<[f64; 3]> {
    match index {
        1..=15 => Some(NAMED[index as usize - 1]),
        16..=255 => {
            let level = (index - 16) as f64 / 239.0;
            Some([level; 3])
        }
        _ => None,
    }
}

/// The colour `index` as a CSS hex colour (`#rrggbb`), or `None` as [`rgb`].
pub fn hex(index: i64) -> Option<String> {
    rgb(index).map(css)
}

/// Red, green and blue from 0 to 1 as a CSS colour, `#rrggbb`.
pub fn css([r, g, b]: [f64; 3]) -> String {
    let byte = |x: f64| (x * 255.0).round().clamp(0.0, 255.0) as u8;
    format!("#{:02x}{:02x}{:02x}", byte(r), byte(g), byte(b))
}
