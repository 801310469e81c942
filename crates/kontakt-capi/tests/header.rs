//! `include/kontakt.h` is what cbindgen generates from the crate today: the test regenerates
//! it and fails if the committed file differs. Refresh it with
//! `KONTAKT_BLESS=1 cargo test -p kontakt-capi --test header`.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

use std::path::PathBuf;

#[test]
fn header_is_up_to_date() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).unwrap();
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_config(config)
        .with_src(dir.join("src/lib.rs"))
        .generate()
        .unwrap()
        .write(&mut generated);
    let generated = String::from_utf8(generated).unwrap();
    let path = dir.join("include/kontakt.h");
    if std::env::var_os("KONTAKT_BLESS").is_some() {
        std::fs::write(&path, &generated).unwrap();
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    if committed != generated {
        let line = committed
            .lines()
            .zip(generated.lines())
            .position(|(a, b)| a != b)
            .unwrap_or_else(|| committed.lines().count().min(generated.lines().count()))
            + 1;
        panic!(
            "{} is out of date with src/lib.rs (first difference at line {line}).\n\
             Refresh it with: KONTAKT_BLESS=1 cargo test -p kontakt-capi --test header",
            path.display()
        );
    }
}
