//! Rebuild when a page or an example case changes, or one is added: rust-embed includes
//! the files it finds at compile time, but cargo only watches files it was told about.

fn main() {
    println!("cargo::rerun-if-changed=assets");
    println!("cargo::rerun-if-changed=../../examples");
}
