//! Fuzz target: arbitrary text through the `.par` reader. Checks that nothing panics or
//! hangs, that an error says where (a line), and that every number the reader accepts is
//! finite (a `.par` value pkdgrav's `atof` would misread is reported, never kept).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match walls_sim::io::par::read_par(&text) {
        Ok(params) => {
            let numbers = [
                params.dt,
                params.eps_n,
                params.eps_t,
                params.k_n,
                params.k_t,
                params.mu_s,
                params.mu_r,
            ];
            for x in numbers.into_iter().flatten() {
                assert!(x.is_finite(), "a .par value read as {x}");
            }
        }
        Err(e) => assert!(!e.to_string().is_empty(), "an empty error"),
    }
});
