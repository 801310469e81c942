//! What the binary carries: the pages (crates/kontakt-web/assets/) and the example cases
//! (the repository's examples/*.toml), embedded at build time. Nothing is read from disk
//! at run time.

use rust_embed::RustEmbed;
use serde::Serialize;

/// The pages, scripts, styles and vendored plotting libraries.
#[derive(RustEmbed)]
#[folder = "assets/"]
pub struct Assets;

/// The example cases of the repository.
#[derive(RustEmbed)]
#[folder = "../../examples/"]
#[include = "*.toml"]
pub struct Examples;

/// One example case as `GET /api/examples` lists it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExampleInfo {
    /// The file name without `.toml`, the `{name}` of `GET /api/examples/{name}`.
    pub name: String,
    /// The case's `method` (`hertz` when absent).
    pub method: String,
    /// The case's `name` key, or the file name.
    pub title: String,
    /// The comment block at the top of the file, joined into one paragraph.
    pub description: String,
}

/// The TOML text of the example `name` (top-level files only).
pub fn example(name: &str) -> Option<String> {
    let name = name.strip_suffix(".toml").unwrap_or(name);
    if name.contains(['/', '\\']) || name.starts_with('.') {
        return None;
    }
    let file = Examples::get(&format!("{name}.toml"))?;
    String::from_utf8(file.data.into_owned()).ok()
}

/// Every top-level example, sorted by name.
pub fn examples() -> Vec<ExampleInfo> {
    let mut list: Vec<ExampleInfo> = Examples::iter()
        .filter(|path| !path.contains('/'))
        .filter_map(|path| {
            let name = path.strip_suffix(".toml")?.to_string();
            let text = example(&name)?;
            let table = text.parse::<toml::Table>().ok()?;
            let get = |k: &str| table.get(k).and_then(|v| v.as_str()).map(str::to_string);
            let description = text
                .lines()
                .take_while(|l| l.starts_with('#'))
                .map(|l| l.trim_start_matches('#').trim())
                .collect::<Vec<_>>()
                .join(" ");
            Some(ExampleInfo {
                method: get("method").unwrap_or_else(|| "hertz".into()),
                title: get("name").unwrap_or_else(|| name.clone()),
                name,
                description,
            })
        })
        .collect();
    list.sort_by(|a, b| a.name.cmp(&b.name));
    list
}

/// The `Content-Type` of an asset, from its extension.
pub fn content_type(path: &str) -> &'static str {
    let ext = path.rsplit_once('.').map_or("", |(_, e)| e);
    match ext.to_ascii_lowercase().as_str() {
        "html" => "text/html; charset=utf-8",
        "js" | "mjs" => "text/javascript; charset=utf-8",
        "css" => "text/css; charset=utf-8",
        "json" | "map" => "application/json",
        "svg" => "image/svg+xml",
        "png" => "image/png",
        "ico" => "image/x-icon",
        "woff2" => "font/woff2",
        "toml" | "txt" | "md" => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn examples_are_embedded_with_their_method() {
        let list = examples();
        let hertz = list.iter().find(|e| e.name == "ball_on_flat").unwrap();
        assert_eq!(hertz.method, "hertz");
        assert_eq!(hertz.title, "ball on flat");
        assert!(list.iter().any(|e| e.method == "bearing"));
        assert!(list.iter().all(|e| !e.name.contains('/')));
        assert!(
            example("ball_on_flat")
                .unwrap()
                .contains("method = \"hertz\"")
        );
        assert!(example("../Cargo").is_none());
        assert!(example("nope").is_none());
    }
}
