//! The ParaView collection that `walls_preview::pvd` lays out (the frames that
//! `vtk::write` writes in the folder `pvd::frame_files` names, and the `.pvd` that
//! `pvd::write` writes, as `walls-sim preview --out movie.pvd` writes them), read back as
//! ParaView would: the `.pvd` parsed with Python's XML reader (VTK's wheel has no
//! collection reader; ParaView's `vtkPVDReader` is ParaView's own), each frame's `.vtp`
//! with VTK's `vtkXMLPolyDataReader` from the `vtk` wheel (`scripts/install-test-tools`
//! installs it). The frames, their times, particle positions and the unit metadata must
//! read back, in SI when asked.

mod vtk_reader;

use nalgebra::Vector3;
use vtk_reader::read_back;
use walls_geometry::Particle;
use walls_geometry::units::{AU_CM, Readout, Scale, System, TIME_UNIT_S};
use walls_model::{Options, Units, analyze};
use walls_preview::{MovieFrame, pvd, wall_meshes};

/// Reads the collection named by argv[1]: each data set's timestep and file, and from
/// each file (with vtkXMLPolyDataReader) its points and field data, as JSON; exits 2
/// when VTK reports an error or a warning.
const READER: &str = r#"
import json, os, sys
import xml.etree.ElementTree as ET
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
errors = []
@calldata_type(VTK_STRING)
def catch(obj, event, message):
    errors.append(event + ": " + str(message))
root = ET.parse(sys.argv[1]).getroot()
assert root.get("type") == "Collection", root.get("type")
frames = []
for ds in root.iter("DataSet"):
    path = os.path.join(os.path.dirname(sys.argv[1]), ds.get("file"))
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.AddObserver("ErrorEvent", catch)
    reader.AddObserver("WarningEvent", catch)
    reader.Update()
    data = reader.GetOutput()
    fields = data.GetFieldData()
    field = {}
    for a in range(fields.GetNumberOfArrays()):
        array = fields.GetAbstractArray(a)
        field[array.GetName()] = array.GetValue(0)
    frames.append({
        "timestep": float(ds.get("timestep")),
        "file": ds.get("file"),
        "points": [list(data.GetPoint(p)) for p in range(data.GetNumberOfPoints())],
        "radius": [data.GetPointData().GetArray("radius").GetValue(p) for p in range(data.GetNumberOfPoints())],
        "field": field,
    })
if errors:
    print("\n".join(errors), file=sys.stderr)
    sys.exit(2)
print(json.dumps(frames))
"#;

/// Three frames of a disk and a particle falling past it, in a file that sets units
/// (centimetres, seconds).
fn movie() -> (walls_model::Scene, Vec<MovieFrame>) {
    let parsed = walls_syntax::parse("wall\n  type disk\n  radius 0.5\n  color 2\n");
    let mut scene = analyze(&parsed.tree, &Options::default()).scene;
    scene.units = Units {
        length: 1.0 / AU_CM,
        mass: 1.0,
        time: 1.0 / TIME_UNIT_S,
    };
    let frames = (0..3)
        .map(|k| {
            let t = 0.25 * f64::from(k);
            MovieFrame {
                t,
                step: Some(100 * k as u64),
                walls: wall_meshes(&scene, t, 8),
                particles: vec![Particle::at_rest(0.1, Vector3::new(0.0, 0.0, 1.0 - t), 0)],
            }
        })
        .collect();
    (scene, frames)
}

/// Writes the collection `path` of `frames` in `scale`'s units, as walls-sim preview does.
fn write_collection(path: &std::path::Path, frames: &[MovieFrame], scale: &Scale) {
    let dir = path.parent().unwrap();
    let files = pvd::frame_files(path, frames.len());
    std::fs::create_dir_all(dir.join(files[0].parent().unwrap())).unwrap();
    for (frame, file) in frames.iter().zip(&files) {
        let mut out = Vec::new();
        walls_preview::vtk::write(&mut out, &frame.walls, &frame.particles, frame.t, scale)
            .unwrap();
        std::fs::write(dir.join(file), out).unwrap();
    }
    let mut out = Vec::new();
    pvd::write(&mut out, frames, &files, scale).unwrap();
    std::fs::write(path, out).unwrap();
}

#[test]
fn paraview_reads_the_frames_times_and_positions() {
    let (_, frames) = movie();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("movie.pvd");
    write_collection(&path, &frames, &Scale::PKDGRAV);
    let read = read_back(READER, &path);
    let read = read.as_array().unwrap();
    assert_eq!(read.len(), 3);
    for (k, frame) in read.iter().enumerate() {
        assert_eq!(frame["timestep"], 0.25 * k as f64);
        assert_eq!(frame["file"], format!("movie/movie_{k:06}.vtp"));
        assert_eq!(frame["field"]["TIME"], 0.25 * k as f64);
        assert_eq!(frame["field"]["length_unit"], "AU");
        assert_eq!(frame["field"]["time_unit"], "yr/2pi");
    }
    // Frame 2's particle (point 0) is at z = 1 − 0.5.
    assert_eq!(read[2]["points"][0], serde_json::json!([0.0, 0.0, 0.5]));
    assert!(dir.path().join("movie/movie_000002.vtp").is_file());
}

#[test]
fn si_frames_are_in_metres_and_seconds() {
    let (scene, frames) = movie();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("si.pvd");
    let si = Readout::new(System::Si, &scene.units).scale;
    write_collection(&path, &frames, &si);
    let read = read_back(READER, &path);
    let frame = &read[2];
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1.0);
    // z = 0.5 AU, radius 0.1 AU, t = 0.5 pkdgrav time units, in metres and seconds.
    let metres = AU_CM / 100.0;
    let z = frame["points"][0][2].as_f64().unwrap();
    assert!(close(z, 0.5 * metres), "{z}");
    assert!(close(frame["radius"][0].as_f64().unwrap(), 0.1 * metres));
    let t = frame["timestep"].as_f64().unwrap();
    assert!(close(t, 0.5 * TIME_UNIT_S), "{t}");
    assert!(close(
        frame["field"]["TIME"].as_f64().unwrap(),
        0.5 * TIME_UNIT_S
    ));
    assert_eq!(frame["field"]["length_unit"], "m");
    assert_eq!(frame["field"]["mass_unit"], "kg");
    assert_eq!(frame["field"]["time_unit"], "s");
    assert_eq!(read[0]["file"], "si/si_000000.vtp");
}
