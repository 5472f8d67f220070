//! Pictures of walls files (docs/spec.md §2 `walls-sim preview`, §3 "Drawing"): every
//! wall of a scene placed where it is at a time and tessellated into triangles in
//! ssdraw's colours, for the writers of each picture format to draw: [`svg`] (the
//! embedded renderer), [`pov`] (POV-Ray), [`vtk`] (VTK PolyData for ParaView), [`pvd`] (a
//! movie's frames as a ParaView collection) and [`html`] (an interactive page).
//! [`ssdraw`] reads the view of a pkdgrav user's `ssdraw.par`. [`finite`] is what every
//! writer refuses before it writes a byte: a number that is not finite, or too large to
//! draw.

pub mod finite;
pub mod html;
pub mod mesh;
pub mod movie;
pub mod palette;
pub mod pov;
pub mod pvd;
pub mod ssdraw;
pub mod svg;
pub mod vtk;

pub use mesh::{Mesh, WallMesh, wall_meshes, wall_meshes_in};
pub use movie::MovieFrame;

/// `s` as XML or HTML text or a quoted attribute's value: `&`, `<`, `>` and `"`
/// escaped.
pub(crate) fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('"', "&quot;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
