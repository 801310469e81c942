//! Prints the table of approximation errors in docs/hertz.md:
//! `cargo run --release -p kontakt --example approximation_errors`.

use kontakt::hertz::approximation::{Approximation, approximation_error};

fn main() -> Result<(), kontakt::Error> {
    println!("| B/A | model | a | b | p0 | delta |");
    println!("|---:|---|---:|---:|---:|---:|");
    for ratio in [1.0, 2.0, 5.0, 10.0, 30.0, 100.0, 1e3, 1e4] {
        for (name, model) in [
            ("Greenwood", Approximation::Greenwood),
            ("Hamrock-Brewe", Approximation::HamrockBrewe),
        ] {
            let e = approximation_error(ratio, model)?;
            println!(
                "| {ratio} | {name} | {:+.2} % | {:+.2} % | {:+.2} % | {:+.2} % |",
                100.0 * e.semi_major,
                100.0 * e.semi_minor,
                100.0 * e.max_pressure,
                100.0 * e.approach
            );
        }
    }
    Ok(())
}
