//! `kontakt fmu`: a bearing case and an element case packed as FMUs (the zip holds the
//! model description with the case's GUID, the binary under the platform folder and the
//! case in resources/), the library found next to the executable, and one-line input
//! errors (exit status 2) for a case that is no element, a missing library.
//! FMPy's tests of the FMUs themselves: crates/kontakt-py/tests/test_fmu.py.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

mod support;
use support::{bad, example, kontakt, tempdir};

/// Run `kontakt fmu ARGS` without `$KONTAKT_FMI_LIBRARY`, expect success, return stdout.
fn pack(args: &[&str]) -> String {
    let run = kontakt()
        .env_remove("KONTAKT_FMI_LIBRARY")
        .arg("fmu")
        .args(args)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{args:?}: {stderr}");
    String::from_utf8(run.stdout).unwrap()
}

fn contains(haystack: &[u8], needle: &[u8]) -> bool {
    haystack.windows(needle.len()).any(|w| w == needle)
}

#[test]
fn packs_the_case_the_description_and_the_library() {
    let dir = tempdir("fmu", "pack");
    // a stand-in library: the command packs the bytes it is given
    let lib = dir.join("libstandin.so");
    std::fs::write(&lib, b"\x7fELF stand-in").unwrap();
    let capi = example("../crates/kontakt-capi/examples/element_ball_on_flat.toml");
    for (case, kind) in [
        (example("bearing_32008x.toml"), "bearing element"),
        (capi, "contact element"),
    ] {
        let out = dir.join("case.fmu");
        let stdout = pack(&[
            case.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--library",
            lib.to_str().unwrap(),
        ]);
        assert!(stdout.contains(kind), "{stdout}");
        let zip = std::fs::read(&out).unwrap();
        let text = std::fs::read_to_string(&case).unwrap();
        assert_eq!(&zip[..4], b"PK\x03\x04");
        for name in [
            "modelDescription.xml".to_string(),
            kontakt_fmi::archive::binary_path(),
            "resources/case.toml".to_string(),
        ] {
            assert!(contains(&zip, name.as_bytes()), "{name} missing");
        }
        assert!(contains(&zip, b"\x7fELF stand-in"));
        assert!(contains(&zip, text.as_bytes()), "the case is stored as is");
        let guid = kontakt_fmi::description::guid(&text);
        assert!(contains(&zip, format!("guid=\"{guid}\"").as_bytes()));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Without `--library` the command takes the library that `cargo test` left next to the
/// executable (target/debug/deps): a clean clone's CI can build FMUs after
/// `cargo test --workspace`.
#[cfg(target_os = "linux")]
#[test]
fn finds_the_library_next_to_the_executable() {
    let case = example("bearing_32008x.toml");
    let stdout = pack(&[case.to_str().unwrap(), "-o", "/dev/null"]);
    assert!(stdout.contains("libkontakt_fmi.so"), "{stdout}");
}

#[test]
fn input_errors_are_one_line_with_exit_status_2() {
    let dir = tempdir("fmu", "errors");
    let out = dir.join("x.fmu");
    let out = out.to_str().unwrap();
    let hertz = example("ball_on_flat.toml");
    let line = bad(&["fmu", hertz.to_str().unwrap(), "-o", out, "--library", out]);
    // the library is checked before the case is planned
    assert!(
        line.contains("--library") && line.contains("no such file"),
        "{line}"
    );
    let lib = dir.join("lib.so");
    std::fs::write(&lib, b"x").unwrap();
    let lib = lib.to_str().unwrap();
    let line = bad(&["fmu", hertz.to_str().unwrap(), "-o", out, "--library", lib]);
    assert!(
        line.contains("method = hertz") && line.contains("\"bearing\""),
        "{line}"
    );
    assert!(
        !std::path::Path::new(out).exists(),
        "no FMU written on error"
    );
    let line = bad(&["fmu", "missing.toml", "-o", out, "--library", lib]);
    assert!(line.contains("missing.toml"), "{line}");
    let run = kontakt()
        .env("KONTAKT_FMI_LIBRARY", dir.join("none.so"))
        .args([
            "fmu",
            example("bearing_32008x.toml").to_str().unwrap(),
            "-o",
            out,
        ])
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("KONTAKT_FMI_LIBRARY"));
    std::fs::remove_dir_all(&dir).unwrap();
}
