//! The syntax diagnostic codes, each documented once with a bad and a good example.
//!
//! Codes are stable: a code is never reused for another meaning. `S0xx` are about the
//! file as text, `S1xx` about statements and values. The examples are tested: each bad
//! example produces its code and each good example produces no diagnostic at all.

use walls_diagnostics::Code;

/// The file is not valid UTF-8.
pub static INVALID_UTF8: Code = Code {
    id: "S001",
    name: "invalid-utf8",
    summary: "the file is not valid UTF-8 text",
    explanation: "A walls file is text. A byte sequence that is not UTF-8 usually means the \
file is binary, or was saved in a legacy encoding with a non-ASCII character in a comment. \
The diagnostic points at the first bad byte; re-save the file as UTF-8 (pkdgrav's keywords \
are all ASCII, so only comments can need anything else).

Bad: a comment `# café` saved in Latin-1, where `é` is the single byte 0xE9.

Good:
```walls
# café
wall type plane
```
",
};

/// The last line does not end with a newline.
pub static MISSING_FINAL_NEWLINE: Code = Code {
    id: "S002",
    name: "missing-final-newline",
    summary: "the last line does not end with a newline",
    explanation: "pkdgrav reads the walls file line by line and aborts when the last line \
has no newline. The fix (safe) appends one; `walls-fmt` always writes one.

Bad: a file whose last line, `wall type plane`, has no newline after it.

Good:
```walls
wall type plane
```
",
};

/// A line longer than pkdgrav's line buffer.
pub static LINE_TOO_LONG: Code = Code {
    id: "S003",
    name: "line-too-long",
    summary: "a line is longer than the 4095 bytes pkdgrav reads at once",
    explanation: "pkdgrav reads each line into a buffer of 4096 bytes, so a line of more \
than 4095 bytes (not counting its newline) is cut and misread. The diagnostic covers the \
bytes past the limit. Split the statements over several lines: every token with its \
values on one line, as `walls-fmt` writes them.

Bad: a generated file with every wall on one line of 5000 bytes.

Good:
```walls
wall type triangle
  origin 1 1 1
  vertex1 0 -2 -2
  vertex2 -2 0 -2
```
",
};

/// A comment glued to the end of a word.
pub static GLUED_COMMENT: Code = Code {
    id: "S004",
    name: "glued-comment",
    summary: "a `#` or `!` comment is glued to the word before it",
    explanation: "pkdgrav starts a comment only at the beginning of a word. `1#x` is read \
as the number 1 followed by more words, and `plane#x` is one unknown word, so the \
comment you meant is not a comment to pkdgrav. The fix (safe) inserts a space before the \
`#` or `!`.

Bad:
```walls
wall type plane#floor
```

Good:
```walls
wall type plane # floor
```
",
};

/// A UTF-8 byte-order mark.
pub static BYTE_ORDER_MARK: Code = Code {
    id: "S005",
    name: "byte-order-mark",
    summary: "a UTF-8 byte-order mark, which pkdgrav reads as part of a word",
    explanation: "Some editors start UTF-8 files with a byte-order mark (the bytes EF BB BF, \
invisible in most editors). pkdgrav does not know it: it reads the mark as the first \
bytes of the word after it, so the file's first `wall` is an unknown word and pkdgrav \
stops. The fix (safe) removes the mark; the rest of the file is checked as if it were \
gone. Save the file as UTF-8 without BOM.

Bad (the file starts with a byte-order mark):
```walls
\u{feff}wall type plane
```

Good:
```walls
wall type plane
```
",
};

/// A control character or a bidirectional control.
pub static CONTROL_CHARACTER: Code = Code {
    id: "S006",
    name: "control-character",
    summary: "a control character or a bidirectional control, which a terminal or an editor acts on instead of showing it",
    explanation: "A walls file is read by pkdgrav, and by people in terminals, editors and code \
review. Some characters are not shown as what they are: the C0 controls other than tab and \
newline (escape, bell, NUL, vertical tab, form feed, a carriage return that does not end a \
line), DEL, the C1 controls (U+0080 to U+009F), the line and paragraph separators (U+2028, \
U+2029) and the bidirectional controls (U+202A to U+202E, U+2066 to U+2069). A terminal \
obeys them: `ESC ] 52 ; c ; … BEL` in a comment sets the clipboard of whoever prints the \
file, a carriage return writes the rest of the line over its start. An editor or a review \
shows a line with a right-to-left override in another order than pkdgrav reads it \
(\"Trojan Source\"). The walls tools show each as an escape: `\\x1b`, `\\u{202e}` \
(docs/diagnostics.md, \"Control characters\").

pkdgrav ignores them in a comment, reads a carriage return, vertical tab or form feed \
between words as a space, and any other as part of the word it stands in (which is then \
an unknown word, S101, or a malformed number, S102). So this is a warning, one for each \
run of such characters, at most 1,000 in a file (the last says how many runs follow). \
Between words, where pkdgrav reads them as a space, the fix \
(safe) replaces them with one. In a comment or a word there is no fix: only the author \
knows what the text should say (right-to-left text in a comment may use the isolates on \
purpose), and the characters are best seen, escaped, before they go.

Bad: a comment holding the bytes `ESC ] 52 ; c ; aGk= BEL`, or `# floor` with a \
right-to-left override (U+202E) after the `#`.

Good:
```walls
# floor
wall type plane
```
",
};

/// A word that is no keyword of the language.
pub static UNKNOWN_WORD: Code = Code {
    id: "S101",
    name: "unknown-word",
    summary: "a word that is not a keyword of the walls language",
    explanation: "pkdgrav stops at a word it does not know. Keywords and type names are \
matched without regard to case, so the usual causes are misspellings (`raduis`), `_` \
written for `-` or the reverse (`osc_ampl`), or a stray word. When a keyword is close, \
the diagnostic suggests it in its help. It offers no fix: a fix never changes what the \
file means, and the statement a guessed keyword makes is read and judged like any other \
(it may set a value a later token overrides, that the wall's type ignores, or that another \
wall inherited from `defaults`). The numbers after an unknown word are taken as its values, \
so they cause no further diagnostics.

Bad:
```walls
wall type disk
  raduis 0.5
```

Good:
```walls
wall type disk
  radius 0.5
```
",
};

/// A malformed number where a number belongs.
pub static INVALID_NUMBER: Code = Code {
    id: "S102",
    name: "invalid-number",
    summary: "a value that should be a number is not a decimal number",
    explanation: "pkdgrav reads numbers with C's `atof`, which silently reads `1.2.3` as \
1.2, `abc` as 0 and `1e` as 1, and accepts `nan`, `inf` and hexadecimal floats. We accept \
only decimal reals: an optional sign, digits with an optional `.` and fraction (`5.`, \
`.5`), and an optional exponent (`1.99102e-07`, `+3E+2`). The message says what pkdgrav \
would have read instead.

Bad:
```walls
wall type disk
  radius 0.5.1
```

Good:
```walls
wall type disk
  radius 0.51
```
",
};

/// A number that is not zero as written but that a double cannot hold.
pub static NUMBER_UNDERFLOW: Code = Code {
    id: "S110",
    name: "number-underflow",
    summary: "a non-zero number too small for a double",
    explanation: "pkdgrav reads numbers with C's `atof`, which turns a number too small for a \
double, such as `1e-400`, into 0 without a word (it only sets `errno`, which pkdgrav does \
not look at): `epsn 1e-400` becomes a sticky wall, `radius 1e-400` a wall of no size. \
This is an error. A number below the smallest normal double (about 2.2e-308), such as \
`1e-310`, is read as a subnormal double with fewer significant digits (again with only \
`errno` set): a warning. Write 0 if you mean 0, or choose units that keep values in range. \
Every number the tools read follows the same rule (`.par`, particle, cohesion and mesh \
files, options): a number that reads as 0 is refused, a subnormal read with a warning, \
each with its file and line or option; a subnormal a program gives (`walls.Wall`, \
`walls.dumps`) gets this warning in the file written.

Bad:
```walls
wall type plane
  epsn 1e-400
```

Good:
```walls
wall type plane
  epsn 0
```
",
};

/// Fewer values than the keyword takes.
pub static MISSING_VALUE: Code = Code {
    id: "S103",
    name: "missing-value",
    summary: "a keyword has fewer values than it takes",
    explanation: "Every keyword takes a fixed number of values on its line: a vector is \
exactly three numbers, `type` one type name, most others one number. The diagnostic \
points where the missing value was expected and says what was found instead.

Bad:
```walls
wall type disk
  origin 1 2
  radius 0.5
```

Good:
```walls
wall type disk
  origin 1 2 0
  radius 0.5
```
",
};

/// More values than the keyword takes.
pub static UNEXPECTED_VALUE: Code = Code {
    id: "S104",
    name: "unexpected-value",
    summary: "a value that no keyword takes",
    explanation: "A value after a keyword's last value, or before the first keyword of the \
file, belongs to nothing: pkdgrav would read it as a keyword and stop. Usually a vector \
has four numbers, or a keyword was deleted.

Bad:
```walls
wall type disk
  origin 1 2 3 4
```

Good:
```walls
wall type disk
  origin 1 2 3
```
",
};

/// A non-integer where pkdgrav reads an integer.
pub static EXPECTED_INTEGER: Code = Code {
    id: "S105",
    name: "expected-integer",
    summary: "a value that pkdgrav reads as an integer is not one",
    explanation: "`color`, `cohesion_model` and `assembly` are read with C's `atoi`, which \
silently truncates: `12.5` becomes 12 and `1e2` becomes 1. Write a whole number.

Bad:
```walls
wall type plane
  color 12.5
```

Good:
```walls
wall type plane
  color 12
```
",
};

/// A wall type that does not exist.
pub static UNKNOWN_WALL_TYPE: Code = Code {
    id: "S106",
    name: "unknown-wall-type",
    summary: "`type` is followed by something that is not a wall type",
    explanation: "The wall types are plane, triangle, rectangle, disk (or disc), \
cylinder-infinite, cylinder-finite and shell, matched without regard to case. When a \
type is close, the diagnostic suggests it in its help (not as a fix: the type decides \
what every other token of the wall means). Until the type reads, the wall is judged by no \
type: the checks that depend on it are silent on the wall.

Bad:
```walls
wall type cylinder
```

Good:
```walls
wall type cylinder-finite
```
",
};

/// Values on a later line than their keyword.
pub static VALUE_ON_OTHER_LINE: Code = Code {
    id: "S107",
    name: "value-on-other-line",
    summary: "a keyword's values are not on the keyword's line",
    explanation: "The document calls the format loose, but pkdgrav reads a keyword's values \
from the keyword's own line. Values on a later line are read as keywords, and the file is \
rejected. The fix (safe, offered when no comment stands in between) joins the lines; \
`walls-fmt` does the same.

Bad:
```walls
wall type disk
  origin 1 2
         3
```

Good:
```walls
wall type disk
  origin 1 2 3
```
",
};

/// A wall property outside any block.
pub static OUTSIDE_BLOCK: Code = Code {
    id: "S108",
    name: "outside-block",
    summary: "a wall token stands outside any `wall` or `defaults` block",
    explanation: "Wall tokens set a property of the wall (or the defaults) being edited. \
Before the first `wall` or `defaults` there is none, and `lengthunit`, `massunit`, \
`timeunit` and `time` close an open wall block (not a defaults block), so a wall token \
after them belongs to no wall until the next `wall` or `defaults`.

Bad:
```walls
wall type disk
lengthunit 2
  radius 0.5
```

Good:
```walls
lengthunit 2
wall type disk
  radius 0.5
```
",
};

/// A type name without `type` before it.
pub static TYPE_NAME_WITHOUT_TYPE: Code = Code {
    id: "S109",
    name: "type-name-without-type",
    summary: "a wall type name stands where a keyword belongs",
    explanation: "A type name is the value of `type`: `wall plane` is read by pkdgrav as \
the keyword `wall` and then an unknown word. The help says where `type` goes; there is \
no fix, since the type decides what every other token of the wall means. Until it reads, \
the wall is judged by no type: the checks that depend on it are silent on the wall.

Bad:
```walls
wall plane
```

Good:
```walls
wall type plane
```
",
};

/// Every syntax code, in code order.
pub static ALL: &[&Code] = &[
    &INVALID_UTF8,
    &MISSING_FINAL_NEWLINE,
    &LINE_TOO_LONG,
    &GLUED_COMMENT,
    &BYTE_ORDER_MARK,
    &CONTROL_CHARACTER,
    &UNKNOWN_WORD,
    &INVALID_NUMBER,
    &MISSING_VALUE,
    &UNEXPECTED_VALUE,
    &EXPECTED_INTEGER,
    &UNKNOWN_WALL_TYPE,
    &VALUE_ON_OTHER_LINE,
    &OUTSIDE_BLOCK,
    &TYPE_NAME_WITHOUT_TYPE,
    &NUMBER_UNDERFLOW,
];
