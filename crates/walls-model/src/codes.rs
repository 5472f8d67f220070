//! The model diagnostic codes: the registry.
//!
//! `C1xx` are single values pkdgrav refuses, `C2xx` walls and files that are legal but
//! very likely wrong, `C3xx` reactive walls, `M0xx` what depends on the contact model.
//! Each code is defined, with its explanation and a bad and a good example, beside its
//! check in its own file under `rules/`; this module re-exports them and lists them in
//! [`ALL`]. The examples are tested: each bad example produces its code, each good
//! example nothing (in the mode, and with the options, the bad example names).

use walls_diagnostics::Code;

pub use crate::rules::arithmetic_overflow::ARITHMETIC_OVERFLOW;
pub use crate::rules::assembly_without_mass::ASSEMBLY_WITHOUT_MASS;
pub use crate::rules::axes_not_orthogonal::AXES_NOT_ORTHOGONAL;
pub use crate::rules::axis_not_unit::AXIS_NOT_UNIT;
pub use crate::rules::cohesion_model::COHESION_MODEL;
pub use crate::rules::color_range::COLOR_RANGE;
pub use crate::rules::degenerate_triangle::DEGENERATE_TRIANGLE;
pub use crate::rules::epsn_range::EPSN_RANGE;
pub use crate::rules::epst_range::EPST_RANGE;
pub use crate::rules::hole_not_inside::HOLE_NOT_INSIDE;
pub use crate::rules::hsdem_particle_value::HSDEM_PARTICLE_VALUE;
pub use crate::rules::ignored_by_type::IGNORED_BY_TYPE;
pub use crate::rules::ignored_in_hsdem::IGNORED_IN_HSDEM;
pub use crate::rules::inertia_off_diagonal::INERTIA_OFF_DIAGONAL;
pub use crate::rules::invalid_assembly::INVALID_ASSEMBLY;
pub use crate::rules::k_t_before_k_n::KT_BEFORE_KN;
pub use crate::rules::lone_oscillation::LONE_OSCILLATION;
pub use crate::rules::mass_without_assembly::MASS_WITHOUT_ASSEMBLY;
pub use crate::rules::material_range::MATERIAL_RANGE;
pub use crate::rules::negative_osc_freq::NEGATIVE_OSC_FREQ;
pub use crate::rules::negative_time::NEGATIVE_TIME;
pub use crate::rules::negative_value::NEGATIVE_VALUE;
pub use crate::rules::no_walls::NO_WALLS;
pub use crate::rules::not_in_hsdem::NOT_IN_HSDEM;
pub use crate::rules::number_too_large::NUMBER_TOO_LARGE;
pub use crate::rules::open_angle_range::OPEN_ANGLE_RANGE;
pub use crate::rules::osc_phase_range::OSC_PHASE_RANGE;
pub use crate::rules::osc_vec_not_following_orient::OSC_VEC_NOT_FOLLOWING_ORIENT;
pub use crate::rules::reactive_spinning::REACTIVE_SPINNING;
pub use crate::rules::reactive_type::REACTIVE_TYPE;
pub use crate::rules::rectangle_not_rectangular::RECTANGLE_NOT_RECTANGULAR;
pub use crate::rules::repeated_token::REPEATED_TOKEN;
pub use crate::rules::sticky_wall_order::STICKY_WALL_ORDER;
pub use crate::rules::taper_on_ring::TAPER_ON_RING;
pub use crate::rules::taper_range::TAPER_RANGE;
pub use crate::rules::time_ignored::TIME_IGNORED;
pub use crate::rules::too_many_walls::TOO_MANY_WALLS;
pub use crate::rules::transparency_range::TRANSPARENCY_RANGE;
pub use crate::rules::unit_not_positive::UNIT_NOT_POSITIVE;
pub use crate::rules::unused_default::UNUSED_DEFAULT;
pub use crate::rules::wall_too_fast::WALL_TOO_FAST;
pub use crate::rules::zero_vector::ZERO_VECTOR;

/// Every model code, in code order.
pub static ALL: &[&Code] = &[
    &UNIT_NOT_POSITIVE,
    &NEGATIVE_TIME,
    &TIME_IGNORED,
    &ZERO_VECTOR,
    &DEGENERATE_TRIANGLE,
    &RECTANGLE_NOT_RECTANGULAR,
    &NEGATIVE_VALUE,
    &HOLE_NOT_INSIDE,
    &TAPER_RANGE,
    &TAPER_ON_RING,
    &OPEN_ANGLE_RANGE,
    &OSC_PHASE_RANGE,
    &NEGATIVE_OSC_FREQ,
    &EPSN_RANGE,
    &EPST_RANGE,
    &COLOR_RANGE,
    &TRANSPARENCY_RANGE,
    &MATERIAL_RANGE,
    &COHESION_MODEL,
    &NUMBER_TOO_LARGE,
    &ARITHMETIC_OVERFLOW,
    &IGNORED_BY_TYPE,
    &REPEATED_TOKEN,
    &KT_BEFORE_KN,
    &LONE_OSCILLATION,
    &OSC_VEC_NOT_FOLLOWING_ORIENT,
    &STICKY_WALL_ORDER,
    &UNUSED_DEFAULT,
    &NO_WALLS,
    &TOO_MANY_WALLS,
    &WALL_TOO_FAST,
    &REACTIVE_TYPE,
    &REACTIVE_SPINNING,
    &ASSEMBLY_WITHOUT_MASS,
    &MASS_WITHOUT_ASSEMBLY,
    &INVALID_ASSEMBLY,
    &AXIS_NOT_UNIT,
    &AXES_NOT_ORTHOGONAL,
    &INERTIA_OFF_DIAGONAL,
    &NOT_IN_HSDEM,
    &IGNORED_IN_HSDEM,
    &HSDEM_PARTICLE_VALUE,
];
