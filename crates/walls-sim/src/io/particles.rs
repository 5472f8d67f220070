//! Particles from the files a pkdgrav user has.
//!
//! * CSV (docs/spec.md §2): header `mass,radius,x,y,z,vx,vy,vz`, optionally followed by
//!   `wx,wy,wz,color`; one particle a row, in pkdgrav units.
//! * pkdgrav `.ss` files: big-endian XDR. A 16-byte header (double time, int32 count,
//!   int32 magic: −1 standard, −10101 reduced), then per particle either 96 bytes (double
//!   mass, radius, `pos[3]`, `vel[3]`, `spin[3]`; int32 color, original index) or 28
//!   bytes (float mass, radius, `pos[3]`; int32 color, index).
//!
//! [`write_ss_output`] writes the `.ss` files of a run's outputs, named as pkdgrav names
//! them ([`ss_file_name`]), record by record; [`write_ss`] makes one in memory.
//!
//! Every error says where: the CSV line or the `.ss` byte offset.

use super::{FileError, InputError, error};
use crate::bodies::State;
use crate::warning::Warning;
use nalgebra::Vector3;
use std::fs::File;
use std::io::{self, Read, Write};
use std::path::Path;
use walls_geometry::Particle;

type Vec3 = Vector3<f64>;

/// Particles read from a file, with the warnings about its numbers: each a [`Particle`],
/// or made one from it as it is read (a run's [`State`]s: the run then holds no second
/// array of its particles, [`read_file_as`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Particles<T = Particle> {
    /// The particles, in the file's order.
    pub particles: Vec<T>,
    /// Its subnormal numbers (W701), each located in the file (`line 3: \`x\``, `byte
    /// 40: particle 0's \`x\``; [`read_file`] puts the file's path before).
    pub warnings: Vec<Warning>,
}

/// Reads particles from CSV text.
pub fn read_csv(text: &str) -> Result<Particles, InputError> {
    read_csv_from(text.as_bytes(), text.len() as u64)
}

/// Reads particles from the CSV `source` gives, row by row (a file is never in memory
/// whole), a field's bytes that are not UTF-8 read as U+FFFD, as [`read_bytes`] reads
/// them. `len`, the source's length in bytes, sizes the particles' array from the first
/// row's length.
fn read_csv_from<T: From<Particle>>(
    source: impl io::Read,
    len: u64,
) -> Result<Particles<T>, InputError> {
    // The names and fields trimmed of white space as Unicode defines it (as the csv
    // reader's trim of text records does), here, one field at a time: the reader's own
    // trim made a new record for each row. The reader buffers `source` itself.
    let mut reader = csv::ReaderBuilder::new()
        .buffer_capacity(1 << 16)
        .from_reader(source);
    let header: Vec<String> = reader
        .byte_headers()
        .map_err(|e| error("line 1", e.to_string()))?
        .iter()
        .map(|h| String::from_utf8_lossy(h).trim().to_string())
        .collect();
    const REQUIRED: [&str; 8] = ["mass", "radius", "x", "y", "z", "vx", "vy", "vz"];
    const OPTIONAL: [&str; 5] = ["wx", "wy", "wz", "color", "org_idx"];
    let column = |name: &str| header.iter().position(|h| h == name);
    for name in REQUIRED {
        if column(name).is_none() {
            return Err(error(
                "line 1",
                format!("the header has no `{name}` column (it needs mass,radius,x,y,z,vx,vy,vz)"),
            ));
        }
    }
    // A column named twice would be read from its first place and its second ignored.
    for (n, name) in header.iter().enumerate() {
        if let Some(first) = header[..n].iter().position(|h| h == name) {
            return Err(error(
                "line 1",
                format!(
                    "the column `{}` is named twice (columns {} and {})",
                    super::excerpt(name),
                    first + 1,
                    n + 1
                ),
            ));
        }
    }
    if let Some(extra) = header
        .iter()
        .find(|h| !REQUIRED.contains(&h.as_str()) && !OPTIONAL.contains(&h.as_str()))
    {
        return Err(error(
            "line 1",
            format!("unknown column `{}`", super::excerpt(extra)),
        ));
    }
    // Each column's place in a row, found once (`wx`, `wy`, `wz`, `color` and `org_idx`
    // may be absent).
    let [
        mass,
        radius,
        x,
        y,
        z,
        vx,
        vy,
        vz,
        wx,
        wy,
        wz,
        color,
        org_idx,
    ] = [
        "mass", "radius", "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "color", "org_idx",
    ]
    .map(|name| (name, column(name)));
    // One record read into again and again, and the line named only in an error
    // (allocating both for every row took 5 % of the instructions of a run's set-up
    // from 10⁵ rows).
    let mut out = Vec::new();
    let mut warnings = Vec::new();
    let mut record = csv::ByteRecord::new();
    for n in 0_usize.. {
        let line = || format!("line {}", n + 2);
        match reader.read_byte_record(&mut record) {
            Ok(true) => {}
            Ok(false) => break,
            Err(e) => return Err(error(line(), e.to_string())),
        }
        if n == 0 {
            // Asked for, not required: a file that is mostly a hole asks for little.
            let _ = out.try_reserve(rows_expected(len, &reader, &record).min(MOST_RESERVED));
        }
        // A field as text (trimmed where it is used): the row's bytes checked once, each
        // field its part of them (a field that does not end on a character's boundary,
        // as two halves of one character split by a comma would, is read on its own).
        let row = std::str::from_utf8(record.as_slice()).ok();
        let field = |i: usize| match row.zip(record.range(i)).and_then(|(row, r)| row.get(r)) {
            Some(field) => std::borrow::Cow::Borrowed(field),
            None => text(record.get(i).unwrap_or(b"")),
        };
        let mut number = |(name, column): (&str, Option<usize>)| -> Result<f64, InputError> {
            let Some(i) = column else {
                return Ok(0.0);
            };
            let text = field(i);
            let field = text.trim();
            super::number(field, || format!("{}: `{name}`", line()), &mut warnings).map_err(|why| {
                let field = super::excerpt(field);
                error(line(), format!("`{name}` is `{field}`, {why}"))
            })
        };
        let integer = |(name, column): (&str, Option<usize>)| -> Result<Option<i32>, InputError> {
            let Some(i) = column else {
                return Ok(None);
            };
            let text = field(i);
            let field = text.trim();
            field.parse::<i32>().map(Some).map_err(|_| {
                let field = super::excerpt(field);
                error(line(), format!("`{name}` is `{field}`, not an integer"))
            })
        };
        let particle = Particle {
            mass: number(mass)?,
            radius: number(radius)?,
            pos: Vec3::new(number(x)?, number(y)?, number(z)?),
            vel: Vec3::new(number(vx)?, number(vy)?, number(vz)?),
            spin: Vec3::new(number(wx)?, number(wy)?, number(wz)?),
            color: integer(color)?.unwrap_or(DEFAULT_COLOR),
            // pkdgrav's original index, as a `.ss` file's: a negative one names an
            // aggregate (docs/pkdgrav-physics.md §9); else the row's place.
            index: integer(org_idx)?.unwrap_or(n as i32),
        };
        check(&particle).map_err(|says| error(line(), says))?;
        out.push(T::from(particle));
    }
    Ok(Particles {
        particles: out,
        warnings,
    })
}

/// The most particles the CSV reader makes room for before it has read them (1.6 GB of
/// particles, 2.7 GB of a run's states; room asked for, touched only as rows fill it):
/// past it the array grows as they come.
const MOST_RESERVED: usize = 1 << 24;

/// How many rows a CSV of `len` bytes probably holds, from where its first row ended
/// (rows of one table are about as long as each other): growing the array of 10⁶
/// particles one doubling at a time left each smaller array behind it. At most one row
/// per 16 bytes (the shortest row of eight numbers).
fn rows_expected<R: io::Read>(len: u64, reader: &csv::Reader<R>, first: &csv::ByteRecord) -> usize {
    let Some(start) = first.position().map(|p| p.byte()) else {
        return 0;
    };
    let row = reader.position().byte().saturating_sub(start).max(16);
    usize::try_from(len.saturating_sub(start) / row).unwrap_or(0)
}

/// `bytes` as text, those that are not UTF-8 read as U+FFFD (`from_utf8_lossy`, whose
/// check of every byte took twice as long as `from_utf8`'s for the fields of a CSV row).
#[inline]
fn text(bytes: &[u8]) -> std::borrow::Cow<'_, str> {
    match std::str::from_utf8(bytes) {
        Ok(text) => text.into(),
        Err(_) => String::from_utf8_lossy(bytes),
    }
}

/// Whether a run can use particle `p`: a positive mass and radius, finite values, and
/// the squares a run takes of them (its moment of inertia 0.4·m·r², its kinetic energy
/// ½m|v|² and ⅕m·r²|ω|², the squared distance |x|²) neither overflowing nor, for the
/// inertia, underflowing to 0; a `color` pkdgrav's tools can draw.
pub fn check(p: &Particle) -> Result<(), String> {
    if !(p.mass > 0.0 && p.radius > 0.0) {
        return Err("mass and radius must be positive".into());
    }
    let values = [p.mass, p.radius];
    let vectors = [p.pos, p.vel, p.spin];
    if !values
        .iter()
        .chain(vectors.iter().flatten())
        .all(|x| x.is_finite())
    {
        return Err("its values must be finite numbers".into());
    }
    let inertia = crate::dynamics::sphere_inertia(p.mass, p.radius);
    if !(inertia > 0.0 && inertia.is_finite()) {
        return Err(format!(
            "its moment of inertia 0.4·m·r² (m = {:e}, r = {:e}) is {inertia:e}, outside what a double holds: check the values' scale (pkdgrav units)",
            p.mass, p.radius
        ));
    }
    let squares = [
        ("kinetic energy ½m|v|²", 0.5 * p.mass * p.vel.norm_squared()),
        ("spin energy ½I|ω|²", 0.5 * inertia * p.spin.norm_squared()),
        (
            "squared distance from the origin |x|²",
            p.pos.norm_squared(),
        ),
    ];
    if let Some((what, x)) = squares.iter().find(|(_, x)| !x.is_finite()) {
        return Err(format!(
            "its {what} is {x}, beyond what a double holds: check the values' scale (pkdgrav units)"
        ));
    }
    if p.color > COLOR_MAX {
        return Err(format!(
            "`color` is {}; pkdgrav's colours are 0 to {COLOR_MAX} (negative: stuck to wall −1 − color)",
            p.color
        ));
    }
    Ok(())
}

/// The largest colour pkdgrav's tools draw (docs/spec.md §1: 0 to 255; a negative colour
/// means stuck to a wall).
pub const COLOR_MAX: i32 = 255;

/// The colour of a particle whose file gives none (a CSV without a `color` column, a
/// `particles.csv` written before it had one): 3, green in ssdraw's palette.
pub const DEFAULT_COLOR: i32 = 3;

/// A cursor over big-endian XDR data that reports the byte offset of a short read.
struct Xdr<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Xdr<'_> {
    fn take<const N: usize>(&mut self) -> Result<[u8; N], InputError> {
        let slice = self.bytes.get(self.at..self.at + N).ok_or_else(|| {
            error(
                format!("byte {}", self.at),
                format!(
                    "the file ends inside a record ({} bytes in all)",
                    self.bytes.len()
                ),
            )
        })?;
        self.at += N;
        Ok(slice.try_into().expect("the slice has N bytes"))
    }
    fn f64(&mut self) -> Result<f64, InputError> {
        self.take::<8>().map(f64::from_be_bytes)
    }
    fn f32(&mut self) -> Result<f64, InputError> {
        self.take::<4>().map(|b| f32::from_be_bytes(b) as f64)
    }
    fn i32(&mut self) -> Result<i32, InputError> {
        self.take::<4>().map(i32::from_be_bytes)
    }
}

/// The `.ss` magic numbers.
const STANDARD: i32 = -1;
const REDUCED: i32 = -10101;

/// The fields of a standard `.ss` record's doubles, in the file's order.
const SS_FIELDS: [&str; 11] = [
    "mass", "radius", "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz",
];

/// A `.ss` file's 16-byte header, checked against the file's length.
struct Header {
    time: f64,
    count: usize,
    standard: bool,
}

/// Reads the header of a `.ss` file of `len` bytes from `x` (its time, particle count and
/// magic number) and checks that the records the count implies (standard or reduced) make
/// exactly `len` bytes; the header's time goes to `warnings` if subnormal. This is all a
/// file is checked by before its records are read ([`read_ss_file`]).
fn header(x: &mut Xdr<'_>, len: u64, warnings: &mut Vec<Warning>) -> Result<Header, InputError> {
    let time = x.f64()?;
    if !time.is_finite() {
        return Err(error(
            "byte 0",
            format!("the header's time is {time}, not a finite number"),
        ));
    }
    super::subnormal(time, || "byte 0: the header's time".into(), warnings);
    let count = x.i32()?;
    let magic = x.i32()?;
    let record: u64 = match magic {
        STANDARD => 96,
        REDUCED => 28,
        m => {
            return Err(error(
                "byte 12",
                format!("magic number {m}: a .ss file has −1 (standard) or −10101 (reduced)"),
            ));
        }
    };
    let need = 16 + u64::from(count.max(0).unsigned_abs()) * record;
    if count < 0 || len != need {
        return Err(error(
            "byte 8",
            format!("{count} particles of {record} bytes need {need} bytes, the file has {len}"),
        ));
    }
    Ok(Header {
        time,
        count: count.unsigned_abs() as usize,
        standard: magic == STANDARD,
    })
}

/// Reads a pkdgrav `.ss` file: its time and particles.
pub fn read_ss(bytes: &[u8]) -> Result<(f64, Particles), InputError> {
    read_ss_as(bytes)
}

/// [`read_ss`], each particle made a `T` as it is read.
fn read_ss_as<T: From<Particle>>(bytes: &[u8]) -> Result<(f64, Particles<T>), InputError> {
    let mut x = Xdr { bytes, at: 0 };
    let mut warnings = Vec::new();
    let Header {
        time,
        count,
        standard,
    } = header(&mut x, bytes.len() as u64, &mut warnings)?;
    let mut out = Vec::with_capacity(count);
    for k in 0..count {
        let start = x.at;
        let p = if standard {
            let mass = x.f64()?;
            let radius = x.f64()?;
            let pos = Vec3::new(x.f64()?, x.f64()?, x.f64()?);
            let vel = Vec3::new(x.f64()?, x.f64()?, x.f64()?);
            let spin = Vec3::new(x.f64()?, x.f64()?, x.f64()?);
            Particle {
                mass,
                radius,
                pos,
                vel,
                spin,
                color: x.i32()?,
                index: x.i32()?,
            }
        } else {
            let mass = x.f32()?;
            let radius = x.f32()?;
            let pos = Vec3::new(x.f32()?, x.f32()?, x.f32()?);
            Particle {
                mass,
                radius,
                pos,
                vel: Vec3::zeros(),
                spin: Vec3::zeros(),
                color: x.i32()?,
                index: x.i32()?,
            }
        };
        check(&p)
            .map_err(|says| error(format!("byte {start}"), format!("particle {k}: {says}")))?;
        if standard {
            // (A reduced record's single-precision numbers are normal doubles.)
            let values = [p.mass, p.radius].into_iter().chain(p.pos.iter().copied());
            let values = values
                .chain(p.vel.iter().copied())
                .chain(p.spin.iter().copied());
            for ((i, value), name) in values.enumerate().zip(SS_FIELDS) {
                let at = || format!("byte {}: particle {k}'s `{name}`", start + 8 * i);
                super::subnormal(value, at, &mut warnings);
            }
        }
        out.push(T::from(p));
    }
    Ok((
        time,
        Particles {
            particles: out,
            warnings,
        },
    ))
}

/// `particles` as a pkdgrav `.ss` file at `time` (standard records, big-endian XDR):
/// what [`read_ss`] reads back exactly.
pub fn write_ss(time: f64, particles: &[impl AsRef<Particle>]) -> Vec<u8> {
    let mut out = Vec::with_capacity(16 + 96 * particles.len());
    let each = particles.iter().map(|p| p.as_ref().clone());
    // Writing to memory cannot fail.
    let _ = write_records(&mut out, time, particles.len(), each);
    out
}

/// A run's output after a step, as pkdgrav writes it: the living particles of `states`,
/// in input order, as [`State::as_written`] shows them, at `time`; written to `w` record
/// by record, as [`write_ss`] would make it.
pub fn write_ss_output(w: impl Write, time: f64, states: &[State]) -> io::Result<()> {
    let alive = || states.iter().filter(|s| s.alive);
    write_records(w, time, alive().count(), alive().map(State::as_written))
}

/// The `.ss` file of the first `count` of `particles` (at most `i32::MAX`) at `time`.
fn write_records(
    mut w: impl Write,
    time: f64,
    count: usize,
    particles: impl Iterator<Item = Particle>,
) -> io::Result<()> {
    let count = i32::try_from(count).unwrap_or(i32::MAX);
    w.write_all(&time.to_be_bytes())?;
    w.write_all(&count.to_be_bytes())?;
    w.write_all(&STANDARD.to_be_bytes())?;
    for p in particles.take(count as usize) {
        for x in [p.mass, p.radius]
            .into_iter()
            .chain(p.pos.iter().copied())
            .chain(p.vel.iter().copied())
            .chain(p.spin.iter().copied())
        {
            w.write_all(&x.to_be_bytes())?;
        }
        w.write_all(&p.color.to_be_bytes())?;
        w.write_all(&p.index.to_be_bytes())?;
    }
    Ok(())
}

/// The name pkdgrav gives the output after `step`: `name.NNNNN`, the step with at least
/// `digits` digits (`achOutName`, `nDigits`).
pub fn ss_file_name(name: &str, digits: usize, step: u64) -> String {
    format!("{name}.{step:0digits$}")
}

/// The two particle file formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// CSV text with a header row ([`read_csv`]).
    Csv,
    /// A pkdgrav `.ss` file ([`read_ss`]).
    Ss,
}

/// The format of the particle file `name` holding `bytes`: its extension when it is
/// `.csv` or `.ss` (in any case); otherwise (pkdgrav's `ss.00100`, a `.txt`, standard
/// input) its content: a `.ss` file's 16-byte binary header ends with the magic number
/// −1 or −10101, a CSV is text whose first line has commas. `None` when neither fits.
pub fn format_of(name: &str, bytes: &[u8]) -> Option<Format> {
    let extension = std::path::Path::new(name)
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("csv") => return Some(Format::Csv),
        Some("ss") => return Some(Format::Ss),
        _ => {}
    }
    let magic = bytes
        .get(12..16)
        .and_then(|b| <[u8; 4]>::try_from(b).ok())
        .map(i32::from_be_bytes);
    if matches!(magic, Some(STANDARD | REDUCED)) {
        return Some(Format::Ss);
    }
    let first = bytes.split(|&b| b == b'\n').next().unwrap_or_default();
    let text = std::str::from_utf8(first).ok()?;
    text.contains(',').then_some(Format::Csv)
}

/// Particles from `bytes`, the contents of the particle file `name`, in the format
/// [`format_of`] finds.
pub fn read_bytes(name: &str, bytes: &[u8]) -> Result<Particles, InputError> {
    read_bytes_as(name, bytes)
}

/// [`read_bytes`], each particle made a `T` as it is read.
fn read_bytes_as<T: From<Particle>>(name: &str, bytes: &[u8]) -> Result<Particles<T>, InputError> {
    match format_of(name, bytes) {
        Some(Format::Csv) => read_csv_from(bytes, bytes.len() as u64),
        Some(Format::Ss) => read_ss_as(bytes).map(|(_, ps)| ps),
        None => Err(error(
            "byte 0",
            "neither a particle CSV (a text header row: mass,radius,x,y,z,vx,vy,vz) nor a pkdgrav .ss file (a binary header with the magic number -1 or -10101 at byte 12)",
        )),
    }
}

/// Opens the file at `path` to read it, refusing what is not a regular file (a folder, a
/// FIFO, a device, a socket) before opening it: reading `/dev/zero` would fill memory, a
/// FIFO would block. Returns the file and its length.
fn open_regular(path: &Path) -> Result<(File, u64), FileError> {
    let name = path.display().to_string();
    let regular = |m: &std::fs::Metadata| {
        use std::os::unix::fs::FileTypeExt;
        let t = m.file_type();
        let kind = if t.is_file() {
            return Ok(());
        } else if t.is_dir() {
            "a folder"
        } else if t.is_fifo() {
            "a FIFO (named pipe)"
        } else if t.is_char_device() {
            "a character device"
        } else if t.is_block_device() {
            "a block device"
        } else if t.is_socket() {
            "a socket"
        } else {
            "not a file"
        };
        Err(FileError::read(
            &name,
            io::Error::other(format!(
                "it is {kind}, not a regular file (for standard input, give -)"
            )),
        ))
    };
    regular(&std::fs::metadata(path).map_err(|e| FileError::read(&name, e))?)?;
    let file = File::open(path).map_err(|e| FileError::read(&name, e))?;
    // What was opened, should the name have changed meanwhile.
    let m = file.metadata().map_err(|e| FileError::read(&name, e))?;
    regular(&m)?;
    Ok((file, m.len()))
}

/// The first `at_most` bytes of `file`, fewer if it ends sooner; `path` names it.
fn read_head(file: &mut File, at_most: u64, path: &Path) -> Result<Vec<u8>, FileError> {
    let mut bytes = Vec::new();
    file.take(at_most)
        .read_to_end(&mut bytes)
        .map_err(|e| FileError::read(&path.display().to_string(), e))?;
    Ok(bytes)
}

/// The bytes of the regular file `file` of `len` bytes (by its metadata) whose first
/// bytes, `head`, were read: the rest is read up to one byte past `len`, so a file that
/// grows meanwhile is found wrong without being read whole.
fn read_rest(
    mut file: File,
    len: u64,
    mut head: Vec<u8>,
    path: &Path,
) -> Result<Vec<u8>, FileError> {
    let rest = (len + 1).saturating_sub(head.len() as u64);
    let mut more = read_head(&mut file, rest, path)?;
    head.append(&mut more);
    Ok(head)
}

/// The `.ss` file `file` of `len` bytes whose first 16 bytes (fewer if it is shorter) are
/// `head`: the header is checked against `len` (the particle count and the record size
/// give the length) before the records are read, so a file of the wrong length, however
/// large, is refused having read 16 bytes.
fn read_ss_open<T: From<Particle>>(
    file: File,
    len: u64,
    head: Vec<u8>,
    path: &Path,
) -> Result<(f64, Particles<T>), FileError> {
    let name = path.display().to_string();
    if head.len() == 16 {
        let mut x = Xdr {
            bytes: &head,
            at: 0,
        };
        header(&mut x, len, &mut Vec::new()).map_err(|e| FileError::input(&name, e))?;
    }
    let bytes = read_rest(file, len, head, path)?;
    read_ss_as(&bytes).map_err(|e| FileError::input(&name, e))
}

/// Reads the pkdgrav `.ss` file at `path` as [`read_file`] reads one: a path that is not
/// a regular file is refused before it is opened, and the 16-byte header is checked
/// against the file's length before the rest is read. Its time and particles (the
/// warnings not yet located: see [`read_file`]).
pub fn read_ss_file(path: &Path) -> Result<(f64, Particles), FileError> {
    let (mut file, len) = open_regular(path)?;
    let head = read_head(&mut file, 16, path)?;
    read_ss_open(file, len, head, path)
}

/// Reads the file at `path`, or standard input when it is `-`; a path that is not a
/// regular file (a folder, a FIFO, a device) is refused before it is read.
pub fn read_input(path: &str) -> Result<Vec<u8>, FileError> {
    if path == "-" {
        let mut bytes = Vec::new();
        std::io::Read::read_to_end(&mut std::io::stdin().lock(), &mut bytes)
            .map_err(|e| FileError::read("standard input", e))?;
        return Ok(bytes);
    }
    let path = Path::new(path);
    let (file, len) = open_regular(path)?;
    read_rest(file, len, Vec::new(), path)
}

/// Particles from the file at `path` (`-`: standard input), CSV or a pkdgrav `.ss`
/// file ([`format_of`]), the warnings located in it. A path that is not a regular file
/// is refused before it is read; a CSV is read as it streams in (at 10⁶ particles its
/// 124 MB of text, read whole, would lie beside the particles), a `.ss` file's header is
/// checked against the file's length before its records are read ([`read_ss_file`]).
pub fn read_file(path: &str) -> Result<Particles, FileError> {
    read_file_as(path)
}

/// [`read_file`], each particle made a `T` as it is read: a run reads its particles
/// straight into its [`State`]s, so that no array of [`Particle`]s (96 bytes each) is
/// made and freed beside them: a freed array's pages stay resident under mimalloc until
/// it frees another page a second or more later.
pub fn read_file_as<T: From<Particle>>(path: &str) -> Result<Particles<T>, FileError> {
    let name = if path == "-" { "<stdin>" } else { path };
    let read = if path == "-" {
        read_bytes_as(path, &read_input(path)?)
    } else {
        let p = Path::new(path);
        let (mut file, len) = open_regular(p)?;
        let head = read_head(&mut file, 16, p)?;
        match format_of(path, &head) {
            Some(Format::Csv) => read_csv_from(io::Cursor::new(head).chain(file), len),
            Some(Format::Ss) => return Ok(located(name, read_ss_open(file, len, head, p)?.1)),
            // Found by the whole first line, not its first 16 bytes.
            None => read_bytes_as(path, &read_rest(file, len, head, p)?),
        }
    };
    let read = read.map_err(|e| FileError::input(name, e))?;
    Ok(located(name, read))
}

/// A particle file as [`open_input`] gives it to a reader that tells more formats apart
/// than [`read_file`] (the preview's run outputs).
pub enum Opened {
    /// A pkdgrav `.ss` file: its header's time and its particles.
    Ss(f64, Particles),
    /// Anything else (or standard input), as its bytes.
    Bytes(Vec<u8>),
}

/// The file at `path` (`-`: standard input) as [`read_file`] opens it: a path that is
/// not a regular file refused before it is read, a `.ss` file (by its name or its first
/// 16 bytes) read header first ([`read_ss_file`]); anything else read whole.
pub fn open_input(path: &str) -> Result<Opened, FileError> {
    if path == "-" {
        return Ok(Opened::Bytes(read_input(path)?));
    }
    let p = Path::new(path);
    let (mut file, len) = open_regular(p)?;
    let head = read_head(&mut file, 16, p)?;
    if format_of(path, &head) == Some(Format::Ss) {
        let (t, read) = read_ss_open(file, len, head, p)?;
        return Ok(Opened::Ss(t, read));
    }
    Ok(Opened::Bytes(read_rest(file, len, head, p)?))
}

/// `read` with its warnings located in the file `name`.
fn located<T>(name: &str, read: Particles<T>) -> Particles<T> {
    Particles {
        warnings: super::in_file(name, read.warnings),
        ..read
    }
}
