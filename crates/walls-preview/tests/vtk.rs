//! The VTK PolyData that `walls_preview::vtk::write` writes, read back by an independent
//! reader: VTK's own `vtkXMLPolyDataReader`, from the `vtk` wheel on PyPI (meshio, the
//! lighter choice, reads `.vtu` but not `.vtp`). `scripts/install-test-tools` installs
//! it. The reader must see every point, one vertex cell per particle, one triangle per
//! mesh triangle, cell and point arrays as long as the cells and points, and the same
//! coordinates and values that were written.

mod vtk_reader;

use nalgebra::Vector3;
use serde_json::Value;
use std::path::Path;
use vtk_reader::read_back;
use walls_geometry::Particle;
use walls_geometry::units::Scale;
use walls_model::{Options, analyze};
use walls_preview::{vtk, wall_meshes};

/// Reads the file named by argv[1] with vtkXMLPolyDataReader and prints what it saw as
/// JSON; exits 2 when VTK reports an error or a warning.
const READER: &str = r#"
import json, sys
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkIdList
from vtkmodules.vtkCommonDataModel import vtkCellTypes
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
errors = []
@calldata_type(VTK_STRING)
def catch(obj, event, message):
    errors.append(event + ": " + str(message))
reader = vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.AddObserver("ErrorEvent", catch)
reader.AddObserver("WarningEvent", catch)
reader.Update()
if errors:
    print("\n".join(errors), file=sys.stderr)
    sys.exit(2)
data = reader.GetOutput()
types = {}
for c in range(data.GetNumberOfCells()):
    name = vtkCellTypes.GetClassNameFromTypeId(data.GetCellType(c))
    types[name] = types.get(name, 0) + 1
def arrays(fields):
    result = {}
    for a in range(fields.GetNumberOfArrays()):
        array = fields.GetArray(a)
        result[array.GetName()] = {
            "type": array.GetDataTypeAsString(),
            "tuples": array.GetNumberOfTuples(),
            "components": array.GetNumberOfComponents(),
            "values": [list(array.GetTuple(t)) for t in range(array.GetNumberOfTuples())],
        }
    return result
def cells(cell_array):
    ids = vtkIdList()
    result = []
    cell_array.InitTraversal()
    while cell_array.GetNextCell(ids):
        result.append([ids.GetId(i) for i in range(ids.GetNumberOfIds())])
    return result
points = data.GetPoints()
print(json.dumps({
    "points": data.GetNumberOfPoints(),
    "cells": data.GetNumberOfCells(),
    "types": types,
    "verts": cells(data.GetVerts()),
    "polys": cells(data.GetPolys()),
    "lines": data.GetNumberOfLines(),
    "strips": data.GetNumberOfStrips(),
    "coordinates": [list(points.GetPoint(p)) for p in range(data.GetNumberOfPoints())] if points else [],
    "coordinate_type": points.GetData().GetDataTypeAsString() if points else None,
    "cell_data": arrays(data.GetCellData()),
    "point_data": arrays(data.GetPointData()),
}))
"#;

fn particle(i: i32) -> Particle {
    let f = f64::from(i);
    Particle {
        mass: 1.0 + f,
        radius: 0.05 + 0.01 * f,
        pos: Vector3::new(0.1 * f + 1e-13, -0.3 + f / 7.0, 0.5 + 1.0 / 3.0),
        vel: Vector3::new(f, -2.0 * f, 1e-17),
        spin: Vector3::new(0.0, 0.5, -f),
        color: 3 + i,
        index: 10 + i,
    }
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .flat_map(|t| t.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()))
        .collect()
}

#[test]
fn vtkxmlpolydatareader_reads_back_the_walls_and_particles() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join("examples/sample.walls")).unwrap();
    let parsed = walls_syntax::parse(text);
    let scene = analyze(&parsed.tree, &Options::default()).scene;
    let walls = wall_meshes(&scene, 0.0, 24);
    assert!(walls.len() >= 5, "sample.walls has its walls");
    let particles: Vec<_> = (0..4).map(particle).collect();

    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sample.vtp");
    let mut bytes = Vec::new();
    vtk::write(&mut bytes, &walls, &particles, 0.0, &Scale::PKDGRAV).unwrap();
    std::fs::write(&path, &bytes).unwrap();
    let seen = read_back(READER, &path);

    let wall_points: usize = walls.iter().map(|w| w.mesh.positions.len()).sum();
    let triangles: usize = walls.iter().map(|w| w.mesh.triangles.len()).sum();
    let points = particles.len() + wall_points;
    let cells = particles.len() + triangles;
    assert_eq!(seen["points"], points);
    assert_eq!(seen["cells"], cells);
    assert_eq!(seen["lines"], 0);
    assert_eq!(seen["strips"], 0);
    let mut types = serde_json::Map::new();
    types.insert("vtkVertex".into(), particles.len().into());
    types.insert("vtkTriangle".into(), triangles.into());
    assert_eq!(seen["types"], Value::Object(types));
    assert_eq!(seen["coordinate_type"], "double");

    // Coordinates: particles first, then each wall's vertices, to 1e-12 (in fact exact).
    let expected: Vec<Vector3<f64>> = particles
        .iter()
        .map(|p| p.pos)
        .chain(walls.iter().flat_map(|w| w.mesh.positions.iter().copied()))
        .collect();
    let coordinates = numbers(&seen["coordinates"]);
    assert_eq!(coordinates.len(), 3 * points);
    for (i, p) in expected.iter().enumerate() {
        for k in 0..3 {
            let got = coordinates[3 * i + k];
            assert!(
                (got - p[k]).abs() <= 1e-12,
                "point {i} component {k}: wrote {}, read {got}",
                p[k]
            );
        }
    }
    assert_eq!(coordinates[0], particles[0].pos.x, "exact round trip");

    // Cells: one vertex per particle, then the triangles over the shifted vertices.
    let verts: Vec<Vec<u64>> = serde_json::from_value(seen["verts"].clone()).unwrap();
    assert_eq!(
        verts,
        (0..particles.len() as u64)
            .map(|i| vec![i])
            .collect::<Vec<_>>()
    );
    let polys: Vec<Vec<u64>> = serde_json::from_value(seen["polys"].clone()).unwrap();
    let mut base = particles.len() as u64;
    let mut expected_polys = Vec::new();
    for w in &walls {
        for t in &w.mesh.triangles {
            expected_polys.push(t.iter().map(|&i| base + u64::from(i)).collect::<Vec<_>>());
        }
        base += w.mesh.positions.len() as u64;
    }
    assert_eq!(polys, expected_polys);

    // Cell data spans the verts, then the polys.
    let cell_data = &seen["cell_data"];
    for (name, ty) in [("wall", "int"), ("color", "int"), ("opacity", "double")] {
        let a = &cell_data[name];
        assert_eq!(a["type"], ty, "{name}");
        assert_eq!(a["tuples"], cells, "{name}");
        assert_eq!(a["components"], 1, "{name}");
    }
    let per_cell = |f: &dyn Fn(&walls_preview::WallMesh) -> f64| -> Vec<f64> {
        walls
            .iter()
            .flat_map(|w| std::iter::repeat_n(f(w), w.mesh.triangles.len()))
            .collect()
    };
    let wall: Vec<f64> = std::iter::repeat_n(-1.0, particles.len())
        .chain(per_cell(&|w| w.wall as f64))
        .collect();
    assert_eq!(numbers(&cell_data["wall"]["values"]), wall);
    let color: Vec<f64> = particles
        .iter()
        .map(|p| f64::from(p.color))
        .chain(per_cell(&|w| w.color as f64))
        .collect();
    assert_eq!(numbers(&cell_data["color"]["values"]), color);
    let opacity: Vec<f64> = std::iter::repeat_n(1.0, particles.len())
        .chain(per_cell(&|w| w.opacity))
        .collect();
    assert_eq!(numbers(&cell_data["opacity"]["values"]), opacity);

    // Point data: the particles' values, then neutral ones on the walls' vertices.
    let point_data = &seen["point_data"];
    for (name, ty, components) in [
        ("radius", "double", 1),
        ("velocity", "double", 3),
        ("spin", "double", 3),
        ("mass", "double", 1),
        ("particle", "int", 1),
    ] {
        let a = &point_data[name];
        assert_eq!(a["type"], ty, "{name}");
        assert_eq!(a["tuples"], points, "{name}");
        assert_eq!(a["components"], components, "{name}");
    }
    let radius = numbers(&point_data["radius"]["values"]);
    let written: Vec<f64> = particles.iter().map(|p| p.radius).collect();
    assert_eq!(radius[..particles.len()], written[..]);
    assert!(radius[particles.len()..].iter().all(|&r| r == 0.0));
    let velocity = numbers(&point_data["velocity"]["values"]);
    let written: Vec<f64> = particles
        .iter()
        .flat_map(|p| [p.vel.x, p.vel.y, p.vel.z])
        .collect();
    assert_eq!(velocity[..written.len()], written[..]);
    let index = numbers(&point_data["particle"]["values"]);
    assert_eq!(&index[..particles.len()], [10.0, 11.0, 12.0, 13.0]);
    assert!(index[particles.len()..].iter().all(|&i| i == -1.0));
    let spin = numbers(&point_data["spin"]["values"]);
    let written: Vec<f64> = particles
        .iter()
        .flat_map(|p| [p.spin.x, p.spin.y, p.spin.z])
        .collect();
    assert_eq!(spin[..written.len()], written[..]);
    let mass = numbers(&point_data["mass"]["values"]);
    let written: Vec<f64> = particles.iter().map(|p| p.mass).collect();
    assert_eq!(mass[..written.len()], written[..]);
}

#[test]
fn walls_alone_and_nothing_at_all_are_read_back() {
    let parsed = walls_syntax::parse("wall type triangle\n  vertex1 1 0 0\n  vertex2 0 1 0\n");
    let scene = analyze(&parsed.tree, &Options::default()).scene;
    let walls = wall_meshes(&scene, 0.0, 8);
    let dir = tempfile::tempdir().unwrap();
    for (name, walls) in [("walls.vtp", &walls[..]), ("empty.vtp", &[][..])] {
        let path = dir.path().join(name);
        let mut bytes = Vec::new();
        vtk::write(&mut bytes, walls, &[], 0.0, &Scale::PKDGRAV).unwrap();
        std::fs::write(&path, &bytes).unwrap();
        let seen = read_back(READER, &path);
        let triangles = walls.len();
        assert_eq!(seen["points"], 3 * triangles, "{name}");
        assert_eq!(seen["cells"], triangles, "{name}");
        assert_eq!(seen["cell_data"]["color"]["tuples"], triangles, "{name}");
        assert_eq!(
            seen["point_data"]["radius"]["tuples"],
            3 * triangles,
            "{name}"
        );
    }
}
