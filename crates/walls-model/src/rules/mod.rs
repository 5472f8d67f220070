//! The model rules: one file per diagnostic code, holding the code (its id, name and
//! explanation with the Bad and Good examples that `walls-cli`'s tests run) and the check
//! that reports it. [`crate::codes`] is the registry that lists them in code order.
//!
//! Rules run at three moments:
//!
//! * **Value rules** (C101–C120, C305, C306, C308) judge one value as the resolver reads
//!   it, since pkdgrav refuses the file at that token. Which rule applies is the
//!   keyword's [`ValueRange`] column in the `walls-keywords` table: [`check_general`]
//!   and [`check_property`] are the one place that maps a range to its rule. The
//!   resolver calls them and stores what they return (a direction normalised, a
//!   transparency as a fraction); it does no checking of its own.
//! * `osc-freq` (C113) is read like any value but reported when its block ends, so that
//!   the fix can use the block's final amplitude and phase.
//! * **Block, wall and file rules** (C105, C106, C108, C110, C121, C2xx, C301–C304,
//!   C307, M001, M003) run on the resolved scene, from `check.rs` in a fixed order (which
//!   orders diagnostics at the same span); M002 runs on the syntax tree.
//!
//! Codes share a file only where they share their check: none do today. C104 is one
//! code for two ranges (a direction, normalised, and a vertex).

pub(crate) mod arithmetic_overflow;
pub(crate) mod assembly_without_mass;
pub(crate) mod axes_not_orthogonal;
pub(crate) mod axis_not_unit;
pub(crate) mod cohesion_model;
pub(crate) mod color_range;
pub(crate) mod degenerate_triangle;
pub(crate) mod epsn_range;
pub(crate) mod epst_range;
pub(crate) mod hole_not_inside;
pub(crate) mod hsdem_particle_value;
pub(crate) mod ignored_by_type;
pub(crate) mod ignored_in_hsdem;
pub(crate) mod inertia_off_diagonal;
pub(crate) mod invalid_assembly;
pub(crate) mod k_t_before_k_n;
pub(crate) mod lone_oscillation;
pub(crate) mod mass_without_assembly;
pub(crate) mod material_range;
pub(crate) mod negative_osc_freq;
pub(crate) mod negative_time;
pub(crate) mod negative_value;
pub(crate) mod no_walls;
pub(crate) mod not_in_hsdem;
pub(crate) mod number_too_large;
pub(crate) mod open_angle_range;
pub(crate) mod osc_phase_range;
pub(crate) mod osc_vec_not_following_orient;
pub(crate) mod reactive_spinning;
pub(crate) mod reactive_type;
pub(crate) mod rectangle_not_rectangular;
pub(crate) mod repeated_token;
pub(crate) mod sticky_wall_order;
pub(crate) mod taper_on_ring;
pub(crate) mod taper_range;
pub(crate) mod time_ignored;
pub(crate) mod too_many_walls;
pub(crate) mod transparency_range;
pub(crate) mod unit_not_positive;
pub(crate) mod unused_default;
pub(crate) mod wall_too_fast;
pub(crate) mod zero_vector;

use crate::ContactModel;
use crate::scene::{Value, Wall};
use std::collections::HashMap;
use std::hash::Hash;
use std::ops::Range;
use walls_diagnostics::{Diagnostic, MAX_LABELS};
use walls_keywords::{Keyword, ValueRange};

/// Walls gathered by the place (`K`) that gave them what a rule reports, for one
/// diagnostic per place: the groups come in the order of their first wall, when walls
/// are added in file order.
pub(crate) struct ByPlace<'w, K> {
    /// Where each place's group is in `groups`.
    at: HashMap<K, usize>,
    groups: Vec<(K, Vec<&'w Wall>)>,
}

impl<K> Default for ByPlace<'_, K> {
    fn default() -> Self {
        ByPlace {
            at: HashMap::new(),
            groups: Vec::new(),
        }
    }
}

impl<'w, K: Hash + Eq + Copy> ByPlace<'w, K> {
    /// Adds `wall` to the group of `place`.
    pub(crate) fn add(&mut self, place: K, wall: &'w Wall) {
        let i = *self.at.entry(place).or_insert_with(|| {
            self.groups.push((place, Vec::new()));
            self.groups.len() - 1
        });
        self.groups[i].1.push(wall);
    }

    /// Each place with its walls (at least one), in the order of their first wall.
    pub(crate) fn into_groups(self) -> Vec<(K, Vec<&'w Wall>)> {
        self.groups
    }
}

/// How a message names `walls` (at least one): `wall 3`, or `4 walls (3, 5, 8, 9)` with
/// the first [`MAX_LABELS`] numbers and `…` for the rest.
pub(crate) fn walls_named(walls: &[&Wall]) -> String {
    if let [wall] = walls {
        return format!("wall {}", wall.index);
    }
    let mut ids: Vec<String> = walls
        .iter()
        .take(MAX_LABELS)
        .map(|w| w.index.to_string())
        .collect();
    if walls.len() > MAX_LABELS {
        ids.push("…".into());
    }
    format!("{} walls ({})", walls.len(), ids.join(", "))
}

/// A value as the resolver read it, for the value rules.
pub(crate) struct Read<'a> {
    /// The keyword the value belongs to.
    pub keyword: Keyword,
    /// The span of the values.
    pub span: Range<usize>,
    /// The values as written: messages quote them unscaled.
    pub written: &'a str,
    /// The contact model.
    pub mode: ContactModel,
}

/// Checks the value of a general token (`time`, a unit) by its range; returns whether the
/// resolver may use it.
pub(crate) fn check_general(at: &Read, x: f64, out: &mut Vec<Diagnostic>) -> bool {
    match at.keyword.value_range() {
        ValueRange::Positive => unit_not_positive::check(at, x, out),
        ValueRange::NonNegative => {
            if !negative_time::check(at, x, out) {
                time_ignored::check(at, x, out);
            }
            true
        }
        _ => true,
    }
}

/// Checks the value of a property by its range (after [`number_too_large`]); returns the
/// value to store.
#[inline]
pub(crate) fn check_property(at: &Read, value: Value, out: &mut Vec<Diagnostic>) -> Value {
    match (at.keyword.value_range(), value) {
        (ValueRange::Direction, Value::Vector(v)) => return zero_vector::direction_of(at, v, out),
        (ValueRange::NonZero, Value::Vector(v)) => zero_vector::non_zero(at, v, out),
        (ValueRange::NonNegative, Value::Number(x)) => negative_value::check(at, x, out),
        (ValueRange::Fraction, Value::Number(x)) => taper_range::check(at, x, out),
        (ValueRange::HalfTurn, Value::Number(x)) => open_angle_range::check(at, x, out),
        (ValueRange::Phase, Value::Number(x)) => osc_phase_range::check(at, x, out),
        (ValueRange::NormalRestitution, Value::Number(x)) => epsn_range::check(at, x, out),
        (ValueRange::TangentialRestitution, Value::Number(x)) => epst_range::check(at, x, out),
        (ValueRange::Palette, Value::Integer(c)) => color_range::check(at, c, out),
        (ValueRange::Transparency, Value::Number(x)) => {
            return transparency_range::check(at, x, out);
        }
        (ValueRange::ParticleOrNonNegative, Value::Number(x)) => material_range::check(at, x, out),
        (ValueRange::CohesionModel, Value::Integer(m)) => cohesion_model::check(at, m, out),
        (ValueRange::Assembly, Value::Integer(a)) => invalid_assembly::check(at, a, out),
        (ValueRange::UnitVector, Value::Vector(v)) => axis_not_unit::check(at, v, out),
        (ValueRange::InertiaRow(row), Value::Vector(v)) => {
            inertia_off_diagonal::check(at, row, v, out)
        }
        // `ValueRange::Any` needs no check; `osc-freq` (`NonNegativeFrequency`) is
        // reported when its block ends (negative_osc_freq).
        _ => {}
    }
    value
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Vec3;
    use walls_keywords::Role;

    /// Every keyword with a range reports a value outside it, under the code its range
    /// names, in the place the resolver asks (general tokens or properties).
    #[test]
    fn every_range_reaches_its_rule() {
        for &k in Keyword::ALL {
            let (bad, id) = match k.value_range() {
                // `osc-freq` is reported when its block ends.
                ValueRange::Any | ValueRange::NonNegativeFrequency => continue,
                ValueRange::Positive => (Value::Number(0.0), "C101"),
                ValueRange::NonNegative if k.role() == Role::General => {
                    (Value::Number(-1.0), "C102")
                }
                ValueRange::NonNegative => (Value::Number(-1.0), "C107"),
                ValueRange::Direction | ValueRange::NonZero => {
                    (Value::Vector(Vec3::zeros()), "C104")
                }
                ValueRange::Fraction => (Value::Number(1.5), "C109"),
                ValueRange::HalfTurn => (Value::Number(270.0), "C111"),
                ValueRange::Phase => (Value::Number(1.25), "C112"),
                ValueRange::NormalRestitution => (Value::Number(1.2), "C114"),
                ValueRange::TangentialRestitution => (Value::Number(-0.5), "C115"),
                ValueRange::Palette => (Value::Integer(300), "C116"),
                ValueRange::Transparency => (Value::Number(150.0), "C117"),
                ValueRange::ParticleOrNonNegative => (Value::Number(-0.5), "C118"),
                ValueRange::CohesionModel => (Value::Integer(2), "C119"),
                ValueRange::Assembly => (Value::Integer(2), "C305"),
                ValueRange::UnitVector => (Value::Vector(Vec3::new(2.0, 0.0, 0.0)), "C306"),
                ValueRange::InertiaRow(_) => (Value::Vector(Vec3::new(1.0, 1.0, 1.0)), "C308"),
            };
            let at = Read {
                keyword: k,
                span: 0..1,
                written: "x",
                mode: ContactModel::Ssdem,
            };
            let mut out = Vec::new();
            match (k.role(), bad) {
                (Role::General, Value::Number(x)) => {
                    check_general(&at, x, &mut out);
                }
                _ => {
                    check_property(&at, bad, &mut out);
                }
            }
            let ids: Vec<_> = out.iter().map(|d| d.code.id).collect();
            assert_eq!(ids, [id], "{k:?}");
        }
    }
}
