//! `walls.Wall`, and the calls behind `walls.dumps`, `walls.from_mesh` and
//! `walls.read_mesh` (python/walls/_build.py): the `walls-build` library's builder and
//! meshes, with Python's values (numbers, tuples, lists, NumPy arrays and scalars)
//! converted to the builder's by [`crate::args`], its refusals raised as `TypeError` or
//! `ValueError`, and a mesh's problems as `WallsError`.

use crate::args;
use crate::diagnostics;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use std::path::PathBuf;
use walls_build::mesh::{self, Mesh, MeshOptions, Orientation};
use walls_build::{
    BuildError, CheckOptions, DumpOptions, Given, LengthUnit, Units, Value, Wall, describe, dumps,
};
use walls_diagnostics::Severity;
use walls_keywords::ContactModel;

/// Adds the class and functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyWall>()?;
    m.add_function(wrap_pyfunction!(_dumps, m)?)?;
    m.add_function(wrap_pyfunction!(_from_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(_read_mesh, m)?)?;
    Ok(())
}

/// A refused token: `TypeError` for a value of the wrong kind, else `ValueError` (an
/// unknown keyword or type, a keyword that is not a wall's or a unit).
fn refused(e: BuildError) -> PyErr {
    if e.is_type_error() {
        PyTypeError::new_err(e.to_string())
    } else {
        PyValueError::new_err(e.to_string())
    }
}

/// The token `name` set to `value` by `set` (a wall's or the units'), the value
/// converted for the shape its keyword takes ([`args::token`]).
fn set_token<T>(
    name: &Bound<'_, PyAny>,
    value: &Bound<'_, PyAny>,
    set: impl FnOnce(&str, Given) -> Result<T, BuildError>,
) -> PyResult<()> {
    let name = args::word(name, &"a token's name")?;
    // The builder's own lookup: any case, `_` for `-`; a name it does not know is left
    // for its refusal.
    let shape = walls_keywords::keyword(&name)
        .or_else(|| walls_keywords::keyword(&name.replace('_', "-")))
        .map(|k| k.shape());
    let given = args::token(value, &name, shape)?;
    set(&name, given).map_err(refused)?;
    Ok(())
}

/// A checked value as Python sees it: a float, an int, a tuple of 3 floats or a str.
fn to_python<'py>(py: Python<'py>, value: Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::Number(x) => x.into_pyobject(py)?.into_any(),
        Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        Value::Vector(v) => PyTuple::new(py, v)?.into_any(),
        Value::Type(t) => PyString::new(py, t.name()).into_any(),
    })
}

/// One wall of a walls file: its type and tokens, given as keyword arguments
/// (`Wall(type="triangle", origin=(0, 0, 0), vertex1=…, vertex2=…)`; `osc_ampl` for
/// `osc-ampl`). Each token is checked against the keyword table as it is set.
#[pyclass(name = "Wall", module = "walls", eq, from_py_object)]
#[derive(Clone, PartialEq)]
pub struct PyWall {
    wall: Wall,
}

impl PyWall {
    /// A wall with the tokens of `tokens` (keyword arguments or a dict), in order.
    fn of(tokens: Option<&Bound<'_, PyDict>>) -> PyResult<PyWall> {
        let mut wall = Wall::new();
        if let Some(tokens) = tokens {
            for (name, value) in tokens.iter() {
                set_token(&name, &value, |name, given| wall.set(name, given).map(drop))?;
            }
        }
        Ok(PyWall { wall })
    }
}

#[pymethods]
impl PyWall {
    #[new]
    #[pyo3(signature = (**tokens))]
    fn new(tokens: Option<&Bound<'_, PyDict>>) -> PyResult<PyWall> {
        PyWall::of(tokens)
    }

    /// Sets the token `name` to `value` (checked as the constructor checks it) and
    /// returns the wall.
    fn set<'py>(
        mut slf: PyRefMut<'py, Self>,
        name: &Bound<'py, PyAny>,
        value: &Bound<'py, PyAny>,
    ) -> PyResult<PyRefMut<'py, Self>> {
        set_token(name, value, |name, given| {
            slf.wall.set(name, given).map(drop)
        })?;
        Ok(slf)
    }

    /// The wall's type name, or None for the defaults' type.
    #[getter]
    fn r#type(&self) -> Option<&'static str> {
        self.wall.wall_type()
    }

    /// The tokens, in the order the file writes them: a dict from each canonical name to
    /// its value (a float, an int, a tuple of 3 floats, or the type's name).
    #[getter]
    fn tokens<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (name, value) in self.wall.tokens() {
            dict.set_item(name, to_python(py, value)?)?;
        }
        Ok(dict)
    }

    /// The value of the token `name`; `KeyError` if the wall does not set it.
    fn __getitem__<'py>(
        &self,
        py: Python<'py>,
        name: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let name = args::word(name, &"a token's name")?;
        match self.wall.get(&name) {
            Some(value) => to_python(py, value),
            None => Err(pyo3::exceptions::PyKeyError::new_err(name)),
        }
    }

    fn __repr__(&self) -> String {
        let tokens: Vec<String> = self
            .wall
            .tokens()
            .map(|(name, value)| {
                let shown = match value {
                    Value::Type(t) => format!("'{}'", t.name()),
                    Value::Vector(v) => format!(
                        "({}, {}, {})",
                        walls_build::number(v[0]),
                        walls_build::number(v[1]),
                        walls_build::number(v[2])
                    ),
                    other => other.to_string(),
                };
                format!("{}={shown}", name.replace('-', "_"))
            })
            .collect();
        format!("Wall({})", tokens.join(", "))
    }
}

/// `defaults` of `walls.dumps`: a `Wall`, a dict of tokens, or None.
fn defaults(value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Wall>> {
    let Some(value) = value.filter(|v| !v.is_none()) else {
        return Ok(None);
    };
    if let Ok(wall) = value.extract::<PyWall>() {
        return Ok(Some(wall.wall));
    }
    match value.cast::<PyDict>() {
        Ok(dict) => Ok(Some(PyWall::of(Some(dict))?.wall)),
        Err(_) => Err(args::wrong(
            &"defaults",
            "a Wall or a dict of tokens",
            value,
        )),
    }
}

/// `units` of `walls.dumps`: a length unit's name (`"cm"`), a dict of `lengthunit`,
/// `massunit` and `timeunit`, or None.
fn units(value: Option<&Bound<'_, PyAny>>) -> PyResult<Units> {
    let Some(value) = value.filter(|v| !v.is_none()) else {
        return Ok(Units::new());
    };
    if value.is_instance_of::<PyString>() {
        let name = args::word(value, &"units")?;
        return LengthUnit::named(&name).map(Units::length).ok_or_else(|| {
            PyValueError::new_err(format!(
                "units must name a length unit (mm, cm, m, km, au) or be a dict, not {name:?}"
            ))
        });
    }
    let dict = value.cast::<PyDict>().map_err(|_| {
        args::wrong(
            &"units",
            "a length unit's name or a dict of unit tokens",
            value,
        )
    })?;
    let mut units = Units::new();
    for (name, x) in dict.iter() {
        set_token(&name, &x, |name, given| units.set(name, given).map(drop))?;
    }
    Ok(units)
}

/// `walls` of `walls.dumps`: an iterable of `Wall`s (not a `Wall` itself).
fn walls_of(walls: &Bound<'_, PyAny>) -> PyResult<Vec<Wall>> {
    let not_walls = |w: &Bound<'_, PyAny>| args::wrong(&"walls", "an iterable of Wall objects", w);
    if walls.extract::<PyWall>().is_ok() || walls.is_instance_of::<PyString>() {
        return Err(not_walls(walls));
    }
    walls
        .try_iter()
        .map_err(|_| not_walls(walls))?
        .enumerate()
        .map(|(i, w)| {
            let w = w?;
            w.extract::<PyWall>()
                .map(|w| w.wall)
                .map_err(|_| args::wrong(&args::Item(&"walls", i), "a Wall", &w))
        })
        .collect()
}

/// `walls.dumps`: the text, and each warning as a line for `warnings.warn`.
#[pyfunction]
#[pyo3(
    signature = (walls, units = None, defaults = None, comment = None, *, mode = ContactModel::Ssdem, max_walls = 20),
    text_signature = "(walls, units=None, defaults=None, comment=None, *, mode=\"ssdem\", max_walls=20)"
)]
#[allow(clippy::too_many_arguments)]
fn _dumps<'py>(
    py: Python<'py>,
    walls: &Bound<'py, PyAny>,
    units: Option<&Bound<'py, PyAny>>,
    defaults: Option<&Bound<'py, PyAny>>,
    comment: Option<&Bound<'py, PyAny>>,
    #[pyo3(from_py_with = args::mode)] mode: ContactModel,
    #[pyo3(from_py_with = args::max_walls)] max_walls: usize,
) -> PyResult<(String, Vec<String>)> {
    let walls = walls_of(walls)?;
    let options = DumpOptions {
        units: self::units(units)?,
        defaults: self::defaults(defaults)?,
        comment: args::optional(comment, |v| args::word(v, &"comment"))?,
        check: CheckOptions {
            mode,
            max_walls,
            ..CheckOptions::default()
        },
        ..DumpOptions::default()
    };
    match py.detach(|| dumps(&walls, &options)) {
        Ok(dumped) => {
            let warnings = dumped
                .warnings
                .iter()
                .map(|d| {
                    describe(&dumped.text, std::slice::from_ref(d))
                        .trim_end()
                        .to_string()
                })
                .collect();
            Ok((dumped.text, warnings))
        }
        Err(e) => {
            let errors: Vec<_> = e
                .diagnostics
                .into_iter()
                .filter(|d| d.severity == Severity::Error)
                .collect();
            Err(diagnostics::error(
                py,
                "the walls make a file with errors",
                &e.text,
                &errors,
            ))
        }
    }
}

/// `vertices` of `walls.from_mesh`: rows of 3 numbers.
fn vertices(value: &Bound<'_, PyAny>) -> PyResult<Vec<[f64; 3]>> {
    let rows = args::sequence(value, &"vertices")?;
    rows.iter()
        .enumerate()
        .map(|(i, v)| args::row(v, &args::Item(&"vertices", i), "numbers", args::number))
        .collect()
}

/// `faces` of `walls.from_mesh`: rows of 3 indices of `vertices` rows (from 0).
fn faces(value: &Bound<'_, PyAny>, vertices: usize) -> PyResult<Vec<[usize; 3]>> {
    let rows = args::sequence(value, &"faces")?;
    let index =
        |v: &Bound<'_, PyAny>, name: args::Name<'_>| args::index(v, name, "vertices", vertices);
    rows.iter()
        .enumerate()
        .map(|(i, f)| args::row(f, &args::Item(&"faces", i), "vertex indices", index))
        .collect()
}

/// `walls.from_mesh`: the walls of a mesh given as arrays.
#[pyfunction]
#[pyo3(
    signature = (vertices, faces, orientation = Orientation::Keep, merge_rectangles = false),
    text_signature = "(vertices, faces, orientation=\"keep\", merge_rectangles=False)"
)]
fn _from_mesh<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = args::orientation)] orientation: Orientation,
    #[pyo3(from_py_with = args::merge_rectangles)] merge_rectangles: bool,
) -> PyResult<Vec<PyWall>> {
    let vertices = self::vertices(vertices)?;
    let faces = self::faces(faces, vertices.len())?;
    let options = MeshOptions {
        orientation,
        merge_rectangles,
    };
    let walls = py
        .detach(|| Mesh::from_arrays(vertices, &faces).and_then(|m| mesh::to_walls(&m, &options)))
        .map_err(|e| diagnostics::plain(py, e.to_string()))?;
    Ok(walls.into_iter().map(|wall| PyWall { wall }).collect())
}

/// `walls.read_mesh`: the points and faces (indices from 0) of an STL or OBJ file, and
/// its warnings.
#[pyfunction]
fn _read_mesh<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::path)] path: PathBuf,
) -> PyResult<(Bound<'py, PyList>, Bound<'py, PyList>, Vec<String>)> {
    let name = path.display().to_string();
    let read = py
        .detach(|| mesh::read_mesh(&path))
        .map_err(|e| diagnostics::plain(py, e.in_file(&name)))?;
    let vertices = read
        .mesh
        .vertices
        .iter()
        .map(|&v| PyTuple::new(py, v))
        .collect::<PyResult<Vec<_>>>()?;
    let faces = read
        .mesh
        .faces
        .iter()
        .map(|f| PyTuple::new(py, f.vertices))
        .collect::<PyResult<Vec<_>>>()?;
    let (vertices, faces) = (PyList::new(py, vertices)?, PyList::new(py, faces)?);
    let warnings = read.warnings.iter().map(|w| w.in_file(&name)).collect();
    Ok((vertices, faces, warnings))
}
