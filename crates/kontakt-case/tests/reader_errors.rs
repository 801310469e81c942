//! The case reader's messages (issue 15, item 5): the line, the key path as the file spells
//! it and the schema's words; values with line breaks stay on one line (issue 14).

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

use kontakt::Error;
use kontakt_case::Case;

const BALL: &str = "[contact]\nkind = \"point\"\n\n[body1]\nradii_mm = [5.0, 5.0]\n\
    e_mpa = 210000.0\nnu = 0.3\n\n[body2]\nradii_mm = [1e300, 1e300]\ne_mpa = 210000.0\n\
    nu = 0.3\n\n[load]\nforce_n = 100.0\n";

/// The reader's error on `text` as (line, key, message).
fn error(text: &str) -> (Option<usize>, String, String) {
    match Case::from_toml_str(text) {
        Err(Error::CaseFile { line, key, message }) => (line, key.into_owned(), message),
        other => panic!("expected a case-file error, got {other:?}"),
    }
}

/// Found by fuzzing: a string value with a line break in an error made a message of
/// two lines; it is escaped (`\n`), for an unknown variant and an unknown method alike.
#[test]
fn line_breaks_in_values_are_escaped() {
    let text = BALL.replace("\"point\"", "\"a\\nb\"");
    let m = Case::from_toml_str(&text).unwrap_err().to_string();
    assert!(!m.contains('\n') && m.contains("a\\nb"), "{m}");
    let m = Case::from_toml_str(&format!("method = \"x\\ny\"\n{BALL}"))
        .unwrap_err()
        .to_string();
    assert!(!m.contains('\n') && m.contains("x\\ny"), "{m}");
}

/// Each class of reader error reads as the schema's words, with the line and the key
/// path as the file spells it (issue 15: no "invalid case = TOML at line 9").
#[test]
fn reader_errors_name_line_and_key_path() {
    assert_eq!(BALL.lines().count(), 15);
    assert!(Case::from_toml_str(BALL).is_ok());
    let cases: [(String, usize, &str, &str); 7] = [
        (
            BALL.replace("nu = 0.3\n\n[body2]", "nu = = 0.3\n\n[body2]"),
            7,
            "case",
            "not valid TOML: ",
        ),
        (
            BALL.replace("kind = \"point\"", "kind = \"point\"\nangel_deg = 1.0"),
            3,
            "contact.angel_deg",
            "unknown key `contact.angel_deg`; [contact] takes `kind`, `angle_deg`",
        ),
        (
            format!("{BALL}\n[yeld]\nstress_mpa = 1.0\n"),
            17,
            "yeld",
            "unknown key `yeld`; the top level takes `name`, ",
        ),
        (
            BALL.replace("force_n = 100.0", "force_n = \"100\""),
            15,
            "load.force_n",
            "`load.force_n`: string \"100\", expected a number",
        ),
        (
            BALL.replace(
                "e_mpa = 210000.0\nnu = 0.3\n\n[body2]",
                "nu = 0.3\n\n[body2]",
            ),
            4,
            "body1.e_mpa",
            "missing key `body1.e_mpa`",
        ),
        (
            BALL.replace("\"point\"", "\"spot\""),
            2,
            "contact.kind",
            "`contact.kind` = `spot`: expected `point` or `line`",
        ),
        (
            BALL.replace("[load]", "[load.extra]\nx = 1\n[load]"),
            14,
            "load.extra",
            "unknown key `load.extra`; [load] takes ",
        ),
    ];
    for (text, line, key, start) in cases {
        let (l, k, m) = error(&text);
        assert_eq!((l, k.as_str()), (Some(line), key), "{m}\n{text}");
        assert!(m.starts_with(start), "{m:?} should start with {start:?}");
        let shown = Case::from_toml_str(&text).unwrap_err().to_string();
        assert_eq!(shown, format!("line {line}: {m}"));
    }
}

/// Found by the Python fuzz harness: a path with a line break, or a whole case text given
/// as a path, gave a message of several lines; now escaped and shortened to one line.
#[test]
fn odd_paths_give_one_line() {
    for path in ["\n", "a\nb/c.toml", &"x/".repeat(300)] {
        let e = kontakt_case::read_case_file(std::path::Path::new(path))
            .unwrap_err()
            .to_string();
        assert!(!e.contains('\n'), "{e:?}");
        assert!(e.chars().count() < 200, "{e:?}");
    }
}

/// Issue 30 item 6: a sweep's `base` file goes through the case files' capped reader:
/// `/dev/zero` is refused after 16 MiB + 1 byte (it was read without a cap).
#[cfg(unix)]
#[test]
fn sweep_base_file_is_capped() {
    let text = "mode = \"grid\"\nbase = \"/dev/zero\"\n\n[[parameter]]\nkey = \"load.force_n\"\n\
                values = [1.0]\n";
    let e = kontakt_case::Sweep::from_toml_str(text, std::path::Path::new("."))
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(
        e.contains("base = \"/dev/zero\"") && e.contains("larger than 16 MiB"),
        "{e}"
    );
}

/// A missing top-level table is named as itself, not under the key whose line the parser
/// pointed at (found while building the C bearing element: a case of only
/// `method = "bearing"` said "missing key `method.bearing`").
#[test]
fn a_missing_top_level_table_is_named_as_itself() {
    for (method, table) in [("bearing", "bearing"), ("hertz", "contact")] {
        let text = format!("method = \"{method}\"\n");
        let (_, key, m) = error(&text);
        assert_eq!(key, table, "{m}");
        assert!(m.starts_with(&format!("missing key `{table}`")), "{m}");
    }
}
