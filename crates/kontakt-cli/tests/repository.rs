#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message
//! The repository holds no machine paths (issue 30 item 15): a document or comment that
//! cites a folder of the machine it was written on, a home directory or a local file
//! address points at a file the reader does not have. Every text file of the repository (sources, docs, examples, tools; not
//! `target/` or `.git/`) is searched for them.

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The text files under `dir`, skipping build output and hidden folders.
fn text_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        if path.is_dir() {
            if !(name.starts_with('.') && name != ".ci" && name != ".cargo")
                && name != "target"
                && name != "__pycache__"
            {
                text_files(&path, out);
            }
        } else if [
            "md", "rs", "toml", "py", "pyi", "sh", "yml", "yaml", "txt", "h", "c", "cfg", "ini",
        ]
        .iter()
        .any(|e| path.extension().is_some_and(|x| x == *e))
            || name == "run"
            || name == "test"
        {
            out.push(path);
        }
    }
}

#[test]
fn no_machine_paths_in_the_repository() {
    // Spelled in pieces, so that this file does not match itself.
    let patterns: Vec<String> = [
        ["/wo", "rk/"],
        ["/ho", "me/"],
        ["/ro", "ot/"],
        ["/Us", "ers/"],
        ["/m", "nt/"],
        ["/t", "mp/"],
        ["fi", "le://"],
        ["shared/", "reference/"],
        ["shared/", "seeds/"],
    ]
    .iter()
    .map(|p| p.concat())
    .collect();
    let mut files = Vec::new();
    text_files(&root(), &mut files);
    assert!(files.len() > 100, "only {} files found", files.len());
    let mut found = Vec::new();
    for file in &files {
        let Ok(text) = std::fs::read_to_string(file) else {
            continue;
        };
        for (k, line) in text.lines().enumerate() {
            if let Some(p) = patterns.iter().find(|p| line.contains(p.as_str())) {
                let shown = file
                    .strip_prefix(root())
                    .unwrap_or(file)
                    .display()
                    .to_string();
                found.push(format!("{shown}:{}: `{p}` in {}", k + 1, line.trim()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "machine paths in the repository (cite the published source or a file in the \
         repository instead):\n{}",
        found.join("\n")
    );
}
