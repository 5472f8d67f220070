//! Nothing that is not finite is drawn or written (docs/preview.md, "Numbers a picture
//! cannot draw"): a plane whose origin is 1e308 (its tessellation NaN), a wall or a
//! particle beyond ±1e150, and a frame of a movie that holds one are refused by every
//! writer (SVG, VTK, the ParaView collection, POV-Ray, the HTML page) with an
//! `InvalidData` error that names the wall or particle and the time (and the frame of a
//! movie), before a byte is written, a file made or a folder created; an ordinary scene
//! still draws.

use nalgebra::Vector3;
use std::io::ErrorKind;
use walls_geometry::Particle;
use walls_geometry::units::{Readout, Scale, System};
use walls_model::Scene;
use walls_preview::finite::NotDrawable;
use walls_preview::html::{self, MovieOptions};
use walls_preview::{MovieFrame, WallMesh, pov, pvd, svg, vtk, wall_meshes};
use walls_test_support::model_scene as scene;

/// The file: `origin 1e308 1e308 1e308` tessellates to NaN.
const FAR_PLANE: &str = "wall\n  type plane\n  origin 1e308 1e308 1e308\n";

/// A disk that is fine, and a particle far out.
const DISK: &str = "wall type disk\n  radius 1\n  color 2\n";

/// The message of an `InvalidData` error holding a [`NotDrawable`].
fn refused(e: std::io::Error) -> String {
    assert_eq!(e.kind(), ErrorKind::InvalidData, "{e}");
    let inner = e.into_inner().expect("the error holds why");
    inner
        .downcast::<NotDrawable>()
        .expect("a NotDrawable")
        .to_string()
}

fn frame(t: f64, step: Option<u64>, walls: Vec<WallMesh>, particles: Vec<Particle>) -> MovieFrame {
    MovieFrame {
        t,
        step,
        walls,
        particles,
    }
}

/// Two frames of the disk: the second with particle 7 at x = 1e152.
fn movie_with_a_far_particle() -> (Scene, Vec<MovieFrame>) {
    let s = scene(DISK);
    let near = Particle::at_rest(0.1, Vector3::zeros(), 3);
    let mut far = Particle::at_rest(0.1, Vector3::new(1e152, 0.0, 0.0), 7);
    far.index = 7;
    let frames = vec![
        frame(0.0, Some(0), wall_meshes(&s, 0.0, 8), vec![near.clone()]),
        frame(0.5, Some(10), wall_meshes(&s, 0.5, 8), vec![near, far]),
    ];
    (s, frames)
}

const FAR_PARTICLE: &str = "particle 7 at t = 0.5 (frame 2 of 2, step 10): its position is \
                            1e152, beyond the ±1e150 a picture can draw";

const NAN_PLANE: &str = "wall 0 (plane) at t = 0: a vertex of its mesh is NaN";

#[test]
fn svg_refuses_a_nan_plane_and_a_far_particle_writing_nothing() {
    let s = scene(FAR_PLANE);
    let walls = wall_meshes(&s, 0.0, 8);
    let readout = Readout::new(System::Pkdgrav, &s.units);
    let frames = [svg::Frame {
        t: 0.0,
        walls: &walls,
        particles: &[],
    }];
    let box_ = (Vector3::zeros(), Vector3::repeat(1.0));
    let draw = |out: &mut Vec<u8>, frames: &[svg::Frame], readout: &Readout| {
        svg::write(out, frames, &svg::View::default(), box_, 4.0, readout)
    };
    let mut out = Vec::new();
    let e = draw(&mut out, &frames, &readout);
    assert_eq!(refused(e.unwrap_err()), NAN_PLANE);
    assert!(out.is_empty(), "{} bytes written", out.len());

    let (s, movie) = movie_with_a_far_particle();
    let frames: Vec<svg::Frame> = movie
        .iter()
        .map(|f| svg::Frame {
            t: f.t,
            walls: &f.walls,
            particles: &f.particles,
        })
        .collect();
    let readout = Readout::new(System::Pkdgrav, &s.units);
    let e = draw(&mut out, &frames, &readout);
    // The SVG's frames have no steps: the frame's number and time name it.
    assert_eq!(
        refused(e.unwrap_err()),
        FAR_PARTICLE.replace(", step 10", "")
    );
    assert!(out.is_empty());
    // The first frame alone draws, without a NaN.
    draw(&mut out, &frames[..1], &readout).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("<polygon") && !text.contains("NaN"));
}

#[test]
fn vtk_refuses_a_nan_plane_writing_nothing() {
    let s = scene(FAR_PLANE);
    let walls = wall_meshes(&s, 0.0, 8);
    let mut out = Vec::new();
    let e = vtk::write(&mut out, &walls, &[], 0.0, &Scale::PKDGRAV);
    assert_eq!(refused(e.unwrap_err()), NAN_PLANE);
    assert!(out.is_empty(), "{} bytes written", out.len());
    // A particle with an infinite spin (a programme's, not a reader's: readers refuse
    // it) is refused too.
    let mut spinning = Particle::at_rest(0.1, Vector3::zeros(), 4);
    spinning.spin.z = f64::INFINITY;
    let e = vtk::write(&mut out, &[], &[spinning], 2.0, &Scale::PKDGRAV);
    assert_eq!(
        refused(e.unwrap_err()),
        "particle 4 at t = 2: its spin is infinite"
    );
    assert!(out.is_empty());
}

#[test]
fn a_collection_refuses_a_movie_frame_writing_nothing() {
    let (_, movie) = movie_with_a_far_particle();
    let files = pvd::frame_files(std::path::Path::new("movie.pvd"), movie.len());
    let mut out = Vec::new();
    let e = pvd::write(&mut out, &movie, &files, &Scale::PKDGRAV).unwrap_err();
    assert_eq!(refused(e), FAR_PARTICLE);
    assert!(out.is_empty(), "{} bytes written", out.len());
}

#[test]
fn pov_refuses_a_nan_plane_a_far_frame_and_a_camera_out_of_range() {
    let s = scene(FAR_PLANE);
    let view = pov::View::default();
    let mut out = Vec::new();
    let e = pov::write(&mut out, &s, 0.0, &[], &view).unwrap_err();
    assert_eq!(refused(e), NAN_PLANE);
    assert!(out.is_empty());

    let (s, movie) = movie_with_a_far_particle();
    let box_ = (Vector3::repeat(-1.0), Vector3::repeat(1.0));
    let e = pov::write_frame(&mut out, &s, &movie[1], box_, &view).unwrap_err();
    // One frame of the movie, as the caller numbers it: its time and step.
    assert_eq!(
        refused(e),
        "particle 7 at t = 0.5 (step 10): its position is 1e152, beyond the ±1e150 a \
         picture can draw"
    );
    // An ssdraw camera 1e150 away from a scene 1e-160 across: renormalised, it is
    // beyond a double.
    let tiny = (Vector3::repeat(-5e-161), Vector3::repeat(5e-161));
    let far_camera = pov::View {
        camera: Some((Vector3::new(1e150, 0.0, 0.0), Vector3::zeros())),
        ..view
    };
    let e = pov::write_frame(&mut out, &s, &movie[0], tiny, &far_camera).unwrap_err();
    assert_eq!(
        refused(e),
        "the view at t = 0 (step 0): its camera position, in units of the scene's size, is \
         infinite"
    );
    assert!(out.is_empty(), "{} bytes written", out.len());
    // The first frame, framed as a movie is, draws.
    pov::write_frame(&mut out, &s, &movie[0], box_, &view).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("disc {") && !text.to_lowercase().contains("nan"));
}

#[test]
fn the_page_refuses_a_nan_plane_and_a_far_frame_writing_nothing() {
    let s = scene(FAR_PLANE);
    let mut out = Vec::new();
    let e = html::write(&mut out, &s, None, 0.0, 1).unwrap_err();
    assert_eq!(refused(e), NAN_PLANE);
    assert!(out.is_empty(), "{} bytes written", out.len());

    let (s, movie) = movie_with_a_far_particle();
    let options = MovieOptions {
        readout: Readout::new(System::Auto, &s.units),
        trails: None,
        title: "far".into(),
    };
    let e = html::write_movie(&mut out, &s, &movie, &options).unwrap_err();
    assert_eq!(refused(e), FAR_PARTICLE);
    assert!(out.is_empty());
}

#[test]
fn a_view_of_any_length_is_a_direction() {
    // `--view 1e308 0 0` (or an ssdraw camera that far) looked along NaN: every point of
    // the SVG was NaN. A view is a direction, whatever its length.
    let s = scene(DISK);
    let walls = wall_meshes(&s, 0.0, 16);
    let readout = Readout::new(System::Pkdgrav, &s.units);
    let frames = [svg::Frame {
        t: 0.0,
        walls: &walls,
        particles: &[],
    }];
    let box_ = (Vector3::repeat(-1.0), Vector3::repeat(1.0));
    let draw = |from: Vector3<f64>, up: Vector3<f64>| {
        let view = svg::View {
            from,
            up,
            ..svg::View::default()
        };
        let mut out = Vec::new();
        svg::write(&mut out, &frames, &view, box_, 4.0, &readout).unwrap();
        String::from_utf8(out).unwrap()
    };
    let far = draw(Vector3::new(1e308, 0.0, 0.0), Vector3::new(0.0, 0.0, 1e308));
    assert!(!far.contains("NaN"), "{far:.600}");
    assert_eq!(far, draw(Vector3::x(), Vector3::z()));
}
