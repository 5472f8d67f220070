//! Prints the benchmark's generated hull of N triangle walls (default 100000), for
//! measuring the real binary: `cargo run --release -p walls-cli --example gen-hull -- 100000 > hull.walls`.

#[path = "../benches/hull.rs"]
mod hull;

fn main() -> std::process::ExitCode {
    match std::env::args().nth(1).map_or(Ok(100_000), |a| a.parse()) {
        Ok(n) => {
            print!("{}", hull::triangles(n));
            std::process::ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("gen-hull: N must be a whole number: {e}");
            std::process::ExitCode::from(2)
        }
    }
}
