//! The resolved scene as JSON, as `walls-sim scene` prints it (docs/spec.md §2).
//!
//! `{"walls":[{"index":0,"line":N,"type":"plane","<token>":value,…}]}`: one key per wall
//! token, spelled as the token, in the order of the keyword table, holding the effective
//! value in pkdgrav units (vectors as 3-element arrays). `orient` is the unit normal the
//! wall uses: for triangles and rectangles, vertex1 × vertex2 normalised. `transparency`
//! is a fraction; `mass` is null when infinite (0). With a time, each wall also has
//! `position`, its origin displaced by its motion then (null if that overflows).
//!
//! It lists every token's effective value, so it reads the resolved wall's settings (the
//! one place outside [`crate::Wall::decode`] that does); the position is the typed
//! [`crate::Motion`]'s.

use serde::Serialize;
use serde::ser::{SerializeMap, SerializeSeq, Serializer};
use std::io::{self, Write};
use walls_diagnostics::LineIndex;
use walls_keywords::{Keyword, Role};
use walls_model::{Scene, Value, Wall};

/// Writes the scene of `text` as pretty JSON followed by a newline; `time` adds each
/// wall's `position` at that time.
pub fn write_scene(
    out: &mut dyn Write,
    scene: &Scene,
    text: &str,
    time: Option<f64>,
) -> io::Result<()> {
    let index = LineIndex::new(text);
    let doc = Doc {
        walls: Walls {
            scene,
            text,
            index: &index,
            time,
        },
    };
    serde_json::to_writer_pretty(&mut *out, &doc)?;
    writeln!(out)
}

#[derive(Serialize)]
struct Doc<'a> {
    walls: Walls<'a>,
}

struct Walls<'a> {
    scene: &'a Scene,
    text: &'a str,
    index: &'a LineIndex,
    time: Option<f64>,
}

impl Serialize for Walls<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.scene.walls.len()))?;
        for wall in &self.scene.walls {
            seq.serialize_element(&WallJson { wall, walls: self })?;
        }
        seq.end()
    }
}

struct WallJson<'a> {
    wall: &'a Wall,
    walls: &'a Walls<'a>,
}

impl Serialize for WallJson<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let wall = self.wall;
        let mut map = serializer.serialize_map(None)?;
        map.serialize_entry("index", &wall.index)?;
        let line = self
            .walls
            .index
            .line_col(self.walls.text, wall.span.start)
            .line;
        map.serialize_entry("line", &line)?;
        for &k in Keyword::ALL.iter().filter(|k| k.role() == Role::Property) {
            match (k, wall.value(k)) {
                (Keyword::Orient, _) => map.serialize_entry(k.name(), wall.normal().as_slice())?,
                (Keyword::Mass, Some(Value::Number(0.0))) => {
                    map.serialize_entry(k.name(), &Option::<f64>::None)?
                }
                (_, Some(Value::Number(x))) => map.serialize_entry(k.name(), &x)?,
                (_, Some(Value::Integer(i))) => map.serialize_entry(k.name(), &i)?,
                (_, Some(Value::Vector(v))) => map.serialize_entry(k.name(), v.as_slice())?,
                (_, Some(Value::Type(t))) => map.serialize_entry(k.name(), t.name())?,
                (_, None) => {}
            }
        }
        if let Some(t) = self.walls.time {
            let position = crate::Wall::decode(wall).motion.position(t);
            map.serialize_entry("position", &position.as_ref().map(|p| p.as_slice()))?;
        }
        map.end()
    }
}
