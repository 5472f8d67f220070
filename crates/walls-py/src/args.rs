//! Every argument of the Python API, converted strictly and in this one place: which
//! Python values are numbers, integers, flags, words and sequences, and the refusals,
//! each naming the argument (docs/python.md, "Arguments").
//!
//! * A value of the wrong kind is a `TypeError`: `bool` (Python's or NumPy's) where a
//!   number is meant, complex numbers, `str` where a number is meant, `bytes`,
//!   `bytearray` and `memoryview` anywhere, sets, mappings and iterators where a sequence
//!   is meant, NumPy dates and durations.
//! * A number is taken exactly or refused with a `ValueError`: an integer outside the
//!   argument's range; NaN and the infinities; a real that overflows a double, or that
//!   is not 0 and would round to 0 (the walls-file rule of S110: a subnormal double is
//!   kept); for an integer, a real that is not exactly whole. A real is rounded to the
//!   nearest double once, as a walls file's decimal is: `np.longdouble`,
//!   `fractions.Fraction`, `decimal.Decimal`, an `int` beyond 2**53.
//! * NumPy: arrays are sequences of their items and a 0-d array is its one item; scalars
//!   and items of every dtype are taken by their kind (`dtype.kind`), never by a cast:
//!   integers and `float16` to `float64` exactly, `longdouble` rounded as above,
//!   `bool_` as a bool, complex, dates, durations, bytes and records refused.

use pyo3::exceptions::{PyOverflowError, PyTypeError, PyUnicodeEncodeError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{
    PyBool, PyByteArray, PyBytes, PyFloat, PyInt, PyList, PyMemoryView, PySequence, PyString,
    PyTuple, PyType,
};
use std::fmt;
use std::ops::RangeInclusive;
use std::path::PathBuf;
use walls_build::Given;
use walls_build::mesh::Orientation;
use walls_keywords::{ContactModel, ValueShape};

/// An argument's name as a message gives it (`radius`, `vertices[4][2]`), made only for
/// a message.
pub type Name<'a> = &'a dyn fmt::Display;

/// The name of an item of an argument: `vertices[4]`.
pub struct Item<'a>(pub Name<'a>, pub usize);

impl fmt::Display for Item<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}[{}]", self.0, self.1)
    }
}

/// A Python value as the API sees it, before it is taken for an argument.
enum Kind<'py> {
    /// `True` or `False`, or NumPy's `bool_`: never a number here.
    Bool(bool),
    /// An integer, exactly: Python's `int`, NumPy's integers, anything with `__index__`.
    Int(Bound<'py, PyInt>),
    /// Any other real: Python's `float`, NumPy's `longdouble`, any `numbers.Real`,
    /// `decimal.Decimal` ([`double`] rounds it).
    Real(Bound<'py, PyAny>),
    /// A `str` (or a subclass: NumPy's `str_`), made a Rust string by [`string`].
    Text(Bound<'py, PyString>),
    /// A sequence: a list, a tuple, a NumPy array, any other `collections.abc.Sequence`
    /// but text and bytes. Its length is asked before its items are made.
    Items(Items<'py>),
    /// Anything else: complex numbers, bytes, None, mappings, sets, iterators, dates.
    Other,
}

/// What `value` is.
fn kind<'py>(value: &Bound<'py, PyAny>) -> PyResult<Kind<'py>> {
    let py = value.py();
    if let Ok(b) = value.cast::<PyBool>() {
        return Ok(Kind::Bool(b.is_true()));
    }
    if let Ok(i) = value.cast::<PyInt>() {
        return Ok(Kind::Int(i.clone()));
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(Kind::Real(value.clone()));
    }
    if let Ok(s) = value.cast::<PyString>() {
        return Ok(Kind::Text(s.clone()));
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        return items(value);
    }
    if value.is_instance_of::<PyBytes>()
        || value.is_instance_of::<PyByteArray>()
        || value.is_instance_of::<PyMemoryView>()
    {
        return Ok(Kind::Other);
    }
    if let Some(numpy) = numpy(py)? {
        if value.is_instance(numpy.ndarray.bind(py))? {
            return array(value, numpy);
        }
        if value.is_instance(numpy.generic.bind(py))? {
            return scalar(value, numpy);
        }
    }
    // `__index__` is Python's protocol of exact integers (PEP 357): `numbers.Integral`
    // and other libraries' integer scalars.
    if value.hasattr("__index__")?
        && let Ok(index) = py.import("operator")?.call_method1("index", (value,))
    {
        return Ok(Kind::Int(index.cast_into::<PyInt>()?));
    }
    static REAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    static DECIMAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    if value.is_instance(REAL.import(py, "numbers", "Real")?)?
        || value.is_instance(DECIMAL.import(py, "decimal", "Decimal")?)?
    {
        return Ok(Kind::Real(value.clone()));
    }
    if value.cast::<PySequence>().is_ok() {
        return items(value);
    }
    Ok(Kind::Other)
}

/// The items of a sequence.
fn items<'py>(value: &Bound<'py, PyAny>) -> PyResult<Kind<'py>> {
    Ok(Kind::Items(Items {
        sequence: value.clone(),
        listed: false,
    }))
}

/// A sequence whose items are made only when its length is right: a vector given a
/// NumPy array of 10**8 numbers is refused without a list of them.
struct Items<'py> {
    sequence: Bound<'py, PyAny>,
    /// Whether the items are the Python values of a NumPy array's (`tolist`, exact for
    /// every dtype but `longdouble`, whose items stay NumPy scalars to be rounded once).
    listed: bool,
}

impl<'py> Items<'py> {
    /// How many items the sequence says it has.
    fn len(&self) -> PyResult<usize> {
        self.sequence.len()
    }

    /// At most `most` items (a sequence may hold more than its length says, without
    /// end: a `Sequence` whose `__getitem__` never raises `IndexError`).
    fn take(&self, most: usize) -> PyResult<Vec<Bound<'py, PyAny>>> {
        let sequence = if self.listed {
            self.sequence.call_method0("tolist")?
        } else {
            self.sequence.clone()
        };
        sequence.try_iter()?.take(most).collect()
    }
}

/// NumPy's two base types, once NumPy is imported (this module never imports it).
struct NumPy {
    ndarray: Py<PyType>,
    generic: Py<PyType>,
}

/// NumPy's types, if the program has imported NumPy.
fn numpy(py: Python<'_>) -> PyResult<Option<&NumPy>> {
    static NUMPY: PyOnceLock<NumPy> = PyOnceLock::new();
    if let Some(numpy) = NUMPY.get(py) {
        return Ok(Some(numpy));
    }
    let modules = py.import("sys")?.getattr("modules")?;
    let Ok(module) = modules.get_item("numpy") else {
        return Ok(None);
    };
    let numpy = NUMPY.get_or_try_init(py, || -> PyResult<NumPy> {
        Ok(NumPy {
            ndarray: module.getattr("ndarray")?.cast_into::<PyType>()?.unbind(),
            generic: module.getattr("generic")?.cast_into::<PyType>()?.unbind(),
        })
    })?;
    Ok(Some(numpy))
}

/// A NumPy dtype's kind (`dtype.kind`: `b`, `i`, `u`, `f`, `c`, `O`, `M`, `m`, `U`, `S`,
/// `V`) and whether its items are wider than a double (`longdouble`).
fn dtype(value: &Bound<'_, PyAny>) -> PyResult<(String, bool)> {
    let dtype = value.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    let wide = kind == "f" && dtype.getattr("itemsize")?.extract::<usize>()? > 8;
    Ok((kind, wide))
}

/// Whether a dtype's kind is never a number, a word or a flag here: dates, durations
/// (whose `item()` may be a plain int of nanoseconds) and records.
fn refused_dtype(kind: &str) -> bool {
    matches!(kind, "M" | "m" | "V")
}

/// A NumPy array: a 0-d array is its item; another is the sequence of its items.
fn array<'py>(value: &Bound<'py, PyAny>, numpy: &NumPy) -> PyResult<Kind<'py>> {
    let (dtype, wide) = self::dtype(value)?;
    if refused_dtype(&dtype) {
        return Ok(Kind::Other);
    }
    if value.getattr("ndim")?.extract::<usize>()? == 0 {
        // A NumPy scalar, or the object an object array holds.
        let item = value.get_item(())?;
        return if item.is_instance(numpy.generic.bind(value.py()))? {
            scalar(&item, numpy)
        } else {
            self::item(&item, numpy)
        };
    }
    Ok(Kind::Items(Items {
        sequence: value.clone(),
        listed: !wide,
    }))
}

/// A NumPy scalar: a `longdouble` rounded to a double, any other as its Python value
/// (`item()`: `int`, `float`, `bool`, `complex`, `str` or `bytes`, exactly).
fn scalar<'py>(value: &Bound<'py, PyAny>, numpy: &NumPy) -> PyResult<Kind<'py>> {
    let (dtype, wide) = self::dtype(value)?;
    if refused_dtype(&dtype) {
        Ok(Kind::Other)
    } else if wide {
        Ok(Kind::Real(value.clone()))
    } else {
        item(&value.call_method0("item")?, numpy)
    }
}

/// The item of a 0-d array or a NumPy scalar: a Python value, or a NumPy scalar of its
/// own (`clongdouble.item()`, a `longdouble` in an object array). Another array or
/// scalar here is refused, not followed: an object array may hold itself.
fn item<'py>(item: &Bound<'py, PyAny>, numpy: &NumPy) -> PyResult<Kind<'py>> {
    let py = item.py();
    if item.is_instance(numpy.ndarray.bind(py))? {
        return Ok(Kind::Other);
    }
    if item.is_instance(numpy.generic.bind(py))? {
        let (dtype, wide) = self::dtype(item)?;
        return Ok(if wide && !refused_dtype(&dtype) {
            Kind::Real(item.clone())
        } else {
            Kind::Other
        });
    }
    kind(item)
}

/// A real as the nearest double, and whether that is the value itself; refused when it
/// is NaN or an infinity, overflows a double, or is not 0 and rounds to 0.
fn double(value: &Bound<'_, PyAny>, name: Name<'_>) -> PyResult<(f64, bool)> {
    if let Ok(f) = value.cast::<PyFloat>() {
        return Ok((finite(name, value, f.value())?, true));
    }
    let x = match value.extract::<f64>() {
        Ok(x) => x,
        Err(e) if e.is_instance_of::<PyOverflowError>(value.py()) => {
            return Err(too_large(name, value));
        }
        // `Decimal("sNaN")`: "cannot convert signaling NaN to float".
        Err(e) if e.is_instance_of::<PyValueError>(value.py()) => f64::NAN,
        Err(e) => return Err(e),
    };
    if x.is_infinite() && !value.eq(x)? {
        return Err(too_large(name, value));
    }
    let x = finite(name, value, x)?;
    if x == 0.0 && !value.eq(0)? {
        return Err(PyValueError::new_err(format!(
            "{name} is {}, too small for a double: it would be read as 0 (write 0 if you mean 0)",
            shown(value)
        )));
    }
    Ok((x, value.eq(x)?))
}

/// `x`, the double of `value`, if it is finite.
fn finite(name: Name<'_>, value: &Bound<'_, PyAny>, x: f64) -> PyResult<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(PyValueError::new_err(format!(
            "{name} must be a finite number, not {}",
            shown(value)
        )))
    }
}

/// The refusal of a number too large for a double.
fn too_large(name: Name<'_>, value: &Bound<'_, PyAny>) -> PyErr {
    PyValueError::new_err(format!(
        "{name} is {}, too large for a double (at most 1.7976931348623157e308)",
        shown(value)
    ))
}

/// A value as a message shows it: its `str`, shortened past 60 characters (an int
/// of a thousand digits, a long array).
fn shown(value: &Bound<'_, PyAny>) -> String {
    let text = match value.str() {
        Ok(text) => text.to_string(),
        // An int past Python's limit of digits (`sys.set_int_max_str_digits`).
        Err(_) => match value.call_method0("bit_length") {
            Ok(bits) => return format!("an integer of {bits} bits"),
            Err(_) => return format!("a {} that cannot be shown", type_name(value)),
        },
    };
    match text.char_indices().nth(60) {
        Some((cut, _)) => format!("{}… ({} characters)", &text[..cut], text.chars().count()),
        None => text,
    }
}

/// The name of a value's type, with its module unless it is a builtin
/// (`numpy.complex128`, `complex`).
fn type_name(value: &Bound<'_, PyAny>) -> String {
    value
        .get_type()
        .fully_qualified_name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "value".to_string())
}

/// The refusal of a value of the wrong kind: "`name` must be `what`, not `type`".
pub fn wrong(name: Name<'_>, what: &str, value: &Bound<'_, PyAny>) -> PyErr {
    PyTypeError::new_err(format!("{name} must be {what}, not {}", type_name(value)))
}

/// The refusal of an integer out of `range`.
fn out_of_range(name: Name<'_>, range: &RangeInclusive<i128>, value: &Bound<'_, PyAny>) -> PyErr {
    PyValueError::new_err(format!(
        "{name} must be an integer from {} to {}, not {}",
        range.start(),
        range.end(),
        shown(value)
    ))
}

/// An integer argument in `range` (`max_walls`, `indent_width`): an `int` or a NumPy
/// integer, never a bool or a real.
pub fn integer(
    value: &Bound<'_, PyAny>,
    name: Name<'_>,
    range: RangeInclusive<i128>,
) -> PyResult<i128> {
    match kind(value)? {
        Kind::Int(i) => within(&i, name, range),
        _ => Err(wrong(name, "an integer", value)),
    }
}

/// An index of a sequence argument of `len` items (`faces[0][1]`, an index of
/// `vertices`), from 0.
pub fn index(value: &Bound<'_, PyAny>, name: Name<'_>, of: &str, len: usize) -> PyResult<usize> {
    if let Ok(i) = value.cast_exact::<PyInt>()
        && let Ok(n) = i.extract::<usize>()
        && n < len
    {
        return Ok(n);
    }
    let i = match kind(value)? {
        Kind::Int(i) => i,
        _ => return Err(wrong(name, "an integer", value)),
    };
    match i.extract::<usize>() {
        Ok(n) if n < len => Ok(n),
        _ if len == 0 => Err(PyValueError::new_err(format!(
            "{name} must be an index of {of}, which is empty, not {}",
            shown(value)
        ))),
        _ => Err(PyValueError::new_err(format!(
            "{name} must be an index of {of}, from 0 to {}, not {}",
            len - 1,
            shown(value)
        ))),
    }
}

/// The integer `i` if it lies in `range`.
fn within(i: &Bound<'_, PyInt>, name: Name<'_>, range: RangeInclusive<i128>) -> PyResult<i128> {
    match i.extract::<i128>() {
        Ok(n) if range.contains(&n) => Ok(n),
        _ => Err(out_of_range(name, &range, i.as_any())),
    }
}

/// A number argument (`min_radius`, `dt`, `time`, a vertex's coordinate): an `int`, a
/// `float` or any real (rounded once to the nearest double), finite and not a non-zero
/// number that rounds to 0.
pub fn number(value: &Bound<'_, PyAny>, name: Name<'_>) -> PyResult<f64> {
    if let Ok(f) = value.cast_exact::<PyFloat>() {
        return finite(name, value, f.value());
    }
    match kind(value)? {
        Kind::Int(i) => real_of_int(&i, name),
        Kind::Real(real) => Ok(double(&real, name)?.0),
        _ => Err(wrong(name, "a number", value)),
    }
}

/// An `int` as the nearest double (exact up to 2**53), refused when it overflows.
fn real_of_int(i: &Bound<'_, PyInt>, name: Name<'_>) -> PyResult<f64> {
    i.extract::<f64>().map_err(|_| too_large(name, i.as_any()))
}

/// A flag (`strict`, `merge_rectangles`, …): `True` or `False` (or NumPy's `bool_`),
/// never 0, 1 or None.
pub fn flag(value: &Bound<'_, PyAny>, name: Name<'_>) -> PyResult<bool> {
    match kind(value)? {
        Kind::Bool(b) => Ok(b),
        _ => Err(wrong(name, "True or False", value)),
    }
}

/// A `str` argument (`comment`, a token's name, a wall type's name), never `bytes`.
pub fn word(value: &Bound<'_, PyAny>, name: Name<'_>) -> PyResult<String> {
    match kind(value)? {
        Kind::Text(text) => string(&text, name),
        _ => Err(wrong(name, "a str", value)),
    }
}

/// A `str` as UTF-8, refused (`UnicodeEncodeError`, a `ValueError`) with the argument's
/// name when it holds a lone surrogate (`"\ud800"`), which no file can hold.
fn string(text: &Bound<'_, PyString>, name: Name<'_>) -> PyResult<String> {
    text.to_cow().map(|t| t.into_owned()).map_err(|e| {
        let py = text.py();
        if e.is_instance_of::<PyUnicodeEncodeError>(py) {
            PyValueError::new_err(format!("{name} is not UTF-8 text: {}", e.value(py)))
        } else {
            e
        }
    })
}

/// A walls file as Python hands it over.
pub enum Text {
    /// A `str`.
    Str(String),
    /// `bytes`, to decode as a file's are.
    Bytes(Vec<u8>),
}

/// The `text` of `walls.lint`, `walls.format` and `walls.scene`: a `str`, or `bytes`
/// (or a subclass of either) read as a file is.
pub fn text(value: &Bound<'_, PyAny>) -> PyResult<Text> {
    if let Ok(bytes) = value.cast::<PyBytes>() {
        return Ok(Text::Bytes(bytes.as_bytes().to_vec()));
    }
    match kind(value)? {
        Kind::Text(text) => string(&text, &"text").map(Text::Str),
        _ => Err(wrong(&"text", "str or bytes", value)),
    }
}

/// One of a few names (`mode`, `orientation`): the value `choices` pairs it with.
pub fn choice<T: Copy>(
    value: &Bound<'_, PyAny>,
    name: Name<'_>,
    choices: &[(&str, T)],
) -> PyResult<T> {
    let names = || {
        let quoted: Vec<String> = choices.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        match quoted.split_last() {
            Some((last, [])) => last.clone(),
            Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
            None => String::new(),
        }
    };
    let given = match kind(value)? {
        Kind::Text(text) => string(&text, name)?,
        _ => return Err(wrong(name, &names(), value)),
    };
    choices
        .iter()
        .find(|(n, _)| *n == given)
        .map(|&(_, t)| t)
        .ok_or_else(|| PyValueError::new_err(format!("{name} must be {}, not {given:?}", names())))
}

/// The items of a sequence argument (`walls`, `vertices`, `faces`, a row of them): a
/// list, a tuple, a NumPy array or any `Sequence` but text and bytes, never a set, a
/// mapping or an iterator (whose order or length is not the caller's to see).
pub fn sequence<'py>(
    value: &Bound<'py, PyAny>,
    name: Name<'_>,
) -> PyResult<Vec<Bound<'py, PyAny>>> {
    match kind(value)? {
        Kind::Items(items) => items.take(items.len()?),
        _ => Err(wrong(
            name,
            "a sequence (a list, a tuple or a NumPy array)",
            value,
        )),
    }
}

/// A row of exactly `N` values of a sequence argument (`vertices[4]`, `faces[0]`), each
/// converted by `each` under its own name (`vertices[4][2]`).
pub fn row<T: Copy + Default, const N: usize>(
    value: &Bound<'_, PyAny>,
    name: Name<'_>,
    what: &str,
    each: impl Fn(&Bound<'_, PyAny>, Name<'_>) -> PyResult<T>,
) -> PyResult<[T; N]> {
    let what = || format!("a sequence of {N} {what}");
    let mut out = [T::default(); N];
    // A list or a tuple (the rows of a mesh, `tolist`'s): its items as they are.
    if let Ok(list) = value.cast_exact::<PyList>()
        && list.len() == N
    {
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = each(&list.get_item(i)?, &Item(name, i))?;
        }
        return Ok(out);
    }
    let items = match kind(value)? {
        Kind::Items(items) => items,
        _ => return Err(wrong(name, &what(), value)),
    };
    let len = items.len()?;
    if len != N {
        return Err(PyTypeError::new_err(format!(
            "{name} must be {}, not a sequence of {len}",
            what()
        )));
    }
    let items = items.take(N + 1)?;
    if items.len() != N {
        return Err(PyTypeError::new_err(format!(
            "{name} must be {}: its length is {N} but it holds {} items",
            what(),
            if items.len() > N { "more" } else { "fewer" }
        )));
    }
    for (i, (slot, item)) in out.iter_mut().zip(&items).enumerate() {
        *slot = each(item, &Item(name, i))?;
    }
    Ok(out)
}

/// A token's value, of the shape its keyword takes, as the builder is given it: a word
/// for `type`, a double for a number, three for a vector, and for an integer an `int`
/// (or a real that is exactly whole) that fits 64 bits. `None` (a name no keyword has,
/// or a block keyword) leaves the refusal of the name to the builder.
pub fn token(
    value: &Bound<'_, PyAny>,
    name: Name<'_>,
    shape: Option<ValueShape>,
) -> PyResult<Given> {
    let Some(shape) = shape.filter(|s| *s != ValueShape::None) else {
        return Ok(Given::List(Vec::new()));
    };
    let what = shape.describe();
    match shape {
        ValueShape::TypeName => match kind(value)? {
            Kind::Text(text) => string(&text, name).map(Given::Text),
            _ => Err(wrong(name, what, value)),
        },
        ValueShape::Number => number(value, name).map(Given::Float),
        ValueShape::Vector => {
            let v: [f64; 3] = row(value, name, "numbers", number)?;
            Ok(Given::from(v))
        }
        ValueShape::Integer => {
            let range = i128::from(i64::MIN)..=i128::from(i64::MAX);
            match kind(value)? {
                Kind::Int(i) => within(&i, name, range).map(|n| Given::Int(n as i64)),
                Kind::Real(real) => {
                    let (x, exact) = double(&real, name)?;
                    // 2**63: the doubles from -2**63 up to it (exclusive) are i64s.
                    let bound = -(i64::MIN as f64);
                    if !(-bound..bound).contains(&x) {
                        Err(out_of_range(name, &range, value))
                    } else if exact && x.fract() == 0.0 {
                        Ok(Given::Int(x as i64))
                    } else {
                        Err(PyValueError::new_err(format!(
                            "{name} must be an integer, not {} (pkdgrav would read it with atoi, dropping the fraction)",
                            shown(value)
                        )))
                    }
                }
                _ => Err(wrong(name, what, value)),
            }
        }
        ValueShape::None => unreachable!("filtered above"),
    }
}

/// `mode`: the contact model, by the name the tools' `--mode` takes.
pub fn mode(value: &Bound<'_, PyAny>) -> PyResult<ContactModel> {
    choice(
        value,
        &"mode",
        &[
            ("ssdem", ContactModel::Ssdem),
            ("hsdem", ContactModel::Hsdem),
        ],
    )
}

/// An optional argument (`max_walls=None`): None is the default.
pub fn optional<'py, T>(
    value: Option<&Bound<'py, PyAny>>,
    convert: impl FnOnce(&Bound<'py, PyAny>) -> PyResult<T>,
) -> PyResult<Option<T>> {
    value.filter(|v| !v.is_none()).map(convert).transpose()
}

/// `max_walls`: pkdgrav's MAX_NUM_WALLS, any count `--max-walls` takes.
pub fn max_walls(value: &Bound<'_, PyAny>) -> PyResult<usize> {
    let n = integer(value, &"max_walls", 0..=usize::MAX as i128)?;
    Ok(usize::try_from(n).expect("within usize's range"))
}

/// `strict` of `walls.scene`.
pub fn strict(value: &Bound<'_, PyAny>) -> PyResult<bool> {
    flag(value, &"strict")
}

/// `merge_rectangles` of `walls.from_mesh`.
pub fn merge_rectangles(value: &Bound<'_, PyAny>) -> PyResult<bool> {
    flag(value, &"merge_rectangles")
}

/// `orientation` of `walls.from_mesh`.
pub fn orientation(value: &Bound<'_, PyAny>) -> PyResult<Orientation> {
    choice(value, &"orientation", Orientation::ALL)
}

/// `path` of `walls.read_mesh`: a `str` or an `os.PathLike` (never `bytes`), without a
/// NUL character (which no file name holds: Python's `open` refuses it too).
pub fn path(value: &Bound<'_, PyAny>) -> PyResult<PathBuf> {
    let bytes = value.is_instance_of::<PyBytes>() || value.is_instance_of::<PyByteArray>();
    match value.extract::<PathBuf>() {
        Ok(path) if path.as_os_str().as_encoded_bytes().contains(&0) => {
            Err(PyValueError::new_err("path must not hold a NUL character"))
        }
        Ok(path) if !bytes => Ok(path),
        _ => Err(wrong(&"path", "a str or an os.PathLike", value)),
    }
}
