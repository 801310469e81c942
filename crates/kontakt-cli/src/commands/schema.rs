//! `kontakt schema`: print the JSON Schema of the case files ([`kontakt_case::case_schema`]),
//! the one that `docs/kontakt-case.schema.json` holds.

use anyhow::Result;
use std::io::Write;

/// Write the case schema, pretty-printed JSON with a final newline.
pub fn run(out: &mut impl Write) -> Result<()> {
    let text = serde_json::to_string_pretty(&kontakt_case::case_schema())?;
    writeln!(out, "{text}")?;
    Ok(())
}
