//! pkdgrav's contact law four contacts at a time (`contact::lanes`) against the law on
//! each contact alone (`ssdem::dashpot_contact_with`): the same numbers, bit for bit, in
//! every lane, for random contacts and records (new and old contacts, normals reversed
//! since the last step, zero and turning springs, sticking and sliding, angles past the
//! series' range, rolling and twisting on and off, no tangential spring, both sliding
//! rules). On x86-64 only, where the lanes are.

#![cfg(target_arch = "x86_64")]

use nalgebra::Vector3;
use proptest::prelude::*;
use walls_geometry::Material;
use walls_sim::contact::lanes::{self, Contacts, LANES, Simd, V};
use walls_sim::contact::ssdem::{Dashpot, Optional, Record, Sliding, dashpot_contact_with};
use walls_test_support::exact::{bits, number};

type Vec3 = Vector3<f64>;

/// A vector of components in −`size`..`size`, or zero one time in four.
fn vector(size: f64) -> impl Strategy<Value = Vec3> {
    prop_oneof![
        1 => Just(Vec3::zeros()),
        3 => (-size..size, -size..size, -size..size).prop_map(|(x, y, z)| Vec3::new(x, y, z)),
    ]
}

/// A unit vector.
fn unit() -> impl Strategy<Value = Vec3> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter("not too short", |(x, y, z)| x * x + y * y + z * z > 1e-4)
        .prop_map(|(x, y, z)| Vec3::new(x, y, z).normalize())
}

/// What a record's normal is: a new contact's (zero), an old one's a little turned from
/// the contact's, or the contact's reversed (the mean of the two is zero).
#[derive(Debug, Clone, Copy)]
enum Old {
    New,
    Tilted(Vec3),
    Reversed,
}

/// One contact: its [`Dashpot`] (between particles) and damping, and its record.
fn contact() -> impl Strategy<Value = (Dashpot, (f64, f64), Record)> {
    (
        (
            1e-6..1e-3f64,
            unit(),
            vector(0.5),
            vector(200.0),
            vector(200.0),
        ),
        (1e-4..1e-3f64, 1e-4..1e-3f64, 1e-4..1e-3f64),
        (0.0..0.1f64, 0.0..0.1f64),
        (
            prop_oneof![
                1 => Just(Old::New),
                4 => vector(0.05).prop_map(Old::Tilted),
                1 => Just(Old::Reversed),
            ],
            vector(1e-4),
            vector(1e-3),
            prop_oneof![1 => Just(0.0), 3 => -1e-3..1e-3f64],
        ),
    )
        .prop_map(
            |((overlap, normal, velocity, spin, turn), (l1, l2, radius), damping, old)| {
                let (tilt, spring, roll, twist) = old;
                let record = Record {
                    spring,
                    normal: match tilt {
                        Old::New => Vec3::zeros(),
                        Old::Tilted(t) => (normal + t).normalize(),
                        Old::Reversed => -normal,
                    },
                    roll,
                    twist,
                    layer: 0,
                };
                let dashpot = Dashpot {
                    overlap,
                    normal,
                    velocity,
                    spin,
                    turn,
                    levers: (l1, l2),
                    mass: 1.0,
                    radius,
                    wall: false,
                    constant_torque: None,
                    sliding: Sliding::Reset,
                };
                (dashpot, damping, record)
            },
        )
}

/// A material of the particles, with or without rolling and twisting.
fn material() -> impl Strategy<Value = Material> {
    (
        (10.0..1e4f64, prop_oneof![1 => Just(0.0), 5 => 0.1..1.0f64]),
        (
            0.0..1.0f64,
            prop_oneof![Just(0.0), 0.0..1.0f64],
            prop_oneof![Just(0.0), 0.0..1.0f64],
        ),
        0.1..1.0f64,
    )
        .prop_map(|((k_n, kt), (mu_s, mu_r, mu_t), beta_s)| Material {
            eps_n: 0.5,
            eps_t: 0.5,
            k_n,
            k_t: kt * k_n,
            mu_s,
            mu_r,
            mu_t,
            beta_s,
        })
}

/// The four contacts' `field` in lanes.
fn lanes_of(each: [Vec3; LANES]) -> V {
    V::gather(|l| each[l].into())
}

/// Lane `l` of `v`.
fn lane(v: &V, l: usize) -> Vec3 {
    v.each_lane()[l].into()
}

/// [`lanes::dashpot`] compiled as the run compiles it, for the processor it runs on.
#[multiversion::multiversion(targets(
    "x86_64+avx512f+avx512vl+avx512dq+avx2+fma",
    "x86_64+avx2+fma"
))]
fn dispatched(
    simd: Simd,
    c: &Contacts,
    records: &mut [Record; LANES],
    dt: f64,
    mat: &Material,
    sliding: Sliding,
) -> lanes::Forces {
    lanes::dashpot(simd, c, records.each_mut(), dt, mat, sliding)
}

/// The lanes need x86-64-v3 (AVX2, FMA, BMI1 and 2, LZCNT, POPCNT: every x86-64 processor
/// of the last decade); on a processor without it the run takes every contact one at a
/// time and the property below compares nothing, so this fails rather than let it pass
/// untested.
#[test]
fn the_processor_has_the_lanes() {
    assert!(
        Simd::new().is_some(),
        "this processor lacks x86-64-v3: the four-lane law is not tested here"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn four_at_a_time_are_each_alone(
        four in prop::array::uniform4(contact()),
        mat in material(),
        dt in prop_oneof![Just(5e-6), 1e-6..1e-3f64],
        clamp in any::<bool>(),
        no_rolling in any::<bool>(),
    ) {
        // Without rolling resistance every rolling spring is zero, the common case.
        let four = four.map(|(d, damping, r)| {
            let roll = if no_rolling { Vec3::zeros() } else { r.roll };
            (d, damping, Record { roll, ..r })
        });
        let sliding = if clamp { Sliding::Clamp } else { Sliding::Reset };
        let c: [Dashpot; LANES] = four.map(|(d, _, _)| Dashpot { sliding, ..d });
        let contacts = Contacts {
            overlap: lanes::gather(|l| c[l].overlap),
            normal: lanes_of(c.map(|c| c.normal)),
            velocity: lanes_of(c.map(|c| c.velocity)),
            spin: lanes_of(c.map(|c| c.spin)),
            turn: lanes_of(c.map(|c| c.turn)),
            levers: (lanes::gather(|l| c[l].levers.0), lanes::gather(|l| c[l].levers.1)),
            radius: lanes::gather(|l| c[l].radius),
            damping: (lanes::gather(|l| four[l].1.0), lanes::gather(|l| four[l].1.1)),
        };
        let mut records = four.map(|(_, _, r)| r);
        // (Nothing to compare without the lanes: `the_processor_has_the_lanes` fails.)
        let Some(simd) = Simd::new() else { return Ok(()) };
        let forces = dispatched(simd, &contacts, &mut records, dt, &mat, sliding);
        for l in 0..LANES {
            let (_, damping, mut alone) = four[l];
            let extra = Optional { damping: Some(damping), ..Optional::default() };
            let want = dashpot_contact_with(&c[l], &mut alone, dt, &mat, &extra);
            prop_assert_eq!(bits(lane(&forces.force, l)), bits(want.force), "force, lane {}", l);
            prop_assert_eq!(bits(lane(&forces.torque, l)), bits(want.torque), "torque, lane {}", l);
            prop_assert_eq!(
                bits(lane(&forces.partner_torque, l)),
                bits(want.partner_torque),
                "partner's torque, lane {}",
                l
            );
            let got = records[l];
            prop_assert_eq!(bits(got.spring), bits(alone.spring), "spring, lane {}", l);
            prop_assert_eq!(bits(got.normal), bits(alone.normal), "normal, lane {}", l);
            prop_assert_eq!(bits(got.roll), bits(alone.roll), "roll, lane {}", l);
            prop_assert_eq!(number(got.twist), number(alone.twist), "twist, lane {}", l);
        }
    }
}
