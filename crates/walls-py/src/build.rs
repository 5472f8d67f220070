//! `walls.Wall`, and the calls behind `walls.dumps`, `walls.from_mesh` and
//! `walls.read_mesh` (python/walls/_build.py): the `walls-build` library's builder and
//! meshes, with Python's values (numbers, tuples, lists, NumPy arrays and scalars)
//! converted to the builder's and its refusals raised as `TypeError` or `WallsError`.

use crate::diagnostics::{self, WallsError};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use std::path::PathBuf;
use walls_build::mesh::{self, Mesh, MeshOptions, Orientation};
use walls_build::{
    BuildError, CheckOptions, DumpOptions, Given, LengthUnit, Units, Value, Wall, describe, dumps,
};
use walls_diagnostics::Severity;

/// Adds the class and functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyWall>()?;
    m.add_function(wrap_pyfunction!(_dumps, m)?)?;
    m.add_function(wrap_pyfunction!(_from_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(_read_mesh, m)?)?;
    Ok(())
}

/// A refused token: `TypeError` for a value of the wrong kind, else `WallsError`.
fn refused(e: BuildError) -> PyErr {
    if e.is_type_error() {
        PyTypeError::new_err(e.to_string())
    } else {
        WallsError::new_err(e.to_string())
    }
}

/// A Python value as the builder takes it: bools (Python's and NumPy's), strings, reals,
/// iterables (tuples, lists, NumPy arrays) as lists, other integers (anything with
/// `__index__`: NumPy's) and reals (anything with `__float__`).
fn given(value: &Bound<'_, PyAny>) -> PyResult<Given> {
    let numpy_bool = value
        .get_type()
        .name()
        .is_ok_and(|n| n == "bool_" || n == "bool");
    if value.is_instance_of::<PyBool>() || numpy_bool {
        return Ok(Given::Bool(value.is_truthy()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(Given::Text(value.extract()?));
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(Given::Float(value.extract()?));
    }
    let mapping = value.is_instance_of::<PyDict>() || value.hasattr("keys")?;
    if !value.is_instance_of::<PyInt>() && !mapping && value.hasattr("__iter__")? {
        let items = value.try_iter()?;
        return Ok(Given::List(
            items
                .map(|item| given(&item?))
                .collect::<PyResult<Vec<_>>>()?,
        ));
    }
    if value.is_instance_of::<PyInt>() || value.hasattr("__index__")? {
        let index = value
            .py()
            .import("operator")?
            .call_method1("index", (value,))?;
        return index
            .extract::<i64>()
            .map(Given::Int)
            .or_else(|_| Ok(Given::Float(index.extract::<f64>()?)));
    }
    if value.hasattr("__float__")? {
        return Ok(Given::Float(value.extract()?));
    }
    Err(PyTypeError::new_err(format!(
        "a token's value is a number, a sequence of 3 numbers or a wall type name, not {}",
        value.get_type().name()?
    )))
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
                let name: String = name.extract()?;
                wall.set(&name, given(&value)?).map_err(refused)?;
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
        name: &str,
        value: &Bound<'py, PyAny>,
    ) -> PyResult<PyRefMut<'py, Self>> {
        slf.wall.set(name, given(value)?).map_err(refused)?;
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
    fn __getitem__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        match self.wall.get(name) {
            Some(value) => to_python(py, value),
            None => Err(pyo3::exceptions::PyKeyError::new_err(name.to_string())),
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
        Err(_) => Err(PyTypeError::new_err(format!(
            "defaults must be a Wall or a dict of tokens, not {}",
            value.get_type().name()?
        ))),
    }
}

/// `units` of `walls.dumps`: a length unit's name (`"cm"`), a dict of `lengthunit`,
/// `massunit` and `timeunit`, or None.
fn units(value: Option<&Bound<'_, PyAny>>) -> PyResult<Units> {
    let Some(value) = value.filter(|v| !v.is_none()) else {
        return Ok(Units::new());
    };
    if let Ok(name) = value.extract::<String>() {
        return LengthUnit::named(&name).map(Units::length).ok_or_else(|| {
            PyValueError::new_err(format!(
                "units must name a length unit (mm, cm, m, km, au) or be a dict, not {name:?}"
            ))
        });
    }
    let dict = value.cast::<PyDict>().map_err(|_| {
        PyTypeError::new_err("units must be a length unit's name or a dict of unit tokens")
    })?;
    let mut units = Units::new();
    for (name, x) in dict.iter() {
        let name: String = name.extract()?;
        units.set(&name, given(&x)?).map_err(refused)?;
    }
    Ok(units)
}

/// `walls.dumps`: the text, and each warning as a line for `warnings.warn`.
#[pyfunction]
#[pyo3(signature = (walls, units = None, defaults = None, comment = None, *, mode = "ssdem", max_walls = 20))]
fn _dumps(
    py: Python<'_>,
    walls: &Bound<'_, PyAny>,
    units: Option<&Bound<'_, PyAny>>,
    defaults: Option<&Bound<'_, PyAny>>,
    comment: Option<String>,
    mode: &str,
    max_walls: usize,
) -> PyResult<(String, Vec<String>)> {
    let walls = walls
        .try_iter()?
        .map(|w| {
            let w = w?;
            w.extract::<PyWall>().map(|w| w.wall).map_err(|_| {
                PyTypeError::new_err(format!(
                    "walls must hold Wall objects, not {}",
                    w.get_type()
                        .name()
                        .map(|n| n.to_string())
                        .unwrap_or_default()
                ))
            })
        })
        .collect::<PyResult<Vec<Wall>>>()?;
    let options = DumpOptions {
        units: self::units(units)?,
        defaults: self::defaults(defaults)?,
        comment,
        check: CheckOptions {
            mode: crate::api::contact_model(mode)?,
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

/// A mesh problem as a `WallsError`.
fn mesh_error(e: mesh::Problem) -> PyErr {
    WallsError::new_err(e.to_string())
}

/// `walls.from_mesh`: the walls of a mesh given as arrays.
#[pyfunction]
#[pyo3(signature = (vertices, faces, orientation = "keep", merge_rectangles = false))]
fn _from_mesh(
    py: Python<'_>,
    vertices: Vec<[f64; 3]>,
    faces: Vec<[usize; 3]>,
    orientation: &str,
    merge_rectangles: bool,
) -> PyResult<Vec<PyWall>> {
    let orientation = Orientation::named(orientation).ok_or_else(|| {
        PyValueError::new_err(format!(
            "orientation must be \"keep\", \"outward\" or \"inward\", not {orientation:?}"
        ))
    })?;
    let options = MeshOptions {
        orientation,
        merge_rectangles,
    };
    let walls = py
        .detach(|| Mesh::from_arrays(vertices, &faces).and_then(|m| mesh::to_walls(&m, &options)))
        .map_err(mesh_error)?;
    Ok(walls.into_iter().map(|wall| PyWall { wall }).collect())
}

/// `walls.read_mesh`: the points and faces (indices from 0) of an STL or OBJ file, and
/// its warnings.
#[pyfunction]
fn _read_mesh<'py>(
    py: Python<'py>,
    path: PathBuf,
) -> PyResult<(Bound<'py, PyList>, Bound<'py, PyList>, Vec<String>)> {
    let name = path.display().to_string();
    let read = py
        .detach(|| mesh::read_mesh(&path))
        .map_err(|e| WallsError::new_err(e.in_file(&name)))?;
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
