//! `ssdraw.par` read as ssdraw reads it (docs/pkdgrav-physics.md §16, docs/preview.md
//! "ssdraw's view"): a file in the style of pkdgrav's own to the exact values, labels as
//! exact prefixes with the first line used, the labels ssdraw needs reported by name,
//! and every value the preview cannot read refused with its line, whatever the bytes.

use nalgebra::Vector3;
use walls_preview::ssdraw::{LABELS, MAX_LINE, MAX_LINES, SsdrawView, read};

/// An ssdraw.par as pkdgrav's tests write them: labels padded with blanks to a column,
/// `!` comments after the values. `Particle shape` 2 (POV-Ray), so the POV-Ray labels
/// are needed too.
const PKDGRAV_STYLE: &str = "\
# ssdraw.par for soft_sphere_cube
Length unit             1               ! in AU
Time unit               1               ! in yr/2pi
Frame size              640 480         ! pixels
Light source option     0               ! 0=at camera
Light source position   0 0 0           ! Abs or rel coords
Light source intensity  1               ! 0 to 1
Camera option           0               ! 0=abs, 1=rel
Camera position         1e-12 2e-12 3e-12 ! Abs or rel coords of camera
View option             0               ! 0=look at, 1=direction
Look at/view direction  -4.5e-13 0 +2.5E-13 ! Abs or rel coords
Focus distance          0               ! 0=auto
Sky vector              0 0 1           ! the up vector
Starting view size      0               ! 0=auto
View scaling criterion  0
Scale length by radius? 0               ! 0=no
View target zoom factor 1
Particle shape          2               ! 0 point, 1 solid sphere, 2 POV-Ray
Particle radius scaling 1
Color override          0               ! 0=none
Draw color first        0
Start at COM?           0               ! 0=no
Inertia control         0
Use sliding patches?    0
Wall data file          walls.dat       ! the walls
Wall time offset        0.125           ! 0: the walls file's own time
Shape file              none
Renormalize?            1
Aspect ratio            1.5             ! width/height
Camera light intensity  0.3
Blob threshold          0
Highlight index         -1
";

fn v(x: f64, y: f64, z: f64) -> Option<Vector3<f64>> {
    Some(Vector3::new(x, y, z))
}

fn error(text: &[u8]) -> String {
    read(text).unwrap_err().to_string()
}

#[test]
fn a_pkdgrav_style_file_reads_to_the_exact_values() {
    let view = read(PKDGRAV_STYLE).unwrap();
    assert_eq!(view.camera, v(1e-12, 2e-12, 3e-12));
    assert_eq!(view.look_at, v(-4.5e-13, 0.0, 2.5e-13));
    assert_eq!(view.up, v(0.0, 0.0, 1.0));
    assert_eq!(view.walls_file.as_deref(), Some("walls.dat"));
    assert_eq!(view.wall_time_offset, Some(0.125));
    assert_eq!(view.aspect, Some(1.5));
    assert_eq!(view.missing, Vec::<&str>::new(), "every label is there");
    // The options the preview reads but does not follow are told, with their values.
    let notes: Vec<(usize, &str)> = (view.notes.iter())
        .map(|n| (n.line, n.message.as_str()))
        .collect();
    assert_eq!(notes.len(), 2, "{notes:?}");
    assert_eq!(notes[0].0, 8);
    assert!(
        notes[0]
            .1
            .starts_with("`Camera option` `0` is read but not followed")
    );
    assert_eq!(notes[1].0, 10);
    assert!(
        notes[1]
            .1
            .starts_with("`View option` `0` is read but not followed")
    );
    // Every other label ssdraw reads is listed as not used, by its line.
    let unused: Vec<&str> = view.unused.iter().map(|(_, l)| *l).collect();
    assert_eq!(unused.len(), 31 - 8, "{unused:?}");
    assert_eq!(view.unused[0], (2, "Length unit"));
    assert!(view.unused.contains(&(18, "Particle shape")));
    assert!(view.unused.contains(&(32, "Highlight index")));
}

#[test]
fn a_missing_label_is_reported_by_name() {
    let without = |label: &str| -> String {
        (PKDGRAV_STYLE.lines())
            .filter(|l| !l.starts_with(label))
            .map(|l| format!("{l}\n"))
            .collect()
    };
    for label in [
        "Time unit",
        "Sky vector",
        "Use sliding patches?",
        "Blob threshold",
    ] {
        let view = read(without(label)).unwrap();
        assert_eq!(view.missing, [label], "{label}");
    }
    // `Wall time offset` is needed only when a walls file is named (an empty value
    // names none).
    let no_walls = without("Wall time offset").replace("walls.dat ", "          ");
    let view = read(&no_walls).unwrap();
    assert_eq!(view.walls_file, None);
    assert_eq!(view.missing, Vec::<&str>::new());
    let view = read(without("Wall time offset")).unwrap();
    assert_eq!(view.missing, ["Wall time offset"]);
    // The POV-Ray labels are needed only for POV-Ray output (`Particle shape` 2).
    let spheres = without("Aspect ratio").replace("shape          2", "shape          1");
    assert_eq!(read(&spheres).unwrap().missing, Vec::<&str>::new());
    assert_eq!(
        read(without("Aspect ratio")).unwrap().missing,
        ["Aspect ratio"]
    );
    // An empty file lacks every label ssdraw always reads, in §16's order.
    let empty = read("").unwrap();
    assert_eq!(
        empty,
        SsdrawView {
            missing: LABELS[..24].iter().map(|(l, _)| *l).collect(),
            ..SsdrawView::default()
        }
    );
    assert_eq!(empty.missing[0], "Length unit");
    assert_eq!(empty.missing[23], "Wall data file");
}

#[test]
fn labels_are_exact_prefixes_and_the_first_line_is_read() {
    // What follows the label is its value: `=2`, `(the up vector) 0 1 0`.
    assert_eq!(
        error(b"Frame size 1\nAspect ratio=2\n"),
        "line 2: `Aspect ratio` takes 1 number, not `=2`: `=2` is not a number"
    );
    assert_eq!(
        error(b"Sky vector (the up vector) 0 1 0"),
        "line 1: `Sky vector` takes 3 numbers, not `(the up vector) 0 1 0`: `(the` is not a number"
    );
    let view = read(
        "Camera position 1 2 3\n\
         Camera position 4 5 6\n\
         camera position 7 8 9\n  Camera position 7 8 9\n\
         Camera  position 7 8 9\n\
         Sky vector0 1 0\n\
         Wall data fileX.walls\n",
    )
    .unwrap();
    assert_eq!(view.camera, v(1.0, 2.0, 3.0), "the first line is read");
    // The label is a prefix: what follows it is the value, blank or not.
    assert_eq!(view.up, v(0.0, 1.0, 0.0));
    assert_eq!(view.walls_file.as_deref(), Some("X.walls"));
    let notes: Vec<(usize, &str)> = (view.notes.iter())
        .map(|n| (n.line, n.message.as_str()))
        .collect();
    assert_eq!(
        notes,
        [
            (
                2,
                "`Camera position` again: ssdraw reads line 1's (the first), and so does the preview; this line is not read"
            ),
            (
                3,
                "`camera position 7 8 9` starts with no label ssdraw reads: ssdraw ignores the line, and so does the preview (ssdraw's labels are exact, case-sensitive and start the line: `Camera position`?)"
            ),
            (
                4,
                "`Camera position 7 8 9` starts with no label ssdraw reads: ssdraw ignores the line, and so does the preview (ssdraw's labels are exact, case-sensitive and start the line: `Camera position`?)"
            ),
            (
                5,
                "`Camera  position 7 8 9` starts with no label ssdraw reads: ssdraw ignores the line, and so does the preview"
            ),
        ]
    );
    // A label with trailing junk before its value is not read as the label's value.
    assert_eq!(
        error(b"Camera positions 1 2 3"),
        "line 1: `Camera position` takes 3 numbers, not `s 1 2 3`: `s` is not a number"
    );
}

#[test]
fn comments_and_line_endings() {
    let view = read(
        "# a comment line\r\n\
         Camera position 1 2 3 # the camera ! both cut\r\n\
         Sky vector 0 0 1!no blank before the comment\r\n\
         Wall data file walls#1.dat\r\n\
         Aspect ratio 2\r\n",
    )
    .unwrap();
    assert_eq!(view.camera, v(1.0, 2.0, 3.0));
    assert_eq!(view.up, v(0.0, 0.0, 1.0));
    // `#` cuts the line wherever it is, in a file name too (as ssdraw reads it).
    assert_eq!(view.walls_file.as_deref(), Some("walls"));
    assert_eq!(view.aspect, Some(2.0));
    assert_eq!(view.notes, []);
}

#[test]
fn values_the_preview_cannot_read_are_refused_with_their_line() {
    for (text, message) in [
        (
            &b"\nCamera position 1 2\n"[..],
            "line 2: `Camera position` takes 3 numbers, not `1 2`",
        ),
        (
            b"Camera position 1 2 3 4",
            "line 1: `Camera position` takes 3 numbers, not `1 2 3 4`",
        ),
        (
            b"Camera position = 1 2 3",
            "line 1: `Camera position` takes 3 numbers, not `= 1 2 3`: `=` is not a number",
        ),
        (
            b"Look at/view direction 1e400 0 0",
            "line 1: `Look at/view direction` takes 3 numbers, not `1e400 0 0`: `1e400` is too large for a double: pkdgrav reads it as infinity",
        ),
        (
            b"Sky vector 0 0 1e-400",
            "line 1: `Sky vector` takes 3 numbers, not `0 0 1e-400`: `1e-400` is too small for a double: pkdgrav reads it as 0",
        ),
        (
            b"Sky vector nan 0 1",
            "line 1: `Sky vector` takes 3 numbers, not `nan 0 1`: `nan` is not a finite number",
        ),
        (
            b"Wall time offset 0x10",
            "line 1: `Wall time offset` takes 1 number, not `0x10`: `0x10` is not a number",
        ),
        (
            b"Aspect ratio -1",
            "line 1: `Aspect ratio` must be above 0, not -1",
        ),
        (
            b"Aspect ratio 0",
            "line 1: `Aspect ratio` must be above 0, not 0",
        ),
        (
            b"Particle shape 2.5",
            "line 1: `Particle shape` takes a whole number (0 point, 1 solid sphere, 2 POV-Ray), not `2.5`",
        ),
        // Control characters are shown escaped, never written to the terminal as they are.
        (
            b"Camera position 1 2 \x1b[31m3",
            "line 1: `Camera position` takes 3 numbers, not `1 2 \\u{1b}[31m3`: `\\u{1b}[31m3` is not a number",
        ),
        (
            b"Camera position 1 2 3\x00",
            "line 1: `Camera position` takes 3 numbers, not `1 2 3\\u{0}`: `3\\u{0}` is not a number",
        ),
        (
            b"Wall data file a\x07b.walls",
            "line 1: `Wall data file` names a file with the control character \\u{7}: `a\\u{7}b.walls`",
        ),
        (
            b"Look at/view direction 1 2 3\nCamera position 1 2 3",
            "line 1: `Look at/view direction` is `Camera position` (line 2): a camera at the point it looks at looks nowhere",
        ),
        (
            b"Wall data file w\xffalls",
            "line 1: `Wall data file`'s value is not UTF-8 text",
        ),
    ] {
        assert_eq!(error(text), message, "{}", String::from_utf8_lossy(text));
    }
}

#[test]
fn lines_beyond_ssdraws_limits_are_refused() {
    // At most 256 characters a line (the line ending left out), 1000 lines.
    let longest = format!("Camera position 1 2 3 !{}\r\n", "x".repeat(MAX_LINE - 23));
    assert!(read(&longest).is_ok());
    let longer = format!("\n{}", longest.replace("!", "!x"));
    assert_eq!(
        error(longer.as_bytes()),
        "line 2: longer than the 256 characters a line ssdraw reads (it would split the line)"
    );
    // A 10 MB line is refused as soon as it is seen, and not quoted.
    let huge = vec![b'a'; 10_000_000];
    assert_eq!(
        error(&huge),
        "line 1: longer than the 256 characters a line ssdraw reads (it would split the line)"
    );
    let most = "! comment\n".repeat(MAX_LINES);
    assert!(read(&most).is_ok());
    assert_eq!(
        error(format!("{most}\n").as_bytes()),
        "line 1001: ssdraw reads at most 1000 lines; this file has more"
    );
}

#[test]
fn odd_bytes_in_lines_the_preview_does_not_read_are_told_not_fatal() {
    // Bytes that are not UTF-8, or control characters, in a line ssdraw does not read
    // (or in a comment) are shown, escaped, and the file is read.
    let view = read(b"Bl\xe9 \x01\nCamera position 1 2 3 ! caf\xe9\n\x00\n").unwrap();
    assert_eq!(view.camera, v(1.0, 2.0, 3.0));
    assert_eq!(view.notes.len(), 2);
    assert!(
        view.notes[0]
            .message
            .starts_with("`Bl\u{fffd} \\u{1}` starts with no label"),
        "{:?}",
        view.notes
    );
    assert!(
        view.notes[1]
            .message
            .starts_with("`\\u{0}` starts with no label")
    );
    // A line of blanks (or a lone `\r`) is no line to tell.
    assert_eq!(read(" \t\r\n\r\n\n").unwrap().notes, []);
}

#[test]
fn arbitrary_bytes_never_panic_and_errors_name_a_line_of_the_file() {
    // Lines made of pieces of real ones, numbers of every kind, blanks, comments and
    // stray bytes, from a fixed xorshift: every input reads or is refused at one of its
    // lines.
    let mut pieces: Vec<&[u8]> = LABELS.iter().map(|(l, _)| l.as_bytes()).collect();
    pieces.extend([
        &b" "[..],
        b"\t",
        b"  ",
        b"\n",
        b"\r\n",
        b"\r",
        b"!",
        b"#",
        b"0",
        b"-1.5e-3",
        b"1e400",
        b"1e-400",
        b"4.9e-324",
        b"nan",
        b"x",
        b"=",
        b"\xff",
        b"\xe9",
        b"\x00",
        b"\x1b",
        b"walls.dat",
        "…".as_bytes(),
    ]);
    let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for _ in 0..20_000 {
        let n = next() % 40;
        let bytes: Vec<u8> = (0..n)
            .flat_map(|_| {
                pieces[(next() % pieces.len() as u64) as usize]
                    .iter()
                    .copied()
            })
            .collect();
        let lines = bytes.split(|&b| b == b'\n').count();
        if let Err(e) = read(&bytes) {
            assert!(
                (1..=lines).contains(&e.line),
                "{e} for {:?}",
                String::from_utf8_lossy(&bytes)
            );
            assert!(!e.message.contains(['\0', '\x1b', '\r']), "{e:?}");
        }
    }
}
